//! The engine lent out while a cycle runs: what a preempting task's cycle needs to run on the
//! same memory as the cycle it interrupts.

use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use program_image::{ProgramImage, Region};

use super::debug::{BreakpointSpec, DebugError, DebugState};
use super::exec::{Exec, NEVER_DUE};
use super::fault::{FaultKind, FaultRecord};
use super::lower::Compiled;
use super::lower::lower_condition;
use super::memory::Regions;
use super::native::MotionState;
use super::task_clock::TaskClock;

/// The engine's code and memory, borrowed: from [`super::Engine::view`] between cycles, or
/// from an interrupted cycle at a safe point, where [`Preempt::preempt`] receives it to run
/// cycles of tasks of higher priority.
pub struct EngineView<'e> {
    pub(super) image: &'e Arc<ProgramImage>,
    pub(super) regions: &'e Regions,
    pub(super) code: &'e Compiled,
    pub(super) memory: &'e mut [u8],
    pub(super) motion: &'e mut MotionState,
    pub(super) debug: &'e mut DebugState,
}

/// What the scheduler gives a cycle so that a task of higher priority may interrupt it.
pub struct Preemption<'p> {
    /// Set when a task of higher priority may be due; read at every safe point (a backward
    /// jump or a call), so it must be cheap: a relaxed load.
    pub due: &'p AtomicBool,
    /// Called at a safe point when `due` is set, with the interrupted cycle's engine.
    pub hook: &'p mut dyn Preempt,
}

/// The scheduler's side of preemption: runs the cycles that interrupt another.
pub trait Preempt {
    /// Runs, on `engine`, the cycles of tasks that interrupt the cycle in progress; the
    /// interrupted cycle goes on when it returns. It should clear [`Preemption::due`] (or
    /// the interrupted cycle calls it again at its next safe point).
    fn preempt(&mut self, engine: EngineView<'_>);

    /// Serves the halt of task `task`, whose cycle is halted at a statement start on
    /// `engine` (`docs/debugging.md` §2): returns when [`DebugState::is_halted`] says the
    /// task may go on, or when [`DebugState::abandoning`] says its cycle is abandoned.
    /// Without this, a halt goes on at once.
    fn halt(&mut self, engine: EngineView<'_>, task: usize) {
        let _ = (engine, task);
    }
}

impl EngineView<'_> {
    /// The image being run.
    pub fn image(&self) -> &ProgramImage {
        self.image
    }

    /// How many times generated code was entered since the image loaded
    /// ([`super::Engine::native_entries`]), for the scheduler's views of the engine.
    pub fn native_entries(&self) -> u64 {
        self.code
            .native_entries
            .load(std::sync::atomic::Ordering::Relaxed)
    }

    /// The image being run, shared rather than copied (an online change's check keeps it
    /// while it compares, away from the scheduler's thread).
    pub fn shared_image(&self) -> Arc<ProgramImage> {
        Arc::clone(self.image)
    }

    /// The data-region offsets of the motion block instances whose commands the motion
    /// kernel keeps, as [`Engine::motion_instances`] gives them.
    pub fn motion_instances(&self) -> Vec<usize> {
        super::motion_offsets(self.motion, self.regions.data)
    }

