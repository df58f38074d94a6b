//! Trace configurations: which signals the runtime records and when.

use serde::{Deserialize, Serialize};

/// A trace configuration object of the application.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct TraceConfig {
    /// The trace's name; it is the file name, not stored in the file.
    #[serde(skip)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The task in whose cycle samples are taken.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub task: String,
    /// A sample is taken every `every_n_cycles` cycles of the task (1 = every cycle).
    pub every_n_cycles: u32,
    /// How many samples the trace buffer holds.
    pub record_count: u32,
    /// When recording stops; without a trigger the buffer runs as a ring.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trigger: Option<TraceTrigger>,
    /// The recorded variables in display order.
    #[serde(default, rename = "variable", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub variables: Vec<TraceVariable>,
}

/// The trigger of a trace.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct TraceTrigger {
    /// The path of the trigger variable.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub variable: String,
    /// The condition on it.
    pub condition: TraceTriggerCondition,
    /// For level conditions on numbers: the value crossed, as written.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
    pub level: Option<String>,
    /// Share of the buffer recorded before the trigger, 0 to 100 percent.
    #[cfg_attr(feature = "proptest", proptest(strategy = "0u8..=100"))]
    pub pre_trigger_percent: u8,
}

/// The condition that fires a trace trigger.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum TraceTriggerCondition {
    /// A BOOL goes from FALSE to TRUE, or a number rises through `level`.
    Rising,
    /// A BOOL goes from TRUE to FALSE, or a number falls through `level`.
    Falling,
    /// A BOOL is TRUE, or a number equals `level`.
    Level,
}

/// A recorded variable.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct TraceVariable {
    /// The variable's path, such as `Main.fbConveyor.tDelay.ET`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub path: String,
    /// The plot colour as `#rrggbb`, if chosen by the user.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
    pub color: Option<String>,
}
