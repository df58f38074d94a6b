use std::sync::Arc;

use tokio::io::{AsyncReadExt, DuplexStream};

use super::*;
use crate::areas::Area;
use crate::modbus::ModbusMap;
use crate::modbus::rtu_slave::RtuSlaveCounts;

/// The silence of a 19200 baud line.
const SILENCE: Duration = Duration::from_micros(2006);

/// Longer than any answer takes: a master that has waited this long has no answer coming.
const NO_ANSWER: Duration = Duration::from_millis(500);

/// A slave with unit id 1 over an in-memory line, with `%QW0` = 1 and `%QW1` = 2.
struct Line {
    master: DuplexStream,
    areas: Arc<Mutex<LocatedAreas>>,
    counters: Arc<RtuSlaveCounters>,
}

fn line(writes: WritePolicy) -> Line {
    let mut areas = LocatedAreas::new(4, 4, 4);
    areas.set_word(Area::Output, 0, 1).unwrap();
    areas.set_word(Area::Output, 1, 2).unwrap();
    let areas = Arc::new(Mutex::new(areas));
    let counters = Arc::new(RtuSlaveCounters::default());
    let (master, port) = tokio::io::duplex(1024);
    let options = RtuSlaveOptions {
        unit_id: 1,
        silence: SILENCE,
        writes,
    };
    let (served_areas, served_counters) = (Arc::clone(&areas), Arc::clone(&counters));
    tokio::spawn(async move {
        let map = MapSlot::new(ModbusMap::default());
        serve_rtu(port, &served_areas, &map, &options, &served_counters).await
    });
    Line {
        master,
        areas,
        counters,
    }
}

impl Line {
    async fn send(&mut self, frame: &[u8]) {
        self.master.write_all(frame).await.unwrap();
    }

    /// The answer of `length` bytes, and how long after the request it came.
    async fn answer(&mut self, length: usize) -> Vec<u8> {
        let mut answer = vec![0; length];
        tokio::time::timeout(NO_ANSWER, self.master.read_exact(&mut answer))
            .await
            .expect("no answer")
            .unwrap();
        answer
    }

    async fn no_answer(&mut self) {
        let mut byte = [0; 1];
        let read = tokio::time::timeout(NO_ANSWER, self.master.read(&mut byte)).await;
        assert!(read.is_err(), "answered {byte:?}");
    }

    fn counts(&self) -> RtuSlaveCounts {
        self.counters.counts()
    }
}

#[tokio::test(start_paused = true)]
async fn a_read_is_answered_after_the_silence_with_the_golden_answer() {
    let mut line = line(WritePolicy::All);
    let start = tokio::time::Instant::now();
    line.send(&[0x01, 0x03, 0x00, 0x00, 0x00, 0x02, 0xC4, 0x0B])
        .await;
    let answer = line.answer(9).await;
    assert_eq!(
        answer,
        [0x01, 0x03, 0x04, 0x00, 0x01, 0x00, 0x02, 0x2A, 0x32]
    );
    // tokio's timers tick in whole milliseconds, so the silence may end up to one later.
    let waited = start.elapsed();
    assert!(
        waited >= SILENCE && waited <= SILENCE + Duration::from_millis(1),
        "{waited:?}"
    );
    assert_eq!(line.counts().answered, 1);
}

#[tokio::test(start_paused = true)]
async fn a_frame_for_another_unit_or_with_a_bad_crc_gets_no_answer_and_the_next_one_does() {
    let mut line = line(WritePolicy::All);
    line.send(&rtu_frame(2, &[0x03, 0x00, 0x00, 0x00, 0x01]))
        .await;
    line.no_answer().await;
    let mut damaged = rtu_frame(1, &[0x03, 0x00, 0x00, 0x00, 0x01]);
    damaged[2] ^= 0x40;
    line.send(&damaged).await;
    line.no_answer().await;
    line.send(&rtu_frame(1, &[0x03, 0x00, 0x01, 0x00, 0x01]))
        .await;
    assert_eq!(
        line.answer(7).await,
        rtu_frame(1, &[0x03, 0x02, 0x00, 0x02])
    );
    let counts = line.counts();
    assert_eq!((counts.ignored, counts.bad_crc, counts.answered), (1, 1, 1));
}

#[tokio::test(start_paused = true)]
async fn a_broadcast_write_runs_without_an_answer_and_a_broadcast_read_is_ignored() {
    let mut line = line(WritePolicy::All);
    line.send(&rtu_frame(0, &[0x06, 0x00, 0x01, 0x12, 0x34]))
        .await;
    line.no_answer().await;
    assert_eq!(
        line.areas.lock().unwrap().word(Area::Output, 1),
        Some(0x1234)
    );
    line.send(&rtu_frame(0, &[0x03, 0x00, 0x00, 0x00, 0x01]))
        .await;
    line.no_answer().await;
    let counts = line.counts();
    assert_eq!(
        (counts.broadcasts, counts.ignored, counts.answered),
        (1, 1, 0)
    );
}

#[tokio::test(start_paused = true)]
async fn the_online_services_function_code_gets_exception_1() {
    let mut line = line(WritePolicy::All);
    line.send(&rtu_frame(1, &[100, 0x01, 0x00, 0x00])).await;
    assert_eq!(line.answer(5).await, rtu_frame(1, &[100 | 0x80, 1]));
    line.send(&rtu_frame(1, &[0x07])).await;
    assert_eq!(line.answer(5).await, rtu_frame(1, &[0x87, 1]));
}