    /// The same engine, borrowed again for a shorter time.
    pub fn reborrow(&mut self) -> EngineView<'_> {
        EngineView {
            image: self.image,
            regions: self.regions,
            code: self.code,
            memory: &mut *self.memory,
            motion: &mut *self.motion,
            debug: &mut *self.debug,
        }
    }

    /// The debug session's state.
    pub fn debug(&self) -> &DebugState {
        self.debug
    }

    /// The debug session's state, to change (from a halt, or between cycles).
    pub fn debug_mut(&mut self) -> &mut DebugState {
        self.debug
    }

    /// `BREAK_SET`: checks `spec` (a statement start, the hit target, the condition decoded,
    /// verified and lowered) and sets the breakpoint; returns its id and whether it replaced
    /// one at the same place, instance and task.
    pub fn set_breakpoint(&mut self, spec: BreakpointSpec) -> Result<(u16, bool), DebugError> {
        let condition = DebugState::decode_condition(self.image, spec.pou, &spec.condition)?
            .map(|condition| lower_condition(&condition, self.regions))
            .transpose()?;
        self.debug.insert_breakpoint(spec, condition)
    }

    /// The pointer value (`docs/program-image.md` §5.2) of the absolute offset `at` as task
    /// `task` sees it: a place in its stack is of region 2.
    pub fn pointer_value(&self, task: usize, at: usize) -> u64 {
        self.regions.pointer_to(at, self.regions.stack(task).1)
    }

    /// The bytes of task `task`'s stack (`FRAME_READ`).
    pub fn stack_bytes(&self, task: usize) -> &[u8] {
        let (start, end) = self.regions.stack(task);
        self.memory.get(start..end).unwrap_or_default()
    }

    /// The bytes of task `task`'s stack, writable (`FRAME_WRITE`).
    pub fn stack_bytes_mut(&mut self, task: usize) -> &mut [u8] {
        let (start, end) = self.regions.stack(task);
        self.memory.get_mut(start..end).unwrap_or_default()
    }

    /// Where task `task`'s stack starts, to give a frame's start from it (`STACK`).
    pub fn stack_start(&self, task: usize) -> usize {
        self.regions.stack(task).0
    }

    /// The bytes of a region.
    pub fn region(&self, region: Region) -> &[u8] {
        region_bytes(self.image, self.regions, self.memory, region)
    }

    /// The bytes of a region, writable.
    pub fn region_mut(&mut self, region: Region) -> &mut [u8] {
        let start = self.regions.start(region);
        let size = self.image.region_size(region) as usize;
        self.memory.get_mut(start..start + size).unwrap_or_default()
    }

    /// Runs one cycle of task `task` at task time `now_ns` on the `clock` it comes from: its
    /// programs in order, then the motion kernel's end of cycle. A fault stops the cycle where
    /// it happened and is returned with its place. With `preemption`, tasks of higher priority
    /// may interrupt the cycle at its safe points; the time they take does not count against
    /// its watchdog.
    // A fault is rare and ends the task, so its record need not be boxed to keep `Ok` small.
    #[allow(clippy::result_large_err)]
    pub fn run_cycle(
        &mut self,
        task: usize,
        now_ns: i64,
        clock: TaskClock,
        cycle: u64,
        preemption: Option<Preemption<'_>>,
    ) -> Result<(), FaultRecord> {
        let image = self.image;
        let Some(info) = image.tasks.get(task) else {
            return Ok(());
        };
        // Without a watchdog a task still cannot hang the runtime: ten seconds ends it.
        let limit_ns = if info.watchdog_ns > 0 {
            info.watchdog_ns
                .saturating_mul(u64::from(info.watchdog_sensitivity.max(1)))
        } else {
            10_000_000_000
        };
        let started = Instant::now();
        let deadline = Some((started + Duration::from_nanos(limit_ns), limit_ns / 1000));
        let regions = self.regions;
        let mut preemption = preemption;
        let (due, hook): (&AtomicBool, Option<&mut dyn Preempt>) = match preemption.as_mut() {
            Some(preemption) => (preemption.due, Some(&mut *preemption.hook)),
            None => (&NEVER_DUE, None),
        };
        let mut exec = Exec::new(
            self.memory,
            image,
            regions,
            self.code,
            regions.stack(task),
            now_ns,
            deadline,
            self.motion,
            (due, hook),
            (task, &mut *self.debug),
        );
        exec.clock_started = (clock == TaskClock::Real).then_some(started);
        if exec.session {
            exec.begin_debug_cycle(cycle);
        }
        for call in &info.programs {
            if exec.session {
                exec.begin_debug_program();
            }
            let instance = regions.data + call.instance_offset as usize;
            if let Err(kind) = exec.call_block(call.pou as usize, instance, 0) {
                if exec.session {
                    exec.debug.cycle_ends(task);
                }
                let (pou, instruction) = exec.fault_at.unwrap_or((call.pou as usize, 0));
                return Err(fault_record(image, task, kind, pou, instruction, cycle));
            }
        }
        if exec.session {
            exec.end_debug_cycle(cycle);
            exec.debug.cycle_ends(task);
        }
        let halted_ns = exec.halted_ns;
        let data_start = regions.data;
        let data_end = data_start + image.layout.data_size as usize;
        if let Some(data) = self.memory.get_mut(data_start..data_end) {
            self.motion
                .after_cycle(task, now_ns, info.interval_ns, data);
            self.motion.skip_halted(task, halted_ns);
        }
        Ok(())
    }
}

/// The bytes of `region` in `memory`.
pub(super) fn region_bytes<'m>(
    image: &ProgramImage,
    regions: &Regions,
    memory: &'m [u8],
    region: Region,
) -> &'m [u8] {
    let start = regions.start(region);
    let size = image.region_size(region) as usize;
    memory.get(start..start + size).unwrap_or_default()
}

/// The record of a fault of `kind` in task `task` at instruction `instruction` of POU `pou`,
/// with the source line when the image has one.
fn fault_record(
    image: &ProgramImage,
    task: usize,
    kind: FaultKind,
    pou: usize,
    instruction: usize,
    cycle: u64,
) -> FaultRecord {
    let info = image.pous.get(pou);
    let entry = info.and_then(|p| {
        p.lines
            .iter()
            .take_while(|entry| entry.index as usize <= instruction)
            .last()
    });
    FaultRecord {
        task: image
            .tasks
            .get(task)
            .map(|t| t.name.clone())
            .unwrap_or_default(),
        kind,
        pou: info.map(|p| p.name.clone()).unwrap_or_default(),
        file: entry.and_then(|e| image.sources.get(e.file as usize).cloned()),
        line: entry.map(|e| e.line),
        instruction: instruction as u32,
        cycle,
    }
}
