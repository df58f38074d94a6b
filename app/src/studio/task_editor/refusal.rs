//! Why the task editor refuses a value or a program call, kept typed until it is shown in the
//! interface language.

use super::time_literal::TimeRefusal;
use crate::studio::i18n::{Language, RefusalText};
use crate::studio::tree_actions::Refusal;

/// Why a task field or a new program call is refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TaskRefusal {
    /// The new task name is refused.
    Name(Refusal),
    /// The interval or watchdog time is refused.
    Time(TimeRefusal),
    /// The trigger is no variable path.
    NotAVariable(String),
    /// The priority is no number from 0 to `lowest`.
    NotAPriority {
        /// What was typed.
        input: String,
        /// The highest priority number, the lowest priority.
        lowest: u8,
    },
    /// The watchdog sensitivity is no number of 1 or more.
    NotASensitivity(String),
    /// No program was chosen to call.
    NoProgramChosen,
    /// The project has no PROGRAM of that name.
    NoSuchProgram(String),
    /// The task already calls the program.
    AlreadyCalls {
        /// The task.
        task: String,
        /// The program.
        program: String,
    },
}

impl TaskRefusal {
    /// The refusal as the user reads it, in `language`.
    pub fn text(&self, language: Language) -> String {
        match self {
            Self::Name(refusal) => refusal.text(language),
            Self::Time(refusal) => refusal.text(language),
            Self::NotAVariable(input) => {
                RefusalText::NotATriggerVariable.fill(language, &[("input", input)])
            }
            Self::NotAPriority { input, lowest } => RefusalText::NotAPriority.fill(
                language,
                &[("input", input), ("lowest", &lowest.to_string())],
            ),
            Self::NotASensitivity(input) => {
                RefusalText::NotASensitivity.fill(language, &[("input", input)])
            }
            Self::NoProgramChosen => RefusalText::ChooseProgramToCall.get(language).to_owned(),
            Self::NoSuchProgram(program) => {
                RefusalText::NoProgramNamed.fill(language, &[("program", program)])
            }
            Self::AlreadyCalls { task, program } => {
                RefusalText::AlreadyCalls.fill(language, &[("task", task), ("program", program)])
            }
        }
    }
}

impl From<TimeRefusal> for TaskRefusal {
    fn from(refusal: TimeRefusal) -> Self {
        Self::Time(refusal)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn task_refusals_read_in_english_and_chinese() {
        let priority = TaskRefusal::NotAPriority {
            input: "32".to_owned(),
            lowest: 31,
        };
        assert_eq!(
            priority.text(Language::English),
            "'32' is not a priority: use 0 (highest) to 31 (lowest)"
        );
        assert_eq!(
            priority.text(Language::SimplifiedChinese),
            "“32”不是优先级：请使用 0（最高）到 31（最低）"
        );
        let calls = TaskRefusal::AlreadyCalls {
            task: "MainTask".to_owned(),
            program: "Main".to_owned(),
        };
        assert_eq!(calls.text(Language::English), "MainTask already calls Main");
        assert_eq!(
            calls.text(Language::SimplifiedChinese),
            "MainTask 已调用 Main"
        );
    }
}
