//! The refusals the studio gives in the interface language: of the project model's edits, of
//! typed literals and values, of the tree's and the task editor's gestures, and the build's own
//! failures. An enum of its own beside [`super::Text`], so each stays one exhaustive `match` of
//! a readable length.

use super::language::Language;
use super::template::fill_template;

/// Every refusal text. Adding a variant forces a translation for each language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum RefusalText {
    EditNoSuchObject,
    EditNoSuchFolder,
    EditNoSuchMember,
    WhatMethod,
    WhatProperty,
    WhatAction,
    EditIndexOutOfRange,
    EditInvalidName,
    EditDuplicateName,
    EditInvalidObject,
    EditNotText,
    EditBadTextRange,
    EditMoveIntoItself,
    EditKindChanged,
    EditNotNetworks,
    EditNotChart,
    EditNetworkRangeOutOfRange,
    LitUnknownBase,
    LitNoDigits,
    LitBadDigitBinary,
    LitBadDigitOctal,
    LitBadDigitHex,
    LitBadDigitDecimal,
    LitNotANumber,
    LitNoValue,
    LitNoUnit,
    LitNoNumber,
    LitBadNumber,
    LitUnknownUnit,
    LitNotADate,
    LitNoSuchDate,
    LitNotATimeOfDay,
    LitNotADateAndTime,
    LitNoHash,
    RefuseEmptyName,
    RefuseKeyword,
    RefuseNoReturnType,
    RefuseNoPropertyType,
    RefuseNoMembers,
    RefuseSfcNotHere,
    RefuseSerialPortInUse,
    TimeEmpty,
    TimeTooLong,
    TimeNotWholeMicros,
    TimeNotPositive,
    TimeTooLongAtMost,
    NotATriggerVariable,
    NotAPriority,
    NotASensitivity,
    ChooseProgramToCall,
    NoProgramNamed,
    AlreadyCalls,
    ValueNotAString,
    ValueTooLong,
    ValueNotWritable,
    ValueNotAValue,
    ValueBadLiteral,
    ValueOutOfRange,
    BuildNoThread,
    BuildHiddenErrors,
    BuildCompilerStopped,
}

