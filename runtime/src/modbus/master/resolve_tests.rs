//! Resolving section 14's paths in a program: places, and the refusals of §5.2.

use program_image::modbus_master::{Link, OnError, Schedule, Trigger, WordOrder};
use program_image::{ModbusTable, Symbol};

use super::*;
use crate::test_images::{TestTask, image};

/// The test image with `GVL.count : DINT`, `GVL.values : ARRAY[0..3] OF DINT` and the
/// constant `GVL.k : INT`, besides its located BOOL `Trigger`.
fn program() -> ProgramImage {
    let mut image = image(&[TestTask::cyclic(1_000_000, 1)], &[]);
    let dint = image.types.len() as u32;
    image.types.push(TypeDef::Elementary(Elementary::Dint));
    image.types.push(TypeDef::Array {
        element: dint,
        dims: vec![(0, 3)],
    });
    image.types.push(TypeDef::Elementary(Elementary::Int));
    let symbol = |path: &str, ty: u32, offset: u32, flags: u16| Symbol {
        path: path.to_owned(),
        ty,
        region: Region::Data,
        offset,
        bit: None,
        flags: SymbolFlags(SymbolFlags::GLOBAL | flags),
    };
    image.symbols.push(symbol("GVL.count", dint, 8, 0));
    image.symbols.push(symbol("GVL.values", dint + 1, 16, 0));
    image
        .symbols
        .push(symbol("GVL.k", dint + 2, 32, SymbolFlags::CONSTANT));
    image
}

fn device(variable: &str, value_type: Elementary, count: u16) -> DeviceDef {
    DeviceDef {
        name: "Drive".to_owned(),
        link: Link::Tcp {
            host: "127.0.0.1".to_owned(),
            port: 502,
        },
        unit_id: 1,
        timeout_ms: 100,
        task: 0,
        schedule: Schedule::EveryCycle,
        word_order: WordOrder::HighFirst,
        max_read_gap: 0,
        status: None,
        channels: vec![program_image::modbus_master::ChannelDef {
            variable: variable.to_owned(),
            table: ModbusTable::HoldingRegisters,
            address: 0,
            value_type,
            count,
            direction: Direction::Read,
            function_code: 3,
            trigger: Trigger::Cyclic,
            on_error: OnError::KeepLastValue,
            error_flag: Some("Trigger".to_owned()),
        }],
    }
}

/// Resolves a section of `device` alone.
fn resolve_one(image: &ProgramImage, device: &DeviceDef) -> Result<DevicePlaces, ResolveError> {
    let section = MasterSection {
        devices: vec![device.clone()],
        ..MasterSection::default()
    };
    resolve_section(image, &section).map(|mut places| places.remove(0))
}

fn refusal(device: DeviceDef) -> String {
    match resolve_one(&program(), &device) {
        Ok(places) => panic!("resolved: {places:?}"),
        Err(error) => error.to_string(),
    }
}

#[test]
fn paths_become_places_and_misfits_are_refused_with_device_channel_and_field() {
    let image = program();
    let places = resolve_one(&image, &device("GVL.values", Elementary::Dint, 4)).unwrap();
    assert_eq!(places.task, 0);
    let channel = &places.channels[0];
    assert_eq!((channel.variable.offset, channel.variable.bytes), (16, 16));
    // The located BOOL flag keeps its bit.
    let flag = channel.error_flag.unwrap();
    assert_eq!(
        (flag.region, flag.offset, flag.bit),
        (Region::Memory, 4, Some(0))
    );

    assert_eq!(
        refusal(device("GVL.values", Elementary::Int, 4)),
        "the image is inconsistent: Modbus device 'Drive', channel 1 (GVL.values), field variable: the channel carries INT values, but the variable's element type is DINT"
    );
    assert!(refusal(device("GVL.count", Elementary::Dint, 3)).contains(
        "the channel has 3 DINT values, but the variable is of type DINT: expected an ARRAY of 3 elements"
    ));
    assert!(
        refusal(device("GVL.nothing", Elementary::Dint, 1))
            .ends_with("field variable: unknown variable 'GVL.nothing'")
    );
    assert!(
        refusal(device("GVL.k", Elementary::Int, 1))
            .ends_with("'GVL.k' is a constant, which the runtime cannot write")
    );
    let mut flagged = device("GVL.count", Elementary::Dint, 1);
    flagged.channels[0].error_flag = Some("GVL.count".to_owned());
    assert!(refusal(flagged).ends_with("field error_flag: 'GVL.count' is of type DINT, not BOOL"));
    let mut status = device("GVL.count", Elementary::Dint, 1);
    status.status = Some("GVL.values".to_owned());
    assert_eq!(
        refusal(status),
        "the image is inconsistent: Modbus device 'Drive', field status: the status variable is of type ARRAY[0..3] OF DINT, not MODBUS_DEVICE_STATUS"
    );
    let mut elsewhere = device("GVL.count", Elementary::Dint, 1);
    elsewhere.task = 4;
    assert!(refusal(elsewhere).ends_with("field task: task 4 does not exist"));
}
