//! The dialog that adds a method, action, transition or property to a POU: its name, type and language.

use egui::Ui;
use project_model::{Object, Project};

use super::action::TreeAction;
use super::body_language::BodyLanguage;
use super::dialog_fields::{body_language_ui, text_field};
use super::members::{MemberKind, NewMember, TypeField, member_name_taken, member_problem};
use super::names::unique_name;
use super::refusal::Refusal;
use crate::studio::i18n::{Language, Text};

/// The entries of the dialog adding a member to a POU, as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct MemberDialog {
    /// The POU's name.
    pub pou: String,
    /// What is added.
    pub kind: MemberKind,
    /// The name as typed.
    pub name: String,
    /// A method's return type or a property's type as typed (unused for actions and
    /// transitions).
    pub type_name: String,
    /// The implementation language.
    pub language: BodyLanguage,
    /// Whether the name field was given the keyboard focus yet.
    pub focused: bool,
}

impl MemberDialog {
    /// The dialog adding a member of `kind` to the POU named `pou`, proposing a name the POU
    /// does not use yet and `language`.
    pub fn new(project: &Project, pou: &str, kind: MemberKind, language: BodyLanguage) -> Self {
        let taken = |name: &str| match project.application.object(pou) {
            Some(Object::Pou(pou)) => member_name_taken(pou, name),
            _ => false,
        };
        let type_name = match kind.type_field() {
            TypeField::Required => "INT".to_owned(),
            TypeField::Optional | TypeField::None => String::new(),
        };
        Self {
            pou: pou.to_owned(),
            kind,
            name: unique_name(kind.base_name(), taken),
            type_name,
            language,
            focused: false,
        }
    }

    /// The member the entries describe.
    fn member(&self) -> NewMember {
        NewMember {
            kind: self.kind,
            name: self.name.trim().to_owned(),
            language: self.language,
            type_name: match self.kind.type_field() {
                TypeField::None => String::new(),
                TypeField::Optional | TypeField::Required => self.type_name.trim().to_owned(),
            },
        }
    }

    /// Why the entries cannot be confirmed yet, if they cannot.
    pub(super) fn problem(&self, project: &Project) -> Option<Refusal> {
        match project.application.object(&self.pou) {
            Some(Object::Pou(pou)) => member_problem(pou, &self.member()),
            _ => Some(project_model::EditError::NoSuchObject(self.pou.clone()).into()),
        }
    }

    /// The action the entries ask for.
    pub(super) fn action(&self) -> TreeAction {
        TreeAction::AddMember {
            pou: self.pou.clone(),
            member: self.member(),
        }
    }

    /// The heading and fields; true when Enter was pressed in a field.
    pub(super) fn fields_ui(&mut self, ui: &mut Ui, language: Language) -> bool {
        ui.heading(self.kind.heading().get(language));
        let mut entered = text_field(
            ui,
            Text::Name.get(language),
            &mut self.name,
            &mut self.focused,
        );
        if self.kind.type_field() != TypeField::None {
            let mut already = true;
            entered |= text_field(
                ui,
                Text::ReturnType.get(language),
                &mut self.type_name,
                &mut already,
            );
        }
        body_language_ui(ui, &mut self.language, language, false);
        entered
    }
}
