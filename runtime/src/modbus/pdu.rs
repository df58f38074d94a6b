//! Serving one request PDU against the located areas, without sockets.
//!
//! The checks follow the order of the Modbus application protocol specification (V1.1b3): the
//! function code first (exception 1), then the quantity and the shape of the request
//! (exception 3), then the addresses (exception 2), and only then the reading or writing.
//! A write touches the areas only after every address of it has been found present, so a
//! request is all or nothing.

use std::sync::Mutex;

use crate::areas::LocatedAreas;
use crate::modbus::exception::ExceptionCode;
use crate::modbus::map::{BitLocation, ModbusMap, RegisterLocation, Table};
use crate::modbus::write_policy::{REFUSED_WRITE, WritePolicy};

/// The longest PDU of Modbus TCP: 253 bytes, function code included.
pub const MAX_PDU_BYTES: usize = 253;
/// The most bits one request reads (function codes 1 and 2).
pub const MAX_READ_BITS: u16 = 2000;
/// The most coils one request writes (function code 15).
pub const MAX_WRITE_BITS: u16 = 1968;
/// The most registers one request reads (function codes 3, 4 and 23).
pub const MAX_READ_REGISTERS: u16 = 125;
/// The most registers one request writes (function code 16).
pub const MAX_WRITE_REGISTERS: u16 = 123;
/// The most registers function code 23 writes.
pub const MAX_READ_WRITE_REGISTERS: u16 = 121;

/// Whether `function` is one of the standard function codes the areas serve: 1 to 6, 15, 16
/// and 23.
pub fn is_standard_function(function: u8) -> bool {
    matches!(function, 1..=6 | 15 | 16 | 23)
}

/// The response PDU to the request PDU `request` (function code first, no MBAP header).
///
/// Never panics and never allocates more than a response needs, whatever `request` holds; the
/// response is at most [`MAX_PDU_BYTES`] long. A function code other than the standard ones
/// is answered with exception 1: custom function codes are the server's business.
pub fn handle_pdu(areas: &mut LocatedAreas, map: &ModbusMap, request: &[u8]) -> Vec<u8> {
    let Some((&function, data)) = request.split_first() else {
        return ExceptionCode::IllegalFunction.response(0);
    };
    let mut fields = Fields(data);
    let served = match function {
        1 => read_bits(areas, map, Table::Coils, &mut fields),
        2 => read_bits(areas, map, Table::DiscreteInputs, &mut fields),
        3 => read_registers(areas, map, Table::HoldingRegisters, &mut fields),
        4 => read_registers(areas, map, Table::InputRegisters, &mut fields),
        5 => write_single_coil(areas, map, &mut fields),
        6 => write_single_register(areas, map, &mut fields),
        15 => write_multiple_coils(areas, map, &mut fields),
        16 => write_multiple_registers(areas, map, &mut fields),
        23 => read_write_multiple_registers(areas, map, &mut fields),
        _ => Err(ExceptionCode::IllegalFunction),
    };
    match served {
        Ok(body) => {
            let mut response = Vec::with_capacity(1 + body.len());
            response.push(function);
            response.extend_from_slice(&body);
            response
        }
        Err(exception) => exception.response(function),
    }
}

/// The response PDU to the request PDU `request` on the areas a server shares with the
/// engine: a write that `writes` does not allow gets [`REFUSED_WRITE`], and areas the engine
/// left poisoned (it panicked while holding them) exception 4; otherwise [`handle_pdu`] with
/// the areas locked for this one request.
///
/// The TCP server answers its standard function codes with it and the RTU slave every
/// request, so the two serve the map alike.
pub fn serve_pdu(
    areas: &Mutex<LocatedAreas>,
    map: &ModbusMap,
    writes: &WritePolicy,
    request: &[u8],
) -> Vec<u8> {
    let function = request.first().copied().unwrap_or(0);
    if !is_standard_function(function) {
        return ExceptionCode::IllegalFunction.response(function);
    }
    if !writes.allows(request) {
        return REFUSED_WRITE.response(function);
    }
    match areas.lock() {
        Ok(mut areas) => handle_pdu(&mut areas, map, request),
        Err(_) => ExceptionCode::ServerDeviceFailure.response(function),
    }
}

/// The fields of a request after its function code, read front to back; running short is an
/// illegal data value.
struct Fields<'a>(&'a [u8]);

impl<'a> Fields<'a> {
    fn u8(&mut self) -> Result<u8, ExceptionCode> {
        let (&first, rest) = self
            .0
            .split_first()
            .ok_or(ExceptionCode::IllegalDataValue)?;
        self.0 = rest;
        Ok(first)
    }

