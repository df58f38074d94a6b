//! A project's own Modbus map travels in the image to the runtime's server.

use project_model::{ModbusServerMap, ModbusServerRange, ModbusTable};
use runtime::modbus::{ModbusMap, Table};

fn project_with(ranges: Vec<ModbusServerRange>) -> project_model::Project {
    let source = compiler::SourceProject::new(
        "PROGRAM main VAR x AT %MW3 : INT; END_VAR x := 7; END_PROGRAM",
    );
    let mut project = source.project.clone();
    project.controller.modbus_map = Some(ModbusServerMap { ranges });
    project
}

fn range(table: ModbusTable, start: u16, count: u16, address: &str) -> ModbusServerRange {
    ModbusServerRange {
        table,
        start,
        count,
        area_address: address.to_owned(),
    }
}

#[test]
fn a_project_map_replaces_the_default_map() {
    let project = project_with(vec![
        range(ModbusTable::HoldingRegister, 100, 10, "%MW0"),
        range(ModbusTable::HoldingRegister, 200, 4, "%MD2"),
        range(ModbusTable::Coil, 0, 16, "%QX2.0"),
    ]);
    let image = compiler::compile_project(&project).unwrap();
    let map = ModbusMap::for_image(&image).unwrap();
    // %MW3 is holding register 103 now, and register 3 is no longer mapped.
    let register = map.locate_register(Table::HoldingRegisters, 103).unwrap();
    assert_eq!(register.byte, 6);
    assert!(map.locate_register(Table::HoldingRegisters, 3).is_none());
    assert_eq!(map.locate_bit(Table::Coils, 9).unwrap().byte, 3);
    let decoded = program_image::ProgramImage::decode(&image.encode()).unwrap();
    assert_eq!(decoded.modbus_map, image.modbus_map);
}

#[test]
fn an_image_without_a_map_uses_the_default_one() {
    let source =
        compiler::SourceProject::new("PROGRAM main VAR x : INT; END_VAR x := 7; END_PROGRAM");
    let image = compiler::compile_source(&source, "main.st").unwrap();
    assert_eq!(ModbusMap::for_image(&image).unwrap(), ModbusMap::openplc());
}

#[test]
fn a_bad_map_range_is_refused_naming_the_range() {
    for (bad, expected) in [
        (
            range(ModbusTable::Coil, 0, 8, "%QW0"),
            "range[1] (Coil 0): a bit table starts at bit 0",
        ),
        (
            range(ModbusTable::Coil, 0, 8, "%QX0.3"),
            "a bit table starts at bit 0 of a byte",
        ),
        (
            range(ModbusTable::HoldingRegister, 5, 2, "%MX0.0"),
            "a register table starts at a W, D or L address",
        ),
        (
            range(ModbusTable::HoldingRegister, 5, 2, "MW0"),
            "is not a direct address",
        ),
        (
            range(ModbusTable::HoldingRegister, 5, 0, "%MW0"),
            "the count must be at least 1",
        ),
    ] {
        let error = compiler::compile_project(&project_with(vec![bad]))
            .unwrap_err()
            .to_string();
        assert!(error.contains(expected), "{error}");
    }
}
