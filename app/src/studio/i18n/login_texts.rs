//! The words of logging in to a target that runs another version of the project (the online
//! change dialog), in English and Simplified Chinese: an enum of its own beside
//! [`super::Text`], so each stays one exhaustive `match` of a readable length.

use super::language::Language;
use super::template::fill_template;

/// Every word of the online change login. Adding a variant forces a translation for each
/// language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum LoginText {
    // The three choices and what each does.
    WithOnlineChange,
    WithDownload,
    WithoutChange,
    OnlineChangeHint,
    DownloadHint,
    WithoutChangeHint,
    // The dialog's questions and states.
    Checking,
    Applying,
    Impossible,
    TargetSays,
    WhatWillChange,
    NoDetails,
    // Why an online change is impossible (`docs/protocol.md` §7's reasons).
    ReasonNoProgram,
    ReasonSameProgram,
    ReasonTaskConfiguration,
    ReasonLocatedAreas,
    ReasonMotion,
    ReasonTaskHalted,
    ReasonOther,
    // The headings of the list of changes.
    PousChanged,
    PousAdded,
    PousRemoved,
    VariablesAdded,
    VariablesRemoved,
    VariablesReinitialised,
    PointersCleared,
    ForcesReleased,
    TracesRemoved,
    MotionBlocksDropped,
    OtherChanges,
    // The counts.
    CountCarried,
    CountPointersMoved,
    // Messages after the choice.
    Applied,
    ApplyFailed,
    CheckFailed,
    LoggedInWithoutChange,
}

impl LoginText {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::WithOnlineChange => ("Login with online change", "在线修改并登录"),
            Self::WithDownload => ("Login with download", "下载并登录"),
            Self::WithoutChange => ("Login without change", "不做修改直接登录"),
            Self::OnlineChangeHint => (
                "The new code takes over between two cycles; the tasks keep running and the variables keep their values",
                "新代码在两个周期之间接管；任务继续运行，变量保留其值",
            ),
            Self::DownloadHint => (
                "The target's program stops and the project's replaces it, stopped until you start it (F5); its variables start from their initial values (RETAIN and PERSISTENT kept)",
                "目标上的程序停止并被项目程序替换，替换后保持停止，直到您启动它（F5）；变量从初始值开始（RETAIN 和 PERSISTENT 保留）",
            ),
            Self::WithoutChangeHint => (
                "Log in to the program the target runs; the project's changes are not sent",
                "登录到目标正在运行的程序；不发送项目的修改",
            ),
            Self::Checking => (
                "Sending the program and checking the online change…",
                "正在发送程序并检查在线修改…",
            ),
            Self::Applying => ("Applying the online change…", "正在应用在线修改…"),
            Self::Impossible => (
                "An online change is impossible: {reason}",
                "无法进行在线修改：{reason}",
            ),
            Self::TargetSays => ("The target says: {why}", "目标说明：{why}"),
            Self::WhatWillChange => ("What the online change will do", "在线修改将执行的操作"),
            Self::NoDetails => ("No POU or variable changes", "没有 POU 或变量的修改"),
            Self::ReasonNoProgram => ("the target runs no program", "目标没有运行程序"),
            Self::ReasonSameProgram => {
                ("the target already runs this program", "目标已在运行此程序")
            }
            Self::ReasonTaskConfiguration => ("the task configuration changed", "任务配置已修改"),
            Self::ReasonLocatedAreas => (
                "the sizes of the I/O areas or the Modbus map changed",
                "I/O 区域的大小或 Modbus 映射已修改",
            ),
            Self::ReasonMotion => ("an axis or a cam table changed", "轴或凸轮表已修改"),
            Self::ReasonTaskHalted => (
                "a task is halted; continue it first",
                "有任务处于暂停状态；请先继续运行",
            ),
            Self::ReasonOther => (
                "the target refused it (reason {number})",
                "目标拒绝了它（原因 {number}）",
            ),
            Self::PousChanged => ("POUs whose code changed", "代码已修改的 POU"),
            Self::PousAdded => ("POUs added", "新增的 POU"),
            Self::PousRemoved => ("POUs removed", "删除的 POU"),
            Self::VariablesAdded => (
                "Variables added (they start from their initial values)",
                "新增的变量（从初始值开始）",
            ),
            Self::VariablesRemoved => ("Variables removed", "删除的变量"),
            Self::VariablesReinitialised => (
                "Variables reinitialised (their type changed)",
                "重新初始化的变量（类型已修改）",
            ),
            Self::PointersCleared => (
                "Pointers cleared (what they pointed to is gone)",
                "清零的指针（其指向的变量已不存在）",
            ),
            Self::ForcesReleased => ("Forces released", "释放的强制值"),
            Self::TracesRemoved => ("Traces removed", "删除的跟踪"),
            Self::MotionBlocksDropped => (
                "Motion blocks dropped (their axis goes on with its motion)",
                "丢弃的运动功能块（其轴继续当前运动）",
            ),
            Self::OtherChanges => ("Other changes", "其他修改"),
            Self::CountCarried => ("Variables that keep their values", "保留其值的变量"),
            Self::CountPointersMoved => ("Pointers moved", "移动的指针"),
            Self::Applied => (
                "online change applied after cycle {cycle}: {carried} variables kept their values",
                "在线修改已在第 {cycle} 个周期后应用：{carried} 个变量保留了其值",
            ),
            Self::ApplyFailed => (
                "The online change failed: {reason}. The target kept its program.",
                "在线修改失败：{reason}。目标保留了原有程序。",
            ),
            Self::CheckFailed => (
                "The online change could not be checked: {reason}.",
                "无法检查在线修改：{reason}。",
            ),
            Self::LoggedInWithoutChange => (
                "logged in without change: the target runs another version of the program",
                "已不做修改直接登录：目标运行的是该程序的另一个版本",
            ),
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
