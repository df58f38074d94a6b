//! The runtime as `rivet-runtime` assembles it (scheduler, Modbus server, online services with a
//! password), in process on 127.0.0.1 and a free port, for the benchmarks that drive it through
//! real clients.

use std::net::SocketAddr;
use std::sync::{Arc, Mutex};

use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};
use runtime::online::OnlineServices;
use runtime::scheduler::{Scheduler, SchedulerOptions};

/// Starts the runtime with `options` and `password`; returns the address it serves and its
/// scheduler.
pub async fn start(options: SchedulerOptions, password: &str) -> (SocketAddr, Arc<Scheduler>) {
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Arc::new(Scheduler::spawn(Arc::clone(&areas), options).unwrap());
    let map = MapSlot::new(ModbusMap::default());
    let services = Arc::new(
        OnlineServices::new(Arc::clone(&scheduler), Some(password.to_owned()))
            .with_map(Arc::clone(&map)),
    );
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let address = listener.local_addr().unwrap();
    tokio::spawn(serve(
        listener,
        areas,
        map,
        ServerOptions {
            custom: Some(services.handler()),
            closed: Some(services.closed_handler()),
            ..ServerOptions::default()
        },
    ));
    (address, scheduler)
}
