//! A readable listing of code, one instruction a line, for tests and for people reading what
//! the compiler generated.
//!
//! Operands are written by region and byte offset: `G` global data, `I` instance, `F` frame,
//! `K` constant pool, `%I` `%Q` `%M` the located areas. An instruction is its name, its type
//! and `dst <- sources`, as in `add DINT F8 <- I0, K4`.

use std::fmt;

use crate::code::{Instr, Operand, Transfer};

/// The instructions of `code`, one a line, each after its index.
pub fn listing(code: &[Instr]) -> String {
    let mut out = String::new();
    for (index, instr) in code.iter().enumerate() {
        out.push_str(&format!("{index:<3} {instr}\n"));
    }
    out
}

impl fmt::Display for Operand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Global(offset) => write!(f, "G{offset}"),
            Self::Instance(offset) => write!(f, "I{offset}"),
            Self::Frame(offset) => write!(f, "F{offset}"),
            Self::Const(offset) => write!(f, "K{offset}"),
            Self::Input(offset) => write!(f, "%I{offset}"),
            Self::Output(offset) => write!(f, "%Q{offset}"),
            Self::Memory(offset) => write!(f, "%M{offset}"),
        }
    }
}

/// Transfers as `caller->callee_offset:size`, comma-separated, in brackets.
struct Transfers<'a>(&'a [Transfer]);

impl fmt::Display for Transfers<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("[")?;
        for (index, transfer) in self.0.iter().enumerate() {
            if index > 0 {
                f.write_str(", ")?;
            }
            write!(
                f,
                "{}@{}:{}",
                transfer.caller, transfer.callee_offset, transfer.size
            )?;
        }
        f.write_str("]")
    }
}

/// `ptr` or `*ptr` for an instance reached through a pointer.
fn instance(operand: &Operand, indirect: bool) -> String {
    if indirect {
        format!("*{operand}")
    } else {
        operand.to_string()
    }
}

impl fmt::Display for Instr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Move { ty, dst, src } => write!(f, "move {} {dst} <- {src}", ty.name()),
            Self::Copy { size, dst, src } => write!(f, "copy {size} {dst} <- {src}"),
            Self::Unary { op, ty, dst, src } => {
                write!(f, "{} {} {dst} <- {src}", lower(op), ty.name())
            }
            Self::Binary { op, ty, dst, a, b } => {
                write!(f, "{} {} {dst} <- {a}, {b}", lower(op), ty.name())
            }
            Self::Compare { op, ty, dst, a, b } => {
                write!(f, "cmp.{} {} {dst} <- {a}, {b}", lower(op), ty.name())
            }
            Self::Convert { from, to, dst, src } => {
                write!(f, "convert {}>{} {dst} <- {src}", from.name(), to.name())
            }
            Self::Trunc { from, to, dst, src } => {
                write!(f, "trunc {}>{} {dst} <- {src}", from.name(), to.name())
            }
            Self::GetBit { ty, dst, src, bit } => {
                write!(f, "getbit {} {dst} <- {src}.{bit}", ty.name())
            }
            Self::SetBit { ty, dst, bit, src } => {
                write!(f, "setbit {} {dst}.{bit} <- {src}", ty.name())
            }
            Self::Jump { target } => write!(f, "jump {target}"),
            Self::JumpIf { cond, target } => write!(f, "jumpif {cond} {target}"),
            Self::JumpIfNot { cond, target } => write!(f, "jumpifnot {cond} {target}"),
            Self::Address { dst, place } => write!(f, "address {dst} <- &{place}"),
            Self::Element {
                dst,
                base,
                index,
                index_ty,
                low,
                count,
                stride,
            } => write!(
                f,
                "element {dst} <- {base}[{index} {} from {low}, {count} of {stride}]",
                index_ty.name()
            ),
            Self::LoadElement {
                ty,
                dst,
                array,
                index,
                index_ty,
                low,
                count,
                stride,
                offset,
            } => write!(
                f,
                "loadelement {} {dst} <- {array}[{index} {} from {low}, {count} of {stride}]+{offset}",
                ty.name(),
                index_ty.name()
            ),
            Self::StoreElement {
                ty,
                array,
                index,
                index_ty,
                low,
                count,
                stride,
                offset,
                src,
            } => write!(
                f,
                "storeelement {} {array}[{index} {} from {low}, {count} of {stride}]+{offset} <- {src}",
                ty.name(),
                index_ty.name()
            ),
            Self::Offset { dst, base, offset } => write!(f, "offset {dst} <- {base}+{offset}"),
            Self::Load { size, dst, ptr } => write!(f, "load {size} {dst} <- *{ptr}"),
            Self::Store { size, ptr, src } => write!(f, "store {size} *{ptr} <- {src}"),
            Self::CallFunction {
                pou,
                instance: this,
                inputs,
                outputs,
            } => {
                write!(f, "call pou{pou}")?;
                if let Some(this) = this {
                    write!(f, " on {this}")?;
                }
                write!(f, " in {} out {}", Transfers(inputs), Transfers(outputs))
            }
            Self::CallBlock {
                pou,
                instance: at,
                indirect,
            } => write!(f, "callblock pou{pou} on {}", instance(at, *indirect)),
            Self::CallStdBlock {
                block,
                long,
                instance: at,
                indirect,
            } => {
                let long = if *long { " long" } else { "" };
                write!(f, "callstd {block:?}{long} on {}", instance(at, *indirect))
            }
            Self::CallStdFunction {
                function,
                wide,
                dst,
                args,
            } => {
                let wide = if *wide { " wide" } else { "" };
                write!(f, "callfn {function:?}{wide} {}:{} <-", dst.0, dst.1)?;
                for (index, (operand, size)) in args.iter().enumerate() {
                    let separator = if index > 0 { "," } else { "" };
                    write!(f, "{separator} {operand}:{size}")?;
                }
                Ok(())
            }
            Self::Return => f.write_str("return"),
            Self::ToText {
                from,
                wide,
                dst,
                capacity,
                src,
            } => {
                let text = if *wide { "WSTRING" } else { "STRING" };
                write!(
                    f,
                    "totext {}>{text}({capacity}) {dst} <- {src}",
                    from.name()
                )
            }
            Self::FromText {
                to,
                wide,
                dst,
                src,
                capacity,
            } => {
                let text = if *wide { "WSTRING" } else { "STRING" };
                write!(
                    f,
                    "fromtext {text}({capacity})>{} {dst} <- {src}",
                    to.name()
                )
            }
            Self::CallVirtual {
                table,
                interface,
                inputs,
                outputs,
            } => {
                write!(f, "callvirtual {interface} via")?;
                for (class, pou) in table {
                    write!(f, " {class}:pou{pou}")?;
                }
                write!(f, " in {} out {}", Transfers(inputs), Transfers(outputs))
            }
            Self::OpenElement {
                dst,
                descriptor,
                indices,
                stride,
            } => {
                write!(f, "openelement {dst} <- {descriptor}[")?;
                for (index, (operand, ty)) in indices.iter().enumerate() {
                    let separator = if index > 0 { ", " } else { "" };
                    write!(f, "{separator}{operand} {}", ty.name())?;
                }
                write!(f, "] of {stride}")
            }
            Self::Now { dst } => write!(f, "now {dst}"),
            Self::Native { block } => write!(f, "native {block}"),
            Self::Clock { long: false, dst } => write!(f, "time {dst}"),
            Self::Clock { long: true, dst } => write!(f, "ltime {dst}"),
        }
    }
}

