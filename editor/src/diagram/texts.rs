//! The words the diagram editor shows, so the app can give them in the user's language.

/// The user-visible words of the diagram editor. The default is English; the app sets its
/// translation with [`super::DiagramEditor::set_texts`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DiagramTexts {
    /// The view toggle's Ladder Diagram choice.
    pub ladder_view: String,
    /// The view toggle's Function Block Diagram choice.
    pub function_block_view: String,
    /// The label before a network's number, as in "Network 3".
    pub network: String,
    /// Shown for an empty title or operand that can be typed in.
    pub placeholder: String,
    /// The toolbox's heading.
    pub toolbox: String,
    /// The toolbox's contact.
    pub contact: String,
    /// The toolbox's normally closed contact.
    pub negated_contact: String,
    /// The toolbox's parallel contact.
    pub parallel_contact: String,
    /// The toolbox's coil.
    pub coil: String,
    /// The toolbox's set coil.
    pub set_coil: String,
    /// The toolbox's reset coil.
    pub reset_coil: String,
    /// The toolbox's box.
    pub block: String,
    /// The FBD toolbox's input (a contact's operand in the LD view).
    pub input: String,
    /// The FBD toolbox's assignment (a coil in the LD view).
    pub assignment: String,
    /// The FBD toolbox's set assignment (a set coil in the LD view).
    pub set_assignment: String,
    /// The FBD toolbox's reset assignment (a reset coil in the LD view).
    pub reset_assignment: String,
    /// The FBD toolbox's negation of the selected input, output or pin.
    pub negation: String,
    /// The toolbox's jump.
    pub jump: String,
    /// The toolbox's return.
    pub return_: String,
    /// The toolbox's network.
    pub new_network: String,
    /// The accessible label of the text field over an element.
    pub operand_field: String,
    /// The accessible label of the field where a box's type is typed.
    pub block_type_field: String,
    /// The accessible label of a network title's field.
    pub title_field: String,
    /// The accessible label of a network comment's field.
    pub comment_field: String,
    /// The accessible label of a network label's field.
    pub label_field: String,
    /// The input assistant's heading.
    pub input_assistant: String,
    /// The input assistant's variables section.
    pub variables: String,
    /// The input assistant's blocks section.
    pub blocks: String,
    /// The label of the field where a value is prepared for writing or forcing.
    pub prepared_value: String,
    /// The zoom percentage's tooltip.
    pub zoom: String,
    /// The context menu's entry that sets or clears the breakpoint of the selection.
    pub toggle_breakpoint: String,
}

impl Default for DiagramTexts {
    fn default() -> Self {
        Self {
            ladder_view: "LD".to_owned(),
            function_block_view: "FBD".to_owned(),
            network: "Network".to_owned(),
            placeholder: "???".to_owned(),
            toolbox: "Toolbox".to_owned(),
            contact: "Contact".to_owned(),
            negated_contact: "Negated contact".to_owned(),
            parallel_contact: "Parallel contact".to_owned(),
            coil: "Coil".to_owned(),
            set_coil: "Set coil".to_owned(),
            reset_coil: "Reset coil".to_owned(),
            block: "Box".to_owned(),
            input: "Input".to_owned(),
            assignment: "Assignment".to_owned(),
            set_assignment: "Set assignment".to_owned(),
            reset_assignment: "Reset assignment".to_owned(),
            negation: "Negation".to_owned(),
            jump: "Jump".to_owned(),
            return_: "Return".to_owned(),
            new_network: "Network".to_owned(),
            operand_field: "Operand".to_owned(),
            block_type_field: "Box type".to_owned(),
            title_field: "Network title".to_owned(),
            comment_field: "Network comment".to_owned(),
            label_field: "Network label".to_owned(),
            input_assistant: "Input assistant".to_owned(),
            variables: "Variables".to_owned(),
            blocks: "Blocks".to_owned(),
            prepared_value: "Prepared value".to_owned(),
            zoom: "Zoom (Ctrl+wheel)".to_owned(),
            toggle_breakpoint: "Toggle breakpoint".to_owned(),
        }
    }
}
