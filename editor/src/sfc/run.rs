//! Running the editor's commands on the selection: each structural command is one edit of
//! `project_model::sfc_edit`, and the new elements it made are selected.

use egui::Id;
use project_model::sfc_edit::{
    self, SfcEditError, copy_nodes, delete_nodes, find_node, max_sfc_id, paste_after,
};
use project_model::{ElementId, SfcChart, SfcNode};

use super::commands::SfcCommand;
use super::editor::{FrameResult, SfcEditor};
use super::entry::{Entry, EntryTarget};
use super::types::SfcOnlineCommand;

impl SfcEditor {
    /// Runs `command` on the selection.
    pub(super) fn command(
        &mut self,
        ctx: &egui::Context,
        command: SfcCommand,
        frame: &mut FrameResult,
    ) {
        let online_command = matches!(
            command,
            SfcCommand::ToggleStepActive
                | SfcCommand::FireTransition
                | SfcCommand::Copy
                | SfcCommand::OpenMacro
                | SfcCommand::LeaveMacro
        );
        if self.read_only && !online_command {
            return;
        }
        let selection = self.selection.clone();
        let first = selection.first().copied();
        let last = selection.last().copied();
        let before = max_sfc_id(&self.chart);
        let needs_selection = || first.ok_or(SfcEditError::EmptySelection);
        match command {
            SfcCommand::InsertStepTransitionAfter => {
                let result = needs_selection()
                    .and_then(|_| self.last_in_order(&selection))
                    .and_then(|id| sfc_edit::insert_step_transition_after(&self.chart, id));
                self.apply_and_select_new(result, before, frame);
            }
            SfcCommand::InsertStepTransitionBefore => {
                let result = needs_selection()
                    .and_then(|_| self.first_in_order(&selection))
                    .and_then(|id| sfc_edit::insert_step_transition_before(&self.chart, id));
                self.apply_and_select_new(result, before, frame);
            }
            SfcCommand::InsertMacroStep => {
                let result = needs_selection()
                    .and_then(|_| self.last_in_order(&selection))
                    .and_then(|id| sfc_edit::insert_macro_step_after(&self.chart, id));
                self.apply_and_select_new(result, before, frame);
            }
            SfcCommand::InsertAlternativeBranch => {
                let result = sfc_edit::insert_alternative_branch(&self.chart, &selection);
                self.apply_and_select_new(result, before, frame);
            }
            SfcCommand::InsertParallelBranch => {
                let result = sfc_edit::insert_parallel_branch(&self.chart, &selection);
                self.apply_and_select_new(result, before, frame);
            }
            SfcCommand::AddBranch => {
                let result = needs_selection()
                    .and_then(|id| self.enclosing_branch(id))
                    .and_then(|id| sfc_edit::add_branch(&self.chart, id));
                self.apply_and_select_new(result, before, frame);
            }
            SfcCommand::WrapInMacro => {
                let result = sfc_edit::wrap_in_macro(&self.chart, &selection);
                self.apply_and_select_new(result, before, frame);
            }
            SfcCommand::InsertJump => {
                let target = self.initial_step_name();
                let result = needs_selection()
                    .and_then(|_| last.ok_or(SfcEditError::EmptySelection))
                    .and_then(|id| sfc_edit::insert_jump_after(&self.chart, id, &target));
                if self.apply_and_select_new(result, before, frame) {
                    self.open_entry(None);
                }
            }
            SfcCommand::AddActionAssociation => match first {
                Some(id) if matches!(find_node(&self.chart, id), Some(SfcNode::Step(_))) => {
                    self.entry = Some(Entry::new(EntryTarget::NewAssociation(id), String::new()));
                }
                Some(id) => frame.refusal = Some(SfcEditError::NotAStep(id)),
                None => frame.refusal = Some(SfcEditError::EmptySelection),
            },
            SfcCommand::Delete => {
                let result = delete_nodes(&self.chart, &selection);
                if self.apply(result, frame) {
                    self.selection.clear();
                }
            }
            SfcCommand::Copy => match copy_nodes(&self.chart, &selection) {
                Ok(nodes) => {
                    ctx.data_mut(|data| data.insert_temp(clipboard_id(), nodes));
                }
                Err(error) => frame.refusal = Some(error),
            },
            SfcCommand::Paste => {
                let nodes: Vec<SfcNode> = ctx
                    .data(|data| data.get_temp(clipboard_id()))
                    .unwrap_or_default();
                let result = needs_selection()
                    .and_then(|_| self.last_in_order(&selection))
                    .and_then(|id| paste_after(&self.chart, id, &nodes));
                self.apply_and_select_new(result, before, frame);
            }
            SfcCommand::EditText => self.open_entry(None),
            SfcCommand::OpenMacro => {
                if let Some(id) = first
                    && matches!(find_node(&self.chart, id), Some(SfcNode::Macro(_)))
                {
                    self.macro_path.push(id);
                    self.after_level_change();
                }
            }
            SfcCommand::LeaveMacro => {
                if let Some(id) = self.macro_path.pop() {
                    self.after_level_change();
                    self.selection = vec![id];
                }
            }
            SfcCommand::ToggleStepActive => {
                if let Some(id) = first
                    && let Some(SfcNode::Step(step)) = find_node(&self.chart, id)
                    && let Some(online) = &self.online
                {
                    let active = online.steps.get(&id).is_some_and(|state| state.active);
                    frame.online = Some(SfcOnlineCommand::SetStepActive {
                        step: step.name.clone(),
                        active: !active,
                    });
                }
            }
            SfcCommand::FireTransition => {
                if let Some(id) = first
                    && matches!(find_node(&self.chart, id), Some(SfcNode::Transition(_)))
                    && self.online.as_ref().is_some_and(|online| online.tip_mode)
                {
                    frame.online = Some(SfcOnlineCommand::FireTransition { transition: id });
                }
            }
        }
    }

