//! The words of debugging (the Debug menu, the Breakpoints and Call stack panes, the breakpoint
//! dialog), in English and Simplified Chinese: an enum of its own beside [`super::Text`].

use super::language::Language;
use super::template::fill_template;

/// Every word of debugging. Adding a variant forces a translation for each language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum DebugText {
    Debug,
    ToggleBreakpoint,
    Continue,
    StepOver,
    StepInto,
    StepOut,
    RunToCursor,
    HaltTask,
    HaltAll,
    FlowControl,
    Breakpoints,
    CallStack,
    NoBreakpoints,
    NoHaltedTask,
    EditBreakpoint,
    Remove,
    RemoveAll,
    GoTo,
    Condition,
    HitCount,
    HitAlways,
    HitEqual,
    HitMultipleOf,
    HitAtLeast,
    HitTarget,
    Instance,
    Task,
    EveryInstance,
    EveryTask,
    Ok,
    Cancel,
    BreakpointAt,
    WaitingBeneath,
    WaitingBeneathAHaltedTask,
    Halted,
    NoStatementAfter,
    NoElementStatement,
    GraphicalNetwork,
    GraphicalElement,
    GraphicalNamedElement,
    GraphicalChartElement,
    GraphicalStep,
    GraphicalTransition,
    LogInToDebug,
    NotHalted,
    TargetRefusesDebugging,
    NoCaret,
    SummaryCondition,
    SummaryHits,
    BreakpointNotSet,
    BreakpointConditionError,
    BreakpointNoInstance,
    BreakpointNoTask,
    BreakpointOtherBuild,
    DebugRefused,
}

impl DebugText {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::Debug => ("Debug", "调试"),
            Self::ToggleBreakpoint => ("Toggle breakpoint", "切换断点"),
            Self::Continue => ("Continue", "继续"),
            Self::StepOver => ("Step over", "单步跳过"),
            Self::StepInto => ("Step into", "单步进入"),
            Self::StepOut => ("Step out", "单步跳出"),
            Self::RunToCursor => ("Run to cursor", "运行到光标处"),
            Self::HaltTask => ("Halt task", "暂停任务"),
            Self::HaltAll => ("Halt all", "全部暂停"),
            Self::FlowControl => ("Flow control", "流程控制"),
            Self::Breakpoints => ("Breakpoints", "断点"),
            Self::CallStack => ("Call stack", "调用堆栈"),
            Self::NoBreakpoints => (
                "No breakpoints (F9 on a statement sets one)",
                "没有断点（在语句上按 F9 设置）",
            ),
            Self::NoHaltedTask => ("No task is halted", "没有暂停的任务"),
            Self::EditBreakpoint => ("Edit…", "编辑…"),
            Self::Remove => ("Remove", "删除"),
            Self::RemoveAll => ("Remove all", "全部删除"),
            Self::GoTo => ("Go to", "转到"),
            Self::Condition => ("Break when true", "条件为真时暂停"),
            Self::HitCount => ("Hit count", "命中次数"),
            Self::HitAlways => ("Always", "总是"),
            Self::HitEqual => ("Equal to", "等于"),
            Self::HitMultipleOf => ("A multiple of", "的倍数"),
            Self::HitAtLeast => ("Greater than or equal to", "大于或等于"),
            Self::HitTarget => ("Hit count target", "命中次数目标"),
            Self::Instance => ("Only in instance", "仅在实例中"),
            Self::Task => ("Only in task", "仅在任务中"),
            Self::EveryInstance => ("every instance", "所有实例"),
            Self::EveryTask => ("every task", "所有任务"),
            Self::Ok => ("OK", "确定"),
            Self::Cancel => ("Cancel", "取消"),
            Self::BreakpointAt => ("Breakpoint at {place}", "位于 {place} 的断点"),
            Self::WaitingBeneath => ("{task}: waiting beneath {halted}", "{task}：等待 {halted}"),
            Self::WaitingBeneathAHaltedTask => (
                "{task}: waiting beneath a halted task",
                "{task}：等待一个已暂停的任务",
            ),
            Self::Halted => ("{task}: halted", "{task}：已暂停"),
            Self::NoStatementAfter => (
                "no statement at or after line {line} of {file}",
                "{file} 第 {line} 行及其后没有语句",
            ),
            Self::NoElementStatement => (
                "{place} has no statement of its own (an operator box such as ADD is computed in the statement of what it feeds, an empty network has none): put the breakpoint on the network, a coil, a box or an assignment",
                "{place} 没有自己的语句（ADD 等运算框在其所连接元素的语句中计算，空网络没有语句）：请将断点设在网络、线圈、功能块或赋值上",
            ),
            Self::GraphicalNetwork => ("{body}: network {network}", "{body}：网络 {network}"),
            Self::GraphicalElement => (
                "{body}: network {network}, element {element}",
                "{body}：网络 {network}，元素 {element}",
            ),
            Self::GraphicalNamedElement => (
                "{body}: network {network}, {name}",
                "{body}：网络 {network}，{name}",
            ),
            Self::GraphicalChartElement => ("{body}: {name}", "{body}：{name}"),
            Self::GraphicalStep => ("{body}: step {name}", "{body}：步 {name}"),
            Self::GraphicalTransition => {
                ("{body}: transition {condition}", "{body}：转换 {condition}")
            }
            Self::LogInToDebug => ("log in to debug (Alt+F8)", "请先登录再调试 (Alt+F8)"),
            Self::NotHalted => ("no task is halted", "没有暂停的任务"),
            Self::BreakpointNotSet => (
                "breakpoint {place} not set: {reason}",
                "断点 {place} 未设置：{reason}",
            ),
            Self::BreakpointConditionError => (
                "breakpoint {place} not set: the condition '{condition}' does not compile: {reason}",
                "断点 {place} 未设置：条件“{condition}”无法编译：{reason}",
            ),
            Self::BreakpointNoInstance => (
                "breakpoint {place} not set: '{instance}' is no instance this statement runs on",
                "断点 {place} 未设置：“{instance}”不是执行此语句的实例",
            ),
            Self::BreakpointNoTask => (
                "breakpoint {place} not set: the program has no task '{task}'",
                "断点 {place} 未设置：程序中没有任务“{task}”",
            ),
            Self::BreakpointOtherBuild => (
                "breakpoint {place} not set: its condition belongs to another build than the one logged in with; log in again",
                "断点 {place} 未设置：其条件属于与登录时不同的编译结果，请重新登录",
            ),
            Self::DebugRefused => ("debugging: {reason}", "调试：{reason}"),
            Self::TargetRefusesDebugging => (
                "the target does not offer debugging",
                "目标设备不提供调试功能",
            ),
            Self::NoCaret => (
                "put the caret on a statement of a Structured Text body, or select a network, element, step or transition of a graphical body, first",
                "请先将光标放在结构化文本实现的语句上，或在图形实现中选择网络、元素、步或转换",
            ),
            Self::SummaryCondition => ("when {condition}", "当 {condition}"),
            Self::SummaryHits => ("hit count {mode} {target}", "命中次数{mode} {target}"),
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
