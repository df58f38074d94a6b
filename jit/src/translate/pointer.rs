//! Pointer values: `Address`, `Element`, `Offset`, and resolving a pointer for `Load` and
//! `Store` against the region spans; the fused element accesses `LoadElement` and
//! `StoreElement`, which check their index as `Element` does (`docs/native-engine.md` §5.4,
//! §7, §10).

use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{InstBuilder, Type, Value, types};
use program_image::{Elementary, Operand};

use super::call::displaced;
use super::counted::interpreter_high;
use super::{Translator, context_flags, int_type, is_signed, memory_flags};
use crate::context;
use crate::fault_kind;
use crate::layout::{POINTER_OFFSET_MASK, TAG_STACK};

impl Translator<'_, '_> {
    /// The pointer value of a direct place (`Address`): a constant for the fixed regions, made
    /// at run time for instance and frame places, searching the spans in the runtime's order.
    pub(crate) fn address_of(&mut self, place: Operand) -> Value {
        let fixed = self.layout.absolute(place);
        if let Some(at) = fixed {
            // A fixed place inside its own region (or at an earlier empty one) matches it
            // before the stack, so its pointer does not depend on the running task. One that
            // matches no fixed span (the zero-size place at the end of the constant pool,
            // which is where the first task's stack starts) is searched at run time like an
            // instance or frame place, as the interpreter's `pointer_to` does.
            let pointer = self.layout.pointer_to(at, 0);
            if pointer != 0 {
                return self.builder.ins().iconst(types::I64, pointer as i64);
            }
        }
        let at = match fixed {
            Some(at) => self.builder.ins().iconst(types::I64, at as i64),
            None => self.absolute(place),
        };
        let stack_end = self.builder.ins().load(
            types::I64,
            context_flags(),
            self.context,
            context::STACK_END,
        );
        let stack_size = self.layout.stack_size;
        // The stack span: `stack_end.saturating_sub(stack_size) .. stack_end`.
        let room = self.builder.ins().icmp_imm_u(
            IntCC::UnsignedGreaterThanOrEqual,
            stack_end,
            stack_size as i64,
        );
        let below = self
            .builder
            .ins()
            .iadd_imm_s(stack_end, -(stack_size as i64));
        let zero = self.builder.ins().iconst(types::I64, 0);
        let stack_start = self.builder.ins().select(room, below, zero);
        let stack_start_plus_one = self.builder.ins().iadd_imm_u(stack_start, 1);
        let stack_limit = self.builder.ins().umax(stack_end, stack_start_plus_one);
        // Built from the last span to the first, so the first match wins.
        let mut pointer = self.span_pointer(at, TAG_STACK, stack_start, stack_limit, zero);
        for (tag, start, end) in self.layout.fixed_spans().into_iter().rev() {
            let start_value = self.builder.ins().iconst(types::I64, start as i64);
            let limit = self
                .builder
                .ins()
                .iconst(types::I64, end.max(start + 1) as i64);
            pointer = self.span_pointer(at, tag, start_value, limit, pointer);
        }
        pointer
    }

    /// `(tag << 56) | (at - start)` when `start <= at < limit`, else `otherwise`.
    fn span_pointer(
        &mut self,
        at: Value,
        tag: u64,
        start: Value,
        limit: Value,
        otherwise: Value,
    ) -> Value {
        let above = self
            .builder
            .ins()
            .icmp(IntCC::UnsignedGreaterThanOrEqual, at, start);
        let below = self.builder.ins().icmp(IntCC::UnsignedLessThan, at, limit);
        let inside = self.builder.ins().band(above, below);
        let offset = self.builder.ins().isub(at, start);
        let tagged = self.builder.ins().bor_imm_u(offset, (tag << 56) as i64);
        self.builder.ins().select(inside, tagged, otherwise)
    }

    /// `Element`: the index checked against `low ..= high` (a fault outside), then
    /// `dst := base + (index − low) · stride`, wrapping.
    pub(crate) fn element(
        &mut self,
        dst: Operand,
        base: Operand,
        (index, index_ty): (Operand, Elementary),
        low: i64,
        count: u64,
        stride: u32,
    ) {
        let moved = self.checked_element_offset((index, index_ty), low, count, stride);
        let pointer = self.load(types::I64, base);
        let result = self.builder.ins().iadd(pointer, moved);
        self.store(result, dst);
    }

