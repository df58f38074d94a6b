//! A generic Modbus TCP device polled by `online::device`: typed channels over coils and
//! registers, both word orders, writes, forces that hold, and a trace sampled by polling.
//! The device here is the runtime's own Modbus server over bare areas (no program), which
//! answers exactly as the standard says. `master/` tests the runtime's own Modbus master
//! (`docs/modbus-master.md`) against the same server and against misbehaving fake slaves.

// The helpers below are test code too: a failure should stop the test where it happens.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::sync::{Arc, Mutex};
use std::time::Duration;

use online::device::{Channel, Device, Table, WordOrder};
use program_image::Elementary;
use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};

mod master;

async fn device_server() -> (std::net::SocketAddr, Arc<Mutex<LocatedAreas>>) {
    let areas = Arc::new(Mutex::new(LocatedAreas::new(64, 64, 8192)));
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let address = listener.local_addr().unwrap();
    tokio::spawn(serve(
        listener,
        Arc::clone(&areas),
        MapSlot::new(ModbusMap::default()),
        ServerOptions::default(),
    ));
    (address, areas)
}

fn channel(name: &str, table: Table, address: u16, ty: Elementary) -> Channel {
    Channel {
        name: name.to_owned(),
        table,
        address,
        ty,
    }
}

#[tokio::test]
async fn typed_channels_read_write_and_force_in_both_word_orders() {
    let (address, areas) = device_server().await;
    for order in [WordOrder::HighFirst, WordOrder::LowFirst] {
        let channels = vec![
            channel("lamp", Table::Coils, 3, Elementary::Bool),
            channel("speed", Table::HoldingRegisters, 1024, Elementary::Int),
            channel("pressure", Table::HoldingRegisters, 1030, Elementary::Real),
            channel("energy", Table::HoldingRegisters, 1040, Elementary::Lreal),
            channel("count", Table::HoldingRegisters, 1034, Elementary::Dint),
        ];
        let mut device = Device::connect(address, 1, order, Duration::from_secs(2), channels)
            .await
            .unwrap();
        device.write(0, &[1]).await.unwrap();
        device.write(1, &(-1234i16).to_le_bytes()).await.unwrap();
        device.write(2, &1.5f32.to_le_bytes()).await.unwrap();
        device.write(3, &(-2.25f64).to_le_bytes()).await.unwrap();
        device.write(4, &123_456i32.to_le_bytes()).await.unwrap();
        let snapshot = device.poll().await.unwrap();
        assert_eq!(snapshot.values[0], vec![1]);
        assert_eq!(snapshot.values[1], (-1234i16).to_le_bytes().to_vec());
        assert_eq!(snapshot.values[2], 1.5f32.to_le_bytes().to_vec());
        assert_eq!(snapshot.values[3], (-2.25f64).to_le_bytes().to_vec());
        assert_eq!(snapshot.values[4], 123_456i32.to_le_bytes().to_vec());
        // The word order decides which register holds the high word of the REAL (16#3FC0).
        let memory = areas.lock().unwrap().memory.clone();
        let first_register = u16::from_be_bytes([memory[13], memory[12]]);
        let expected = if order == WordOrder::HighFirst {
            0x3FC0
        } else {
            0x0000
        };
        assert_eq!(first_register, expected, "{order:?}");
    }
}

#[tokio::test]
async fn a_forced_channel_is_written_again_before_every_poll_and_a_trace_samples_polls() {
    let (address, areas) = device_server().await;
    let channels = vec![channel(
        "setpoint",
        Table::HoldingRegisters,
        0,
        Elementary::Uint,
    )];
    let mut device = Device::connect(
        address,
        1,
        WordOrder::HighFirst,
        Duration::from_secs(2),
        channels,
    )
    .await
    .unwrap();
    device
        .force(0, 500u16.to_le_bytes().to_vec())
        .await
        .unwrap();
    // Someone else overwrites the register; the next poll writes the forced value first.
    areas.lock().unwrap().output[0..2].copy_from_slice(&7u16.to_le_bytes());
    assert_eq!(
        device.poll().await.unwrap().values[0],
        500u16.to_le_bytes().to_vec()
    );
    assert_eq!(device.forces().len(), 1);
    device.unforce(None);
    areas.lock().unwrap().output[0..2].copy_from_slice(&7u16.to_le_bytes());
    let trace = device.trace(5, Duration::from_millis(5)).await.unwrap();
    assert_eq!(trace.len(), 5);
    assert!(
        trace
            .iter()
            .all(|s| s.values[0] == 7u16.to_le_bytes().to_vec())
    );
    assert!(trace.windows(2).all(|w| w[1].time > w[0].time));
}

#[tokio::test]
async fn a_channel_that_cannot_hold_its_type_and_a_read_only_write_are_refused() {
    let (address, _) = device_server().await;
    let bad = vec![channel("x", Table::Coils, 0, Elementary::Int)];
    let error = Device::connect(
        address,
        1,
        WordOrder::HighFirst,
        Duration::from_secs(2),
        bad,
    )
    .await
    .err()
    .unwrap();
    assert!(error.to_string().contains("cannot hold a INT"), "{error}");
    let channels = vec![channel("in", Table::InputRegisters, 0, Elementary::Int)];
    let mut device = Device::connect(
        address,
        1,
        WordOrder::HighFirst,
        Duration::from_secs(2),
        channels,
    )
    .await
    .unwrap();
    let error = device.write(0, &[1, 0]).await.unwrap_err();
    assert!(error.to_string().contains("cannot be written"), "{error}");
}

/// Kills the pymodbus server when the test ends, however it ends.
struct Peer(std::process::Child);

impl Drop for Peer {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

#[tokio::test]
async fn a_pymodbus_server_is_monitored_written_forced_and_traced() {
    let python = tests::peers::python_with_pymodbus();
    // A free port on loopback for the server to take.
    let port = std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port();
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/peers/pymodbus_server.py");
    let _peer = Peer(
        std::process::Command::new(python)
            .arg(script)
            .arg(port.to_string())
            .spawn()
            .unwrap(),
    );
    let address: std::net::SocketAddr = format!("127.0.0.1:{port}").parse().unwrap();
    for order in [WordOrder::HighFirst, WordOrder::LowFirst] {
        let channels = vec![
            channel("valve", Table::Coils, 5, Elementary::Bool),
            channel("flow", Table::HoldingRegisters, 10, Elementary::Real),
            channel("total", Table::HoldingRegisters, 20, Elementary::Udint),
        ];
        // The server takes a moment to start listening.
        let started = std::time::Instant::now();
        let mut device = loop {
            match Device::connect(address, 1, order, Duration::from_secs(2), channels.clone()).await
            {
                Ok(device) => break device,
                Err(error) if started.elapsed() < Duration::from_secs(20) => {
                    let _ = error;
                    tokio::time::sleep(Duration::from_millis(100)).await;
                }
                Err(error) => panic!("pymodbus did not start: {error}"),
            }
        };
        device.write(0, &[1]).await.unwrap();
        device.write(1, &(-3.75f32).to_le_bytes()).await.unwrap();
        device
            .force(2, 4_000_000_000u32.to_le_bytes().to_vec())
            .await
            .unwrap();
        let trace = device.trace(3, Duration::from_millis(10)).await.unwrap();
        for snapshot in &trace {
            assert_eq!(snapshot.values[0], vec![1]);
            assert_eq!(
                snapshot.values[1],
                (-3.75f32).to_le_bytes().to_vec(),
                "{order:?}"
            );
            assert_eq!(snapshot.values[2], 4_000_000_000u32.to_le_bytes().to_vec());
        }
    }
}
