//! The state a textual SFC chart keeps in its instance: each step's `x`, `_x`, `t` and
//! activation time, each associated action's `ACTION_CONTROL`, and the chart's own flags.
//! The `x` and `_x` of all steps, and the `busy` and `Q` of all actions, are arrays of bytes,
//! so the code tests the flags of eight steps or actions with one LWORD.

use std::collections::HashMap;

use crate::sfc_chart::{ActionQualifier, Chart};
use crate::syntax::parse_statements;

use super::sfc::top_level;

/// Steps or actions whose flags one LWORD covers.
pub(super) const GROUP: usize = 8;

/// Offsets of a step's state inside its 16 bytes (its `x` and `_x` are in the arrays).
pub(super) mod step_at {
    pub(crate) const ENTERING: u32 = 2;
    pub(crate) const LEAVING: u32 = 3;
    pub(crate) const T: u32 = 4;
    pub(crate) const STARTED: u32 = 8;
    pub(crate) const SIZE: u32 = 16;
}

/// Offsets of an action's `ACTION_CONTROL` state inside its bytes (its `busy` flag, set
/// while something may change its outputs, and its `Q` are in the arrays).
pub(super) mod action_at {
    /// BOOL: `A`, the action's body runs this cycle (`_Action.x`).
    pub(crate) const A: u32 = 2;
    /// BOOL: the body runs in the first pass (a final or pulse call with `Q` FALSE).
    pub(crate) const FINAL: u32 = 3;
    /// BOOL: `Q` of the previous cycle.
    pub(crate) const Q_PREV: u32 = 4;
    /// BOOL per qualifier: its input this cycle (the OR over the active steps).
    pub(crate) const REQUEST: u32 = 5;
    /// BOOL per qualifier: its flip-flop or edge memory.
    pub(crate) const MEMORY: u32 = 16;
    /// BOOL per qualifier: its timer is running.
    pub(crate) const RUNNING: u32 = 27;
    /// TIME per qualifier: its duration.
    pub(crate) const TIME: u32 = 40;
    /// LINT per qualifier: the clock when its timer started.
    pub(crate) const STARTED: u32 = 88;
    pub(crate) const SIZE: u32 = 176;
}

fn index_of(qualifier: ActionQualifier) -> u32 {
    ActionQualifier::ALL
        .iter()
        .position(|q| *q == qualifier)
        .unwrap_or(0) as u32
}

/// One step's state in the instance.
#[derive(Clone, Debug)]
pub(crate) struct StepSlots {
    pub(crate) name: String,
    pub(crate) initial: bool,
    /// BOOL `x`: active this cycle, in the array of the steps' `x`.
    pub(super) x: u32,
    /// BOOL `_x`: active next cycle, in the array of the steps' `_x`.
    pub(super) next: u32,
    /// Where its 16 further bytes start.
    pub(super) at: u32,
}

impl StepSlots {
    /// BOOL `x`: active this cycle.
    pub(crate) fn x(&self) -> u32 {
        self.x
    }
    /// BOOL `_x`: active next cycle.
    pub(crate) fn next(&self) -> u32 {
        self.next
    }
    /// TIME `t`: elapsed since activation.
    pub(crate) fn t(&self) -> u32 {
        self.at + step_at::T
    }
    pub(super) fn entering(&self) -> u32 {
        self.at + step_at::ENTERING
    }
    pub(super) fn leaving(&self) -> u32 {
        self.at + step_at::LEAVING
    }
    pub(super) fn started(&self) -> u32 {
        self.at + step_at::STARTED
    }
}

/// One associated action's state in the instance.
#[derive(Clone, Debug)]
pub(crate) struct ActionSlots {
    /// The name as first written in an association.
    pub(crate) name: String,
    /// BOOL in the array of the actions' `busy` flags.
    pub(super) busy: u32,
    /// BOOL `Q` in the array of the actions' `Q`.
    pub(super) q: u32,
    /// Where its further bytes start.
    pub(super) at: u32,
}

impl ActionSlots {
    /// BOOL `_Action.x`: the action's body runs this cycle.
    pub(crate) fn x(&self) -> u32 {
        self.at + action_at::A
    }
    /// BOOL `_Action._x`: the action is active (its `Q`).
    pub(crate) fn active(&self) -> u32 {
        self.q
    }
    pub(super) fn busy(&self) -> u32 {
        self.busy
    }
    pub(super) fn request(&self, q: ActionQualifier) -> u32 {
        self.at + action_at::REQUEST + index_of(q)
    }
    pub(super) fn memory(&self, q: ActionQualifier) -> u32 {
        self.at + action_at::MEMORY + index_of(q)
    }
    pub(super) fn running(&self, q: ActionQualifier) -> u32 {
        self.at + action_at::RUNNING + index_of(q)
    }
    pub(super) fn time(&self, q: ActionQualifier) -> u32 {
        self.at + action_at::TIME + 4 * index_of(q)
    }
    pub(super) fn timer_started(&self, q: ActionQualifier) -> u32 {
        self.at + action_at::STARTED + 8 * index_of(q)
    }
}

