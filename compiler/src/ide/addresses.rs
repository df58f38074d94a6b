//! Direct addresses for the declaration table and the I/O mapping: whether an `AT` address is
//! well formed and fits its variable's type, and which located variables of a project share bits.
//!
//! The layout is CODESYS's byte addressing (`%MWn` covers bytes `2n` and `2n+1`), the same one the
//! checker and the code generator use, because all three read addresses through
//! `sema::address`.

use std::ops::Range;

use project_model::{Object, Project, Variable};

use crate::elementary::Elementary;
use crate::sema::address::{self, AddressError, Area};

/// The memory area an address lies in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum AddressArea {
    /// `%I`, the inputs.
    Input,
    /// `%Q`, the outputs.
    Output,
    /// `%M`, the markers.
    Memory,
}

impl AddressArea {
    /// The letter after `%`: `I`, `Q` or `M`.
    pub fn letter(self) -> char {
        match self {
            Self::Input => 'I',
            Self::Output => 'Q',
            Self::Memory => 'M',
        }
    }
}

/// What a valid direct address covers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AddressInfo {
    /// The area.
    pub area: AddressArea,
    /// The access size in bits (1, 8, 16, 32 or 64); `None` for an address left to the I/O
    /// mapping (`%I*`, `%Q*`).
    pub size_bits: Option<u32>,
    /// The bits covered, counted from the start of the area, end exclusive; `None` when the
    /// address names no fixed place (`%I*`, or a hierarchical address such as `%IW2.5.7`).
    pub bits: Option<Range<u64>>,
}

impl AddressInfo {
    /// Whether the address names a fixed place in its area (`%I*` does not).
    pub fn is_assigned(&self) -> bool {
        self.bits.is_some()
    }

    /// The bytes touched, end exclusive: `%MW1` touches bytes 2 and 3, `%IX0.3` byte 0.
    pub fn bytes(&self) -> Option<Range<u64>> {
        let bits = self.bits.as_ref()?;
        Some(bits.start / 8..bits.end.div_ceil(8))
    }
}

/// Why an address does not fit the variable it is given to, in the declaration table's words.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum AddressCheckError {
    /// The cell holds only blanks.
    #[error("the address is empty: write one such as %IX0.0, or clear the cell")]
    Empty,
    /// The text is not a direct address.
    #[error(transparent)]
    Syntax(#[from] AddressError),
    /// The address is well formed but its size does not fit the type: `%QW4` for a REAL.
    #[error(
        "{text} is {size_bits} bit{} but {ty} needs {needed_bits}: use {suggestion}",
        plural_s(.size_bits)
    )]
    WrongSize {
        /// The address, trimmed.
        text: String,
        /// The size of the address in bits.
        size_bits: u32,
        /// The variable's type, in capitals.
        ty: String,
        /// The size the type needs in bits.
        needed_bits: u32,
        /// The address of the needed size at the same place, or only its area and size letter
        /// when the place is not aligned to that size (`%MW`).
        suggestion: String,
    },
}

/// The `s` of `bits` after a size other than 1.
fn plural_s(size_bits: &u32) -> &'static str {
    if *size_bits == 1 { "" } else { "s" }
}

/// Reads the syntax of `address` without regard to a type: `%IX0.3`, `%QW4`, `%MD10`, `%I*`.
pub fn address_info(address: &str) -> Result<AddressInfo, AddressError> {
    let text = address.trim();
    let parsed = address::parse_address(text)?;
    let area_of = |area: Area| match area {
        Area::Input => AddressArea::Input,
        Area::Output => AddressArea::Output,
        Area::Memory => AddressArea::Memory,
    };
    if let Some(parsed) = parsed {
        return Ok(AddressInfo {
            area: area_of(parsed.area),
            size_bits: Some(parsed.size_bits),
            bits: Some(parsed.bits()),
        });
    }
    // The parser accepted the text without a place: `%I*` or a hierarchical address. Its area
    // and size letter are still the second and third characters.
    let upper = text.to_ascii_uppercase();
    let mut chars = upper.chars().skip(1);
    let area = match chars.next() {
        Some('I') => AddressArea::Input,
        Some('Q') => AddressArea::Output,
        _ => AddressArea::Memory,
    };
    let size_bits = match chars.next() {
        Some('*') => None,
        Some('B') => Some(8),
        Some('W') => Some(16),
        Some('D') => Some(32),
        Some('L') => Some(64),
        _ => Some(1),
    };
    Ok(AddressInfo {
        area,
        size_bits,
        bits: None,
    })
}

