//! The execution engine: an image's memory and code, run one task cycle at a time.
//!
//! The image's code is lowered once at load time ([`lower`]) into closures over resolved
//! operands; [`Engine::run_cycle`] runs one task's programs and turns a fault into a
//! [`FaultRecord`] naming the POU and source line. [`EngineView`] lends the code and memory to
//! the scheduler, whose [`Preempt`] hook runs the cycles of higher-priority tasks at the safe
//! points of an interrupted one (`docs/scheduler.md`).

mod blocks;
mod carry;
mod choice;
mod debug;
mod exec;
mod exec_debug;
mod fault;
mod jit_host;
mod jit_pure;
mod lower;
mod lower_refusal;
mod memory;
mod native;
mod native_load;
mod online_change;
mod scalar;
mod strings;
mod task_clock;
mod view;

use std::sync::Arc;

use program_image::{InitRun, ProgramImage, Region};

pub use carry::carry_retained;
pub use choice::{EngineChoice, EngineChoiceError, NativeReport, PouFallback};
pub use debug::{
    Breakpoint, BreakpointSpec, DebugError, DebugState, FlowRecording, FlowRecordings, FlowTrack,
    Halt, HaltReason, HitMode, MAX_BREAKPOINTS, MAX_FLOW_TRACKS, StackFrame, StepKind, TaskDebug,
};
pub use fault::{FaultKind, FaultRecord};
pub use lower::LowerError;
pub use native::MotionLoadError;
pub use online_change::{
    AppliedChange, ChangeDetail, ChangeRefusal, ChangeSummary, DetailKind, OnlineChangePlan,
};
pub use task_clock::TaskClock;
pub use view::{EngineView, Preempt, Preemption};

pub(crate) use exec::NATIVE_STACK_BUDGET;
use lower::Compiled;
use memory::Regions;

/// How the engine's memory is reset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ResetKind {
    /// Everything but RETAIN and PERSISTENT variables.
    Warm,
    /// Everything but PERSISTENT variables.
    Cold,
    /// Everything.
    Origin,
}

/// A loaded image with its memory.
pub struct Engine {
    /// Shared, so that an online change's check can compare with the running image without
    /// copying it on the scheduler's thread.
    image: Arc<ProgramImage>,
    regions: Regions,
    code: Compiled,
    memory: Vec<u8>,
    motion: native::MotionState,
    debug: DebugState,
    /// What the engine choice made of the image at load.
    native_report: NativeReport,
}

