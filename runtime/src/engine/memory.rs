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

    /// The same layout as the native engine takes it (`docs/native-engine.md` §4.2): built from
    /// these regions rather than computed again, so that generated code and the interpreter
    /// address the same bytes.
    pub(crate) fn jit_layout(&self) -> jit::Layout {
        jit::Layout {
            data: self.data as u64,
            input: self.input as u64,
            output: self.output as u64,
            memory: self.memory as u64,
            constants: self.constants as u64,
            stacks: self.stacks as u64,
            stack_size: self.stack_size as u64,
            total: self.total as u64,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_images::{self, TestTask};

    #[test]
    fn the_native_layout_agrees_with_the_regions_for_every_region_and_task_stack() {
        let tasks = [
            TestTask::cyclic(1_000_000, 1),
            TestTask::cyclic(2_000_000, 2),
            TestTask::cyclic(4_000_000, 3),
        ];
        let mut image = test_images::image(&tasks, &[]);
        // Every region is present and of a different size, so that a region swapped or left
        // out in either computation moves the ones after it.
        image.layout.data_size = image.layout.data_size.max(64);
        image.layout.input_size = 12;
        image.layout.output_size = 20;
        image.layout.memory_size = 28;
        image.layout.stack_size = 256;
        image.constants = vec![7; 36];
        let regions = Regions::of(&image, tasks.len());
        let layout = regions.jit_layout();
        assert_eq!(layout, jit::Layout::of(&image, tasks.len()));
        let data = u64::from(image.layout.data_size);
        assert_eq!(
            (
                layout.input,
                layout.output,
                layout.memory,
                layout.constants,
                layout.stacks
            ),
            (data, data + 12, data + 32, data + 60, data + 96)
        );
        assert_eq!(layout.total, data + 96 + 3 * 256);
        assert_eq!(
            regions.stack(2),
            ((data + 96 + 512) as usize, layout.total as usize)
        );
    }
}