/// Checks `address` as the `AT` address of a variable of type `ty`: its syntax, and that its
/// size fits an elementary type (BOOL on `X`, INT on `W`, REAL on `D`, …). The error says what is
/// wrong and what would fit, such as `%QW4 is 16 bits but REAL needs 32: use %QD2`.
///
/// Types that are not elementary (arrays, structures, strings, function blocks) may lie at any
/// size of address, as in CODESYS, so only the syntax is checked for them.
pub fn check_address(address: &str, ty: &str) -> Result<AddressInfo, AddressCheckError> {
    let text = address.trim();
    if text.is_empty() {
        return Err(AddressCheckError::Empty);
    }
    let info = address_info(text)?;
    let (Some(size), Some(needed)) = (info.size_bits, needed_bits(ty)) else {
        return Ok(info);
    };
    if size == needed {
        return Ok(info);
    }
    let letter = size_letter(needed);
    let area = info.area.letter();
    let suggestion = match info.bits.as_ref() {
        // The address of the wanted size at the same first byte, when the byte is aligned to it.
        Some(bits) if needed == 1 => format!("%{area}X{}.{}", bits.start / 8, bits.start % 8),
        Some(bits) if bits.start % u64::from(needed) == 0 => {
            format!("%{area}{letter}{}", bits.start / u64::from(needed))
        }
        _ => format!("%{area}{letter}"),
    };
    Err(AddressCheckError::WrongSize {
        text: text.to_owned(),
        size_bits: size,
        ty: ty.trim().to_ascii_uppercase(),
        needed_bits: needed,
        suggestion,
    })
}

/// The size a located variable of type `ty` must have, `None` when any size will do.
fn needed_bits(ty: &str) -> Option<u32> {
    match Elementary::from_name(ty.trim())? {
        Elementary::Bool => Some(1),
        Elementary::String | Elementary::Wstring => None,
        other => Some(other.size_bits()),
    }
}

fn size_letter(bits: u32) -> char {
    match bits {
        1 => 'X',
        8 => 'B',
        16 => 'W',
        32 => 'D',
        _ => 'L',
    }
}

/// A located variable, named with the object that declares it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LocatedVariable {
    /// The declaring POU or global variable list; a method's variables are owned by
    /// `POU.Method`.
    pub owner: String,
    /// The variable's name.
    pub name: String,
    /// The address as written.
    pub address: String,
    /// The type as written.
    pub ty: String,
    /// The variable's comment.
    pub comment: String,
}

/// Two located variables whose bits overlap: writing one changes the other. A warning, since
/// CODESYS allows it (a word and its bits are sometimes meant to share memory).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Overlap {
    /// The variable declared first in the project's tree order.
    pub first: LocatedVariable,
    /// The other variable.
    pub second: LocatedVariable,
}

impl Overlap {
    /// The warning as a sentence, such as
    /// `GVL.wWord at %MW1 overlaps GVL.bByte at %MB2: writing one changes the other`.
    pub fn message(&self) -> String {
        format!(
            "{}.{} at {} overlaps {}.{} at {}: writing one changes the other",
            self.first.owner,
            self.first.name,
            self.first.address,
            self.second.owner,
            self.second.name,
            self.second.address
        )
    }
}

/// Every located variable of the project (POUs, their methods and global variable lists) with
/// its address, in tree order. Variables whose address does not parse are left out.
pub fn located_variables(project: &Project) -> Vec<(LocatedVariable, AddressInfo)> {
    let mut found = Vec::new();
    let mut add = |owner: &str, variables: &[Variable]| {
        for variable in variables {
            let Some(text) = variable.address.as_deref() else {
                continue;
            };
            if let Ok(info) = address_info(text) {
                let located = LocatedVariable {
                    owner: owner.to_owned(),
                    name: variable.name.clone(),
                    address: text.trim().to_owned(),
                    ty: variable.ty.clone(),
                    comment: variable.comment.clone(),
                };
                found.push((located, info));
            }
        }
    };
    for object in project.application.objects() {
        match object {
            Object::Pou(pou) => {
                add(&pou.name, &pou.variables);
                for method in &pou.methods {
                    add(&format!("{}.{}", pou.name, method.name), &method.variables);
                }
            }
            Object::Gvl(gvl) => add(&gvl.name, &gvl.variables),
            _ => {}
        }
    }
    found
}

