//! How the scheduler's thread waits for a command without sharing a lock with the senders.
//!
//! A blocked `Receiver::recv_timeout` of std's channel registers the receiver under a mutex of
//! the channel, which every send then takes to wake it; a sending thread of normal priority
//! that is preempted while holding that mutex would keep a real-time scheduler waiting (the soak
//! benchmark measured wake-ups late by up to 130 ms that way). So the thread only ever polls the
//! channel (`try_recv`, which takes no lock, and then no send does either) and sleeps with
//! `std::thread::park_timeout`; the handle unparks it after each send (an atomic operation and a
//! wake-up, no lock). The answers go back the same way: the asking thread polls its channel and
//! parks, and [`Answer::send`] unparks it, so the scheduler's send takes no lock either.

use std::sync::mpsc;
use std::time::Duration;

use super::Command;

/// The longest sleep when nothing is planned, so the thread notices a handle that went away
/// without unparking it.
const IDLE_POLL: Duration = Duration::from_millis(100);

/// Where the scheduler's thread sends the answer to one command.
pub(super) struct Answer<T> {
    /// `None` once sent or dropped.
    sender: Option<mpsc::Sender<T>>,
    asker: std::thread::Thread,
}

impl<T> Answer<T> {
    /// Sends the answer and wakes the asking thread; an asker that went away is not told.
    pub(super) fn send(mut self, answer: T) -> Result<(), mpsc::SendError<T>> {
        let sent = match self.sender.take() {
            Some(sender) => sender.send(answer),
            None => Err(mpsc::SendError(answer)),
        };
        self.asker.unpark();
        sent
    }
}

impl<T> Drop for Answer<T> {
    /// An answer never sent (the scheduler's thread ended) wakes the asker too, which then
    /// finds the channel closed.
    fn drop(&mut self) {
        if self.sender.take().is_some() {
            self.asker.unpark();
        }
    }
}

/// A channel for one answer to the calling thread, and its receiving end.
pub(super) fn answer<T>() -> (Answer<T>, mpsc::Receiver<T>) {
    let (sender, receiver) = mpsc::channel();
    let answer = Answer {
        sender: Some(sender),
        asker: std::thread::current(),
    };
    (answer, receiver)
}

/// Waits on the calling thread (the one [`answer`] was made on) for the answer; `None` when the
/// scheduler's thread ended without one.
pub(super) fn wait_for_answer<T>(receiver: &mpsc::Receiver<T>) -> Option<T> {
    loop {
        match receiver.try_recv() {
            Ok(answer) => return Some(answer),
            Err(mpsc::TryRecvError::Disconnected) => return None,
            Err(mpsc::TryRecvError::Empty) => std::thread::park(),
        }
    }
}

/// What a wait for a command gave.
pub(super) enum Received {
    /// A command.
    Command(Command),
    /// Nothing came within the wait (or the thread woke early): look at the schedule again.
    Nothing,
    /// The handle is gone.
    Gone,
}

/// Waits at most `wait` (`None`: until a command comes) for the next command.
pub(super) fn wait(commands: &mpsc::Receiver<Command>, wait: Option<Duration>) -> Received {
    match commands.try_recv() {
        Ok(command) => return Received::Command(command),
        Err(mpsc::TryRecvError::Disconnected) => return Received::Gone,
        Err(mpsc::TryRecvError::Empty) => {}
    }
    // A send after the look above has unparked the thread already: this returns at once.
    std::thread::park_timeout(wait.map_or(IDLE_POLL, |wait| wait.min(IDLE_POLL)));
    match commands.try_recv() {
        Ok(command) => Received::Command(command),
        Err(mpsc::TryRecvError::Disconnected) => Received::Gone,
        Err(mpsc::TryRecvError::Empty) => Received::Nothing,
    }
}

#[cfg(test)]
mod tests {
    use std::time::Instant;

    use super::*;

    #[test]
    fn a_send_and_unpark_wakes_a_waiting_thread_and_a_dropped_handle_is_seen() {
        let (sender, commands) = mpsc::channel();
        let waiting = std::thread::spawn(move || {
            let start = Instant::now();
            let first = wait(&commands, Some(Duration::from_secs(3600)));
            let woken = start.elapsed();
            let mut last = Received::Nothing;
            while matches!(last, Received::Nothing) {
                last = wait(&commands, None);
            }
            (
                matches!(first, Received::Command(_)),
                woken,
                matches!(last, Received::Gone),
            )
        });
        let (reply, _answer) = answer();
        sender.send(Command::Start(reply)).unwrap();
        waiting.thread().unpark();
        drop(sender);
        let (got_command, woken, saw_gone) = waiting.join().unwrap();
        assert!(got_command);
        // Far less than the hour asked for: the unpark woke it.
        assert!(woken < Duration::from_secs(60), "{woken:?}");
        assert!(saw_gone);
    }

    #[test]
    fn an_answer_sent_or_dropped_on_another_thread_wakes_the_asker() {
        let (reply, answered) = answer();
        std::thread::spawn(move || reply.send(42))
            .join()
            .unwrap()
            .unwrap();
        assert_eq!(wait_for_answer(&answered), Some(42));
        let (reply, answered) = answer::<i32>();
        std::thread::spawn(move || drop(reply)).join().unwrap();
        assert_eq!(wait_for_answer(&answered), None);
    }
}
