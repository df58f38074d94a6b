//! The services of the protocol with their numbers (`docs/protocol.md` §3).

/// A service: the byte after the function code in a request and its response.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Service {
    /// `IDENTIFY`: the protocol version, the runtime and its program.
    Identify = 0x01,
    /// `LOGIN`: a token for the password.
    Login = 0x02,
    /// `LOGOUT`: the connection's token ends.
    Logout = 0x03,
    /// `DOWNLOAD_BEGIN`: a new transfer of an image.
    DownloadBegin = 0x10,
    /// `DOWNLOAD_CHUNK`: some bytes of the image.
    DownloadChunk = 0x11,
    /// `DOWNLOAD_COMMIT`: check and load the transferred image.
    DownloadCommit = 0x12,
    /// `DOWNLOAD_ABORT`: drop the transfer.
    DownloadAbort = 0x13,
    /// `ONLINE_CHANGE_CHECK`: whether the transferred image can take over online (§7).
    OnlineChangeCheck = 0x14,
    /// `ONLINE_CHANGE_DETAILS`: what the check found (§7).
    OnlineChangeDetails = 0x15,
    /// `ONLINE_CHANGE_APPLY`: the switch to the checked image between two cycles (§7).
    OnlineChangeApply = 0x16,
    /// `START`: run the program.
    Start = 0x20,
    /// `STOP`: stop the program.
    Stop = 0x21,
    /// `RESET`: reset the program's memory.
    Reset = 0x22,
    /// `RESOLVE`: the place and type of a variable's path.
    Resolve = 0x30,
    /// `READ`: one snapshot of some places.
    Read = 0x31,
    /// `WRITE`: values written once, between two cycles.
    Write = 0x32,
    /// `FORCE`: values held until released.
    Force = 0x33,
    /// `UNFORCE`: forces released.
    Unforce = 0x34,
    /// `FORCES`: the forced places with their values.
    Forces = 0x35,
    /// `ENUMERATION`: the values of an enumeration-typed variable's type by name.
    Enumeration = 0x36,
    /// `TRACE_CONFIGURE`: a new trace and its first places.
    TraceConfigure = 0x40,
    /// `TRACE_ARM`: recording starts.
    TraceArm = 0x41,
    /// `TRACE_STATUS`: where the trace is.
    TraceStatus = 0x42,
    /// `TRACE_UPLOAD`: recorded samples.
    TraceUpload = 0x43,
    /// `TRACE_ADD`: more places for the configured trace.
    TraceAdd = 0x44,
    /// `TASKS`: statistics of the tasks.
    Tasks = 0x50,
    /// `FAULTS`: the faults recorded.
    Faults = 0x51,
    /// `MODBUS_DEVICES`: the state and counters of the Modbus devices the runtime masters.
    ModbusDevices = 0x52,
    /// `DEBUG_ATTACH`: the debug session created or taken over (version 3).
    DebugAttach = 0x60,
    /// `DEBUG_DETACH`: the debug session ended.
    DebugDetach = 0x61,
    /// `BREAK_SET`: a breakpoint set.
    BreakSet = 0x62,
    /// `BREAK_CLEAR`: a breakpoint, or every one, cleared.
    BreakClear = 0x63,
    /// `BREAK_LIST`: the session's breakpoints.
    BreakList = 0x64,
    /// `HALT_STATE`: the session and what every task is doing.
    HaltState = 0x65,
    /// `STEP`: a halted task goes on to the next statement start of a kind.
    Step = 0x66,
    /// `RUN_TO`: a halted task goes on to a statement start.
    RunTo = 0x67,
    /// `CONTINUE`: a halted task goes on.
    Continue = 0x68,
    /// `HALT`: a task halts at its next statement start.
    Halt = 0x69,
    /// `STACK`: a halted task's call stack.
    Stack = 0x6A,
    /// `FRAME_READ`: bytes of a halted task's frame.
    FrameRead = 0x6B,
    /// `FRAME_WRITE`: bytes written into a halted task's frame.
    FrameWrite = 0x6C,
    /// `FLOW_CONFIGURE`: which POUs' statements are recorded.
    FlowConfigure = 0x6D,
    /// `FLOW_READ`: which statements of a POU ran.
    FlowRead = 0x6E,
}

impl Service {
    /// Every service, in the order of their numbers.
    pub const ALL: [Service; 43] = [
        Service::Identify,
        Service::Login,
        Service::Logout,
        Service::DownloadBegin,
        Service::DownloadChunk,
        Service::DownloadCommit,
        Service::DownloadAbort,
        Service::OnlineChangeCheck,
        Service::OnlineChangeDetails,
        Service::OnlineChangeApply,
        Service::Start,
        Service::Stop,
        Service::Reset,
        Service::Resolve,
        Service::Read,
        Service::Write,
        Service::Force,
        Service::Unforce,
        Service::Forces,
        Service::Enumeration,
        Service::TraceConfigure,
        Service::TraceArm,
        Service::TraceStatus,
        Service::TraceUpload,
        Service::TraceAdd,
        Service::Tasks,
        Service::Faults,
        Service::ModbusDevices,
        // The debugging services (version 3, §6).
        Service::DebugAttach,
        Service::DebugDetach,
        Service::BreakSet,
        Service::BreakClear,
        Service::BreakList,
        Service::HaltState,
        Service::Step,
        Service::RunTo,
        Service::Continue,
        Service::Halt,
        Service::Stack,
        Service::FrameRead,
        Service::FrameWrite,
        Service::FlowConfigure,
        Service::FlowRead,
    ];

    /// The service's number on the wire.
    pub fn number(self) -> u8 {
        self as u8
    }

    /// The service with `number`, if protocol version 3 has one.
    pub fn from_number(number: u8) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|service| service.number() == number)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_service_is_found_by_its_number_and_no_other_number_names_one() {
        for service in Service::ALL {
            assert_eq!(Service::from_number(service.number()), Some(service));
        }
        let known = (0..=u8::MAX)
            .filter(|&number| Service::from_number(number).is_some())
            .count();
        assert_eq!(known, Service::ALL.len());
    }
}
