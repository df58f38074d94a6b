//! The request plan: the example of `docs/modbus-master.md` §6.2, single writes, triggers,
//! limits, and a property test over random valid channel sets.

use proptest::prelude::*;

use super::*;
use crate::{Elementary, ModbusTable};

/// A cyclic channel of `count` values of `value_type` at `address`, with the default function
/// code of its table and direction.
fn channel(
    table: ModbusTable,
    address: u16,
    value_type: Elementary,
    count: u16,
    direction: Direction,
) -> ChannelDef {
    let function_code = match (direction, table) {
        (Read, Coils) => 1,
        (Read, DiscreteInputs) => 2,
        (Read, HoldingRegisters) => 3,
        (Read, InputRegisters) => 4,
        (Write, Coils) => 15,
        (Write, _) => 16,
    };
    ChannelDef {
        variable: format!("GVL.v{address}"),
        table,
        address,
        value_type,
        count,
        direction,
        function_code,
        trigger: Trigger::Cyclic,
        on_error: OnError::KeepLastValue,
        error_flag: None,
    }
}

/// A TCP device of these channels.
fn device(max_read_gap: u16, channels: Vec<ChannelDef>) -> DeviceDef {
    DeviceDef {
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
        max_read_gap,
        status: None,
        channels,
    }
}

/// Each request as (function code, start, quantity, channel indices), for compact checks.
fn summary(requests: &[PlannedRequest]) -> Vec<(u8, u16, u16, Vec<usize>)> {
    requests
        .iter()
        .map(|request| {
            let channels = request.channels.iter().map(|c| c.channel).collect();
            (
                request.function_code,
                request.start,
                request.quantity,
                channels,
            )
        })
        .collect()
}

use Direction::{Read, Write};
use ModbusTable::{Coils, DiscreteInputs, HoldingRegisters, InputRegisters};

#[test]
fn the_specification_example_groups_reads_by_the_allowed_gap() {
    let channels = vec![
        channel(InputRegisters, 0, Elementary::Real, 1, Read),
        channel(InputRegisters, 2, Elementary::Int, 1, Read),
        channel(InputRegisters, 10, Elementary::Dint, 1, Read),
        channel(HoldingRegisters, 5, Elementary::Int, 1, Write),
    ];
    assert_eq!(
        summary(&plan(&device(0, channels.clone()))),
        [
            (16, 5, 1, vec![3]),
            (4, 0, 3, vec![0, 1]),
            (4, 10, 2, vec![2])
        ]
    );
    let wide = plan(&device(7, channels));
    assert_eq!(
        summary(&wide),
        [(16, 5, 1, vec![3]), (4, 0, 12, vec![0, 1, 2])]
    );
    let offsets: Vec<u16> = wide[1].channels.iter().map(|c| c.offset).collect();
    assert_eq!(offsets, [0, 2, 10]);
}

#[test]
fn writes_never_bridge_a_gap_and_single_write_codes_stand_alone() {
    let mut single = channel(HoldingRegisters, 2, Elementary::Int, 1, Write);
    single.function_code = 6;
    let channels = vec![
        channel(HoldingRegisters, 0, Elementary::Int, 2, Write),
        single,
        channel(HoldingRegisters, 3, Elementary::Int, 1, Write),
        channel(HoldingRegisters, 5, Elementary::Int, 1, Write),
    ];
    // Holding register 2 is written by function code 6, so 0–1 and 3 are not neighbours.
    assert_eq!(
        summary(&plan(&device(125, channels))),
        [
            (16, 0, 2, vec![0]),
            (6, 2, 1, vec![1]),
            (16, 3, 1, vec![2]),
            (16, 5, 1, vec![3])
        ]
    );
}

#[test]
fn a_round_orders_writes_edges_and_tables_as_specified() {
    let edge = |mut channel: ChannelDef, variable: &str| {
        channel.trigger = Trigger::RisingEdge {
            variable: variable.to_owned(),
        };
        channel
    };
    let channels = vec![
        channel(InputRegisters, 0, Elementary::Int, 1, Read),
        edge(channel(Coils, 9, Elementary::Bool, 1, Read), "GVL.xB"),
        channel(HoldingRegisters, 0, Elementary::Int, 1, Read),
        edge(
            channel(HoldingRegisters, 20, Elementary::Int, 1, Write),
            "GVL.xA",
        ),
        channel(DiscreteInputs, 0, Elementary::Bool, 1, Read),
        channel(HoldingRegisters, 10, Elementary::Int, 1, Write),
        edge(channel(Coils, 30, Elementary::Bool, 1, Write), "gvl.xb"),
        channel(Coils, 0, Elementary::Bool, 1, Read),
        channel(Coils, 40, Elementary::Bool, 1, Write),
    ];
    let requests = plan(&device(0, channels));
    // Cyclic writes (coils, then holding registers), edge writes by the trigger that appears
    // first (GVL.xB, written gvl.xb too, before GVL.xA), cyclic reads by table, edge reads.
    assert_eq!(
        summary(&requests)
            .into_iter()
            .map(|(_, _, _, channels)| channels[0])
            .collect::<Vec<_>>(),
        [8, 5, 6, 3, 7, 4, 2, 0, 1]
    );
    assert_eq!(
        requests[2].trigger,
        Trigger::RisingEdge {
            variable: "gvl.xb".to_owned()
        }
    );
}

