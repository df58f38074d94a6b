//! The studio's async runtime: one thread that drives every network task (sessions with
//! targets, the embedded simulator's Modbus server), so the UI thread never waits on I/O.

use std::thread::JoinHandle;

use tokio::sync::oneshot;

/// A tokio runtime on its own thread; dropping it ends the tasks and joins the thread.
pub struct Background {
    handle: tokio::runtime::Handle,
    stop: Option<oneshot::Sender<()>>,
    thread: Option<JoinHandle<()>>,
}

impl Background {
    /// Starts the runtime thread.
    pub fn start() -> std::io::Result<Self> {
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()?;
        let handle = runtime.handle().clone();
        let (stop, stopped) = oneshot::channel::<()>();
        let thread = std::thread::Builder::new()
            .name("rivet-online".into())
            .spawn(move || {
                // Spawned tasks run while this thread waits in `block_on`; an error only means
                // the sender was dropped, which also asks the thread to end.
                let _ = runtime.block_on(stopped);
            })?;
        Ok(Self {
            handle,
            stop: Some(stop),
            thread: Some(thread),
        })
    }

    /// The handle that spawns tasks on the runtime.
    pub fn handle(&self) -> &tokio::runtime::Handle {
        &self.handle
    }
}

impl Drop for Background {
    fn drop(&mut self) {
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}
