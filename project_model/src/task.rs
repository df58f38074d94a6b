//! The task configuration: which programs run when.

use serde::{Deserialize, Serialize};

/// A task of the task configuration.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Task {
    /// The task's name, an IEC identifier.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// When the task runs.
    pub kind: TaskKind,
    /// Priority from 0 (highest) to 31 (lowest), as in CODESYS.
    #[cfg_attr(feature = "proptest", proptest(strategy = "0u8..=31"))]
    pub priority: u8,
    /// The watchdog, if enabled.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub watchdog: Option<Watchdog>,
    /// The programs the task calls, in calling order: program names, or program instance names
    /// from a configuration.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident_vec()"))]
    pub programs: Vec<String>,
}

/// When a task runs.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum TaskKind {
    /// Runs every `interval_us` microseconds.
    Cyclic {
        /// The cycle interval in microseconds.
        interval_us: u32,
    },
    /// Runs again as soon as it finishes, yielding to higher priorities.
    Freewheeling,
    /// Runs once on every rising edge of a BOOL variable.
    Event {
        /// The path of the BOOL variable whose rising edge starts the task.
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
        trigger: String,
    },
}

/// A task watchdog: the task is stopped with a fault when its cycle takes longer than `time_us`
/// in `sensitivity` consecutive cycles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Watchdog {
    /// The longest allowed cycle time in microseconds.
    pub time_us: u32,
    /// How many consecutive overruns trip the watchdog (1 = the first one).
    pub sensitivity: u32,
}
