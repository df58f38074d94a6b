//! Which compiler's rules a project follows where IEC 61131-3 and CODESYS differ.

use serde::{Deserialize, Serialize};

/// The language rules a project is checked by, the manifest's `dialect`.
///
/// CODESYS V3.5 accepts some programs that IEC 61131-3 refuses (arithmetic on bit strings,
/// implicit narrowing of integers); `docs/dialect.md` lists each difference with its source.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "kebab-case")]
pub enum Dialect {
    /// CODESYS V3.5's leniencies, with warnings where CODESYS warns (the default, so projects
    /// ported from CODESYS compile as they did there).
    #[default]
    Codesys,
    /// IEC 61131-3 only: every CODESYS leniency is an error.
    IecStrict,
}

impl Dialect {
    /// Whether this is the default, which the manifest leaves out.
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }

    /// The name as written in the manifest (`codesys`, `iec-strict`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Codesys => "codesys",
            Self::IecStrict => "iec-strict",
        }
    }
}