    /// Applies `result` and selects the first new step (else the first new node) it made.
    fn apply_and_select_new(
        &mut self,
        result: Result<SfcChart, SfcEditError>,
        before: u32,
        frame: &mut FrameResult,
    ) -> bool {
        if !self.apply(result, frame) {
            return false;
        }
        let new: Vec<(ElementId, bool)> = self
            .layout
            .elements
            .iter()
            .filter(|placed| placed.id.0 > before)
            .map(|placed| {
                (
                    placed.id,
                    matches!(placed.shape, super::layout::SfcShape::Step { .. }),
                )
            })
            .collect();
        let chosen = new
            .iter()
            .find(|(_, step)| *step)
            .or(new.first())
            .map(|(id, _)| *id);
        if let Some(id) = chosen {
            self.selection = vec![id];
        }
        true
    }

    /// Of `selection`, the node that comes first in its sequence (the selection is a run).
    fn first_in_order(&self, selection: &[ElementId]) -> Result<ElementId, SfcEditError> {
        self.in_order(selection)
            .first()
            .copied()
            .ok_or(SfcEditError::EmptySelection)
    }

    /// Of `selection`, the node that comes last in its sequence.
    fn last_in_order(&self, selection: &[ElementId]) -> Result<ElementId, SfcEditError> {
        self.in_order(selection)
            .last()
            .copied()
            .ok_or(SfcEditError::EmptySelection)
    }

    /// `selection` in the layout's order (which is the sequences' order).
    fn in_order(&self, selection: &[ElementId]) -> Vec<ElementId> {
        self.layout
            .elements
            .iter()
            .map(|placed| placed.id)
            .filter(|id| selection.contains(id))
            .collect()
    }

    /// The branch `id` is, or the innermost branch holding it.
    fn enclosing_branch(&self, id: ElementId) -> Result<ElementId, SfcEditError> {
        if matches!(
            find_node(&self.chart, id),
            Some(SfcNode::Alternative(_) | SfcNode::Parallel(_))
        ) {
            return Ok(id);
        }
        innermost_branch(&self.chart.sequence, id, None)
            .flatten()
            .ok_or(SfcEditError::NotABranch(id))
    }

    /// The name of the chart's initial step, the target a new jump starts with.
    fn initial_step_name(&self) -> String {
        match self.chart.sequence.first() {
            Some(SfcNode::Step(step)) => step.name.clone(),
            _ => String::new(),
        }
    }
}

/// Where the shared SFC clipboard is kept in the egui context (so a copy in one chart pastes
/// into another); it lives until the application ends.
fn clipboard_id() -> Id {
    Id::unique("editor::sfc::clipboard")
}

/// The innermost alternative or parallel branch holding node `id` (`Some(None)` when it is in
/// `nodes` outside any branch; `None` when it is not in `nodes`).
fn innermost_branch(
    nodes: &[SfcNode],
    id: ElementId,
    around: Option<ElementId>,
) -> Option<Option<ElementId>> {
    for node in nodes {
        if node.id() == id {
            return Some(around);
        }
        let found = match node {
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => branches
                .branches
                .iter()
                .find_map(|branch| innermost_branch(&branch.nodes, id, Some(branches.id))),
            SfcNode::Macro(macro_step) => innermost_branch(&macro_step.body, id, None),
            SfcNode::Step(_) | SfcNode::Transition(_) | SfcNode::Jump(_) => None,
        };
        if found.is_some() {
            return found;
        }
    }
    None
}
