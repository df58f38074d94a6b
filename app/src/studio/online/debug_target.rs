//! The debugger's door to the target (`docs/protocol.md` §6).

use super::Online;
use crate::studio::debug::{DebugCommand, DebugTarget};

impl DebugTarget for Online {
    /// The session offers no debugging service yet: the runtime answers every debugging
    /// request with status 7, as a `--debug off` runtime does, so every command is refused
    /// here and the studio says the target does not offer debugging. The session's calls of
    /// `docs/protocol.md` §6 replace this refusal when the online client offers them.
    fn debug(&mut self, _command: DebugCommand) -> bool {
        false
    }
}
