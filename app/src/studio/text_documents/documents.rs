//! The text editors of the open documents and the words they show.

use std::collections::HashMap;
use std::ops::Range;

use editor::{EditorTexts, StEditor, TableTexts};
use project_model::TextTarget;

use super::part::Part;
use crate::studio::graphical_documents::GraphicalDocuments;
use crate::studio::i18n::{Language, Text};
use crate::studio::reveal::Reveal;
use crate::studio::tree_node::TreeNode;

use super::inline::InlineValues;
use super::live_check::LiveCheck;

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

/// One editor and the model text it was last brought in line with.
pub(super) struct TextEditor {
    pub(super) editor: StEditor,
    /// The model's text the editor's text stands for. The editor may hold a different text
    /// (a declaration part typed but not yet valid, or formatted differently from the model's
    /// rendering); it is replaced only when the model's text changes from elsewhere.
    pub(super) synced: String,
}

/// Every text editor of the open documents and what they share.
#[derive(Default)]
pub struct TextDocuments {
    pub(super) editors: HashMap<TextKey, TextEditor>,
    /// The part each POU document shows.
    pub(super) parts: HashMap<String, Part>,
    /// Whether a POU document shows its declarations as a table rather than text.
    pub(super) tables: HashMap<String, bool>,
    /// A place to show once its document is drawn.
    pub reveal: Option<(TreeNode, Reveal)>,
    pub(super) live: LiveCheck,
    /// Values shown inline while online, and the prepared ones typed in their boxes (the
    /// diagram editors' prepared operands among them).
    pub inline: InlineValues,
    /// The diagram editors of the LD and FBD bodies.
    pub graphical: GraphicalDocuments,
    /// The statement line at the caret of the Structured Text body edited last, or the
    /// selected network, element, step or transition of the graphical body used last, where
    /// the Debug menu's "Toggle breakpoint" and "Run to cursor" act; forgotten with the editors.
    pub last_caret: Option<crate::studio::debug::BreakpointPlace>,
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
pub(crate) fn table_texts(language: Language) -> TableTexts {
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

    /// The debugger's marks the editor of a body draws, if it is open.
    pub fn body_debug_marks(&self, target: &TextTarget) -> Option<&editor::StDebugMarks> {
        self.editors
            .get(&TextKey::Body(target.clone()))
            .map(|entry| entry.editor.debug_marks())
    }

    /// The POU bodies open in Structured Text editors, each with the instance its inline
    /// values show (none for a function), sorted by name: what flow control records.
    pub fn flow_bodies(&self, project: &project_model::Project) -> Vec<(String, Option<String>)> {
        let mut bodies: Vec<(String, Option<String>)> = project_model::object_files(project)
            .into_iter()
            .filter_map(|(_, object)| match object {
                project_model::Object::Pou(pou)
                    if self
                        .editors
                        .contains_key(&TextKey::Body(TextTarget::Pou(pou.name.clone()))) =>
                {
                    Some((pou.name.clone(), super::inline::instance_of(project, pou)))
                }
                _ => None,
            })
            .collect();
        bodies.sort();
        bodies
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

    pub(super) fn editor(&mut self, key: TextKey, model: &str) -> &mut TextEditor {
        self.editor_of(key, model, StEditor::new)
    }

    /// The editor of an Instruction List body, highlighted as IL.
    pub(super) fn instruction_list_editor(&mut self, key: TextKey, model: &str) -> &mut TextEditor {
        self.editor_of(key, model, StEditor::instruction_list)
    }

    fn editor_of(
        &mut self,
        key: TextKey,
        model: &str,
        new: fn(&str) -> StEditor,
    ) -> &mut TextEditor {
        let language = self.language;
        let entry = self.editors.entry(key).or_insert_with(|| {
            let mut editor = new(model);
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
