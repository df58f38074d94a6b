//! Why a Modbus TCP device's connection could not be opened: the detail its status shows
//! (`docs/modbus-master.md` §6.9) until a round gets through.

/// Why [`connect`](super::link_tcp) failed; its `Display` is the status detail users see.
#[derive(Debug, thiserror::Error)]
pub(crate) enum ConnectError {
    /// The device is on a serial line, which a TCP link never serves.
    #[error("'{device}' is not a TCP device")]
    NotTcp {
        /// The device's name.
        device: String,
    },
    /// The peer answered the connection with a refusal (nothing listens on the port).
    #[error("connection refused by {peer}")]
    Refused {
        /// The peer, `host:port`.
        peer: String,
    },
    /// Another failure of the connection, with the operating system's reason.
    #[error("cannot connect to {peer}: {source}")]
    Failed {
        /// The peer, `host:port`.
        peer: String,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// No connection within the time allowed.
    #[error("cannot connect to {peer} within {limit_ms} ms")]
    TimedOut {
        /// The peer, `host:port`.
        peer: String,
        /// The time allowed, in milliseconds.
        limit_ms: u128,
    },
}
