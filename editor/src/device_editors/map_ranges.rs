//! The ranges of the controller's own Modbus map: a table, its first address and count, and
//! the located address the range starts at.

use compiler::ide::address_info;
use egui::Ui;
use project_model::{ModbusServerRange, ModbusTable};

use super::field::{DeviceEditorState, reason_ui};
use super::refusal::Refusal;
use super::table::{Commit, Table, table_ui};
use super::texts::fill;
use super::{DeviceEdit, DeviceTexts, keep};

/// Draws the ranges as a table with a button to add one and one to delete each.
pub(crate) fn map_ranges_ui(
    ui: &mut Ui,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    ranges: &[ModbusServerRange],
    commit: Commit<'_, ModbusServerRange>,
) -> Option<DeviceEdit> {
    ui.add_space(4.0);
    ui.strong(&texts.map_ranges);
    let tables = table_options(texts);
    let table = Table {
        id: "map ranges",
        key: "ranges",
        row_key: "range",
        name: &texts.map_ranges,
        columns: &[
            &texts.table,
            &texts.start,
            &texts.count,
            &texts.area_address,
        ],
        rows: ranges,
        commit,
    };
    let mut out = table_ui(ui, state, texts, &table, |ui, row, range| {
        row.field("table", &texts.table, 130.0).combo_ui(
            ui,
            range.table,
            &tables,
            |item, table| item.table = table,
        );
        row.field("start", &texts.start, 60.0).whole_ui(
            ui,
            range.start,
            0..=u16::MAX,
            |item, start| item.start = start,
        );
        row.field("count", &texts.count, 60.0).whole_ui(
            ui,
            range.count,
            1..=u16::MAX,
            |item, count| item.count = count,
        );
        row.field("address", &texts.area_address, 90.0).typed_ui(
            ui,
            &range.area_address,
            |item, text| {
                address_problem(item.table, text)?;
                item.area_address = text.to_uppercase();
                Ok(item.area_address.clone())
            },
        );
        None
    });
    if ui.button(&texts.add_range).clicked() {
        let mut list = ranges.to_vec();
        list.push(next_range(ranges));
        let label = fill(&texts.add_row, &[("node", &texts.map_ranges)]);
        keep(&mut out, state.settle("ranges", commit(label, list)));
    }
    reason_ui(ui, state, texts, "ranges");
    out
}

/// The four tables with their names, for combo boxes.
pub(crate) fn table_options(texts: &DeviceTexts) -> Vec<(String, ModbusTable)> {
    ModbusTable::ALL
        .iter()
        .map(|&table| (table_name(texts, table), table))
        .collect()
}

/// A table's name in the user's language.
pub(crate) fn table_name(texts: &DeviceTexts, table: ModbusTable) -> String {
    match table {
        ModbusTable::Coil => texts.coil.clone(),
        ModbusTable::DiscreteInput => texts.discrete_input.clone(),
        ModbusTable::HoldingRegister => texts.holding_register.clone(),
        ModbusTable::InputRegister => texts.input_register.clone(),
    }
}

/// Why `address` cannot start a range of `table`: not a direct address, or of the wrong size
/// (a bit table starts at bit 0 of a byte, a register table at a W, D or L address), as the
/// build requires.
fn address_problem(table: ModbusTable, address: &str) -> Result<(), Refusal> {
    let info = address_info(address)?;
    let fits = info.bits.is_some()
        && if table.holds_bits() {
            info.size_bits == Some(1) && info.bits.as_ref().is_some_and(|bits| bits.start % 8 == 0)
        } else {
            matches!(info.size_bits, Some(16 | 32 | 64))
        };
    if fits {
        return Ok(());
    }
    let address = address.to_owned();
    Err(if table.holds_bits() {
        Refusal::BitTableAddress { address }
    } else {
        Refusal::RegisterTableAddress { address }
    })
}

/// A new range: one holding register after the last range, mapped onto `%MW0`.
fn next_range(ranges: &[ModbusServerRange]) -> ModbusServerRange {
    let start = ranges
        .iter()
        .filter(|range| range.table == ModbusTable::HoldingRegister)
        .map(|range| range.start.saturating_add(range.count))
        .max()
        .unwrap_or(0);
    ModbusServerRange {
        table: ModbusTable::HoldingRegister,
        start,
        count: 1,
        area_address: "%MW0".to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_starts_at_a_byte_s_first_bit_or_at_a_register_address() {
        let address_problem =
            |table, address| address_problem(table, address).map_err(|error| error.to_string());
        assert_eq!(address_problem(ModbusTable::Coil, "%QX4.0"), Ok(()));
        assert_eq!(
            address_problem(ModbusTable::Coil, "%QX4.1"),
            Err(
                "a coil or discrete input range starts at bit 0 of a byte, such as %QX4.0, not %QX4.1"
                    .into()
            )
        );
        assert_eq!(
            address_problem(ModbusTable::HoldingRegister, "%MD2"),
            Ok(())
        );
        assert!(address_problem(ModbusTable::InputRegister, "%IB2").is_err());
        assert!(address_problem(ModbusTable::InputRegister, "MW2").is_err());
    }

    #[test]
    fn a_new_range_follows_the_last_holding_register_range() {
        let first = next_range(&[]);
        assert_eq!((first.start, first.count), (0, 1));
        let second = next_range(&[ModbusServerRange { count: 10, ..first }]);
        assert_eq!(second.start, 10);
    }
}
