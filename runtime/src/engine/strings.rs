//! The string functions of the standard library as engine instructions: operands are read as
//! STRING/WSTRING of their declared capacity, computed by `stdlib::string`, and stored cut to
//! the result's capacity.

use program_image::{Elementary, StdFunction};

use super::exec::{Addr, Exec};
use super::fault::FaultKind;
use super::lower::{Flow, Op};
use super::lower_refusal::LowerRefusal;
use crate::stdlib::{string, text};

/// An argument of a string function: a string of some capacity, or an integer (DINT).
#[derive(Clone, Copy)]
enum Arg {
    Text(Addr, usize),
    Int(Addr),
}

/// The characters of one kind of string, read from and written to memory.
trait Unit: Copy + Ord + Send + Sync + 'static {
    fn load(x: &Exec<'_>, at: Addr, capacity: usize) -> Result<Vec<Self>, FaultKind>;
    fn store(x: &mut Exec<'_>, at: Addr, capacity: usize, chars: &[Self]) -> Result<(), FaultKind>;
}

impl Unit for u8 {
    fn load(x: &Exec<'_>, at: Addr, capacity: usize) -> Result<Vec<Self>, FaultKind> {
        let start = x.at(at);
        let bytes = x
            .mem
            .get(start..start + capacity + 1)
            .ok_or(FaultKind::Memory)?;
        Ok(string::load(bytes, capacity).to_vec())
    }
    fn store(x: &mut Exec<'_>, at: Addr, capacity: usize, chars: &[Self]) -> Result<(), FaultKind> {
        let start = x.at(at);
        let bytes = x
            .mem
            .get_mut(start..start + capacity + 1)
            .ok_or(FaultKind::Memory)?;
        string::store(bytes, chars, capacity);
        Ok(())
    }
}

impl Unit for u16 {
    fn load(x: &Exec<'_>, at: Addr, capacity: usize) -> Result<Vec<Self>, FaultKind> {
        let start = x.at(at);
        let bytes = x
            .mem
            .get(start..start + 2 * (capacity + 1))
            .ok_or(FaultKind::Memory)?;
        Ok(string::load_wide(bytes, capacity))
    }
    fn store(x: &mut Exec<'_>, at: Addr, capacity: usize, chars: &[Self]) -> Result<(), FaultKind> {
        let start = x.at(at);
        let bytes = x
            .mem
            .get_mut(start..start + 2 * (capacity + 1))
            .ok_or(FaultKind::Memory)?;
        string::store_wide(bytes, chars, capacity);
        Ok(())
    }
}

/// The instruction for a string function.
pub(crate) fn lower(
    function: StdFunction,
    wide: bool,
    dst: (Addr, u32),
    args: Vec<(Addr, u32)>,
) -> Result<Op, LowerRefusal> {
    let args: Vec<Arg> = args
        .into_iter()
        .map(|(at, capacity)| {
            if capacity == 0 {
                Arg::Int(at)
            } else {
                Arg::Text(at, capacity as usize)
            }
        })
        .collect();
    let expected: &[bool] = match function {
        StdFunction::Len => &[true],
        StdFunction::Left | StdFunction::Right => &[true, false],
        StdFunction::Mid | StdFunction::Delete => &[true, false, false],
        StdFunction::Concat | StdFunction::Find | StdFunction::Compare => &[true, true],
        StdFunction::Insert => &[true, true, false],
        StdFunction::Replace => &[true, true, false, false],
        StdFunction::Recode => &[true],
    };
    let shape_ok = args.len() == expected.len()
        && args
            .iter()
            .zip(expected)
            .all(|(arg, text)| matches!(arg, Arg::Text(..)) == *text);
    if !shape_ok {
        return Err(LowerRefusal::StringArguments { function });
    }
    if function == StdFunction::Recode {
        return Ok(recode(wide, dst, &args));
    }
    Ok(if wide {
        run::<u16>(function, dst, args)
    } else {
        run::<u8>(function, dst, args)
    })
}

/// `STRING_TO_WSTRING` (from narrow when `wide` is false) and `WSTRING_TO_STRING`: each
/// character keeps its code; a wide one above 255 is skipped, as TwinCAT's WSTRING_TO_STRING2
/// skips what it cannot convert.
fn recode(wide: bool, dst: (Addr, u32), args: &[Arg]) -> Op {
    let (dst, capacity) = (dst.0, dst.1 as usize);
    let (src, src_capacity) = match args.first() {
        Some(Arg::Text(at, capacity)) => (*at, *capacity),
        _ => (dst, 0),
    };
    Box::new(move |x| {
        if wide {
            let text: Vec<u8> = u16::load(x, src, src_capacity)?
                .into_iter()
                .filter_map(|unit| u8::try_from(unit).ok())
                .collect();
            u8::store(x, dst, capacity, &text)?;
        } else {
            let text: Vec<u16> = u8::load(x, src, src_capacity)?
                .into_iter()
                .map(u16::from)
                .collect();
            u16::store(x, dst, capacity, &text)?;
        }
        Ok(Flow::Next)
    })
}

fn run<C: Unit>(function: StdFunction, dst: (Addr, u32), args: Vec<Arg>) -> Op {
    let (dst, capacity) = (dst.0, dst.1 as usize);
    Box::new(move |x| {
        let text = |x: &Exec<'_>, i: usize| match args[i] {
            Arg::Text(at, capacity) => C::load(x, at, capacity),
            Arg::Int(_) => Ok(Vec::new()),
        };
        let int = |x: &Exec<'_>, i: usize| match args[i] {
            Arg::Int(at) => x.get::<i32>(at).map(i64::from),
            Arg::Text(..) => Ok(0),
        };
        let result = match function {
            StdFunction::Len => {
                x.set::<i32>(dst, string::len(&text(x, 0)?) as i32)?;
                return Ok(Flow::Next);
            }
            StdFunction::Find => {
                x.set::<i32>(dst, string::find(&text(x, 0)?, &text(x, 1)?) as i32)?;
                return Ok(Flow::Next);
            }
            StdFunction::Compare => {
                let ordering = text(x, 0)?.cmp(&text(x, 1)?);
                x.set::<i32>(dst, ordering as i32)?;
                return Ok(Flow::Next);
            }
            StdFunction::Left => string::left(&text(x, 0)?, int(x, 1)?),
            StdFunction::Right => string::right(&text(x, 0)?, int(x, 1)?),
            StdFunction::Mid => string::mid(&text(x, 0)?, int(x, 1)?, int(x, 2)?),
            StdFunction::Concat => string::concat(&text(x, 0)?, &text(x, 1)?),
            StdFunction::Insert => string::insert(&text(x, 0)?, &text(x, 1)?, int(x, 2)?),
            StdFunction::Delete => string::delete(&text(x, 0)?, int(x, 1)?, int(x, 2)?),
            StdFunction::Replace => {
                string::replace(&text(x, 0)?, &text(x, 1)?, int(x, 2)?, int(x, 3)?)
            }
            // Lowered by `recode` before `run` is reached.
            StdFunction::Recode => return Ok(Flow::Next),
        };
        C::store(x, dst, capacity, &result)?;
        Ok(Flow::Next)
    })
}

/// `*_TO_STRING`: the value's text, cut to the string's capacity.
pub(crate) fn to_text(from: Elementary, wide: bool, dst: Addr, capacity: u32, src: Addr) -> Op {
    let capacity = capacity as usize;
    Box::new(move |x| {
        let raw = super::lower::read_raw(x, src, from)?;
        if wide {
            u16::store(x, dst, capacity, &text::to_wtext(raw, from))?;
        } else {
            u8::store(x, dst, capacity, &text::to_text_bytes(raw, from))?;
        }
        Ok(Flow::Next)
    })
}

/// `STRING_TO_*`: the value the text spells.
pub(crate) fn from_text(to: Elementary, wide: bool, dst: Addr, src: Addr, capacity: u32) -> Op {
    let capacity = capacity as usize;
    Box::new(move |x| {
        let raw = if wide {
            text::from_wtext(&u16::load(x, src, capacity)?, to)
        } else {
            text::from_text(&u8::load(x, src, capacity)?, to)
        };
        super::lower::write_raw(x, dst, to, raw)?;
        Ok(Flow::Next)
    })
}
