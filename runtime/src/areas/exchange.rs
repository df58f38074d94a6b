//! The exchange of the located areas with a program's memory, which tolerates a skipped turn.
//!
//! The scheduler's thread must never wait for the areas' lock (a Modbus thread that holds it
//! may itself be waiting for a processor), so it only tries the lock, and a busy lock skips the
//! exchange. A skipped exchange must lose nothing: neither what the program wrote to `%Q` and
//! `%M` (published at the next exchange that gets the lock) nor what a client wrote meanwhile
//! (taken in at the next exchange). The areas therefore remember, bit by bit, what clients
//! wrote since the program last took them in; an exchange merges both sides by those marks.

use super::{Area, LocatedAreas};

impl LocatedAreas {
    /// The start of a cycle, for one area and the program's region of it: `%I` is copied to
    /// the program; for `%Q` and `%M` the program and the areas become the same: the bits
    /// clients wrote since the last exchange from the areas, every other bit from the program
    /// (which may hold writes not published yet), and the area's marks are cleared. Bytes
    /// beyond the shorter side are left as they are.
    pub fn exchange(&mut self, area: Area, program: &mut [u8]) {
        match area {
            Area::Input => copy(&self.input, program),
            Area::Output => merge_both(&mut self.output, program, &mut self.written_output),
            Area::Memory => merge_both(&mut self.memory, program, &mut self.written_memory),
        }
    }

    /// The end of a cycle: the areas' `%Q` and `%M` take the program's, but for the bits
    /// clients wrote since the last exchange, which the next exchange takes in.
    pub fn publish(&mut self, output: &[u8], memory: &[u8]) {
        merge_into_areas(&mut self.output, output, &self.written_output);
        merge_into_areas(&mut self.memory, memory, &self.written_memory);
    }

    /// Forgets what clients wrote since the last exchange (after a reset or a load, which
    /// replace the program's values with the areas' or the other way round).
    pub fn forget_writes(&mut self) {
        self.written_output.clear();
        self.written_memory.clear();
    }

    /// Marks the bits `bits` (one mask byte per byte) from byte `byte` of `area` as written by
    /// a client. `%I` is not marked: the program only reads it.
    pub(super) fn mark_written(
        &mut self,
        area: Area,
        byte: usize,
        bits: impl IntoIterator<Item = u8>,
    ) {
        let (length, marks) = match area {
            Area::Input => return,
            Area::Output => (self.output.len(), &mut self.written_output),
            Area::Memory => (self.memory.len(), &mut self.written_memory),
        };
        if marks.len() < length {
            marks.resize(length, 0);
        }
        for (mark, bits) in marks.iter_mut().skip(byte).zip(bits) {
            *mark |= bits;
        }
    }
}

/// Copies as many bytes as both slices have.
fn copy(from: &[u8], to: &mut [u8]) {
    let length = from.len().min(to.len());
    to[..length].copy_from_slice(&from[..length]);
}

/// Makes `area` and `program` equal: `area`'s bits where `marks` has them, `program`'s
/// elsewhere; then clears `marks`.
fn merge_both(area: &mut [u8], program: &mut [u8], marks: &mut Vec<u8>) {
    if marks.is_empty() {
        // Nobody wrote: the program's bytes are the newer ones everywhere.
        copy(program, area);
        return;
    }
    for (index, (area, program)) in area.iter_mut().zip(program.iter_mut()).enumerate() {
        let mark = marks.get(index).copied().unwrap_or(0);
        let merged = (*area & mark) | (*program & !mark);
        *area = merged;
        *program = merged;
    }
    marks.clear();
}

/// Writes `program` into `area` but for the bits `marks` has.
fn merge_into_areas(area: &mut [u8], program: &[u8], marks: &[u8]) {
    if marks.is_empty() {
        copy(program, area);
        return;
    }
    for (index, (area, program)) in area.iter_mut().zip(program).enumerate() {
        let mark = marks.get(index).copied().unwrap_or(0);
        *area = (*area & mark) | (*program & !mark);
    }
}

#[cfg(test)]
#[path = "exchange_tests.rs"]
mod tests;