    fn u16(&mut self) -> Result<u16, ExceptionCode> {
        Ok(u16::from_be_bytes([self.u8()?, self.u8()?]))
    }

    /// The remaining bytes, which must be exactly `count`.
    fn rest(&mut self, count: usize) -> Result<&'a [u8], ExceptionCode> {
        let rest = std::mem::take(&mut self.0);
        if rest.len() == count {
            Ok(rest)
        } else {
            Err(ExceptionCode::IllegalDataValue)
        }
    }

    /// Ends the request: nothing may be left.
    fn end(&mut self) -> Result<(), ExceptionCode> {
        self.rest(0).map(|_| ())
    }
}

/// A quantity within `1..=max`, or an illegal data value.
fn quantity(fields: &mut Fields<'_>, max: u16) -> Result<u16, ExceptionCode> {
    let quantity = fields.u16()?;
    if (1..=max).contains(&quantity) {
        Ok(quantity)
    } else {
        Err(ExceptionCode::IllegalDataValue)
    }
}

/// The addresses `start..start + quantity`, or an illegal data address when they run past 65535.
fn addresses(start: u16, quantity: u16) -> Result<impl Iterator<Item = u16>, ExceptionCode> {
    let end = u32::from(start) + u32::from(quantity);
    if end > 0x1_0000 {
        return Err(ExceptionCode::IllegalDataAddress);
    }
    Ok((u32::from(start)..end).filter_map(|address| u16::try_from(address).ok()))
}

/// Where each bit of `start..start + quantity` is, all of them present in the areas.
fn present_bits(
    areas: &LocatedAreas,
    map: &ModbusMap,
    table: Table,
    start: u16,
    quantity: u16,
) -> Result<Vec<BitLocation>, ExceptionCode> {
    addresses(start, quantity)?
        .map(|address| {
            map.locate_bit(table, address)
                .filter(|location| location.byte < areas.bytes(location.area).len())
                .ok_or(ExceptionCode::IllegalDataAddress)
        })
        .collect()
}

/// Where each register of `start..start + quantity` is, all of them present in the areas.
fn present_registers(
    areas: &LocatedAreas,
    map: &ModbusMap,
    table: Table,
    start: u16,
    quantity: u16,
) -> Result<Vec<RegisterLocation>, ExceptionCode> {
    addresses(start, quantity)?
        .map(|address| {
            map.locate_register(table, address)
                .filter(|location| areas.word_at_byte(location.area, location.byte).is_some())
                .ok_or(ExceptionCode::IllegalDataAddress)
        })
        .collect()
}

fn read_bits(
    areas: &LocatedAreas,
    map: &ModbusMap,
    table: Table,
    fields: &mut Fields<'_>,
) -> Result<Vec<u8>, ExceptionCode> {
    let start = fields.u16()?;
    let quantity = quantity(fields, MAX_READ_BITS)?;
    fields.end()?;
    let locations = present_bits(areas, map, table, start, quantity)?;
    let mut body = vec![0; 1 + locations.len().div_ceil(8)];
    body[0] = (body.len() - 1) as u8;
    for (i, location) in locations.iter().enumerate() {
        if areas.bit(location.area, location.byte, location.bit) == Some(true) {
            body[1 + i / 8] |= 1 << (i % 8);
        }
    }
    Ok(body)
}

/// The registers at `locations` as a read response body: byte count, then big-endian words.
fn register_values(areas: &LocatedAreas, locations: &[RegisterLocation]) -> Vec<u8> {
    let mut body = Vec::with_capacity(1 + 2 * locations.len());
    body.push((2 * locations.len()) as u8);
    for location in locations {
        let word = areas
            .word_at_byte(location.area, location.byte)
            .unwrap_or(0);
        body.extend_from_slice(&word.to_be_bytes());
    }
    body
}

fn read_registers(
    areas: &LocatedAreas,
    map: &ModbusMap,
    table: Table,
    fields: &mut Fields<'_>,
) -> Result<Vec<u8>, ExceptionCode> {
    let start = fields.u16()?;
    let quantity = quantity(fields, MAX_READ_REGISTERS)?;
    fields.end()?;
    let locations = present_registers(areas, map, table, start, quantity)?;
    Ok(register_values(areas, &locations))
}

