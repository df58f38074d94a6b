//! Interface text in English and Simplified Chinese.

use serde::{Deserialize, Serialize};

/// The interface language, chosen in the settings and remembered between runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Language {
    /// English.
    #[default]
    English,
    /// Simplified Chinese.
    SimplifiedChinese,
}

impl Language {
    /// Every language, in the order the settings menu lists them.
    pub const ALL: [Self; 2] = [Self::English, Self::SimplifiedChinese];

    /// The language's own name, shown in the settings menu.
    pub fn native_name(self) -> &'static str {
        match self {
            Self::English => "English",
            Self::SimplifiedChinese => "简体中文",
        }
    }
}

/// Every piece of interface text. Adding a variant forces a translation for each language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum Text {
    File,
    Open,
    Save,
    SaveAs,
    Quit,
    Settings,
    LanguageMenu,
    Theme,
    Dark,
    Light,
    Help,
    About,
    AboutText,
    Devices,
    TaskConfiguration,
    Application,
    IoAreas,
    ModbusDevices,
    Axes,
    NoProjectOpen,
    NoProjectHint,
    OpenObjectHint,
    CouldNotOpen,
    Messages,
    Saved,
    NothingToSave,
    SaveFailed,
    SaveAsRefused,
    Opened,
    ReadOnly,
    Declarations,
    Implementation,
    Method,
    Property,
    Action,
    NoImplementation,
    Warnings,
    ProblemsFound,
    Close,
    CamMaster,
    CamSlave,
    CompileFormat,
    Segments,
    Law,
    MasterFrom,
    MasterTo,
    SlaveFrom,
    SlaveTo,
    VelocityEnd,
    AccelerationEnd,
    Points,
    Tappets,
    Track,
    Name,
    Position,
    PositivePass,
    NegativePass,
    NoAction,
    SwitchOn,
    SwitchOff,
    Invert,
    OnFor,
}

impl Text {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::File => ("File", "文件"),
            Self::Open => ("Open project…", "打开项目…"),
            Self::Save => ("Save project", "保存项目"),
            Self::SaveAs => ("Save project as…", "项目另存为…"),
            Self::Quit => ("Quit", "退出"),
            Self::Settings => ("Settings", "设置"),
            Self::LanguageMenu => ("Language", "语言"),
            Self::Theme => ("Theme", "主题"),
            Self::Dark => ("Dark", "深色"),
            Self::Light => ("Light", "浅色"),
            Self::Help => ("Help", "帮助"),
            Self::About => ("About Rivet", "关于 Rivet"),
            Self::AboutText => (
                "Rivet: an engineering studio for IEC 61131-3 controllers",
                "Rivet：IEC 61131-3 控制器工程开发环境",
            ),
            Self::Devices => ("Devices", "设备"),
            Self::TaskConfiguration => ("Task configuration", "任务配置"),
            Self::Application => ("Application", "应用"),
            Self::IoAreas => ("I/O", "输入/输出"),
            Self::ModbusDevices => ("Modbus TCP devices", "Modbus TCP 设备"),
            Self::Axes => ("Axes", "轴"),
            Self::NoProjectOpen => ("No project is open", "未打开项目"),
            Self::NoProjectHint => (
                "Open a project folder with File > Open project…",
                "请通过 文件 > 打开项目… 打开项目文件夹",
            ),
            Self::OpenObjectHint => (
                "Double-click an object in the device tree to open it",
                "双击设备树中的对象以打开",
            ),
            Self::CouldNotOpen => ("Could not open the project", "无法打开项目"),
            Self::Messages => ("Messages", "消息"),
            Self::Saved => ("Saved", "已保存"),
            Self::NothingToSave => ("Saved: no file needed changing", "已保存：无文件需要更改"),
            Self::SaveFailed => ("Saving failed", "保存失败"),
            Self::SaveAsRefused => (
                "That folder already holds a project; choose an empty folder",
                "该文件夹已包含项目，请选择空文件夹",
            ),
            Self::Opened => ("Opened", "已打开"),
            Self::ReadOnly => ("read-only", "只读"),
            Self::Declarations => ("Declarations", "声明"),
            Self::Implementation => ("Implementation", "实现"),
            Self::Method => ("Method", "方法"),
            Self::Property => ("Property", "属性"),
            Self::Action => ("Action", "动作"),
            Self::NoImplementation => ("No implementation", "无实现"),
            Self::Warnings => ("warning(s)", "个警告"),
            Self::ProblemsFound => ("problem(s) found", "个问题"),
            Self::Close => ("Close", "关闭"),
            Self::CamMaster => ("Master", "主轴"),
            Self::CamSlave => ("Slave", "从轴"),
            Self::CompileFormat => ("Compile format", "编译格式"),
            Self::Segments => ("Segments", "段"),
            Self::Law => ("Law", "运动规律"),
            Self::MasterFrom => ("Master from", "主轴起点"),
            Self::MasterTo => ("Master to", "主轴终点"),
            Self::SlaveFrom => ("Slave from", "从轴起点"),
            Self::SlaveTo => ("Slave to", "从轴终点"),
            Self::VelocityEnd => ("V end", "终点速度"),
            Self::AccelerationEnd => ("A end", "终点加速度"),
            Self::Points => ("Points", "点"),
            Self::Tappets => ("Tappets", "凸轮开关"),
            Self::Track => ("Track", "轨道"),
            Self::Name => ("Name", "名称"),
            Self::Position => ("Position", "位置"),
            Self::PositivePass => ("Positive pass", "正向通过"),
            Self::NegativePass => ("Negative pass", "负向通过"),
            Self::NoAction => ("No action", "无动作"),
            Self::SwitchOn => ("Switch on", "接通"),
            Self::SwitchOff => ("Switch off", "断开"),
            Self::Invert => ("Invert", "取反"),
            Self::OnFor => ("On for", "接通时长"),
        };
        match language {
            Language::English => english,
            Language::SimplifiedChinese => chinese,
        }
    }
}
