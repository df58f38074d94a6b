//! Coils through Rivet's own Modbus server (`runtime::modbus::serve`): a read of coils
//! (function 1) into an array of BOOL, a write of one coil (function 5) and a write of many
//! (function 15), whose bits land in the server's `%QX` bits.

use std::sync::{Arc, Mutex};

use program_image::modbus_master::{Direction, Schedule};
use program_image::{Elementary, ModbusTable};
use runtime::areas::LocatedAreas;
use runtime::scheduler::{Scheduler, SchedulerOptions};

use super::{Slave, channel, compile, device, wait_until};

/// Reads ten coils into `xIn`, writes `xOne` to one coil and `axMany` to ten.
const PROGRAM: &str = "
PROGRAM Main
VAR
    xIn : ARRAY[0..9] OF BOOL;
    xOne : BOOL := TRUE;
    axMany : ARRAY[0..9] OF BOOL;
END_VAR
axMany[0] := TRUE;
axMany[3] := xIn[1];
axMany[9] := TRUE;
END_PROGRAM
";

/// Whether coil `coil` of the server is set (`%QX coil/8 . coil%8`).
fn coil(slave: &Slave, coil: usize) -> bool {
    slave.areas.lock().unwrap().output[coil / 8] >> (coil % 8) & 1 == 1
}

#[test]
fn coils_are_read_and_written_one_and_many_at_a_time() {
    let slave = Slave::start();
    // Coil 1 set: the program copies it to the fourth of the many written.
    slave.areas.lock().unwrap().output[0] = 0b0000_0010;
    let bits = |variable: &str, address: u16, count: u16, direction, function_code| {
        let mut bits = channel(variable, address, direction);
        bits.table = ModbusTable::Coils;
        bits.value_type = Elementary::Bool;
        bits.count = count;
        bits.function_code = function_code;
        bits
    };
    let mut coils = device(slave.address, Schedule::Interval { interval_ms: 10 });
    coils.status = None;
    coils.channels = vec![
        bits("Main.xIn", 0, 10, Direction::Read, 1),
        bits("Main.xOne", 20, 1, Direction::Write, 5),
        bits("Main.axMany", 30, 10, Direction::Write, 15),
    ];
    let mut image = compile(PROGRAM);
    image.modbus_master = Some(program_image::modbus_master::MasterSection {
        serial_ports: Vec::new(),
        devices: vec![coils],
    });
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler.load(image).unwrap();
    scheduler.start().unwrap();
    wait_until("the coils are written", || {
        coil(&slave, 20) && coil(&slave, 30) && coil(&slave, 33) && coil(&slave, 39)
    });
    // Function 15 wrote the cleared bits too, and touched no coil beyond its ten.
    for cleared in [31, 32, 34, 35, 36, 37, 38, 40] {
        assert!(!coil(&slave, cleared), "coil {cleared}");
    }
    // Coil 1 cleared: the read brings it, and the program writes coil 33 cleared.
    slave.areas.lock().unwrap().output[0] = 0;
    wait_until("the read coil reaches the written ones", || {
        !coil(&slave, 33) && coil(&slave, 30)
    });
    scheduler.shutdown().unwrap();
}
