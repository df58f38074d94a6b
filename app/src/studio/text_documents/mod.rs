//! The documents that hold Structured Text: POUs (declarations as text or as a table above the
//! implementation; methods, actions and property accessors one at a time) and global variable
//! lists. Text is edited with `editor::StEditor`; every change goes to the model as an edit
//! after the frame, typing merged into one undo step per run.

mod inline;
mod live_check;
mod services;

use std::collections::HashMap;
use std::ops::Range;

use editor::{
    EditorDiagnostic, EditorTexts, Gesture, KeywordCompletions, StEditor, TableTexts, VariableTable,
};
use egui::{RichText, Ui};
use project_model::{Body, Edit, GlobalVarList, Object, Pou, Project, TextTarget, VarOwner};

use super::command::{Command, Commands};
use super::i18n::{Language, Text};
pub use super::reveal::Reveal;
use super::tree_node::TreeNode;
use super::view::StudioView;
pub use inline::InlineValues;
use live_check::LiveCheck;
use services::BodyServices;

/// Which text an editor holds.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum TextKey {
    /// A body.
    Body(TextTarget),
    /// The declaration part of a POU (`method: None`) or of one of its methods.
    Declarations {
        /// The POU.
        pou: String,
        /// The method, if it is one.
        method: Option<String>,
    },
    /// A global variable list's declarations.
    Gvl(String),
}

/// The part of a POU a document shows.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum Part {
    /// The POU's own declarations and implementation.
    #[default]
    Main,
    /// A method.
    Method(String),
    /// An action.
    Action(String),
    /// A property's getter or setter.
    Property(String, bool),
}

/// One editor and the model text it was last brought in line with.
struct TextEditor {
    editor: StEditor,
    /// The model's text the editor's text stands for. The editor may hold a different text
    /// (a declaration part typed but not yet valid, or formatted differently from the model's
    /// rendering); it is replaced only when the model's text changes from elsewhere.
    synced: String,
}

/// Every text editor of the open documents and what they share.
#[derive(Default)]
pub struct TextDocuments {
    editors: HashMap<TextKey, TextEditor>,
    /// The part each POU document shows.
    parts: HashMap<String, Part>,
    /// Whether a POU document shows its declarations as a table rather than text.
    tables: HashMap<String, bool>,
    /// A place to show once its document is drawn.
    pub reveal: Option<(TreeNode, Reveal)>,
    live: LiveCheck,
    /// Values shown inline while online, and the prepared ones typed in their boxes.
    pub inline: InlineValues,
    /// The language the editors' own words are in.
    language: Language,
}

/// The editor's own words (find bar, value box) in `language`.
fn editor_texts(language: Language) -> EditorTexts {
    let get = |text: Text| text.get(language).to_owned();
    EditorTexts {
        find: get(Text::Find),
        replace: get(Text::ReplaceWith),
        match_case: get(Text::MatchCase),
        whole_word: get(Text::WholeWord),
        previous: get(Text::Previous),
        next: get(Text::Next),
        replace_one: get(Text::ReplaceOne),
        replace_all: get(Text::ReplaceAll),
        close: get(Text::Close),
        prepared_value: get(Text::PreparedValue),
    }
}

/// The declaration table's and the I/O mapping's words in `language`.
pub(super) fn table_texts(language: Language) -> TableTexts {
    let get = |text: Text| text.get(language).to_owned();
    TableTexts {
        section: get(Text::TableSection),
        name: get(Text::Name),
        address: get(Text::TableAddress),
        data_type: get(Text::TableType),
        initial_value: get(Text::TableInitialValue),
        flags: get(Text::TableFlags),
        comment: get(Text::Comment),
        retain: get(Text::Retain),
        persistent: get(Text::Persistent),
        constant: get(Text::Constant),
        insert_above: get(Text::InsertAbove),
        insert_below: get(Text::InsertBelow),
        delete: get(Text::Delete),
        move_up: get(Text::MoveUp),
        move_down: get(Text::MoveDown),
        drag_hint: get(Text::DragIntoWatch),
        cell_of: get(Text::CellOf),
        drag_path: get(Text::DragPath),
        warning_for: get(Text::WarningFor),
        insert_variable: get(Text::InsertVariable),
        delete_variable: get(Text::DeleteVariable),
        move_variable_up: get(Text::MoveVariableUp),
        move_variable_down: get(Text::MoveVariableDown),
        no_io_areas: get(Text::NoIoAreas),
        outside_areas: get(Text::OutsideAreas),
        inputs: get(Text::AreaInputs),
        outputs: get(Text::AreaOutputs),
        markers: get(Text::AreaMarkers),
        channel: get(Text::Channel),
        variable: get(Text::Variable),
        declared_as: get(Text::DeclaredAs),
        modbus_table: get(Text::ModbusTable),
        no_binding: get(Text::NoBinding),
        not_declared: get(Text::NotDeclared),
        coil: get(Text::Coil),
        discrete_input: get(Text::DiscreteInput),
        holding_register: get(Text::HoldingRegister),
        input_register: get(Text::InputRegister),
    }
}

