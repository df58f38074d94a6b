//! The cells of one row of the declaration table: what each draws and the edit it returns.

use std::collections::HashMap;

use egui::{Id, Key, Label, Response, RichText, Role, TextEdit, Ui, WidgetInfo};
use project_model::{ListEdit, VarSection, Variable};

use super::cells::{self, TextColumn};
use super::state::{Draft, RowAction, TableState};
use crate::TableTexts;
use crate::table_texts::fill;

/// Sets one of the retain, persistent and constant flags of a variable.
type SetFlag = fn(&mut Variable, bool);

/// Everything the cells of one frame share: the rows, the remembered state, and the gesture of
/// the frame (at most one edit or row action is made per frame).
pub(crate) struct TableFrame<'a> {
    /// The table's id; cell ids derive from it.
    pub(crate) id: Id,
    /// The variables shown.
    pub(crate) variables: &'a [Variable],
    /// Overlap warnings by variable name.
    pub(crate) warnings: &'a HashMap<String, String>,
    /// Selection and drafts.
    pub(crate) state: &'a mut TableState,
    /// Whether cells only show their values.
    pub(crate) read_only: bool,
    /// The path prefix under which names can be dragged, if they can.
    pub(crate) drag_prefix: Option<&'a str>,
    /// Whether names can be dragged without a path too (onto a CFC pin).
    pub(crate) drag_names: bool,
    /// The table's words.
    pub(crate) texts: &'a TableTexts,
    /// The committed cell edit of this frame, with its undo label.
    pub(crate) edit: Option<(String, ListEdit<Variable>)>,
    /// The row gesture of this frame.
    pub(crate) action: Option<RowAction>,
}

