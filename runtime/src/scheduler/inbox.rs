//! How commands reach the scheduler's thread, and answers come back, without the thread ever
//! waiting for another thread.
//!
//! std's channel does not do for the commands: a blocked `recv_timeout` registers the receiver
//! under a mutex of the channel that every send then takes, and even `try_recv` spins while a
//! sender is between reserving its slot and writing it. A sending thread of normal priority
//! that is preempted there keeps a real-time scheduler waiting (the soak benchmark measured
//! wake-ups late by up to 130 ms, then stalls of 100 ms). So the commands wait in a queue
//! behind a mutex that senders lock and the scheduler's thread only *tries*: when the lock is
//! busy, the thread looks again [`LOCK_RETRY`] later, and does its cycles meanwhile. It sleeps
//! with `std::thread::park_timeout`; the handle unparks it after each send (an atomic operation
//! and a wake-up, no lock). The answers go back on std's channel, which the asking thread polls
//! and parks on, and [`Answer::send`] unparks it: the scheduler's send then takes no lock that
//! another thread could hold, since nobody waits inside the channel.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError, TryLockError, mpsc};
use std::time::Duration;

use super::Command;

/// The longest sleep when nothing is planned, so the thread notices a handle that went away
/// without unparking it.
const IDLE_POLL: Duration = Duration::from_millis(100);

/// How soon the thread tries again a lock another thread held (the command queue, the located
/// areas for a command, the status for statistics) instead of waiting for it.
pub(super) const LOCK_RETRY: Duration = Duration::from_micros(200);

/// What the handle and the scheduler's thread share.
struct Shared {
    queue: Mutex<VecDeque<Command>>,
    /// How many commands are queued, so the thread takes no lock when none are.
    queued: AtomicUsize,
    /// Set by the thread, under the queue's lock, when it ends: nothing more is accepted.
    closed: AtomicBool,
    /// Set when the handle went away.
    handle_gone: AtomicBool,
}

/// The handle's side: sends commands.
pub(super) struct Postbox {
    shared: Arc<Shared>,
}

/// The scheduler thread's side: takes commands, never waiting for the queue's lock.
pub(super) struct Inbox {
    shared: Arc<Shared>,
}

/// A new queue of commands.
pub(super) fn queue() -> (Postbox, Inbox) {
    let shared = Arc::new(Shared {
        queue: Mutex::new(VecDeque::new()),
        queued: AtomicUsize::new(0),
        closed: AtomicBool::new(false),
        handle_gone: AtomicBool::new(false),
    });
    let postbox = Postbox {
        shared: Arc::clone(&shared),
    };
    (postbox, Inbox { shared })
}

impl Shared {
    fn lock(&self) -> MutexGuard<'_, VecDeque<Command>> {
        self.queue.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

impl Postbox {
    /// Queues `command`; gives it back when the thread has ended. The caller then unparks the
    /// thread.
    pub(super) fn send(&self, command: Command) -> Result<(), Command> {
        let mut queue = self.shared.lock();
        if self.shared.closed.load(Ordering::Acquire) {
            return Err(command);
        }
        queue.push_back(command);
        self.shared.queued.fetch_add(1, Ordering::Release);
        Ok(())
    }
}

impl Drop for Postbox {
    fn drop(&mut self) {
        self.shared.handle_gone.store(true, Ordering::Release);
    }
}

/// What a look at the queue found.
enum Taken {
    Command(Command),
    Empty,
    /// A sender holds the queue's lock now.
    Busy,
    Gone,
}

impl Inbox {
    /// The next command, without waiting for the queue's lock.
    fn take(&self) -> Taken {
        if self.shared.queued.load(Ordering::Acquire) == 0 {
            return if self.shared.handle_gone.load(Ordering::Acquire) {
                Taken::Gone
            } else {
                Taken::Empty
            };
        }
        let mut queue = match self.shared.queue.try_lock() {
            Ok(queue) => queue,
            Err(TryLockError::Poisoned(poisoned)) => poisoned.into_inner(),
            Err(TryLockError::WouldBlock) => return Taken::Busy,
        };
        match queue.pop_front() {
            Some(command) => {
                self.shared.queued.fetch_sub(1, Ordering::Release);
                Taken::Command(command)
            }
            None => Taken::Empty,
        }
    }