impl TextDocuments {
    /// Forgets every editor (another project was opened).
    pub fn clear(&mut self) {
        *self = Self::default();
    }

    /// The live check's findings in a POU as `CODE: message`.
    pub fn live_findings(&self, pou: &str) -> Vec<String> {
        self.live
            .findings(pou)
            .map(|(_, found)| {
                found
                    .iter()
                    .map(|f| format!("{}: {}", f.diagnostic.code.id(), f.diagnostic.message))
                    .collect()
            })
            .unwrap_or_default()
    }

    /// The selection of a body's editor.
    pub fn body_selection(&self, target: &TextTarget) -> Option<Range<usize>> {
        self.editors
            .get(&TextKey::Body(target.clone()))
            .map(|entry| entry.editor.selection())
    }

    /// Puts the editors' own words in `language` (called every frame; changes only on a
    /// switch of language).
    pub fn set_language(&mut self, language: Language) {
        if language != self.language {
            self.language = language;
            for entry in self.editors.values_mut() {
                entry.editor.set_texts(editor_texts(language));
            }
        }
    }

    fn editor(&mut self, key: TextKey, model: &str) -> &mut TextEditor {
        let language = self.language;
        let entry = self.editors.entry(key).or_insert_with(|| {
            let mut editor = StEditor::new(model);
            editor.set_texts(editor_texts(language));
            TextEditor {
                editor,
                synced: model.to_owned(),
            }
        });
        if entry.synced != model {
            entry.editor.set_text(model);
            entry.synced = model.to_owned();
        }
        entry
    }
}

/// The POU part a document shows, and where to put the caret in it this frame.
#[derive(Clone, Copy)]
struct Shown<'a> {
    /// The POU.
    pou: &'a Pou,
    /// Its part shown.
    part: &'a Part,
    /// The place to reveal, once.
    reveal: Option<&'a Reveal>,
}

/// The body of a POU part, with its target.
fn body_of<'p>(pou: &'p Pou, part: &Part) -> Option<(TextTarget, &'p Body)> {
    let name = pou.name.clone();
    Some(match part {
        Part::Main => (TextTarget::Pou(name), &pou.body),
        Part::Method(method) => (
            TextTarget::Method {
                pou: name,
                method: method.clone(),
            },
            &pou.methods.iter().find(|m| m.name == *method)?.body,
        ),
        Part::Action(action) => (
            TextTarget::Action {
                pou: name,
                action: action.clone(),
            },
            &pou.actions.iter().find(|a| a.name == *action)?.body,
        ),
        Part::Property(property, get) => {
            let property_data = pou.properties.iter().find(|p| p.name == *property)?;
            let accessor = if *get {
                property_data.get.as_ref()
            } else {
                property_data.set.as_ref()
            }?;
            (
                TextTarget::Property {
                    pou: name,
                    property: property.clone(),
                    get: *get,
                },
                &accessor.body,
            )
        }
    })
}

