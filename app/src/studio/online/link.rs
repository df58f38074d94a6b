//! One session with a target, seen from the UI thread: commands are queued without waiting,
//! events are collected each frame, and every event wakes the UI.

use std::sync::mpsc;

use online::session::{Command, Event, SessionOptions};
use tokio::sync::mpsc as async_mpsc;

/// A session with a target. Dropping it ends the session.
pub struct Link {
    commands: async_mpsc::Sender<Command>,
    events: mpsc::Receiver<Event>,
}

impl Link {
    /// Starts a session on `handle`; `wake` is called after each event so the UI redraws.
    pub fn open(
        handle: &tokio::runtime::Handle,
        options: SessionOptions,
        wake: impl Fn() + Send + 'static,
    ) -> Self {
        let _entered = handle.enter();
        let (commands, mut session_events) = online::session::spawn(options);
        let (forward, events) = mpsc::channel();
        handle.spawn(async move {
            while let Some(event) = session_events.recv().await {
                if forward.send(event).is_err() {
                    return;
                }
                wake();
            }
        });
        Self { commands, events }
    }

    /// Queues a command; `false` when the queue is full or the session ended, which the caller
    /// reports rather than waiting.
    pub fn send(&self, command: Command) -> bool {
        self.commands.try_send(command).is_ok()
    }

    /// The events that arrived since the last call.
    pub fn drain(&self) -> Vec<Event> {
        self.events.try_iter().collect()
    }
}

impl Drop for Link {
    fn drop(&mut self) {
        let _ = self.commands.try_send(Command::Close);
    }
}
