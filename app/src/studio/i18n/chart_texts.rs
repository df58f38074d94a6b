//! The words of the CFC and SFC editors and of their refusals, in English and Simplified
//! Chinese: an enum of its own beside [`super::DiagramText`], so each stays one exhaustive
//! `match` of a readable length.

use super::language::Language;
use super::template::fill_template;

/// Every word of the chart editors. Adding a variant forces a translation for each language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum ChartText {
    // Shared by both editors.
    Toolbox,
    Jump,
    Comment,
    Delete,
    // The CFC editor's own words (`editor::CfcTexts`).
    Input,
    Output,
    Block,
    Label,
    Return,
    Composer,
    Selector,
    ConnectionSource,
    ConnectionSink,
    InputPin,
    ControlPoint,
    DisplayExecutionOrder,
    ExecutionOrder,
    SendToFront,
    SendToBack,
    OrderMoveUp,
    OrderMoveDown,
    SetExecutionOrder,
    OrderByDataFlow,
    OrderByTopology,
    Negate,
    RisingEdge,
    FallingEdge,
    NoEdge,
    SetOutput,
    ResetOutput,
    PlainOutput,
    RemoveControlPoint,
    Placeholder,
    ExpressionField,
    BlockTypeField,
    InstanceField,
    NameField,
    CommentField,
    OrderField,
    PreparedValue,
    CfcZoom,
    // The SFC editor's own words (`editor::SfcTexts`).
    StepTransition,
    StepTransitionBefore,
    AlternativeBranch,
    ParallelBranch,
    AddBranch,
    MacroStep,
    WrapInMacro,
    ActionAssociation,
    Copy,
    Paste,
    EditText,
    OpenMacro,
    LeaveMacro,
    Chart,
    StepProperties,
    MinTime,
    MaxTime,
    EntryAction,
    MainAction,
    ExitAction,
    Qualifier,
    Action,
    Time,
    Indicator,
    Remove,
    MoveUp,
    Priority,
    ActivateStep,
    DeactivateStep,
    FireTransition,
    OverMaxTime,
    StepNameField,
    ConditionField,
    JumpTargetField,
    SfcZoom,
    // Why a CFC command did nothing (`editor::CfcRefusal`, `project_model::CfcEditError`).
    CfcNoElement,
    CfcNothingSelected,
    CfcNotAnOutput,
    CfcNotAnInput,
    CfcSelfConnection,
    CfcNoWire,
    CfcNoControlPoint,
    CfcNotExecutable,
    CfcOrderOutOfRange,
    CfcWrongKind,
    CfcNotExtensible,
    CfcUnknownBlock,
    CfcUnknownStructure,
    CfcNotANumber,
    // Why an SFC command did nothing (`project_model::sfc_edit::SfcEditError`).
    SfcStructure,
    SfcEmptySelection,
    SfcNoSuchElement,
    SfcNotAStep,
    SfcNotATransition,
    SfcNotABranch,
    SfcNotAJump,
    SfcNotARun,
    SfcJumpNotAtEnd,
    SfcInvalidName,
    SfcDuplicateName,
    SfcUnknownStep,
    SfcEmptyCondition,
    SfcEmptyAction,
    SfcMissingDuration,
    SfcUnexpectedDuration,
    SfcNoSuchAssociation,
    SfcEmptyClipboard,
    // The SFC's structural rules (`project_model::sfc_edit::SfcRule`).
    RuleMainStartsWithStep,
    RuleMainEndsWithJump,
    RuleStepNeedsTransitionAfter,
    RuleTransitionNeedsStepAfter,
    RuleJumpIsLast,
    RuleTwoBranches,
    RuleAlternativeBeginsWithTransition,
    RuleAlternativeEndsWithTransitionOrJump,
    RuleParallelBeginsWithStep,
    RuleParallelEndsWithStep,
    RuleMacroBeginsAndEndsWithStep,
    RuleNoJumpInMacro,
    RuleSequenceNotEmpty,
    RuleUniqueIds,
}

