//! Loop promotion (`docs/native-engine.md` §5.3): a scalar place read and written in a loop
//! is kept in an SSA variable across the loop's iterations, so that a `FOR` variable or an
//! accumulator does not put a store-to-load dependency on every iteration.
//!
//! The analysis finds loops from backward jumps, keeps those whose body makes no call and
//! reaches no memory through a pointer, and promotes the places every access of which in the
//! body is the same direct operand of the same size, all other accesses being provably
//! disjoint from it. The translator then loads the places on entry to the loop (a preheader
//! block that every entry from outside goes through), writes them back on every exit, on
//! every fault, and before every callback (the back-edge's `rivet_jit_tick` among them), and
//! loads them again after a callback: at every safe point, call and fault, memory holds what
//! the interpreter's memory holds.

use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{Block, InstBuilder, MemFlagsData, Type, Value, types};
use program_image::{Elementary, Instr, Operand};

use super::counted::{CountedLoop, Hoisted, counted_loop};
use super::{Translator, memory_flags};
use crate::layout::Layout;

/// The largest copy made by inline loads and stores (a larger one is a callback, a call).
const INLINE_COPY_BYTES: u32 = 64;

#[cfg(test)]
thread_local! {
    /// Set by the tests to translate on the current thread without promotion, and compare.
    pub(crate) static PROMOTION_OFF_IN_TESTS: std::cell::Cell<bool> =
        const { std::cell::Cell::new(false) };
}

/// A loop whose places are promoted: instructions `start ..= end`, the backward jump at `end`.
#[derive(Clone, Debug)]
pub(crate) struct PromotedLoop {
    /// The loop's first instruction, the target of its backward jump.
    pub(crate) start: u32,
    /// The backward jump that closes it.
    pub(crate) end: u32,
    /// The places kept in variables: a direct operand and its size in bytes.
    pub(crate) places: Vec<(Operand, u32)>,
    /// The byte ranges the loop touches per base, when it touches places of more than one
    /// base: the analysis takes places of different bases as disjoint, which a test on entry
    /// confirms, running an unpromoted copy of the loop when they are not.
    pub(crate) guard: Option<Guard>,
    /// When the loop is a counted `FOR` loop, the element accesses by its counter whose
    /// checks its preheader makes (`counted.rs`).
    pub(crate) counted: Option<CountedLoop>,
}

/// The smallest ranges holding every place a loop touches, per base: offsets from the
/// instance, offsets from the frame, absolute offsets in each fixed region.
///
/// The fixed regions get one range each because they are disjoint by the layout and a place
/// in one is compared with places in the others by offset: one range around all of them
/// would span the data region's program instances up to the constant pool and meet the
/// instance whenever a loop touches a global and a constant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Guard {
    /// From the instance: first byte and end.
    pub(crate) instance: Option<(u64, u64)>,
    /// From the frame.
    pub(crate) frame: Option<(u64, u64)>,
    /// In the memory, per fixed region: data, `%I`, `%Q`, `%M`, constants.
    pub(crate) fixed: [Option<(u64, u64)>; 5],
}

#[cfg(test)]
thread_local! {
    /// The guards' outcomes on the current thread: entries into the promoted copy of a
    /// guarded loop and into its unpromoted copy. Generated code translated in a test adds to
    /// them, so that a test sees which copy ran.
    pub(crate) static GUARD_OUTCOMES_IN_TESTS: [std::sync::atomic::AtomicU64; 2] =
        const { [std::sync::atomic::AtomicU64::new(0), std::sync::atomic::AtomicU64::new(0)] };
    /// Where the guards built on the current thread count their outcomes, when not in its own
    /// [`GUARD_OUTCOMES_IN_TESTS`]: a compiling thread (`compile.rs`) counts in the loading
    /// thread's, which outlives it and which the test reads.
    pub(crate) static GUARD_OUTCOMES_AT_IN_TESTS: std::cell::Cell<Option<usize>> =
        const { std::cell::Cell::new(None) };
}

/// The address of the outcome counters the guards built on the current thread add to.
#[cfg(test)]
pub(crate) fn guard_outcomes_address_in_tests() -> usize {
    GUARD_OUTCOMES_AT_IN_TESTS
        .with(std::cell::Cell::get)
        .unwrap_or_else(|| {
            GUARD_OUTCOMES_IN_TESTS.with(|outcomes| std::ptr::from_ref(outcomes) as usize)
        })
}

