//! The small dialogs of the device tree: the name, kind and language of a new POU or member,
//! and renaming.
//!
//! Names are checked as they are typed; the reason a name is refused stays on screen and the
//! dialog stays open until the name is acceptable or the user cancels.

use egui::{RichText, Ui};
use project_model::{PouKind, Project};

use super::action::{TreeAction, rename_scope};
use super::body_language::BodyLanguage;
use super::dialog_fields::{body_language_ui, text_field};
use super::member_dialog::MemberDialog;
use super::names::{NameScope, name_problem, unique_name};
use super::refusal::Refusal;
use crate::studio::i18n::{Language, Text};
use crate::studio::tree_node::TreeNode;

/// A dialog open over the device tree.
#[derive(Clone, Debug, PartialEq)]
pub enum TreeDialog {
    /// Asks the kind, name and (for a function) return type of a new POU.
    NewPou {
        /// The folder the POU goes into.
        folder: Vec<String>,
        /// Program, function block or function.
        kind: PouKind,
        /// The name as typed.
        name: String,
        /// The return type as typed (used for functions only).
        return_type: String,
        /// The implementation language.
        language: BodyLanguage,
        /// Whether the name field was given the keyboard focus yet.
        focused: bool,
    },
    /// Asks the name, type and language of a new method, action or property.
    NewMember(MemberDialog),
    /// Asks a node's new name.
    Rename {
        /// The node.
        node: TreeNode,
        /// The name as typed.
        name: String,
        /// Whether the name field was given the keyboard focus yet.
        focused: bool,
    },
}

/// What became of the dialog this frame.
#[derive(Clone, Debug, PartialEq)]
pub enum DialogOutcome {
    /// It stays open.
    Open,
    /// The user cancelled it.
    Cancelled,
    /// The user confirmed an acceptable entry.
    Confirmed(TreeAction),
}

impl TreeDialog {
    /// The dialog for a new POU in `folder`, proposing a fresh name and `language`.
    pub fn new_pou(project: &Project, folder: Vec<String>, language: BodyLanguage) -> Self {
        let name = unique_name("POU", |name| {
            NameScope::Object.is_taken(project, name, None)
        });
        Self::NewPou {
            folder,
            kind: PouKind::Program,
            name,
            return_type: "BOOL".to_owned(),
            language,
            focused: false,
        }
    }

    /// The rename dialog of `node`, or `None` for nodes that have no name of their own.
    pub fn rename(node: TreeNode) -> Option<Self> {
        let (_, name) = rename_scope(&node)?;
        let name = name.to_owned();
        Some(Self::Rename {
            node,
            name,
            focused: false,
        })
    }

    /// Why the entry cannot be confirmed yet, if it cannot.
    fn problem(&self, project: &Project) -> Option<Refusal> {
        match self {
            Self::NewPou {
                kind,
                name,
                return_type,
                ..
            } => name_problem(project, NameScope::Object, name.trim(), None).or_else(|| {
                (*kind == PouKind::Function && return_type.trim().is_empty())
                    .then_some(Refusal::NoReturnType)
            }),
            Self::NewMember(dialog) => dialog.problem(project),
            Self::Rename { node, name, .. } => {
                let (scope, old) = rename_scope(node)?;
                name_problem(project, scope, name.trim(), Some(old))
            }
        }
    }

    /// The action the dialog's entry asks for.
    fn action(&self) -> TreeAction {
        match self {
            Self::NewPou {
                folder,
                kind,
                name,
                return_type,
                language,
                ..
            } => TreeAction::AddPou {
                folder: folder.clone(),
                kind: *kind,
                name: name.trim().to_owned(),
                return_type: Some(return_type.trim().to_owned()),
                language: *language,
            },
            Self::NewMember(dialog) => dialog.action(),
            Self::Rename { node, name, .. } => TreeAction::Rename {
                node: node.clone(),
                name: name.trim().to_owned(),
            },
        }
    }

    /// Draws the dialog as a modal window and reports what the user did.
    pub fn ui(
        &mut self,
        ctx: &egui::Context,
        project: &Project,
        language: Language,
    ) -> DialogOutcome {
        let problem = self.problem(project);
        let modal = egui::Modal::new(egui::Id::unique("device_tree_dialog")).show(ctx, |ui| {
            ui.set_min_width(320.0);
            let entered = self.fields_ui(ui, language);
            if let Some(problem) = &problem {
                let problem = problem.text(language);
                ui.label(RichText::new(problem).color(ui.visuals().error_fg_color));
            }
            ui.add_space(6.0);
            let mut outcome = DialogOutcome::Open;
            ui.horizontal(|ui| {
                let ok =
                    ui.add_enabled(problem.is_none(), egui::Button::new(Text::Ok.get(language)));
                if ok.clicked() || (entered && problem.is_none()) {
                    outcome = DialogOutcome::Confirmed(self.action());
                } else if entered {
                    // Enter took the focus away from a refused name: give it back, so the
                    // user can correct the name right away.
                    self.refocus();
                }
                if ui.button(Text::Cancel.get(language)).clicked() {
                    outcome = DialogOutcome::Cancelled;
                }
            });
            outcome
        });
        if modal.inner == DialogOutcome::Open && modal.should_close() {
            return DialogOutcome::Cancelled;
        }
        modal.inner
    }

    /// Makes the name field take the keyboard focus again on the next frame.
    fn refocus(&mut self) {
        match self {
            Self::NewPou { focused, .. } | Self::Rename { focused, .. } => *focused = false,
            Self::NewMember(dialog) => dialog.focused = false,
        }
    }

    /// The dialog's title and fields; true when Enter was pressed in a field.
    fn fields_ui(&mut self, ui: &mut Ui, language: Language) -> bool {
        let mut entered = false;
        match self {
            Self::NewPou {
                kind,
                name,
                return_type,
                language: body_language,
                focused,
                ..
            } => {
                ui.heading(Text::AddPou.get(language));
                ui.horizontal(|ui| {
                    for (value, text) in [
                        (PouKind::Program, Text::Program),
                        (PouKind::FunctionBlock, Text::FunctionBlock),
                        (PouKind::Function, Text::Function),
                    ] {
                        ui.radio_value(kind, value, text.get(language));
                    }
                });
                entered |= text_field(ui, Text::Name.get(language), name, focused);
                if *kind == PouKind::Function {
                    let mut already = true;
                    entered |= text_field(
                        ui,
                        Text::ReturnType.get(language),
                        return_type,
                        &mut already,
                    );
                }
                body_language_ui(ui, body_language, language, *kind != PouKind::Function);
            }
            Self::NewMember(dialog) => entered |= dialog.fields_ui(ui, language),
            Self::Rename { name, focused, .. } => {
                ui.heading(Text::Rename.get(language));
                entered |= text_field(ui, Text::Name.get(language), name, focused);
            }
        }
        entered
    }
}