/// Draws a POU document (graphical bodies as their data until their editors come). Returns
/// `false` when `name` is not a POU.
pub(crate) fn pou_document_ui(
    view: StudioView<'_>,
    texts: &mut TextDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    name: &str,
) -> bool {
    let Some(project) = view.project() else {
        return false;
    };
    let Some(Object::Pou(pou)) = project.application.object(name) else {
        return false;
    };
    let language = view.language;
    let mut part = texts.parts.get(name).cloned().unwrap_or_default();

    // A pending reveal for this document picks its part first.
    let node = TreeNode::Object(name.to_owned());
    let reveal = match &texts.reveal {
        Some((target, reveal)) if *target == node => {
            let reveal = reveal.clone();
            texts.reveal = None;
            Some(reveal)
        }
        _ => None,
    };
    if let Some(Reveal::Body(target, _)) = &reveal {
        part = part_of(target);
    }
    if let Some(Reveal::Declaration {
        container: Some(container),
        ..
    }) = &reveal
        && pou.methods.iter().any(|m| m.name == *container)
    {
        part = Part::Method(container.clone());
    }

    // The part selector: the POU and each method, action and property accessor.
    ui.horizontal_wrapped(|ui| {
        ui.label(RichText::new(format!("{} {}", pou.kind.keyword(), pou.name)).strong());
        ui.separator();
        let mut choices = vec![(Part::Main, Text::Implementation.get(language).to_owned())];
        choices.extend(pou.methods.iter().map(|m| {
            (
                Part::Method(m.name.clone()),
                format!("{} {}", Text::Method.get(language), m.name),
            )
        }));
        choices.extend(pou.actions.iter().map(|a| {
            (
                Part::Action(a.name.clone()),
                format!("{} {}", Text::Action.get(language), a.name),
            )
        }));
        for property in &pou.properties {
            for (get, word) in [(true, "Get"), (false, "Set")] {
                let exists = if get {
                    property.get.is_some()
                } else {
                    property.set.is_some()
                };
                if exists {
                    choices.push((
                        Part::Property(property.name.clone(), get),
                        format!("{} {}.{word}", Text::Property.get(language), property.name),
                    ));
                }
            }
        }
        if choices.len() > 1 {
            for (choice, text) in choices {
                if ui.selectable_label(part == choice, text).clicked() {
                    part = choice;
                }
            }
        }
        ui.separator();
        let table = texts.tables.entry(name.to_owned()).or_insert(false);
        ui.selectable_value(table, false, Text::AsText.get(language));
        ui.selectable_value(table, true, Text::AsTable.get(language));
    });
    texts.parts.insert(name.to_owned(), part.clone());

    let show_table = texts.tables.get(name).copied().unwrap_or(false);
    let height = ui.available_height();
    let declaration_height = (height * 0.35).clamp(80.0, 320.0);
    egui::Panel::top(egui::Id::unique(("declarations", name)))
        .resizable(true)
        .default_size(declaration_height)
        .show(ui, |ui| {
            let shown = Shown {
                pou,
                part: &part,
                reveal: reveal.as_ref(),
            };
            declarations_ui(view, texts, commands, ui, shown, show_table);
        });
    egui::CentralPanel::default_margins().show(ui, |ui| {
        let shown = Shown {
            pou,
            part: &part,
            reveal: reveal.as_ref(),
        };
        body_ui(view, texts, commands, ui, shown);
    });
    true
}

fn part_of(target: &TextTarget) -> Part {
    match target {
        TextTarget::Pou(_) => Part::Main,
        TextTarget::Method { method, .. } => Part::Method(method.clone()),
        TextTarget::Action { action, .. } => Part::Action(action.clone()),
        TextTarget::Property { property, get, .. } => Part::Property(property.clone(), *get),
    }
}

