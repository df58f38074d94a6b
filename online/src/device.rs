//! Generic Modbus TCP devices: a third-party server's coils and registers read and written as
//! typed values, so they can be monitored, written, forced (re-written every poll) and traced
//! (sampled at every poll) without downloading anything.

use std::collections::BTreeMap;
use std::net::SocketAddr;
use std::time::{Duration, Instant};

use program_image::Elementary;
use tokio_modbus::client::{Context, Reader as _, Writer as _};
use tokio_modbus::prelude::SlaveContext as _;

use crate::error::OnlineError;

/// A Modbus table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Table {
    /// Read-write bits.
    Coils,
    /// Read-only bits.
    DiscreteInputs,
    /// Read-write registers.
    HoldingRegisters,
    /// Read-only registers.
    InputRegisters,
}

/// How a value wider than one register is laid out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WordOrder {
    /// The most significant word first ("ABCD").
    HighFirst,
    /// The least significant word first ("CDAB").
    LowFirst,
}

/// One channel bound to a variable.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Channel {
    /// The variable's path, for people.
    pub name: String,
    /// The table.
    pub table: Table,
    /// The zero-based address of the first coil or register.
    pub address: u16,
    /// The value's type: BOOL for bits; INT, UINT, DINT, UDINT, LINT, ULINT, REAL or LREAL for
    /// registers (1, 2 or 4 of them).
    pub ty: Elementary,
}

impl Channel {
    /// Coils or registers the value takes.
    pub fn width(&self) -> u16 {
        if self.table.holds_bits() {
            1
        } else {
            (self.ty.size_bytes() / 2).max(1) as u16
        }
    }
}

impl Table {
    fn holds_bits(self) -> bool {
        matches!(self, Self::Coils | Self::DiscreteInputs)
    }

    fn writable(self) -> bool {
        matches!(self, Self::Coils | Self::HoldingRegisters)
    }
}

/// One poll of every channel: their values as little-endian bytes of their types.
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceSnapshot {
    /// When the poll ended, since the device was connected.
    pub time: Duration,
    /// Each channel's value, in channel order.
    pub values: Vec<Vec<u8>>,
}

/// A connection to a third-party Modbus TCP server.
pub struct Device {
    address: SocketAddr,
    context: Context,
    timeout: Duration,
    order: WordOrder,
    channels: Vec<Channel>,
    forces: BTreeMap<usize, Vec<u8>>,
    started: Instant,
}

impl Device {
    /// Connects to `address` as unit `unit` with these channels.
    pub async fn connect(
        address: SocketAddr,
        unit: u8,
        order: WordOrder,
        timeout: Duration,
        channels: Vec<Channel>,
    ) -> Result<Self, OnlineError> {
        let mut context = match tokio::time::timeout(
            timeout,
            tokio_modbus::client::tcp::connect(address),
        )
        .await
        {
            Err(_) => return Err(OnlineError::Timeout(address, timeout.as_millis() as u64)),
            Ok(Err(error)) if error.kind() == std::io::ErrorKind::ConnectionRefused => {
                return Err(OnlineError::Refused(address));
            }
            Ok(Err(error)) => return Err(OnlineError::Io(address, error)),
            Ok(Ok(context)) => context,
        };
        context.set_slave(tokio_modbus::Slave(unit));
        for channel in &channels {
            let fits = if channel.table.holds_bits() {
                channel.ty == Elementary::Bool
            } else {
                matches!(channel.ty.size_bytes(), 2 | 4 | 8) && channel.ty != Elementary::Bool
            };
            if !fits {
                return Err(OnlineError::Rejected(format!(
                    "{}: a {:?} channel cannot hold a {}",
                    channel.name,
                    channel.table,
                    channel.ty.name()
                )));
            }
        }
        Ok(Self {
            address,
            context,
            timeout,
            order,
            channels,
            forces: BTreeMap::new(),
            started: Instant::now(),
        })
    }