impl RefusalText {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::EditNoSuchObject => (
                "there is no object named '{name}'",
                "没有名为“{name}”的对象",
            ),
            Self::EditNoSuchFolder => ("there is no folder '{name}'", "没有文件夹“{name}”"),
            Self::EditNoSuchMember => (
                "'{pou}' has no {what} named '{name}'",
                "“{pou}”没有名为“{name}”的{what}",
            ),
            Self::WhatMethod => ("method", "方法"),
            Self::WhatProperty => ("property", "属性"),
            Self::WhatAction => ("action", "动作"),
            Self::EditIndexOutOfRange => (
                "position {index} is out of range (the list has {len} entries)",
                "位置 {index} 超出范围（列表有 {len} 个条目）",
            ),
            Self::EditInvalidName => (
                "'{name}' is not a valid name: use letters, digits and '_', starting with a letter or '_'",
                "“{name}”不是有效名称：请使用字母、数字和“_”，并以字母或“_”开头",
            ),
            Self::EditDuplicateName => {
                ("the name '{name}' is already used", "名称“{name}”已被使用")
            }
            Self::EditInvalidObject => ("{reason}", "{reason}"),
            Self::EditNotText => (
                "the body of {name} is not Structured Text",
                "{name} 的实现不是结构化文本",
            ),
            Self::EditBadTextRange => (
                "the range {start}..{end} is not a valid range of a text of {len} bytes",
                "范围 {start}..{end} 不是 {len} 字节文本中的有效范围",
            ),
            Self::EditMoveIntoItself => {
                ("a folder cannot be moved into itself", "文件夹不能移入自身")
            }
            Self::EditKindChanged => ("'{name}' cannot change its kind", "“{name}”不能更改其种类"),
            Self::EditNotNetworks => (
                "the body of {name} is not a Ladder or Function Block Diagram",
                "{name} 的实现不是梯形图或功能块图",
            ),
            Self::EditNotChart => (
                "the body of {name} is not a chart of that language",
                "{name} 的实现不是该语言的图表",
            ),
            Self::EditNetworkRangeOutOfRange => (
                "cannot replace {remove} networks at position {at}: the body has {len} networks",
                "无法替换位置 {at} 起的 {remove} 个网络：该实现只有 {len} 个网络",
            ),
            Self::LitUnknownBase => (
                "'{base}#' is not a base; use 2#, 8# or 16#",
                "“{base}#”不是进制；请使用 2#、8# 或 16#",
            ),
            Self::LitNoDigits => ("'{text}' has no digits", "“{text}”没有数字"),
            Self::LitBadDigitBinary => (
                "'{text}' may hold only the digits 0 and 1",
                "“{text}”只能包含数字 0 和 1",
            ),
            Self::LitBadDigitOctal => (
                "'{text}' may hold only the digits 0 to 7",
                "“{text}”只能包含数字 0 到 7",
            ),
            Self::LitBadDigitHex => (
                "'{text}' may hold only the digits 0 to 9 and A to F",
                "“{text}”只能包含数字 0 到 9 和 A 到 F",
            ),
            Self::LitBadDigitDecimal => {
                ("'{text}' is not a decimal number", "“{text}”不是十进制数")
            }
            Self::LitNotANumber => ("'{text}' is not a number", "“{text}”不是数字"),
            Self::LitNoValue => (
                "'{text}' has no value; write for example T#2s",
                "“{text}”没有值；例如请写 T#2s",
            ),
            Self::LitNoUnit => (
                "'{text}': the number at the end has no unit (d, h, m, s, ms, us, ns)",
                "“{text}”：末尾的数字没有单位（d、h、m、s、ms、us、ns）",
            ),
            Self::LitNoNumber => (
                "'{text}': expected a number before '{rest}'",
                "“{text}”：“{rest}”之前应有数字",
            ),
            Self::LitBadNumber => (
                "'{text}': '{number}' is not a number",
                "“{text}”：“{number}”不是数字",
            ),
            Self::LitUnknownUnit => (
                "'{text}': unknown unit at '{rest}'; use d, h, m, s, ms, us or ns",
                "“{text}”：“{rest}”处的单位未知；请使用 d、h、m、s、ms、us 或 ns",
            ),
            Self::LitNotADate => (
                "'{text}' is not a date; write D#YYYY-MM-DD",
                "“{text}”不是日期；请写 D#YYYY-MM-DD",
            ),
            Self::LitNoSuchDate => (
                "'{text}' is not a valid calendar date",
                "“{text}”不是有效的日历日期",
            ),
            Self::LitNotATimeOfDay => (
                "'{text}' is not a time of day; write TOD#HH:MM:SS.fff",
                "“{text}”不是时刻；请写 TOD#HH:MM:SS.fff",
            ),
            Self::LitNotADateAndTime => (
                "'{text}' is not a date and time; write DT#YYYY-MM-DD-HH:MM:SS",
                "“{text}”不是日期和时间；请写 DT#YYYY-MM-DD-HH:MM:SS",
            ),
            Self::LitNoHash => ("'{text}' has no '#'", "“{text}”没有“#”"),
            Self::RefuseEmptyName => ("enter a name", "请输入名称"),
            Self::RefuseKeyword => (
                "'{name}' is a keyword of IEC 61131-3 and cannot name anything",
                "“{name}”是 IEC 61131-3 的关键字，不能用作名称",
            ),
            Self::RefuseNoReturnType => (
                "a function needs a return type, such as BOOL or INT",
                "函数需要返回类型，例如 BOOL 或 INT",
            ),
            Self::RefuseNoPropertyType => (
                "a property needs a type, such as BOOL or INT",
                "属性需要类型，例如 BOOL 或 INT",
            ),
            Self::RefuseNoMembers => (
                "'{pou}' cannot have methods, actions, transitions or properties: only programs and function blocks can",
                "“{pou}”不能有方法、动作、转换或属性：只有程序和功能块可以",
            ),
            Self::RefuseSfcNotHere => (
                "only a program or function block itself can be a Sequential Function Chart",
                "只有程序或功能块本身可以用顺序功能图编写",
            ),
            Self::RefuseSerialPortInUse => (
                "the serial port '{port}' is used by {devices}: move them to another port or delete them first",
                "串口“{port}”正被 {devices} 使用：请先将这些设备移到其他串口或删除",
            ),
            Self::TimeEmpty => (
                "enter a time such as T#10ms, or a number of microseconds",
                "请输入时间，例如 T#10ms，或微秒数",
            ),
            Self::TimeTooLong => ("'{text}' is too long", "“{text}”太长"),
            Self::TimeNotWholeMicros => (
                "'{text}' is not a whole number of microseconds, the finest step a task has",
                "“{text}”不是整微秒数，而微秒是任务的最小时间步长",
            ),
            Self::TimeNotPositive => ("the time must be longer than 0", "时间必须大于 0"),
            Self::TimeTooLongAtMost => (
                "'{text}' is too long: at most {max}",
                "“{text}”太长：最多 {max}",
            ),
            Self::NotATriggerVariable => (
                "'{input}' is not a variable: write its path, such as GVL_IO.xStart",
                "“{input}”不是变量：请写出其路径，例如 GVL_IO.xStart",
            ),
            Self::NotAPriority => (
                "'{input}' is not a priority: use 0 (highest) to {lowest} (lowest)",
                "“{input}”不是优先级：请使用 0（最高）到 {lowest}（最低）",
            ),
            Self::NotASensitivity => (
                "'{input}' is not a sensitivity: give how many overruns in a row trip the watchdog (1 or more)",
                "“{input}”不是灵敏度：请给出连续超时多少次触发看门狗（1 或更多）",
            ),
            Self::ChooseProgramToCall => ("choose a program to call", "请选择要调用的程序"),
            Self::NoProgramNamed => (
                "the project has no PROGRAM named '{program}'",
                "项目中没有名为“{program}”的 PROGRAM",
            ),
            Self::AlreadyCalls => ("{task} already calls {program}", "{task} 已调用 {program}"),
            Self::ValueNotAString => (
                "'{text}' is not a string; write it in quotes, such as 'abc'",
                "“{text}”不是字符串；请用引号括起来，例如 'abc'",
            ),
            Self::ValueTooLong => (
                "'{text}' is longer than the {length} characters the string holds",
                "“{text}”超过了字符串可容纳的 {length} 个字符",
            ),
            Self::ValueNotWritable => (
                "only elementary values and strings can be written",
                "只能写入基本类型的值和字符串",
            ),
            Self::ValueNotAValue => (
                "'{text}' is not a value of {ty}",
                "“{text}”不是 {ty} 类型的值",
            ),
            Self::ValueBadLiteral => (
                "'{text}' is not a value of {ty}: {reason}",
                "“{text}”不是 {ty} 类型的值：{reason}",
            ),
            Self::ValueOutOfRange => (
                "{text} is outside the range of {ty}",
                "{text} 超出 {ty} 的范围",
            ),
            Self::BuildNoThread => ("no build thread: {reason}", "无法启动编译线程：{reason}"),
            Self::BuildHiddenErrors => (
                "the compiler found errors the checker did not report",
                "编译器发现了检查器未报告的错误",
            ),
            Self::BuildCompilerStopped => (
                "the compiler stopped unexpectedly (an internal error); your edits are kept",
                "编译器意外停止（内部错误）；您的编辑已保留",
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