/// Why an image cannot be loaded.
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    /// The image is inconsistent.
    #[error(transparent)]
    Image(#[from] program_image::ImageError),
    /// An instruction the engine cannot run.
    #[error(transparent)]
    Lower(#[from] LowerError),
    /// An axis the motion kernel cannot run.
    #[error(transparent)]
    Motion(#[from] MotionLoadError),
}

impl Engine {
    /// Verifies and loads `image`, with memory as after a cold start, with the default engine
    /// ([`EngineChoice::default`]).
    pub fn new(image: ProgramImage) -> Result<Self, LoadError> {
        Self::with_choice(image, EngineChoice::default()).map(|(engine, _)| engine)
    }

    /// Verifies and loads `image`, with memory as after a cold start, run by the engine
    /// `choice` names (`docs/native-engine.md` §8). With [`EngineChoice::Native`] the image is
    /// translated here, on the loading thread; a POU the translator refuses, or the whole image
    /// when no machine code can be made, runs in the interpreter, which the report says.
    pub fn with_choice(
        image: ProgramImage,
        choice: EngineChoice,
    ) -> Result<(Self, NativeReport), LoadError> {
        image.verify()?;
        let regions = Regions::of(&image, image.tasks.len());
        let mut code = Compiled::new(&image, &regions)?;
        let motion = native::MotionState::new(&image)?;
        let native_report = match choice {
            EngineChoice::Interpreter => NativeReport::interpreter(&image),
            EngineChoice::Native => {
                let (native, report) = native_load::translate(&image, &regions);
                code.native = native;
                report
            }
        };
        let mut engine = Self {
            debug: DebugState::new(&image),
            memory: vec![0; regions.total],
            image: Arc::new(image),
            regions,
            code,
            motion,
            native_report: native_report.clone(),
        };
        engine.reset(ResetKind::Origin);
        Ok((engine, native_report))
    }

    /// What the engine choice made of the image at load.
    pub fn native_report(&self) -> &NativeReport {
        &self.native_report
    }

    /// How many times generated code was entered from the interpreter since the image loaded:
    /// 0 unless the native engine runs, and it does not in a cycle the debugger watches.
    pub fn native_entries(&self) -> u64 {
        self.code
            .native_entries
            .load(std::sync::atomic::Ordering::Relaxed)
    }

    /// The image being run.
    pub fn image(&self) -> &ProgramImage {
        &self.image
    }

    /// The image being run, shared rather than copied.
    pub fn shared_image(&self) -> Arc<ProgramImage> {
        Arc::clone(&self.image)
    }

    /// The data-region offsets of the motion block instances whose commands the motion
    /// kernel keeps (an online change follows them, or drops those whose instance is gone).
    pub fn motion_instances(&self) -> Vec<usize> {
        motion_offsets(&self.motion, self.regions.data)
    }

    /// Re-initialises memory as `kind` says.
    pub fn reset(&mut self, kind: ResetKind) {
        // The axes start again powered off at rest, and the motion blocks forget their
        // commands, as their instances' memory is initialised again. The image was accepted
        // with this motion section, so building its kernel again cannot fail.
        if let Ok(motion) = native::MotionState::new(&self.image) {
            self.motion = motion;
        }
        let kept = self.kept_ranges(kind);
        let saved: Vec<(usize, Vec<u8>)> = kept
            .iter()
            .filter_map(|&(offset, length)| {
                let (offset, length) = (offset as usize, length as usize);
                self.memory
                    .get(offset..offset + length)
                    .map(|bytes| (offset, bytes.to_vec()))
            })
            .collect();
        self.memory.fill(0);
        let regions = self.regions.clone();
        let image = &self.image;
        let memory = &mut self.memory;
        let mut apply = |runs: &[InitRun], start: usize| {
            for run in runs {
                let at = start + run.offset as usize;
                if let Some(place) = memory.get_mut(at..at + run.bytes.len()) {
                    place.copy_from_slice(&run.bytes);
                }
            }
        };
        apply(&image.initial.data, regions.data);
        apply(&image.initial.input, regions.input);
        apply(&image.initial.output, regions.output);
        apply(&image.initial.memory, regions.memory);
        if let Some(place) = memory.get_mut(regions.constants..regions.stacks) {
            place.copy_from_slice(&image.constants);
        }
        for (offset, bytes) in saved {
            if let Some(place) = self.memory.get_mut(offset..offset + bytes.len()) {
                place.copy_from_slice(&bytes);
            }
        }
    }

    fn kept_ranges(&self, kind: ResetKind) -> Vec<(u32, u32)> {
        let retain = &self.image.retain;
        match kind {
            ResetKind::Warm => retain
                .retain
                .iter()
                .chain(&retain.persistent)
                .copied()
                .collect(),
            ResetKind::Cold => retain.persistent.clone(),
            ResetKind::Origin => Vec::new(),
        }
    }

    /// Runs one cycle of task `task` at task time `now_ns` on a simulated clock
    /// ([`TaskClock::Simulated`]): its programs in order. A fault stops the cycle where it
    /// happened and is returned with its place. Nothing interrupts it (the scheduler runs
    /// cycles through [`EngineView::run_cycle`] on the real clock to let tasks preempt).
    // A fault is rare and ends the task, so its record need not be boxed to keep `Ok` small.
    #[allow(clippy::result_large_err)]
    pub fn run_cycle(&mut self, task: usize, now_ns: i64, cycle: u64) -> Result<(), FaultRecord> {
        self.view()
            .run_cycle(task, now_ns, TaskClock::Simulated, cycle, None)
    }

    /// The code and memory, borrowed together, to run cycles on.
    pub fn view(&mut self) -> EngineView<'_> {
        EngineView {
            image: &self.image,
            regions: &self.regions,
            code: &self.code,
            memory: &mut self.memory,
            motion: &mut self.motion,
            debug: &mut self.debug,
        }
    }

    /// The debug session's state.
    pub fn debug(&self) -> &DebugState {
        &self.debug
    }

    /// The debug session's state, to change between cycles.
    pub fn debug_mut(&mut self) -> &mut DebugState {
        &mut self.debug
    }

    /// The motion kernel's view of each axis of the image, in the image's order.
    pub(crate) fn axis_snapshots(&self) -> Vec<Option<motion::kernel::AxisSnapshot>> {
        self.motion.axis_snapshots()
    }

    /// The constants region: the image's constant pool as the engine holds it, which a store
    /// through a pointer can reach, so the differential harness compares it too.
    pub(crate) fn constants(&self) -> &[u8] {
        self.memory
            .get(self.regions.constants..self.regions.stacks)
            .unwrap_or_default()
    }

    /// The bytes of a region.
    pub fn region(&self, region: Region) -> &[u8] {
        view::region_bytes(&self.image, &self.regions, &self.memory, region)
    }

    /// The bytes of a region, writable.
    pub fn region_mut(&mut self, region: Region) -> &mut [u8] {
        let start = self.regions.start(region);
        let size = self.image.region_size(region) as usize;
        self.memory.get_mut(start..start + size).unwrap_or_default()
    }
}

/// The data-region offsets of the motion block instances `motion` keeps, sorted; `data_base`
/// is where the data region starts in memory.
fn motion_offsets(motion: &native::MotionState, data_base: usize) -> Vec<usize> {
    let mut offsets: Vec<usize> = motion
        .instances()
        .into_iter()
        .filter_map(|offset| offset.checked_sub(data_base))
        .collect();
    offsets.sort_unstable();
    offsets
}