/// The SFC state a chart keeps at the end of its instance.
#[derive(Clone, Debug, Default)]
pub(crate) struct SfcLayout {
    /// BOOL: the initial step has been activated.
    pub(crate) initialised: u32,
    /// BOOL: `SFCQuitError` in the previous cycle.
    pub(super) quit_before: u32,
    /// BOOL: `SFCTip` in the previous cycle.
    pub(super) tip_before: u32,
    /// LINT: the task clock of the previous cycle, when the transitions fired.
    pub(super) previous_now: u32,
    /// The arrays of the steps' `x` and `_x` and of the actions' `busy` and `Q`, each padded
    /// to whole groups: (start, bytes).
    pub(super) step_x: (u32, u32),
    pub(super) step_next: (u32, u32),
    pub(super) action_busy: (u32, u32),
    pub(super) action_q: (u32, u32),
    pub(crate) steps: Vec<StepSlots>,
    /// By lower-case name, in alphabetical order.
    pub(crate) actions: Vec<(String, ActionSlots)>,
    /// The index in `steps` of each step by lower-case name.
    step_index: HashMap<String, usize>,
    /// BOOL per transition written with statements, by lower-case name: its value.
    transition_values: Vec<(String, u32)>,
}

impl SfcLayout {
    /// The layout of the chart in `text` placed from `offset` on, with its end; `None` when
    /// the text has no steps.
    pub(crate) fn of_body(text: &str, offset: u32) -> Option<(Self, u32)> {
        if !crate::sfc_chart::may_hold_chart(text) {
            return None;
        }
        let root = top_level(&parse_statements(text).syntax())?;
        let chart = Chart::of(&root)?;
        let start = offset.next_multiple_of(8);
        let mut layout = Self {
            initialised: start,
            quit_before: start + 1,
            tip_before: start + 2,
            previous_now: start + 8,
            ..Self::default()
        };
        let padded = |count: usize| (count.div_ceil(GROUP) * GROUP) as u32;
        let steps = padded(chart.steps.len());
        let actions_list = chart.associated_actions();
        let actions = padded(actions_list.len());
        let mut at = start + 16;
        layout.step_x = (at, steps);
        layout.step_next = (at + steps, steps);
        layout.action_busy = (at + 2 * steps, actions);
        layout.action_q = (at + 2 * steps + actions, actions);
        at += 2 * steps + 2 * actions;
        for (index, step) in chart.steps.iter().enumerate() {
            layout
                .step_index
                .entry(step.name.to_ascii_lowercase())
                .or_insert(index);
            layout.steps.push(StepSlots {
                name: step.name.clone(),
                initial: step.initial,
                x: layout.step_x.0 + index as u32,
                next: layout.step_next.0 + index as u32,
                at,
            });
            at += step_at::SIZE;
        }
        for (index, name) in actions_list.into_iter().enumerate() {
            let written = chart
                .steps
                .iter()
                .flat_map(|s| &s.associations)
                .find(|a| a.action.eq_ignore_ascii_case(&name))
                .map_or(name.clone(), |a| a.action.clone());
            layout.actions.push((
                name,
                ActionSlots {
                    name: written,
                    busy: layout.action_busy.0 + index as u32,
                    q: layout.action_q.0 + index as u32,
                    at,
                },
            ));
            at += action_at::SIZE;
        }
        for transition in &chart.transitions {
            if transition.node.condition().is_none()
                && let Some(name) = transition.node.name()
            {
                layout
                    .transition_values
                    .push((name.text().to_ascii_lowercase(), at));
                at += 1;
            }
        }
        Some((layout, at))
    }

    /// The BOOL holding the value of the transition `name` written with statements.
    pub(crate) fn transition_value(&self, name: &str) -> Option<u32> {
        self.transition_values
            .iter()
            .find(|(known, _)| known.eq_ignore_ascii_case(name))
            .map(|(_, at)| *at)
    }

    /// The step called `name`.
    pub(crate) fn step(&self, name: &str) -> Option<&StepSlots> {
        self.step_index
            .get(&name.to_ascii_lowercase())
            .and_then(|index| self.steps.get(*index))
    }

    /// The associated action called `name`.
    pub(crate) fn action(&self, name: &str) -> Option<&ActionSlots> {
        let name = name.to_ascii_lowercase();
        self.actions
            .binary_search_by(|(known, _)| known.as_str().cmp(&name))
            .ok()
            .map(|index| &self.actions[index].1)
    }
}
