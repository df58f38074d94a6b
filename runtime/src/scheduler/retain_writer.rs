//! The thread that writes retained values while the scheduler runs, so that a slow disk never
//! delays a task cycle.

use std::sync::{Arc, Mutex, MutexGuard, PoisonError, mpsc};
use std::thread::JoinHandle;

use crate::retain::{RetainSnapshot, RetainStore};

/// A retain store behind a writer thread. Periodic saves are queued; everything else (restore,
/// the save on stop, delete) first waits for the queue to drain and then uses the store
/// directly, so an older snapshot never overwrites a newer one.
pub(super) struct RetainWriter {
    store: Arc<Mutex<RetainStore>>,
    /// `None` when the thread could not be started: saves are then done in place.
    jobs: Option<mpsc::Sender<Job>>,
    thread: Option<JoinHandle<()>>,
    report: Arc<dyn Fn(Option<String>) + Send + Sync>,
}

enum Job {
    Write(RetainSnapshot),
    Flush(mpsc::Sender<()>),
}

impl RetainWriter {
    /// Starts the writer of `store`; `report` hears the outcome of every queued save: the
    /// error's message, or `None` after a success.
    pub(super) fn spawn(
        store: RetainStore,
        report: Arc<dyn Fn(Option<String>) + Send + Sync>,
    ) -> Self {
        let store = Arc::new(Mutex::new(store));
        let (jobs, received) = mpsc::channel::<Job>();
        let thread_store = Arc::clone(&store);
        let thread_report = Arc::clone(&report);
        let thread = std::thread::Builder::new()
            .name("rivet-retain".to_owned())
            .spawn(move || {
                // Polled, never blocked in: a thread asleep inside the channel would make the
                // scheduler's send take the channel's lock (`inbox.rs` says why that matters).
                while let Some(job) = next_job(&received) {
                    match job {
                        Job::Write(snapshot) => {
                            let written = lock(&thread_store).write(snapshot);
                            thread_report(written.err().map(|error| error.to_string()));
                        }
                        Job::Flush(done) => {
                            let _ = done.send(());
                        }
                    }
                }
            })
            .ok();
        Self {
            store,
            jobs: thread.is_some().then_some(jobs),
            thread,
            report,
        }
    }

    /// Queues `snapshot` to be written when it differs from what was last written.
    pub(super) fn write_later(&self, snapshot: RetainSnapshot) {
        let unsent = match &self.jobs {
            Some(jobs) => jobs.send(Job::Write(snapshot)).err().map(|error| error.0),
            None => Some(Job::Write(snapshot)),
        };
        self.wake();
        if let Some(Job::Write(snapshot)) = unsent {
            let written = lock(&self.store).write(snapshot);
            (self.report)(written.err().map(|error| error.to_string()));
        }
    }

    /// Waits for the queued saves, then lends the store.
    pub(super) fn with_store<R>(&self, use_store: impl FnOnce(&mut RetainStore) -> R) -> R {
        if let Some(jobs) = &self.jobs {
            let (done, finished) = mpsc::channel();
            if jobs.send(Job::Flush(done)).is_ok() {
                self.wake();
                // An error means the thread has ended, and then nothing is queued any more.
                let _ = finished.recv();
            }
        }
        use_store(&mut lock(&self.store))
    }
}

impl RetainWriter {
    /// Wakes the writer's thread to look at its queue.
    fn wake(&self) {
        if let Some(thread) = &self.thread {
            thread.thread().unpark();
        }
    }
}

/// The next job for the writer's thread, parked until one comes; `None` once the queue is
/// closed and empty.
fn next_job(received: &mpsc::Receiver<Job>) -> Option<Job> {
    loop {
        match received.try_recv() {
            Ok(job) => return Some(job),
            Err(mpsc::TryRecvError::Disconnected) => return None,
            Err(mpsc::TryRecvError::Empty) => std::thread::park(),
        }
    }
}

impl Drop for RetainWriter {
    fn drop(&mut self) {
        // Closing the queue ends the thread once it has written what is queued.
        self.jobs = None;
        self.wake();
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}
