//! Variable declarations of POUs, methods and global variable lists.

use serde::{Deserialize, Serialize};

/// The declaration section a variable belongs to.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "SCREAMING_SNAKE_CASE")]
pub enum VarSection {
    /// `VAR`: local, kept between calls of a program or function block.
    #[default]
    Var,
    /// `VAR_INPUT`.
    VarInput,
    /// `VAR_OUTPUT`.
    VarOutput,
    /// `VAR_IN_OUT`: passed by reference.
    VarInOut,
    /// `VAR_GLOBAL`: only in global variable lists.
    VarGlobal,
    /// `VAR_EXTERNAL`: a reference to a global variable.
    VarExternal,
    /// `VAR_TEMP`: re-initialised on every call.
    VarTemp,
    /// `VAR_STAT`: static, shared by every instance.
    VarStat,
    /// `VAR_INST`: an instance variable of a method (CODESYS).
    VarInst,
    /// `VAR_CONFIG`: instance-specific addresses for `AT %I*` / `%Q*` variables.
    VarConfig,
}

impl VarSection {
    /// Every section, in the order declarations are usually written.
    pub const ALL: [Self; 10] = [
        Self::VarInput,
        Self::VarOutput,
        Self::VarInOut,
        Self::Var,
        Self::VarTemp,
        Self::VarStat,
        Self::VarInst,
        Self::VarGlobal,
        Self::VarExternal,
        Self::VarConfig,
    ];

    /// The IEC keyword that opens the section, such as `VAR_INPUT`.
    pub fn keyword(self) -> &'static str {
        match self {
            Self::Var => "VAR",
            Self::VarInput => "VAR_INPUT",
            Self::VarOutput => "VAR_OUTPUT",
            Self::VarInOut => "VAR_IN_OUT",
            Self::VarGlobal => "VAR_GLOBAL",
            Self::VarExternal => "VAR_EXTERNAL",
            Self::VarTemp => "VAR_TEMP",
            Self::VarStat => "VAR_STAT",
            Self::VarInst => "VAR_INST",
            Self::VarConfig => "VAR_CONFIG",
        }
    }
}

/// One declared variable.
///
/// Types, initial values and addresses are kept as the text the user wrote (`ARRAY[1..3] OF INT`,
/// `[1, 2, 3]`, `%IX0.0`): the compiler parses and checks them, so the model never rejects what a
/// user typed and nothing is lost on a round trip.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Variable {
    /// The variable's name, an IEC identifier.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The declaration section.
    #[serde(default)]
    pub section: VarSection,
    /// The type as written, for example `INT`, `TON`, `STRING(20)` or `ARRAY[0..9] OF REAL`.
    #[serde(rename = "type")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub ty: String,
    /// The initial value as written, if any, for example `5`, `T#2s` or `(x := 1, y := 2)`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
    pub initial: Option<String>,
    /// The `AT` address as written, for example `%IX0.0`, `%QW4` or `%I*`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
    pub address: Option<String>,
    /// `CONSTANT`: the value cannot be written.
    #[serde(default, skip_serializing_if = "is_false")]
    pub constant: bool,
    /// `RETAIN`: kept across warm reset and runtime restart.
    #[serde(default, skip_serializing_if = "is_false")]
    pub retain: bool,
    /// `PERSISTENT`: also kept across cold reset.
    #[serde(default, skip_serializing_if = "is_false")]
    pub persistent: bool,
    /// The comment shown beside the declaration.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
}

impl Variable {
    /// A `VAR` variable of the given type with nothing else set.
    pub fn new(name: impl Into<String>, ty: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            ty: ty.into(),
            ..Self::default()
        }
    }
}

/// Serde helper: skips values equal to their default so files list only what is set.
pub(crate) fn is_default<T: Default + PartialEq>(value: &T) -> bool {
    *value == T::default()
}

/// Serde helper: skips `false` flags so files list only what is set.
pub(crate) fn is_false(value: &bool) -> bool {
    !*value
}