    /// The channels.
    pub fn channels(&self) -> &[Channel] {
        &self.channels
    }

    fn io<T>(
        &self,
        result: Result<tokio_modbus::Result<T>, tokio::time::error::Elapsed>,
    ) -> Result<T, OnlineError> {
        match result {
            Err(_) => Err(OnlineError::Timeout(
                self.address,
                self.timeout.as_millis() as u64,
            )),
            Ok(Err(error)) => Err(OnlineError::Io(
                self.address,
                std::io::Error::other(error.to_string()),
            )),
            Ok(Ok(Err(exception))) => Err(OnlineError::Exception(format!("{exception:?}"))),
            Ok(Ok(Ok(value))) => Ok(value),
        }
    }

    /// Reads every channel: contiguous addresses of one table in one request, forces
    /// re-written first so they hold.
    pub async fn poll(&mut self) -> Result<DeviceSnapshot, OnlineError> {
        let forces: Vec<(usize, Vec<u8>)> =
            self.forces.iter().map(|(i, v)| (*i, v.clone())).collect();
        for (index, value) in forces {
            self.write_channel(index, &value).await?;
        }
        let mut values = vec![Vec::new(); self.channels.len()];
        for (table, start, count, members) in self.spans() {
            let timeout = self.timeout;
            if table.holds_bits() {
                let result = match table {
                    Table::Coils => {
                        tokio::time::timeout(timeout, self.context.read_coils(start, count)).await
                    }
                    _ => {
                        tokio::time::timeout(
                            timeout,
                            self.context.read_discrete_inputs(start, count),
                        )
                        .await
                    }
                };
                let bits = self.io(result)?;
                for index in members {
                    let at = usize::from(self.channels[index].address - start);
                    values[index] = vec![u8::from(bits.get(at).copied().unwrap_or(false))];
                }
            } else {
                let result = match table {
                    Table::HoldingRegisters => {
                        tokio::time::timeout(
                            timeout,
                            self.context.read_holding_registers(start, count),
                        )
                        .await
                    }
                    _ => {
                        tokio::time::timeout(
                            timeout,
                            self.context.read_input_registers(start, count),
                        )
                        .await
                    }
                };
                let words = self.io(result)?;
                for index in members {
                    let channel = &self.channels[index];
                    let at = usize::from(channel.address - start);
                    let width = usize::from(channel.width());
                    let registers = words.get(at..at + width).unwrap_or_default();
                    values[index] = bytes_of_registers(registers, self.order);
                }
            }
        }
        Ok(DeviceSnapshot {
            time: self.started.elapsed(),
            values,
        })
    }

    /// Runs of channels that one request reads: (table, first address, count, channel indices).
    fn spans(&self) -> Vec<(Table, u16, u16, Vec<usize>)> {
        let mut order: Vec<usize> = (0..self.channels.len()).collect();
        order.sort_by_key(|&i| (self.channels[i].table, self.channels[i].address));
        let mut spans: Vec<(Table, u16, u16, Vec<usize>)> = Vec::new();
        for index in order {
            let channel = &self.channels[index];
            let end = channel.address.saturating_add(channel.width());
            let limit = if channel.table.holds_bits() {
                2000
            } else {
                125
            };
            match spans.last_mut() {
                Some((table, start, count, members))
                    if *table == channel.table
                        && channel.address <= *start + *count
                        && end - *start <= limit =>
                {
                    *count = (*count).max(end - *start);
                    members.push(index);
                }
                _ => spans.push((channel.table, channel.address, channel.width(), vec![index])),
            }
        }
        spans
    }

