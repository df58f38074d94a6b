//! The declaration parts of POUs, methods and global variable lists, as text (parsed back into
//! the model as it is typed) or as the variable table.

use editor::{EditorDiagnostic, Gesture, KeywordCompletions, VariableTable};
use egui::{RichText, Ui};
use project_model::{
    DeclarationsChange, Edit, Object, TypedDeclarations, TypedHeader, VarOwner,
    gvl_declarations_change, pou_declarations_change,
};

use crate::studio::command::{Command, Commands};
use crate::studio::i18n::Text;
use crate::studio::reveal::Reveal;
use crate::studio::view::StudioView;

use super::diagnostics::{declaration_diagnostics, editor_diagnostic, find_word};
use super::documents::{TextDocuments, TextKey, table_texts};
use super::part::{Part, Shown};

/// The declarations of the POU part: as text (parsed back into the model as you type) or as
/// the variable table.
pub(super) fn declarations_ui(
    view: StudioView<'_>,
    texts: &mut TextDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    shown: Shown<'_>,
    show_table: bool,
) {
    let Shown { pou, part, reveal } = shown;
    let method = match part {
        Part::Method(method) => Some(method.clone()),
        _ => None,
    };
    let method_data = method
        .as_ref()
        .and_then(|name| pou.methods.iter().find(|m| m.name == *name));
    let (text, variables, owner) = match (part, method_data) {
        (Part::Method(_), Some(m)) => (
            m.declaration_text(),
            m.variables.clone(),
            VarOwner::Method {
                pou: pou.name.clone(),
                method: m.name.clone(),
            },
        ),
        (Part::Property(property, _), _) => {
            let text = pou
                .properties
                .iter()
                .find(|p| p.name == *property)
                .map(|p| p.declaration_text())
                .unwrap_or_default();
            (text, Vec::new(), VarOwner::Pou(pou.name.clone()))
        }
        _ => (
            pou.declaration_text(),
            pou.variables.clone(),
            VarOwner::Pou(pou.name.clone()),
        ),
    };
    let read_only = matches!(
        part,
        Part::Property(..) | Part::Action(_) | Part::Transition(_)
    ) || view.online.is_logged_in();
    if show_table
        && !matches!(
            part,
            Part::Property(..) | Part::Action(_) | Part::Transition(_)
        )
    {
        // The overlaps are computed once per project revision, not per frame.
        let warnings = editor::overlap_warnings(view.overlaps, &pou.name);
        let drag_prefix = (pou.kind == project_model::PouKind::Program && method.is_none())
            .then(|| pou.name.clone());
        let output = VariableTable::new(("variables", &pou.name, &method))
            .read_only(read_only)
            .drag_prefix(drag_prefix)
            .drag_names(matches!(pou.body, project_model::Body::Cfc { .. }))
            .texts(table_texts(view.language))
            .show(ui, &variables, &warnings);
        if let Some((label, edit)) = output.edit {
            commands.push(Command::Edit(label, vec![Edit::Variables { owner, edit }]));
        }
        return;
    }
    let key = TextKey::Declarations {
        pou: pou.name.clone(),
        method: method.clone(),
    };
    let owner_name = method
        .as_ref()
        .map_or(pou.name.clone(), |m| format!("{}.{m}", pou.name));
    let label = Text::DeclarationsOf.fill(view.language, &[("name", &owner_name)]);
    let diagnostics = declaration_diagnostics(&texts.live, &pou.name, &text);
    let entry = texts.editor(key, &text);
    entry.editor.set_read_only(read_only);
    if let Some(Reveal::Declaration { name, .. }) = reveal
        && let Some(range) = find_word(entry.editor.text(), name)
    {
        entry.editor.reveal(range);
        entry.editor.request_focus();
    }
    let output = entry.editor.show(ui, &label, &KeywordCompletions);
    if output.changes.is_empty() {
        if let Some(diagnostics) = diagnostics {
            entry.editor.set_diagnostics(diagnostics);
        }
        return;
    }
    // The text typed is read back into variables; while it does not parse, it stays in the
    // editor with its errors and the model keeps the last valid declarations.
    let typed = entry.editor.text().to_owned();
    match compiler::ide::parse_declarations(&typed) {
        Err(errors) => {
            entry
                .editor
                .set_diagnostics(errors.iter().map(editor_diagnostic).collect());
        }
        Ok(parsed) => {
            entry.editor.set_diagnostics(Vec::new());
            match pou_declarations_change(pou, method.as_deref(), typed_declarations(parsed)) {
                DeclarationsChange::Unchanged => {}
                DeclarationsChange::Renamed => {
                    entry.editor.set_diagnostics(vec![EditorDiagnostic {
                        range: 0..typed.find('\n').unwrap_or(typed.len()),
                        severity: editor::Severity::Error,
                        code: String::new(),
                        message: Text::RenameInTree.get(view.language).to_owned(),
                    }]);
                }
                DeclarationsChange::Changed { edit, rendered } => {
                    // The model will render this text; until it changes from elsewhere the
                    // editor keeps what was typed.
                    entry.synced = rendered;
                    let merge_key = match output.gesture {
                        Some(Gesture::Typing { run }) => {
                            Some(format!("declarations {} {run}", pou.name))
                        }
                        _ => None,
                    };
                    commands.push(Command::EditText {
                        label: Text::UndoEditDeclarations
                            .fill(view.language, &[("name", &pou.name)]),
                        edits: vec![*edit],
                        merge_key,
                    });
                }
            }
        }
    }
}

