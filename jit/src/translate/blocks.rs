//! Instruction indices to Cranelift blocks: a block starts at instruction 0, at every jump
//! target and after every instruction that branches or returns (`docs/native-engine.md` §3).

use cranelift_codegen::ir::Block;
use cranelift_frontend::FunctionBuilder;
use program_image::Instr;

/// The block each instruction index starts, if it starts one; index `code.len()` is the end,
/// where running past the last instruction returns.
pub(crate) struct Blocks {
    /// Per instruction index (and `code.len()`): the block it starts, if any.
    starts: Vec<Option<Block>>,
    /// The block past the last instruction, which returns `Ok`.
    end: Block,
}

impl Blocks {
    /// Creates a block for every instruction that starts one.
    pub(crate) fn new(code: &[Instr], builder: &mut FunctionBuilder<'_>) -> Self {
        let mut starts = vec![None; code.len() + 1];
        let mut mark = |index: usize, builder: &mut FunctionBuilder<'_>| {
            if let Some(slot) = starts.get_mut(index)
                && slot.is_none()
            {
                *slot = Some(builder.create_block());
            }
        };
        mark(0, builder);
        for (index, instr) in code.iter().enumerate() {
            match instr {
                Instr::Jump { target }
                | Instr::JumpIf { target, .. }
                | Instr::JumpIfNot { target, .. } => {
                    mark(*target as usize, builder);
                    mark(index + 1, builder);
                }
                Instr::Return => mark(index + 1, builder),
                _ => {}
            }
        }
        let end = builder.create_block();
        if let Some(last) = starts.last_mut() {
            *last = Some(end);
        }
        Self { starts, end }
    }

    /// The end block, where running past the last instruction returns.
    pub(crate) fn end(&self) -> Block {
        self.end
    }

    /// The block instruction `index` starts, if any.
    pub(crate) fn at(&self, index: usize) -> Option<Block> {
        self.starts.get(index).copied().flatten()
    }

    /// Gives instructions `start ..= end` new blocks, for a second copy of them (the
    /// unpromoted copy of a loop, `promote.rs`); returns the blocks they had, for
    /// [`Self::restore`].
    pub(crate) fn renew(
        &mut self,
        start: usize,
        end: usize,
        builder: &mut FunctionBuilder<'_>,
    ) -> Vec<Option<Block>> {
        let mut saved = Vec::new();
        for slot in self.starts.iter_mut().take(end + 1).skip(start) {
            saved.push(*slot);
            if slot.is_some() {
                *slot = Some(builder.create_block());
            }
        }
        saved
    }

    /// Gives instructions from `start` on the blocks [`Self::renew`] returned.
    pub(crate) fn restore(&mut self, start: usize, saved: Vec<Option<Block>>) {
        for (slot, block) in self.starts.iter_mut().skip(start).zip(saved) {
            *slot = block;
        }
    }
}