    /// The next command if one can be taken now: `Nothing` when none is queued or the queue is
    /// busy (the caller looks again soon).
    pub(super) fn try_take(&self) -> Received {
        match self.take() {
            Taken::Command(command) => Received::Command(command),
            Taken::Empty | Taken::Busy => Received::Nothing,
            Taken::Gone => Received::Gone,
        }
    }

    /// Waits at most `wait` (`None`: until a command comes) for the next command.
    pub(super) fn wait(&self, wait: Option<Duration>) -> Received {
        let sleep = match self.take() {
            Taken::Command(command) => return Received::Command(command),
            Taken::Gone => return Received::Gone,
            Taken::Busy => wait.map_or(LOCK_RETRY, |wait| wait.min(LOCK_RETRY)),
            Taken::Empty => wait.map_or(IDLE_POLL, |wait| wait.min(IDLE_POLL)),
        };
        // A send after the look above has unparked the thread already: this returns at once.
        std::thread::park_timeout(sleep);
        self.try_take()
    }
}

impl Drop for Inbox {
    /// The thread ends: later sends are refused, and the commands still queued are dropped,
    /// which wakes their askers with no answer.
    fn drop(&mut self) {
        let abandoned = {
            let mut queue = self.shared.lock();
            self.shared.closed.store(true, Ordering::Release);
            std::mem::take(&mut *queue)
        };
        drop(abandoned);
    }
}

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
    /// Nothing could be taken within the wait (or the thread woke early): look at the schedule
    /// again.
    Nothing,
    /// The handle is gone.
    Gone,
}

#[cfg(test)]
mod tests {
    use std::time::Instant;

    use super::*;

    #[test]
    fn a_send_and_unpark_wakes_a_waiting_thread_and_a_dropped_handle_is_seen() {
        let (postbox, inbox) = queue();
        let waiting = std::thread::spawn(move || {
            let start = Instant::now();
            let first = inbox.wait(Some(Duration::from_secs(3600)));
            let woken = start.elapsed();
            let mut last = Received::Nothing;
            while matches!(last, Received::Nothing) {
                last = inbox.wait(None);
            }
            (
                matches!(first, Received::Command(_)),
                woken,
                matches!(last, Received::Gone),
            )
        });
        let (reply, _answer) = answer();
        assert!(postbox.send(Command::Start(reply)).is_ok());
        waiting.thread().unpark();
        drop(postbox);
        let (got_command, woken, saw_gone) = waiting.join().unwrap();
        assert!(got_command);
        // Far less than the hour asked for: the unpark woke it.
        assert!(woken < Duration::from_secs(60), "{woken:?}");
        assert!(saw_gone);
    }

    #[test]
    fn a_held_queue_does_not_stall_the_taker_and_its_command_arrives_once_released() {
        let (postbox, inbox) = queue();
        let (reply, _answer) = answer();
        assert!(postbox.send(Command::Start(reply)).is_ok());
        let held = postbox.shared.lock();
        assert!(matches!(inbox.try_take(), Received::Nothing));
        assert!(matches!(
            inbox.wait(Some(Duration::from_secs(3600))),
            Received::Nothing
        ));
        drop(held);
        assert!(matches!(
            inbox.try_take(),
            Received::Command(Command::Start(_))
        ));
    }

    #[test]
    fn commands_left_when_the_thread_ends_wake_their_askers_and_later_ones_are_refused() {
        let (postbox, inbox) = queue();
        let (reply, answered) = answer::<Result<(), crate::scheduler::SchedulerError>>();
        assert!(postbox.send(Command::Start(reply)).is_ok());
        drop(inbox);
        assert!(wait_for_answer(&answered).is_none());
        let (reply, _answered) = answer();
        assert!(postbox.send(Command::Start(reply)).is_err());
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
