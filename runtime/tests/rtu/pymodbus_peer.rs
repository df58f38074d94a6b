//! The pymodbus slave the Modbus master's tests talk to (`peers::PymodbusServer`), checked with
//! tokio-modbus: over TCP its tables follow the test's commands both ways, it answers late and
//! with exceptions when told; over RTU on a socat pair it answers as two units.

use std::time::{Duration, Instant};

use tokio_modbus::client::{Reader, Writer};
use tokio_modbus::slave::SlaveContext;
use tokio_modbus::{ExceptionCode, Slave};

use crate::peers::{PymodbusServer, SocatPair};
use crate::rtu::open_when_free;
use crate::{PATIENCE, connect};

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_tcp_peer_serves_what_the_test_sets_and_reports_what_is_written() {
    let mut peer = PymodbusServer::tcp();
    let mut client = connect(([127, 0, 0, 1], peer.port).into()).await;
    peer.set("ir", 0, 21);
    assert_eq!(
        client.read_input_registers(0, 1).await.unwrap().unwrap(),
        [21]
    );
    client.write_single_register(10, 42).await.unwrap().unwrap();
    assert_eq!(peer.get("hr", 10), 42);
    // Addresses from 1000 on do not exist.
    assert_eq!(
        client.read_holding_registers(1000, 1).await.unwrap(),
        Err(ExceptionCode::IllegalDataAddress)
    );

    peer.exceptions(true);
    assert_eq!(
        client.read_input_registers(0, 1).await.unwrap(),
        Err(ExceptionCode::IllegalDataAddress)
    );
    peer.exceptions(false);
    peer.delay(200);
    let start = Instant::now();
    assert_eq!(
        client.read_input_registers(0, 1).await.unwrap().unwrap(),
        [21]
    );
    assert!(start.elapsed() >= Duration::from_millis(200));
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_rtu_peer_answers_as_each_of_its_units_on_a_socat_pair() {
    let dir = tempfile::tempdir().unwrap();
    let cable = SocatPair::start(dir.path());
    let mut peer = PymodbusServer::rtu(&cable.slave, 19200, 'N', 1, &[1, 2]);
    peer.set("hr", 5, 11);
    peer.set("2.hr", 5, 22);
    let port = open_when_free(&cable.master, "19200-8N1");
    let mut client = tokio_modbus::client::rtu::attach_slave(port, Slave(1));
    let read = tokio::time::timeout(PATIENCE, client.read_holding_registers(5, 1));
    assert_eq!(read.await.unwrap().unwrap().unwrap(), [11]);
    client.set_slave(Slave(2));
    let read = tokio::time::timeout(PATIENCE, client.read_holding_registers(5, 1));
    assert_eq!(read.await.unwrap().unwrap().unwrap(), [22]);
    let write = tokio::time::timeout(PATIENCE, client.write_single_register(6, 66));
    write.await.unwrap().unwrap().unwrap();
    assert_eq!(peer.get("2.hr", 6), 66);
    assert_eq!(peer.get("hr", 6), 0);
}
