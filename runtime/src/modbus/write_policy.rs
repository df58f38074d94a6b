//! Which standard Modbus writes a runtime takes: all, none, or listed ranges of coils and
//! holding registers (`docs/modbus-map.md` §5).

use std::str::FromStr;

use crate::modbus::exception::ExceptionCode;

/// What the standard function codes 5, 6, 15, 16 and 23 may write; reads are never limited.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum WritePolicy {
    /// Every write is served, as without a password.
    #[default]
    All,
    /// Every write is refused: only the online services, with the password, change the target.
    None,
    /// A write is served only when every address it writes lies in one of the ranges.
    Ranges(Vec<WritableRange>),
}

/// Addresses `first..=last` of one writable table, in the 0-based addresses of the request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WritableRange {
    /// The table written.
    pub table: WritableTable,
    /// The first address.
    pub first: u16,
    /// The last address, included.
    pub last: u16,
}

/// The Modbus tables a client can write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WritableTable {
    /// Coils (function codes 5 and 15).
    Coils,
    /// Holding registers (function codes 6, 16 and 23).
    HoldingRegisters,
}

/// The exception every refused write gets, whatever its address, quantity or values, so that a
/// refusal tells nothing about the map: 1, illegal function.
pub const REFUSED_WRITE: ExceptionCode = ExceptionCode::IllegalFunction;

/// A write policy that does not parse, with the part that is wrong.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
#[error(
    "{text:?} is not a Modbus write policy: {reason}; expected `all`, `none`, or ranges such as \
     `coils:0-15,holding:1024-1100,holding:2048`"
)]
pub struct WritePolicyError {
    /// The part of the policy that is wrong.
    pub text: String,
    /// What is wrong with it.
    pub reason: &'static str,
}

impl WritePolicy {
    /// Whether the standard request PDU `request` (function code first) may be served: reads
    /// always, writes as the policy says. A write too short to say what it writes is refused
    /// when the policy limits writes.
    pub fn allows(&self, request: &[u8]) -> bool {
        let Some((&function, data)) = request.split_first() else {
            return true;
        };
        let field = |at: usize| {
            data.get(at..at + 2)
                .map(|bytes| u16::from_be_bytes([bytes[0], bytes[1]]))
        };
        let written = match function {
            5 => field(0).map(|address| (WritableTable::Coils, address, 1)),
            6 => field(0).map(|address| (WritableTable::HoldingRegisters, address, 1)),
            15 => field(0)
                .zip(field(2))
                .map(|(a, n)| (WritableTable::Coils, a, n)),
            16 => field(0)
                .zip(field(2))
                .map(|(a, n)| (WritableTable::HoldingRegisters, a, n)),
            // Read/write multiple registers: the write's address and quantity follow the read's.
            23 => field(4)
                .zip(field(6))
                .map(|(a, n)| (WritableTable::HoldingRegisters, a, n)),
            _ => return true,
        };
        match self {
            WritePolicy::All => true,
            WritePolicy::None => false,
            WritePolicy::Ranges(ranges) => written.is_some_and(|(table, first, quantity)| {
                let Some(last) = quantity
                    .checked_sub(1)
                    .and_then(|extra| first.checked_add(extra))
                else {
                    return false;
                };
                ranges
                    .iter()
                    .any(|range| range.table == table && range.first <= first && last <= range.last)
            }),
        }
    }
}

impl FromStr for WritePolicy {
    type Err = WritePolicyError;

