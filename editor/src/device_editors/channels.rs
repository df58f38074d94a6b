//! The channel table of a Modbus device: each channel's variable, table, address, data type
//! and comment, and on a device the runtime masters its count, direction, function code,
//! trigger, error handling and error flag (`channel_master.rs`); rows added by naming a
//! variable and deleted by a button.

use compiler::ide::{
    check_channel_binding, check_channel_variable, variable_type, variable_values,
};
use egui::Ui;
use project_model::{
    DeviceProblem, ModbusBinding, ModbusDataType, ModbusTable, Project, request_limit,
};

use super::channel_master::channel_master_cells_ui;
use super::field::{DeviceEditorState, FieldId, reason_ui, text_field_ui};
use super::map_ranges::table_options;
use super::refusal::Refusal;
use super::table::{Commit, Table, table_ui};
use super::texts::fill;
use super::{DeviceEdit, DeviceTexts, keep};

/// Draws the channels as a table, with a field that adds a channel for a variable; `master`
/// adds the columns of the runtime master's settings.
pub(crate) fn channels_ui(
    ui: &mut Ui,
    project: &Project,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    bindings: &[ModbusBinding],
    master: bool,
    commit: Commit<'_, ModbusBinding>,
) -> Option<DeviceEdit> {
    ui.strong(&texts.channels);
    let tables = table_options(texts);
    let types: Vec<(String, ModbusDataType)> = ModbusDataType::ALL
        .iter()
        .map(|&data_type| (data_type.iec_name().to_owned(), data_type))
        .collect();
    let table = Table {
        id: "modbus channels",
        key: "channels",
        row_key: "channel",
        name: &texts.channels,
        columns: &columns(texts, master),
        rows: bindings,
        commit,
    };
    let mut out = table_ui(ui, state, texts, &table, |ui, row, binding| {
        let fits = channel_fit(project, binding, master);
        row.field("variable", &texts.variable, 190.0).typed_ui(
            ui,
            &binding.variable,
            |item, text| {
                item.variable = text.to_owned();
                channel_fit(project, item, master)?;
                Ok(text.to_owned())
            },
        );
        row.field("table", &texts.table, 130.0).combo_ui(
            ui,
            binding.table,
            &tables,
            |item, table| {
                item.data_type = data_type_for_table(project, item, table);
                item.table = table;
            },
        );
        row.field("address", &texts.address, 60.0).whole_ui(
            ui,
            binding.address,
            0..=u16::MAX,
            |item, address| item.address = address,
        );
        row.field("type", &texts.data_type, 80.0).checked_combo_ui(
            ui,
            binding.data_type,
            &types,
            |item, data_type| {
                item.data_type = data_type;
                if fits.is_ok() {
                    channel_fit(project, item, master)?;
                }
                Ok(())
            },
        );
        if master {
            channel_master_cells_ui(ui, row, project, texts, binding);
        }
        row.field("comment", &texts.comment, 160.0).text_ui(
            ui,
            &binding.comment,
            |item, comment| item.comment = comment,
        );
        // Bound before this check existed, the variable changed since, or the count was changed
        // ahead of the variable (so a channel can go from one value to an array): say so.
        fits.err().map(|refusal| texts.refusal.describe(&refusal))
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
                let item = new_binding(project, bindings, text, master)?;
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

/// Whether `binding`'s variable fits the channel: on a device the runtime masters by data type
/// and count, as the build checks it (E0141); on a studio device, which polls one value per
/// channel, by data type.
fn channel_fit(project: &Project, binding: &ModbusBinding, master: bool) -> Result<(), Refusal> {
    if master {
        Ok(check_channel_binding(project, binding)?)
    } else {
        Ok(check_channel_variable(
            project,
            &binding.variable,
            binding.data_type,
        )?)
    }
}

/// The titles of the table's columns: the master's settings only on a device the runtime
/// masters, where they have an effect.
fn columns(texts: &DeviceTexts, master: bool) -> Vec<&str> {
    let mut columns = vec![
        texts.variable.as_str(),
        &texts.table,
        &texts.address,
        &texts.data_type,
    ];
    if master {
        columns.extend([
            texts.count.as_str(),
            &texts.direction,
            &texts.function_code,
            &texts.trigger,
            &texts.trigger_variable,
            &texts.on_error,
            &texts.error_flag,
        ]);
    }
    columns.push(&texts.comment);
    columns
}

/// A channel for `variable`: the data type of its declared type, a coil for a BOOL and a
/// holding register otherwise (both can be written), at the first address after that table's
/// channels. On a device the runtime masters (`master`), a one-dimensional array of a channel's
/// type is one channel of the array's length, refused when one request cannot carry it.
fn new_binding(
    project: &Project,
    bindings: &[ModbusBinding],
    variable: &str,
    master: bool,
) -> Result<ModbusBinding, Refusal> {
    let values = variable_values(project, variable)
        .and_then(|(element, length)| Some((data_type_of(element)?, length)));
    let (data_type, count) = match values {
        Some((data_type, None)) => (data_type, 1),
        // An array longer than a count holds is longer than any request carries: refused below.
        Some((data_type, Some(length))) if master => {
            (data_type, u16::try_from(length).unwrap_or(u16::MAX))
        }
        _ => {
            // The check says why: no such variable, or a type no channel holds.
            check_channel_variable(project, variable, ModbusDataType::Uint16)?;
            (ModbusDataType::Uint16, 1)
        }
    };
    let table = if data_type == ModbusDataType::Bool {
        ModbusTable::Coil
    } else {
        ModbusTable::HoldingRegister
    };
    let address = bindings
        .iter()
        .filter(|binding| binding.table == table)
        .map(|binding| {
            let span = u16::try_from(binding.span()).unwrap_or(u16::MAX);
            binding.address.saturating_add(span)
        })
        .max()
        .unwrap_or(0);
    let binding = ModbusBinding {
        count,
        ..ModbusBinding::new(variable, table, address, data_type)
    };
    let limit = request_limit(binding.table, binding.direction);
    if binding.span() > limit {
        return Err(DeviceProblem::ChannelTooLong {
            row: bindings.len() + 1,
            count,
            span: binding.span(),
            limit,
        }
        .into());
    }
    Ok(binding)
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
    use project_model::{Object, Variable};

    fn example() -> Project {
        project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project
    }

    #[test]
    fn a_new_channel_takes_its_variable_s_type_and_the_next_free_address() {
        let project = example();
        let bindings = &project.modbus_devices[0].bindings;
        let total = new_binding(&project, bindings, "GVL_Machine.udiTotalPackages", false).unwrap();
        assert_eq!(total.table, ModbusTable::HoldingRegister);
        assert_eq!(total.data_type, ModbusDataType::Uint32);
        assert_eq!(total.address, 0);
        let mut more = bindings.clone();
        more.push(total);
        let count = new_binding(&project, &more, "GVL_Machine.iPackagesInBatch", false).unwrap();
        assert_eq!((count.address, count.data_type), (2, ModbusDataType::Int16));
        let flag = new_binding(&project, &more, "GVL_Machine.xAcknowledge", false).unwrap();
        assert_eq!((flag.table, flag.address), (ModbusTable::Coil, 0));
    }

    #[test]
    fn a_new_channel_for_a_missing_variable_or_a_structure_is_refused() {
        let project = example();
        let missing = new_binding(&project, &[], "GVL_Machine.xNothing", true)
            .unwrap_err()
            .to_string();
        assert!(missing.contains("there is no variable"), "{missing}");
        let recipe = new_binding(&project, &[], "GVL_Machine.stRecipe", true)
            .unwrap_err()
            .to_string();
        assert!(recipe.contains("declared as ST_Recipe"), "{recipe}");
    }

    #[test]
    fn a_new_channel_of_a_runtime_device_takes_an_array_s_length_as_its_count() {
        let mut project = example();
        let Some(Object::Gvl(gvl)) = project.application.object_mut("GVL_Machine") else {
            panic!("the example has no GVL_Machine");
        };
        gvl.variables.extend([
            Variable::new("arSpeeds", "ARRAY[1..3] OF REAL"),
            Variable::new("axLamps", "ARRAY[0..7] OF BOOL"),
            Variable::new("aiLog", "ARRAY[0..199] OF INT"),
        ]);
        let speeds = new_binding(&project, &[], "GVL_Machine.arSpeeds", true).unwrap();
        assert_eq!(
            (speeds.table, speeds.data_type, speeds.count),
            (ModbusTable::HoldingRegister, ModbusDataType::Real, 3)
        );
        let lamps = new_binding(&project, &[], "GVL_Machine.axLamps", true).unwrap();
        assert_eq!(
            (lamps.table, lamps.data_type, lamps.count),
            (ModbusTable::Coil, ModbusDataType::Bool, 8)
        );
        // The next channel of the table starts after all the array's registers.
        let after = new_binding(&project, &[speeds], "GVL_Machine.iPackagesInBatch", true);
        assert_eq!(after.map(|binding| binding.address), Ok(6));
        assert_eq!(
            check_channel_binding(&project, &lamps),
            Ok(()),
            "the inferred channel fits its variable"
        );
        // 200 registers are more than one read carries (125).
        assert!(matches!(
            new_binding(&project, &[], "GVL_Machine.aiLog", true),
            Err(Refusal::Problem(DeviceProblem::ChannelTooLong {
                count: 200,
                ..
            }))
        ));
        // The studio's own poll reads one value per channel.
        let studio = new_binding(&project, &[], "GVL_Machine.arSpeeds", false)
            .unwrap_err()
            .to_string();
        assert!(
            studio.contains("declared as ARRAY[1..3] OF REAL"),
            "{studio}"
        );
    }

    #[test]
    fn bit_strings_fit_unsigned_channels_of_their_size() {
        assert_eq!(data_type_of("word"), Some(ModbusDataType::Uint16));
        assert_eq!(data_type_of("LREAL"), Some(ModbusDataType::Lreal));
        assert_eq!(data_type_of("STRING"), None);
    }
}