/// How an instruction touches a direct place.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Access {
    /// Loaded through the translator's `load`.
    Read,
    /// Stored through the translator's `store`.
    Write,
    /// Read or written as bytes by an inline copy or an element access, which bypass `load`
    /// and `store`.
    Raw,
}

/// Where a direct place lies: at a fixed offset of the memory, or at an offset from the
/// instance or the frame, which are only known at run time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Base {
    Fixed(u64),
    Instance(u64),
    Frame(u64),
}

fn base(operand: Operand, layout: &Layout) -> Base {
    match operand {
        Operand::Instance(offset) => Base::Instance(u64::from(offset)),
        Operand::Frame(offset) => Base::Frame(u64::from(offset)),
        fixed => Base::Fixed(layout.absolute(fixed).unwrap_or(0)),
    }
}

/// Whether `size_a` bytes at `a` and `size_b` bytes at `b` may share a byte, in a promoted
/// loop: places of the same base are compared by offset; places of different bases are
/// disjoint, as the loop's [`Guard`] confirms on entry.
pub(crate) fn may_overlap(
    layout: &Layout,
    (a, size_a): (Operand, u32),
    (b, size_b): (Operand, u32),
) -> bool {
    let overlap = |x: u64, y: u64| x < y + u64::from(size_b) && y < x + u64::from(size_a);
    match (base(a, layout), base(b, layout)) {
        (Base::Fixed(x), Base::Fixed(y))
        | (Base::Instance(x), Base::Instance(y))
        | (Base::Frame(x), Base::Frame(y)) => overlap(x, y),
        _ => false,
    }
}

/// The index in [`Guard::fixed`] of a fixed operand's region.
fn fixed_region(operand: Operand) -> usize {
    match operand {
        Operand::Input(_) => 1,
        Operand::Output(_) => 2,
        Operand::Memory(_) => 3,
        Operand::Const(_) => 4,
        _ => 0,
    }
}

/// The guard of the places `all` a loop touches: `None` when they all have one base (the
/// fixed regions being one base, disjoint by the layout).
fn guard(layout: &Layout, all: &[(Operand, u32, Access)]) -> Option<Guard> {
    let mut guard = Guard::default();
    let widen = |range: &mut Option<(u64, u64)>, at: u64, size: u32| {
        let end = at + u64::from(size);
        *range = Some(match *range {
            Some((first, last)) => (first.min(at), last.max(end)),
            None => (at, end),
        });
    };
    for (operand, size, _) in all {
        match base(*operand, layout) {
            Base::Instance(at) => widen(&mut guard.instance, at, *size),
            Base::Frame(at) => widen(&mut guard.frame, at, *size),
            Base::Fixed(at) => widen(&mut guard.fixed[fixed_region(*operand)], at, *size),
        }
    }
    let fixed = guard.fixed.iter().any(Option::is_some);
    let bases = usize::from(guard.instance.is_some())
        + usize::from(guard.frame.is_some())
        + usize::from(fixed);
    (bases > 1).then_some(guard)
}

