//! A read-only property grid for any serialisable part of the project.

use egui::{RichText, Ui};
use toml::{Table, Value};

/// Shows `value` as a grid of names and values, with nested tables and lists as collapsible
/// groups. It reads the same field names as the project files, so what the user sees here is
/// what `git diff` shows.
pub fn property_view_ui<T: serde::Serialize>(ui: &mut Ui, id_salt: &str, value: &T) {
    match Table::try_from(value) {
        Ok(table) => table_ui(ui, id_salt, &table),
        Err(error) => {
            ui.colored_label(ui.visuals().error_fg_color, error.to_string());
        }
    }
}

fn table_ui(ui: &mut Ui, id_salt: &str, table: &Table) {
    let (plain, nested): (Vec<_>, Vec<_>) = table.iter().partition(|(_, value)| is_plain(value));
    if !plain.is_empty() {
        egui::Grid::new(ui.make_persistent_id(("properties", id_salt)))
            .num_columns(2)
            .striped(true)
            .spacing([24.0, 4.0])
            .show(ui, |ui| {
                for (key, value) in plain {
                    ui.label(RichText::new(key).strong());
                    ui.label(plain_text(value));
                    ui.end_row();
                }
            });
    }
    for (key, value) in nested {
        let child_salt = format!("{id_salt}.{key}");
        match value {
            Value::Table(child) => {
                egui::CollapsingHeader::new(RichText::new(key).strong())
                    .id_salt(&child_salt)
                    .default_open(true)
                    .show(ui, |ui| table_ui(ui, &child_salt, child));
            }
            Value::Array(items) => {
                egui::CollapsingHeader::new(
                    RichText::new(format!("{key} ({})", items.len())).strong(),
                )
                .id_salt(&child_salt)
                .default_open(true)
                .show(ui, |ui| {
                    for (index, item) in items.iter().enumerate() {
                        let item_salt = format!("{child_salt}[{index}]");
                        match item {
                            Value::Table(child) => {
                                egui::CollapsingHeader::new(format!("{key} {}", index + 1))
                                    .id_salt(&item_salt)
                                    .default_open(items.len() <= 8)
                                    .show(ui, |ui| table_ui(ui, &item_salt, child));
                            }
                            other => {
                                ui.label(plain_text(other));
                            }
                        }
                    }
                });
            }
            other => {
                ui.label(plain_text(other));
            }
        }
    }
}

/// Values shown on one grid line: scalars and lists of scalars.
fn is_plain(value: &Value) -> bool {
    match value {
        Value::Table(_) => false,
        Value::Array(items) => items
            .iter()
            .all(|item| !matches!(item, Value::Table(_) | Value::Array(_))),
        _ => true,
    }
}

fn plain_text(value: &Value) -> String {
    match value {
        Value::String(text) => text.clone(),
        Value::Array(items) => items.iter().map(plain_text).collect::<Vec<_>>().join(", "),
        other => other.to_string(),
    }
}