/// The declarations of the POU part: as text (parsed back into the model as you type) or as
/// the variable table.
fn declarations_ui(
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
    let read_only =
        matches!(part, Part::Property(..) | Part::Action(_)) || view.online.is_logged_in();
    if show_table && !matches!(part, Part::Property(..) | Part::Action(_)) {
        // The overlaps are computed once per project revision, not per frame.
        let warnings = editor::overlap_warnings(view.overlaps, &pou.name);
        let drag_prefix = (pou.kind == project_model::PouKind::Program && method.is_none())
            .then(|| pou.name.clone());
        let output = VariableTable::new(("variables", &pou.name, &method))
            .read_only(read_only)
            .drag_prefix(drag_prefix)
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
    let label = format!(
        "Declarations of {}",
        method
            .as_ref()
            .map_or(pou.name.clone(), |m| format!("{}.{m}", pou.name))
    );
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
            let renamed = parsed.header.as_ref().is_some_and(|header| {
                !header
                    .name
                    .eq_ignore_ascii_case(method.as_deref().unwrap_or(&pou.name))
            });
            if renamed {
                entry.editor.set_diagnostics(vec![EditorDiagnostic {
                    range: 0..typed.find('\n').unwrap_or(typed.len()),
                    severity: editor::Severity::Error,
                    code: String::new(),
                    message: Text::RenameInTree.get(view.language).to_owned(),
                }]);
                return;
            }
            let mut changed = pou.clone();
            match &method {
                Some(method) => {
                    if let Some(m) = changed.methods.iter_mut().find(|m| m.name == *method) {
                        m.variables = parsed.variables;
                        if let Some(header) = parsed.header {
                            m.return_type = header.return_type;
                        }
                    }
                }
                None => {
                    changed.variables = parsed.variables;
                    changed.comment = parsed.comment;
                    if let Some(header) = parsed.header {
                        changed.return_type = header.return_type;
                        changed.extends = header.extends;
                        changed.implements = header.implements;
                    }
                }
            }
            if changed != *pou {
                // The model will render this text; until it changes from elsewhere the editor
                // keeps what was typed.
                entry.synced = match &method {
                    Some(method) => changed
                        .methods
                        .iter()
                        .find(|m| m.name == *method)
                        .map(|m| m.declaration_text())
                        .unwrap_or_default(),
                    None => changed.declaration_text(),
                };
                let merge = match output.gesture {
                    Some(Gesture::Typing { run }) => {
                        Some(format!("declarations {} {run}", pou.name))
                    }
                    _ => None,
                };
                commands.push(Command::EditText {
                    label: format!("Edit the declarations of {}", pou.name),
                    edits: vec![Edit::ReplaceObject(Object::Pou(changed))],
                    merge_key: merge,
                });
            }
        }
    }
}

/// The live check's findings in the POU's declarations, placed on the declared names.
fn declaration_diagnostics(
    live: &LiveCheck,
    pou: &str,
    text: &str,
) -> Option<Vec<EditorDiagnostic>> {
    let (_, findings) = live.findings(pou)?;
    Some(
        findings
            .iter()
            .filter_map(|found| {
                let name = found.declaration.as_deref()?;
                let range = find_word(text, name)?;
                Some(EditorDiagnostic {
                    range,
                    severity: severity(found.diagnostic.severity),
                    code: found.diagnostic.code.id().to_owned(),
                    message: found.diagnostic.message.clone(),
                })
            })
            .collect(),
    )
}

fn severity(severity: compiler::Severity) -> editor::Severity {
    match severity {
        compiler::Severity::Error => editor::Severity::Error,
        compiler::Severity::Warning => editor::Severity::Warning,
    }
}

fn editor_diagnostic(diagnostic: &compiler::Diagnostic) -> EditorDiagnostic {
    EditorDiagnostic {
        range: diagnostic.range.clone(),
        severity: severity(diagnostic.severity),
        code: diagnostic.code.id().to_owned(),
        message: diagnostic.message.clone(),
    }
}

/// The first whole-word, case-insensitive occurrence of `word` in `text`.
pub fn find_word(text: &str, word: &str) -> Option<Range<usize>> {
    if word.is_empty() {
        return None;
    }
    let lower = text.to_ascii_lowercase();
    let wanted = word.to_ascii_lowercase();
    let is_word = |c: char| c.is_alphanumeric() || c == '_';
    let mut from = 0;
    while let Some(found) = lower[from..].find(&wanted) {
        let start = from + found;
        let end = start + wanted.len();
        let before = lower[..start].chars().next_back();
        let after = lower[end..].chars().next();
        if !before.is_some_and(is_word) && !after.is_some_and(is_word) {
            return Some(start..end);
        }
        from = end;
    }
    None
}