impl ChartText {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::Toolbox => ("Toolbox", "工具箱"),
            Self::Jump => ("Jump", "跳转"),
            Self::Comment => ("Comment", "注释"),
            Self::Delete => ("Delete", "删除"),
            Self::Input => ("Input", "输入"),
            Self::Output => ("Output", "输出"),
            Self::Block => ("Box", "功能块"),
            Self::Label => ("Label", "标签"),
            Self::Return => ("Return", "返回"),
            Self::Composer => ("Composer", "组合器"),
            Self::Selector => ("Selector", "选择器"),
            Self::ConnectionSource => ("Connection mark (source)", "连接标记（源）"),
            Self::ConnectionSink => ("Connection mark (sink)", "连接标记（汇）"),
            Self::InputPin => ("Input pin", "输入引脚"),
            Self::ControlPoint => ("Control point", "控制点"),
            Self::DisplayExecutionOrder => ("Display Execution Order", "显示执行顺序"),
            Self::ExecutionOrder => ("Execution Order", "执行顺序"),
            Self::SendToFront => ("Send to Front", "置于最前"),
            Self::SendToBack => ("Send to Back", "置于最后"),
            Self::OrderMoveUp => ("Move Up", "上移"),
            Self::OrderMoveDown => ("Move Down", "下移"),
            Self::SetExecutionOrder => ("Set Execution Order…", "设置执行顺序…"),
            Self::OrderByDataFlow => ("Order by Data Flow", "按数据流排序"),
            Self::OrderByTopology => ("Order by Topology", "按拓扑排序"),
            Self::Negate => ("Negate", "取反"),
            Self::RisingEdge => ("Rising edge", "上升沿"),
            Self::FallingEdge => ("Falling edge", "下降沿"),
            Self::NoEdge => ("No edge", "无边沿"),
            Self::SetOutput => ("Set output", "置位输出"),
            Self::ResetOutput => ("Reset output", "复位输出"),
            Self::PlainOutput => ("Plain output", "普通输出"),
            Self::RemoveControlPoint => ("Remove control point", "删除控制点"),
            Self::Placeholder => ("???", "???"),
            Self::ExpressionField => ("Expression", "表达式"),
            Self::BlockTypeField => ("Box type", "功能块类型"),
            Self::InstanceField => ("Instance", "实例"),
            Self::NameField => ("Name", "名称"),
            Self::CommentField => ("Comment", "注释"),
            Self::OrderField => ("Execution order", "执行顺序"),
            Self::PreparedValue => ("Prepared value", "预备值"),
            Self::CfcZoom => ("Zoom (Ctrl+wheel)", "缩放（Ctrl+滚轮）"),
            Self::StepTransition => ("Step-transition", "步-转换"),
            Self::StepTransitionBefore => ("Step-transition before", "在前插入步-转换"),
            Self::AlternativeBranch => ("Alternative branch", "选择分支"),
            Self::ParallelBranch => ("Parallel branch", "并行分支"),
            Self::AddBranch => ("Add branch", "添加分支"),
            Self::MacroStep => ("Macro step", "宏步"),
            Self::WrapInMacro => ("Wrap in macro step", "包装为宏步"),
            Self::ActionAssociation => ("Action association", "动作关联"),
            Self::Copy => ("Copy", "复制"),
            Self::Paste => ("Paste", "粘贴"),
            Self::EditText => ("Edit text", "编辑文本"),
            Self::OpenMacro => ("Open macro step", "打开宏步"),
            Self::LeaveMacro => ("Back", "返回上层"),
            Self::Chart => ("Chart", "图表"),
            Self::StepProperties => ("Step properties", "步属性"),
            Self::MinTime => ("Minimum time", "最短时间"),
            Self::MaxTime => ("Maximum time", "最长时间"),
            Self::EntryAction => ("Entry action", "进入动作"),
            Self::MainAction => ("Step action", "步动作"),
            Self::ExitAction => ("Exit action", "退出动作"),
            Self::Qualifier => ("Qualifier", "限定符"),
            Self::Action => ("Action", "动作"),
            Self::Time => ("Time", "时间"),
            Self::Indicator => ("Indicator", "指示变量"),
            Self::Remove => ("Remove", "移除"),
            Self::MoveUp => ("Move up", "上移"),
            Self::Priority => ("Priority", "优先级"),
            Self::ActivateStep => ("Activate step", "激活步"),
            Self::DeactivateStep => ("Deactivate step", "取消激活步"),
            Self::FireTransition => ("Fire transition", "触发转换"),
            Self::OverMaxTime => ("Maximum time exceeded", "超过最长时间"),
            Self::StepNameField => ("Step name", "步名称"),
            Self::ConditionField => ("Condition", "条件"),
            Self::JumpTargetField => ("Jump target", "跳转目标"),
            Self::SfcZoom => ("Zoom (Ctrl + mouse wheel)", "缩放（Ctrl + 鼠标滚轮）"),
            Self::CfcNoElement => ("no element has the id {id}", "没有编号为 {id} 的元素"),
            Self::CfcNothingSelected => ("no element is selected", "未选择任何元素"),
            Self::CfcNotAnOutput => (
                "element {id} has no output pin '{pin}'",
                "元素 {id} 没有输出引脚“{pin}”",
            ),
            Self::CfcNotAnInput => (
                "element {id} has no input pin '{pin}'",
                "元素 {id} 没有输入引脚“{pin}”",
            ),
            Self::CfcSelfConnection => (
                "element {id} cannot be wired to itself (only a box keeps a feedback)",
                "元素 {id} 不能连接到自身（只有功能块可以反馈）",
            ),
            Self::CfcNoWire => (
                "no wire drives pin '{pin}' of element {id}",
                "没有连线驱动元素 {id} 的引脚“{pin}”",
            ),
            Self::CfcNoControlPoint => (
                "the wire into element {id} has no control point {index}",
                "进入元素 {id} 的连线没有控制点 {index}",
            ),
            Self::CfcNotExecutable => (
                "element {id} has no execution order (only boxes, outputs, jumps, labels, returns, composers and selectors do)",
                "元素 {id} 没有执行顺序（只有功能块、输出、跳转、标签、返回、组合器和选择器有）",
            ),
            Self::CfcOrderOutOfRange => (
                "execution order {order} is out of range (the chart runs {count} elements)",
                "执行顺序 {order} 超出范围（图表执行 {count} 个元素）",
            ),
            Self::CfcWrongKind => (
                "the command does not apply to element {id}",
                "该命令不适用于元素 {id}",
            ),
            Self::CfcNotExtensible => (
                "a {type} box cannot take more inputs",
                "{type} 功能块不能再增加输入",
            ),
            Self::CfcUnknownBlock => (
                "no operator, function or function block is called '{name}'",
                "没有名为“{name}”的运算符、函数或功能块",
            ),
            Self::CfcUnknownStructure => (
                "no structure type is called '{name}'",
                "没有名为“{name}”的结构体类型",
            ),
            Self::CfcNotANumber => (
                "'{text}' is not an execution order number",
                "“{text}”不是执行顺序编号",
            ),
            Self::SfcStructure => ("element {id}: {rule}", "元素 {id}：{rule}"),
            Self::SfcEmptySelection => ("nothing is selected", "未选择任何内容"),
            Self::SfcNoSuchElement => ("element {id} is not in the chart", "元素 {id} 不在图表中"),
            Self::SfcNotAStep => ("element {id} is not a step", "元素 {id} 不是步"),
            Self::SfcNotATransition => ("element {id} is not a transition", "元素 {id} 不是转换"),
            Self::SfcNotABranch => ("element {id} is not a branch", "元素 {id} 不是分支"),
            Self::SfcNotAJump => ("element {id} is not a jump", "元素 {id} 不是跳转"),
            Self::SfcNotARun => (
                "the selected elements are not one run of a sequence",
                "所选元素不是同一序列中连续的一段",
            ),
            Self::SfcJumpNotAtEnd => (
                "element {id}: a jump can only follow the last transition of a sequence",
                "元素 {id}：跳转只能跟在序列的最后一个转换之后",
            ),
            Self::SfcInvalidName => (
                "'{name}' is not a valid step name",
                "“{name}”不是有效的步名称",
            ),
            Self::SfcDuplicateName => (
                "a step named '{name}' already exists",
                "已存在名为“{name}”的步",
            ),
            Self::SfcUnknownStep => ("no step is named '{name}'", "没有名为“{name}”的步"),
            Self::SfcEmptyCondition => (
                "element {id}: a transition needs a condition",
                "元素 {id}：转换需要条件",
            ),
            Self::SfcEmptyAction => (
                "an action association needs an action",
                "动作关联需要一个动作",
            ),
            Self::SfcMissingDuration => (
                "qualifier {qualifier} needs a time",
                "限定符 {qualifier} 需要时间",
            ),
            Self::SfcUnexpectedDuration => (
                "qualifier {qualifier} takes no time",
                "限定符 {qualifier} 不带时间",
            ),
            Self::SfcNoSuchAssociation => (
                "element {id}: there is no action association {index}",
                "元素 {id}：没有第 {index} 个动作关联",
            ),
            Self::SfcEmptyClipboard => (
                "the clipboard holds no SFC elements",
                "剪贴板中没有 SFC 元素",
            ),
            Self::RuleMainStartsWithStep => {
                ("the chart begins with its initial step", "图表以初始步开始")
            }
            Self::RuleMainEndsWithJump => {
                ("the main sequence ends with a jump", "主序列以跳转结束")
            }
            Self::RuleStepNeedsTransitionAfter => {
                ("a step needs a transition after it", "步之后需要一个转换")
            }
            Self::RuleTransitionNeedsStepAfter => {
                ("a transition needs a step after it", "转换之后需要一个步")
            }
            Self::RuleJumpIsLast => (
                "a jump is the last element of its sequence",
                "跳转必须是其序列的最后一个元素",
            ),
            Self::RuleTwoBranches => ("a branch has at least two branches", "分支至少有两条支路"),
            Self::RuleAlternativeBeginsWithTransition => (
                "each alternative branch begins with a transition",
                "每条选择分支以转换开始",
            ),
            Self::RuleAlternativeEndsWithTransitionOrJump => (
                "each alternative branch ends with a transition or a jump",
                "每条选择分支以转换或跳转结束",
            ),
            Self::RuleParallelBeginsWithStep => (
                "each parallel branch begins with a step",
                "每条并行分支以步开始",
            ),
            Self::RuleParallelEndsWithStep => (
                "each parallel branch ends with a step",
                "每条并行分支以步结束",
            ),
            Self::RuleMacroBeginsAndEndsWithStep => (
                "a macro step begins and ends with a step",
                "宏步以步开始并以步结束",
            ),
            Self::RuleNoJumpInMacro => ("a macro step holds no jump", "宏步中不能有跳转"),
            Self::RuleSequenceNotEmpty => ("a sequence cannot be empty", "序列不能为空"),
            Self::RuleUniqueIds => (
                "every element has an id of its own",
                "每个元素都有自己的编号",
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
