//! The SFC editor's commands: what the menus, the context menu, the toolbox and the keys ask
//! for, and the keys that ask for them.

use egui::{Key, Modifiers};

/// A command of the SFC editor, run on the selection.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SfcCommand {
    /// Insert a step and a transition after the selected node (Ctrl+T).
    InsertStepTransitionAfter,
    /// Insert a step and a transition before the selected node (Ctrl+Shift+T).
    InsertStepTransitionBefore,
    /// Wrap the selected transitions into an alternative branch with a new branch at its
    /// right (Ctrl+R).
    InsertAlternativeBranch,
    /// Wrap the selected steps into a parallel branch with a new branch at its right
    /// (Ctrl+P).
    InsertParallelBranch,
    /// Add a branch at the right of the selected alternative or parallel branch (Ctrl+B).
    AddBranch,
    /// Insert a jump after the selected transition, which ends its branch (Ctrl+J).
    InsertJump,
    /// Insert a macro step and a transition after the selected node (Ctrl+M).
    InsertMacroStep,
    /// Wrap the selected steps and transitions into a macro step (Ctrl+Shift+M).
    WrapInMacro,
    /// Add an action association to the selected step (Ctrl+Q).
    AddActionAssociation,
    /// Delete the selection (Delete).
    Delete,
    /// Copy the selection to the clipboard (Ctrl+C).
    Copy,
    /// Paste the clipboard after the selected node (Ctrl+V).
    Paste,
    /// Edit the selected node's text in place (F2, Enter).
    EditText,
    /// Show the selected macro step's body (Enter on a macro step, Ctrl+Down).
    OpenMacro,
    /// Go back to the level above the shown macro step (Ctrl+Up).
    LeaveMacro,
    /// Online: activate the selected step if inactive, else deactivate it (Ctrl+Enter).
    ToggleStepActive,
    /// Online, in tip mode: fire the selected transition (Ctrl+Enter).
    FireTransition,
}

/// The command a key with `modifiers` asks for, if any; Enter and the online keys depend on
/// the selection and are decided by the editor.
pub(super) fn command_for_key(key: Key, modifiers: Modifiers) -> Option<SfcCommand> {
    if modifiers.command {
        return match (key, modifiers.shift) {
            (Key::T, false) => Some(SfcCommand::InsertStepTransitionAfter),
            (Key::T, true) => Some(SfcCommand::InsertStepTransitionBefore),
            (Key::R, _) => Some(SfcCommand::InsertAlternativeBranch),
            (Key::P, _) => Some(SfcCommand::InsertParallelBranch),
            (Key::B, _) => Some(SfcCommand::AddBranch),
            (Key::J, _) => Some(SfcCommand::InsertJump),
            (Key::M, false) => Some(SfcCommand::InsertMacroStep),
            (Key::M, true) => Some(SfcCommand::WrapInMacro),
            (Key::Q, _) => Some(SfcCommand::AddActionAssociation),
            (Key::ArrowDown, _) => Some(SfcCommand::OpenMacro),
            (Key::ArrowUp, _) => Some(SfcCommand::LeaveMacro),
            _ => None,
        };
    }
    match key {
        Key::Delete | Key::Backspace => Some(SfcCommand::Delete),
        Key::F2 => Some(SfcCommand::EditText),
        _ => None,
    }
}

/// The insertion commands of the toolbox and the context menu, in the order they list them.
pub(super) const INSERTIONS: [SfcCommand; 9] = [
    SfcCommand::InsertStepTransitionAfter,
    SfcCommand::InsertStepTransitionBefore,
    SfcCommand::InsertAlternativeBranch,
    SfcCommand::InsertParallelBranch,
    SfcCommand::AddBranch,
    SfcCommand::InsertJump,
    SfcCommand::InsertMacroStep,
    SfcCommand::WrapInMacro,
    SfcCommand::AddActionAssociation,
];
