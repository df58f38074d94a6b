//! The typed fields of a task and the checks a value passes before it becomes an edit.

use project_model::{Project, Task, TaskKind, Watchdog, is_valid_identifier};

use super::refusal::TaskRefusal;
use super::time_literal::{format_time_us, parse_time_us};
use crate::studio::i18n::{Language, Text};
use crate::studio::tree_actions::{NameScope, name_problem};

/// A field of a task typed as text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Field {
    /// The task's name.
    Name,
    /// A cyclic task's interval.
    Interval,
    /// An event task's trigger variable.
    Trigger,
    /// The priority, 0 to 31.
    Priority,
    /// The watchdog's time.
    WatchdogTime,
    /// The watchdog's sensitivity.
    Sensitivity,
}

/// The highest priority number (the lowest priority), as in CODESYS.
pub const LOWEST_PRIORITY: u8 = 31;

/// What a watchdog starts with when it is switched on: twice the interval of a cyclic task,
/// 100 ms otherwise, tripping on the first overrun.
pub fn default_watchdog(task: &Task) -> Watchdog {
    let time_us = match task.kind {
        TaskKind::Cyclic { interval_us } => interval_us.saturating_mul(2),
        _ => 100_000,
    };
    Watchdog {
        time_us,
        sensitivity: 1,
    }
}

impl Field {
    /// The field's name in the interface.
    pub fn text(self) -> Text {
        match self {
            Self::Name => Text::Name,
            Self::Interval => Text::Interval,
            Self::Trigger => Text::TriggerVariable,
            Self::Priority => Text::Priority,
            Self::WatchdogTime => Text::WatchdogTime,
            Self::Sensitivity => Text::Sensitivity,
        }
    }

    /// The field's current value as text, or `None` when the task has no such field (the
    /// interval of an event task, the time of a disabled watchdog).
    pub fn current(self, task: &Task) -> Option<String> {
        match (self, &task.kind) {
            (Self::Name, _) => Some(task.name.clone()),
            (Self::Interval, TaskKind::Cyclic { interval_us }) => {
                Some(format_time_us(*interval_us))
            }
            (Self::Trigger, TaskKind::Event { trigger }) => Some(trigger.clone()),
            (Self::Priority, _) => Some(task.priority.to_string()),
            (Self::WatchdogTime, _) => task.watchdog.map(|w| format_time_us(w.time_us)),
            (Self::Sensitivity, _) => task.watchdog.map(|w| w.sensitivity.to_string()),
            (Self::Interval | Self::Trigger, _) => None,
        }
    }

    /// The task with this field set to `input`, and the undo label of the change in
    /// `language`; or the reason the input is refused.
    pub fn apply(
        self,
        project: &Project,
        task: &Task,
        input: &str,
        language: Language,
    ) -> Result<(Task, String), TaskRefusal> {
        let input = input.trim();
        let mut changed = task.clone();
        let name = &task.name;
        let label = match self {
            Self::Name => {
                if let Some(problem) =
                    name_problem(project, NameScope::Task, input, Some(name.as_str()))
                {
                    return Err(TaskRefusal::Name(problem));
                }
                changed.name = input.to_owned();
                Text::UndoRenameTask.fill(language, &[("name", name), ("new", input)])
            }
            Self::Interval => {
                let interval_us = parse_time_us(input)?;
                changed.kind = TaskKind::Cyclic { interval_us };
                let value = format_time_us(interval_us);
                Text::UndoSetInterval.fill(language, &[("name", name), ("value", &value)])
            }
            Self::Trigger => {
                let valid = !input.is_empty() && input.split('.').all(is_valid_identifier);
                if !valid {
                    return Err(TaskRefusal::NotAVariable(input.to_owned()));
                }
                changed.kind = TaskKind::Event {
                    trigger: input.to_owned(),
                };
                Text::UndoSetTrigger.fill(language, &[("name", name), ("value", input)])
            }
            Self::Priority => {
                let priority = input
                    .parse::<u8>()
                    .ok()
                    .filter(|p| *p <= LOWEST_PRIORITY)
                    .ok_or_else(|| TaskRefusal::NotAPriority {
                        input: input.to_owned(),
                        lowest: LOWEST_PRIORITY,
                    })?;
                changed.priority = priority;
                let value = priority.to_string();
                Text::UndoSetPriority.fill(language, &[("name", name), ("value", &value)])
            }
            Self::WatchdogTime => {
                let time_us = parse_time_us(input)?;
                let mut watchdog = task.watchdog.unwrap_or_else(|| default_watchdog(task));
                watchdog.time_us = time_us;
                changed.watchdog = Some(watchdog);
                let value = format_time_us(time_us);
                Text::UndoSetWatchdogTime.fill(language, &[("name", name), ("value", &value)])
            }
            Self::Sensitivity => {
                let sensitivity = input
                    .parse::<u32>()
                    .ok()
                    .filter(|s| *s >= 1)
                    .ok_or_else(|| TaskRefusal::NotASensitivity(input.to_owned()))?;
                let mut watchdog = task.watchdog.unwrap_or_else(|| default_watchdog(task));
                watchdog.sensitivity = sensitivity;
                changed.watchdog = Some(watchdog);
                let value = sensitivity.to_string();
                Text::UndoSetSensitivity.fill(language, &[("name", name), ("value", &value)])
            }
        };
        Ok((changed, label))
    }
}

