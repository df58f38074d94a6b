//! The online change services (`docs/protocol.md` §7): check a transferred image against the
//! running program, list what will change, and switch to it between two cycles.

use std::sync::Arc;

use online_protocol::{
    ChangeApplied, ChangeCheck, ChangeDetailEntry, MAX_COUNT, MAX_PAYLOAD_BYTES, MAX_TEXT_BYTES,
    Place, Refusal, Response, Status, cut,
};
use program_image::{ImageHash, ProgramImage, Region};

use super::{OnlineServices, current_transfer, lock, not_now, scheduler_refusal};
use crate::engine::{ChangeRefusal, DebugState, DetailKind, Engine, OnlineChangePlan, TaskDebug};
use crate::modbus::ModbusMap;
use crate::scheduler::SchedulerError;

/// A transfer checked for an online change: the new engine, prepared away from the scheduler's
/// thread, and the plan against the program that ran at the check.
pub(super) struct CheckedChange {
    transfer: u16,
    engine: Engine,
    plan: Arc<OnlineChangePlan>,
    from: ImageHash,
    to: ImageHash,
}

/// What the check needs of the running program, taken between two cycles.
struct Running {
    /// Shared with the running engine: copying a large image would hold the tasks.
    image: Arc<ProgramImage>,
    data: Vec<u8>,
    forces: Vec<Place>,
    trace: Option<Vec<Place>>,
    motion_instances: Vec<usize>,
    identity: Option<ImageHash>,
    /// The first task halted, waiting beneath a halted task or stepping, by name.
    halted_task: Option<String>,
}

impl OnlineServices {
    /// `ONLINE_CHANGE_CHECK`: verifies the transfer as a commit does, prepares the new engine
    /// and compares it with the running program; the transfer stays open.
    pub(super) fn online_change_check(&self, transfer: u16) -> Result<Response, Refusal> {
        let image = {
            let mut current = lock(&self.transfer);
            current_transfer(&mut current, transfer)?.image()?
        };
        let refused = |message: String| Refusal {
            status: Status::ImageRefused,
            message,
        };
        ModbusMap::for_image(&image)
            .map_err(|error| refused(format!("the image's Modbus map is refused: {error}")))?;
        let to = image.identity();
        // The native report is kept by the engine but printed nowhere: the services run in a
        // library without a console of their own, and protocol version 3 has no field for it
        // (`docs/native-engine.md` §8.2, §13).
        let engine = Engine::with_choice(image.clone(), self.scheduler.engine_choice())
            .map(|(engine, _)| engine)
            .map_err(|error| refused(format!("the program image cannot be loaded: {error}")))?;
        let identity = self.scheduler.status().image;
        let running = self.between(move |between| {
            Ok(between.memory.as_ref().map(|memory| Running {
                image: memory.engine.shared_image(),
                data: memory.engine.region(Region::Data).to_vec(),
                forces: between.forces.entries().iter().map(|(p, _)| *p).collect(),
                trace: between.trace.config().map(|config| {
                    let mut places = config.places.clone();
                    places.push(config.trigger_place);
                    places
                }),
                motion_instances: memory.engine.motion_instances(),
                identity,
                halted_task: halted_task(memory.engine.debug()),
            }))
        })?;
        let Some(running) = running else {
            *lock(&self.checked) = None;
            return Ok(Response::OnlineChangeCheck(ChangeCheck {
                reason: ChangeRefusal::NoProgram.number(),
                why: "no program is loaded: there is nothing to change, download".to_owned(),
                ..ChangeCheck::default()
            }));
        };
        let mut plan = OnlineChangePlan::new(&running.image, &running.data, &image);
        let mut forces_released = 0u16;
        for place in running.forces.iter().filter(|place| place.region == 0) {
            if plan
                .moved_range(place.offset as usize, place.value_bytes())
                .is_none()
            {
                forces_released = forces_released.saturating_add(1);
                plan.add_detail(DetailKind::ForceReleased, place_name(&running.image, place));
            }
        }
        if let Some(places) = &running.trace
            && places.iter().any(|place| {
                place.region == 0
                    && plan
                        .moved_range(place.offset as usize, place.value_bytes())
                        .is_none()
            })
        {
            plan.add_detail(DetailKind::TraceRemoved, "trace".to_owned());
        }
        for offset in &running.motion_instances {
            if plan.moved_byte(*offset).is_none() {
                let place = Place {
                    region: 0,
                    offset: u32::try_from(*offset).unwrap_or(u32::MAX),
                    bit: None,
                    size: 1,
                };
                plan.add_detail(
                    DetailKind::MotionBlockDropped,
                    place_name(&running.image, &place),
                );
            }
        }
        let summary = plan.summary();
        let refusal = plan.refusal().map(|(reason, why)| (reason, why.to_owned()));
        let refusal = refusal.or_else(|| {
            running.halted_task.as_ref().map(|task| {
                (
                    ChangeRefusal::Halted,
                    format!("task '{task}' is halted or stepping: continue it first"),
                )
            })
        });
        let (possible, reason, why) = match refusal {
            Some((reason, why)) => (false, reason.number(), why),
            None => (true, 0, String::new()),
        };
        let clamp16 = |count: u32| u16::try_from(count).unwrap_or(u16::MAX);
        let check = ChangeCheck {
            possible,
            reason,
            pous_changed: clamp16(summary.pous_changed),
            pous_added: clamp16(summary.pous_added),
            pous_removed: clamp16(summary.pous_removed),
            carried: summary.carried,
            added: summary.added,
            removed: summary.removed,
            reinitialised: summary.reinitialised,
            pointers_moved: summary.pointers_moved,
            pointers_cleared: summary.pointers_cleared,
            forces_released,
            details: u16::try_from(plan.details().len()).unwrap_or(u16::MAX),
            why: cut(&why, MAX_TEXT_BYTES).to_owned(),
        };
        if let Some(active) = lock(&self.transfer).as_mut() {
            active.checked = true;
        }
        *lock(&self.checked) = running.identity.map(|from| CheckedChange {
            transfer,
            engine,
            plan: Arc::new(plan),
            from,
            to,
        });
        Ok(Response::OnlineChangeCheck(check))
    }