/// The direct places an instruction touches, as the translator emits it; `None` for an
/// instruction a promoting loop must not contain: a call of any kind (a host operation, a
/// copy larger than 64 bytes) or an access through a pointer, which may reach any place. An
/// element access (`LoadElement`, `StoreElement`) touches its whole array.
pub(crate) fn accesses(instr: &Instr) -> Option<Vec<(Operand, u32, Access)>> {
    use Access::{Raw, Read, Write};
    let size = |ty: &Elementary| ty.size_bytes();
    Some(match instr {
        Instr::Move { ty, dst, src } => vec![(*src, size(ty), Read), (*dst, size(ty), Write)],
        Instr::Copy { size, dst, src } if *size <= INLINE_COPY_BYTES => {
            vec![(*src, *size, Raw), (*dst, *size, Raw)]
        }
        Instr::Unary { ty, dst, src, .. } => {
            vec![(*src, size(ty), Read), (*dst, size(ty), Write)]
        }
        Instr::Binary { ty, dst, a, b, .. } => vec![
            (*a, size(ty), Read),
            (*b, size(ty), Read),
            (*dst, size(ty), Write),
        ],
        Instr::Compare { ty, dst, a, b, .. } => {
            vec![(*a, size(ty), Read), (*b, size(ty), Read), (*dst, 1, Write)]
        }
        Instr::Convert { from, to, dst, src } | Instr::Trunc { from, to, dst, src } => {
            vec![(*src, size(from), Read), (*dst, size(to), Write)]
        }
        Instr::GetBit { ty, dst, src, .. } => vec![(*src, size(ty), Read), (*dst, 1, Write)],
        Instr::SetBit { ty, dst, src, .. } => vec![
            (*dst, size(ty), Read),
            (*src, 1, Read),
            (*dst, size(ty), Write),
        ],
        // The place's address is made, not read.
        Instr::Address { dst, .. } => vec![(*dst, 8, Write)],
        Instr::Element {
            dst,
            base,
            index,
            index_ty,
            ..
        } => vec![
            (*index, size(index_ty), Read),
            (*base, 8, Read),
            (*dst, 8, Write),
        ],
        Instr::Offset { dst, base, .. } => vec![(*base, 8, Read), (*dst, 8, Write)],
        // The element itself is reached at a computed address, past `load` and `store`: the
        // whole array is touched as bytes, so no place inside it is promoted and the guard
        // covers it. An array too large to name in one access is not promoted.
        Instr::LoadElement {
            ty,
            dst,
            array,
            index,
            index_ty,
            count,
            stride,
            ..
        } => vec![
            (*index, size(index_ty), Read),
            (*array, array_extent(*count, *stride)?, Raw),
            (*dst, size(ty), Write),
        ],
        Instr::StoreElement {
            ty,
            array,
            index,
            index_ty,
            count,
            stride,
            src,
            ..
        } => vec![
            (*src, size(ty), Read),
            (*index, size(index_ty), Read),
            (*array, array_extent(*count, *stride)?, Raw),
        ],
        Instr::Now { dst } => vec![(*dst, 8, Write)],
        // A return writes the places back first.
        Instr::Jump { .. } | Instr::Return => Vec::new(),
        Instr::JumpIf { cond, .. } | Instr::JumpIfNot { cond, .. } => vec![(*cond, 1, Read)],
        _ => return None,
    })
}

/// The bytes an array of `count` elements of `stride` bytes spans, when they fit a `u32`.
fn array_extent(count: u64, stride: u32) -> Option<u32> {
    u32::try_from(count.checked_mul(u64::from(stride))?).ok()
}

pub(crate) fn jump_target(instr: &Instr) -> Option<u32> {
    match instr {
        Instr::Jump { target } | Instr::JumpIf { target, .. } | Instr::JumpIfNot { target, .. } => {
            Some(*target)
        }
        _ => None,
    }
}

/// The loops of `code` whose places may be promoted, disjoint, in code order. Inner loops are
/// preferred: they run most often. `folded_constants` is the constant pool when its values
/// are folded into the code: reads of it then touch no memory and need no guard.
pub(crate) fn promotable_loops(
    code: &[Instr],
    layout: &Layout,
    folded_constants: Option<&[u8]>,
) -> Vec<PromotedLoop> {
    #[cfg(test)]
    if PROMOTION_OFF_IN_TESTS.with(std::cell::Cell::get) {
        return Vec::new();
    }
    let mut regions: Vec<(u32, u32)> = code
        .iter()
        .enumerate()
        .filter_map(|(pc, instr)| {
            let target = jump_target(instr)?;
            (target as usize <= pc).then_some((target, pc as u32))
        })
        .collect();
    regions.sort_by_key(|(start, end)| (end - start, *start));
    let mut chosen: Vec<PromotedLoop> = Vec::new();
    for (start, end) in regions {
        if chosen
            .iter()
            .any(|known| start <= known.end && known.start <= end)
        {
            continue;
        }
        if let Some(promoted) = analyse(code, layout, folded_constants, start, end) {
            chosen.push(promoted);
        }
    }
    chosen.sort_by_key(|promoted| promoted.start);
    chosen
}

