//! What a bound path names when the runtime cannot copy it between cycles, for the build's
//! E0140 and the device editor's refusal, which say the same.

use std::fmt;

/// Something a Modbus channel's path may name that has no fixed place between cycles, so the
/// runtime master cannot copy its value (`docs/modbus-master.md` §3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unplaceable {
    /// A `VAR_TEMP` of a program or function block.
    VarTemp,
    /// A `VAR_IN_OUT`, a reference to a caller's variable.
    VarInOut,
    /// A `VAR_EXTERNAL`, a reference to a global variable.
    VarExternal,
    /// A variable of a function.
    FunctionVariable,
    /// A method of a program or function block.
    Method,
    /// A property of a program or function block.
    Property,
    /// An axis or a cam table.
    AxisOrCam,
}

impl fmt::Display for Unplaceable {
    /// The words after "is", as the build's E0140 says them: `a VAR_TEMP, which has no place
    /// between cycles`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::VarTemp => "a VAR_TEMP, which has no place between cycles",
            Self::VarInOut => "a VAR_IN_OUT, a reference to a caller's variable",
            Self::VarExternal => "a VAR_EXTERNAL, a reference to a global variable",
            Self::FunctionVariable => "a variable of a function, which has no place between calls",
            Self::Method => "a method, whose variables have no place between calls",
            Self::Property => "a property, whose value its accessors compute",
            Self::AxisOrCam => "an axis or cam table, which the motion kernel writes",
        })
    }
}
