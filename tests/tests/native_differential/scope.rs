//! The four POUs of a generated program and what each may name.
//!
//! Every POU declares the same variables for each type (`a_T`, `b_T`, `c_T`, the array `r_T`,
//! loop counters), so one expression strategy fits them all but for what only some may use:
//! pointers and function block instances live in the program, and functions are called only
//! where no call cycle can arise.

use super::types::Ty;

/// One of the generated POUs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    /// `PROGRAM main`: pointers to array elements, two instances of the function block.
    Program,
    /// `FUNCTION_BLOCK FB_Gen`: inputs `a_T`, outputs `b_T`, state `c_T`.
    Block,
    /// `FUNCTION FnR : LREAL`, which may call `FnI`.
    FunctionReal,
    /// `FUNCTION FnI : LINT`, which calls nothing.
    FunctionInt,
}

/// The loop counters by nesting level: the FOR variable of a loop at statement depth `d` is
/// `FOR_COUNTERS[d - 1]`, so nested loops never share one.
pub const FOR_COUNTERS: [(&str, Ty); 3] = [("i1", Ty::Dint), ("i2", Ty::Int), ("i3", Ty::Lint)];

/// The WHILE and REPEAT counters by nesting level, as [`FOR_COUNTERS`].
pub const WHILE_COUNTERS: [&str; 3] = ["w1", "w2", "w3"];

impl Scope {
    /// The POU's name, as a call writes it.
    pub fn pou_name(self) -> &'static str {
        match self {
            Scope::Program => "main",
            Scope::Block => "FB_Gen",
            Scope::FunctionReal => "FnR",
            Scope::FunctionInt => "FnI",
        }
    }

    /// Whether the scope has the pointers `p_T` (set to an element of `r_T` before use).
    pub fn has_pointers(self) -> bool {
        self == Scope::Program
    }

    /// Whether the scope has the instances `fb1` and `fb2` of `FB_Gen`.
    pub fn has_instances(self) -> bool {
        self == Scope::Program
    }

    /// Whether code here may call `FnI`.
    pub fn calls_int_function(self) -> bool {
        self != Scope::FunctionInt
    }

    /// Whether code here may call `FnR`.
    pub fn calls_real_function(self) -> bool {
        matches!(self, Scope::Program | Scope::Block)
    }

    /// The variables of type `ty` an expression may read.
    pub fn readable(self, ty: Ty) -> Vec<String> {
        let suffix = ty.suffix();
        let mut names = vec![
            format!("a_{suffix}"),
            format!("b_{suffix}"),
            format!("c_{suffix}"),
        ];
        names.extend(
            FOR_COUNTERS
                .iter()
                .filter(|(_, counter)| *counter == ty)
                .map(|(name, _)| (*name).to_owned()),
        );
        if ty == Ty::Dint {
            names.extend(WHILE_COUNTERS.iter().map(|name| (*name).to_owned()));
        }
        names
    }

    /// The variables of type `ty` a statement may assign: not the inputs of a block or a
    /// function, and never a loop counter, so every loop stays bounded.
    pub fn writable(self, ty: Ty) -> Vec<String> {
        let suffix = ty.suffix();
        let mut names = vec![format!("b_{suffix}"), format!("c_{suffix}")];
        if self == Scope::Program {
            names.push(format!("a_{suffix}"));
        }
        match (self, ty) {
            (Scope::FunctionInt, Ty::Lint) => names.push("FnI".to_owned()),
            (Scope::FunctionReal, Ty::Lreal) => names.push("FnR".to_owned()),
            _ => {}
        }
        names
    }
}
