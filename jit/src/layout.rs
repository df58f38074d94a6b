//! Where the regions of an image lie in the engine's memory, and the pointer values of
//! `docs/program-image.md` §5.2, exactly as the runtime's `engine/memory.rs` computes them.

use program_image::{Operand, ProgramImage};

use crate::isa::NativeUnsupported;

/// The pointer tag of the data region.
pub(crate) const TAG_DATA: u64 = 1;
/// The pointer tag of the running task's stack.
pub(crate) const TAG_STACK: u64 = 2;
/// The pointer tag of `%I`.
pub(crate) const TAG_INPUT: u64 = 3;
/// The pointer tag of `%Q`.
pub(crate) const TAG_OUTPUT: u64 = 4;
/// The pointer tag of `%M`.
pub(crate) const TAG_MEMORY: u64 = 5;
/// The pointer tag of the constant pool.
pub(crate) const TAG_CONST: u64 = 6;
/// The bits of a pointer below its tag: the offset in its region.
pub(crate) const POINTER_OFFSET_MASK: u64 = (1 << 56) - 1;

/// The absolute offsets of the regions in the engine's one memory (data, `%I`, `%Q`, `%M`,
/// constants, then one stack per task), given by the runtime (`docs/native-engine.md` §4.2).
///
/// [`Layout::of`] computes it as the runtime's `Regions::of` does; the translator refuses a
/// layout whose region sizes disagree with the image it translates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Start of the data region (globals and program instances).
    pub data: u64,
    /// Start of `%I`.
    pub input: u64,
    /// Start of `%Q`.
    pub output: u64,
    /// Start of `%M`.
    pub memory: u64,
    /// Start of the constant pool.
    pub constants: u64,
    /// Start of the first task's stack.
    pub stacks: u64,
    /// Bytes of one task's stack.
    pub stack_size: u64,
    /// Bytes of the whole memory.
    pub total: u64,
}

impl Layout {
    /// The layout of `image` with `tasks` stacks (at least one), as the runtime lays it out.
    pub fn of(image: &ProgramImage, tasks: usize) -> Self {
        let sizes = &image.layout;
        let data = 0;
        let input = data + u64::from(sizes.data_size);
        let output = input + u64::from(sizes.input_size);
        let memory = output + u64::from(sizes.output_size);
        let constants = memory + u64::from(sizes.memory_size);
        let stacks = constants + image.constants.len() as u64;
        let stack_size = u64::from(sizes.stack_size);
        Self {
            data,
            input,
            output,
            memory,
            constants,
            stacks,
            stack_size,
            total: stacks + stack_size * tasks.max(1) as u64,
        }
    }

    /// The spans pointers resolve against, by tag (0–7): start and end offsets; tag 2 is the
    /// stack that ends at `stack_end`; tags 0 and 7 are empty.
    pub fn spans(&self, stack_end: u64) -> [[u64; 2]; 8] {
        let mut spans = [[0; 2]; 8];
        for (tag, start, end) in self.tagged_spans(stack_end) {
            spans[tag as usize] = [start, end];
        }
        spans
    }

    /// The spans in the order the runtime searches them when it makes a pointer.
    fn tagged_spans(&self, stack_end: u64) -> [(u64, u64, u64); 6] {
        [
            (TAG_DATA, self.data, self.input),
            (TAG_INPUT, self.input, self.output),
            (TAG_OUTPUT, self.output, self.memory),
            (TAG_MEMORY, self.memory, self.constants),
            (TAG_CONST, self.constants, self.stacks),
            (
                TAG_STACK,
                stack_end.saturating_sub(self.stack_size),
                stack_end,
            ),
        ]
    }

    /// The spans of the fixed regions (everything but the stack), in search order.
    pub(crate) fn fixed_spans(&self) -> [(u64, u64, u64); 5] {
        let [data, input, output, memory, constants, _] = self.tagged_spans(0);
        [data, input, output, memory, constants]
    }

    /// The pointer value of the absolute offset `at`, as seen from the task whose stack ends
    /// at `stack_end`: the first span holding `at` (an empty span holds its start), 0 if none.
    pub fn pointer_to(&self, at: u64, stack_end: u64) -> u64 {
        for (tag, start, end) in self.tagged_spans(stack_end) {
            if at >= start && at < end.max(start + 1) {
                return (tag << 56) | (at - start);
            }
        }
        0
    }

    /// The absolute offset of a direct operand of a fixed region, `None` for `Instance` and
    /// `Frame`, whose base is known only at run time.
    pub(crate) fn absolute(&self, operand: Operand) -> Option<u64> {
        let (start, offset) = match operand {
            Operand::Global(o) => (self.data, o),
            Operand::Input(o) => (self.input, o),
            Operand::Output(o) => (self.output, o),
            Operand::Memory(o) => (self.memory, o),
            Operand::Const(o) => (self.constants, o),
            Operand::Instance(_) | Operand::Frame(_) => return None,
        };
        Some(start + u64::from(offset))
    }

    /// Refuses a layout that is not the one of `image`: generated code addresses the fixed
    /// regions at these offsets, so they must be where verification proved the operands.
    pub(crate) fn check(&self, image: &ProgramImage) -> Result<(), NativeUnsupported> {
        let expected = Self::of(image, 1);
        let fixed_agree = self.data == expected.data
            && self.input == expected.input
            && self.output == expected.output
            && self.memory == expected.memory
            && self.constants == expected.constants
            && self.stacks == expected.stacks
            && self.stack_size == expected.stack_size;
        let stacks_fit = self.total >= self.stacks.saturating_add(self.stack_size);
        if fixed_agree && stacks_fit {
            Ok(())
        } else {
            Err(NativeUnsupported::LayoutMismatch {
                layout: format!("{self:?}"),
                image: format!("{expected:?}"),
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn layout() -> Layout {
        Layout {
            data: 0,
            input: 16,
            output: 16,
            memory: 24,
            constants: 32,
            stacks: 40,
            stack_size: 100,
            total: 240,
        }
    }

    #[test]
    fn pointers_are_made_as_the_runtime_makes_them() {
        let layout = layout();
        assert_eq!(layout.pointer_to(3, 240), (TAG_DATA << 56) | 3);
        // An empty %I holds its start, which is also %Q's start: the first span wins.
        assert_eq!(layout.pointer_to(16, 240), TAG_INPUT << 56);
        assert_eq!(layout.pointer_to(17, 240), (TAG_OUTPUT << 56) | 1);
        assert_eq!(layout.pointer_to(33, 240), (TAG_CONST << 56) | 1);
        // The first task's stack is not the running task's: no pointer.
        assert_eq!(layout.pointer_to(50, 240), 0);
        assert_eq!(layout.pointer_to(150, 240), (TAG_STACK << 56) | 10);
        assert_eq!(layout.spans(240)[TAG_STACK as usize], [140, 240]);
        assert_eq!(layout.spans(240)[0], [0, 0]);
        assert_eq!(layout.spans(240)[7], [0, 0]);
    }
}
