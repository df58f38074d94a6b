//! `runtime::serial::open_port` on both ends of a socat pair: the settings are taken, bytes
//! cross, a second opener is refused, and a pulled cable reads end of file.

use std::time::Duration;

use runtime::serial::{SerialSettings, open_port};
use tokio::io::{AsyncReadExt, AsyncWriteExt};

use crate::peers::SocatPair;
use crate::rtu::open_when_free;

/// How long a byte may take to cross the cable before the test gives up.
const CROSSING: Duration = Duration::from_secs(5);

#[tokio::test]
async fn both_ends_of_a_socat_pair_open_8n1_and_8n2_and_carry_bytes_both_ways() {
    let dir = tempfile::tempdir().unwrap();
    let cable = SocatPair::start(dir.path());
    for format in ["19200-8N1", "9600-8N2", "115200-8N1"] {
        let mut master = open_when_free(&cable.master, format);
        let mut slave = open_when_free(&cable.slave, format);
        master.write_all(b"\x01\x03\x00\x00").await.unwrap();
        let mut received = [0; 4];
        tokio::time::timeout(CROSSING, slave.read_exact(&mut received))
            .await
            .unwrap()
            .unwrap();
        assert_eq!(&received, b"\x01\x03\x00\x00", "{format}");
        slave.write_all(b"\xff").await.unwrap();
        let mut answer = [0; 1];
        tokio::time::timeout(CROSSING, master.read_exact(&mut answer))
            .await
            .unwrap()
            .unwrap();
        assert_eq!(answer, [0xff], "{format}");
    }
}

#[tokio::test]
async fn an_open_port_is_exclusive_and_a_pulled_cable_reads_end_of_file() {
    let dir = tempfile::tempdir().unwrap();
    let mut cable = SocatPair::start(dir.path());
    let settings: SerialSettings = "19200-8N1".parse().unwrap();
    let mut slave = open_when_free(&cable.slave, "19200-8N1");
    let second = open_port(&cable.slave, &settings).unwrap_err();
    assert!(
        second
            .to_string()
            .starts_with(&format!("cannot open {}: ", cable.slave.display())),
        "{second}"
    );
    cable.kill();
    assert!(!cable.slave.exists(), "socat left its name behind");
    let mut byte = [0; 1];
    let read = tokio::time::timeout(CROSSING, slave.read(&mut byte))
        .await
        .unwrap();
    assert!(matches!(read, Ok(0) | Err(_)), "{read:?}");
    cable.restart();
    open_when_free(&cable.slave, "19200-8N1");
}
