//! When each task runs next: the scheduler's decisions as plain functions of time, so they are
//! tested without a clock.

use program_image::{Task, TaskKind};

use super::statistics::TaskStatistics;

/// The schedule of one task: when it is due next, its edge detection and watchdog count.
#[derive(Clone, Debug)]
pub(crate) struct TaskPlan {
    kind: TaskKind,
    interval_ns: u64,
    watchdog_ns: u64,
    watchdog_sensitivity: u32,
    /// The planned start of the next cycle; `None` while stopped, faulted, or (an event task)
    /// waiting for its trigger.
    next_start_ns: Option<u64>,
    /// The trigger's value at the last look, for the rising edge.
    trigger_was_set: bool,
    /// The cycle statistics, published to the handle.
    pub(crate) statistics: TaskStatistics,
}

impl TaskPlan {
    /// The plan of `task`, stopped.
    pub(crate) fn new(task: &Task) -> Self {
        Self {
            kind: task.kind,
            interval_ns: task.interval_ns,
            watchdog_ns: task.watchdog_ns,
            watchdog_sensitivity: task.watchdog_sensitivity.max(1),
            next_start_ns: None,
            trigger_was_set: false,
            statistics: TaskStatistics::new(task.name.clone(), task.kind, task.priority),
        }
    }

    /// The planned start of the next cycle, if one is planned.
    pub(crate) fn next_start_ns(&self) -> Option<u64> {
        self.next_start_ns
    }

    /// Whether the task is an event task.
    pub(crate) fn is_event(&self) -> bool {
        self.kind == TaskKind::Event
    }

    /// Starts the task at `now_ns`: cyclic and freewheeling tasks are due at once; an event
    /// task waits for a rising edge after `trigger_set`, its trigger's value now.
    pub(crate) fn start(&mut self, now_ns: u64, trigger_set: bool) {
        if self.statistics.faulted {
            return;
        }
        self.trigger_was_set = trigger_set;
        self.next_start_ns = match self.kind {
            TaskKind::Cyclic | TaskKind::Freewheeling => Some(now_ns),
            TaskKind::Event => None,
        };
    }

    /// Stops the task: nothing is planned until the next start.
    pub(crate) fn stop(&mut self) {
        self.next_start_ns = None;
    }

    /// Looks at an event task's trigger at `now_ns`: a rising edge makes the task due then.
    /// Edges that come and go between two looks are not seen.
    pub(crate) fn observe_trigger(&mut self, set: bool, now_ns: u64) {
        if set && !self.trigger_was_set && !self.statistics.faulted && self.next_start_ns.is_none()
        {
            self.next_start_ns = Some(now_ns);
        }
        self.trigger_was_set = set;
    }

    /// Records a cycle planned at `planned_ns` that ran from `started_ns` to `ended_ns`, of
    /// which `preempted_ns` went to tasks that interrupted it, and plans the next one. Returns
    /// `true` when the cycle was the `watchdog_sensitivity`-th in a row whose own time (without
    /// the interruptions) was longer than the watchdog time, which faults the task.
    ///
    /// A cyclic task keeps its phase: its next start is the first planned start after this one
    /// that has not passed by more than an interval, so a task that overran starts its next
    /// cycle at once and then drops the cycles it missed. A freewheeling task is due again
    /// `pause_ns` after its end, so that tasks of lower priority get their turn.
    pub(crate) fn finish(
        &mut self,
        planned_ns: u64,
        started_ns: u64,
        ended_ns: u64,
        preempted_ns: u64,
        pause_ns: u64,
    ) -> bool {
        let cycle_ns = ended_ns
            .saturating_sub(started_ns)
            .saturating_sub(preempted_ns);
        self.statistics
            .record(cycle_ns, started_ns.saturating_sub(planned_ns));
        self.next_start_ns = match self.kind {
            TaskKind::Cyclic => {
                let interval = self.interval_ns.max(1);
                let passed = ended_ns.saturating_sub(planned_ns) / interval;
                // The planned starts between this one and the next are dropped.
                self.statistics.missed_cycles += passed.saturating_sub(1);
                Some(planned_ns + passed.max(1) * interval)
            }
            TaskKind::Freewheeling => Some(ended_ns + pause_ns),
            TaskKind::Event => None,
        };
        if self.watchdog_ns > 0 && cycle_ns > self.watchdog_ns {
            self.statistics.consecutive_overruns += 1;
        } else {
            self.statistics.consecutive_overruns = 0;
        }
        self.statistics.consecutive_overruns >= self.watchdog_sensitivity
    }

    /// Faults the task: it runs no more until a reset.
    pub(crate) fn fault(&mut self) {
        self.statistics.faulted = true;
        self.next_start_ns = None;
    }
}