/// The places of loop `start ..= end` that may be promoted, if it has any.
fn analyse(
    code: &[Instr],
    layout: &Layout,
    folded_constants: Option<&[u8]>,
    start: u32,
    end: u32,
) -> Option<PromotedLoop> {
    let inside = |index: u32| (start..=end).contains(&index);
    // Entered only at its start: a jump from outside into its middle would skip the loads.
    for (pc, instr) in code.iter().enumerate() {
        if let Some(target) = jump_target(instr)
            && !inside(pc as u32)
            && target > start
            && target <= end
        {
            return None;
        }
    }
    let mut all = Vec::new();
    for pc in start..=end {
        let instr = code.get(pc as usize)?;
        // A jump out backwards would leave through a back-edge; the enclosing loop may be
        // promoted instead.
        if jump_target(instr).is_some_and(|target| target < start) {
            return None;
        }
        all.extend(accesses(instr)?);
    }
    // A read the translator answers with an immediate (`Translator::load`) touches no
    // memory: it can neither meet a promoted place nor widen the guard.
    all.retain(
        |(operand, size, access)| match (operand, access, folded_constants) {
            (Operand::Const(offset), Access::Read, Some(pool)) => {
                let first = *offset as usize;
                pool.get(first..first.saturating_add(*size as usize))
                    .is_none()
            }
            _ => true,
        },
    );
    let mut places: Vec<(Operand, u32)> = Vec::new();
    for (operand, size, access) in &all {
        let place = (*operand, *size);
        if *access != Access::Write
            || matches!(operand, Operand::Const(_))
            || places.contains(&place)
        {
            continue;
        }
        let read = all.iter().any(|(other, other_size, kind)| {
            (*other, *other_size) == place && *kind == Access::Read
        });
        let alone = all.iter().all(|(other, other_size, kind)| {
            let same = (*other, *other_size) == place && *kind != Access::Raw;
            same || !may_overlap(layout, place, (*other, *other_size))
        });
        if read && alone {
            places.push(place);
        }
    }
    if places.is_empty() {
        return None;
    }
    let counted = counted_loop(code, layout, (start, end), &places);
    Some(PromotedLoop {
        start,
        end,
        places,
        guard: guard(layout, &all),
        counted,
    })
}

/// The integer IR type of a promoted place's size.
fn place_type(size: u32) -> Type {
    match size {
        1 => types::I8,
        2 => types::I16,
        4 => types::I32,
        _ => types::I64,
    }
}

impl Translator<'_, '_> {
    /// The promoted loop that starts at instruction `index`, if any.
    pub(crate) fn loop_starting_at(&self, index: usize) -> Option<usize> {
        self.promoted_loops
            .iter()
            .position(|promoted| promoted.start as usize == index)
    }

    /// Emits promoted loop `position`: its preheader (every entry from outside goes through
    /// it), which tests the guard and, for a counted loop, the checks it makes for the whole
    /// loop, and runs an unpromoted copy of the loop when either fails, else loads the places
    /// into variables; then the loop on those variables, which writes them back on every way
    /// out. Returns whether control falls through past the loop's end.
    pub(crate) fn promoted_loop(&mut self, position: usize, reachable: bool) -> bool {
        let promoted = self.promoted_loops[position].clone();
        let (start, end) = (promoted.start as usize, promoted.end as usize);
        let preheader = self.preheaders[position];
        if reachable {
            self.builder.ins().jump(preheader, &[]);
        }
        self.builder.switch_to_block(preheader);
        let overlapping = promoted.guard.map(|guard| self.guard_fails(&guard));
        let counted = promoted
            .counted
            .as_ref()
            .map(|counted| self.counted_checks_fail(counted));
        let fails = match (overlapping, counted.map(|(fails, _)| fails)) {
            (Some(overlapping), Some(unchecked)) => {
                Some(self.builder.ins().bor(overlapping, unchecked))
            }
            (one, other) => one.or(other),
        };
        // The unpromoted copy is emitted only when something can send the loop to it.
        if let Some(fails) = fails {
            let saved = self.blocks.renew(start, end, &mut self.builder);
            let copy = self.blocks.at(start).unwrap_or(self.blocks.end());
            let on_variables = self.builder.create_block();
            #[cfg(not(test))]
            self.builder.ins().brif(fails, copy, &[], on_variables, &[]);
            #[cfg(test)]
            self.counted_guard(fails, copy, on_variables);
            // The copy works on memory; its backward jumps to the start go through the
            // preheader, which tests the guard again.
            let mut falls_through = false;
            for index in start..=end {
                falls_through = self.emit_at(index, falls_through);
            }
            self.blocks.restore(start, saved);
            // The loop ends with its backward jump, after which control never falls.
            debug_assert!(
                !falls_through,
                "a loop that falls through its backward jump"
            );
            self.builder.switch_to_block(on_variables);
        }
        self.promoted = promoted
            .places
            .iter()
            .map(|(operand, size)| {
                let variable = self.builder.declare_var(place_type(*size));
                (*operand, *size, variable)
            })
            .collect();
        self.active_loop = Some(position);
        if let (Some(counted_loop), Some((_, [counter, end_value, step]))) =
            (promoted.counted.as_ref(), counted)
        {
            let ty = place_type(counted_loop.ty.size_bytes());
            self.hoisted = Some(Hoisted {
                start: promoted.start,
                preheader,
                counter: counted_loop.counter,
                accesses: counted_loop.accesses.clone(),
                invariants: vec![
                    (counted_loop.end, ty, end_value),
                    (counted_loop.step, ty, step),
                ],
            });
            // The counter starts from the value the checks were made for.
            if let Some((_, _, variable)) = self
                .promoted
                .iter()
                .find(|(place, _, _)| *place == counted_loop.counter)
            {
                self.builder.def_var(*variable, counter);
            }
        }
        self.reload_promoted();
        let header = self.blocks.at(start).unwrap_or(self.blocks.end());
        self.builder.ins().jump(header, &[]);
        let mut falls_through = false;
        for index in start..=end {
            falls_through = self.emit_at(index, falls_through);
        }
        if falls_through {
            self.write_back();
        }
        self.active_loop = None;
        self.hoisted = None;
        self.promoted.clear();
        falls_through
    }