fn write_single_coil(
    areas: &mut LocatedAreas,
    map: &ModbusMap,
    fields: &mut Fields<'_>,
) -> Result<Vec<u8>, ExceptionCode> {
    let address = fields.u16()?;
    let value = match fields.u16()? {
        0xFF00 => true,
        0x0000 => false,
        _ => return Err(ExceptionCode::IllegalDataValue),
    };
    fields.end()?;
    let [location] = present_bits(areas, map, Table::Coils, address, 1)?[..] else {
        return Err(ExceptionCode::IllegalDataAddress);
    };
    areas.set_bit(location.area, location.byte, location.bit, value);
    Ok(request_echo(address, if value { 0xFF00 } else { 0 }))
}

fn write_single_register(
    areas: &mut LocatedAreas,
    map: &ModbusMap,
    fields: &mut Fields<'_>,
) -> Result<Vec<u8>, ExceptionCode> {
    let address = fields.u16()?;
    let value = fields.u16()?;
    fields.end()?;
    let [location] = present_registers(areas, map, Table::HoldingRegisters, address, 1)?[..] else {
        return Err(ExceptionCode::IllegalDataAddress);
    };
    areas.set_word_at_byte(location.area, location.byte, value);
    Ok(request_echo(address, value))
}

fn write_multiple_coils(
    areas: &mut LocatedAreas,
    map: &ModbusMap,
    fields: &mut Fields<'_>,
) -> Result<Vec<u8>, ExceptionCode> {
    let start = fields.u16()?;
    let quantity = quantity(fields, MAX_WRITE_BITS)?;
    let byte_count = usize::from(fields.u8()?);
    if byte_count != usize::from(quantity).div_ceil(8) {
        return Err(ExceptionCode::IllegalDataValue);
    }
    let packed = fields.rest(byte_count)?;
    let locations = present_bits(areas, map, Table::Coils, start, quantity)?;
    for (i, location) in locations.iter().enumerate() {
        let value = packed
            .get(i / 8)
            .is_some_and(|byte| byte >> (i % 8) & 1 == 1);
        areas.set_bit(location.area, location.byte, location.bit, value);
    }
    Ok(request_echo(start, quantity))
}

/// The values of a register write: byte count, then exactly that many bytes of big-endian words.
fn register_writes<'a>(
    fields: &mut Fields<'a>,
    quantity: u16,
) -> Result<impl Iterator<Item = u16> + 'a, ExceptionCode> {
    let byte_count = usize::from(fields.u8()?);
    if byte_count != 2 * usize::from(quantity) {
        return Err(ExceptionCode::IllegalDataValue);
    }
    let bytes = fields.rest(byte_count)?;
    Ok(bytes
        .chunks_exact(2)
        .map(|pair| u16::from_be_bytes([pair[0], pair[1]])))
}

fn write_multiple_registers(
    areas: &mut LocatedAreas,
    map: &ModbusMap,
    fields: &mut Fields<'_>,
) -> Result<Vec<u8>, ExceptionCode> {
    let start = fields.u16()?;
    let quantity = quantity(fields, MAX_WRITE_REGISTERS)?;
    let values = register_writes(fields, quantity)?;
    let locations = present_registers(areas, map, Table::HoldingRegisters, start, quantity)?;
    for (location, value) in locations.iter().zip(values) {
        areas.set_word_at_byte(location.area, location.byte, value);
    }
    Ok(request_echo(start, quantity))
}

fn read_write_multiple_registers(
    areas: &mut LocatedAreas,
    map: &ModbusMap,
    fields: &mut Fields<'_>,
) -> Result<Vec<u8>, ExceptionCode> {
    let read_start = fields.u16()?;
    let read_quantity = quantity(fields, MAX_READ_REGISTERS)?;
    let write_start = fields.u16()?;
    let write_quantity = quantity(fields, MAX_READ_WRITE_REGISTERS)?;
    let values = register_writes(fields, write_quantity)?;
    let table = Table::HoldingRegisters;
    let reads = present_registers(areas, map, table, read_start, read_quantity)?;
    let writes = present_registers(areas, map, table, write_start, write_quantity)?;
    for (location, value) in writes.iter().zip(values) {
        areas.set_word_at_byte(location.area, location.byte, value);
    }
    Ok(register_values(areas, &reads))
}

/// The body of a write response: the request's address and its value or quantity.
fn request_echo(address: u16, value: u16) -> Vec<u8> {
    let mut body = Vec::with_capacity(4);
    body.extend_from_slice(&address.to_be_bytes());
    body.extend_from_slice(&value.to_be_bytes());
    body
}

#[cfg(test)]
mod tests;
