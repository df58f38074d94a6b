//! The shape every device editor shares: fields of one value (a node, or a row of a table),
//! each with a key, a name and a width, whose accepted input changes a copy of the value that
//! goes to the editor's checks with its undo label.

use std::borrow::Cow;
use std::hash::Hash;
use std::ops::RangeInclusive;

use egui::Ui;

use super::field::{
    DeviceEditorState, FieldId, checkbox_ui, parse_number, parse_whole, pending_combo_ui, row_ui,
    text_field_ui,
};
use super::refusal::Refusal;
use super::table::Table;
use super::{DeviceEdit, DeviceTexts, field_label, keep, row_label, set_label};

/// Checks a changed node under its undo label and makes the edit, or says why it is refused.
pub(crate) type Change<'a, T> = &'a dyn Fn(String, T) -> Result<DeviceEdit, Refusal>;

/// Where a form's value lives, which decides its fields' keys and labels.
enum Place<'a, T> {
    /// A node of the device tree, named `node`, whose changes go to `change`.
    Node {
        /// The node's name, as labels show it.
        node: &'a str,
        /// Checks the changed node and makes its edit.
        change: Change<'a, T>,
    },
    /// The row at `index` of `table`.
    Row {
        /// The table holding the row.
        table: &'a Table<'a, T>,
        /// The row's place in the table, from 0.
        index: usize,
    },
}

/// The value a form edits, with the editor's words and where the value lives.
struct Subject<'a, T> {
    /// The editor's words.
    texts: &'a DeviceTexts,
    /// The value as it is now.
    value: &'a T,
    /// Where the value lives.
    place: Place<'a, T>,
}

/// The fields of one value being drawn, and the edit of this frame's gesture among them.
pub(crate) struct Form<'a, T> {
    /// The editor's drafts and refusals.
    state: &'a mut DeviceEditorState,
    /// The value edited.
    subject: Subject<'a, T>,
    /// Whether each field is a row of a two-column grid, titled with its name.
    rows: bool,
    /// The edit of this frame's gesture, if a field made one.
    edit: Option<DeviceEdit>,
}

impl<'a, T: Clone> Form<'a, T> {
    /// The fields of the node `value` named `node`, changed through `change`.
    pub(crate) fn node(
        state: &'a mut DeviceEditorState,
        texts: &'a DeviceTexts,
        value: &'a T,
        node: &'a str,
        change: Change<'a, T>,
    ) -> Self {
        let place = Place::Node { node, change };
        Self::new(state, texts, value, place)
    }

    /// The fields of the row at `index` of `table`.
    pub(crate) fn row(
        state: &'a mut DeviceEditorState,
        texts: &'a DeviceTexts,
        table: &'a Table<'a, T>,
        index: usize,
    ) -> Option<Self> {
        let value = table.rows.get(index)?;
        Some(Self::new(state, texts, value, Place::Row { table, index }))
    }

    /// The fields of `value`, which lives at `place`.
    fn new(
        state: &'a mut DeviceEditorState,
        texts: &'a DeviceTexts,
        value: &'a T,
        place: Place<'a, T>,
    ) -> Self {
        Self {
            state,
            subject: Subject {
                texts,
                value,
                place,
            },
            rows: false,
            edit: None,
        }
    }

    /// Draws the fields `add` adds as the rows of a two-column grid, each titled with its name
    /// (a check box's row has no title: its name stands beside the box).
    pub(crate) fn grid_ui(
        &mut self,
        ui: &mut Ui,
        id_salt: impl Hash + std::fmt::Debug,
        add: impl FnOnce(&mut Self, &mut Ui),
    ) {
        egui::Grid::new(id_salt)
            .num_columns(2)
            .spacing([12.0, 6.0])
            .show(ui, |ui| {
                self.rows = true;
                add(self, ui);
                self.rows = false;
            });
    }

    /// A field keyed `key`, called `name` on its row, in its accessible label and in its undo
    /// label, `width` points wide.
    pub(crate) fn field<'f>(
        &'f mut self,
        key: &'f str,
        name: &'f str,
        width: f32,
    ) -> FormField<'f, 'a, T> {
        FormField {
            form: self,
            key,
            name,
            undo_name: name,
            width,
            suffix: "",
        }
    }

    /// Whether the combo box keyed `key` shows a choice that waits for another field
    /// ([`FormField::pending_combo_ui`]).
    pub(crate) fn is_pending(&self, key: &str) -> bool {
        self.state.is_pending(&self.subject.key(key))
    }

    /// The edit of this frame's gesture, if there was one.
    pub(crate) fn finish(self) -> Option<DeviceEdit> {
        self.edit
    }
}