    /// In tests, the guard's branch through blocks that count its outcome in
    /// [`GUARD_OUTCOMES_IN_TESTS`] on the way to `copy` or `on_variables`.
    #[cfg(test)]
    fn counted_guard(&mut self, overlapping: Value, copy: Block, on_variables: Block) {
        use cranelift_codegen::ir::AtomicRmwOp;
        let counting = [self.builder.create_block(), self.builder.create_block()];
        self.builder
            .ins()
            .brif(overlapping, counting[1], &[], counting[0], &[]);
        for (outcome, destination) in [on_variables, copy].into_iter().enumerate() {
            self.builder.switch_to_block(counting[outcome]);
            let counter = (guard_outcomes_address_in_tests()
                + outcome * size_of::<std::sync::atomic::AtomicU64>())
                as i64;
            let address = self.builder.ins().iconst(types::I64, counter);
            let one = self.builder.ins().iconst(types::I64, 1);
            self.builder.ins().atomic_rmw(
                types::I64,
                MemFlagsData::trusted(),
                AtomicRmwOp::Add,
                address,
                one,
            );
            self.builder.ins().jump(destination, &[]);
        }
    }

    /// Whether the ranges of a guard overlap, for this call's instance and frame: the
    /// instance's range with the frame's, and each with every fixed region's range (the fixed
    /// regions are disjoint by the layout).
    fn guard_fails(&mut self, guard: &Guard) -> Value {
        let mut moving = Vec::new();
        for (base, range) in [(self.instance, guard.instance), (self.frame, guard.frame)] {
            if let Some((first, last)) = range {
                moving.push((
                    self.builder.ins().iadd_imm_u(base, first as i64),
                    self.builder.ins().iadd_imm_u(base, last as i64),
                ));
            }
        }
        let mut fixed = Vec::new();
        for (first, last) in guard.fixed.iter().flatten() {
            fixed.push((
                self.builder.ins().iconst(types::I64, *first as i64),
                self.builder.ins().iconst(types::I64, *last as i64),
            ));
        }
        let mut pairs = Vec::new();
        if let [instance, frame] = moving[..] {
            pairs.push((instance, frame));
        }
        for moving_range in &moving {
            for fixed_range in &fixed {
                pairs.push((*moving_range, *fixed_range));
            }
        }
        let mut any = self.builder.ins().iconst(types::I8, 0);
        for ((first_a, last_a), (first_b, last_b)) in pairs {
            let a_before_b_ends = self
                .builder
                .ins()
                .icmp(IntCC::UnsignedLessThan, first_a, last_b);
            let b_before_a_ends = self
                .builder
                .ins()
                .icmp(IntCC::UnsignedLessThan, first_b, last_a);
            let overlap = self.builder.ins().band(a_before_b_ends, b_before_a_ends);
            any = self.builder.ins().bor(any, overlap);
        }
        any
    }

    /// Where a jump from the current instruction to `index` goes instead of the instruction's
    /// own block: the preheader of a promoted loop entered from outside, or an exit block
    /// that writes the places back when it leaves the active loop.
    pub(crate) fn promoted_destination(&mut self, index: u32, destination: Block) -> Block {
        let active = self.active_loop.map(|position| {
            (
                self.promoted_loops[position].start,
                self.promoted_loops[position].end,
            )
        });
        let leaves_active = active.is_some_and(|(_, end)| index > end);
        let inside_active = active.is_some_and(|(start, end)| (start..=end).contains(&index));
        let destination = match self
            .promoted_loops
            .iter()
            .position(|promoted| promoted.start == index)
        {
            Some(position) if !inside_active => self.preheaders[position],
            _ => destination,
        };
        if !leaves_active {
            return destination;
        }
        let exit = self.builder.create_block();
        self.exits.push((exit, destination));
        exit
    }

