//! The online services (`docs/protocol.md`) end to end: a scheduler and a Modbus server in
//! this process with the services wired in, and a tokio-modbus client sending function code
//! 0x64 over 127.0.0.1.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::borrow::Cow;
use std::net::SocketAddr;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use online_protocol::{
    CHUNK_BYTES, FUNCTION_CODE, Place, Reader, Request, TraceConfig, TriggerKind,
};
use program_image::ProgramImage;
use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};
use runtime::online::OnlineServices;
use runtime::scheduler::{Scheduler, SchedulerOptions};
use sha2::{Digest, Sha256};
use tokio_modbus::client::{Client, Context};
use tokio_modbus::{Request as ModbusRequest, Response};

/// How long any one step may take before the test gives up.
const PATIENCE: Duration = Duration::from_secs(10);

/// Counts, assigns a constant every cycle and pulses every tenth cycle.
const COUNTING: &str = "\
PROGRAM Main
VAR
    counter : DINT;
    assigned : DINT;
    pulse : BOOL;
END_VAR
counter := counter + 1;
assigned := 5;
pulse := (counter MOD 10) = 0;
END_PROGRAM
";

/// Another program, to download over the first.
const OTHER: &str = "\
PROGRAM Main
VAR
    counter : DINT;
END_VAR
counter := counter + 2;
END_PROGRAM
";

fn compile(text: &str) -> ProgramImage {
    let source = compiler::SourceProject::new(text);
    match compiler::compile_source(&source, "test.st") {
        Ok(image) => image,
        Err(error) => panic!("the test program does not compile: {error:?}"),
    }
}

/// A scheduler and a Modbus server with the online services on 127.0.0.1 port 0.
struct Plc {
    scheduler: Arc<Scheduler>,
    address: SocketAddr,
    server: tokio::task::JoinHandle<std::io::Result<()>>,
}

impl Plc {
    async fn start(password: Option<&str>) -> Self {
        Self::start_at("127.0.0.1:0".parse().unwrap(), password).await
    }

    /// A PLC listening on `address` (a PLC started again where one was).
    async fn start_at(address: SocketAddr, password: Option<&str>) -> Self {
        let areas = Arc::new(Mutex::new(LocatedAreas::default()));
        let scheduler =
            Arc::new(Scheduler::spawn(Arc::clone(&areas), SchedulerOptions::default()).unwrap());
        let services = Arc::new(OnlineServices::new(
            Arc::clone(&scheduler),
            password.map(str::to_owned),
        ));
        let listener = tokio::net::TcpListener::bind(address).await.unwrap();
        let address = listener.local_addr().unwrap();
        let server = tokio::spawn(serve(
            listener,
            areas,
            MapSlot::new(ModbusMap::default()),
            ServerOptions {
                custom: Some(services.handler()),
                closed: Some(services.closed_handler()),
                ..ServerOptions::default()
            },
        ));
        Self {
            scheduler,
            address,
            server,
        }
    }

    async fn connect(&self) -> Context {
        tokio::time::timeout(PATIENCE, tokio_modbus::client::tcp::connect(self.address))
            .await
            .expect("connecting took too long")
            .unwrap()
    }
}

impl Drop for Plc {
    fn drop(&mut self) {
        self.server.abort();
    }
}

/// Sends `request` and returns the status and payload of the answer.
async fn ask(client: &mut Context, request: &Request) -> (u8, Vec<u8>) {
    let call = client.call(ModbusRequest::Custom(
        FUNCTION_CODE,
        Cow::Owned(request.encode()),
    ));
    let response = tokio::time::timeout(PATIENCE, call)
        .await
        .expect("the answer took too long")
        .unwrap()
        .unwrap();
    let Response::Custom(function, body) = response else {
        panic!("not a custom response: {response:?}");
    };
    assert_eq!(function, FUNCTION_CODE);
    assert_eq!(
        body[0],
        request.service().number(),
        "the answer names its service"
    );
    (body[1], body[2..].to_vec())
}

