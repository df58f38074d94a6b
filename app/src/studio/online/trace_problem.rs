//! Why a trace could not start: its configuration does not fit the program or the device it
//! records, or a variable could not be resolved. Shown in the interface language.

use thiserror::Error;

use super::device_problem::DeviceProblem;
use crate::studio::i18n::{Language, Text};

/// Why a trace run was refused before or while it was armed.
#[derive(Debug, Error)]
pub enum TraceProblem {
    /// The trace's task is not one of the program's tasks.
    #[error("{}", Text::ProgramHasNoTask.fill(*language, &[("task", task)]))]
    NoSuchTask {
        /// The task the trace names.
        task: String,
        /// The language the text is shown in.
        language: Language,
    },
    /// The task's position does not fit the protocol's task number.
    #[error("{}", Text::TooManyTasks.get(*language))]
    TooManyTasks {
        /// The language the text is shown in.
        language: Language,
    },
    /// The trace records no variable.
    #[error("{}", Text::NoVariablesToRecord.get(*language))]
    NoVariables {
        /// The language the text is shown in.
        language: Language,
    },
    /// The trace records no sample.
    #[error("{}", Text::RecordCountZero.get(*language))]
    RecordCountZero {
        /// The language the text is shown in.
        language: Language,
    },
    /// Every n-th cycle is 0 or beyond the protocol's 16 bits.
    #[error(
        "{}",
        Text::EveryNthRange.fill(
            *language,
            &[("max", &u16::MAX.to_string()), ("value", &every_n_cycles.to_string())]
        )
    )]
    EveryNthOutOfRange {
        /// The configured number of cycles between two samples.
        every_n_cycles: u32,
        /// The language the text is shown in.
        language: Language,
    },
    /// The target could not resolve a recorded variable or the trigger.
    #[error("{path}: {reason}")]
    NotResolved {
        /// The variable's path.
        path: String,
        /// The target's reason, as the session reported it.
        reason: String,
    },
    /// The trigger variable is not a BOOL.
    #[error("{}", Text::TriggerNotBool.fill(*language, &[("name", name)]))]
    TriggerNotBool {
        /// The trigger variable's path.
        name: String,
        /// The language the text is shown in.
        language: Language,
    },
    /// A variable of a device trace is bound to a channel of several values, which the
    /// studio's poll does not read.
    #[error(
        "{}",
        Text::DeviceArrayChannel.fill(*language, &[("path", path), ("count", &count.to_string())])
    )]
    SeveralValues {
        /// The variable's path.
        path: String,
        /// The number of values of its channel.
        count: u16,
        /// The language the text is shown in.
        language: Language,
    },
    /// A variable of a device trace is bound to no device the studio polls.
    #[error("{}", Text::NotBoundToDevice.fill(*language, &[("path", path)]))]
    NotBoundToDevice {
        /// The variable's path.
        path: String,
        /// The language the text is shown in.
        language: Language,
    },
    /// The variables of a device trace are bound to different devices.
    #[error("{}", Text::DifferentDevices.get(*language))]
    DifferentDevices {
        /// The language the text is shown in.
        language: Language,
    },
    /// A variable's binding names a channel its device does not have.
    #[error("{}", Text::BindingNoChannel.get(*language))]
    BindingNoChannel {
        /// The language the text is shown in.
        language: Language,
    },
    /// A device trace has a trigger, which polling cannot honour.
    #[error("{}", Text::DeviceTraceNoTrigger.get(*language))]
    DeviceTraceNoTrigger {
        /// The language the text is shown in.
        language: Language,
    },
    /// The device of a device trace is no longer in the project.
    #[error("{}", Text::DeviceGone.get(*language))]
    DeviceGone {
        /// The language the text is shown in.
        language: Language,
    },
    /// The device refused to start the trace.
    #[error(transparent)]
    Device(#[from] DeviceProblem),
}

#[cfg(test)]
mod tests {
    use project_model::{TraceConfig, TraceVariable};

    use super::super::trace_run::TraceRun;
    use super::*;

    /// A trace of `Main.x` in task `task`, sampled every `every` cycles.
    fn config(task: &str, every: u32, record_count: u32) -> TraceConfig {
        TraceConfig {
            name: "T".to_owned(),
            task: task.to_owned(),
            every_n_cycles: every,
            record_count,
            trigger: None,
            variables: vec![TraceVariable {
                path: "Main.x".to_owned(),
                color: None,
            }],
        }
    }

    /// Why `config` is refused, in `language`.
    fn refusal(config: &TraceConfig, language: Language) -> String {
        let tasks = ["MainTask".to_owned()];
        match TraceRun::default().prepare(config, &tasks, language) {
            Ok(paths) => panic!("accepted with {paths:?}"),
            Err(problem) => problem.to_string(),
        }
    }

    #[test]
    fn a_refused_configuration_reads_as_the_template_filled_in_each_language() {
        assert_eq!(
            refusal(&config("Fast", 1, 100), Language::English),
            "the program has no task 'Fast'"
        );
        assert_eq!(
            refusal(&config("Fast", 1, 100), Language::SimplifiedChinese),
            "程序中没有任务“Fast”"
        );
        assert_eq!(
            refusal(&config("maintask", 70_000, 100), Language::English),
            "every n-th cycle must be 1 to 65535, not 70000"
        );
        assert_eq!(
            refusal(&config("MainTask", 1, 0), Language::SimplifiedChinese),
            "记录数为 0"
        );
    }

    #[test]
    fn a_device_refusal_and_an_unresolved_path_keep_their_own_text() {
        let busy = TraceProblem::from(DeviceProblem::Busy {
            device: "Meter".to_owned(),
            language: Language::English,
        });
        assert_eq!(busy.to_string(), "device Meter is busy; try again");
        let not_polled = DeviceProblem::NotPolled {
            device: "Meter".to_owned(),
            language: Language::SimplifiedChinese,
        };
        assert_eq!(
            not_polled.to_string(),
            "设备 Meter 未被轮询；请监视其一个变量"
        );
        let unresolved = TraceProblem::NotResolved {
            path: "Main.y".to_owned(),
            reason: "not found".to_owned(),
        };
        assert_eq!(unresolved.to_string(), "Main.y: not found");
    }
}
