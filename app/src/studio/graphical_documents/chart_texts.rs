//! The CFC and SFC editors' words in the interface language.

use std::sync::Arc;

use editor::{CfcTexts, SfcTexts};

use crate::studio::error_texts::sfc_edit_error_text;
use crate::studio::i18n::{ChartText, Language};

/// The CFC editor's words in `language`.
pub(super) fn cfc_texts(language: Language) -> CfcTexts {
    let get = |text: ChartText| text.get(language).to_owned();
    CfcTexts {
        toolbox: get(ChartText::Toolbox),
        input: get(ChartText::Input),
        output: get(ChartText::Output),
        block: get(ChartText::Block),
        jump: get(ChartText::Jump),
        label: get(ChartText::Label),
        return_: get(ChartText::Return),
        composer: get(ChartText::Composer),
        selector: get(ChartText::Selector),
        comment: get(ChartText::Comment),
        connection_source: get(ChartText::ConnectionSource),
        connection_sink: get(ChartText::ConnectionSink),
        input_pin: get(ChartText::InputPin),
        control_point: get(ChartText::ControlPoint),
        display_execution_order: get(ChartText::DisplayExecutionOrder),
        execution_order: get(ChartText::ExecutionOrder),
        send_to_front: get(ChartText::SendToFront),
        send_to_back: get(ChartText::SendToBack),
        move_up: get(ChartText::OrderMoveUp),
        move_down: get(ChartText::OrderMoveDown),
        set_execution_order: get(ChartText::SetExecutionOrder),
        order_by_data_flow: get(ChartText::OrderByDataFlow),
        order_by_topology: get(ChartText::OrderByTopology),
        negate: get(ChartText::Negate),
        rising_edge: get(ChartText::RisingEdge),
        falling_edge: get(ChartText::FallingEdge),
        no_edge: get(ChartText::NoEdge),
        set_output: get(ChartText::SetOutput),
        reset_output: get(ChartText::ResetOutput),
        plain_output: get(ChartText::PlainOutput),
        remove_control_point: get(ChartText::RemoveControlPoint),
        delete: get(ChartText::Delete),
        placeholder: get(ChartText::Placeholder),
        expression_field: get(ChartText::ExpressionField),
        block_type_field: get(ChartText::BlockTypeField),
        instance_field: get(ChartText::InstanceField),
        name_field: get(ChartText::NameField),
        comment_field: get(ChartText::CommentField),
        order_field: get(ChartText::OrderField),
        prepared_value: get(ChartText::PreparedValue),
        zoom: get(ChartText::CfcZoom),
        toggle_breakpoint: crate::studio::i18n::DebugText::ToggleBreakpoint
            .get(language)
            .to_owned(),
    }
}

/// The SFC editor's words in `language`, its refusals among them.
pub(super) fn sfc_texts(language: Language) -> SfcTexts {
    let get = |text: ChartText| text.get(language).to_owned();
    SfcTexts {
        toolbox: get(ChartText::Toolbox),
        step_transition: get(ChartText::StepTransition),
        step_transition_before: get(ChartText::StepTransitionBefore),
        alternative_branch: get(ChartText::AlternativeBranch),
        parallel_branch: get(ChartText::ParallelBranch),
        add_branch: get(ChartText::AddBranch),
        jump: get(ChartText::Jump),
        macro_step: get(ChartText::MacroStep),
        wrap_in_macro: get(ChartText::WrapInMacro),
        action_association: get(ChartText::ActionAssociation),
        delete: get(ChartText::Delete),
        copy: get(ChartText::Copy),
        paste: get(ChartText::Paste),
        edit_text: get(ChartText::EditText),
        open_macro: get(ChartText::OpenMacro),
        leave_macro: get(ChartText::LeaveMacro),
        chart: get(ChartText::Chart),
        step_properties: get(ChartText::StepProperties),
        min_time: get(ChartText::MinTime),
        max_time: get(ChartText::MaxTime),
        entry_action: get(ChartText::EntryAction),
        main_action: get(ChartText::MainAction),
        exit_action: get(ChartText::ExitAction),
        comment: get(ChartText::Comment),
        qualifier: get(ChartText::Qualifier),
        action: get(ChartText::Action),
        time: get(ChartText::Time),
        indicator: get(ChartText::Indicator),
        remove: get(ChartText::Remove),
        move_up: get(ChartText::MoveUp),
        priority: get(ChartText::Priority),
        activate_step: get(ChartText::ActivateStep),
        deactivate_step: get(ChartText::DeactivateStep),
        fire_transition: get(ChartText::FireTransition),
        over_max_time: get(ChartText::OverMaxTime),
        step_name_field: get(ChartText::StepNameField),
        condition_field: get(ChartText::ConditionField),
        jump_target_field: get(ChartText::JumpTargetField),
        zoom: get(ChartText::SfcZoom),
        toggle_breakpoint: crate::studio::i18n::DebugText::ToggleBreakpoint
            .get(language)
            .to_owned(),
        refusal: Arc::new(move |error| sfc_edit_error_text(error, language)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::sfc_edit::SfcEditError;

    #[test]
    fn the_chart_editors_speak_the_interface_language() {
        let english = cfc_texts(Language::English);
        let chinese = cfc_texts(Language::SimplifiedChinese);
        assert_eq!(english, CfcTexts::default());
        assert_ne!(english.order_by_data_flow, chinese.order_by_data_flow);
        let sfc = sfc_texts(Language::SimplifiedChinese);
        assert_eq!(sfc.parallel_branch, "并行分支");
        assert_eq!(
            (sfc.refusal)(&SfcEditError::UnknownStep("Fill".to_owned())),
            "没有名为“Fill”的步"
        );
    }
}