/// Every pair of located variables whose bits overlap, in the order of their first variable:
/// `%MW1` overlaps `%MB2` (both hold byte 2), `%MW1` and `%MB4` do not.
pub fn located_overlaps(project: &Project) -> Vec<Overlap> {
    let located = located_variables(project);
    let mut overlaps = Vec::new();
    for (index, (first, a)) in located.iter().enumerate() {
        let Some(a_bits) = a.bits.as_ref() else {
            continue;
        };
        for (second, b) in &located[index + 1..] {
            let Some(b_bits) = b.bits.as_ref() else {
                continue;
            };
            if a.area == b.area && a_bits.start < b_bits.end && b_bits.start < a_bits.end {
                overlaps.push(Overlap {
                    first: first.clone(),
                    second: second.clone(),
                });
            }
        }
    }
    overlaps
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::{GlobalVarList, Node, Pou, PouKind, VarSection};

    #[test]
    fn valid_addresses_report_their_area_size_and_bits() {
        let bit = check_address("%IX0.3", "BOOL").unwrap();
        assert_eq!(bit.area, AddressArea::Input);
        assert_eq!(bit.size_bits, Some(1));
        assert_eq!(bit.bits, Some(3..4));
        assert_eq!(bit.bytes(), Some(0..1));
        let byte = check_address("%QB2", "BYTE").unwrap();
        assert_eq!((byte.area, byte.bytes()), (AddressArea::Output, Some(2..3)));
        let word = check_address("%QW4", "INT").unwrap();
        assert_eq!(word.bytes(), Some(8..10));
        let double = check_address("%MD10", "REAL").unwrap();
        assert_eq!(
            (double.area, double.bytes()),
            (AddressArea::Memory, Some(40..44))
        );
        let long = check_address("%ML1", "LREAL").unwrap();
        assert_eq!(long.bytes(), Some(8..16));
        assert_eq!(check_address(" %mw1 ", "word").unwrap().bits, Some(16..32));
    }

    #[test]
    fn unassigned_addresses_fit_any_type_and_name_no_place() {
        for (text, area) in [("%I*", AddressArea::Input), ("%Q*", AddressArea::Output)] {
            let info = check_address(text, "DINT").unwrap();
            assert_eq!(info.area, area);
            assert!(!info.is_assigned());
            assert_eq!((info.size_bits, info.bytes()), (None, None));
        }
    }

    #[test]
    fn broken_syntax_says_what_is_wrong() {
        assert!(
            check_address("IX0.0", "BOOL")
                .unwrap_err()
                .to_string()
                .contains("start with '%'")
        );
        assert!(
            check_address("%ZX0.0", "BOOL")
                .unwrap_err()
                .to_string()
                .contains("memory area")
        );
        assert!(
            check_address("%IK3", "BOOL")
                .unwrap_err()
                .to_string()
                .contains("size")
        );
        assert!(
            check_address("%IX0.8", "BOOL")
                .unwrap_err()
                .to_string()
                .contains("bits 0 to 7")
        );
        assert!(
            check_address("%IWa", "INT")
                .unwrap_err()
                .to_string()
                .contains("not a number")
        );
        assert!(
            check_address("", "INT")
                .unwrap_err()
                .to_string()
                .contains("empty")
        );
    }

    #[test]
    fn each_size_mismatch_names_the_address_that_fits() {
        let cases = [
            (
                "%QW4",
                "REAL",
                "%QW4 is 16 bits but REAL needs 32: use %QD2",
            ),
            (
                "%QB2",
                "BOOL",
                "%QB2 is 8 bits but BOOL needs 1: use %QX2.0",
            ),
            (
                "%IX0.0",
                "BYTE",
                "%IX0.0 is 1 bit but BYTE needs 8: use %IB0",
            ),
            ("%ID1", "SINT", "%ID1 is 32 bits but SINT needs 8: use %IB4"),
            ("%MB3", "WORD", "%MB3 is 8 bits but WORD needs 16: use %MW"),
            (
                "%MD0",
                "UINT",
                "%MD0 is 32 bits but UINT needs 16: use %MW0",
            ),
            (
                "%MW2",
                "TIME",
                "%MW2 is 16 bits but TIME needs 32: use %MD1",
            ),
            (
                "%QD2",
                "LREAL",
                "%QD2 is 32 bits but LREAL needs 64: use %QL1",
            ),
            (
                "%QL1",
                "DINT",
                "%QL1 is 64 bits but DINT needs 32: use %QD2",
            ),
            (
                "%IW0",
                "ULINT",
                "%IW0 is 16 bits but ULINT needs 64: use %IL0",
            ),
        ];
        for (address, ty, message) in cases {
            assert_eq!(
                check_address(address, ty).map_err(|error| error.to_string()),
                Err(message.to_owned()),
                "{address}"
            );
        }
    }

    #[test]
    fn an_address_error_says_as_data_why_the_address_does_not_fit() {
        assert_eq!(
            check_address(" %QW4 ", "real"),
            Err(AddressCheckError::WrongSize {
                text: "%QW4".to_owned(),
                size_bits: 16,
                ty: "REAL".to_owned(),
                needed_bits: 32,
                suggestion: "%QD2".to_owned(),
            })
        );
        assert_eq!(
            check_address("IX0.0", "BOOL"),
            Err(AddressCheckError::Syntax(AddressError::NoPercent {
                text: "IX0.0".to_owned()
            }))
        );
        assert_eq!(check_address("  ", "BOOL"), Err(AddressCheckError::Empty));
        assert_eq!(
            address_info("%IX0.9"),
            Err(AddressError::NoSuchBit {
                text: "%IX0.9".to_owned(),
                bit: 9
            })
        );
    }

    #[test]
    fn types_that_are_not_elementary_accept_any_size() {
        assert!(check_address("%IB0", "ARRAY[0..3] OF BYTE").is_ok());
        assert!(check_address("%QW0", "ST_Frame").is_ok());
        assert!(check_address("%MB10", "STRING(20)").is_ok());
    }

    fn gvl(name: &str, located: &[(&str, &str)]) -> Node {
        Node::Object(Object::Gvl(GlobalVarList {
            name: name.to_owned(),
            comment: String::new(),
            variables: located
                .iter()
                .map(|(variable, address)| Variable {
                    section: VarSection::VarGlobal,
                    address: Some((*address).to_owned()),
                    ..Variable::new(*variable, "BYTE")
                })
                .collect(),
        }))
    }

    fn project(nodes: Vec<Node>) -> Project {
        let mut project = Project::default();
        project.application.children = nodes;
        project
    }

    #[test]
    fn a_word_overlaps_the_bytes_it_covers_and_no_other() {
        let overlaps = located_overlaps(&project(vec![gvl(
            "GVL",
            &[("wWord", "%MW1"), ("bInside", "%MB2"), ("bAfter", "%MB4")],
        )]));
        assert_eq!(overlaps.len(), 1, "{overlaps:?}");
        assert_eq!(overlaps[0].first.name, "wWord");
        assert_eq!(overlaps[0].second.name, "bInside");
        assert_eq!(
            overlaps[0].message(),
            "GVL.wWord at %MW1 overlaps GVL.bInside at %MB2: writing one changes the other"
        );
    }

    #[test]
    fn bits_overlap_their_byte_across_owners_but_not_other_areas() {
        let pou = Node::Object(Object::Pou(Pou {
            name: "Main".to_owned(),
            kind: PouKind::Program,
            return_type: None,
            extends: None,
            implements: Vec::new(),
            comment: String::new(),
            variables: vec![Variable {
                address: Some("%QX3.7".to_owned()),
                ..Variable::new("xLamp", "BOOL")
            }],
            body: project_model::Body::st(""),
            methods: Vec::new(),
            properties: Vec::new(),
            actions: Vec::new(),
            transitions: Vec::new(),
        }));
        let overlaps = located_overlaps(&project(vec![
            pou,
            gvl(
                "GVL_IO",
                &[
                    ("bOut", "%QB3"),
                    ("bIn", "%IB3"),
                    ("bNext", "%QB4"),
                    ("any", "%Q*"),
                ],
            ),
        ]));
        assert_eq!(overlaps.len(), 1, "{overlaps:?}");
        assert_eq!(
            (
                overlaps[0].first.owner.as_str(),
                overlaps[0].second.owner.as_str()
            ),
            ("Main", "GVL_IO")
        );
        assert_eq!(overlaps[0].second.address, "%QB3");
    }
}