#[test]
fn a_request_closes_at_the_limit_of_one_request() {
    // 130 INTs one after another: 125 fit one read, the rest go into a second.
    let reads: Vec<ChannelDef> = (0..130)
        .map(|address| channel(InputRegisters, address, Elementary::Int, 1, Read))
        .collect();
    let requests = plan(&device(0, reads));
    assert_eq!(
        requests
            .iter()
            .map(|r| (r.start, r.quantity))
            .collect::<Vec<_>>(),
        [(0, 125), (125, 5)]
    );
    // Writes stop at 123 registers: three INTs after 30 LREALs just fit, a 31st LREAL starts
    // the next request.
    let lreals: Vec<ChannelDef> = (0..30)
        .map(|n| channel(HoldingRegisters, n * 4, Elementary::Lreal, 1, Write))
        .collect();
    let mut writes = lreals.clone();
    writes.push(channel(HoldingRegisters, 120, Elementary::Int, 3, Write));
    let requests = plan(&device(0, writes));
    assert_eq!(
        requests
            .iter()
            .map(|r| (r.start, r.quantity))
            .collect::<Vec<_>>(),
        [(0, 123)]
    );
    let mut writes = lreals;
    writes.push(channel(HoldingRegisters, 120, Elementary::Lreal, 1, Write));
    let requests = plan(&device(0, writes));
    assert_eq!(
        requests
            .iter()
            .map(|r| (r.start, r.quantity))
            .collect::<Vec<_>>(),
        [(0, 120), (120, 4)]
    );
    let mut coils = vec![
        channel(Coils, 0, Elementary::Bool, 1968, Write),
        channel(Coils, 1968, Elementary::Bool, 1, Write),
        channel(Coils, 0, Elementary::Bool, 2000, Read),
    ];
    // The read channel lives in its own table range (discrete inputs) so nothing overlaps.
    coils[2].table = DiscreteInputs;
    coils[2].function_code = 2;
    assert_eq!(
        summary(&plan(&device(0, coils))),
        [
            (15, 0, 1968, vec![0]),
            (15, 1968, 1, vec![1]),
            (2, 0, 2000, vec![2])
        ]
    );
}

#[test]
fn an_unverified_device_is_planned_without_panicking() {
    // Overlapping channels, a channel past one request and a write on an input register: the
    // studio may plan a device it has not checked.
    let channels = vec![
        channel(HoldingRegisters, 0, Elementary::Lreal, 2000, Read),
        channel(HoldingRegisters, 2, Elementary::Int, 1, Read),
        channel(InputRegisters, 65535, Elementary::Lreal, 65535, Write),
    ];
    let requests = plan(&device(125, channels));
    let mut served: Vec<usize> = requests
        .iter()
        .flat_map(|r| r.channels.iter().map(|c| c.channel))
        .collect();
    served.sort_unstable();
    assert_eq!(served, [0, 1, 2]);
    assert!(requests.iter().all(|r| r.quantity >= 1));
}

/// One channel's random choices: table, unused addresses before it, register type, count,
/// whether it writes, whether it uses a single-write code, its trigger (0 cyclic, else the
/// number of one of three BOOLs), whether its trigger path is spelt in another case, and
/// whether a read sets its variable to zero on error.
type ChannelSpec = (
    ModbusTable,
    u16,
    Elementary,
    u16,
    bool,
    bool,
    usize,
    bool,
    bool,
);

