//! What the engine keeps for motion between calls: the kernel with the image's axes, the
//! `motion` function block of every native instance, and when each task last ran.

use std::collections::HashMap;

use motion::axis::{AxisConfig, SoftwareLimits};
use motion::fb::CamIn;
use motion::kernel::{AxisId, AxisSnapshot, Kernel};
use motion::sync::CamId;
use program_image::{ProgramImage, StructKind, TypeDef};

use super::blocks::{Instance, Kept};

/// One axis of the image in the kernel.
#[derive(Clone, Copy, Debug)]
struct AxisLink {
    id: AxisId,
    task: usize,
    /// The data-region offset of its `AXIS_REF`.
    offset: usize,
}

/// The offsets of the `AXIS_REF` members the runtime writes after each cycle.
#[derive(Clone, Debug, Default)]
struct AxisRefLayout {
    state: Option<usize>,
    regulator_on: Option<usize>,
    error: Option<usize>,
    error_id: Option<usize>,
    is_homed: Option<usize>,
    set_position: Option<usize>,
    act_position: Option<usize>,
    set_velocity: Option<usize>,
    act_velocity: Option<usize>,
    set_acceleration: Option<usize>,
    act_acceleration: Option<usize>,
    position_period: Option<usize>,
}

/// The offsets of the live members of `MC_CAM_REF` (`docs/motion.md` §2).
#[derive(Clone, Copy, Debug, Default)]
struct CamRefLayout {
    master_position: Option<usize>,
    slave_position: Option<usize>,
    tappets: Option<usize>,
}

/// The motion state of a loaded image.
pub(crate) struct MotionState {
    kernel: Kernel,
    axes: Vec<AxisLink>,
    /// The kernel's cam for each `nCamId`.
    cams: Vec<CamId>,
    /// The data-region offset of each cam's `MC_CAM_REF`, by `nCamId`.
    cam_refs: Vec<usize>,
    cam_ref: CamRefLayout,
    axis_ref: AxisRefLayout,
    instances: HashMap<usize, Instance, super::fast_hash::FastBuild>,
    last_cycle_ns: Vec<Option<i64>>,
}

/// Why an image's motion section cannot run.
#[derive(Debug, thiserror::Error)]
#[error("{what}: {message}")]
pub struct MotionLoadError {
    /// The axis or cam, as "axis 'Master'".
    what: String,
    message: String,
}

impl MotionState {
    /// The kernel of `image`'s axes, all powered off at position 0.
    pub(crate) fn new(image: &ProgramImage) -> Result<Self, MotionLoadError> {
        let mut kernel = Kernel::new();
        let mut axes = Vec::new();
        if let Some(section) = &image.motion {
            for axis in &section.axes {
                let config = AxisConfig {
                    modulo_period: axis.modulo_period,
                    software_limits: axis
                        .software_limits
                        .map(|(min, max)| SoftwareLimits { min, max }),
                    max_velocity: axis.max_velocity,
                    max_acceleration: axis.max_acceleration,
                    max_deceleration: axis.max_deceleration,
                    max_jerk: axis.max_jerk,
                };
                let id = kernel.add_axis(config).map_err(|error| MotionLoadError {
                    what: format!("axis '{}'", axis.name),
                    message: error.to_string(),
                })?;
                axes.push(AxisLink {
                    id,
                    task: axis.task as usize,
                    offset: axis.offset as usize,
                });
            }
        }
        let mut cams = Vec::new();
        let mut cam_refs = Vec::new();
        for cam in image.motion.iter().flat_map(|section| &section.cams) {
            cam_refs.push(cam.offset as usize);
            let failed = |message: String| MotionLoadError {
                what: format!("cam table '{}'", cam.name),
                message,
            };
            let curve = super::cams::curve_of(cam).map_err(failed)?;
            let id = kernel
                .add_cam(curve, super::cams::tracks_of(cam))
                .map_err(|error| failed(error.to_string()))?;
            cams.push(id);
        }
        Ok(Self {
            kernel,
            axes,
            cams,
            cam_refs,
            cam_ref: cam_ref_layout(image),
            axis_ref: axis_ref_layout(image),
            instances: HashMap::default(),
            last_cycle_ns: vec![None; image.tasks.len()],
        })
    }