/// The implementation of the POU part, with live diagnostics, completion, hover, F12, Shift+F12
/// and values inline while online.
fn body_ui(
    view: StudioView<'_>,
    texts: &mut TextDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    shown: Shown<'_>,
) {
    let Shown { pou, part, reveal } = shown;
    let language = view.language;
    let Some((target, body)) = body_of(pou, part) else {
        ui.label(RichText::new(Text::NoImplementation.get(language)).weak());
        return;
    };
    let Some(text) = body.st_text() else {
        match body {
            Body::None => {
                ui.label(RichText::new(Text::NoImplementation.get(language)).weak());
            }
            graphical => {
                super::document_view::graphical_body_ui(ui, &target_label(&target), graphical)
            }
        }
        return;
    };
    let Some(session) = view.session else {
        return;
    };
    let project = &session.project;
    let revision = session.history.revision();
    if texts.live.update(project, &pou.name, revision) {
        ui.ctx().request_repaint_after(live_check::CHECK_DELAY);
    }
    let diagnostics = body_diagnostics(&texts.live, project, &pou.name, &target);
    let inline = if view.online.is_online() {
        texts
            .inline
            .values_for(view.online, project, &target, text, pou)
    } else {
        texts.inline.forget(&target);
        Vec::new()
    };
    let read_only = view.online.is_logged_in();
    let key = TextKey::Body(target.clone());
    let text = text.to_owned();
    let label = format!("Implementation of {}", target_label(&target));
    let services = BodyServices {
        project,
        target: target.clone(),
    };
    let entry = texts.editor(key, &text);
    entry.editor.set_read_only(read_only);
    if let Some(diagnostics) = diagnostics {
        entry.editor.set_diagnostics(diagnostics);
    }
    entry.editor.set_inline_values(inline);
    if let Some(Reveal::Body(_, range)) = reveal {
        entry.editor.reveal(range.clone());
        entry.editor.request_focus();
    }
    let output = entry.editor.show(ui, &label, &services);
    if let Some(offset) = output.goto_definition {
        match compiler::ide::definition(project, &target, offset) {
            Some(definition) => {
                let object = definition.object.clone().unwrap_or_default();
                if object.is_empty() {
                    commands.status(
                        Text::InStandardLibrary
                            .get(language)
                            .replace("{name}", &definition.name),
                    );
                } else {
                    commands.push(Command::Reveal(
                        TreeNode::Object(object),
                        Reveal::Declaration {
                            container: definition.container.clone(),
                            name: definition.name.clone(),
                        },
                    ));
                }
            }
            None => commands.status(Text::NoDeclarationAtCaret.get(language)),
        }
    }
    if let Some(offset) = output.find_references {
        commands.push(Command::FindReferences(target.clone(), offset));
    }
    if let Some((range, value)) = output.prepared {
        texts.inline.prepare(&target, range, value);
    }
    if !output.changes.is_empty() {
        let edits = output
            .changes
            .into_iter()
            .map(|change| Edit::ReplaceText {
                target: target.clone(),
                range: change.range,
                text: change.text,
            })
            .collect();
        let merge_key = match output.gesture {
            Some(Gesture::Typing { run }) => Some(format!("{target:?} {run}")),
            _ => None,
        };
        commands.push(Command::EditText {
            label: format!("Edit {}", target_label(&target)),
            edits,
            merge_key,
        });
    }
}

/// The live check's findings in one body.
fn body_diagnostics(
    live: &LiveCheck,
    project: &Project,
    pou: &str,
    target: &TextTarget,
) -> Option<Vec<EditorDiagnostic>> {
    let (_, findings) = live.findings(pou)?;
    let file = project_model::st_body_files(project)
        .into_iter()
        .find(|body| body.target == *target)
        .map(|body| body.file)?;
    Some(
        findings
            .iter()
            .filter(|found| found.file == file && found.declaration.is_none())
            .map(|found| editor_diagnostic(&found.diagnostic))
            .collect(),
    )
}

/// A body's name for labels: `Main`, `FB_Motor.Start`, `FB_Motor.Speed.Get`.
pub fn target_label(target: &TextTarget) -> String {
    match target {
        TextTarget::Pou(pou) => pou.clone(),
        TextTarget::Method { pou, method } => format!("{pou}.{method}"),
        TextTarget::Action { pou, action } => format!("{pou}.{action}"),
        TextTarget::Property { pou, property, get } => {
            format!("{pou}.{property}.{}", if *get { "Get" } else { "Set" })
        }
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
        &format!("Declarations of {}", gvl.name),
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
            let changed = GlobalVarList {
                variables: parsed.variables,
                comment: parsed.comment,
                ..gvl.clone()
            };
            if changed != *gvl {
                entry.synced = changed.declaration_text();
                let merge_key = match output.gesture {
                    Some(Gesture::Typing { run }) => Some(format!("gvl {} {run}", gvl.name)),
                    _ => None,
                };
                commands.push(Command::EditText {
                    label: format!("Edit the declarations of {}", gvl.name),
                    edits: vec![Edit::ReplaceObject(Object::Gvl(changed))],
                    merge_key,
                });
            }
        }
    }
    true
}
