//! The execution engine: an image's memory and code, run one task cycle at a time.
//!
//! The image's code is lowered once at load time ([`lower`]) into closures over resolved
//! operands; [`Engine::run_cycle`] runs one task's programs and turns a fault into a
//! [`FaultRecord`] naming the POU and source line.

mod blocks;
mod carry;
mod exec;
mod fault;
mod lower;
mod memory;
mod native;
mod online_change;
mod scalar;
mod strings;

use std::time::{Duration, Instant};

use program_image::{InitRun, ProgramImage, Region};

pub use carry::carry_retained;
pub use fault::{FaultKind, FaultRecord};
pub use lower::LowerError;
pub use native::MotionLoadError;
pub use online_change::{
    AppliedChange, ChangeDetail, ChangeRefusal, ChangeSummary, DetailKind, OnlineChangePlan,
};

use exec::Exec;
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
    image: ProgramImage,
    regions: Regions,
    code: Compiled,
    memory: Vec<u8>,
    motion: native::MotionState,
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
    /// Verifies and loads `image`, with memory as after a cold start.
    pub fn new(image: ProgramImage) -> Result<Self, LoadError> {
        image.verify()?;
        let regions = Regions::of(&image, image.tasks.len());
        let code = Compiled::new(&image, &regions)?;
        let motion = native::MotionState::new(&image)?;
        let mut engine = Self {
            memory: vec![0; regions.total],
            image,
            regions,
            code,
            motion,
        };
        engine.reset(ResetKind::Origin);
        Ok(engine)
    }

    /// The image being run.
    pub fn image(&self) -> &ProgramImage {
        &self.image
    }

    /// The data-region offsets of the motion block instances whose commands the motion
    /// kernel keeps (an online change follows them, or drops those whose instance is gone).
    pub fn motion_instances(&self) -> Vec<usize> {
        let base = self.regions.data;
        let mut offsets: Vec<usize> = self
            .motion
            .instances()
            .into_iter()
            .filter_map(|offset| offset.checked_sub(base))
            .collect();
        offsets.sort_unstable();
        offsets
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

    /// Runs one cycle of task `task` at task time `now_ns`: its programs in order. A fault
    /// stops the cycle where it happened and is returned with its place.
    // A fault is rare and ends the task, so its record need not be boxed to keep `Ok` small.
    #[allow(clippy::result_large_err)]
    pub fn run_cycle(&mut self, task: usize, now_ns: i64, cycle: u64) -> Result<(), FaultRecord> {
        let Some(info) = self.image.tasks.get(task) else {
            return Ok(());
        };
        // Without a watchdog a task still cannot hang the runtime: ten seconds ends it.
        let limit_ns = if info.watchdog_ns > 0 {
            info.watchdog_ns
                .saturating_mul(u64::from(info.watchdog_sensitivity.max(1)))
        } else {
            10_000_000_000
        };
        let deadline = Some((
            Instant::now() + Duration::from_nanos(limit_ns),
            limit_ns / 1000,
        ));
        let (stack_start, stack_end) = self.regions.stack(task);
        let mut exec = Exec::new(
            &mut self.memory,
            &self.regions,
            &self.code,
            (stack_start, stack_end),
            now_ns,
            deadline,
            &mut self.motion,
        );
        for call in &info.programs {
            let instance = self.regions.data + call.instance_offset as usize;
            if let Err(kind) = exec.call_block(call.pou as usize, instance) {
                let (pou, instruction) = exec.fault_at.unwrap_or((call.pou as usize, 0));
                return Err(self.fault_record(task, kind, pou, instruction, cycle));
            }
        }
        let interval_ns = info.interval_ns;
        let data_start = self.regions.data;
        let data_end = data_start + self.image.layout.data_size as usize;
        if let Some(data) = self.memory.get_mut(data_start..data_end) {
            self.motion.after_cycle(task, now_ns, interval_ns, data);
        }
        Ok(())
    }

    fn fault_record(
        &self,
        task: usize,
        kind: FaultKind,
        pou: usize,
        instruction: usize,
        cycle: u64,
    ) -> FaultRecord {
        let image = &self.image;
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

    /// The bytes of a region.
    pub fn region(&self, region: Region) -> &[u8] {
        let start = self.regions.start(region);
        let size = self.image.region_size(region) as usize;
        self.memory.get(start..start + size).unwrap_or_default()
    }

    /// The bytes of a region, writable.
    pub fn region_mut(&mut self, region: Region) -> &mut [u8] {
        let start = self.regions.start(region);
        let size = self.image.region_size(region) as usize;
        self.memory.get_mut(start..start + size).unwrap_or_default()
    }
}