    /// `all`, `none`, or comma-separated ranges `coils:FIRST-LAST` or `holding:FIRST-LAST`
    /// (`-LAST` may be left out for one address).
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let error = |part: &str, reason| WritePolicyError {
            text: part.to_owned(),
            reason,
        };
        match text.trim() {
            "all" => return Ok(WritePolicy::All),
            "none" => return Ok(WritePolicy::None),
            "" => return Err(error(text, "it is empty")),
            _ => {}
        }
        let mut ranges = Vec::new();
        for part in text.split(',').map(str::trim) {
            let (table, addresses) = part
                .split_once(':')
                .ok_or_else(|| error(part, "a range is TABLE:FIRST-LAST"))?;
            let table = match table.trim() {
                "coils" => WritableTable::Coils,
                "holding" => WritableTable::HoldingRegisters,
                _ => return Err(error(part, "the table is `coils` or `holding`")),
            };
            let (first, last) = addresses.split_once('-').unwrap_or((addresses, addresses));
            let address = |number: &str| {
                number
                    .trim()
                    .parse::<u16>()
                    .map_err(|_| error(part, "an address is a number from 0 to 65535"))
            };
            let (first, last) = (address(first)?, address(last)?);
            if last < first {
                return Err(error(part, "the last address is below the first"));
            }
            ranges.push(WritableRange { table, first, last });
        }
        Ok(WritePolicy::Ranges(ranges))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn policies_parse_from_their_documented_forms() {
        assert_eq!("all".parse(), Ok(WritePolicy::All));
        assert_eq!(" none ".parse(), Ok(WritePolicy::None));
        assert_eq!(
            "coils:0-15, holding:2048".parse(),
            Ok(WritePolicy::Ranges(vec![
                WritableRange {
                    table: WritableTable::Coils,
                    first: 0,
                    last: 15
                },
                WritableRange {
                    table: WritableTable::HoldingRegisters,
                    first: 2048,
                    last: 2048
                },
            ]))
        );
        for (wrong, reason) in [
            ("", "empty"),
            ("coils", "TABLE:FIRST-LAST"),
            ("inputs:0-3", "`coils` or `holding`"),
            ("coils:0-70000", "0 to 65535"),
            ("holding:9-3", "below the first"),
        ] {
            let error = wrong.parse::<WritePolicy>().unwrap_err();
            assert!(error.to_string().contains(reason), "{wrong}: {error}");
        }
    }

    #[test]
    fn a_range_policy_takes_a_write_only_wholly_inside_one_range_of_its_table() {
        let policy: WritePolicy = "coils:8-15,holding:1024-1027".parse().unwrap();
        // Function 5 at coil 8, 6 at register 1027: inside.
        assert!(policy.allows(&[5, 0, 8, 0xFF, 0]));
        assert!(policy.allows(&[6, 0x04, 0x03, 0, 1]));
        // Register 8 is not a coil, and coil 16 is past the range.
        assert!(!policy.allows(&[6, 0, 8, 0, 1]));
        assert!(!policy.allows(&[5, 0, 16, 0xFF, 0]));
        // 15: coils 8-15 fit, 9-16 do not.
        assert!(policy.allows(&[15, 0, 8, 0, 8, 1, 0xFF]));
        assert!(!policy.allows(&[15, 0, 9, 0, 8, 1, 0xFF]));
        // 16: registers 1026-1027 fit, 1026-1028 do not; a quantity of 0 writes nothing named.
        assert!(policy.allows(&[16, 0x04, 0x02, 0, 2, 4, 0, 0, 0, 0]));
        assert!(!policy.allows(&[16, 0x04, 0x02, 0, 3, 6, 0, 0, 0, 0, 0, 0]));
        assert!(!policy.allows(&[16, 0x04, 0x02, 0, 0, 0]));
        // 23 is judged by its write part (register 1024, 1 register), not its read part.
        assert!(policy.allows(&[23, 0, 0, 0, 1, 0x04, 0x00, 0, 1, 2, 0, 7]));
        assert!(!policy.allows(&[23, 0x04, 0, 0, 1, 0, 0, 0, 1, 2, 0, 7]));
        // A write too short to say where it writes is refused; reads always pass.
        assert!(!policy.allows(&[16, 0x04]));
        assert!(policy.allows(&[3, 0, 0, 0, 1]));
        assert!(policy.allows(&[1, 0, 100, 0, 1]));
    }

    #[test]
    fn all_and_none_take_every_write_or_none() {
        let writes: [&[u8]; 5] = [
            &[5, 0, 0, 0xFF, 0],
            &[6, 0, 0, 0, 1],
            &[15, 0, 0, 0, 1, 1, 1],
            &[16, 0, 0, 0, 1, 2, 0, 1],
            &[23, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1],
        ];
        for write in writes {
            assert!(WritePolicy::All.allows(write));
            assert!(!WritePolicy::None.allows(write));
        }
        assert!(WritePolicy::None.allows(&[4, 0, 0, 0, 1]));
        assert!(WritePolicy::None.allows(&[]));
    }
}