/// The choices of one channel on one of `tables`, with the unused addresses before it, its
/// count, whether it writes and its trigger drawn from the strategies given.
fn channel_specs(
    tables: Vec<ModbusTable>,
    gaps: BoxedStrategy<u16>,
    counts: BoxedStrategy<u16>,
    writes: BoxedStrategy<bool>,
    triggers: BoxedStrategy<usize>,
) -> impl Strategy<Value = ChannelSpec> {
    (
        prop::sample::select(tables),
        gaps,
        prop::sample::select(vec![
            Elementary::Int,
            Elementary::Uint,
            Elementary::Dint,
            Elementary::Real,
            Elementary::Lint,
            Elementary::Lreal,
        ]),
        counts,
        writes,
        any::<bool>(),
        triggers,
        any::<bool>(),
        any::<bool>(),
    )
}

/// A valid channel set: per table, channels laid out one after another with random gaps, then
/// shuffled; each channel with a random type, count, direction the table allows, function code,
/// `on_error` and one of a few triggers, whose paths may differ only in case.
fn channel_sets_of(
    specs: impl Strategy<Value = ChannelSpec>,
) -> impl Strategy<Value = (u16, Vec<ChannelDef>)> {
    (
        0u16..12,
        prop::collection::vec(specs, 0..60),
        any::<proptest::sample::Index>(),
    )
        .prop_map(|(gap, specs, shuffle)| {
            let mut next = [0u32; 4];
            let mut channels = Vec::new();
            for spec in specs {
                let (table, gap_before, register_type, count, write, single, trigger, upper, zero) =
                    spec;
                let bits = table_holds_bits(table);
                let value_type = if bits {
                    Elementary::Bool
                } else {
                    register_type
                };
                let direction = if write && matches!(table, Coils | HoldingRegisters) {
                    Write
                } else {
                    Read
                };
                let mut channel = channel(table, 0, value_type, count, direction);
                if direction == Write && single && channel.span() == 1 {
                    channel.function_code = if bits { 5 } else { 6 };
                }
                if direction == Read && zero {
                    channel.on_error = OnError::SetToZero;
                }
                if trigger > 0 {
                    // IEC names ignore case, so GVL.xTrigger1 and gvl.XTRIGGER1 are one BOOL.
                    let path = format!("GVL.xTrigger{trigger}");
                    channel.trigger = Trigger::RisingEdge {
                        variable: if upper { path.to_uppercase() } else { path },
                    };
                }
                if channel.span() > request_limit(direction, table) {
                    continue;
                }
                let slot = &mut next[table as usize];
                let address = *slot + u32::from(gap_before);
                if address + channel.span() > 65_536 {
                    continue;
                }
                channel.address = address as u16;
                *slot = address + channel.span();
                channels.push(channel);
            }
            // A deterministic shuffle: the project's order is not the address order.
            if !channels.is_empty() {
                let turn = shuffle.index(channels.len());
                channels.rotate_left(turn);
                channels.reverse();
            }
            (gap, channels)
        })
}

/// Channel sets over all four tables, mostly of a few values each, in both directions and
/// with four triggers.
fn mixed_channel_sets() -> impl Strategy<Value = (u16, Vec<ChannelDef>)> {
    channel_sets_of(channel_specs(
        vec![Coils, DiscreteInputs, HoldingRegisters, InputRegisters],
        (0u16..6).boxed(),
        prop_oneof![4 => 1u16..4, 1 => 1u16..40].boxed(),
        any::<bool>().boxed(),
        (0usize..4).boxed(),
    ))
}

/// Channel sets of coils and discrete inputs of up to 500 bits each, mostly cyclic, adjacent
/// and of one direction (reads only, or mostly writes), so that runs of one group are long
/// enough for requests to close at the limits of 2000 bits read and 1968 written.
fn bit_heavy_channel_sets() -> impl Strategy<Value = (u16, Vec<ChannelDef>)> {
    let bit_specs = |tables: Vec<ModbusTable>, writes: BoxedStrategy<bool>| {
        channel_specs(
            tables,
            prop_oneof![3 => Just(0u16), 1 => 0u16..6].boxed(),
            prop_oneof![1 => 1u16..4, 3 => 1u16..500].boxed(),
            writes,
            prop_oneof![15 => Just(0usize), 1 => 1usize..4].boxed(),
        )
    };
    prop_oneof![
        channel_sets_of(bit_specs(vec![Coils, DiscreteInputs], Just(false).boxed())),
        channel_sets_of(bit_specs(
            vec![Coils],
            prop_oneof![9 => Just(true), 1 => Just(false)].boxed()
        )),
    ]
}

/// What makes requests one group: direction, table, function code and trigger (without case).
type RequestGroup = (Direction, ModbusTable, u8, Option<String>);

