//! The tables of the device editors (a Modbus device's channels, the controller's map ranges):
//! a heading row, one row of fields per item with a delete button, and changes of the whole list
//! checked by the node that holds it.

use egui::{RichText, Ui, WidgetInfo};

use super::field::DeviceEditorState;
use super::form::Form;
use super::refusal::Refusal;
use super::texts::fill;
use super::{DeviceEdit, DeviceTexts, keep, row_label};

/// Gives a changed list of rows and its undo label to `commit`, which checks it against the
/// project and makes the edit, or says why it is refused.
pub(crate) type Commit<'a, T> = &'a dyn Fn(String, Vec<T>) -> Result<DeviceEdit, Refusal>;

/// A table of a device editor: what it is called and keyed by, and its rows.
pub(crate) struct Table<'a, T> {
    /// The id of its grid.
    pub id: &'a str,
    /// The key of the refusal of a row deleted or added.
    pub key: &'a str,
    /// The first word of its cells' keys: "channel" in "channel 2 address".
    pub row_key: &'a str,
    /// Its name, the node its undo labels name: "Channels".
    pub name: &'a str,
    /// The titles of its columns, the delete button's column left out.
    pub columns: &'a [&'a str],
    /// Its rows as they are now.
    pub rows: &'a [T],
    /// Checks a changed list of rows and makes its edit.
    pub commit: Commit<'a, T>,
}

/// Draws `table` as a striped grid whose rows are drawn by `cells`, each followed by a delete
/// button and, when `cells` returns one, a warning whose reason shows on hover and is its
/// accessible name.
pub(crate) fn table_ui<T: Clone>(
    ui: &mut Ui,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    table: &Table<'_, T>,
    mut cells: impl FnMut(&mut Ui, &mut Form<'_, T>, &T) -> Option<String>,
) -> Option<DeviceEdit> {
    let mut out = None;
    egui::Grid::new(table.id)
        .num_columns(table.columns.len() + 1)
        .striped(true)
        .spacing([12.0, 4.0])
        .show(ui, |ui| {
            for title in table.columns {
                ui.strong(*title);
            }
            ui.label("");
            ui.end_row();
            for (index, item) in table.rows.iter().enumerate() {
                let Some(mut form) = Form::row(state, texts, table, index) else {
                    continue;
                };
                let warning = cells(ui, &mut form, item);
                keep(&mut out, form.finish());
                let row = index + 1;
                let delete = ui.button(&texts.delete);
                if let Some(reason) = warning {
                    let mark = ui.label(
                        RichText::new("!")
                            .strong()
                            .color(ui.visuals().warn_fg_color),
                    );
                    // The reason is the mark's accessible name too, so a screen reader says
                    // it where a sighted user hovers.
                    mark.widget_info(|| {
                        WidgetInfo::labeled(egui::Role::Label, true, reason.clone())
                    });
                    mark.on_hover_text(reason);
                }
                let label = row_label(texts, &texts.delete, row);
                delete.widget_info(|| WidgetInfo::labeled(egui::Role::Button, true, label.clone()));
                if delete.clicked() {
                    let mut list = table.rows.to_vec();
                    list.remove(index);
                    let label = fill(
                        &texts.delete_row,
                        &[("row", &row.to_string()), ("node", table.name)],
                    );
                    keep(
                        &mut out,
                        state.settle(table.key, (table.commit)(label, list)),
                    );
                }
                ui.end_row();
            }
        });
    out
}
