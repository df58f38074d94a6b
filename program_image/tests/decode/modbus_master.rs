//! Section 14 `modbus_master` (`docs/modbus-master.md` §5): its encoding pinned, its round
//! trip, its critical flag, and the load-time refusals that name the device, the channel's
//! number and the field.

use std::fmt::Write as _;

use expect_test::expect_file;
use program_image::modbus_master::{
    ChannelDef, DeviceDef, Direction, Link, MasterSection, OnError, Parity, Schedule,
    SerialPortDef, Trigger, WordOrder, request_limit,
};
use program_image::{Elementary, ImageError, ModbusTable, ProgramImage};

use super::{container, refused, sections, small_image};

/// A small section of every kind of entry: a serial port, a TCP device with a read array and a
/// single-register write, and an RTU device with a rising-edge coil write and an error flag.
fn small_section() -> MasterSection {
    let read = ChannelDef {
        variable: "GVL_Io.aiTemperatures".to_owned(),
        table: ModbusTable::InputRegisters,
        address: 0,
        value_type: Elementary::Int,
        count: 8,
        direction: Direction::Read,
        function_code: 4,
        trigger: Trigger::Cyclic,
        on_error: OnError::SetToZero,
        error_flag: None,
    };
    let write = ChannelDef {
        variable: "Main.iOut".to_owned(),
        table: ModbusTable::HoldingRegisters,
        address: 10,
        value_type: Elementary::Dint,
        count: 1,
        direction: Direction::Write,
        function_code: 16,
        trigger: Trigger::Cyclic,
        on_error: OnError::KeepLastValue,
        error_flag: None,
    };
    let edge = ChannelDef {
        variable: "GVL_Io.xValve".to_owned(),
        table: ModbusTable::Coils,
        address: 3,
        value_type: Elementary::Bool,
        count: 1,
        direction: Direction::Write,
        function_code: 5,
        trigger: Trigger::RisingEdge {
            variable: "GVL_Io.xSend".to_owned(),
        },
        on_error: OnError::KeepLastValue,
        error_flag: Some("GVL_Io.xValveError".to_owned()),
    };
    MasterSection {
        serial_ports: vec![SerialPortDef {
            name: "RS485".to_owned(),
            device: "/dev/ttyUSB0".to_owned(),
            baud_rate: 19200,
            parity: Parity::Even,
            data_bits: 8,
            stop_bits: 1,
            inter_frame_delay_us: 5000,
        }],
        devices: vec![
            DeviceDef {
                name: "BeltDrive".to_owned(),
                link: Link::Tcp {
                    host: "127.0.0.1".to_owned(),
                    port: 5502,
                },
                unit_id: 1,
                timeout_ms: 100,
                task: 0,
                schedule: Schedule::Interval { interval_ms: 10 },
                word_order: WordOrder::LowFirst,
                max_read_gap: 0,
                status: Some("GVL_Io.stBeltDrive".to_owned()),
                channels: vec![read, write],
            },
            DeviceDef {
                name: "Valves".to_owned(),
                link: Link::Rtu { serial_port: 0 },
                unit_id: 3,
                timeout_ms: 200,
                task: 0,
                schedule: Schedule::EveryCycle,
                word_order: WordOrder::HighFirst,
                max_read_gap: 7,
                status: None,
                channels: vec![edge],
            },
        ],
    }
}

