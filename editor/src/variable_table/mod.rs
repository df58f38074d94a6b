//! The variable declaration table: one row per variable with its section, name, address, type,
//! initial value, retain, persistent and constant flags, and comment, edited in place.
//!
//! The table never changes the model. Each committed cell returns one
//! `ListEdit::Replace`, each row gesture one `Insert`, `Remove` or `Move`, which the app wraps in
//! `Edit::Variables` and applies after the frame, so a gesture is one undo step.

mod cells;
mod row;
mod state;

use std::collections::HashMap;

use egui::{IdSalt, Ui};
use egui_extras::{Column, TableBuilder};
use project_model::{ListEdit, VarSection, Variable};

use cells::TextColumn;
pub use cells::overlap_warnings;
use row::TableFrame;
use state::{RowAction, TableState};

use crate::TableTexts;

/// The declaration table of one POU, method or global variable list.
///
/// Built each frame; what it remembers between frames (selection, text being typed) lives in
/// egui's memory under its id and is never saved.
#[derive(Clone, Debug)]
pub struct VariableTable {
    id_salt: IdSalt,
    read_only: bool,
    new_section: VarSection,
    drag_prefix: Option<String>,
    drag_names: bool,
    texts: TableTexts,
}

/// What the user did with the table this frame.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VariableTableOutput {
    /// The edit of this frame, with a label for the undo menu ("Address of xStart"); at most one
    /// per frame.
    pub edit: Option<(String, ListEdit<Variable>)>,
    /// The selected row, which the toolbar acts on.
    pub selected: Option<usize>,
}

impl VariableTable {
    /// A table whose state is kept under `id_salt`, unique among the tables shown at once (the
    /// owner's name is a good choice).
    pub fn new(id_salt: impl std::hash::Hash + std::fmt::Debug) -> Self {
        Self {
            id_salt: IdSalt::new(id_salt),
            read_only: false,
            new_section: VarSection::Var,
            drag_prefix: None,
            drag_names: false,
            texts: TableTexts::default(),
        }
    }

    /// Shows the table's words in the user's language.
    pub fn texts(mut self, texts: TableTexts) -> Self {
        self.texts = texts;
        self
    }

    /// Lets each name be dragged as the path `prefix.name` (a program's or a global variable
    /// list's name; a function block's variables have one path per instance, so none).
    pub fn drag_prefix(mut self, prefix: Option<String>) -> Self {
        self.drag_prefix = prefix;
        self
    }

    /// Lets each name be dragged even without a path, for a CFC body of the same POU to drop
    /// on a pin ([`crate::VariableDragPayload`]).
    pub fn drag_names(mut self, drag: bool) -> Self {
        self.drag_names = drag;
        self
    }

    /// Shows values without editing them (online, or a library POU).
    pub fn read_only(mut self, read_only: bool) -> Self {
        self.read_only = read_only;
        self
    }

    /// The section of a variable inserted into an empty table (`VAR_GLOBAL` for a list);
    /// otherwise a new row takes its neighbour's section.
    pub fn new_section(mut self, section: VarSection) -> Self {
        self.new_section = section;
        self
    }

    /// Draws `variables` and returns what the user did. `warnings` holds the overlap warnings by
    /// variable name (see [`overlap_warnings`]), shown as yellow marks beside the address.
    pub fn show(
        self,
        ui: &mut Ui,
        variables: &[Variable],
        warnings: &HashMap<String, String>,
    ) -> VariableTableOutput {
        let id = ui.make_persistent_id(self.id_salt);
        let mut state: TableState = ui.data(|data| data.get_temp(id)).unwrap_or_default();
        state.forget_stale(variables);
        let mut frame = TableFrame {
            id,
            variables,
            warnings,
            state: &mut state,
            read_only: self.read_only,
            drag_prefix: self.drag_prefix.as_deref(),
            drag_names: self.drag_names,
            texts: &self.texts,
            edit: None,
            action: None,
        };
        if !self.read_only {
            toolbar_ui(ui, &mut frame);
        }
        table_ui(ui, &mut frame);
        let TableFrame { edit, action, .. } = frame;
        let edit = edit.or_else(|| {
            let (label, edit, selected) = action?.edit(variables, self.new_section, &self.texts)?;
            state.selected = selected;
            Some((label, edit))
        });
        let selected = state.selected;
        ui.data_mut(|data| data.insert_temp(id, state));
        VariableTableOutput { edit, selected }
    }
}