/// Sends `request` and returns the payload of an answer that must be "done".
async fn done(client: &mut Context, request: &Request) -> Vec<u8> {
    let (status, payload) = ask(client, request).await;
    assert_eq!(
        status,
        0,
        "{request:?} was refused: {}",
        String::from_utf8_lossy(payload.get(1..).unwrap_or_default())
    );
    payload
}

/// The state and image hash `IDENTIFY` gives.
async fn identify(client: &mut Context) -> (u8, [u8; 32]) {
    let payload = done(
        client,
        &Request::Identify {
            protocol: online_protocol::PROTOCOL_VERSION,
        },
    )
    .await;
    let mut reader = Reader::new(&payload);
    assert_eq!(
        reader.u16("u16").unwrap(),
        online_protocol::PROTOCOL_VERSION
    );
    reader.str8("text").unwrap();
    let state = reader.u8("u8").unwrap();
    (state, reader.hash("hash").unwrap())
}

/// Begins a download of `bytes` announced with `hash` and sends the chunks `chunks` selects.
async fn send_image(
    client: &mut Context,
    token: u128,
    bytes: &[u8],
    hash: [u8; 32],
    chunks: impl Fn(usize) -> bool,
) -> u16 {
    let begin = Request::DownloadBegin {
        token,
        size: bytes.len() as u32,
        hash,
    };
    let payload = done(client, &begin).await;
    let mut reader = Reader::new(&payload);
    let transfer = reader.u16("u16").unwrap();
    let chunk_size = reader.u16("u16").unwrap();
    assert_eq!(chunk_size, CHUNK_BYTES);
    for (index, chunk) in bytes.chunks(usize::from(chunk_size)).enumerate() {
        if !chunks(index) {
            continue;
        }
        let request = Request::DownloadChunk {
            token,
            transfer,
            offset: (index * usize::from(chunk_size)) as u32,
            bytes: chunk.to_vec(),
        };
        done(client, &request).await;
    }
    transfer
}

/// Downloads `image` in chunks, commits it and starts it.
async fn download(client: &mut Context, token: u128, image: &ProgramImage) {
    let bytes = image.encode();
    let hash = Sha256::digest(&bytes).into();
    let transfer = send_image(client, token, &bytes, hash, |_| true).await;
    let commit = Request::DownloadCommit {
        token,
        transfer,
        start: true,
    };
    done(client, &commit).await;
}

async fn resolve(client: &mut Context, path: &str) -> Place {
    let payload = done(
        client,
        &Request::Resolve {
            path: path.to_owned(),
        },
    )
    .await;
    Reader::new(&payload).place("place").unwrap()
}

/// The cycle count, the forced bitmap and the DINT values of `places`.
async fn read(client: &mut Context, places: &[Place]) -> (u64, u8, Vec<i32>) {
    let payload = done(
        client,
        &Request::Read {
            places: places.to_vec(),
        },
    )
    .await;
    let mut reader = Reader::new(&payload);
    let cycle = reader.u64("u64").unwrap();
    let forced = reader.u8("u8").unwrap();
    let values = places
        .iter()
        .map(|_| i32::from_le_bytes(reader.take("value", 4).unwrap().try_into().unwrap()))
        .collect();
    (cycle, forced, values)
}

