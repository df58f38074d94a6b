//! The built-in simulator: the soft PLC runtime embedded in the studio, serving Modbus TCP and
//! the online services on a loopback port the operating system picks.

use std::net::SocketAddr;
use std::sync::{Arc, Mutex};

use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};
use runtime::online::OnlineServices;
use runtime::scheduler::{Scheduler, SchedulerOptions};
use thiserror::Error;

/// Why the simulator could not start.
#[derive(Debug, Error)]
pub enum SimulatorError {
    /// No loopback port could be opened.
    #[error("the simulator cannot listen on the loopback interface: {0}")]
    Listen(#[from] std::io::Error),
    /// The runtime's task threads could not start.
    #[error("the simulator's runtime did not start: {0}")]
    Runtime(String),
}

/// A running simulator. It starts with no program; the studio downloads one at login as it
/// would to a controller. Dropping it stops the server and the tasks.
pub struct Simulator {
    address: SocketAddr,
    server: tokio::task::JoinHandle<()>,
    scheduler: Arc<Scheduler>,
}

impl Simulator {
    /// Starts a simulator whose server runs on `handle`.
    pub fn start(handle: &tokio::runtime::Handle) -> Result<Self, SimulatorError> {
        let listener = std::net::TcpListener::bind("127.0.0.1:0")?;
        listener.set_nonblocking(true)?;
        let address = listener.local_addr()?;
        let areas = Arc::new(Mutex::new(LocatedAreas::default()));
        let scheduler = Arc::new(
            Scheduler::spawn(Arc::clone(&areas), SchedulerOptions::default())
                .map_err(|error| SimulatorError::Runtime(error.to_string()))?,
        );
        let map = MapSlot::new(ModbusMap::default());
        let services =
            Arc::new(OnlineServices::new(Arc::clone(&scheduler), None).with_map(Arc::clone(&map)));
        let options = ServerOptions {
            custom: Some(services.handler()),
            closed: Some(services.closed_handler()),
            ..ServerOptions::default()
        };
        let server = handle.spawn(async move {
            // Registering the socket needs the runtime's reactor, so it happens on the runtime.
            match tokio::net::TcpListener::from_std(listener) {
                Ok(listener) => {
                    let _ = serve(listener, areas, map, options).await;
                }
                Err(_) => {
                    // The session's connection attempt reports the failure to the user.
                }
            }
        });
        Ok(Self {
            address,
            server,
            scheduler,
        })
    }

    /// Where the simulator listens.
    pub fn address(&self) -> SocketAddr {
        self.address
    }
}

impl Drop for Simulator {
    fn drop(&mut self) {
        self.server.abort();
        // The tasks stop with the scheduler's last reference; a session still holding one
        // through the services ends when the server's connections close.
        let _ = self.scheduler.stop();
    }
}
