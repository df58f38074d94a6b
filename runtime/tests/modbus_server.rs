//! End-to-end tests of the Modbus TCP server on 127.0.0.1: tokio-modbus, mbpoll and pymodbus as
//! clients, many clients at once, and raw sockets sending frames no client should send.
//!
//! mbpoll and pymodbus are system packages that `scripts/test.sh` installs; without them the
//! tests that use them fail and say so.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::net::SocketAddr;
use std::path::Path;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use runtime::areas::{Area, LocatedAreas};
use runtime::modbus::{ExceptionCode, MapSlot, ModbusMap, ServerOptions, serve};
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::{TcpListener, TcpStream};
use tokio_modbus::client::{Client, Context, Reader, Writer};
use tokio_modbus::prelude::Request;

mod peers;

use peers::{python_with_pymodbus, required_program, run};

/// How long any one step may take before the test gives up on the server.
const PATIENCE: Duration = Duration::from_secs(10);

/// Areas as large as the default map reaches: 1024 bytes of `%I` and `%Q`, 8192 of `%M`.
fn full_areas() -> LocatedAreas {
    LocatedAreas::new(1024, 1024, 8192)
}

/// Starts a server on a free port of 127.0.0.1 with the default map.
async fn start_server(
    areas: LocatedAreas,
    options: ServerOptions,
) -> (SocketAddr, Arc<Mutex<LocatedAreas>>) {
    let listener = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let address = listener.local_addr().unwrap();
    let areas = Arc::new(Mutex::new(areas));
    let map = MapSlot::new(ModbusMap::default());
    tokio::spawn(serve(listener, Arc::clone(&areas), map, options));
    (address, areas)
}

async fn connect(address: SocketAddr) -> Context {
    tokio::time::timeout(PATIENCE, tokio_modbus::client::tcp::connect(address))
        .await
        .expect("connecting took too long")
        .unwrap()
}