    /// Takes over `old`'s kernel (the axes and their motion), the function blocks kept for
    /// its instances and when each task last ran, after an online change whose motion section
    /// differs from the old one only in where its references live. `moved` gives an old
    /// instance's absolute offset in the new memory, `None` where the instance is gone; such
    /// blocks are dropped and their count returned. `old` is left without a kernel and
    /// blocks: it belongs to an engine that is retired.
    pub(crate) fn carry_from(
        &mut self,
        old: &mut MotionState,
        moved: impl Fn(usize) -> Option<usize>,
    ) -> usize {
        self.kernel = std::mem::take(&mut old.kernel);
        self.last_cycle_ns = std::mem::take(&mut old.last_cycle_ns);
        let mut dropped = 0;
        self.instances = HashMap::default();
        for (offset, block) in std::mem::take(&mut old.instances) {
            match moved(offset) {
                Some(new_offset) => {
                    self.instances.insert(new_offset, block);
                }
                None => dropped += 1,
            }
        }
        dropped
    }

    /// The absolute offsets of the instances whose motion blocks are kept.
    pub(crate) fn instances(&self) -> Vec<usize> {
        self.instances.keys().copied().collect()
    }

    /// The kernel's axis for `nAxisId`.
    pub(crate) fn axis(&self, id: usize) -> Option<AxisId> {
        self.axes.get(id).map(|link| link.id)
    }

    /// What the kernel shows of each axis of the image, in the image's order, for comparing
    /// two engines' motion (`runtime::differential`). An axis the kernel cannot show keeps its
    /// place as `None`, so the axes after it keep their indices and names.
    pub(crate) fn axis_snapshots(&self) -> Vec<Option<AxisSnapshot>> {
        self.axes
            .iter()
            .map(|link| self.kernel.snapshot(link.id).ok())
            .collect()
    }

    /// The kernel.
    pub(super) fn kernel(&mut self) -> &mut Kernel {
        &mut self.kernel
    }

    /// The kernel's cam for `nCamId`.
    pub(crate) fn cam(&self, id: u32) -> Option<CamId> {
        self.cams.get(id as usize).copied()
    }

    /// The function block kept for the instance at `instance`, taken out (a new one if there
    /// was none) so that it can be called with another instance's state; give it back with
    /// [`MotionState::put`].
    pub(super) fn take<T: Kept>(&mut self, instance: usize) -> T {
        match self
            .instances
            .remove(&instance)
            .as_mut()
            .and_then(T::unwrap)
        {
            Some(block) => std::mem::take(block),
            None => T::default(),
        }
    }

    /// Keeps `block` for the instance at `instance`.
    pub(super) fn put<T: Kept>(&mut self, instance: usize, block: T) {
        self.instances.insert(instance, block.wrap());
    }

    /// The MC_CamIn kept for the instance at `instance`, if that instance is one.
    pub(super) fn cam_in(&mut self, instance: usize) -> Option<&mut CamIn> {
        self.instances.get_mut(&instance).and_then(CamIn::unwrap)
    }

    /// The kernel and the function block kept for the instance at `instance` (an absolute
    /// offset), made on first use.
    pub(super) fn block<T: Kept>(&mut self, instance: usize) -> (&mut Kernel, &mut T) {
        let slot = self
            .instances
            .entry(instance)
            .or_insert_with(|| T::default().wrap());
        if T::unwrap(slot).is_none() {
            // Another block type at the same address: the image changed under the instance.
            *slot = T::default().wrap();
        }
        let block = match T::unwrap(slot) {
            Some(block) => block,
            None => unreachable!("the slot was just filled with this block type"),
        };
        (&mut self.kernel, block)
    }

    /// After task `task`'s programs ran at `now_ns`: advances its axes by the time since its
    /// previous cycle (`interval_ns` on the first) and writes their `AXIS_REF`s into `data`.
    /// Takes `halted_ns` out of task `task`'s axes' clock: its cycle was halted that long by
    /// the debugger, and the next advance should cover one cycle, not the halt too.
    pub(crate) fn skip_halted(&mut self, task: usize, halted_ns: i64) {
        if let Some(Some(last)) = self.last_cycle_ns.get_mut(task) {
            *last = last.saturating_add(halted_ns);
        }
    }

