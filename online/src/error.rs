//! Everything that can go wrong talking to a target, each with what to do about it.

use std::net::SocketAddr;

/// A failure of an online service.
#[derive(Debug, thiserror::Error)]
pub enum OnlineError {
    /// Nothing listens at the address.
    #[error("{0}: connection refused; is rivet-runtime running there and the port right?")]
    Refused(SocketAddr),
    /// No answer in time.
    #[error("{0}: no answer within {1} ms; check the address and the network")]
    Timeout(SocketAddr, u64),
    /// The connection failed otherwise.
    #[error("{0}: {1}")]
    Io(SocketAddr, std::io::Error),
    /// The device answers Modbus but not Rivet's online services.
    #[error("{0} is a Modbus device but not a Rivet runtime (it does not know function code 100)")]
    NotRivet(SocketAddr),
    /// The target speaks another protocol version.
    #[error(
        "the target speaks online protocol version {theirs}, this client version {ours}; use matching Rivet versions"
    )]
    VersionMismatch {
        /// Ours.
        ours: u16,
        /// The target's.
        theirs: u16,
    },
    /// The target needs a password.
    #[error("the target requires a password for this; give it with --password")]
    PasswordRequired,
    /// The password or token was refused, with the target's words.
    #[error("the target refused the password: {0}")]
    WrongPassword(String),
    /// The target refused the image.
    #[error("the target refused the image: {0}; the old program keeps running")]
    ImageRefused(String),
    /// No variable has that path.
    #[error("unknown variable: {0}")]
    UnknownSymbol(String),
    /// Another refusal, with the target's words.
    #[error("the target refused: {0}")]
    Rejected(String),
    /// A debugging service refused, with the service, the status and the target's words
    /// (`docs/protocol.md` §6: 7 for the wrong state, 2 for no statement start or a refused
    /// condition, 5 for a place outside the frame).
    #[error("the target refused {service} (status {status}): {message}")]
    DebugRefused {
        /// The service's name as `docs/protocol.md` writes it (`BREAK_SET`).
        service: &'static str,
        /// The status number.
        status: u8,
        /// The target's words.
        message: String,
    },
    /// A breakpoint condition too long for the `BREAK_SET` frame, refused before sending.
    #[error(
        "this condition compiles to {bytes} bytes; the target takes at most {limit}: split it or watch a variable instead"
    )]
    ConditionTooLong {
        /// The compiled condition's bytes.
        bytes: usize,
        /// The most the frame carries (`online_protocol::MAX_CONDITION_BYTES`).
        limit: usize,
    },
    /// The runtime does not know `MODBUS_DEVICES` (status 1): it is older than its Modbus
    /// master (`docs/modbus-master.md` §9.1), so the studio shows no device states.
    #[error("this runtime does not report its Modbus devices")]
    ModbusDevicesNotReported,
    /// A Modbus exception.
    #[error("the target answered Modbus exception {0}")]
    Exception(String),
    /// A response that does not follow the protocol.
    #[error("the target's answer does not follow the protocol: {0}")]
    Protocol(String),
}
