use std::time::Duration;

use tokio::io::{AsyncWriteExt, DuplexStream};

use super::*;

/// The silence of a 19200 baud line.
const SILENCE: Duration = Duration::from_micros(2006);

fn hex(text: &str) -> Vec<u8> {
    text.split_whitespace()
        .map(|byte| u8::from_str_radix(byte, 16).unwrap())
        .collect()
}

/// The golden frames of the Delta DVP-15MC manual (digest §1.8), requests and answers.
const GOLDEN: [&str; 12] = [
    "01 03 00 00 00 02 C4 0B",
    "01 03 04 00 01 00 02 2A 32",
    "01 06 00 00 01 00 88 5A",
    "01 10 00 00 00 02 04 01 00 02 00 F3 33",
    "01 10 00 00 00 02 41 C8",
    "01 01 A0 10 00 0D DE 0A",
    "01 01 02 81 11 19 A0",
    "01 02 A0 10 00 0D 9A 0A",
    "01 02 02 81 11 19 E4",
    "01 05 A0 00 FF 00 AE 3A",
    "01 0F A0 00 00 08 01 81 26 55",
    "01 0F A0 00 00 08 76 0D",
];

/// A reader over one end of an in-memory pipe, and the other end to write the line's bytes.
fn line() -> (RtuFrameReader<DuplexStream>, DuplexStream) {
    let (port, sender) = tokio::io::duplex(4096);
    (RtuFrameReader::new(port, SILENCE), sender)
}

fn request(text: &str) -> RtuFrame {
    let bytes = hex(text);
    RtuFrame::Request {
        address: bytes[0],
        pdu: bytes[1..bytes.len() - 2].to_vec(),
    }
}

#[test]
fn the_crc_of_every_golden_frame_is_its_last_two_bytes_low_byte_first() {
    for text in GOLDEN {
        let frame = hex(text);
        let (body, crc) = frame.split_at(frame.len() - 2);
        assert_eq!(crc16(body).to_le_bytes(), crc, "{text}");
        assert_eq!(rtu_frame(body[0], &body[1..]), frame, "{text}");
    }
}

#[tokio::test(start_paused = true)]
async fn a_request_split_into_chunks_anywhere_is_one_frame() {
    for text in [GOLDEN[0], GOLDEN[3], GOLDEN[10]] {
        let frame = hex(text);
        for split in 1..frame.len() {
            let (mut reader, mut sender) = line();
            let (first, second) = frame.split_at(split);
            let (first, second) = (first.to_vec(), second.to_vec());
            tokio::spawn(async move {
                sender.write_all(&first).await.unwrap();
                // Less than the silence: still the same frame.
                tokio::time::sleep(SILENCE / 2).await;
                sender.write_all(&second).await.unwrap();
                // The line stays open and idle afterwards.
                std::future::pending::<()>().await;
            });
            let received = reader.next_frame().await.unwrap();
            assert_eq!(received, Some(request(text)), "{text} split at {split}");
        }
    }
}

#[tokio::test(start_paused = true)]
async fn a_frame_complete_by_its_length_is_taken_without_waiting_for_the_silence() {
    let (mut reader, mut sender) = line();
    let mut both = hex(GOLDEN[0]);
    both.extend(hex(GOLDEN[2]));
    sender.write_all(&both).await.unwrap();
    let start = tokio::time::Instant::now();
    assert_eq!(reader.next_frame().await.unwrap(), Some(request(GOLDEN[0])));
    assert_eq!(reader.next_frame().await.unwrap(), Some(request(GOLDEN[2])));
    assert_eq!(start.elapsed(), Duration::ZERO);
}

#[tokio::test(start_paused = true)]
async fn a_bad_crc_is_dropped_at_the_silence_and_the_next_frame_is_read() {
    let (mut reader, mut sender) = line();
    let mut damaged = hex(GOLDEN[0]);
    damaged[7] ^= 0x01;
    sender.write_all(&damaged).await.unwrap();
    assert_eq!(
        reader.next_frame().await.unwrap(),
        Some(RtuFrame::Dropped(DroppedFrame::BadCrc))
    );
    sender.write_all(&hex(GOLDEN[2])).await.unwrap();
    assert_eq!(reader.next_frame().await.unwrap(), Some(request(GOLDEN[2])));
    // A lone byte is no frame either.
    sender.write_all(&[0x01]).await.unwrap();
    assert_eq!(
        reader.next_frame().await.unwrap(),
        Some(RtuFrame::Dropped(DroppedFrame::BadCrc))
    );
}

#[tokio::test(start_paused = true)]
async fn a_frame_of_another_function_code_ends_at_the_silence() {
    let (mut reader, mut sender) = line();
    let online = rtu_frame(1, &[100, 0x01, 0x02, 0x03]);
    sender.write_all(&online).await.unwrap();
    let start = tokio::time::Instant::now();
    assert_eq!(
        reader.next_frame().await.unwrap(),
        Some(RtuFrame::Request {
            address: 1,
            pdu: vec![100, 0x01, 0x02, 0x03],
        })
    );
    // tokio's timers tick in whole milliseconds, so the silence may end up to one later.
    let waited = start.elapsed();
    assert!(
        waited >= SILENCE && waited <= SILENCE + Duration::from_millis(1),
        "{waited:?}"
    );
}