    pub(crate) fn after_cycle(
        &mut self,
        task: usize,
        now_ns: i64,
        interval_ns: u64,
        data: &mut [u8],
    ) {
        let Some(last) = self.last_cycle_ns.get_mut(task) else {
            return;
        };
        let dt_ns = match *last {
            Some(previous) if now_ns > previous => (now_ns - previous) as f64,
            _ => interval_ns as f64,
        };
        *last = Some(now_ns);
        let dt_s = dt_ns / 1e9;
        for link in self.axes.iter().filter(|link| link.task == task) {
            // An axis error is the axis's state (ErrorStop), shown in its AXIS_REF; it does not
            // stop the task.
            let _ = self.kernel.advance(link.id, dt_s);
            if let Ok(snapshot) = self.kernel.snapshot(link.id) {
                let layout = &self.axis_ref;
                let base = link.offset;
                let mut put = |at: Option<usize>, bytes: &[u8]| {
                    if let Some(at) = at
                        && let Some(place) = data.get_mut(base + at..base + at + bytes.len())
                    {
                        place.copy_from_slice(bytes);
                    }
                };
                put(layout.state, &(snapshot.state.code() as i16).to_le_bytes());
                put(layout.regulator_on, &[u8::from(snapshot.powered)]);
                put(layout.error, &[u8::from(snapshot.error)]);
                put(layout.error_id, &snapshot.axis_error_id.to_le_bytes());
                put(layout.is_homed, &[u8::from(snapshot.is_homed)]);
                put(layout.set_position, &snapshot.set_position.to_le_bytes());
                put(layout.act_position, &snapshot.actual_position.to_le_bytes());
                put(layout.set_velocity, &snapshot.set_velocity.to_le_bytes());
                put(layout.act_velocity, &snapshot.actual_velocity.to_le_bytes());
                put(
                    layout.set_acceleration,
                    &snapshot.set_acceleration.to_le_bytes(),
                );
                put(
                    layout.act_acceleration,
                    &snapshot.set_acceleration.to_le_bytes(),
                );
                put(
                    layout.position_period,
                    &snapshot.modulo_period.to_le_bytes(),
                );
                if let Ok(Some(coupling)) = self.kernel.coupling_status(link.id)
                    && let Some(cam) = coupling.cam
                    && let Some(index) = self.cams.iter().position(|id| *id == cam)
                    && let Some(&base) = self.cam_refs.get(index)
                {
                    let layout = self.cam_ref;
                    let position = snapshot.set_position.to_le_bytes();
                    write_at(
                        data,
                        base,
                        layout.master_position,
                        &coupling.cam_master.to_le_bytes(),
                    );
                    write_at(data, base, layout.slave_position, &position);
                }
            }
        }
        // The tappet outputs of each running MC_CamIn, as its cam's dwTappets.
        for instance in self.instances.values() {
            let Instance::CamIn(cam_in) = instance else {
                continue;
            };
            let Ok(selection) = self.kernel.cam_selection(cam_in.cam_table_id) else {
                continue;
            };
            let Some(index) = self.cams.iter().position(|id| *id == selection.cam) else {
                continue;
            };
            if !cam_in.busy {
                continue;
            }
            let bits = cam_in
                .tappets
                .outputs()
                .filter(|(track, on)| *on && (1..=32).contains(track))
                .fold(0u32, |bits, (track, _)| bits | (1 << (track - 1)));
            if let Some(&base) = self.cam_refs.get(index) {
                write_at(data, base, self.cam_ref.tappets, &bits.to_le_bytes());
            }
        }
    }
}

/// Writes `bytes` at `base + at` in `data`, when the member exists and fits.
fn write_at(data: &mut [u8], base: usize, at: Option<usize>, bytes: &[u8]) {
    if let Some(at) = at
        && let Some(place) = data.get_mut(base + at..base + at + bytes.len())
    {
        place.copy_from_slice(bytes);
    }
}

fn cam_ref_layout(image: &ProgramImage) -> CamRefLayout {
    let at = |field: &str| {
        super::io::Members::field_offset(image, "MC_CAM_REF", field).map(|offset| offset as usize)
    };
    CamRefLayout {
        master_position: at("fMasterPosition"),
        slave_position: at("fSlavePosition"),
        tappets: at("dwTappets"),
    }
}

fn axis_ref_layout(image: &ProgramImage) -> AxisRefLayout {
    let Some(members) = image.types.iter().find_map(|ty| match ty {
        TypeDef::Struct {
            name,
            kind: StructKind::Struct,
            members,
            ..
        } if name == "AXIS_REF" => Some(members),
        _ => None,
    }) else {
        return AxisRefLayout::default();
    };
    let at = |name: &str| {
        members
            .iter()
            .find(|member| member.name.eq_ignore_ascii_case(name))
            .map(|member| member.offset as usize)
    };
    AxisRefLayout {
        state: at("nAxisState"),
        regulator_on: at("bRegulatorOn"),
        error: at("bError"),
        error_id: at("nErrorID"),
        is_homed: at("bIsHomed"),
        set_position: at("fSetPosition"),
        act_position: at("fActPosition"),
        set_velocity: at("fSetVelocity"),
        act_velocity: at("fActVelocity"),
        set_acceleration: at("fSetAcceleration"),
        act_acceleration: at("fActAcceleration"),
        position_period: at("fPositionPeriod"),
    }
}
