//! The channel table of a Modbus device: each channel's variable, table, address, data type
//! and comment, rows added by naming a variable and deleted by a button.

use compiler::ide::{check_channel_variable, variable_type};
use egui::{RichText, Ui, WidgetInfo};
use project_model::{ModbusBinding, ModbusDataType, ModbusTable, Project};

use super::field::{DeviceEditorState, FieldId, combo_ui, parse_whole, reason_ui, text_field_ui};
use super::map_ranges::{Commit, table_name, table_options};
use super::refusal::Refusal;
use super::texts::fill;
use super::{DeviceEdit, DeviceTexts, keep, row_label};

/// Draws the channels as a table, with a field that adds a channel for a variable.
pub(crate) fn channels_ui(
    ui: &mut Ui,
    project: &Project,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    bindings: &[ModbusBinding],
    commit: Commit<'_, ModbusBinding>,
) -> Option<DeviceEdit> {
    let mut out = None;
    ui.strong(&texts.channels);
    let tables = table_options(texts);
    let types: Vec<(String, ModbusDataType)> = ModbusDataType::ALL
        .iter()
        .map(|&data_type| (data_type.iec_name().to_owned(), data_type))
        .collect();
    egui::Grid::new("modbus channels")
        .num_columns(6)
        .striped(true)
        .spacing([12.0, 4.0])
        .show(ui, |ui| {
            for title in [
                &texts.variable,
                &texts.table,
                &texts.address,
                &texts.data_type,
                &texts.comment,
            ] {
                ui.strong(title);
            }
            ui.label("");
            ui.end_row();
            for (index, binding) in bindings.iter().enumerate() {
                let row = index + 1;
                let replaced = |item: ModbusBinding, field: &str, value: &str| {
                    let mut list = bindings.to_vec();
                    list[index] = item;
                    let field = row_label(texts, field, row).to_lowercase();
                    let label = fill(
                        &texts.set_field,
                        &[
                            ("field", &field),
                            ("node", &texts.channels),
                            ("value", value),
                        ],
                    );
                    commit(label, list)
                };
                let fits =
                    check_channel_variable(project, &binding.variable, binding.data_type).is_ok();
                let key = format!("channel {index} variable");
                let label = row_label(texts, &texts.variable, row);
                let field = FieldId {
                    key: &key,
                    label: &label,
                    width: 190.0,
                };
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &binding.variable, "", |text| {
                        check_channel_variable(project, text, binding.data_type)?;
                        let item = ModbusBinding {
                            variable: text.to_owned(),
                            ..binding.clone()
                        };
                        replaced(item, &texts.variable, text)
                    }),
                );
                let key = format!("channel {index} table");
                let label = row_label(texts, &texts.table, row);
                let field = FieldId {
                    key: &key,
                    label: &label,
                    width: 130.0,
                };
                keep(
                    &mut out,
                    combo_ui(ui, state, texts, field, binding.table, &tables, |table| {
                        let data_type = data_type_for_table(project, binding, table);
                        let item = ModbusBinding {
                            table,
                            data_type,
                            ..binding.clone()
                        };
                        replaced(item, &texts.table, &table_name(texts, table))
                    }),
                );
                let key = format!("channel {index} address");
                let label = row_label(texts, &texts.address, row);
                let field = FieldId {
                    key: &key,
                    label: &label,
                    width: 60.0,
                };
                keep(
                    &mut out,
                    text_field_ui(
                        ui,
                        state,
                        texts,
                        field,
                        &binding.address.to_string(),
                        "",
                        |text| {
                            let address = parse_whole(text, 0u16, u16::MAX)?;
                            let item = ModbusBinding {
                                address,
                                ..binding.clone()
                            };
                            replaced(item, &texts.address, text)
                        },
                    ),
                );
                let key = format!("channel {index} type");
                let label = row_label(texts, &texts.data_type, row);
                let field = FieldId {
                    key: &key,
                    label: &label,
                    width: 80.0,
                };
                keep(
                    &mut out,
                    combo_ui(
                        ui,
                        state,
                        texts,
                        field,
                        binding.data_type,
                        &types,
                        |data_type| {
                            if fits {
                                check_channel_variable(project, &binding.variable, data_type)?;
                            }
                            let item = ModbusBinding {
                                data_type,
                                ..binding.clone()
                            };
                            replaced(item, &texts.data_type, data_type.iec_name())
                        },
                    ),
                );
                let key = format!("channel {index} comment");
                let label = row_label(texts, &texts.comment, row);
                let field = FieldId {
                    key: &key,
                    label: &label,
                    width: 160.0,
                };
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &binding.comment, "", |text| {
                        let item = ModbusBinding {
                            comment: text.to_owned(),
                            ..binding.clone()
                        };
                        replaced(item, &texts.comment, text)
                    }),
                );
                let delete = ui.button(&texts.delete);
                if !fits {
                    // Bound before this check existed, or the variable changed since: say so.
                    let reason =
                        check_channel_variable(project, &binding.variable, binding.data_type)
                            .err()
                            .map(|error| texts.refusal.describe(&Refusal::from(error)))
                            .unwrap_or_default();
                    ui.label(
                        RichText::new("!")
                            .strong()
                            .color(ui.visuals().warn_fg_color),
                    )
                    .on_hover_text(reason);
                }
                let label = row_label(texts, &texts.delete, row);
                delete.widget_info(|| WidgetInfo::labeled(egui::Role::Button, true, label.clone()));
                if delete.clicked() {
                    let mut list = bindings.to_vec();
                    list.remove(index);
                    let label = fill(
                        &texts.delete_row,
                        &[("row", &row.to_string()), ("node", &texts.channels)],
                    );
                    keep(&mut out, state.settle("channels", commit(label, list)));
                }
                ui.end_row();
            }
        });
    ui.horizontal(|ui| {
        ui.label(&texts.new_channel);
        let field = FieldId {
            key: "new channel",
            label: &texts.new_channel,
            width: 200.0,
        };
        keep(
            &mut out,
            text_field_ui(ui, state, texts, field, "", "", |text| {
                let item = new_binding(project, bindings, text)?;
                let mut list = bindings.to_vec();
                list.push(item);
                let label = fill(&texts.add_row, &[("node", &texts.channels)]);
                commit(label, list)
            }),
        );
    });
    reason_ui(ui, state, texts, "channels");
    out
}