impl<T: Clone> Subject<'_, T> {
    /// The key of the field `key` in the editor's state.
    fn key<'k>(&self, key: &'k str) -> Cow<'k, str> {
        match &self.place {
            Place::Node { .. } => Cow::Borrowed(key),
            Place::Row { table, index } => Cow::Owned(format!("{} {index} {key}", table.row_key)),
        }
    }

    /// The accessible label of the field `name`: "Port of PLC", "Address of row 2".
    fn label(&self, name: &str) -> String {
        match &self.place {
            Place::Node { node, .. } => field_label(self.texts, name, node),
            Place::Row { index, .. } => row_label(self.texts, name, index + 1),
        }
    }

    /// The edit that sets the field `name` to `value`, making the value `item`.
    fn change(&self, name: &str, value: &str, item: T) -> Result<DeviceEdit, Refusal> {
        match &self.place {
            Place::Node { node, change } => change(set_label(self.texts, name, node, value), item),
            Place::Row { table, index } => {
                let field = row_label(self.texts, name, index + 1);
                let label = set_label(self.texts, &field, table.name, value);
                let mut list = table.rows.to_vec();
                if let Some(row) = list.get_mut(*index) {
                    *row = item;
                }
                (table.commit)(label, list)
            }
        }
    }
}

/// A field of a [`Form`] about to be drawn.
pub(crate) struct FormField<'f, 'a, T> {
    /// The form it belongs to.
    form: &'f mut Form<'a, T>,
    /// Its key in the editor's state.
    key: &'f str,
    /// Its name.
    name: &'f str,
    /// What its undo label calls it.
    undo_name: &'f str,
    /// Its width in points.
    width: f32,
    /// The unit or note after it.
    suffix: &'f str,
}

impl<'f, 'a, T: Clone> FormField<'f, 'a, T> {
    /// Shows `suffix` (a unit, a range) after the field.
    pub(crate) fn suffix(self, suffix: &'f str) -> Self {
        Self { suffix, ..self }
    }

    /// Calls the field `undo_name` in its undo label, for a check box that sets another value.
    pub(crate) fn undo_name(self, undo_name: &'f str) -> Self {
        Self { undo_name, ..self }
    }

    /// A text field showing `current`; the accepted text changes a copy of the value through
    /// `accept`, which returns the value its undo label shows.
    pub(crate) fn typed_ui(
        self,
        ui: &mut Ui,
        current: &str,
        accept: impl FnOnce(&mut T, &str) -> Result<String, Refusal>,
    ) {
        let (suffix, title) = (self.suffix, self.name);
        self.show(ui, title, |ui, state, subject, field, name| {
            text_field_ui(ui, state, subject.texts, field, current, suffix, |text| {
                let mut item = subject.value.clone();
                let value = accept(&mut item, text)?;
                subject.change(name, &value, item)
            })
        });
    }

    /// A text field whose accepted text is put into a copy of the value as it is.
    pub(crate) fn text_ui(self, ui: &mut Ui, current: &str, put: impl FnOnce(&mut T, String)) {
        self.typed_ui(ui, current, |item, text| {
            put(item, text.to_owned());
            Ok(text.to_owned())
        });
    }

    /// A field of a whole number in `range`.
    pub(crate) fn whole_ui<N>(
        self,
        ui: &mut Ui,
        current: N,
        range: RangeInclusive<N>,
        put: impl FnOnce(&mut T, N),
    ) where
        N: std::str::FromStr + PartialOrd + std::fmt::Display + Copy,
    {
        self.typed_ui(ui, &current.to_string(), |item, text| {
            put(item, parse_whole(text, *range.start(), *range.end())?);
            Ok(text.to_owned())
        });
    }

    /// A field of a finite number.
    pub(crate) fn number_ui(self, ui: &mut Ui, current: f64, put: impl FnOnce(&mut T, f64)) {
        self.typed_ui(ui, &current.to_string(), |item, text| {
            put(item, parse_number(text)?);
            Ok(text.to_owned())
        });
    }

    /// A combo box of `options`; a choice changes a copy of the value through `accept`, and
    /// the undo label shows the option's text.
    pub(crate) fn checked_combo_ui<V: PartialEq + Copy>(
        self,
        ui: &mut Ui,
        current: V,
        options: &[(String, V)],
        accept: impl FnOnce(&mut T, V) -> Result<(), Refusal>,
    ) {
        self.pending_combo_ui(ui, current, options, |_| false, accept);
    }

