//! What the scheduler's thread has to tell the readers of its status, kept until the status's
//! lock is free: the thread never waits for it, since a reader that holds it (a connection's
//! thread cloning the status) may itself be waiting for a processor. Statistics may therefore
//! be published a cycle or two late; faults are never lost, only delayed.

use std::sync::{Mutex, TryLockError};

use super::plan::TaskPlan;
use super::{MAX_FAULTS, SchedulerState, SchedulerStatus};
use crate::engine::FaultRecord;

/// Statistics and faults not published yet.
#[derive(Default)]
pub(super) struct Outbox {
    /// Faults in the order they happened.
    faults: Vec<FaultRecord>,
    /// Whether the tasks' statistics changed since they were last published.
    stale: bool,
}

impl Outbox {
    /// Notes that the statistics changed and, when `fault` is given, a fault to publish.
    pub(super) fn post(&mut self, fault: Option<FaultRecord>) {
        self.stale = true;
        self.faults.extend(fault);
    }

    /// Whether something waits to be published.
    pub(super) fn pending(&self) -> bool {
        self.stale || !self.faults.is_empty()
    }

    /// Publishes what waits when the status's lock is free now; returns whether it was.
    pub(super) fn try_publish(
        &mut self,
        status: &Mutex<SchedulerStatus>,
        plans: &[TaskPlan],
    ) -> bool {
        if !self.pending() {
            return true;
        }
        let mut status = match status.try_lock() {
            Ok(guard) => guard,
            Err(TryLockError::Poisoned(poisoned)) => poisoned.into_inner(),
            Err(TryLockError::WouldBlock) => return false,
        };
        self.publish(&mut status, plans);
        true
    }

    /// Publishes what waits into `status`, locked by the caller (between cycles, where a wait
    /// delays no cycle in progress).
    pub(super) fn publish(&mut self, status: &mut SchedulerStatus, plans: &[TaskPlan]) {
        if self.stale {
            for (published, plan) in status.tasks.iter_mut().zip(plans) {
                published.clone_from(&plan.statistics);
            }
            self.stale = false;
        }
        for fault in self.faults.drain(..) {
            if status.faults.len() >= MAX_FAULTS {
                status.faults.remove(0);
            }
            status.faults.push(fault);
            status.faults_total += 1;
            status.state = SchedulerState::Faulted;
        }
    }
}

#[cfg(test)]
mod tests {
    use program_image::{Task, TaskKind};

    use super::*;
    use crate::engine::FaultKind;
    use crate::scheduler::Realtime;

    fn fault(cycle: u64) -> FaultRecord {
        FaultRecord {
            task: "Main".to_owned(),
            kind: FaultKind::Memory,
            pou: "Program".to_owned(),
            file: None,
            line: None,
            instruction: 0,
            cycle,
        }
    }

    #[test]
    fn a_held_status_lock_delays_the_statistics_and_faults_but_loses_nothing() {
        let task = Task {
            name: "Main".to_owned(),
            kind: TaskKind::Cyclic,
            interval_ns: 1_000_000,
            trigger: None,
            priority: 1,
            watchdog_ns: 0,
            watchdog_sensitivity: 1,
            programs: Vec::new(),
        };
        let mut plans = vec![TaskPlan::new(&task)];
        let status = Mutex::new(SchedulerStatus {
            state: SchedulerState::Running,
            image: None,
            tasks: vec![plans[0].statistics.clone()],
            faults: Vec::new(),
            faults_total: 0,
            retain_problem: None,
            realtime: Realtime::Normal,
        });
        let mut outbox = Outbox::default();
        let held = status.lock().unwrap();
        for cycle in 0..3 {
            plans[0].statistics.cycles += 1;
            outbox.post(Some(fault(cycle)));
            assert!(!outbox.try_publish(&status, &plans), "waited for the lock");
        }
        drop(held);
        assert!(outbox.try_publish(&status, &plans));
        assert!(!outbox.pending());
        let status = status.lock().unwrap();
        assert_eq!(status.tasks[0].cycles, 3);
        let cycles: Vec<u64> = status.faults.iter().map(|fault| fault.cycle).collect();
        assert_eq!((cycles, status.faults_total), (vec![0, 1, 2], 3));
        assert_eq!(status.state, SchedulerState::Faulted);
    }
}