/// Checks that a well-formed client is still served.
async fn check_still_served(address: SocketAddr) {
    let mut client = connect(address).await;
    let registers = client.read_holding_registers(0, 2).await.unwrap().unwrap();
    assert_eq!(registers.len(), 2);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_tokio_modbus_client_reads_and_writes_every_table() {
    let mut areas = full_areas();
    areas.input[0] = 0b0000_0101;
    areas.set_word(Area::Input, 2, 0x4242).unwrap();
    areas.output[1] = 0b1000_0000;
    areas.set_word(Area::Memory, 3, 1234).unwrap();
    let (address, areas) = start_server(areas, ServerOptions::default()).await;
    let mut client = connect(address).await;

    let discrete = client.read_discrete_inputs(0, 4).await.unwrap().unwrap();
    assert_eq!(discrete, [true, false, true, false]);
    let input_registers = client.read_input_registers(2, 1).await.unwrap().unwrap();
    assert_eq!(input_registers, [0x4242]);
    let coils = client.read_coils(14, 3).await.unwrap().unwrap();
    assert_eq!(coils, [false, true, false]);
    let memory_word = client
        .read_holding_registers(1027, 1)
        .await
        .unwrap()
        .unwrap();
    assert_eq!(memory_word, [1234]);

    client.write_single_coil(0, true).await.unwrap().unwrap();
    client
        .write_multiple_coils(16, &[true, true, false, true])
        .await
        .unwrap()
        .unwrap();
    client
        .write_single_register(3, 0xabcd)
        .await
        .unwrap()
        .unwrap();
    client
        .write_multiple_registers(2048 + 2, &[0x1234, 0x5678])
        .await
        .unwrap()
        .unwrap();
    let read_back = client
        .read_write_multiple_registers(4096, 4, 1024 + 100, &[7, 8])
        .await
        .unwrap()
        .unwrap();
    // %ML0 overlaps %MD1, just written: its high words come first.
    assert_eq!(read_back, [0x1234, 0x5678, 0, 0]);

    let wrong = client.read_holding_registers(9000, 1).await.unwrap();
    assert_eq!(wrong, Err(tokio_modbus::ExceptionCode::IllegalDataAddress));
    let too_many = client.read_holding_registers(0, 126).await.unwrap();
    assert_eq!(too_many, Err(tokio_modbus::ExceptionCode::IllegalDataValue));
    let custom = client
        .call(Request::Custom(0x41, vec![1, 2].into()))
        .await
        .unwrap();
    assert_eq!(
        custom.map(|_| ()),
        Err(tokio_modbus::ExceptionCode::IllegalFunction)
    );

    let areas = areas.lock().unwrap();
    assert_eq!(areas.output[0], 1);
    assert_eq!(areas.output[2], 0b1011);
    assert_eq!(areas.word(Area::Output, 3), Some(0xabcd));
    assert_eq!(areas.memory[4..8], 0x1234_5678_u32.to_le_bytes());
    assert_eq!(areas.word(Area::Memory, 100), Some(7));
    assert_eq!(areas.word(Area::Memory, 101), Some(8));
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn custom_function_codes_reach_the_hook() {
    let options = ServerOptions {
        custom: Some(Arc::new(|function, data| match function {
            0x41 => Ok(data.iter().map(|byte| byte + 1).collect()),
            _ => Err(ExceptionCode::IllegalDataValue),
        })),
        ..ServerOptions::default()
    };
    let (address, _areas) = start_server(full_areas(), options).await;
    let mut client = connect(address).await;
    let answer = client.call(Request::Custom(0x41, vec![1, 2].into())).await;
    let answer = answer.unwrap().unwrap();
    assert_eq!(
        answer,
        tokio_modbus::Response::Custom(0x41, vec![2, 3].into())
    );
    let refused = client.call(Request::Custom(0x42, vec![].into())).await;
    assert_eq!(
        refused.unwrap().map(|_| ()),
        Err(tokio_modbus::ExceptionCode::IllegalDataValue)
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn sixteen_clients_each_make_100_round_trips_at_once() {
    let (address, areas) = start_server(full_areas(), ServerOptions::default()).await;
    let mut clients = tokio::task::JoinSet::new();
    for client_index in 0..16_u16 {
        clients.spawn(async move {
            let mut client = connect(address).await;
            // Every client has its own %MW register, %QW register (beyond the coils) and coil.
            let register = 1024 + client_index;
            for round in 0..100_u16 {
                let value = client_index * 1000 + round;
                client.write_single_register(register, value).await??;
                let read = client.read_holding_registers(register, 1).await??;
                assert_eq!(read, [value], "client {client_index}, round {round}");
                let swapped = client
                    .read_write_multiple_registers(register, 1, 100 + client_index, &[round])
                    .await??;
                assert_eq!(swapped, [value]);
                client
                    .write_single_coil(client_index, round % 2 == 1)
                    .await??;
            }
            Ok::<_, Box<dyn std::error::Error + Send + Sync>>(())
        });
    }
    let mut finished = 0;
    while let Some(result) = tokio::time::timeout(PATIENCE, clients.join_next())
        .await
        .expect("the clients took too long")
    {
        result.unwrap().unwrap();
        finished += 1;
    }
    assert_eq!(finished, 16);
    let areas = areas.lock().unwrap();
    for client_index in 0..16 {
        let value = client_index as u16 * 1000 + 99;
        assert_eq!(areas.word(Area::Memory, client_index), Some(value));
        assert_eq!(areas.word(Area::Output, 100 + client_index), Some(99));
        assert_eq!(
            areas.bit(Area::Output, client_index / 8, client_index as u8 % 8),
            Some(true)
        );
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_new_client_takes_the_place_of_the_longest_idle_one() {
    let options = ServerOptions {
        max_clients: 2,
        ..ServerOptions::default()
    };
    let (address, _areas) = start_server(full_areas(), options).await;
    let mut first = TcpStream::connect(address).await.unwrap();
    first.write_all(&read_request(1)).await.unwrap();
    assert!(matches!(read_answer(&mut first).await, Answer::Frame(_)));
    let mut second = connect(address).await;
    second.read_coils(0, 1).await.unwrap().unwrap();

    // The server is full: the third client is served, and the first, whose last request is
    // the oldest, is closed.
    let mut third = TcpStream::connect(address).await.unwrap();
    third.write_all(&read_request(3)).await.unwrap();
    assert!(matches!(read_answer(&mut third).await, Answer::Frame(_)));
    assert_eq!(read_answer(&mut first).await, Answer::Closed);
    second.read_coils(0, 1).await.unwrap().unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn two_hundred_idle_and_slow_clients_do_not_keep_a_reader_out() {
    let (address, _areas) = start_server(full_areas(), ServerOptions::default()).await;
    // 100 clients that connect and say nothing, 100 that send half a frame and stop.
    let mut squatters = Vec::new();
    for index in 0..200 {
        let mut stream = TcpStream::connect(address).await.unwrap();
        if index % 2 == 1 {
            stream.write_all(&read_request(1)[..5]).await.unwrap();
        }
        squatters.push(stream);
    }
    let mut client = connect(address).await;
    let registers = tokio::time::timeout(PATIENCE, client.read_holding_registers(0, 2))
        .await
        .expect("the reader was kept waiting")
        .unwrap()
        .unwrap();
    assert_eq!(registers.len(), 2);
    // mbpoll, as an operator would, reads too.
    let mbpoll = required_program("mbpoll");
    let stdout = run(mbpoll, mbpoll_args(address, "-t 4 -r 1 -c 2", "")).await;
    assert_eq!(mbpoll_values(&stdout).len(), 2, "{stdout}");
    // The squatters beyond the 64 places were closed, oldest first.
    assert_eq!(read_answer(&mut squatters[0]).await, Answer::Closed);
}

/// What a raw socket got back.
#[derive(Debug, PartialEq)]
enum Answer {
    /// One whole response frame.
    Frame(Vec<u8>),
    /// The server closed the connection.
    Closed,
}

/// A frame reading holding register 0, with transaction id `transaction`.
fn read_request(transaction: u16) -> Vec<u8> {
    frame(transaction, &[3, 0, 0, 0, 1])
}

/// A well-formed MBAP frame around `pdu`, to unit 1.
fn frame(transaction: u16, pdu: &[u8]) -> Vec<u8> {
    let mut frame = transaction.to_be_bytes().to_vec();
    frame.extend_from_slice(&[0, 0]);
    frame.extend_from_slice(&(pdu.len() as u16 + 1).to_be_bytes());
    frame.push(1);
    frame.extend_from_slice(pdu);
    frame
}

/// Reads one response frame, or notices that the server closed the connection.
async fn read_answer(stream: &mut TcpStream) -> Answer {
    let mut header = [0; 7];
    let read = tokio::time::timeout(PATIENCE, stream.read_exact(&mut header))
        .await
        .expect("the server neither answered nor closed the connection");
    if read.is_err() {
        return Answer::Closed;
    }
    let length = usize::from(u16::from_be_bytes([header[4], header[5]]));
    let mut pdu = vec![0; length - 1];
    stream.read_exact(&mut pdu).await.unwrap();
    let mut frame = header.to_vec();
    frame.extend(pdu);
    Answer::Frame(frame)
}

/// Sends `bytes` on a fresh connection, closes the sending side, and returns what came back.
async fn send_raw(address: SocketAddr, bytes: &[u8]) -> Answer {
    let mut stream = TcpStream::connect(address).await.unwrap();
    stream.write_all(bytes).await.unwrap();
    stream.shutdown().await.unwrap();
    read_answer(&mut stream).await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn frames_that_cannot_be_trusted_close_their_connection_only() {
    let (address, _areas) = start_server(full_areas(), ServerOptions::default()).await;
    let mut wrong_protocol = read_request(7);
    wrong_protocol[2] = 0x12;
    let with_length = |length: u16| {
        let mut frame = vec![0, 7, 0, 0];
        frame.extend_from_slice(&length.to_be_bytes());
        frame.extend_from_slice(&[1, 3, 0, 0, 0, 1]);
        frame
    };
    let mut long_promise = frame(7, &[16, 0, 0, 0, 120, 240]);
    long_promise[4..6].copy_from_slice(&254_u16.to_be_bytes());
    let cases: [(&str, Vec<u8>); 8] = [
        ("a truncated header", vec![0, 7, 0, 0, 0]),
        ("an empty connection", vec![]),
        ("a wrong protocol id", wrong_protocol),
        ("length 0", with_length(0)),
        ("length 1", with_length(1)),
        ("length 255", with_length(255)),
        ("length 65535", with_length(65535)),
        ("a PDU shorter than its length", long_promise),
    ];
    for (case, bytes) in cases {
        assert_eq!(send_raw(address, &bytes).await, Answer::Closed, "{case}");
    }
    check_still_served(address).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn malformed_pdus_get_exceptions_and_the_connection_goes_on() {
    let (address, _areas) = start_server(full_areas(), ServerOptions::default()).await;
    let mut stream = TcpStream::connect(address).await.unwrap();
    let cases: [(&[u8], &[u8]); 9] = [
        (&[0x41, 1, 2, 3], &[0xc1, 1]),
        (&[0x90, 0xff], &[0x90, 1]),
        (&[0x00], &[0x80, 1]),
        (&[0x2b, 0x0e, 0x01, 0x00], &[0xab, 1]),
        (&[3, 0, 0], &[0x83, 3]),
        (&[3, 0, 0, 0, 1, 0xff], &[0x83, 3]),
        // tokio-modbus 0.17's decoder indexes past the data of this one (quantity 100, 1 byte).
        (&[15, 0, 0, 0, 100, 1, 0xff], &[0x8f, 3]),
        // And multiplies 0x8000 * 2 in u16 for this one.
        (&[16, 0, 0, 0x80, 0, 0], &[0x90, 3]),
        (&[5, 0, 0, 0x12, 0x34], &[0x85, 3]),
    ];
    for (transaction, (pdu, expected)) in (1..).zip(cases) {
        stream.write_all(&frame(transaction, pdu)).await.unwrap();
        assert_eq!(
            read_answer(&mut stream).await,
            Answer::Frame(frame(transaction, expected)),
            "request {pdu:02x?}"
        );
    }
    // Two requests in one write are both answered, in order.
    let mut pipelined = read_request(100);
    pipelined.extend(frame(101, &[0x41]));
    stream.write_all(&pipelined).await.unwrap();
    assert_eq!(
        read_answer(&mut stream).await,
        Answer::Frame(frame(100, &[3, 2, 0, 0]))
    );
    assert_eq!(
        read_answer(&mut stream).await,
        Answer::Frame(frame(101, &[0xc1, 1]))
    );
    check_still_served(address).await;
}

/// mbpoll's arguments for the server at `address`: its `options` (references 1-based, as mbpoll
/// counts them), then the host, then the `values` to write, if any.
fn mbpoll_args(address: SocketAddr, options: &str, values: &str) -> Vec<String> {
    let port = address.port().to_string();
    let host = address.ip().to_string();
    ["-m", "tcp", "-a", "1", "-1", "-o", "5", "-p", &port]
        .into_iter()
        .chain(options.split_whitespace())
        .chain([host.as_str()])
        .chain(values.split_whitespace())
        .map(str::to_owned)
        .collect()
}

/// The values mbpoll printed, as `[reference]: value` lines.
fn mbpoll_values(stdout: &str) -> Vec<String> {
    stdout
        .lines()
        .filter(|line| line.starts_with('['))
        .map(|line| line.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn mbpoll_reads_holding_registers_and_writes_coils() {
    let mbpoll = required_program("mbpoll");
    let mut areas = full_areas();
    for index in 0..4 {
        areas
            .set_word(Area::Output, index, 100 + index as u16)
            .unwrap();
    }
    areas.memory[20..24].copy_from_slice(&(-123_456_i32).to_le_bytes());
    let (address, areas) = start_server(areas, ServerOptions::default()).await;

    // Reference 1 is address 0, %QW0.
    let stdout = run(mbpoll.clone(), mbpoll_args(address, "-t 4 -r 1 -c 4", "")).await;
    assert_eq!(
        mbpoll_values(&stdout),
        ["[1]: 100", "[2]: 101", "[3]: 102", "[4]: 103"]
    );
    // %MD5 is addresses 2058 and 2059, high word first, which mbpoll calls big endian (-B).
    let stdout = run(
        mbpoll.clone(),
        mbpoll_args(address, "-t 4:int -B -r 2059 -c 1", ""),
    )
    .await;
    assert_eq!(mbpoll_values(&stdout), ["[2059]: -123456"]);

    // Coils 8..=11 (references 9..=12) are %QX1.0 to %QX1.3.
    run(mbpoll.clone(), mbpoll_args(address, "-t 0 -r 9", "1 0 1 1")).await;
    assert_eq!(areas.lock().unwrap().output[1], 0b1101);
    let stdout = run(mbpoll, mbpoll_args(address, "-t 0 -r 9 -c 4", "")).await;
    assert_eq!(
        mbpoll_values(&stdout),
        ["[9]: 1", "[10]: 0", "[11]: 1", "[12]: 1"]
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn pymodbus_reads_and_writes_registers_coils_and_a_double_word() {
    let python = python_with_pymodbus();
    let mut areas = full_areas();
    areas.set_word(Area::Memory, 0, 1111).unwrap();
    areas.set_word(Area::Memory, 1, 2222).unwrap();
    areas.memory[24..28].copy_from_slice(&0xdead_beef_u32.to_le_bytes());
    areas.output[1] = 0b10;
    areas.input[0] = 0b1001;
    areas.set_word(Area::Input, 1, 4321).unwrap();
    let (address, areas) = start_server(areas, ServerOptions::default()).await;

    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/peers/pymodbus_client.py");
    let args = vec![
        script.display().to_string(),
        address.ip().to_string(),
        address.port().to_string(),
    ];
    let stdout = run(python, args).await;
    let expected = "\
%MW0..1 [1111, 2222]
%MD6 0xdeadbeef
%QX1.0..2 [False, True, False]
%IX0.0..3 [True, False, False, True]
%IW0..1 [9, 4321]
unmapped exception 2
";
    assert_eq!(stdout, expected);

    let areas = areas.lock().unwrap();
    assert_eq!(areas.memory[20..24], 0x1234_5678_u32.to_le_bytes());
    assert_eq!(areas.output[0], 0b1101);
    assert_eq!(areas.word(Area::Output, 5), Some(777));
    assert_eq!(areas.word(Area::Memory, 2), Some(3333));
}
