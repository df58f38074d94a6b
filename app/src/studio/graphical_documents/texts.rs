//! The diagram editor's words in the interface language.

use editor::DiagramTexts;

use crate::studio::i18n::{DiagramText, Language};

/// The diagram editor's words in `language`.
pub(super) fn diagram_texts(language: Language) -> DiagramTexts {
    let get = |text: DiagramText| text.get(language).to_owned();
    DiagramTexts {
        ladder_view: get(DiagramText::LadderView),
        function_block_view: get(DiagramText::FunctionBlockView),
        network: get(DiagramText::Network),
        placeholder: get(DiagramText::Placeholder),
        toolbox: get(DiagramText::Toolbox),
        contact: get(DiagramText::Contact),
        negated_contact: get(DiagramText::NegatedContact),
        parallel_contact: get(DiagramText::ParallelContact),
        coil: get(DiagramText::Coil),
        set_coil: get(DiagramText::SetCoil),
        reset_coil: get(DiagramText::ResetCoil),
        block: get(DiagramText::Block),
        input: get(DiagramText::Input),
        assignment: get(DiagramText::Assignment),
        set_assignment: get(DiagramText::SetAssignment),
        reset_assignment: get(DiagramText::ResetAssignment),
        negation: get(DiagramText::Negation),
        jump: get(DiagramText::Jump),
        return_: get(DiagramText::Return),
        new_network: get(DiagramText::NewNetwork),
        operand_field: get(DiagramText::OperandField),
        block_type_field: get(DiagramText::BlockTypeField),
        title_field: get(DiagramText::TitleField),
        comment_field: get(DiagramText::CommentField),
        label_field: get(DiagramText::LabelField),
        input_assistant: get(DiagramText::InputAssistant),
        variables: get(DiagramText::Variables),
        blocks: get(DiagramText::Blocks),
        prepared_value: get(DiagramText::PreparedValue),
        zoom: get(DiagramText::Zoom),
        toggle_breakpoint: crate::studio::i18n::DebugText::ToggleBreakpoint
            .get(language)
            .to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_editor_speaks_the_interface_language() {
        let english = diagram_texts(Language::English);
        let chinese = diagram_texts(Language::SimplifiedChinese);
        assert_eq!(english.contact, "Contact");
        assert_eq!(chinese.contact, "触点");
        assert_ne!(english.input_assistant, chinese.input_assistant);
    }
}