    /// The bytes from an array's first element to element `index`, `(index − low) · stride`,
    /// after checking the index against `low ..= high` with `high` computed as the
    /// interpreter computes it, so a fault reports the same bounds.
    fn checked_element_offset(
        &mut self,
        index: (Operand, Elementary),
        low: i64,
        count: u64,
        stride: u32,
    ) -> Value {
        let (scaled, bias) = self.checked_scaled_index(index, low, count, stride);
        self.builder.ins().iadd_imm_s(scaled, bias)
    }

    /// The checked element offset as `index · stride` and the constant `−low · stride`, whose
    /// wrapping sum it is: the constant can then join an access's displacement, leaving one
    /// addressing mode (base, index scaled, displacement) per element access.
    fn checked_scaled_index(
        &mut self,
        (index, index_ty): (Operand, Elementary),
        low: i64,
        count: u64,
        stride: u32,
    ) -> (Value, i64) {
        let i = self.index_value(index, index_ty);
        // In a counted loop's promoted copy the preheader checked this index for every value
        // the counter takes (`counted.rs`).
        if !self.check_made_in_preheader() {
            let low_value = self.builder.ins().iconst(types::I64, low);
            let high = interpreter_high(low, count);
            let high_value = self.builder.ins().iconst(types::I64, high);
            self.check_index(i, index_ty, low_value, high_value);
        }
        let scaled = self.builder.ins().imul_imm_u(i, i64::from(stride));
        (scaled, low.wrapping_mul(i64::from(stride)).wrapping_neg())
    }

    /// The machine address and displacement of the value a `LoadElement` or `StoreElement`
    /// reaches: the array's own address (a direct place, as any operand's) plus the checked
    /// element offset, with the member's `offset` as the displacement. The verifier checked
    /// that the whole array lies inside its region, and the index is checked, so the access
    /// stays inside the region as the interpreter's does (§7).
    fn element_address(
        &mut self,
        array: Operand,
        index: (Operand, Elementary),
        (low, count, stride): (i64, u64, u32),
        offset: u32,
    ) -> (Value, i32) {
        let (scaled, bias) = self.checked_scaled_index(index, low, count, stride);
        let (address, displacement) = self.based_operand_address(array);
        let element = self.builder.ins().iadd(address, scaled);
        // The displacement, the member's offset and the bias, wrapping as the address does.
        let reach = i64::from(displacement)
            .wrapping_add(i64::from(offset))
            .wrapping_add(bias);
        match i32::try_from(reach) {
            Ok(displacement) => (element, displacement),
            Err(_) => (self.builder.ins().iadd_imm_s(element, reach), 0),
        }
    }

    /// `LoadElement`: the index checked as `Element`, then `dst :=` the `ty` value at
    /// `array + (index − low) · stride + offset`.
    pub(crate) fn load_element(
        &mut self,
        (ty, dst): (Type, Operand),
        array: Operand,
        index: (Operand, Elementary),
        bounds: (i64, u64, u32),
        offset: u32,
    ) {
        let (address, displacement) = self.element_address(array, index, bounds, offset);
        let value = self
            .builder
            .ins()
            .load(ty, memory_flags(), address, displacement);
        self.store(value, dst);
    }

    /// `StoreElement`: the value `src` read first, as the interpreter reads it, then the index
    /// checked as `Element` and the value stored at `array + (index − low) · stride + offset`.
    pub(crate) fn store_element(
        &mut self,
        (ty, src): (Type, Operand),
        array: Operand,
        index: (Operand, Elementary),
        bounds: (i64, u64, u32),
        offset: u32,
    ) {
        let value = self.load(ty, src);
        let (address, displacement) = self.element_address(array, index, bounds, offset);
        self.builder
            .ins()
            .store(memory_flags(), value, address, displacement);
    }

    /// `OpenElement`: per dimension, the bounds read from the descriptor (pointer, then low
    /// and high of each dimension as `i64`), the index checked against them (a fault outside,
    /// with the bounds read), the linear index `linear · count + (index − low)` wrapping; then
    /// `dst := pointer + linear · stride`, wrapping, as the interpreter computes it.
    pub(crate) fn open_element(
        &mut self,
        dst: Operand,
        descriptor: Operand,
        indices: &[(Operand, Elementary)],
        stride: u32,
    ) {
        let pointer = self.load(types::I64, descriptor);
        let mut linear = self.builder.ins().iconst(types::I64, 0);
        for (dimension, (index, index_ty)) in indices.iter().enumerate() {
            let bounds = 8 + 16 * dimension as u32;
            let low = self.load(types::I64, displaced(descriptor, bounds));
            let high = self.load(types::I64, displaced(descriptor, bounds + 8));
            let i = self.index_value(*index, *index_ty);
            self.check_index(i, *index_ty, low, high);
            let span = self.builder.ins().isub(high, low);
            let count = self.builder.ins().iadd_imm_u(span, 1);
            let scaled = self.builder.ins().imul(linear, count);
            let from_low = self.builder.ins().isub(i, low);
            linear = self.builder.ins().iadd(scaled, from_low);
        }
        let moved = self.builder.ins().imul_imm_u(linear, i64::from(stride));
        let result = self.builder.ins().iadd(pointer, moved);
        self.store(result, dst);
    }