/// Reads `place` until `done` accepts its value.
async fn read_until(client: &mut Context, place: Place, what: &str, done: impl Fn(i32) -> bool) {
    let deadline = Instant::now() + PATIENCE;
    loop {
        let (_, _, values) = read(client, &[place]).await;
        if done(values[0]) {
            return;
        }
        assert!(
            Instant::now() < deadline,
            "waited in vain for {what}: {values:?}"
        );
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
}

async fn login(client: &mut Context, password: &str) -> u128 {
    let request = Request::Login {
        password: password.to_owned(),
    };
    u128::from_le_bytes(done(client, &request).await.try_into().unwrap())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_downloaded_program_is_monitored_written_forced_and_traced() {
    let plc = Plc::start(None).await;
    let mut client = plc.connect().await;
    assert_eq!(identify(&mut client).await, (0, [0; 32]));

    let image = compile(COUNTING);
    download(&mut client, 0, &image).await;
    assert_eq!(identify(&mut client).await, (2, image.identity()));

    let counter = resolve(&mut client, "Main.counter").await;
    let assigned = resolve(&mut client, "Main.assigned").await;
    assert_eq!((counter.region, counter.bit, counter.size), (0, None, 4));
    let (first_cycle, _, first) = read(&mut client, &[counter]).await;
    read_until(&mut client, counter, "the counter to count", |value| {
        value > first[0] + 2
    })
    .await;
    let (later_cycle, _, _) = read(&mut client, &[counter]).await;
    assert!(later_cycle > first_cycle);

    let write = Request::Write {
        token: 0,
        values: vec![(counter, 100_000i32.to_le_bytes().to_vec())],
    };
    done(&mut client, &write).await;
    read_until(&mut client, counter, "the written counter", |value| {
        (100_000..100_500).contains(&value)
    })
    .await;

    // The program assigns 5 every cycle; the force wins before and after each one.
    let force = Request::Force {
        token: 0,
        values: vec![(assigned, 77i32.to_le_bytes().to_vec())],
    };
    done(&mut client, &force).await;
    let (forced_at, _, _) = read(&mut client, &[assigned]).await;
    for _ in 0..5 {
        tokio::time::sleep(Duration::from_millis(15)).await;
        let (cycle, forced, values) = read(&mut client, &[counter, assigned]).await;
        assert_eq!((forced, values[1]), (0b10, 77), "at cycle {cycle}");
    }
    let (after, _, _) = read(&mut client, &[assigned]).await;
    assert!(after > forced_at + 2, "cycles ran while forced");
    let forces = done(&mut client, &Request::Forces { from: 0 }).await;
    assert_eq!(&forces[..3], &[1, 0, 1]);
    let unforce = Request::Unforce {
        token: 0,
        places: vec![assigned],
    };
    done(&mut client, &unforce).await;
    read_until(&mut client, assigned, "the program's own value", |value| {
        value == 5
    })
    .await;
    assert_eq!(read(&mut client, &[assigned]).await.1, 0);

    // A trace of the counter around the rising edge of the pulse.
    let pulse = resolve(&mut client, "Main.pulse").await;
    let configure = Request::TraceConfigure {
        token: 0,
        config: TraceConfig {
            task: 0,
            every: 1,
            samples: 8,
            pretrigger: 25,
            trigger: TriggerKind::Rising,
            trigger_place: pulse,
            places: vec![counter],
        },
    };
    assert_eq!(done(&mut client, &configure).await, 4u16.to_le_bytes());
    done(&mut client, &Request::TraceArm { token: 0 }).await;
    let deadline = Instant::now() + PATIENCE;
    let status = loop {
        let status = done(&mut client, &Request::TraceStatus).await;
        if status[0] == 4 {
            break status;
        }
        assert!(
            Instant::now() < deadline,
            "the trace never completed: {status:?}"
        );
        tokio::time::sleep(Duration::from_millis(10)).await;
    };
    let mut reader = Reader::new(&status[1..]);
    assert_eq!(reader.u32("u32").unwrap(), 8);
    assert_eq!(
        reader.u32("u32").unwrap(),
        2,
        "two samples before the trigger"
    );
    let upload = done(&mut client, &Request::TraceUpload { from: 0 }).await;
    let mut reader = Reader::new(&upload);
    assert_eq!(reader.u8("u8").unwrap(), 8);
    let samples: Vec<(u64, i32)> = (0..8)
        .map(|_| {
            let cycle = reader.u64("u64").unwrap();
            reader.u64("u64").unwrap();
            let value = i32::from_le_bytes(reader.take("value", 4).unwrap().try_into().unwrap());
            (cycle, value)
        })
        .collect();
    for pair in samples.windows(2) {
        assert_eq!(pair[1].0, pair[0].0 + 1, "consecutive cycles: {samples:?}");
        assert_eq!(pair[1].1, pair[0].1 + 1, "consecutive counts: {samples:?}");
    }
    assert_eq!(samples[2].1 % 10, 0, "the trigger's sample: {samples:?}");
    assert!(upload.len() == 1 + 8 * 20);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn with_a_password_only_a_logged_in_client_changes_the_target() {
    let plc = Plc::start(Some("open sesame")).await;
    plc.scheduler.load(compile(COUNTING)).unwrap();
    let mut client = plc.connect().await;

    assert_eq!(ask(&mut client, &Request::Start { token: 0 }).await.0, 3);
    assert_eq!(ask(&mut client, &Request::Start { token: 42 }).await.0, 4);
    let wrong = Request::Login {
        password: "sesame".to_owned(),
    };
    assert_eq!(ask(&mut client, &wrong).await.0, 4);
    // The wrong password's answer came when its address's wait was over, so it locks nobody
    // out: another client (of the same address) logs in, and its token is of no use on this
    // connection.
    let mut other = plc.connect().await;
    let other_token = login(&mut other, "open sesame").await;
    let stolen = Request::Start { token: other_token };
    assert_eq!(ask(&mut client, &stolen).await.0, 4);
    assert_eq!(identify(&mut client).await.0, 1, "still stopped");

    // Reading needs no token.
    let counter = resolve(&mut client, "Main.counter").await;
    read(&mut client, &[counter]).await;
    done(&mut client, &Request::Tasks).await;
    done(&mut client, &Request::Faults { from: 0 }).await;

    let token = login(&mut client, "open sesame").await;
    assert_eq!(done(&mut client, &Request::Start { token }).await, [2]);
    read_until(&mut client, counter, "the counter to count", |value| {
        value > 3
    })
    .await;
    let write = Request::Write {
        token: token.wrapping_add(1),
        values: vec![(counter, 0i32.to_le_bytes().to_vec())],
    };
    assert_eq!(ask(&mut client, &write).await.0, 4);
    assert_eq!(done(&mut client, &Request::Stop { token }).await, [1]);
    // After LOGOUT the token is refused, and the other client's is still good.
    done(&mut client, &Request::Logout).await;
    assert_eq!(ask(&mut client, &Request::Start { token }).await.0, 4);
    let start = Request::Start { token: other_token };
    assert_eq!(done(&mut other, &start).await, [2]);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_corrupted_or_interrupted_download_leaves_the_running_program() {
    let plc = Plc::start(None).await;
    let image = compile(COUNTING);
    plc.scheduler.load(image.clone()).unwrap();
    plc.scheduler.start().unwrap();
    let mut client = plc.connect().await;
    let counter = resolve(&mut client, "Main.counter").await;

    // One chunk differs from the bytes the hash was taken of.
    let other = compile(OTHER).encode();
    let hash = Sha256::digest(&other).into();
    let mut corrupted = other.clone();
    corrupted[10] ^= 0xFF;
    let transfer = send_image(&mut client, 0, &corrupted, hash, |_| true).await;
    let commit = Request::DownloadCommit {
        token: 0,
        transfer,
        start: true,
    };
    let (status, message) = ask(&mut client, &commit).await;
    assert_eq!(status, 8);
    assert!(String::from_utf8_lossy(&message).contains("SHA-256"));
    assert_eq!(identify(&mut client).await, (2, image.identity()));

    // Another client begins a download, sends part of it, and goes away.
    let abandoned = {
        let mut interrupted = plc.connect().await;
        send_image(&mut interrupted, 0, &other, hash, |index| index % 2 == 0).await
    };
    let (status, _) = ask(&mut client, &commit).await;
    assert_eq!(status, 7, "the corrupted transfer is gone");
    // The closed connection takes its transfer along (an empty chunk changes nothing).
    let probe = Request::DownloadChunk {
        token: 0,
        transfer: abandoned,
        offset: 0,
        bytes: Vec::new(),
    };
    let deadline = Instant::now() + PATIENCE;
    while ask(&mut client, &probe).await.0 != 7 {
        assert!(Instant::now() < deadline, "the abandoned transfer lives on");
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    assert_eq!(identify(&mut client).await, (2, image.identity()));
    let (_, _, before) = read(&mut client, &[counter]).await;
    read_until(&mut client, counter, "the old program to go on", |value| {
        value > before[0] + 2
    })
    .await;
}

/// The next number of a small linear congruential generator: reproducible "random" points.
fn next(seed: &mut u64) -> u64 {
    *seed = seed
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    *seed >> 33
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_download_cut_or_corrupted_at_100_points_leaves_the_old_program_running() {
    let plc = Plc::start(None).await;
    let (mut client, _) = online::Client::connect(plc.address, None).await.unwrap();
    client
        .download(&compile(COUNTING).encode(), true, |_, _| {})
        .await
        .unwrap();
    let running = client.identify().await.unwrap().image_hash;
    assert!(running.is_some());
    let counter = client.resolve("Main.counter").await.unwrap().place;
    let other = compile(OTHER).encode();
    let hash: [u8; 32] = Sha256::digest(&other).into();
    let chunk = usize::from(CHUNK_BYTES);
    let chunks = other.len().div_ceil(chunk);
    let mut seed = 0x2545_F491_4F6C_DD1D;
    for round in 0..100 {
        let cut_at = next(&mut seed) as usize % chunks;
        let corrupt = next(&mut seed) % 2 == 1;
        let mut raw = plc.connect().await;
        let begin = done(
            &mut raw,
            &Request::DownloadBegin {
                token: 0,
                size: other.len() as u32,
                hash,
            },
        )
        .await;
        let transfer = u16::from_le_bytes([begin[0], begin[1]]);
        let last = if corrupt { chunks - 1 } else { cut_at };
        for k in 0..=last {
            let start = k * chunk;
            let mut bytes = other[start..(start + chunk).min(other.len())].to_vec();
            if corrupt && k == cut_at {
                let at = next(&mut seed) as usize % bytes.len();
                bytes[at] ^= 0x5A;
            }
            done(
                &mut raw,
                &Request::DownloadChunk {
                    token: 0,
                    transfer,
                    offset: start as u32,
                    bytes,
                },
            )
            .await;
        }
        if corrupt {
            // Every byte arrived, one of them wrong: the image is refused.
            let (status, _) = ask(
                &mut raw,
                &Request::DownloadCommit {
                    token: 0,
                    transfer,
                    start: true,
                },
            )
            .await;
            assert_eq!(
                status, 8,
                "round {round}: a corrupted image must be refused"
            );
        }
        // Dropping the connection mid-transfer abandons it.
        drop(raw);
        assert_eq!(
            client.identify().await.unwrap().image_hash,
            running,
            "round {round}"
        );
        // The old program keeps counting (waited for, as a loaded machine may be slow).
        let count = |bytes: &[u8]| i32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]);
        let before = count(&client.read(&[counter]).await.unwrap().values[0].0);
        let started = Instant::now();
        while count(&client.read(&[counter]).await.unwrap().values[0].0) <= before {
            assert!(
                started.elapsed() < PATIENCE,
                "round {round}: the old program stopped counting"
            );
            tokio::time::sleep(Duration::from_millis(5)).await;
        }
    }
}

#[tokio::test]
async fn another_protocol_version_is_refused_naming_both() {
    let plc = Plc::start(None).await;
    let mut raw = plc.connect().await;
    let (status, payload) = ask(&mut raw, &Request::Identify { protocol: 1 }).await;
    assert_eq!(status, 9);
    let message = String::from_utf8_lossy(&payload[1..]).into_owned();
    assert!(
        message.contains("version 1")
            && message.contains(&format!("version {}", online_protocol::PROTOCOL_VERSION)),
        "{message}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_trace_of_more_places_than_one_frame_holds_records_them_all() {
    let mut declarations = String::new();
    let mut body = String::from("n := n + 1;\n");
    for i in 0..40 {
        declarations.push_str(&format!("v{i} : DINT;\n"));
        body.push_str(&format!("v{i} := n + {i};\n"));
    }
    let program =
        format!("PROGRAM Main\nVAR\nn : DINT;\n{declarations}END_VAR\n{body}END_PROGRAM\n");
    let plc = Plc::start(None).await;
    let (mut client, _) = online::Client::connect(plc.address, None).await.unwrap();
    client
        .download(&compile(&program).encode(), true, |_, _| {})
        .await
        .unwrap();
    let mut places = Vec::new();
    for i in 0..40 {
        places.push(client.resolve(&format!("Main.v{i}")).await.unwrap().place);
    }
    let config = online::TraceConfig {
        task: 0,
        every: 1,
        samples: 5,
        pretrigger_percent: 0,
        trigger: online::Trigger::None,
        places: places.clone(),
    };
    assert_eq!(client.trace_configure(&config).await.unwrap(), 160);
    client.trace_arm().await.unwrap();
    let started = Instant::now();
    while client.trace_status().await.unwrap().state != online::TraceState::Complete {
        assert!(started.elapsed() < PATIENCE, "the trace never completed");
        tokio::time::sleep(Duration::from_millis(10)).await;
    }
    let samples = client.trace_upload(&places, |_| {}).await.unwrap();
    assert_eq!(samples.len(), 5);
    for sample in &samples {
        let value = |i: usize| i32::from_le_bytes(sample.values[i][..4].try_into().unwrap());
        // Every place was sampled in the same cycle: v{i} = n + i.
        assert!(
            (0..40).all(|i| value(i) == value(0) + i as i32),
            "{sample:?}"
        );
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_session_streams_snapshots_reports_a_lost_target_and_reconnects() {
    use online::session::{Command, Event, SessionOptions};
    let plc = Plc::start(None).await;
    let (mut client, _) = online::Client::connect(plc.address, None).await.unwrap();
    client
        .download(&compile(COUNTING).encode(), true, |_, _| {})
        .await
        .unwrap();
    let counter = client.resolve("Main.counter").await.unwrap().place;
    drop(client);
    let (commands, mut events) = online::session::spawn(SessionOptions {
        address: plc.address,
        password: None,
        poll_interval: Duration::from_millis(10),
        reconnect_interval: Duration::from_millis(50),
    });
    let mut next = async || {
        tokio::time::timeout(PATIENCE, events.recv())
            .await
            .unwrap()
            .unwrap()
    };
    assert!(matches!(next().await, Event::Connected(identity) if identity.image_hash.is_some()));
    commands.send(Command::Watch(vec![counter])).await.unwrap();
    let mut seen = Vec::new();
    while seen.len() < 3 {
        if let Event::Snapshot(snapshot) = next().await {
            seen.push(snapshot.cycle);
        }
    }
    assert!(seen.windows(2).all(|w| w[1] >= w[0]), "{seen:?}");
    commands.send(Command::Stop).await.unwrap();
    loop {
        match next().await {
            Event::Done(state) => {
                assert_eq!(state, online::TargetState::Stopped);
                break;
            }
            Event::Snapshot(_) => {}
            other => panic!("unexpected {other:?}"),
        }
    }
    // The target goes away: the session says so, then comes back when the target does.
    let address = plc.address;
    drop(plc);
    loop {
        if let Event::Disconnected(reason) = next().await {
            assert!(!reason.is_empty());
            break;
        }
    }
    let again = Plc::start_at(address, None).await;
    loop {
        if let Event::Connected(_) = next().await {
            break;
        }
    }
    commands.send(Command::Close).await.unwrap();
    drop(again);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_session_checks_an_online_change_then_drops_applies_or_downloads_the_transfer() {
    use online::session::{ChangeCommand, Command, Event, SessionOptions};
    let plc = Plc::start(None).await;
    let (mut client, _) = online::Client::connect(plc.address, None).await.unwrap();
    client
        .download(&compile(COUNTING).encode(), true, |_, _| {})
        .await
        .unwrap();
    drop(client);
    let (commands, mut events) = online::session::spawn(SessionOptions {
        address: plc.address,
        password: None,
        poll_interval: Duration::from_millis(10),
        reconnect_interval: Duration::from_millis(50),
    });
    let mut next = async || {
        tokio::time::timeout(PATIENCE, events.recv())
            .await
            .unwrap()
            .unwrap()
    };
    assert!(matches!(next().await, Event::Connected(_)));
    let other = compile(OTHER).encode();
    let send = async |step: ChangeCommand| {
        commands.send(Command::OnlineChange(step)).await.unwrap();
    };
    // Each step's answer, after the transfer's progress.
    let mut answer = async || loop {
        match next().await {
            Event::DownloadProgress(..) => {}
            event => return event,
        }
    };
    for step in ["abort", "apply", "commit"] {
        send(ChangeCommand::Check(other.clone())).await;
        let transfer = match answer().await {
            Event::ChangeChecked {
                transfer,
                check,
                details,
            } if step == "apply" => {
                assert!(check.possible, "{check:?}");
                assert_eq!(check.removed, 2, "{check:?}");
                let names: Vec<&str> = details.iter().map(|d| d.name.as_str()).collect();
                assert!(names.contains(&"Main"), "{names:?}");
                transfer
            }
            Event::ChangeChecked {
                transfer, check, ..
            } => {
                // After the change, the target already runs this program.
                assert_eq!(check.possible, step == "abort", "{step}: {check:?}");
                transfer
            }
            other => panic!("{step}: {other:?}"),
        };
        match step {
            "abort" => send(ChangeCommand::Abort(transfer)).await,
            "apply" => send(ChangeCommand::Apply(transfer)).await,
            _ => {
                send(ChangeCommand::Commit {
                    transfer,
                    start: true,
                })
                .await;
            }
        }
        match answer().await {
            Event::Done(state) => {
                assert_ne!(step, "apply");
                assert_eq!(state, online::TargetState::Running);
            }
            Event::ChangeApplied(applied, state) => {
                assert_eq!(step, "apply");
                assert!(applied.carried >= 1, "{applied:?}");
                assert_eq!(state, online::TargetState::Running);
            }
            other => panic!("{step}: {other:?}"),
        }
    }
    commands.send(Command::Close).await.unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn retained_variables_that_keep_path_and_type_survive_a_download_of_a_changed_program() {
    let first = "PROGRAM Main\nVAR RETAIN total : DINT; changed : INT; END_VAR\nVAR plain : DINT; END_VAR\ntotal := total + 1; changed := 7; plain := 5;\nEND_PROGRAM\n";
    // More variables, `changed` of another type, `total` as it was.
    let second = "PROGRAM Main\nVAR extra : LREAL; END_VAR\nVAR RETAIN fresh : DINT; total : DINT; changed : DINT; END_VAR\nVAR plain : DINT; END_VAR\ntotal := total + 0; extra := 1.0; fresh := 3;\nEND_PROGRAM\n";
    let plc = Plc::start(None).await;
    let (mut client, _) = online::Client::connect(plc.address, None).await.unwrap();
    client
        .download(&compile(first).encode(), true, |_, _| {})
        .await
        .unwrap();
    let total = client.resolve("Main.total").await.unwrap().place;
    let read_total = async |client: &mut online::Client| {
        let bytes = client.read(&[total]).await.unwrap().values[0].0.clone();
        i32::from_le_bytes(bytes[..4].try_into().unwrap())
    };
    let started = Instant::now();
    while read_total(&mut client).await < 2 {
        assert!(
            started.elapsed() < PATIENCE,
            "the first program never counted"
        );
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    let before = read_total(&mut client).await;
    let carried = client
        .download(&compile(second).encode(), true, |_, _| {})
        .await
        .unwrap();
    assert!(carried, "the commit says values were carried over");
    let places = [
        client.resolve("Main.total").await.unwrap().place,
        client.resolve("Main.changed").await.unwrap().place,
        client.resolve("Main.plain").await.unwrap().place,
    ];
    let values = client.read(&places).await.unwrap().values;
    let value = |i: usize| i32::from_le_bytes(values[i].0[..4].try_into().unwrap());
    assert!(
        value(0) >= before,
        "total kept its value: {} < {before}",
        value(0)
    );
    assert_eq!(
        value(1),
        0,
        "a retained variable whose type changed starts again"
    );
    assert_eq!(value(2), 0, "a variable that is not retained starts again");
}
