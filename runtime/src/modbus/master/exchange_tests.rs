//! The exchange between the master and the scheduler: never torn, a skipped `try_lock` is one
//! cycle late, edges are latched until handed over (`docs/modbus-master.md` §6.4, §10 item 6).

use std::sync::Arc;

use program_image::modbus_master::{
    ChannelDef, DeviceDef, Direction, Link, OnError, Schedule, Trigger, WordOrder,
};
use program_image::{Elementary, ModbusTable, Region};
use proptest::prelude::*;

use super::super::copier::{DeviceCopier, ProgramMemory};
use super::super::resolve::{BytePlace, ChannelPlaces, DevicePlaces};
use super::*;

/// How many INT values the read channel has.
const READ_VALUES: usize = 16;
/// Where the read channel's array starts in the data region.
const READ_AT: usize = 0;
/// The cyclic write channel's INT.
const WRITE_AT: usize = 40;
/// The rising-edge write channel's INT.
const EDGE_AT: usize = 42;
/// The trigger BOOL.
const TRIGGER_AT: usize = 44;
/// The status variable.
const STATUS_AT: usize = 48;

struct Data(Vec<u8>);

impl ProgramMemory for Data {
    fn bytes(&self, _region: Region) -> &[u8] {
        &self.0
    }
    fn bytes_mut(&mut self, _region: Region) -> &mut [u8] {
        &mut self.0
    }
}

fn channel(direction: Direction, address: u16, count: u16, trigger: Trigger) -> ChannelDef {
    ChannelDef {
        variable: format!("GVL.v{address}"),
        table: ModbusTable::HoldingRegisters,
        address,
        value_type: Elementary::Int,
        count,
        direction,
        function_code: if direction == Direction::Read { 3 } else { 16 },
        trigger,
        on_error: OnError::KeepLastValue,
        error_flag: None,
    }
}

fn place(offset: usize, bytes: usize) -> BytePlace {
    BytePlace {
        region: Region::Data,
        offset,
        bytes,
        bit: None,
    }
}

fn device() -> (Arc<DeviceExchange>, DeviceCopier) {
    let edge = Trigger::RisingEdge {
        variable: "GVL.xSend".to_owned(),
    };
    let device = DeviceDef {
        name: "Drive".to_owned(),
        link: Link::Tcp {
            host: "127.0.0.1".to_owned(),
            port: 502,
        },
        unit_id: 1,
        timeout_ms: 100,
        task: 0,
        schedule: Schedule::EveryCycle,
        word_order: WordOrder::HighFirst,
        max_read_gap: 0,
        status: Some("GVL.status".to_owned()),
        channels: vec![
            channel(Direction::Read, 0, READ_VALUES as u16, Trigger::Cyclic),
            channel(Direction::Write, 100, 1, Trigger::Cyclic),
            channel(Direction::Write, 200, 1, edge),
        ],
    };
    let exchange = Arc::new(DeviceExchange::new(&device));
    let places = DevicePlaces {
        task: 0,
        channels: vec![
            ChannelPlaces {
                variable: place(READ_AT, 2 * READ_VALUES),
                direction: Direction::Read,
                error_flag: None,
            },
            ChannelPlaces {
                variable: place(WRITE_AT, 2),
                direction: Direction::Write,
                error_flag: None,
            },
            ChannelPlaces {
                variable: place(EDGE_AT, 2),
                direction: Direction::Write,
                error_flag: None,
            },
        ],
        triggers: vec![place(TRIGGER_AT, 1)],
        status: Some(place(STATUS_AT, STATUS_BYTES)),
    };
    let copier = DeviceCopier::new(Arc::clone(&exchange), places);
    (exchange, copier)
}

/// A round whose every value, and its status's round counter, is the round's number.
fn round(exchange: &DeviceExchange, number: u64) -> InputImage {
    let mut image = InputImage::empty(&exchange.layout);
    image.round = number;
    for value in exchange
        .layout
        .slice_mut(&mut image.values, 0)
        .chunks_mut(2)
    {
        value.copy_from_slice(&(number as i16).to_le_bytes());
    }
    image.deliver[0] = true;
    image.status[16..20].copy_from_slice(&(number as u32).to_le_bytes());
    image
}

/// The round numbers the program's memory shows: every value of the channel and the status.
fn seen(data: &Data) -> Vec<i64> {
    let mut numbers: Vec<i64> = data.0[READ_AT..READ_AT + 2 * READ_VALUES]
        .chunks(2)
        .map(|value| i64::from(i16::from_le_bytes([value[0], value[1]])))
        .collect();
    let status = &data.0[STATUS_AT + 16..STATUS_AT + 20];
    numbers.push(i64::from(u32::from_le_bytes([
        status[0], status[1], status[2], status[3],
    ])));
    numbers
}

#[derive(Clone, Debug)]
enum Step {
    /// The master publishes the next round.
    Publish,
    /// A cycle starts, with the input image held by the master or not.
    CycleStart { held: bool },
    /// A cycle ends with the trigger at `trigger` and the edge channel's variable at `value`,
    /// with the output image held by the master or not.
    CycleEnd {
        trigger: bool,
        value: i16,
        held: bool,
    },
    /// The master takes the outputs.
    Take,
}

fn step() -> impl Strategy<Value = Step> {
    prop_oneof![
        Just(Step::Publish),
        any::<bool>().prop_map(|held| Step::CycleStart { held }),
        (any::<bool>(), any::<i16>(), any::<bool>()).prop_map(|(trigger, value, held)| {
            Step::CycleEnd {
                trigger,
                value,
                held,
            }
        }),
        Just(Step::Take),
    ]
}

