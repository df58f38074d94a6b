//! The runtime's Modbus master (`docs/modbus-master.md` §4, §6) against Rivet's own Modbus
//! server on 127.0.0.1 port 0 and against misbehaving fake slaves written here. No test
//! asserts timing: counters and cycle counts that keep growing are the checks.

mod coils;
mod edges;
mod faults;
mod online_change;
mod project;
mod proxy;
mod rtu;
mod scheduler;

use std::net::SocketAddr;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use online_protocol::ModbusDeviceReport;
use program_image::modbus_master::{
    ChannelDef, DeviceDef, Direction, Link, MasterSection, OnError, Schedule, Trigger, WordOrder,
};
use program_image::{Elementary, ModbusTable, ProgramImage};
use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};
use runtime::scheduler::Scheduler;

/// How long any one step may take before the test gives up.
const PATIENCE: Duration = Duration::from_secs(15);

/// The program: doubles what it reads, counts its cycles, has a device's status.
const PROGRAM: &str = "
PROGRAM Main
VAR
    iIn : INT;
    iOut : INT;
    iZeroed : INT := 7;
    xInError : BOOL;
    udiCycles : UDINT;
    stDevice : MODBUS_DEVICE_STATUS;
    xSend : BOOL;
    iEdges : INT;
END_VAR
udiCycles := udiCycles + 1;
iOut := iIn * 2;
xSend := (udiCycles MOD 10) = 0;
IF xSend THEN
    iEdges := iEdges + 1;
END_IF
END_PROGRAM
";

/// Compiles the program.
fn program() -> ProgramImage {
    compile(PROGRAM)
}

/// Compiles `program`; `MODBUS_DEVICE_STATUS` comes from the compiler's own Modbus library
/// (`compiler/src/library/modbus.st`).
fn compile(program: &str) -> ProgramImage {
    let source = compiler::SourceProject::new(program);
    match compiler::compile_source(&source, "main.st") {
        Ok(image) => image,
        Err(error) => panic!("the test program does not compile: {error:?}"),
    }
}

fn channel(variable: &str, address: u16, direction: Direction) -> ChannelDef {
    ChannelDef {
        variable: variable.to_owned(),
        table: ModbusTable::HoldingRegisters,
        address,
        value_type: Elementary::Int,
        count: 1,
        direction,
        function_code: if direction == Direction::Read { 3 } else { 16 },
        trigger: Trigger::Cyclic,
        on_error: OnError::KeepLastValue,
        error_flag: None,
    }
}

/// The device at `address`: reads holding register 0 into `Main.iIn` (error flag
/// `Main.xInError`) and register 2 into `Main.iZeroed` (set to zero on failure; a request of
/// its own, as the gap is not bridged), writes
/// `Main.iOut` to register 10; status `Main.stDevice`.
fn device(address: SocketAddr, schedule: Schedule) -> DeviceDef {
    let mut input = channel("Main.iIn", 0, Direction::Read);
    input.error_flag = Some("Main.xInError".to_owned());
    let mut zeroed = channel("Main.iZeroed", 2, Direction::Read);
    zeroed.on_error = OnError::SetToZero;
    DeviceDef {
        name: "Slave".to_owned(),
        link: Link::Tcp {
            host: address.ip().to_string(),
            port: address.port(),
        },
        unit_id: 1,
        timeout_ms: 300,
        task: 0,
        schedule,
        word_order: WordOrder::HighFirst,
        max_read_gap: 0,
        status: Some("Main.stDevice".to_owned()),
        channels: vec![input, zeroed, channel("Main.iOut", 10, Direction::Write)],
    }
}

/// The program with a master section of `devices`.
fn image_with(devices: Vec<DeviceDef>) -> ProgramImage {
    let mut image = program();
    image.modbus_master = Some(MasterSection {
        serial_ports: Vec::new(),
        devices,
    });
    image
}