/// The task to run at `now_ns`: among those due, the highest priority (lowest number), then the
/// one planned earliest, then the first in the task table.
pub(crate) fn pick(plans: &[TaskPlan], now_ns: u64) -> Option<usize> {
    pick_where(plans, now_ns, |_, _| true)
}

/// As [`pick`], among the tasks `allowed` accepts (given their index and plan).
pub(crate) fn pick_where(
    plans: &[TaskPlan],
    now_ns: u64,
    allowed: impl Fn(usize, &TaskPlan) -> bool,
) -> Option<usize> {
    plans
        .iter()
        .enumerate()
        .filter(|(index, plan)| allowed(*index, plan))
        .filter_map(|(index, plan)| {
            let planned = plan.next_start_ns?;
            (planned <= now_ns).then_some((plan.statistics.priority, planned, index))
        })
        .min()
        .map(|(_, _, index)| index)
}

/// The earliest planned start of any task.
pub(crate) fn next_start_ns(plans: &[TaskPlan]) -> Option<u64> {
    next_start_where(plans, |_, _| true)
}

/// The earliest planned start of the tasks `allowed` accepts (given their index and plan).
pub(crate) fn next_start_where(
    plans: &[TaskPlan],
    allowed: impl Fn(usize, &TaskPlan) -> bool,
) -> Option<u64> {
    plans
        .iter()
        .enumerate()
        .filter(|(index, plan)| allowed(*index, plan))
        .filter_map(|(_, plan)| plan.next_start_ns())
        .min()
}

#[cfg(test)]
mod tests {
    use program_image::ProgramCall;

    use super::*;

    const MS: u64 = 1_000_000;

    fn task(kind: TaskKind, interval_ns: u64, priority: u8) -> Task {
        Task {
            name: format!("{kind:?}{priority}"),
            kind,
            interval_ns,
            trigger: None,
            priority,
            watchdog_ns: 0,
            watchdog_sensitivity: 1,
            programs: vec![ProgramCall {
                pou: 0,
                instance_offset: 0,
            }],
        }
    }

    fn started(tasks: &[Task]) -> Vec<TaskPlan> {
        tasks
            .iter()
            .map(|task| {
                let mut plan = TaskPlan::new(task);
                plan.start(0, false);
                plan
            })
            .collect()
    }

    #[test]
    fn when_several_tasks_are_due_the_highest_priority_runs_first() {
        let mut plans = started(&[
            task(TaskKind::Cyclic, 10 * MS, 5),
            task(TaskKind::Cyclic, 10 * MS, 0),
            task(TaskKind::Freewheeling, 0, 31),
            task(TaskKind::Cyclic, 20 * MS, 0),
        ]);
        let mut order = Vec::new();
        let mut now = 0;
        while let Some(index) = pick(&plans, now) {
            order.push(index);
            let planned = plans[index].next_start_ns().unwrap();
            plans[index].finish(planned, now, now + MS / 10, 0, MS);
            now += MS / 10;
        }
        // Equal priorities go by table order; the freewheeling task comes last at priority 31.
        assert_eq!(order, [1, 3, 0, 2]);
        assert_eq!(next_start_ns(&plans), Some(MS / 10 * 4 + MS));
    }

    #[test]
    fn an_overdue_lower_priority_task_waits_for_a_due_higher_one() {
        let mut plans = started(&[
            task(TaskKind::Cyclic, 10 * MS, 9),
            task(TaskKind::Cyclic, 10 * MS, 1),
        ]);
        plans[1].finish(0, 0, MS, 0, 0);
        plans[1].stop();
        plans[1].start(15 * MS, false);
        assert_eq!(pick(&plans, 15 * MS), Some(1));
    }

    #[test]
    fn a_cyclic_task_keeps_its_phase_and_drops_missed_cycles() {
        let mut plan = TaskPlan::new(&task(TaskKind::Cyclic, 10 * MS, 1));
        plan.start(0, false);
        assert!(!plan.finish(0, 200_000, 2 * MS, 0, 0));
        assert_eq!(plan.next_start_ns(), Some(10 * MS));
        assert_eq!(plan.statistics.last_jitter_ns, 200_000);
        // A cycle that ends 2.5 intervals after its planned start: the cycle planned at 20 ms
        // is dropped, the one planned at 30 ms starts at once.
        assert_eq!(plan.statistics.missed_cycles, 0);
        plan.finish(10 * MS, 10 * MS, 35 * MS, 0, 0);
        assert_eq!(plan.next_start_ns(), Some(30 * MS));
        assert_eq!(plan.statistics.missed_cycles, 1);
        // Starting late is not missing: 5 ms late is still the cycle planned at 30 ms.
        plan.finish(30 * MS, 35 * MS, 36 * MS, 0, 0);
        assert_eq!(plan.next_start_ns(), Some(40 * MS));
        assert_eq!(plan.statistics.max_jitter_ns, 5 * MS);
        assert_eq!(plan.statistics.cycles, 3);
        assert_eq!(plan.statistics.missed_cycles, 1);
    }