/// Why `program` cannot be added to `task`'s calls, or `None` when it can: it must be a
/// PROGRAM of the project that the task does not call yet.
pub fn call_problem(project: &Project, task: &Task, program: &str) -> Option<TaskRefusal> {
    let program = program.trim();
    if program.is_empty() {
        return Some(TaskRefusal::NoProgramChosen);
    }
    let is_program = matches!(
        project.application.object(program),
        Some(project_model::Object::Pou(pou)) if pou.kind == project_model::PouKind::Program
    );
    if !is_program {
        return Some(TaskRefusal::NoSuchProgram(program.to_owned()));
    }
    if task
        .programs
        .iter()
        .any(|called| project_model::same_identifier(called, program))
    {
        return Some(TaskRefusal::AlreadyCalls {
            task: task.name.clone(),
            program: program.to_owned(),
        });
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn task() -> Task {
        Task {
            name: "MainTask".into(),
            kind: TaskKind::Cyclic {
                interval_us: 10_000,
            },
            priority: 1,
            watchdog: None,
            programs: Vec::new(),
        }
    }

    #[test]
    fn valid_values_change_the_task_and_say_so() {
        let project = Project::default();
        let (changed, label) = Field::Priority
            .apply(&project, &task(), "5", Language::English)
            .unwrap();
        assert_eq!(changed.priority, 5);
        assert_eq!(label, "Set priority of MainTask to 5");
        let (changed, _) = Field::Interval
            .apply(&project, &task(), "T#2ms", Language::English)
            .unwrap();
        assert_eq!(changed.kind, TaskKind::Cyclic { interval_us: 2000 });
        let (changed, _) = Field::Sensitivity
            .apply(&project, &task(), "3", Language::English)
            .unwrap();
        assert_eq!(
            changed.watchdog,
            Some(Watchdog {
                time_us: 20_000,
                sensitivity: 3
            })
        );
    }

    #[test]
    fn out_of_range_values_are_refused() {
        let project = Project::default();
        assert!(
            Field::Priority
                .apply(&project, &task(), "32", Language::English)
                .is_err()
        );
        assert!(
            Field::Priority
                .apply(&project, &task(), "-1", Language::English)
                .is_err()
        );
        assert!(
            Field::Interval
                .apply(&project, &task(), "0", Language::English)
                .is_err()
        );
        assert!(
            Field::Sensitivity
                .apply(&project, &task(), "0", Language::English)
                .is_err()
        );
        assert!(
            Field::Trigger
                .apply(&project, &task(), "a..b", Language::English)
                .is_err()
        );
        assert!(call_problem(&project, &task(), "Missing").is_some());
    }
}