/// An operator's name in lower case, as the listing writes it (`add`, `shl`, `lt`).
fn lower(op: &impl fmt::Debug) -> String {
    format!("{op:?}").to_lowercase()
}

#[cfg(test)]
mod tests {
    use expect_test::expect;

    use super::*;
    use crate::Elementary;
    use crate::code::{BinaryOp, CompareOp, StdBlock};

    #[test]
    fn a_listing_writes_each_instruction_on_its_own_numbered_line() {
        let code = [
            Instr::Binary {
                op: BinaryOp::Add,
                ty: Elementary::Dint,
                dst: Operand::Frame(8),
                a: Operand::Instance(0),
                b: Operand::Const(4),
            },
            Instr::Compare {
                op: CompareOp::Lt,
                ty: Elementary::Dint,
                dst: Operand::Frame(16),
                a: Operand::Frame(8),
                b: Operand::Global(12),
            },
            Instr::JumpIfNot {
                cond: Operand::Frame(16),
                target: 5,
            },
            Instr::SetBit {
                ty: Elementary::Byte,
                dst: Operand::Output(2),
                bit: 3,
                src: Operand::Input(0),
            },
            Instr::CallStdBlock {
                block: StdBlock::Ton,
                long: false,
                instance: Operand::Frame(24),
                indirect: true,
            },
            Instr::CallFunction {
                pou: 2,
                instance: None,
                inputs: vec![Transfer {
                    caller: Operand::Memory(4),
                    callee_offset: 0,
                    size: 4,
                }],
                outputs: Vec::new(),
            },
            Instr::Clock {
                long: true,
                dst: Operand::Frame(32),
            },
            Instr::LoadElement {
                ty: Elementary::Real,
                dst: Operand::Frame(40),
                array: Operand::Instance(36),
                index: Operand::Instance(32),
                index_ty: Elementary::Dint,
                low: -2,
                count: 10,
                stride: 8,
                offset: 4,
            },
            Instr::StoreElement {
                ty: Elementary::Dint,
                array: Operand::Global(100),
                index: Operand::Frame(8),
                index_ty: Elementary::Ulint,
                low: 1,
                count: 1000,
                stride: 4,
                offset: 0,
                src: Operand::Frame(40),
            },
            Instr::Return,
        ];
        expect![[r#"
            0   add DINT F8 <- I0, K4
            1   cmp.lt DINT F16 <- F8, G12
            2   jumpifnot F16 5
            3   setbit BYTE %Q2.3 <- %I0
            4   callstd Ton on *F24
            5   call pou2 in [%M4@0:4] out []
            6   ltime F32
            7   loadelement REAL F40 <- I36[I32 DINT from -2, 10 of 8]+4
            8   storeelement DINT G100[F8 ULINT from 1, 1000 of 4]+0 <- F40
            9   return
        "#]]
        .assert_eq(&listing(&code));
    }
}
