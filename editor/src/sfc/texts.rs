//! The SFC editor's words, filled by the app in the user's language.

use std::fmt;
use std::sync::Arc;

use project_model::sfc_edit::SfcEditError;

/// Words a refusal is shown in: the app gives one that speaks the user's language.
pub type SfcRefusalWords = Arc<dyn Fn(&SfcEditError) -> String + Send + Sync>;

/// Every word the SFC editor shows. The defaults are English; the app replaces them.
#[derive(Clone)]
pub struct SfcTexts {
    /// The toolbox's title.
    pub toolbox: String,
    /// "Step-transition" (inserted after the selection).
    pub step_transition: String,
    /// "Step-transition before".
    pub step_transition_before: String,
    /// "Alternative branch".
    pub alternative_branch: String,
    /// "Parallel branch".
    pub parallel_branch: String,
    /// "Add branch".
    pub add_branch: String,
    /// "Jump".
    pub jump: String,
    /// "Macro step".
    pub macro_step: String,
    /// "Wrap in macro step".
    pub wrap_in_macro: String,
    /// "Action association".
    pub action_association: String,
    /// "Delete".
    pub delete: String,
    /// "Copy".
    pub copy: String,
    /// "Paste".
    pub paste: String,
    /// "Edit text".
    pub edit_text: String,
    /// "Open macro step".
    pub open_macro: String,
    /// "Back" out of a macro step, to the chart.
    pub leave_macro: String,
    /// The name of the chart's own level in the macro path.
    pub chart: String,
    /// The step properties panel's title.
    pub step_properties: String,
    /// "Minimum time".
    pub min_time: String,
    /// "Maximum time".
    pub max_time: String,
    /// "Entry action".
    pub entry_action: String,
    /// "Step action" (CODESYS's main action).
    pub main_action: String,
    /// "Exit action".
    pub exit_action: String,
    /// "Comment".
    pub comment: String,
    /// "Qualifier".
    pub qualifier: String,
    /// "Action".
    pub action: String,
    /// "Time".
    pub time: String,
    /// "Indicator".
    pub indicator: String,
    /// "Remove".
    pub remove: String,
    /// "Move up".
    pub move_up: String,
    /// "Priority".
    pub priority: String,
    /// "Activate step" (online).
    pub activate_step: String,
    /// "Deactivate step" (online).
    pub deactivate_step: String,
    /// "Fire transition" (online, tip mode).
    pub fire_transition: String,
    /// "Maximum time exceeded" on a step online.
    pub over_max_time: String,
    /// The accessible name of the field of a step's name.
    pub step_name_field: String,
    /// The accessible name of the field of a transition's condition.
    pub condition_field: String,
    /// The accessible name of the field of a jump's target.
    pub jump_target_field: String,
    /// "Zoom" (the tooltip of the zoom percentage).
    pub zoom: String,
    /// The context menu's entry that sets or clears the breakpoint of the selected step or
    /// transition.
    pub toggle_breakpoint: String,
    /// The refusal's reason in the user's language.
    pub refusal: SfcRefusalWords,
}

impl fmt::Debug for SfcTexts {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SfcTexts")
            .field("toolbox", &self.toolbox)
            .finish_non_exhaustive()
    }
}

impl Default for SfcTexts {
    fn default() -> Self {
        Self {
            toolbox: "Toolbox".into(),
            step_transition: "Step-transition".into(),
            step_transition_before: "Step-transition before".into(),
            alternative_branch: "Alternative branch".into(),
            parallel_branch: "Parallel branch".into(),
            add_branch: "Add branch".into(),
            jump: "Jump".into(),
            macro_step: "Macro step".into(),
            wrap_in_macro: "Wrap in macro step".into(),
            action_association: "Action association".into(),
            delete: "Delete".into(),
            copy: "Copy".into(),
            paste: "Paste".into(),
            edit_text: "Edit text".into(),
            open_macro: "Open macro step".into(),
            leave_macro: "Back".into(),
            chart: "Chart".into(),
            step_properties: "Step properties".into(),
            min_time: "Minimum time".into(),
            max_time: "Maximum time".into(),
            entry_action: "Entry action".into(),
            main_action: "Step action".into(),
            exit_action: "Exit action".into(),
            comment: "Comment".into(),
            qualifier: "Qualifier".into(),
            action: "Action".into(),
            time: "Time".into(),
            indicator: "Indicator".into(),
            remove: "Remove".into(),
            move_up: "Move up".into(),
            priority: "Priority".into(),
            activate_step: "Activate step".into(),
            deactivate_step: "Deactivate step".into(),
            fire_transition: "Fire transition".into(),
            over_max_time: "Maximum time exceeded".into(),
            step_name_field: "Step name".into(),
            condition_field: "Condition".into(),
            jump_target_field: "Jump target".into(),
            zoom: "Zoom (Ctrl + mouse wheel)".into(),
            toggle_breakpoint: "Toggle breakpoint".into(),
            refusal: Arc::new(|error: &SfcEditError| error.to_string()),
        }
    }
}