    /// Faults unless the index `i` (from [`Self::index_value`]) lies in `low ..= high`, as the
    /// interpreter checks it. An unsigned 64-bit index (`ULINT`, `LWORD`) above `i64::MAX`
    /// reads as negative in `i`, so it is refused on its own (a negative low bound would let
    /// it pass) and reported saturated, as index `i64::MAX`.
    fn check_index(&mut self, i: Value, index_ty: Elementary, low: Value, high: Value) {
        let under = self.builder.ins().icmp(IntCC::SignedLessThan, i, low);
        let over = self.builder.ins().icmp(IntCC::SignedGreaterThan, i, high);
        let mut outside = self.builder.ins().bor(under, over);
        let mut reported = i;
        if !is_signed(index_ty) && index_ty.size_bytes() == 8 {
            let beyond_i64 = self.builder.ins().icmp_imm_s(IntCC::SignedLessThan, i, 0);
            outside = self.builder.ins().bor(outside, beyond_i64);
            let saturated = self.builder.ins().iconst(types::I64, i64::MAX);
            reported = self.builder.ins().select(beyond_i64, saturated, i);
        }
        self.fault_if(
            outside,
            fault_kind::INDEX_OUT_OF_BOUNDS,
            [Some(reported), Some(low), Some(high)],
        );
    }

    /// An index operand as the interpreter reads it: extended to 64 bits by its type's
    /// signedness (an `ULINT` above 2⁶³ becomes negative, which [`Self::check_index`] refuses).
    fn index_value(&mut self, index: Operand, index_ty: Elementary) -> Value {
        let ir = int_type(index_ty);
        let value = self.load(ir, index);
        self.resized(value, ir, types::I64, is_signed(index_ty))
    }

    /// `Offset`: a null pointer faults; `dst := base + offset`, wrapping.
    pub(crate) fn offset(&mut self, dst: Operand, base: Operand, offset: u32) {
        let pointer = self.load(types::I64, base);
        let tag = self.builder.ins().ushr_imm_u(pointer, 56);
        let null = self.builder.ins().icmp_imm_u(IntCC::Equal, tag, 0);
        self.fault_if(null, fault_kind::NULL_POINTER, [None; 3]);
        let moved = self.builder.ins().iadd_imm_u(pointer, i64::from(offset));
        self.store(moved, dst);
    }

    /// The absolute offset the pointer in `operand` reaches, checked for `size` bytes: tag 0
    /// is `NullPointer`; a tag above 6 or a range past its region's end `BadPointer`.
    pub(crate) fn resolve(&mut self, operand: Operand, size: u32) -> Value {
        let pointer = self.load(types::I64, operand);
        let tag = self.builder.ins().ushr_imm_u(pointer, 56);
        let null = self.builder.ins().icmp_imm_u(IntCC::Equal, tag, 0);
        self.fault_if(null, fault_kind::NULL_POINTER, [None; 3]);
        let unknown = self
            .builder
            .ins()
            .icmp_imm_u(IntCC::UnsignedGreaterThan, tag, 6);
        self.fault_if(
            unknown,
            fault_kind::BAD_POINTER,
            [Some(pointer), None, None],
        );
        // spans[tag] is at SPANS + 16 · tag in the context.
        let span_offset = self.builder.ins().imul_imm_u(tag, 16);
        let span = self.builder.ins().iadd(self.context, span_offset);
        let start = self
            .builder
            .ins()
            .load(types::I64, context_flags(), span, context::SPANS);
        let end = self
            .builder
            .ins()
            .load(types::I64, context_flags(), span, context::SPANS + 8);
        let offset = self
            .builder
            .ins()
            .band_imm_u(pointer, POINTER_OFFSET_MASK as i64);
        // No overflow: the offset is below 2⁵⁶, start and size below 2³² · a few.
        let at = self.builder.ins().iadd(start, offset);
        let last = self.builder.ins().iadd_imm_u(at, i64::from(size));
        let past = self
            .builder
            .ins()
            .icmp(IntCC::UnsignedGreaterThan, last, end);
        self.fault_if(past, fault_kind::BAD_POINTER, [Some(pointer), None, None]);
        at
    }
}