/// The trigger's BOOL without case, so that triggers spelt differently compare as one.
fn trigger_key(trigger: &Trigger) -> Option<String> {
    match trigger {
        Trigger::Cyclic => None,
        Trigger::RisingEdge { variable } => Some(variable.to_ascii_lowercase()),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn every_channel_is_served_once_within_the_limits_in_round_order(
        (gap, channels) in prop_oneof![mixed_channel_sets(), bit_heavy_channel_sets()]
    ) {
        let device = device(gap, channels.clone());
        // The sets are valid ones: the verifier accepts them as they are planned.
        let section = MasterSection {
            serial_ports: Vec::new(),
            devices: vec![device.clone()],
        };
        prop_assert_eq!(section.verify(1), Ok(()));
        let requests = plan(&device);
        let mut served = vec![0; channels.len()];
        let mut places = Vec::new();
        for request in &requests {
            let first = &channels[request.channels[0].channel];
            let limit = request_limit(request.direction, request.table);
            prop_assert!(u32::from(request.quantity) <= limit);
            prop_assert_eq!(request.start, first.address);
            let mut end = u32::from(request.start);
            for served_channel in &request.channels {
                let channel = &channels[served_channel.channel];
                served[served_channel.channel] += 1;
                // A request holds one direction, table, function code and trigger (its BOOL
                // whatever the case of its path).
                prop_assert_eq!(channel.direction, request.direction);
                prop_assert_eq!(channel.table, request.table);
                prop_assert_eq!(channel.function_code, request.function_code);
                prop_assert_eq!(trigger_key(&channel.trigger), trigger_key(&request.trigger));
                prop_assert_eq!(
                    u32::from(channel.address),
                    u32::from(request.start) + u32::from(served_channel.offset)
                );
                let start = u32::from(channel.address);
                prop_assert!(start >= end, "channels of a request are in address order");
                let allowed = match request.direction {
                    Read => u32::from(gap),
                    Write => 0,
                };
                if start != u32::from(request.start) {
                    prop_assert!(start - end <= allowed, "a gap of {} in {:?}", start - end, request);
                }
                end = start + channel.span();
            }
            prop_assert_eq!(end, u32::from(request.start) + u32::from(request.quantity));
            if matches!(request.function_code, 5 | 6) {
                prop_assert_eq!(request.channels.len(), 1);
                prop_assert_eq!(request.quantity, 1);
            }
            let phase = match (request.direction, &request.trigger) {
                (Write, Trigger::Cyclic) => 0,
                (Write, _) => 1,
                (Read, Trigger::Cyclic) => 2,
                (Read, _) => 3,
            };
            let trigger_rank = match trigger_key(&request.trigger) {
                None => 0,
                Some(key) => 1 + channels
                    .iter()
                    .position(|c| trigger_key(&c.trigger).as_ref() == Some(&key))
                    .unwrap_or(usize::MAX - 1),
            };
            let table_rank = match request.table {
                Coils => 0,
                DiscreteInputs => 1,
                HoldingRegisters => 2,
                InputRegisters => 3,
            };
            places.push((phase, trigger_rank, table_rank, request.start));
        }
        prop_assert!(served.iter().all(|&count| count == 1), "served {:?}", served);
        prop_assert!(places.windows(2).all(|pair| pair[0] <= pair[1]), "order {:?}", places);
        // Greedy: a request of a group starts only because its first channel could not have
        // joined the group's request before it. That request need not be the round's previous
        // one: a single write of the same table may lie between them.
        let mut last_of_group: Vec<(RequestGroup, &PlannedRequest)> = Vec::new();
        for after in requests.iter().filter(|r| !matches!(r.function_code, 5 | 6)) {
            let key = (
                after.direction,
                after.table,
                after.function_code,
                trigger_key(&after.trigger),
            );
            let previous = last_of_group.iter().position(|(group, _)| *group == key);
            if let Some(at) = previous {
                let before = last_of_group[at].1;
                let first = &channels[after.channels[0].channel];
                let end = u32::from(before.start) + u32::from(before.quantity);
                let address = u32::from(first.address);
                prop_assert!(address >= end, "{:?} starts inside {:?}", after, before);
                let allowed = match after.direction {
                    Read => u32::from(gap),
                    Write => 0,
                };
                let too_far = address - end > allowed;
                let too_long = address + first.span() - u32::from(before.start)
                    > request_limit(after.direction, after.table);
                prop_assert!(too_far || too_long, "{:?} could have joined {:?}", after, before);
                last_of_group[at].1 = after;
            } else {
                last_of_group.push((key, after));
            }
        }
    }
}