#[tokio::test(start_paused = true)]
async fn the_write_policy_and_the_map_s_exceptions_are_the_tcp_server_s() {
    let mut line = line(WritePolicy::None);
    line.send(&rtu_frame(1, &[0x06, 0x00, 0x00, 0x00, 0x07]))
        .await;
    assert_eq!(line.answer(5).await, rtu_frame(1, &[0x86, 1]));
    assert_eq!(line.areas.lock().unwrap().word(Area::Output, 0), Some(1));
    // %QW2 and beyond are not in these 4-byte areas.
    line.send(&rtu_frame(1, &[0x03, 0x00, 0x02, 0x00, 0x01]))
        .await;
    assert_eq!(line.answer(5).await, rtu_frame(1, &[0x83, 2]));
    // A write broadcast against the policy changes nothing either.
    line.send(&rtu_frame(0, &[0x06, 0x00, 0x00, 0x00, 0x07]))
        .await;
    line.no_answer().await;
    assert_eq!(line.areas.lock().unwrap().word(Area::Output, 0), Some(1));
}

#[tokio::test(start_paused = true)]
async fn the_slave_ends_at_the_port_s_end_of_file() {
    let (master, port) = tokio::io::duplex(64);
    drop(master);
    let areas = Mutex::new(LocatedAreas::new(2, 2, 2));
    let map = MapSlot::new(ModbusMap::default());
    let options = RtuSlaveOptions {
        unit_id: 1,
        silence: SILENCE,
        writes: WritePolicy::All,
    };
    let counters = RtuSlaveCounters::default();
    serve_rtu(port, &areas, &map, &options, &counters)
        .await
        .unwrap();
    assert_eq!(counters.counts(), RtuSlaveCounts::default());
}

#[tokio::test(start_paused = true)]
async fn an_exception_answer_on_the_line_is_ignored_not_answered() {
    let mut line = line(WritePolicy::All);
    // An exception of function code 3, as an echoing adapter would hand back.
    line.send(&rtu_frame(1, &[0x83, 0x02])).await;
    line.no_answer().await;
    line.send(&rtu_frame(1, &[0x03, 0x00, 0x00, 0x00, 0x01]))
        .await;
    assert_eq!(
        line.answer(7).await,
        rtu_frame(1, &[0x03, 0x02, 0x00, 0x01])
    );
    assert_eq!((line.counts().ignored, line.counts().answered), (1, 1));
}

/// A port whose flush never ends, like a serial port's `tcdrain` on a line that is slow to
/// send: the slave must not wait for it.
struct NeverDrains(DuplexStream);

impl AsyncRead for NeverDrains {
    fn poll_read(
        mut self: std::pin::Pin<&mut Self>,
        context: &mut std::task::Context<'_>,
        buffer: &mut tokio::io::ReadBuf<'_>,
    ) -> std::task::Poll<io::Result<()>> {
        std::pin::Pin::new(&mut self.0).poll_read(context, buffer)
    }
}

impl AsyncWrite for NeverDrains {
    fn poll_write(
        mut self: std::pin::Pin<&mut Self>,
        context: &mut std::task::Context<'_>,
        bytes: &[u8],
    ) -> std::task::Poll<io::Result<usize>> {
        std::pin::Pin::new(&mut self.0).poll_write(context, bytes)
    }

    fn poll_flush(
        self: std::pin::Pin<&mut Self>,
        _context: &mut std::task::Context<'_>,
    ) -> std::task::Poll<io::Result<()>> {
        std::task::Poll::Pending
    }

    fn poll_shutdown(
        mut self: std::pin::Pin<&mut Self>,
        context: &mut std::task::Context<'_>,
    ) -> std::task::Poll<io::Result<()>> {
        std::pin::Pin::new(&mut self.0).poll_shutdown(context)
    }
}

#[tokio::test(start_paused = true)]
async fn the_slave_answers_without_waiting_for_the_port_to_drain() {
    let (mut master, port) = tokio::io::duplex(1024);
    let counters = Arc::new(RtuSlaveCounters::default());
    let served_counters = Arc::clone(&counters);
    tokio::spawn(async move {
        let areas = Mutex::new(LocatedAreas::new(4, 4, 4));
        let map = MapSlot::new(ModbusMap::default());
        let options = RtuSlaveOptions {
            unit_id: 1,
            silence: SILENCE,
            writes: WritePolicy::All,
        };
        serve_rtu(NeverDrains(port), &areas, &map, &options, &served_counters).await
    });
    for _ in 0..2 {
        master
            .write_all(&rtu_frame(1, &[0x03, 0x00, 0x00, 0x00, 0x01]))
            .await
            .unwrap();
        let mut answer = [0; 7];
        tokio::time::timeout(NO_ANSWER, master.read_exact(&mut answer))
            .await
            .expect("no answer")
            .unwrap();
        assert_eq!(answer.to_vec(), rtu_frame(1, &[0x03, 0x02, 0x00, 0x00]));
    }
    assert_eq!(counters.counts().answered, 2);
}