/// A refusal case: the message expected after the change to the small section.
type Case = (&'static str, fn(&mut MasterSection));

/// The small image with the small section.
fn with_master() -> ProgramImage {
    let mut image = small_image();
    image.modbus_master = Some(small_section());
    image
}

/// The message that decoding the small image with `section` gives, which must be a refusal of
/// the Modbus master section.
#[track_caller]
fn master_refusal(section: MasterSection) -> String {
    let mut image = small_image();
    image.modbus_master = Some(section);
    match refused(&image.encode()) {
        error @ ImageError::ModbusMaster(_) => error.to_string(),
        other => panic!("expected a refused Modbus master section, got: {other}"),
    }
}

#[test]
fn a_master_section_round_trips_as_the_critical_section_14() {
    let image = with_master();
    let bytes = image.encode();
    assert_eq!(ProgramImage::decode(&bytes), Ok(image));
    let master = sections(&bytes)
        .into_iter()
        .find(|section| section.id == 14)
        .unwrap_or_else(|| panic!("no section 14"));
    assert_eq!(master.flags, 1, "the Modbus master section is critical");
    // Without runtime devices there is no section 14 at all.
    assert!(sections(&small_image().encode()).iter().all(|s| s.id != 14));
}

#[test]
fn the_encoding_of_a_small_master_section_is_pinned() {
    // A change of these bytes is a change of section 14's format (docs/modbus-master.md §5.1).
    let bytes = with_master().encode();
    let master = sections(&bytes)
        .into_iter()
        .find(|section| section.id == 14)
        .unwrap_or_else(|| panic!("no section 14"));
    let mut dump = String::new();
    let hex = |bytes: &[u8]| bytes.iter().map(|b| format!("{b:02x}")).collect::<String>();
    writeln!(
        dump,
        "section 14 flags {} length {}",
        master.flags,
        master.payload.len()
    )
    .unwrap_or_default();
    // One line per entry, so a change shows where it is.
    let section = small_section();
    let entries = [
        ("serial_ports", postcard::to_allocvec(&section.serial_ports)),
        ("devices[0]", postcard::to_allocvec(&section.devices[0])),
        ("devices[1]", postcard::to_allocvec(&section.devices[1])),
    ];
    for (name, entry) in entries {
        let entry = entry.unwrap_or_else(|error| panic!("{name}: {error}"));
        writeln!(dump, "{name}: {}", hex(&entry)).unwrap_or_default();
    }
    writeln!(dump, "payload: {}", hex(&master.payload)).unwrap_or_default();
    expect_file!["../encoding/modbus_master.txt"].assert_eq(&dump);
}

#[test]
fn device_refusals_name_the_device_and_the_field() {
    let cases: [Case; 9] = [
        (
            "Modbus device 'BeltDrive', field task: index 4, but the image has 1 tasks",
            |s| s.devices[0].task = 4,
        ),
        (
            "Modbus device 'Valves', field link.serial_port: index 1, but the image has 1 serial ports",
            |s| s.devices[1].link = Link::Rtu { serial_port: 1 },
        ),
        (
            "Modbus device 'BeltDrive', field link.host: it is empty, expected a host name or IP address",
            |s| {
                s.devices[0].link = Link::Tcp {
                    host: " ".to_owned(),
                    port: 502,
                }
            },
        ),
        (
            "Modbus device 'Valves', field unit_id: 0 is outside 1 to 247",
            |s| s.devices[1].unit_id = 0,
        ),
        (
            "Modbus device 'BeltDrive', field timeout_ms: 60001 is outside 1 to 60000",
            |s| s.devices[0].timeout_ms = 60_001,
        ),
        (
            "Modbus device 'BeltDrive', field schedule.interval_ms: 0 is outside 1 to 3600000",
            |s| s.devices[0].schedule = Schedule::Interval { interval_ms: 0 },
        ),
        (
            "Modbus device 'Valves', field max_read_gap: 126 is outside 0 to 125",
            |s| s.devices[1].max_read_gap = 126,
        ),
        (
            "Modbus device 'beltdrive', field name: 'beltdrive' is also the name of device 0 ('BeltDrive')",
            |s| s.devices[1].name = "beltdrive".to_owned(),
        ),
        (
            "Modbus device '', field name: it is empty, expected the device's name in the project",
            |s| s.devices[0].name = String::new(),
        ),
    ];
    for (expected, change) in cases {
        let mut section = small_section();
        change(&mut section);
        assert_eq!(
            master_refusal(section),
            format!("the image is inconsistent: {expected}")
        );
    }
}

#[test]
fn channel_refusals_name_the_device_the_channel_number_and_the_field() {
    let cases: [Case; 10] = [
        (
            "Modbus device 'BeltDrive', channel 2 (Main.iOut), field on_error: set to zero (1) applies to a read channel's variable after a failed request; the master never writes a write channel's variable: expected keep last value (0)",
            |s| s.devices[0].channels[1].on_error = OnError::SetToZero,
        ),
        (
            "Modbus device 'Valves', channel 1 (GVL_Io.xValve), field trigger.variable: it is empty, expected the path of the BOOL whose rising edge transfers the channel",
            |s| {
                s.devices[1].channels[0].trigger = Trigger::RisingEdge {
                    variable: " ".to_owned(),
                }
            },
        ),
        (
            "Modbus device 'BeltDrive', channel 2 (Main.iOut), field function_code: function code 3 does not write a holding register: expected 6 or 16",
            |s| s.devices[0].channels[1].function_code = 3,
        ),
        (
            "Modbus device 'BeltDrive', channel 1 (GVL_Io.aiTemperatures), field function_code: function code 16 does not write an input register: expected none: discrete inputs and input registers cannot be written",
            |s| {
                let channel = &mut s.devices[0].channels[0];
                channel.direction = Direction::Write;
                channel.function_code = 16;
            },
        ),
        (
            "Modbus device 'BeltDrive', channel 2 (Main.iOut), field function_code: function code 6 writes one coil or register, but the channel takes 2: use 16",
            |s| s.devices[0].channels[1].function_code = 6,
        ),
        (
            "Modbus device 'BeltDrive', channel 1 (GVL_Io.aiTemperatures), field count: the channel takes 126 coils or registers, but one request may read at most 125",
            |s| s.devices[0].channels[0].count = 126,
        ),
        (
            "Modbus device 'BeltDrive', channel 1 (GVL_Io.aiTemperatures), field count: 0 is outside 1 to 65535",
            |s| s.devices[0].channels[0].count = 0,
        ),
        (
            "Modbus device 'Valves', channel 1 (GVL_Io.xValve), field value_type: a coil cannot hold INT; coils and discrete inputs hold BOOL, registers INT, UINT, DINT, UDINT, LINT, ULINT, REAL or LREAL",
            |s| s.devices[1].channels[0].value_type = Elementary::Int,
        ),
        (
            "Modbus device 'BeltDrive', channel 2 (Main.iOut), field address: the channel at address 65535 takes 2 coils or registers and passes address 65535",
            |s| s.devices[0].channels[1].address = 65_535,
        ),
        (
            "Modbus device 'BeltDrive', channel 3 (GVL_Io.iExtra), field address: the channel overlaps channel 2 (Main.iOut) in the same table",
            |s| {
                // A read at holding register 11 shares a register with the DINT written at 10.
                let mut extra = s.devices[0].channels[0].clone();
                extra.variable = "GVL_Io.iExtra".to_owned();
                extra.table = ModbusTable::HoldingRegisters;
                extra.function_code = 3;
                extra.address = 11;
                extra.count = 1;
                s.devices[0].channels.push(extra);
            },
        ),
    ];
    for (expected, change) in cases {
        let mut section = small_section();
        change(&mut section);
        assert_eq!(
            master_refusal(section),
            format!("the image is inconsistent: {expected}")
        );
    }
}

#[test]
fn serial_port_and_count_refusals_name_the_port_or_the_list() {
    let cases: [Case; 7] = [
        (
            "serial port 0 ('RS485'), field baud_rate: 19201 is not accepted, expected 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200 or 230400",
            |s| s.serial_ports[0].baud_rate = 19_201,
        ),
        (
            "serial port 0 ('RS485'), field data_bits: 7 is not accepted, expected 8, the data bits of Modbus RTU",
            |s| s.serial_ports[0].data_bits = 7,
        ),
        (
            "serial port 0 ('RS485'), field stop_bits: 3 is not accepted, expected 1 or 2",
            |s| s.serial_ports[0].stop_bits = 3,
        ),
        (
            "serial port 0 ('RS485'), field device: it is empty, expected a device file such as /dev/ttyUSB0",
            |s| s.serial_ports[0].device = String::new(),
        ),
        (
            "serial port 0 ('RS485'), field inter_frame_delay_us: 1000001 is outside 0 to 1000000",
            |s| s.serial_ports[0].inter_frame_delay_us = 1_000_001,
        ),
        (
            "serial port 1 ('rs485'), field name: 'rs485' is also the name of serial port 0",
            |s| {
                let mut other = s.serial_ports[0].clone();
                other.name = "rs485".to_owned();
                s.serial_ports.push(other);
            },
        ),
        (
            "the Modbus master section, field devices: 257 entries, at most 256 are accepted",
            |s| {
                let device = s.devices[0].clone();
                s.devices = (0..257)
                    .map(|n| DeviceDef {
                        name: format!("D{n}"),
                        ..device.clone()
                    })
                    .collect();
            },
        ),
    ];
    for (expected, change) in cases {
        let mut section = small_section();
        change(&mut section);
        assert_eq!(
            master_refusal(section),
            format!("the image is inconsistent: {expected}")
        );
    }
    let mut section = small_section();
    let channel = section.devices[1].channels[0].clone();
    section.devices[1].channels = (0..1025)
        .map(|n| ChannelDef {
            address: n,
            ..channel.clone()
        })
        .collect();
    assert_eq!(
        master_refusal(section),
        "the image is inconsistent: Modbus device 'Valves', field channels: 1025 entries, at most 1024 are accepted"
    );
}

#[test]
fn a_malformed_master_section_is_refused_by_name() {
    let bytes = with_master().encode();
    let mut all = sections(&bytes);
    if let Some(master) = all.iter_mut().find(|section| section.id == 14) {
        // The first serial port's parity, 2 (even), becomes a variant that does not exist.
        let parity_at = master
            .payload
            .windows(3)
            .position(|w| w == [0x80, 0x96, 0x01])
            .map(|at| at + 3)
            .unwrap_or_else(|| panic!("no baud rate 19200 in the payload"));
        master.payload[parity_at] = 9;
    }
    match refused(&container(&all)) {
        ImageError::Malformed { section, .. } => assert_eq!(section, "modbus_master"),
        other => panic!("expected a malformed section, got {other}"),
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(1000))]

    #[test]
    fn mutations_of_a_master_section_never_panic_and_plan_what_they_accept(
        edits in proptest::collection::vec(
            (proptest::prelude::any::<proptest::sample::Index>(), proptest::prelude::any::<u8>()),
            1..6,
        ),
    ) {
        let bytes = with_master().encode();
        let mut all = sections(&bytes);
        if let Some(master) = all.iter_mut().find(|section| section.id == 14) {
            for (at, byte) in &edits {
                let at = at.index(master.payload.len());
                master.payload[at] = *byte;
            }
        }
        // The verifier and the decoder see the mutated section; what they accept, the runtime
        // plans, so planning it must not panic, and every request it plans must be one a
        // device can answer: within its function's limit and the address space.
        if let Ok(image) = ProgramImage::decode(&container(&all))
            && let Some(master) = &image.modbus_master
        {
            for device in &master.devices {
                let requests = program_image::modbus_master::plan(device);
                let served: usize = requests.iter().map(|r| r.channels.len()).sum();
                proptest::prop_assert_eq!(served, device.channels.len());
                for request in &requests {
                    let limit = request_limit(request.direction, request.table);
                    let quantity = u32::from(request.quantity);
                    proptest::prop_assert!(
                        (1..=limit).contains(&quantity),
                        "{:?} exceeds {}", request, limit
                    );
                    proptest::prop_assert!(
                        u32::from(request.start) + quantity <= 65_536,
                        "{:?} passes address 65535", request
                    );
                }
            }
        }
    }
}