    /// `ONLINE_CHANGE_DETAILS`: the check's details from index `from` on, as many as fit.
    pub(super) fn online_change_details(
        &self,
        transfer: u16,
        from: u16,
    ) -> Result<Response, Refusal> {
        let checked = lock(&self.checked);
        let change = checked
            .as_ref()
            .filter(|change| change.transfer == transfer)
            .ok_or_else(|| not_now("check the online change of this transfer first"))?;
        let all = change.plan.details();
        let total = u16::try_from(all.len()).unwrap_or(u16::MAX);
        let mut used = 3;
        let mut details = Vec::new();
        for detail in all.iter().skip(usize::from(from)) {
            let entry = ChangeDetailEntry {
                kind: detail.kind as u8,
                name: cut(&detail.name, MAX_TEXT_BYTES).to_owned(),
            };
            if used + entry.wire_bytes() > MAX_PAYLOAD_BYTES || details.len() == MAX_COUNT {
                break;
            }
            used += entry.wire_bytes();
            details.push(entry);
        }
        Ok(Response::OnlineChangeDetails { total, details })
    }

    /// `ONLINE_CHANGE_APPLY`: the switch to the checked image between two cycles; the
    /// transfer ends with it.
    pub(super) fn online_change_apply(&self, transfer: u16) -> Result<Response, Refusal> {
        {
            let mut current = lock(&self.transfer);
            current_transfer(&mut current, transfer)
                .map_err(|_| not_now("the transfer has ended: transfer and check it again"))?;
        }
        let change = {
            let mut checked = lock(&self.checked);
            match checked.take() {
                Some(change) if change.transfer == transfer => change,
                other => {
                    *checked = other;
                    return Err(not_now("check the online change of this transfer first"));
                }
            }
        };
        if let Some((_, why)) = change.plan.refusal() {
            return Err(not_now(&format!("an online change is impossible: {why}")));
        }
        let report = self
            .scheduler
            .online_change(change.engine, change.plan, change.from, change.to)
            .map_err(|error| match error {
                SchedulerError::ProgramChanged => {
                    not_now("the running program changed since the check: transfer and check again")
                }
                other => scheduler_refusal(other),
            })?;
        *lock(&self.transfer) = None;
        Ok(Response::OnlineChangeApply(ChangeApplied {
            cycles: report.cycles,
            carried: report.applied.carried,
            retained: report.applied.retained > 0,
            switch_us: u32::try_from(report.switch.as_micros()).unwrap_or(u32::MAX),
        }))
    }
}

/// The name of the first task that is halted, waiting beneath a halted task or stepping: an
/// online change waits for no task to be in a cycle, which such a task is until it goes on.
fn halted_task(debug: &DebugState) -> Option<String> {
    (0..debug.task_count())
        .find(|&task| {
            debug.is_halted(task)
                || debug.waiting(task)
                || debug.task(task).is_some_and(TaskDebug::stepping)
        })
        .map(|task| debug.task_name(task).to_owned())
}

/// The path of the variable at a data place of `image`, as far as the symbols tell it.
fn place_name(image: &ProgramImage, place: &Place) -> String {
    image
        .symbols
        .iter()
        .filter(|symbol| symbol.region == Region::Data && symbol.offset <= place.offset)
        .max_by_key(|symbol| symbol.offset)
        .map_or_else(
            || format!("data byte {}", place.offset),
            |symbol| match place.offset - symbol.offset {
                0 => symbol.path.clone(),
                more => format!("{} (byte {more})", symbol.path),
            },
        )
}

#[cfg(test)]
#[path = "online_change_tests.rs"]
mod tests;
