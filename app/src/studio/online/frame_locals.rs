//! The locals of a halted function's or method's frame (`FRAME_READ`, `docs/protocol.md` §6),
//! found through the image's `debug` section, for the values shown inline in its body: they
//! live on the task's stack and have no path to watch.

use online::FrameRange;
use online::session::{Command, DebugCommand as SessionCommand};
use program_image::{FrameVariableKind, PouKind, TypeId};

use super::Online;

/// The frame whose locals are asked for or shown.
#[derive(Clone, Debug, PartialEq, Eq)]
struct FrameKey {
    task: u8,
    frame: u16,
}

/// The locals of the shown frame: asked for once per halt and frame, kept until the next.
#[derive(Default)]
pub(super) struct FrameLocals {
    /// The frame asked for last, with the names and types of the ranges asked; `None` after a
    /// new halt, so the shown frame is read again.
    asked: Option<(FrameKey, Vec<(String, TypeId)>)>,
    /// The shown frame's locals by name, each value as an IEC literal.
    values: Vec<(String, String)>,
}

impl Online {
    /// Asks for the locals of frame `frame` of the halted task named `task` when it is a
    /// function's or method's and was not asked for since the last halt; `None` forgets them.
    /// Called every frame with the frame the studio shows.
    pub fn show_frame_locals(&mut self, shown: Option<(&str, usize)>) {
        let Some((task, frame)) = shown else {
            self.frame_locals = FrameLocals::default();
            return;
        };
        let (Some(task), Ok(frame)) = (self.task_index(task), u16::try_from(frame)) else {
            return;
        };
        let key = FrameKey { task, frame };
        if self
            .frame_locals
            .asked
            .as_ref()
            .is_some_and(|(asked, _)| *asked == key)
        {
            return;
        }
        let variables = self.frame_variables(&key);
        self.frame_locals.values.clear();
        let ranges: Vec<FrameRange> = variables.iter().map(|(_, range, _)| *range).collect();
        let names = variables
            .into_iter()
            .map(|(name, _, ty)| (name, ty))
            .collect();
        if ranges.is_empty()
            || self.command(Command::Debug(SessionCommand::FrameRead {
                task,
                frame,
                ranges,
            }))
        {
            self.frame_locals.asked = Some((key, names));
        }
    }

    /// The shown frame's locals by name with their values, empty but for a halted function or
    /// method.
    pub fn frame_locals(&self) -> &[(String, String)] {
        &self.frame_locals.values
    }

    /// A new halt was reported: the shown frame's locals are read again.
    pub(super) fn frame_locals_stale(&mut self) {
        self.frame_locals.asked = None;
    }

    /// Takes the answer to the `FRAME_READ` of the shown frame.
    pub(super) fn frame_read(&mut self, task: u8, frame: u16, values: &[Vec<u8>]) {
        let Some((key, names)) = &self.frame_locals.asked else {
            return;
        };
        let Some(image) = &self.image else { return };
        if *key != (FrameKey { task, frame }) {
            return;
        }
        self.frame_locals.values = names
            .iter()
            .zip(values)
            .map(|((name, ty), bytes)| {
                let value = runtime::value::decode(&image.program, *ty, bytes);
                (name.clone(), value.to_string())
            })
            .collect();
    }

    /// The frame variables to read of a function's or method's frame: each with its range
    /// and type (in-out parameters, pointers to the caller's variables, are left out).
    fn frame_variables(&self, key: &FrameKey) -> Vec<(String, FrameRange, TypeId)> {
        let Some(image) = &self.image else {
            return Vec::new();
        };
        let program = &image.program;
        let Some(pou) = self
            .reported_frame_pou(key.task, key.frame)
            .and_then(|index| Some((index, program.pous.get(index)?)))
            .filter(|(_, pou)| matches!(pou.kind, PouKind::Function | PouKind::Method))
            .map(|(index, _)| index)
        else {
            return Vec::new();
        };
        let Some(debug) = program.debug.as_ref().and_then(|debug| debug.pous.get(pou)) else {
            return Vec::new();
        };
        debug
            .frame
            .iter()
            .filter(|variable| variable.kind != FrameVariableKind::InOut)
            .filter_map(|variable| {
                let size = program
                    .types
                    .get(variable.ty as usize)?
                    .size_bytes(&program.types);
                let range = FrameRange {
                    offset: variable.offset,
                    size: u16::try_from(size).ok().filter(|size| *size > 0)?,
                };
                Some((variable.name.clone(), range, variable.ty))
            })
            .collect()
    }
}