/// The buttons above the table, acting on the selected row (or appending when none is).
fn toolbar_ui(ui: &mut Ui, frame: &mut TableFrame<'_>) {
    let selected = frame.state.selected;
    let len = frame.variables.len();
    ui.horizontal(|ui| {
        let at = selected.unwrap_or(len);
        let texts = frame.texts;
        let buttons = [
            (&texts.insert_above, RowAction::InsertAbove(at), true),
            (
                &texts.insert_below,
                RowAction::InsertBelow(selected.unwrap_or(len)),
                true,
            ),
            (&texts.delete, RowAction::Delete(at), selected.is_some()),
            (
                &texts.move_up,
                RowAction::MoveUp(at),
                selected.is_some_and(|row| row > 0),
            ),
            (
                &texts.move_down,
                RowAction::MoveDown(at),
                selected.is_some_and(|row| row + 1 < len),
            ),
        ];
        for (text, action, enabled) in buttons {
            if ui
                .add_enabled(enabled, egui::Button::new(text.as_str()))
                .clicked()
            {
                frame.action = Some(action);
            }
        }
    });
}

/// The table itself: a header and one row per variable.
fn table_ui(ui: &mut Ui, frame: &mut TableFrame<'_>) {
    let line = ui.spacing().interact_size.y + 4.0;
    let error_lines = 2.0 * ui.text_style_height(&egui::TextStyle::Small) + 2.0;
    let selected = frame.state.selected;
    let texts = frame.texts;
    TableBuilder::new(ui)
        .id_salt(frame.id.with("table"))
        .striped(true)
        .resizable(true)
        .auto_shrink([false, true])
        .cell_layout(egui::Layout::left_to_right(egui::Align::Center))
        .column(Column::initial(120.0).at_least(90.0).clip(true))
        .column(Column::initial(140.0).at_least(60.0).clip(true))
        .column(Column::initial(150.0).at_least(60.0).clip(true))
        .column(Column::initial(120.0).at_least(50.0).clip(true))
        .column(Column::initial(100.0).at_least(40.0).clip(true))
        .column(Column::auto())
        .column(Column::remainder().at_least(80.0).clip(true))
        .header(line, |mut header| {
            for title in [
                texts.section.as_str(),
                TextColumn::Name.title(texts),
                TextColumn::Address.title(texts),
                TextColumn::Type.title(texts),
                TextColumn::Initial.title(texts),
                texts.flags.as_str(),
                TextColumn::Comment.title(texts),
            ] {
                header.col(|ui| {
                    ui.strong(title);
                });
            }
        })
        .body(|mut body| {
            for index in 0..frame.variables.len() {
                let height = if frame.row_has_error(index) {
                    line + error_lines
                } else {
                    line
                };
                body.row(height, |mut row| {
                    row.set_selected(selected == Some(index));
                    row.col(|ui| frame.section_cell(ui, index));
                    for column in [TextColumn::Name, TextColumn::Address, TextColumn::Type] {
                        row.col(|ui| frame.text_cell(ui, index, column));
                    }
                    row.col(|ui| frame.text_cell(ui, index, TextColumn::Initial));
                    row.col(|ui| frame.flags_cell(ui, index));
                    row.col(|ui| frame.text_cell(ui, index, TextColumn::Comment));
                });
            }
        });
}
