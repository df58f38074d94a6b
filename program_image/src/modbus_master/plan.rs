//! How a device's channels become requests (`docs/modbus-master.md` §6.2): a pure function, so
//! that the runtime's master and the studio's device editor ("N requests per round") agree.

use std::collections::BTreeMap;

use crate::ModbusTable;

use super::{DeviceDef, Direction, Trigger, request_limit};

/// One Modbus request of a device's round: a function code over a range of one table, serving
/// one or more channels.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlannedRequest {
    /// The function code: 1 to 4 for a read, 5, 6, 15 or 16 for a write.
    pub function_code: u8,
    /// The table it reads or writes.
    pub table: ModbusTable,
    /// Whether it reads or writes.
    pub direction: Direction,
    /// The first coil or register.
    pub start: u16,
    /// How many coils or registers, from `start`; a read's bridged gaps are read and dropped.
    pub quantity: u16,
    /// The channels it serves, by address.
    pub channels: Vec<RequestChannel>,
    /// Cyclic, or the rising edge that makes it pending.
    pub trigger: Trigger,
}

/// A channel served by a request, and where its values lie in the request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RequestChannel {
    /// The channel's index in [`DeviceDef::channels`] (0-based).
    pub channel: usize,
    /// Its first coil or register, counted from the request's `start`.
    pub offset: u16,
}

/// Where a request goes in a round, compared field by field: cyclic writes, rising-edge writes,
/// cyclic reads, rising-edge reads; then by trigger, table and address.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct RoundPlace {
    phase: u8,
    trigger_rank: usize,
    table_rank: u8,
    start: u16,
}

/// The channels that may share requests: one direction, table, function code and trigger.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct GroupKey {
    phase: u8,
    trigger_rank: usize,
    table_rank: u8,
    function_code: u8,
}

/// The requests of a round of `device`, in the order the round sends them.
///
/// Every channel is served by exactly one request. Channels share a request only when they
/// have the same direction, table, function code and trigger (function codes 5 and 6 serve one
/// channel each), lie in address order, and the request stays within one request's limit;
/// a read request may bridge up to `max_read_gap` unused addresses between them, a write none.
/// The device need not be verified: an unverified one never makes this panic, though a channel
/// too large for one request then gets a request of its own beyond the limit.
pub fn plan(device: &DeviceDef) -> Vec<PlannedRequest> {
    let channels = &device.channels;
    // Triggers rank in the order they first appear, whatever the channel's direction; paths
    // are IEC names, so case does not make two triggers different.
    let mut triggers: Vec<&str> = Vec::new();
    for channel in channels {
        if let Trigger::RisingEdge { variable } = &channel.trigger
            && !triggers.iter().any(|t| t.eq_ignore_ascii_case(variable))
        {
            triggers.push(variable);
        }
    }
    let trigger_rank = |trigger: &Trigger| match trigger {
        Trigger::Cyclic => 0,
        Trigger::RisingEdge { variable } => {
            1 + triggers
                .iter()
                .position(|t| t.eq_ignore_ascii_case(variable))
                .unwrap_or(0)
        }
    };
    let mut groups: BTreeMap<GroupKey, Vec<usize>> = BTreeMap::new();
    let mut requests: Vec<(RoundPlace, PlannedRequest)> = Vec::new();
    for (index, channel) in channels.iter().enumerate() {
        let edge = !matches!(channel.trigger, Trigger::Cyclic);
        let phase = match (channel.direction, edge) {
            (Direction::Write, false) => 0,
            (Direction::Write, true) => 1,
            (Direction::Read, false) => 2,
            (Direction::Read, true) => 3,
        };
        let key = GroupKey {
            phase,
            trigger_rank: trigger_rank(&channel.trigger),
            table_rank: table_rank(channel.table),
            function_code: channel.function_code,
        };
        if matches!(channel.function_code, 5 | 6) {
            // Devices that know only the single-write codes exist, so such a channel is never
            // grouped: its request is exactly the channel.
            let request = PlannedRequest {
                function_code: channel.function_code,
                table: channel.table,
                direction: channel.direction,
                start: channel.address,
                quantity: clamp_quantity(channel.span()),
                channels: vec![RequestChannel {
                    channel: index,
                    offset: 0,
                }],
                trigger: channel.trigger.clone(),
            };
            requests.push((place(key, channel.address), request));
        } else {
            groups.entry(key).or_default().push(index);
        }
    }
    for (key, mut members) in groups {
        // Channels of one table never start at the same address, and the index breaks the
        // tie of an unverified device so the plan stays deterministic.
        members.sort_by_key(|&index| (channels[index].address, index));
        let first = &channels[members[0]];
        let (direction, table) = (first.direction, first.table);
        let gap_allowed = match direction {
            Direction::Read => u32::from(device.max_read_gap),
            // A write never touches an address no channel names.
            Direction::Write => 0,
        };
        let limit = request_limit(direction, table);
        let mut current: Option<(u32, u32, Vec<RequestChannel>)> = None;
        for index in members {
            let channel = &channels[index];
            let start = u32::from(channel.address);
            let end = start + channel.span();
            if let Some((request_start, request_end, served)) = &mut current
                && start >= *request_end
                && start - *request_end <= gap_allowed
                && end - *request_start <= limit
            {
                served.push(RequestChannel {
                    channel: index,
                    offset: (start - *request_start) as u16,
                });
                *request_end = end;
                continue;
            }
            if let Some(closed) = current.take() {
                requests.push(close(key, closed, direction, table, &first.trigger));
            }
            current = Some((
                start,
                end,
                vec![RequestChannel {
                    channel: index,
                    offset: 0,
                }],
            ));
        }
        if let Some(closed) = current {
            requests.push(close(key, closed, direction, table, &first.trigger));
        }
    }
    requests.sort_by_key(|(place, _)| *place);
    requests.into_iter().map(|(_, request)| request).collect()
}

/// The request a group's walk closed: from its first channel's address to its last channel's
/// end.
fn close(
    key: GroupKey,
    (start, end, channels): (u32, u32, Vec<RequestChannel>),
    direction: Direction,
    table: ModbusTable,
    trigger: &Trigger,
) -> (RoundPlace, PlannedRequest) {
    // Addresses come from u16 fields, so the start fits one.
    let start = start as u16;
    let request = PlannedRequest {
        function_code: key.function_code,
        table,
        direction,
        start,
        quantity: clamp_quantity(end - u32::from(start)),
        channels,
        trigger: trigger.clone(),
    };
    (place(key, start), request)
}

/// A request's place in the round.
fn place(key: GroupKey, start: u16) -> RoundPlace {
    RoundPlace {
        phase: key.phase,
        trigger_rank: key.trigger_rank,
        table_rank: key.table_rank,
        start,
    }
}

/// The order of tables within a phase: coils, discrete inputs, holding registers, input
/// registers.
fn table_rank(table: ModbusTable) -> u8 {
    match table {
        ModbusTable::Coils => 0,
        ModbusTable::DiscreteInputs => 1,
        ModbusTable::HoldingRegisters => 2,
        ModbusTable::InputRegisters => 3,
    }
}

/// A quantity as the request carries it; only an unverified channel exceeds a u16.
fn clamp_quantity(quantity: u32) -> u16 {
    u16::try_from(quantity).unwrap_or(u16::MAX)
}