/// Rivet's Modbus server on its own tokio runtime, so that a test can stop it whole (its
/// listener and every connection) and start it again, on a new port (behind a
/// `FaultProxy`, which keeps the master's address: a port freed and bound again could be
/// taken by another test meanwhile).
struct Slave {
    areas: Arc<Mutex<LocatedAreas>>,
    address: SocketAddr,
    runtime: Option<tokio::runtime::Runtime>,
}

impl Slave {
    fn start() -> Self {
        let areas = Arc::new(Mutex::new(LocatedAreas::new(64, 64, 64)));
        let mut slave = Self {
            areas,
            address: SocketAddr::from(([127, 0, 0, 1], 0)),
            runtime: None,
        };
        slave.serve();
        slave
    }

    /// Serves on 127.0.0.1 on a port the system picks, then in `address`.
    fn serve(&mut self) {
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(1)
            .enable_all()
            .build()
            .unwrap();
        let listener = runtime
            .block_on(tokio::net::TcpListener::bind(SocketAddr::from((
                [127, 0, 0, 1],
                0,
            ))))
            .unwrap();
        self.address = listener.local_addr().unwrap();
        runtime.spawn(serve(
            listener,
            Arc::clone(&self.areas),
            MapSlot::new(ModbusMap::default()),
            ServerOptions::default(),
        ));
        self.runtime = Some(runtime);
    }

    /// Stops serving: the listener and every connection close.
    fn stop(&mut self) {
        if let Some(runtime) = self.runtime.take() {
            runtime.shutdown_background();
        }
    }

    /// Sets holding register `register` (`%QW`) to `value`.
    fn set(&self, register: usize, value: i16) {
        self.areas.lock().unwrap().output[2 * register..2 * register + 2]
            .copy_from_slice(&value.to_le_bytes());
    }

    /// Holding register `register`.
    fn get(&self, register: usize) -> i16 {
        let areas = self.areas.lock().unwrap();
        i16::from_le_bytes([areas.output[2 * register], areas.output[2 * register + 1]])
    }
}

impl Drop for Slave {
    fn drop(&mut self) {
        self.stop();
    }
}

/// The bytes of the variable `path` of the loaded program, read between two cycles.
fn read(scheduler: &Scheduler, path: &str, bytes: usize) -> Vec<u8> {
    let path = path.to_owned();
    scheduler
        .between(move |between| {
            let memory = between.memory.as_ref().unwrap();
            let place = runtime::value::resolve(memory.engine.image(), &path).unwrap();
            let start = place.offset as usize;
            memory.engine.region(place.region)[start..start + bytes].to_vec()
        })
        .unwrap()
}

/// Writes `value` into the INT variable `path` of the loaded program between two cycles (as
/// an online write would).
fn write_int(scheduler: &Scheduler, path: &str, value: i16) {
    let path = path.to_owned();
    scheduler
        .between(move |between| {
            let memory = between.memory.as_mut().unwrap();
            let place = runtime::value::resolve(memory.engine.image(), &path).unwrap();
            let start = place.offset as usize;
            memory.engine.region_mut(place.region)[start..start + 2]
                .copy_from_slice(&value.to_le_bytes());
        })
        .unwrap();
}

fn read_int(scheduler: &Scheduler, path: &str) -> i16 {
    let bytes = read(scheduler, path, 2);
    i16::from_le_bytes([bytes[0], bytes[1]])
}

fn read_udint(scheduler: &Scheduler, path: &str) -> u32 {
    let bytes = read(scheduler, path, 4);
    u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]])
}

/// Waits until `done` holds, polling; panics with `what` after [`PATIENCE`], naming the
/// caller's line.
#[track_caller]
fn wait_until(what: &str, mut done: impl FnMut() -> bool) {
    let deadline = Instant::now() + PATIENCE;
    while !done() {
        assert!(Instant::now() < deadline, "gave up waiting until {what}");
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// The first device's snapshot.
fn first(devices: &[ModbusDeviceReport]) -> ModbusDeviceReport {
    devices.first().cloned().expect("the program has a device")
}
