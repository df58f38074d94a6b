//! Keeping the RTU slave's serial port open by its path.

use std::convert::Infallible;
use std::path::Path;
use std::sync::Mutex;
use std::time::Duration;

use crate::areas::LocatedAreas;
use crate::modbus::backoff::Backoff;
use crate::modbus::map_slot::MapSlot;
use crate::modbus::rtu_slave::counters::RtuSlaveCounters;
use crate::modbus::rtu_slave::serve::{RtuSlaveOptions, serve_rtu};
use crate::serial::{SerialOpenError, SerialSettings, open_port};

/// What happened to the port, for the caller to tell its operator.
#[derive(Debug)]
pub enum RtuPortEvent<'a> {
    /// The port is open and being served.
    Opened,
    /// The port could not be opened; the next attempt is in `retry_in`.
    OpenFailed {
        /// Why, with the port's path.
        error: &'a SerialOpenError,
        /// The wait before the next attempt.
        retry_in: Duration,
    },
    /// The open port ended (end of file: the device went away) or failed with `error`; it is
    /// opened again in `retry_in`.
    Closed {
        /// The I/O error, or `None` at end of file.
        error: Option<&'a std::io::Error>,
        /// The wait before the next attempt.
        retry_in: Duration,
    },
}

/// Serves the serial port at `path` with `settings` as the RTU slave of `options`, for ever (it
/// never returns, which its type says, so a caller cannot poll it after an end):
/// when the port cannot be opened or closes, `report` is told, and the port is opened again by
/// its path after the back-off of `docs/modbus-master.md` §6.8 (100 ms doubling to 5 s; back to
/// 100 ms once a frame has arrived), so a USB adapter that comes back is served again.
pub async fn serve_rtu_port(
    path: &Path,
    settings: &SerialSettings,
    areas: &Mutex<LocatedAreas>,
    map: &MapSlot,
    options: &RtuSlaveOptions,
    counters: &RtuSlaveCounters,
    mut report: impl FnMut(RtuPortEvent<'_>),
) -> Infallible {
    let mut backoff = Backoff::default();
    loop {
        let port = match open_port(path, settings) {
            Ok(port) => port,
            Err(error) => {
                let retry_in = backoff.next_wait();
                report(RtuPortEvent::OpenFailed {
                    error: &error,
                    retry_in,
                });
                tokio::time::sleep(retry_in).await;
                continue;
            }
        };
        report(RtuPortEvent::Opened);
        let frames_before = counters.counts().frames();
        let served = serve_rtu(port, areas, map, options, counters).await;
        if counters.counts().frames() > frames_before {
            backoff.reset();
        }
        let retry_in = backoff.next_wait();
        report(RtuPortEvent::Closed {
            error: served.as_ref().err(),
            retry_in,
        });
        tokio::time::sleep(retry_in).await;
    }
}