/// A channel for `variable`: the data type of its declared type, a coil for a BOOL and a
/// holding register otherwise (both can be written), at the first address after that table's
/// channels.
fn new_binding(
    project: &Project,
    bindings: &[ModbusBinding],
    variable: &str,
) -> Result<ModbusBinding, Refusal> {
    let data_type = variable_type(project, variable)
        .and_then(|declared| data_type_of(&declared))
        .map_or_else(
            // The check says why: no such variable, or a type no channel holds.
            || {
                check_channel_variable(project, variable, ModbusDataType::Uint16)
                    .map(|()| ModbusDataType::Uint16)
            },
            Ok,
        )?;
    let table = if data_type == ModbusDataType::Bool {
        ModbusTable::Coil
    } else {
        ModbusTable::HoldingRegister
    };
    let address = bindings
        .iter()
        .filter(|binding| binding.table == table)
        .map(|binding| {
            let width = if table.holds_bits() {
                1
            } else {
                binding.data_type.width()
            };
            binding.address.saturating_add(width)
        })
        .max()
        .unwrap_or(0);
    Ok(ModbusBinding {
        variable: variable.to_owned(),
        table,
        address,
        data_type,
        comment: String::new(),
    })
}

/// The data type a channel moved to `table` gets: BOOL in a bit table; in a register table,
/// the one its variable's type fits, or its current one, or UINT.
fn data_type_for_table(
    project: &Project,
    binding: &ModbusBinding,
    table: ModbusTable,
) -> ModbusDataType {
    if table.holds_bits() {
        return ModbusDataType::Bool;
    }
    if binding.data_type != ModbusDataType::Bool {
        return binding.data_type;
    }
    variable_type(project, &binding.variable)
        .and_then(|declared| data_type_of(&declared))
        .filter(|data_type| *data_type != ModbusDataType::Bool)
        .unwrap_or(ModbusDataType::Uint16)
}

/// The data type whose channel a variable of the IEC type `declared` fits.
fn data_type_of(declared: &str) -> Option<ModbusDataType> {
    let upper = declared.to_ascii_uppercase();
    match upper.as_str() {
        "WORD" => Some(ModbusDataType::Uint16),
        "DWORD" => Some(ModbusDataType::Uint32),
        "LWORD" => Some(ModbusDataType::Uint64),
        _ => ModbusDataType::ALL
            .into_iter()
            .find(|data_type| data_type.iec_name() == upper),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> Project {
        project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project
    }

    #[test]
    fn a_new_channel_takes_its_variable_s_type_and_the_next_free_address() {
        let project = example();
        let bindings = &project.modbus_devices[0].bindings;
        let total = new_binding(&project, bindings, "GVL_Machine.udiTotalPackages").unwrap();
        assert_eq!(total.table, ModbusTable::HoldingRegister);
        assert_eq!(total.data_type, ModbusDataType::Uint32);
        assert_eq!(total.address, 0);
        let mut more = bindings.clone();
        more.push(total);
        let count = new_binding(&project, &more, "GVL_Machine.iPackagesInBatch").unwrap();
        assert_eq!((count.address, count.data_type), (2, ModbusDataType::Int16));
        let flag = new_binding(&project, &more, "GVL_Machine.xAcknowledge").unwrap();
        assert_eq!((flag.table, flag.address), (ModbusTable::Coil, 0));
    }

    #[test]
    fn a_new_channel_for_a_missing_variable_or_a_structure_is_refused() {
        let project = example();
        let missing = new_binding(&project, &[], "GVL_Machine.xNothing")
            .unwrap_err()
            .to_string();
        assert!(missing.contains("there is no variable"), "{missing}");
        let recipe = new_binding(&project, &[], "GVL_Machine.stRecipe")
            .unwrap_err()
            .to_string();
        assert!(recipe.contains("declared as ST_Recipe"), "{recipe}");
    }

    #[test]
    fn bit_strings_fit_unsigned_channels_of_their_size() {
        assert_eq!(data_type_of("word"), Some(ModbusDataType::Uint16));
        assert_eq!(data_type_of("LREAL"), Some(ModbusDataType::Lreal));
        assert_eq!(data_type_of("STRING"), None);
    }
}