impl TableFrame<'_> {
    /// Whether row `row` shows an error line under its cells, which makes it taller.
    pub(crate) fn row_has_error(&self, row: usize) -> bool {
        let drafted = self
            .state
            .drafts
            .iter()
            .any(|((draft_row, column), draft)| {
                *draft_row == row
                    && cells::cell_error(self.variables, row, *column, &draft.text).is_some()
            });
        drafted
            || self
                .variables
                .get(row)
                .is_some_and(|variable| cells::address_error(variable).is_some())
    }

    /// The section cell: a combo box of the IEC sections.
    pub(crate) fn section_cell(&mut self, ui: &mut Ui, row: usize) {
        let variables = self.variables;
        let variable = &variables[row];
        if self.read_only {
            ui.label(variable.section.keyword());
            return;
        }
        let mut chosen = None;
        let combo = egui::ComboBox::from_id_salt(self.id.with(("section", row)))
            .selected_text(variable.section.keyword())
            .width(ui.available_width())
            .show_ui(ui, |ui| {
                for section in VarSection::ALL {
                    let current = section == variable.section;
                    if ui.selectable_label(current, section.keyword()).clicked() && !current {
                        chosen = Some(section);
                    }
                }
            });
        let label = fill(
            &self.texts.cell_of,
            &[("column", &self.texts.section), ("name", &variable.name)],
        );
        combo
            .response
            .widget_info(|| WidgetInfo::labeled(Role::ComboBox, true, &label));
        self.row_gestures(&combo.response, row);
        if let Some(section) = chosen {
            let item = Variable {
                section,
                ..variable.clone()
            };
            self.edit = Some((label, ListEdit::Replace { index: row, item }));
            self.state.selected = Some(row);
        }
    }

    /// A cell edited as text. Typing keeps a draft; Enter, Tab or a click elsewhere commits it
    /// as one `Replace` if it is valid; Escape abandons it.
    pub(crate) fn text_cell(&mut self, ui: &mut Ui, row: usize, column: TextColumn) {
        let variables = self.variables;
        let variable = &variables[row];
        let label = fill(
            &self.texts.cell_of,
            &[
                ("column", column.title(self.texts)),
                ("name", &variable.name),
            ],
        );
        let warning = (column == TextColumn::Address)
            .then(|| self.warnings.get(&variable.name))
            .flatten();
        if column == TextColumn::Name && (self.drag_prefix.is_some() || self.drag_names) {
            // A handle beside the name drags the variable to a watch list (by its path) or onto
            // a CFC pin (by its name).
            let path = self
                .drag_prefix
                .map(|prefix| format!("{prefix}.{}", variable.name));
            let payload = crate::VariableDragPayload {
                name: variable.name.clone(),
                path: path.clone(),
            };
            let handle = ui
                .dnd_drag_source(self.id.with(("drag", row)), payload, |ui| {
                    ui.label(RichText::new("::").weak())
                })
                .response
                .on_hover_text(&self.texts.drag_hint);
            let shown = path.unwrap_or_else(|| variable.name.clone());
            let label = fill(&self.texts.drag_path, &[("path", &shown)]);
            handle.widget_info(|| WidgetInfo::labeled(Role::Button, true, &label));
        }
        if self.read_only {
            ui.horizontal(|ui| {
                if let Some(warning) = warning {
                    warning_mark(ui, self.texts, &variable.name, warning);
                }
                ui.label(column.text(variable));
            });
            return;
        }
        let key = (row, column);
        let mut text = self
            .state
            .drafts
            .get(&key)
            .map_or_else(|| column.text(variable), |draft| draft.text.clone());
        let error_before = self.cell_error(row, column, &text);
        let error_color = ui.visuals().error_fg_color;
        ui.vertical(|ui| {
            let response = ui
                .horizontal(|ui| {
                    if let Some(warning) = warning {
                        warning_mark(ui, self.texts, &variable.name, warning);
                    }
                    let mut field = TextEdit::singleline(&mut text)
                        .id(self.id.with((column, row)))
                        .desired_width(f32::INFINITY);
                    if error_before.is_some() {
                        field = field.text_color(error_color);
                    }
                    ui.add(field)
                })
                .inner;
            response.widget_info(|| WidgetInfo {
                current_text_value: Some(text.clone()),
                ..WidgetInfo::labeled(Role::TextInput, true, &label)
            });
            if response.gained_focus() || response.clicked() {
                self.state.selected = Some(row);
            }
            if response.changed() {
                let draft = Draft {
                    original: variable.clone(),
                    text: text.clone(),
                };
                self.state.drafts.insert(key, draft);
            }
            if response.lost_focus() {
                self.commit(ui, row, column, &label);
            }
            self.row_gestures(&response, row);
            if let Some(error) = self.cell_error(row, column, &text) {
                let shown =
                    ui.add(Label::new(RichText::new(&error).color(error_color).small()).wrap());
                shown.widget_info(|| {
                    WidgetInfo::labeled(Role::Label, true, format!("{label}: {error}"))
                });
            }
        });
    }

    /// The error of the cell's text: a draft is judged as typed; an address already in the
    /// model is judged against the row's type, which may have changed since.
    fn cell_error(&self, row: usize, column: TextColumn, text: &str) -> Option<String> {
        if self.state.drafts.contains_key(&(row, column)) {
            return cells::cell_error(self.variables, row, column, text);
        }
        match column {
            TextColumn::Address => cells::address_error(&self.variables[row]),
            _ => None,
        }
    }

    /// Turns the cell's draft into an edit when focus leaves it.
    fn commit(&mut self, ui: &Ui, row: usize, column: TextColumn, label: &str) {
        let key = (row, column);
        if ui.input(|input| input.key_pressed(Key::Escape)) {
            self.state.drafts.remove(&key);
            return;
        }
        let Some(draft) = self.state.drafts.get(&key) else {
            return;
        };
        if cells::cell_error(self.variables, row, column, &draft.text).is_some() {
            // The draft stays with its error in view; nothing reaches the model.
            return;
        }
        let variables = self.variables;
        let variable = &variables[row];
        let item = column.with_text(variable, &draft.text);
        self.state.drafts.remove(&key);
        if item != *variable {
            self.edit = Some((label.to_owned(), ListEdit::Replace { index: row, item }));
        }
    }

    /// The retain, persistent and constant check boxes.
    pub(crate) fn flags_cell(&mut self, ui: &mut Ui, row: usize) {
        let variables = self.variables;
        let variable = &variables[row];
        let texts = self.texts;
        let flags: [(&str, &str, bool, SetFlag); 3] = [
            ("R", &texts.retain, variable.retain, |v, on| v.retain = on),
            ("P", &texts.persistent, variable.persistent, |v, on| {
                v.persistent = on
            }),
            ("C", &texts.constant, variable.constant, |v, on| {
                v.constant = on
            }),
        ];
        for (short, title, value, set) in flags {
            let mut checked = value;
            let label = fill(
                &texts.cell_of,
                &[("column", title), ("name", &variable.name)],
            );
            let response = ui
                .add_enabled(!self.read_only, egui::Checkbox::new(&mut checked, short))
                .on_hover_text(title);
            response.widget_info(|| WidgetInfo::selected(Role::CheckBox, true, checked, &label));
            self.row_gestures(&response, row);
            if response.changed() {
                let mut item = variable.clone();
                set(&mut item, checked);
                self.edit = Some((label, ListEdit::Replace { index: row, item }));
                self.state.selected = Some(row);
            }
        }
    }

    /// A cell's share of the row: a click selects the row, a secondary click opens its menu.
    fn row_gestures(&mut self, response: &Response, row: usize) {
        if response.clicked() || response.secondary_clicked() {
            self.state.selected = Some(row);
        }
        if self.read_only {
            return;
        }
        let len = self.variables.len();
        let texts = self.texts;
        response.context_menu(|ui| {
            let entries = [
                (&texts.insert_above, RowAction::InsertAbove(row), true),
                (&texts.insert_below, RowAction::InsertBelow(row), true),
                (&texts.delete, RowAction::Delete(row), true),
                (&texts.move_up, RowAction::MoveUp(row), row > 0),
                (&texts.move_down, RowAction::MoveDown(row), row + 1 < len),
            ];
            for (text, action, enabled) in entries {
                if ui
                    .add_enabled(enabled, egui::Button::new(text.as_str()))
                    .clicked()
                {
                    self.action = Some(action);
                    ui.close();
                }
            }
        });
    }
}

/// The yellow mark of an overlap warning; the warning shows on hover and is its accessible label.
fn warning_mark(ui: &mut Ui, texts: &TableTexts, name: &str, warning: &str) {
    let palette = crate::EditorPalette::of(ui);
    let mark = ui
        .add(
            Label::new(RichText::new("!").strong().color(palette.table_warning))
                .sense(egui::Sense::hover()),
        )
        .on_hover_text(warning);
    let label = fill(&texts.warning_for, &[("name", name), ("warning", warning)]);
    mark.widget_info(|| WidgetInfo::labeled(Role::Image, true, &label));
}
