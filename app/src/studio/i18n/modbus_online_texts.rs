//! The words of the runtime Modbus devices' online display (`docs/modbus-master.md` §9.2): the
//! device states, `MB_ErrorCodes` as a PLC engineer reads them, the counters and the status
//! line, in English and Simplified Chinese. An enum of its own beside [`super::Text`], so each
//! stays one exhaustive `match` of a readable length.

use super::language::Language;
use super::template::fill_template;

/// Every word of the Modbus devices' online display. Adding a variant forces a translation for
/// each language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum ModbusOnlineText {
    /// The heading of the device editor's read-only part.
    Online,
    StateLabel,
    Communicating,
    NotYetConnected,
    AnsweringWithErrors,
    NotAnswering,
    SerialPortError,
    MasterOff,
    ProgramNotRunning,
    NoReportYet,
    NotInProgram,
    NotReported,
    Refused,
    LastError,
    ErrorDetail,
    LastErrorAgo,
    LastException,
    NoException,
    Rounds,
    Requests,
    Errors,
    ConsecutiveErrors,
    Overruns,
    LastResponse,
    NoResponseYet,
    Milliseconds,
    Seconds,
    Minutes,
    Hours,
    PollingOne,
    PollingMany,
    ErrorCodeUnknown,
    ResponseSuccess,
    IllegalFunction,
    IllegalDataAddress,
    IllegalDataValue,
    SlaveDeviceFailure,
    Acknowledge,
    SlaveDeviceBusy,
    NegativeAcknowledge,
    MemoryParityError,
    GatewayPathUnavailable,
    GatewayDeviceFailedToRespond,
    ResponseTimeout,
    ResponseCrcFail,
    ResponseWrongSlave,
    ResponseWrongFunctionCode,
    TcpCommunicationError,
    ResponseInvalidData,
    ResponseInvalidProtocol,
    ResponseInvalidHeader,
    SerialPortFailed,
    NotYetPolled,
}

impl ModbusOnlineText {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::Online => ("Online", "在线"),
            Self::StateLabel => ("State", "状态"),
            Self::Communicating => ("Communicating", "通信正常"),
            Self::NotYetConnected => ("Not yet connected", "尚未连接"),
            Self::AnsweringWithErrors => ("Answering with errors", "应答异常"),
            Self::NotAnswering => ("Not answering", "无应答"),
            Self::SerialPortError => ("Serial port error", "串口错误"),
            Self::MasterOff => (
                "Disabled: the runtime's Modbus master is off",
                "已停用：运行时的 Modbus 主站已关闭",
            ),
            Self::ProgramNotRunning => (
                "Stopped: the program is not running, so no I/O data is exchanged",
                "停止：程序未运行，不交换 I/O 数据",
            ),
            Self::NoReportYet => (
                "Not yet connected: no report from the runtime yet",
                "尚未连接：还没有收到运行时的报告",
            ),
            Self::NotInProgram => (
                "Not in the program on the target: build and download to poll it",
                "不在目标上的程序中：编译并下载后才会轮询",
            ),
            Self::NotReported => (
                "This runtime version does not report the Modbus devices' states",
                "该运行时版本不支持报告 Modbus 设备状态",
            ),
            Self::Refused => (
                "The runtime refused to report the Modbus devices' states: {reason}",
                "运行时拒绝报告 Modbus 设备状态：{reason}",
            ),
            Self::LastError => ("Last error", "最近错误"),
            Self::ErrorDetail => ("{error}: {detail}", "{error}：{detail}"),
            Self::LastErrorAgo => ("{error}, {age} ago", "{error}，{age}前"),
            Self::LastException => ("Last exception code", "最近异常码"),
            Self::NoException => ("0 (none)", "0（无）"),
            Self::Rounds => ("Rounds", "轮询次数"),
            Self::Requests => ("Requests", "请求数"),
            Self::Errors => ("Errors", "错误数"),
            Self::ConsecutiveErrors => ("Consecutive errors", "连续错误数"),
            Self::Overruns => ("Overruns", "轮询超限次数"),
            Self::LastResponse => ("Last response time", "最近响应时间"),
            Self::NoResponseYet => ("None yet", "尚无应答"),
            Self::Milliseconds => ("{value} ms", "{value} 毫秒"),
            Self::Seconds => ("{value} s", "{value} 秒"),
            Self::Minutes => ("{value} min", "{value} 分钟"),
            Self::Hours => ("{value} h", "{value} 小时"),
            Self::PollingOne => (
                "Simulator: polling {count} Modbus device",
                "仿真器：正在轮询 {count} 个 Modbus 设备",
            ),
            Self::PollingMany => (
                "Simulator: polling {count} Modbus devices",
                "仿真器：正在轮询 {count} 个 Modbus 设备",
            ),
            Self::ErrorCodeUnknown => ("Error code {code}", "错误代码 {code}"),
            Self::ResponseSuccess => ("No error", "无错误"),
            Self::IllegalFunction => (
                "The device does not support this function code",
                "设备不支持该功能码",
            ),
            Self::IllegalDataAddress => (
                "The device has no such address",
                "非法数据地址（设备无此地址）",
            ),
            Self::IllegalDataValue => ("The device refused the value", "设备拒绝了该数值"),
            Self::SlaveDeviceFailure => (
                "The device failed while serving the request",
                "设备处理请求时发生故障",
            ),
            Self::Acknowledge => (
                "The device accepted the request but needs longer",
                "设备已接受请求，但需要更长时间处理",
            ),
            Self::SlaveDeviceBusy => ("The device is busy", "设备忙"),
            Self::NegativeAcknowledge => (
                "The device cannot carry out the request",
                "设备无法执行该请求",
            ),
            Self::MemoryParityError => (
                "The device found a parity error in its memory",
                "设备检测到存储器奇偶校验错误",
            ),
            Self::GatewayPathUnavailable => (
                "The gateway has no path to the device",
                "网关没有通往设备的路径",
            ),
            Self::GatewayDeviceFailedToRespond => (
                "The device behind the gateway did not answer",
                "网关后的设备无应答",
            ),
            Self::ResponseTimeout => ("No answer within the timeout", "响应超时"),
            Self::ResponseCrcFail => ("The answer's CRC is wrong", "应答的 CRC 校验错误"),
            Self::ResponseWrongSlave => ("The answer came from another unit", "应答来自其他从站"),
            Self::ResponseWrongFunctionCode => {
                ("The answer has another function code", "应答的功能码不符")
            }
            Self::TcpCommunicationError => {
                ("No TCP connection to the device", "与设备的 TCP 连接失败")
            }
            Self::ResponseInvalidData => ("The answer's data is invalid", "应答数据无效"),
            Self::ResponseInvalidProtocol => ("The answer is not Modbus", "应答不是 Modbus 报文"),
            Self::ResponseInvalidHeader => ("The answer's header is invalid", "应答报文头无效"),
            Self::SerialPortFailed => ("The serial port cannot be used", "串口无法使用"),
            Self::NotYetPolled => ("Not polled yet", "尚未轮询"),
        };
        match language {
            Language::English => english,
            Language::SimplifiedChinese => chinese,
        }
    }

    /// The text in `language` with its `{key}` placeholders filled from `values`.
    pub fn fill(self, language: Language, values: &[(&str, &str)]) -> String {
        fill_template(self.get(language), values)
    }
}