#[tokio::test(start_paused = true)]
async fn a_frame_longer_than_256_bytes_is_dropped_whole() {
    let (mut reader, mut sender) = line();
    sender.write_all(&[0x01; 300]).await.unwrap();
    tokio::time::sleep(SILENCE / 2).await;
    // A good frame glued to the long one is part of it.
    sender.write_all(&hex(GOLDEN[0])).await.unwrap();
    assert_eq!(
        reader.next_frame().await.unwrap(),
        Some(RtuFrame::Dropped(DroppedFrame::TooLong))
    );
    sender.write_all(&hex(GOLDEN[0])).await.unwrap();
    assert_eq!(reader.next_frame().await.unwrap(), Some(request(GOLDEN[0])));
}

#[tokio::test(start_paused = true)]
async fn the_end_of_the_port_ends_the_frames() {
    let (mut reader, mut sender) = line();
    sender.write_all(&hex(GOLDEN[2])).await.unwrap();
    drop(sender);
    assert_eq!(reader.next_frame().await.unwrap(), Some(request(GOLDEN[2])));
    assert_eq!(reader.next_frame().await.unwrap(), None);
}

#[tokio::test(start_paused = true)]
async fn a_frame_paused_longer_than_the_silence_but_within_the_patience_is_taken_whole() {
    // A USB adapter's batches: the pause is the adapter's latency timer, not the master's.
    for text in [GOLDEN[0], GOLDEN[3]] {
        let frame = hex(text);
        let (mut reader, mut sender) = line();
        sender.write_all(&frame[..5]).await.unwrap();
        let rest = frame[5..].to_vec();
        tokio::spawn(async move {
            tokio::time::sleep(Duration::from_millis(16)).await;
            sender.write_all(&rest).await.unwrap();
            std::future::pending::<()>().await;
        });
        assert_eq!(reader.next_frame().await.unwrap(), Some(request(text)));
    }
}

#[tokio::test(start_paused = true)]
async fn a_frame_paused_longer_than_the_patience_is_dropped_in_two_parts() {
    let (mut reader, mut sender) = line();
    let frame = hex(GOLDEN[3]);
    sender.write_all(&frame[..5]).await.unwrap();
    let start = tokio::time::Instant::now();
    assert_eq!(
        reader.next_frame().await.unwrap(),
        Some(RtuFrame::Dropped(DroppedFrame::BadCrc))
    );
    // tokio's timers tick in whole milliseconds, so the patience may end up to one later.
    let waited = start.elapsed();
    assert!(
        waited >= INCOMPLETE_FRAME_PATIENCE
            && waited <= INCOMPLETE_FRAME_PATIENCE + Duration::from_millis(1),
        "{waited:?}"
    );
    sender.write_all(&frame[5..]).await.unwrap();
    assert_eq!(
        reader.next_frame().await.unwrap(),
        Some(RtuFrame::Dropped(DroppedFrame::BadCrc))
    );
}

#[tokio::test(start_paused = true)]
async fn leftovers_and_the_next_read_never_make_a_good_frame_too_long() {
    // Function code 16 with 123 registers: a 255-byte frame.
    let mut registers = vec![0x10, 0x00, 0x00, 0x00, 123, 246];
    registers.extend(std::iter::repeat_n(0xAB, 246));
    let long = rtu_frame(1, &registers);
    assert_eq!(long.len(), 255);
    let mut line_bytes = hex(GOLDEN[0]);
    line_bytes.extend(&long);
    line_bytes.extend(&long);
    let (mut reader, mut sender) = line();
    sender.write_all(&line_bytes).await.unwrap();
    let long_request = RtuFrame::Request {
        address: 1,
        pdu: registers,
    };
    assert_eq!(reader.next_frame().await.unwrap(), Some(request(GOLDEN[0])));
    assert_eq!(
        reader.next_frame().await.unwrap(),
        Some(long_request.clone())
    );
    assert_eq!(reader.next_frame().await.unwrap(), Some(long_request));
}

mod chunks {
    use proptest::prelude::*;

    use super::*;

    /// The requests among the golden frames.
    const REQUESTS: [&str; 6] = [
        GOLDEN[0], GOLDEN[2], GOLDEN[3], GOLDEN[5], GOLDEN[7], GOLDEN[10],
    ];

    proptest! {
        #[test]
        fn requests_back_to_back_in_chunks_of_any_size_come_out_whole_and_in_order(
            picks in prop::collection::vec(0..REQUESTS.len(), 1..6),
            chunk_sizes in prop::collection::vec(1usize..12, 1..40),
            pauses_us in prop::collection::vec(0u64..1000, 1..40),
        ) {
            let bytes: Vec<u8> = picks.iter().flat_map(|&pick| hex(REQUESTS[pick])).collect();
            let frames = picks.len();
            let received = tokio::runtime::Builder::new_current_thread()
                .enable_time()
                .start_paused(true)
                .build()
                .unwrap()
                .block_on(async move {
                    let (mut reader, mut sender) = line();
                    tokio::spawn(async move {
                        let mut rest = &bytes[..];
                        let mut step = 0;
                        while !rest.is_empty() {
                            let size = chunk_sizes[step % chunk_sizes.len()].min(rest.len());
                            sender.write_all(&rest[..size]).await.unwrap();
                            rest = &rest[size..];
                            // Pauses shorter than the silence keep a frame together.
                            let pause = pauses_us[step % pauses_us.len()];
                            tokio::time::sleep(Duration::from_micros(pause)).await;
                            step += 1;
                        }
                        std::future::pending::<()>().await;
                    });
                    let mut received = Vec::new();
                    for _ in 0..frames {
                        received.push(reader.next_frame().await.unwrap());
                    }
                    received
                });
            let expected: Vec<Option<RtuFrame>> =
                picks.iter().map(|&pick| Some(request(REQUESTS[pick]))).collect();
            prop_assert_eq!(received, expected);
        }
    }
}
