//! Modbus RTU over socat's virtual serial cables (`peers::SocatPair`, 8N1 and 8N2: this
//! machine's pseudo-terminals refuse parity): the runtime's serial ports,
//! `rivet-runtime --modbus-rtu` as a slave to mbpoll (`docs/modbus-master.md` §7, §10 test 4),
//! and the pymodbus peer the master's tests use, over TCP and RTU.

mod pymodbus_peer;
mod serial_ports;
mod slave;

use std::path::Path;
use std::time::{Duration, Instant};

use runtime::serial::{SerialSettings, open_port};
use tokio_serial::SerialStream;

/// Opens a pty end, trying again for a while when its lock is taken: a process that another
/// test of this binary forks at that moment holds a copy of every open descriptor (and so the
/// `flock` of a port just closed) until it runs its program.
pub fn open_when_free(path: &Path, format: &str) -> SerialStream {
    let settings: SerialSettings = format.parse().unwrap();
    let deadline = Instant::now() + Duration::from_secs(2);
    loop {
        match open_port(path, &settings) {
            Ok(port) => return port,
            Err(error) if Instant::now() > deadline => panic!("{error}"),
            Err(_) => std::thread::sleep(Duration::from_millis(10)),
        }
    }
}