    #[test]
    fn a_freewheeling_task_pauses_between_cycles() {
        let mut plan = TaskPlan::new(&task(TaskKind::Freewheeling, 0, 1));
        plan.start(0, false);
        plan.finish(0, 0, 3 * MS, 0, MS / 2);
        assert_eq!(plan.next_start_ns(), Some(3 * MS + MS / 2));
    }

    #[test]
    fn an_event_task_runs_once_per_rising_edge() {
        let mut plan = TaskPlan::new(&task(TaskKind::Event, 0, 1));
        plan.start(0, true);
        // Already set at start: not an edge.
        plan.observe_trigger(true, MS);
        assert_eq!(plan.next_start_ns(), None);
        plan.observe_trigger(false, 2 * MS);
        plan.observe_trigger(true, 3 * MS);
        assert_eq!(plan.next_start_ns(), Some(3 * MS));
        plan.finish(3 * MS, 3 * MS + 10, 4 * MS, 0, 0);
        assert_eq!(plan.next_start_ns(), None);
        plan.observe_trigger(true, 5 * MS);
        assert_eq!(plan.next_start_ns(), None);
        assert_eq!(plan.statistics.last_jitter_ns, 10);
    }

    #[test]
    fn the_watchdog_faults_after_sensitivity_overruns_in_a_row() {
        let mut watched = task(TaskKind::Cyclic, 10 * MS, 1);
        watched.watchdog_ns = 2 * MS;
        watched.watchdog_sensitivity = 3;
        let mut plan = TaskPlan::new(&watched);
        plan.start(0, false);
        let mut run = |start: u64, length: u64| plan.finish(start, start, start + length, 0, 0);
        assert!(!run(0, 3 * MS));
        assert!(!run(10 * MS, 3 * MS));
        // A cycle within the watchdog time starts the count again.
        assert!(!run(20 * MS, 2 * MS));
        assert!(!run(30 * MS, 5 * MS));
        assert!(!run(40 * MS, 5 * MS));
        assert!(run(50 * MS, 5 * MS));
        assert_eq!(plan.statistics.consecutive_overruns, 3);
    }

    #[test]
    fn time_spent_in_preempting_tasks_is_neither_cycle_time_nor_an_overrun() {
        let mut watched = task(TaskKind::Cyclic, 10 * MS, 5);
        watched.watchdog_ns = 2 * MS;
        let mut plan = TaskPlan::new(&watched);
        plan.start(0, false);
        // 9 ms from start to end, 8 of them in tasks that interrupted it.
        assert!(!plan.finish(0, 0, 9 * MS, 8 * MS, 0));
        assert_eq!(plan.statistics.last_cycle_ns, MS);
        assert_eq!(plan.statistics.consecutive_overruns, 0);
        // The next start keeps the phase of the whole cycle, interruptions included.
        assert_eq!(plan.next_start_ns(), Some(10 * MS));
        assert!(plan.finish(10 * MS, 10 * MS, 19 * MS, 6 * MS, 0));
    }

    #[test]
    fn only_tasks_that_may_preempt_are_picked_and_planned_for() {
        let plans = started(&[
            task(TaskKind::Cyclic, 10 * MS, 5),
            task(TaskKind::Cyclic, 10 * MS, 1),
            task(TaskKind::Cyclic, 10 * MS, 9),
        ]);
        let above =
            |priority: u8| move |_: usize, plan: &TaskPlan| plan.statistics.priority < priority;
        assert_eq!(pick_where(&plans, 0, above(5)), Some(1));
        assert_eq!(pick_where(&plans, 0, above(1)), None);
        assert_eq!(pick_where(&plans, 0, |index, _| index != 1), Some(0));
        assert_eq!(
            next_start_where(&plans, |_, plan| plan.statistics.priority < 9),
            Some(0)
        );
        assert_eq!(
            next_start_where(&plans, |_, plan| plan.statistics.priority < 1),
            None
        );
    }

    #[test]
    fn a_faulted_task_is_not_started_again() {
        let mut plan = TaskPlan::new(&task(TaskKind::Cyclic, 10 * MS, 1));
        plan.start(0, false);
        plan.fault();
        plan.start(MS, false);
        assert_eq!(plan.next_start_ns(), None);
        assert_eq!(pick(std::slice::from_ref(&plan), MS), None);
    }
}
