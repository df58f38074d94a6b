//! The plain data the SFC editor exchanges with the app: its change, the findings and online
//! state it shows, and the online commands it asks the app to execute.

use std::collections::HashMap;
use std::time::Duration;

use project_model::sfc_edit::SfcEditError;
use project_model::{ElementId, SfcChart};

use crate::Severity;

/// One change of the chart: the whole new chart, which the app applies as one
/// `Edit::ReplaceChart` (one gesture, one undo step).
#[derive(Clone, Debug, PartialEq)]
pub struct SfcChange {
    /// The chart after the gesture; it keeps every structural rule.
    pub chart: SfcChart,
}

/// A finding of the checker placed on an element of the chart.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SfcDiagnostic {
    /// The element; `None` for a finding about the chart as a whole.
    pub element: Option<ElementId>,
    /// Error, warning or note.
    pub severity: Severity,
    /// The stable diagnostic code, such as `E0104`.
    pub code: String,
    /// The message, shown on hover.
    pub message: String,
}

/// A step's state while online.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SfcStepOnline {
    /// Whether the step is active (`<step>.x`).
    pub active: bool,
    /// How long it has been active (`<step>.t`).
    pub elapsed: Duration,
    /// Whether it has been active longer than its maximum time (the chart's `SFCError` for this
    /// step); shown as an error on the step.
    pub over_max_time: bool,
}

/// What the target reports while logged in. Replaced by the app each time new values arrive;
/// never saved.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SfcOnline {
    /// Each step's (and macro step's) state, by element.
    pub steps: HashMap<ElementId, SfcStepOnline>,
    /// Each transition's condition value, by element.
    pub transitions: HashMap<ElementId, bool>,
    /// Whether each action is active (`_<action>.x`), by the action's name as the chart writes
    /// it.
    pub actions: HashMap<String, bool>,
    /// Whether the chart runs in tip mode, where a transition fires only when the user fires
    /// it.
    pub tip_mode: bool,
}

/// An online action the user asked for from the chart; the app executes it (never undoable).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SfcOnlineCommand {
    /// Activate (`true`) or deactivate the step: the app writes `<step>._x`.
    SetStepActive {
        /// The step's name.
        step: String,
        /// Whether it becomes active.
        active: bool,
    },
    /// Fire the transition now (tip mode).
    FireTransition {
        /// The transition.
        transition: ElementId,
    },
}

/// What one frame of the SFC editor produced.
#[derive(Debug)]
pub struct SfcOutput {
    /// The canvas's response (focus, hover, the accessible label).
    pub response: egui::Response,
    /// The change made this frame: one gesture, one undo step.
    pub change: Option<SfcChange>,
    /// An online action to execute.
    pub online: Option<SfcOnlineCommand>,
    /// Why the last command did nothing, if it did nothing; the editor also shows it.
    pub refusal: Option<SfcEditError>,
    /// Where the user asked to set or clear a breakpoint (F9 or the context menu): the
    /// selected step (its actions) or transition (its test), in network 0.
    pub toggle_breakpoint: Option<crate::BodyPlace>,
}
