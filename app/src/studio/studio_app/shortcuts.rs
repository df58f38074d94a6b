//! The studio's keyboard shortcuts, turned into commands.

use egui::{Key, KeyboardShortcut, Modifiers};

use crate::studio::command::{Command, Commands};
use crate::studio::debug::DebugCommand;

/// Consumes the studio's shortcuts pressed this frame and queues their commands.
pub(super) fn handle_shortcuts(ctx: &egui::Context, commands: &mut Commands) {
    let shortcuts = [
        (Modifiers::COMMAND, Key::S, Command::Save),
        (Modifiers::COMMAND, Key::O, Command::OpenDialog),
        (Modifiers::COMMAND, Key::Z, Command::Undo),
        (Modifiers::COMMAND, Key::Y, Command::Redo),
        (Modifiers::NONE, Key::F11, Command::Build),
        (Modifiers::ALT, Key::F8, Command::Login),
        (Modifiers::COMMAND, Key::F8, Command::Logout),
        (Modifiers::SHIFT, Key::F8, Command::Stop),
        (Modifiers::NONE, Key::F5, Command::Start),
        // After Shift+F8 and Alt+F8, which a plain F8 would otherwise match too.
        (
            Modifiers::SHIFT,
            Key::F10,
            Command::Debug(DebugCommand::StepOut),
        ),
        (
            Modifiers::NONE,
            Key::F10,
            Command::Debug(DebugCommand::StepOver),
        ),
        (
            Modifiers::NONE,
            Key::F8,
            Command::Debug(DebugCommand::StepInto),
        ),
        (Modifiers::COMMAND, Key::F7, Command::WritePrepared),
        (Modifiers::ALT, Key::F7, Command::ReleaseAllForces),
        (Modifiers::NONE, Key::F7, Command::ForcePrepared),
    ];
    for (modifiers, key, command) in shortcuts {
        let shortcut = KeyboardShortcut::new(modifiers, key);
        if ctx.input_mut(|input| input.consume_shortcut(&shortcut)) {
            commands.push(command);
        }
    }
}
