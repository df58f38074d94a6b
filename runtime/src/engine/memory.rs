//! Where the regions of an image live in the engine's one memory, and the pointer values of
//! `docs/program-image.md` §5.2 (region in bits 56–63, offset below).

use program_image::{ProgramImage, Region};

use super::fault::FaultKind;

const TAG_DATA: u64 = 1;
const TAG_STACK: u64 = 2;
const TAG_INPUT: u64 = 3;
const TAG_OUTPUT: u64 = 4;
const TAG_MEMORY: u64 = 5;
const TAG_CONST: u64 = 6;

/// The start of each region in the engine's memory: data, `%I`, `%Q`, `%M`, constants, then
/// one stack per task.
#[derive(Clone, Debug)]
pub(crate) struct Regions {
    pub(crate) data: usize,
    pub(crate) input: usize,
    pub(crate) output: usize,
    pub(crate) memory: usize,
    pub(crate) constants: usize,
    pub(crate) stacks: usize,
    /// Bytes of one task's stack.
    pub(crate) stack_size: usize,
    /// The whole memory's size.
    pub(crate) total: usize,
}

impl Regions {
    /// The layout of `image` with `tasks` stacks.
    pub(crate) fn of(image: &ProgramImage, tasks: usize) -> Self {
        let layout = &image.layout;
        let data = 0;
        let input = data + layout.data_size as usize;
        let output = input + layout.input_size as usize;
        let memory = output + layout.output_size as usize;
        let constants = memory + layout.memory_size as usize;
        let stacks = constants + image.constants.len();
        let stack_size = layout.stack_size as usize;
        Self {
            data,
            input,
            output,
            memory,
            constants,
            stacks,
            stack_size,
            total: stacks + stack_size * tasks.max(1),
        }
    }

    /// The start of a symbol region.
    pub(crate) fn start(&self, region: Region) -> usize {
        match region {
            Region::Data => self.data,
            Region::Input => self.input,
            Region::Output => self.output,
            Region::Memory => self.memory,
        }
    }

    /// The stack of task `task`: start and end.
    pub(crate) fn stack(&self, task: usize) -> (usize, usize) {
        let start = self.stacks + self.stack_size * task;
        (start, start + self.stack_size)
    }

    fn spans(&self, stack_end: usize) -> [(u64, usize, usize); 6] {
        let stack_start = stack_end.saturating_sub(self.stack_size);
        [
            (TAG_DATA, self.data, self.input),
            (TAG_INPUT, self.input, self.output),
            (TAG_OUTPUT, self.output, self.memory),
            (TAG_MEMORY, self.memory, self.constants),
            (TAG_CONST, self.constants, self.stacks),
            (TAG_STACK, stack_start, stack_end),
        ]
    }

    /// The pointer value of the absolute offset `at`, as seen from the task whose stack ends at
    /// `stack_end`.
    pub(crate) fn pointer_to(&self, at: usize, stack_end: usize) -> u64 {
        for (tag, start, end) in self.spans(stack_end) {
            if at >= start && at < end.max(start + 1) {
                return (tag << 56) | (at - start) as u64;
            }
        }
        0
    }

    /// The absolute offset of `pointer`, checked for `size` bytes.
    pub(crate) fn resolve(
        &self,
        pointer: u64,
        size: usize,
        stack_end: usize,
    ) -> Result<usize, FaultKind> {
        let tag = pointer >> 56;
        if tag == 0 {
            return Err(FaultKind::NullPointer);
        }
        let offset = (pointer & ((1 << 56) - 1)) as usize;
        for (known, start, end) in self.spans(stack_end) {
            if known == tag {
                let at = start
                    .checked_add(offset)
                    .ok_or(FaultKind::BadPointer(pointer))?;
                if at.checked_add(size).is_some_and(|last| last <= end) {
                    return Ok(at);
                }
                return Err(FaultKind::BadPointer(pointer));
            }
        }
        Err(FaultKind::BadPointer(pointer))
    }
}