    async fn write_channel(&mut self, index: usize, value: &[u8]) -> Result<(), OnlineError> {
        let channel = self
            .channels
            .get(index)
            .cloned()
            .ok_or_else(|| OnlineError::Rejected("no such channel".to_owned()))?;
        if !channel.table.writable() {
            return Err(OnlineError::Rejected(format!(
                "{}: {:?} cannot be written",
                channel.name, channel.table
            )));
        }
        let timeout = self.timeout;
        if channel.table.holds_bits() {
            let on = value.first().is_some_and(|b| *b != 0);
            let result =
                tokio::time::timeout(timeout, self.context.write_single_coil(channel.address, on))
                    .await;
            return self.io(result);
        }
        let registers = registers_of_bytes(value, usize::from(channel.width()), self.order);
        let result = tokio::time::timeout(
            timeout,
            self.context
                .write_multiple_registers(channel.address, &registers),
        )
        .await;
        self.io(result)
    }

    /// Writes one channel's value (little-endian bytes of its type) once.
    pub async fn write(&mut self, index: usize, value: &[u8]) -> Result<(), OnlineError> {
        self.write_channel(index, value).await
    }

    /// Forces a channel: its value is written now and again before every poll.
    pub async fn force(&mut self, index: usize, value: Vec<u8>) -> Result<(), OnlineError> {
        self.write_channel(index, &value).await?;
        self.forces.insert(index, value);
        Ok(())
    }

    /// Releases a channel's force, or every force with `None`.
    pub fn unforce(&mut self, index: Option<usize>) {
        match index {
            Some(index) => {
                self.forces.remove(&index);
            }
            None => self.forces.clear(),
        }
    }

    /// The forced channels and their values.
    pub fn forces(&self) -> Vec<(usize, Vec<u8>)> {
        self.forces.iter().map(|(i, v)| (*i, v.clone())).collect()
    }

    /// Polls `samples` times, `interval` apart, and returns every snapshot with its time: a
    /// trace of a device, sampled by polling.
    pub async fn trace(
        &mut self,
        samples: usize,
        interval: Duration,
    ) -> Result<Vec<DeviceSnapshot>, OnlineError> {
        let mut ticker = tokio::time::interval(interval);
        let mut out = Vec::with_capacity(samples);
        for _ in 0..samples {
            ticker.tick().await;
            out.push(self.poll().await?);
        }
        Ok(out)
    }
}

/// The little-endian bytes of a value held in `registers` (each a big-endian 16-bit word on
/// the wire), words in `order`.
pub fn bytes_of_registers(registers: &[u16], order: WordOrder) -> Vec<u8> {
    let words: Vec<u16> = match order {
        // The first register holds the most significant word: reverse into little-endian.
        WordOrder::HighFirst => registers.iter().rev().copied().collect(),
        WordOrder::LowFirst => registers.to_vec(),
    };
    words.iter().flat_map(|w| w.to_le_bytes()).collect()
}

/// The registers that hold `value` (little-endian bytes), `width` of them, words in `order`.
pub fn registers_of_bytes(value: &[u8], width: usize, order: WordOrder) -> Vec<u16> {
    let mut words: Vec<u16> = (0..width)
        .map(|i| {
            let low = value.get(2 * i).copied().unwrap_or(0);
            let high = value.get(2 * i + 1).copied().unwrap_or(0);
            u16::from_le_bytes([low, high])
        })
        .collect();
    if order == WordOrder::HighFirst {
        words.reverse();
    }
    words
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_real_spans_two_registers_in_either_word_order() {
        let bytes = 1.5f32.to_le_bytes().to_vec();
        // 1.5 is 16#3FC00000: ABCD puts 16#3FC0 first.
        assert_eq!(
            registers_of_bytes(&bytes, 2, WordOrder::HighFirst),
            vec![0x3FC0, 0x0000]
        );
        assert_eq!(
            registers_of_bytes(&bytes, 2, WordOrder::LowFirst),
            vec![0x0000, 0x3FC0]
        );
        for order in [WordOrder::HighFirst, WordOrder::LowFirst] {
            assert_eq!(
                bytes_of_registers(&registers_of_bytes(&bytes, 2, order), order),
                bytes
            );
        }
    }
}