    /// Emits the exit blocks of the current instruction: the places written back, then on.
    pub(crate) fn emit_exits(&mut self) {
        for (exit, destination) in std::mem::take(&mut self.exits) {
            self.builder.switch_to_block(exit);
            self.write_back();
            self.builder.ins().jump(destination, &[]);
        }
    }

    /// Stores every promoted place's variable to memory.
    pub(crate) fn write_back(&mut self) {
        for (operand, _, variable) in self.promoted.clone() {
            let value = self.builder.use_var(variable);
            self.raw_store(value, operand);
        }
    }

    /// Loads every promoted place from memory into its variable, but the counter of a counted
    /// loop, which only its preheader and its increment set (`counted.rs`).
    pub(crate) fn reload_promoted(&mut self) {
        let counter = self.hoisted_counter();
        for (operand, size, variable) in self.promoted.clone() {
            if Some(operand) == counter {
                continue;
            }
            let value = self.raw_load(place_type(size), operand);
            self.builder.def_var(variable, value);
        }
    }

    /// A load of `ty` from `operand` answered by a promoted place's variable; `None` for a
    /// place not promoted. A load of bytes a promoted place shares in another shape (which
    /// the analysis excludes) first writes the places back, so memory is current.
    pub(crate) fn promoted_load(&mut self, ty: Type, operand: Operand) -> Option<Value> {
        if self.promoted.is_empty() {
            return None;
        }
        let size = ty.bytes();
        if let Some((_, _, variable)) = self
            .promoted
            .iter()
            .find(|(place, place_size, _)| *place == operand && *place_size == size)
        {
            let value = self.builder.use_var(*variable);
            return Some(if ty.is_float() {
                self.builder.ins().bitcast(ty, MemFlagsData::new(), value)
            } else {
                value
            });
        }
        if self.aliases_promoted(operand, size) {
            self.write_back();
        }
        None
    }

    /// A store into `operand` made to a promoted place's variable: true when it was. A store
    /// to bytes a promoted place shares in another shape (which the analysis excludes) is
    /// made to memory between a write-back and a reload, and is also true.
    pub(crate) fn promoted_store(&mut self, value: Value, operand: Operand) -> bool {
        if self.promoted.is_empty() {
            return false;
        }
        let ty = self.builder.func.dfg.value_type(value);
        let size = ty.bytes();
        if let Some((_, _, variable)) = self
            .promoted
            .iter()
            .find(|(place, place_size, _)| *place == operand && *place_size == size)
        {
            let variable = *variable;
            let value = if ty.is_float() {
                self.builder
                    .ins()
                    .bitcast(place_type(size), MemFlagsData::new(), value)
            } else {
                value
            };
            self.builder.def_var(variable, value);
            return true;
        }
        if !self.aliases_promoted(operand, size) {
            return false;
        }
        self.write_back();
        self.raw_store(value, operand);
        self.reload_promoted();
        true
    }

    /// Before an inline copy of `size` bytes between direct places: the places written back
    /// when the copy may read or write one (which the analysis excludes). Returns whether the
    /// places must be loaded again after it (it may write one).
    pub(crate) fn promoted_copy(&mut self, dst: Operand, src: Operand, size: u32) -> bool {
        if self.promoted.is_empty() || size == 0 {
            return false;
        }
        let writes = self.aliases_promoted(dst, size);
        if writes || self.aliases_promoted(src, size) {
            self.write_back();
        }
        writes
    }

    pub(crate) fn aliases_promoted(&self, operand: Operand, size: u32) -> bool {
        self.promoted.iter().any(|(place, place_size, _)| {
            may_overlap(self.layout, (*place, *place_size), (operand, size))
        })
    }

    /// A store to memory that bypasses promotion.
    fn raw_store(&mut self, value: Value, operand: Operand) {
        let (address, displacement) = self.operand_address(operand);
        self.builder
            .ins()
            .store(memory_flags(), value, address, displacement);
    }

    /// A load from memory that bypasses promotion.
    fn raw_load(&mut self, ty: Type, operand: Operand) -> Value {
        let (address, displacement) = self.operand_address(operand);
        self.builder
            .ins()
            .load(ty, memory_flags(), address, displacement)
    }
}
