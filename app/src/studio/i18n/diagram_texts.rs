//! The words of the LD/FBD editor and of its refusals, in English and Simplified Chinese: an
//! enum of its own beside [`super::Text`], so each stays one exhaustive `match` of a readable
//! length.

use super::language::Language;
use super::template::fill_template;

/// Every word of the diagram editor. Adding a variant forces a translation for each language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum DiagramText {
    // The editor's own words (`editor::DiagramTexts`).
    LadderView,
    FunctionBlockView,
    Network,
    Placeholder,
    Toolbox,
    Contact,
    NegatedContact,
    ParallelContact,
    Coil,
    SetCoil,
    ResetCoil,
    Block,
    Input,
    Assignment,
    SetAssignment,
    ResetAssignment,
    Negation,
    Jump,
    Return,
    NewNetwork,
    OperandField,
    BlockTypeField,
    TitleField,
    CommentField,
    LabelField,
    InputAssistant,
    Variables,
    Blocks,
    PreparedValue,
    Zoom,
    // The undo label of a box's instance declared with the change.
    UndoDeclareInstance,
    // A runtime fault shown at the element whose statement faulted.
    FaultHere,
    // Why a command did nothing (`editor::DiagramRefusal`, `project_model::NetworkEditError`).
    NoSuchNetwork,
    NoSuchElement,
    NotApplicable,
    NotOneChain,
    NothingSelected,
    UnknownBlock,
}

impl DiagramText {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::LadderView => ("LD", "梯形图"),
            Self::FunctionBlockView => ("FBD", "功能块图"),
            Self::Network => ("Network", "网络"),
            Self::Placeholder => ("???", "???"),
            Self::Toolbox => ("Toolbox", "工具箱"),
            Self::Contact => ("Contact", "触点"),
            Self::NegatedContact => ("Negated contact", "常闭触点"),
            Self::ParallelContact => ("Parallel contact", "并联触点"),
            Self::Coil => ("Coil", "线圈"),
            Self::SetCoil => ("Set coil", "置位线圈"),
            Self::ResetCoil => ("Reset coil", "复位线圈"),
            Self::Block => ("Box", "功能块"),
            Self::Input => ("Input", "输入"),
            Self::Assignment => ("Assignment", "赋值"),
            Self::SetAssignment => ("Set assignment", "置位赋值"),
            Self::ResetAssignment => ("Reset assignment", "复位赋值"),
            Self::Negation => ("Negation", "取反"),
            Self::Jump => ("Jump", "跳转"),
            Self::Return => ("Return", "返回"),
            Self::NewNetwork => ("Network", "网络"),
            Self::OperandField => ("Operand", "操作数"),
            Self::BlockTypeField => ("Box type", "功能块类型"),
            Self::TitleField => ("Network title", "网络标题"),
            Self::CommentField => ("Network comment", "网络注释"),
            Self::LabelField => ("Network label", "网络标签"),
            Self::InputAssistant => ("Input assistant", "输入助手"),
            Self::Variables => ("Variables", "变量"),
            Self::Blocks => ("Blocks", "功能块"),
            Self::PreparedValue => ("Prepared value", "准备值"),
            Self::Zoom => ("Zoom (Ctrl+wheel)", "缩放（Ctrl+滚轮）"),
            Self::UndoDeclareInstance => (
                "Edit {name} and declare {instance} : {type}",
                "编辑 {name} 并声明 {instance} : {type}",
            ),
            Self::FaultHere => ("runtime fault: {reason}", "运行时故障：{reason}"),
            Self::NoSuchNetwork => (
                "there is no network {number} (the body has {count})",
                "没有网络 {number}（该实现有 {count} 个网络）",
            ),
            Self::NoSuchElement => ("no element has the id {id}", "没有 ID 为 {id} 的元素"),
            Self::NotApplicable => (
                "the command does not apply to element {id}",
                "该命令不适用于元素 {id}",
            ),
            Self::NotOneChain => (
                "the selected elements are not next to each other in one chain",
                "所选元素在同一串联链中并不相邻",
            ),
            Self::NothingSelected => ("nothing is selected", "未选择任何内容"),
            Self::UnknownBlock => (
                "no function or function block is called '{name}'",
                "没有名为“{name}”的函数或功能块",
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