proptest! {
    #[test]
    fn rounds_are_never_torn_late_by_one_cycle_at_most_and_edges_are_latched(
        steps in proptest::collection::vec(step(), 1..80)
    ) {
        let (exchange, mut copier) = device();
        let mut data = Data(vec![0; 96]);
        let mut published = 0u64;
        // What the model expects.
        let mut taken = 0u64;
        let mut trigger_was = false;
        let mut latched: Option<i16> = None;
        let mut pending: Option<i16> = None;
        for step in steps {
            match step {
                Step::Publish => {
                    published += 1;
                    exchange.publish_round(&round(&exchange, published));
                }
                Step::CycleStart { held } => {
                    let guard = held.then(|| exchange.input.lock());
                    let free = copier.cycle_start(&mut data);
                    drop(guard);
                    prop_assert_eq!(free, !held);
                    if !held {
                        taken = published;
                    }
                    let numbers = seen(&data);
                    // One round, never parts of two; before the first, the initial zeros.
                    prop_assert!(numbers.iter().all(|n| *n == numbers[0]), "torn: {:?}", numbers);
                    prop_assert_eq!(numbers[0], (taken as i16) as i64);
                }
                Step::CycleEnd { trigger, value, held } => {
                    data.0[EDGE_AT..EDGE_AT + 2].copy_from_slice(&value.to_le_bytes());
                    data.0[WRITE_AT..WRITE_AT + 2].copy_from_slice(&value.to_le_bytes());
                    data.0[TRIGGER_AT] = u8::from(trigger);
                    let ends = exchange.cycle_ends();
                    let guard = held.then(|| exchange.output.lock());
                    let free = copier.cycle_end(&data);
                    drop(guard);
                    prop_assert_eq!(free, !held);
                    prop_assert_eq!(exchange.cycle_ends(), ends + 1);
                    if trigger && !trigger_was {
                        latched = Some(value);
                    }
                    trigger_was = trigger;
                    if !held && let Some(value) = latched.take() {
                        pending = Some(value);
                    }
                }
                Step::Take => {
                    let mut values = vec![0; exchange.layout.total];
                    let mut edge_values = vec![0; exchange.layout.total];
                    let mut flags = vec![false];
                    exchange.take_outputs(&mut values, &mut edge_values, &mut flags);
                    match pending.take() {
                        Some(value) => {
                            prop_assert!(flags[0]);
                            prop_assert_eq!(
                                exchange.layout.slice(&edge_values, 2),
                                &value.to_le_bytes()[..]
                            );
                        }
                        None => prop_assert!(!flags[0]),
                    }
                }
            }
        }
    }
}

#[test]
fn a_round_published_while_the_scheduler_copies_is_never_torn() {
    let (exchange, mut copier) = device();
    let publisher = {
        let exchange = Arc::clone(&exchange);
        std::thread::spawn(move || {
            for number in 1..=2000 {
                exchange.publish_round(&round(&exchange, number));
            }
        })
    };
    let mut data = Data(vec![0; 96]);
    let mut last = 0;
    while copier.kept_round() < 2000 {
        copier.cycle_start(&mut data);
        let numbers = seen(&data);
        assert!(
            numbers.iter().all(|n| *n == numbers[0]),
            "torn: {numbers:?}"
        );
        // Rounds only move forward.
        let number = copier.kept_round();
        assert!(number >= last);
        last = number;
    }
    assert!(publisher.join().is_ok());
}

#[test]
fn before_the_first_round_only_the_status_is_copied_and_says_not_yet_polled() {
    let (exchange, mut copier) = device();
    let mut data = Data(vec![0x55; 96]);
    assert!(copier.cycle_start(&mut data));
    // The channel's variable keeps its initial value.
    assert!(
        data.0[READ_AT..READ_AT + 2 * READ_VALUES]
            .iter()
            .all(|byte| *byte == 0x55)
    );
    let status = &data.0[STATUS_AT..STATUS_AT + STATUS_BYTES];
    assert_eq!(
        (status[0], status[1], status[2]),
        (0, 0, super::super::status::error_codes::NOT_YET_POLLED)
    );
    assert!(status[4..].iter().all(|byte| *byte == 0));
    exchange.publish_round(&round(&exchange, 1));
    copier.cycle_start(&mut data);
    assert_eq!(seen(&data), vec![1; READ_VALUES + 1]);
}

#[test]
fn an_edge_latched_at_a_stop_is_forgotten_and_not_sent_after_the_restart() {
    let (exchange, mut copier) = device();
    let mut data = Data(vec![0; 96]);
    exchange.set_running(true);
    // The last cycle before the stop sees an edge while the master holds the output image:
    // the copier latches it.
    data.0[TRIGGER_AT] = 1;
    let guard = exchange.output.lock();
    assert!(!copier.cycle_end(&data));
    drop(guard);
    // The stop forgets it, so the first cycle of the next run hands over no edge of the last.
    copier.forget_edges();
    exchange.set_running(false);
    exchange.set_running(true);
    assert!(copier.cycle_end(&data));
    let mut values = vec![0; exchange.layout.total];
    let mut edge_values = vec![0; exchange.layout.total];
    let mut pending = vec![false];
    assert!(exchange.take_outputs(&mut values, &mut edge_values, &mut pending));
    assert_eq!(pending, [false]);
}
