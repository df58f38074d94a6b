//! Instance layouts of the standard function blocks that the runtime implements natively
//! (`docs/program-image.md` §7.3): the compiler places inputs and outputs where the runtime
//! reads and writes them.

use crate::Elementary::{self, Bool, DateAndTime, Int, Lint, Ltime, Time, Usint};
use crate::code::StdBlock;

/// One member of a standard function block's instance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StdMember {
    /// The IEC name (`IN`, `PT`, `Q`, `ET`); internal state starts with `_`.
    pub name: &'static str,
    /// Its type.
    pub ty: Elementary,
    /// Byte offset in the instance.
    pub offset: u32,
    /// Whether it is an input (`false`: an output or internal state).
    pub input: bool,
}

/// The instance layout of a standard function block.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StdLayout {
    /// Members in declaration order: inputs, outputs, then internal state.
    pub members: Vec<StdMember>,
    /// The instance size in bytes, a multiple of its alignment.
    pub size: u32,
}

impl StdLayout {
    /// The member called `name` (any case).
    pub fn member(&self, name: &str) -> Option<&StdMember> {
        self.members
            .iter()
            .find(|member| member.name.eq_ignore_ascii_case(name))
    }
}

impl StdBlock {
    /// The block called `name` (any case), with whether its times are the long forms.
    pub fn from_name(name: &str) -> Option<(Self, bool)> {
        Some(match name.to_ascii_uppercase().as_str() {
            "TON" => (Self::Ton, false),
            "TOF" => (Self::Tof, false),
            "TP" => (Self::Tp, false),
            "LTON" => (Self::Ton, true),
            "LTOF" => (Self::Tof, true),
            "LTP" => (Self::Tp, true),
            "CTU" => (Self::Ctu, false),
            "CTD" => (Self::Ctd, false),
            "CTUD" => (Self::Ctud, false),
            "R_TRIG" => (Self::RTrig, false),
            "F_TRIG" => (Self::FTrig, false),
            "SR" => (Self::Sr, false),
            "RS" => (Self::Rs, false),
            "RTC" => (Self::Rtc, false),
            _ => return None,
        })
    }
}

/// The instance layout of `block`; `long` selects the LTIME timers (`LTON`, …).
///
/// Timers keep their start time as `_START` (LINT nanoseconds of the task clock) and their
/// previous input and running state in `_STATE`; edge detectors and counters keep the
/// previous clock input in `_M`/`_MU`/`_MD`.
pub fn layout(block: StdBlock, long: bool) -> StdLayout {
    let time = if long { Ltime } else { Time };
    let list: &[(&'static str, Elementary, bool)] = match block {
        StdBlock::Ton | StdBlock::Tof | StdBlock::Tp => &[
            ("IN", Bool, true),
            ("PT", Time, true),
            ("Q", Bool, false),
            ("ET", Time, false),
            ("_START", Lint, false),
            ("_STATE", Usint, false),
        ],
        StdBlock::Ctu => &[
            ("CU", Bool, true),
            ("R", Bool, true),
            ("PV", Int, true),
            ("Q", Bool, false),
            ("CV", Int, false),
            ("_M", Bool, false),
        ],
        StdBlock::Ctd => &[
            ("CD", Bool, true),
            ("LD", Bool, true),
            ("PV", Int, true),
            ("Q", Bool, false),
            ("CV", Int, false),
            ("_M", Bool, false),
        ],
        StdBlock::Ctud => &[
            ("CU", Bool, true),
            ("CD", Bool, true),
            ("R", Bool, true),
            ("LD", Bool, true),
            ("PV", Int, true),
            ("QU", Bool, false),
            ("QD", Bool, false),
            ("CV", Int, false),
            ("_MU", Bool, false),
            ("_MD", Bool, false),
        ],
        StdBlock::RTrig | StdBlock::FTrig => {
            &[("CLK", Bool, true), ("Q", Bool, false), ("_M", Bool, false)]
        }
        StdBlock::Sr => &[("S1", Bool, true), ("R", Bool, true), ("Q1", Bool, false)],
        StdBlock::Rs => &[("S", Bool, true), ("R1", Bool, true), ("Q1", Bool, false)],
        // `_START` is the task clock at the rising edge of EN, in nanoseconds.
        StdBlock::Rtc => &[
            ("EN", Bool, true),
            ("PDT", DateAndTime, true),
            ("Q", Bool, false),
            ("CDT", DateAndTime, false),
            ("_START", Lint, false),
        ],
    };
    let mut members = Vec::with_capacity(list.len());
    let mut offset = 0u32;
    let mut align = 1u32;
    for &(name, ty, input) in list {
        let ty = if ty == Time { time } else { ty };
        let size = ty.size_bytes();
        offset = offset.next_multiple_of(size);
        align = align.max(size);
        members.push(StdMember {
            name,
            ty,
            offset,
            input,
        });
        offset += size;
    }
    StdLayout {
        members,
        size: offset.next_multiple_of(align),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_timer_layout_is_the_documented_one() {
        let ton = layout(StdBlock::Ton, false);
        let offsets: Vec<(&str, u32)> = ton.members.iter().map(|m| (m.name, m.offset)).collect();
        assert_eq!(
            offsets,
            [
                ("IN", 0),
                ("PT", 4),
                ("Q", 8),
                ("ET", 12),
                ("_START", 16),
                ("_STATE", 24)
            ]
        );
        assert_eq!(ton.size, 32);
        let lton = layout(StdBlock::Ton, true);
        assert_eq!(
            lton.member("et").map(|m| (m.ty, m.offset)),
            Some((Ltime, 24))
        );
    }

    #[test]
    fn counters_keep_their_iec_member_order() {
        let ctud = layout(StdBlock::Ctud, false);
        assert_eq!(ctud.member("PV").map(|m| m.offset), Some(4));
        assert_eq!(ctud.member("CV").map(|m| m.offset), Some(8));
        assert_eq!(ctud.size, 12);
        assert_eq!(
            StdBlock::from_name("r_trig"),
            Some((StdBlock::RTrig, false))
        );
    }
}