    /// A combo box of `options` whose choice is put into a copy of the value.
    pub(crate) fn combo_ui<V: PartialEq + Copy>(
        self,
        ui: &mut Ui,
        current: V,
        options: &[(String, V)],
        put: impl FnOnce(&mut T, V),
    ) {
        self.checked_combo_ui(ui, current, options, |item, chosen| {
            put(item, chosen);
            Ok(())
        });
    }

    /// A combo box of `options` whose choice of a value that `waits` names is shown but not
    /// applied until another field's edit completes it; other choices change a copy of the
    /// value through `accept`, and the undo label shows the option's text.
    pub(crate) fn pending_combo_ui<V: PartialEq + Copy>(
        self,
        ui: &mut Ui,
        current: V,
        options: &[(String, V)],
        waits: impl Fn(V) -> bool,
        accept: impl FnOnce(&mut T, V) -> Result<(), Refusal>,
    ) {
        let title = self.name;
        self.show(ui, title, |ui, state, subject, field, name| {
            pending_combo_ui(
                ui,
                state,
                subject.texts,
                field,
                current,
                options,
                waits,
                |chosen| {
                    let mut item = subject.value.clone();
                    accept(&mut item, chosen)?;
                    subject.change(name, option_text(options, chosen), item)
                },
            )
        });
    }

    /// A check box with the field's name beside it, on an untitled row; a change goes into a
    /// copy of the value through `put`, which returns the value its undo label shows.
    pub(crate) fn checkbox_ui(
        self,
        ui: &mut Ui,
        on: bool,
        put: impl FnOnce(&mut T, bool) -> &'static str,
    ) {
        let text = self.name;
        self.show(ui, "", |ui, state, subject, field, name| {
            checkbox_ui(ui, state, subject.texts, field, text, on, |on| {
                let mut item = subject.value.clone();
                let value = put(&mut item, on);
                subject.change(name, value, item)
            })
        });
    }

    /// Draws the field with `draw`, as a grid row titled `title` when the form's fields are
    /// rows, and keeps its edit; `draw` gets the field's id and its name for the undo label.
    fn show(
        self,
        ui: &mut Ui,
        title: &str,
        draw: impl FnOnce(
            &mut Ui,
            &mut DeviceEditorState,
            &Subject<'a, T>,
            FieldId<'_>,
            &str,
        ) -> Option<DeviceEdit>,
    ) {
        let Self {
            form,
            key,
            name,
            undo_name,
            width,
            ..
        } = self;
        let Form {
            state,
            subject,
            rows,
            edit,
        } = form;
        let key = subject.key(key);
        let label = subject.label(name);
        let field = FieldId {
            key: &key,
            label: &label,
            width,
        };
        let made = if *rows {
            row_ui(ui, title, |ui| draw(ui, state, subject, field, undo_name))
        } else {
            draw(ui, state, subject, field, undo_name)
        };
        keep(edit, made);
    }
}

/// The text of the option whose value is `chosen`, which an undo label shows.
fn option_text<V: PartialEq>(options: &[(String, V)], chosen: V) -> &str {
    options
        .iter()
        .find(|(_, value)| *value == chosen)
        .map(|(text, _)| text.as_str())
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_field_is_keyed_and_labelled_by_its_row_and_changes_only_that_row() {
        let texts = DeviceTexts::default();
        let commit = |label: String, rows: Vec<u8>| {
            Ok(DeviceEdit {
                label: format!("{label} {rows:?}"),
                edits: Vec::new(),
            })
        };
        let table = Table {
            id: "numbers",
            key: "numbers",
            row_key: "number",
            name: "Numbers",
            columns: &["Value"],
            rows: &[1, 2, 3],
            commit: &commit,
        };
        let mut state = DeviceEditorState::default();
        let form = Form::row(&mut state, &texts, &table, 1).unwrap();
        assert_eq!(form.subject.key("value"), "number 1 value");
        assert_eq!(form.subject.label("Value"), "Value of row 2");
        let edit = form.subject.change("Value", "7", 7).unwrap();
        assert_eq!(edit.label, "Set value of row 2 of Numbers to 7 [1, 7, 3]");
        assert!(Form::row(&mut state, &texts, &table, 3).is_none());
    }
}