/// The parsed declarations as the model's decision about them takes them.
fn typed_declarations(parsed: compiler::ide::ParsedDeclarations) -> TypedDeclarations {
    TypedDeclarations {
        header: parsed.header.map(|header| TypedHeader {
            name: header.name,
            return_type: header.return_type,
            extends: header.extends,
            implements: header.implements,
        }),
        comment: parsed.comment,
        variables: parsed.variables,
    }
}

/// Draws a global variable list: its declarations as text or as the variable table.
pub(crate) fn gvl_document_ui(
    view: StudioView<'_>,
    texts: &mut TextDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    name: &str,
) -> bool {
    let Some(project) = view.project() else {
        return false;
    };
    let Some(Object::Gvl(gvl)) = project.application.object(name) else {
        return false;
    };
    let language = view.language;
    ui.horizontal(|ui| {
        ui.label(RichText::new(format!("VAR_GLOBAL {}", gvl.name)).strong());
        ui.separator();
        let table = texts.tables.entry(name.to_owned()).or_insert(false);
        ui.selectable_value(table, false, Text::AsText.get(language));
        ui.selectable_value(table, true, Text::AsTable.get(language));
    });
    let read_only = view.online.is_logged_in();
    if texts.tables.get(name).copied().unwrap_or(false) {
        // The overlaps are computed once per project revision, not per frame.
        let warnings = editor::overlap_warnings(view.overlaps, &gvl.name);
        let output = VariableTable::new(("gvl", &gvl.name))
            .read_only(read_only)
            .drag_prefix(Some(gvl.name.clone()))
            .texts(table_texts(view.language))
            .show(ui, &gvl.variables, &warnings);
        if let Some((label, edit)) = output.edit {
            commands.push(Command::Edit(
                label,
                vec![Edit::Variables {
                    owner: VarOwner::Gvl(gvl.name.clone()),
                    edit,
                }],
            ));
        }
        return true;
    }
    let text = gvl.declaration_text();
    let entry = texts.editor(TextKey::Gvl(gvl.name.clone()), &text);
    entry.editor.set_read_only(read_only);
    let output = entry.editor.show(
        ui,
        &Text::DeclarationsOf.fill(view.language, &[("name", &gvl.name)]),
        &KeywordCompletions,
    );
    if output.changes.is_empty() {
        return true;
    }
    let typed = entry.editor.text().to_owned();
    match compiler::ide::parse_declarations(&typed) {
        Err(errors) => entry
            .editor
            .set_diagnostics(errors.iter().map(editor_diagnostic).collect()),
        Ok(parsed) => {
            entry.editor.set_diagnostics(Vec::new());
            if let DeclarationsChange::Changed { edit, rendered } =
                gvl_declarations_change(gvl, typed_declarations(parsed))
            {
                entry.synced = rendered;
                let merge_key = match output.gesture {
                    Some(Gesture::Typing { run }) => Some(format!("gvl {} {run}", gvl.name)),
                    _ => None,
                };
                commands.push(Command::EditText {
                    label: Text::UndoEditDeclarations.fill(view.language, &[("name", &gvl.name)]),
                    edits: vec![*edit],
                    merge_key,
                });
            }
        }
    }
    true
}
