//! One session with a target, seen from the UI thread: commands are queued without waiting,
//! events are collected each frame, and every event wakes the UI.

use std::sync::mpsc;

use online::session::{Command, Event, SessionOptions};
use tokio::sync::mpsc as async_mpsc;

use super::background::Background;

/// A session with a target. Dropping it ends the session, which logs out first (on the
/// background thread: the UI does not wait for it).
pub struct Link {
    commands: async_mpsc::Sender<Command>,
    events: mpsc::Receiver<Event>,
}

impl Link {
    /// Starts a session on `background`; `wake` is called after each event so the UI redraws.
    pub fn open(
        background: &Background,
        options: SessionOptions,
        wake: impl Fn() + Send + 'static,
    ) -> Self {
        let handle = background.handle();
        let _entered = handle.enter();
        let (commands, mut session_events) = online::session::spawn(options);
        let (forward, events) = mpsc::channel();
        let guard = background.session_guard();
        handle.spawn(async move {
            // The events end when the session's task has ended, after its logout: the guard
            // is held until then, so that quitting the studio waits for the logout.
            let _guard = guard;
            while let Some(event) = session_events.recv().await {
                // Once the link is dropped its events are not wanted, but the session is
                // still followed to its end.
                if forward.send(event).is_ok() {
                    wake();
                }
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
