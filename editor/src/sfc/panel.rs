//! The properties panel of the selected step (minimum and maximum time, entry, step and exit
//! actions, comment, action associations) or transition (condition, priority).

use egui::{ComboBox, DragValue, Grid, Response, TextEdit, Ui};
use project_model::sfc_edit::{
    StepProperties, find_node, move_association, remove_association, set_association,
    set_step_properties, set_transition_condition, set_transition_priority,
};
use project_model::{ActionAssociation, ActionQualifier, ElementId, SfcNode};

use super::editor::{FrameResult, SfcEditor};

/// One association's row as it is being typed.
#[derive(Clone, Debug, PartialEq, Eq)]
struct AssociationRow {
    qualifier: ActionQualifier,
    action: String,
    time: String,
    indicator: String,
}

/// The panel's texts as they are being typed, for one element; rebuilt from the chart when the
/// selection or the chart changes.
#[derive(Clone, Debug)]
pub(super) struct PanelState {
    element: ElementId,
    /// Minimum time, maximum time, entry, step and exit action, comment.
    fields: [String; 6],
    associations: Vec<AssociationRow>,
    condition: String,
    priority: Option<u32>,
}

impl PanelState {
    fn of(node: &SfcNode) -> Self {
        let mut state = Self {
            element: node.id(),
            fields: Default::default(),
            associations: Vec::new(),
            condition: String::new(),
            priority: None,
        };
        match node {
            SfcNode::Step(step) => {
                let text = |value: &Option<String>| value.clone().unwrap_or_default();
                state.fields = [
                    text(&step.min_time),
                    text(&step.max_time),
                    text(&step.entry_action),
                    text(&step.main_action),
                    text(&step.exit_action),
                    step.comment.clone(),
                ];
                state.associations = step
                    .actions
                    .iter()
                    .map(|association| AssociationRow {
                        qualifier: association.qualifier,
                        action: association.action.clone(),
                        time: association.duration.clone().unwrap_or_default(),
                        indicator: association.indicator.clone().unwrap_or_default(),
                    })
                    .collect();
            }
            SfcNode::Transition(transition) => {
                state.condition = transition.condition.clone();
                state.priority = transition.priority;
            }
            _ => {}
        }
        state
    }

    fn properties(&self) -> StepProperties {
        let some = |text: &String| Some(text.clone());
        StepProperties {
            min_time: some(&self.fields[0]),
            max_time: some(&self.fields[1]),
            entry_action: some(&self.fields[2]),
            main_action: some(&self.fields[3]),
            exit_action: some(&self.fields[4]),
            comment: self.fields[5].clone(),
        }
    }
}

/// Whether a text field's edit is finished: Enter, or the focus moved away.
fn finished(response: &Response) -> bool {
    response.lost_focus()
}

impl AssociationRow {
    fn association(&self) -> ActionAssociation {
        let optional = |text: &str| (!text.trim().is_empty()).then(|| text.trim().to_owned());
        ActionAssociation {
            action: self.action.clone(),
            qualifier: self.qualifier,
            duration: optional(&self.time),
            indicator: optional(&self.indicator),
        }
    }
}

impl SfcEditor {
    /// The element the panel shows: the single selected step or transition.
    pub(super) fn panel_target(&self) -> Option<&SfcNode> {
        let [id] = self.selection[..] else {
            return None;
        };
        find_node(&self.chart, id)
            .filter(|node| matches!(node, SfcNode::Step(_) | SfcNode::Transition(_)))
    }

    pub(super) fn panel_ui(&mut self, ui: &mut Ui, frame: &mut FrameResult) {
        let Some((id, is_step, fresh)) = self.panel_target().map(|node| {
            (
                node.id(),
                matches!(node, SfcNode::Step(_)),
                PanelState::of(node),
            )
        }) else {
            return;
        };
        let mut state = match self.panel.take() {
            Some(state) if state.element == id => state,
            _ => fresh,
        };
        let mut result = None;
        ui.add_enabled_ui(!self.read_only, |ui| {
            if is_step {
                result = self.step_panel_ui(ui, id, &mut state);
            } else {
                result = self.transition_panel_ui(ui, id, &mut state);
            }
        });
        self.panel = Some(state);
        if let Some(result) = result {
            self.apply(result, frame);
        }
    }

    fn step_panel_ui(
        &self,
        ui: &mut Ui,
        id: ElementId,
        state: &mut PanelState,
    ) -> Option<Result<project_model::SfcChart, project_model::sfc_edit::SfcEditError>> {
        let texts = &self.texts;
        let mut result = None;
        ui.strong(&texts.step_properties);
        let labels = [
            &texts.min_time,
            &texts.max_time,
            &texts.entry_action,
            &texts.main_action,
            &texts.exit_action,
            &texts.comment,
        ];
        Grid::new(("sfc_step_panel", id.0))
            .num_columns(2)
            .show(ui, |ui| {
                for (label, field) in labels.into_iter().zip(state.fields.iter_mut()) {
                    let label = ui.label(label.as_str());
                    let response = ui
                        .add(TextEdit::singleline(field).desired_width(140.0))
                        .labelled_by(label.id);
                    if finished(&response) {
                        result = Some(());
                    }
                    ui.end_row();
                }
            });
        let mut outcome = result.map(|()| set_step_properties(&self.chart, id, state.properties()));
        ui.separator();
        ui.strong(&texts.action_association);
        let count = state.associations.len();
        for index in 0..count {
            let row = &mut state.associations[index];
            let mut commit = false;
            ui.horizontal(|ui| {
                ComboBox::from_id_salt(("sfc_qualifier", id.0, index))
                    .selected_text(row.qualifier.as_str())
                    .width(44.0)
                    .show_ui(ui, |ui| {
                        for qualifier in ActionQualifier::ALL {
                            if ui
                                .selectable_value(&mut row.qualifier, qualifier, qualifier.as_str())
                                .clicked()
                            {
                                commit = true;
                            }
                        }
                    })
                    .response
                    .on_hover_text(&texts.qualifier);
                for (field, label, width) in [
                    (&mut row.action, &texts.action, 80.0),
                    (&mut row.time, &texts.time, 50.0),
                ] {
                    let response = ui.add(
                        TextEdit::singleline(field)
                            .desired_width(width)
                            .hint_text(label.as_str()),
                    );
                    commit |= finished(&response);
                }
            });
            ui.horizontal(|ui| {
                let response = ui.add(
                    TextEdit::singleline(&mut row.indicator)
                        .desired_width(80.0)
                        .hint_text(texts.indicator.as_str()),
                );
                commit |= finished(&response);
                if index > 0 && ui.small_button(texts.move_up.as_str()).clicked() {
                    outcome = Some(move_association(&self.chart, id, index, index - 1));
                }
                if ui.small_button(texts.remove.as_str()).clicked() {
                    outcome = Some(remove_association(&self.chart, id, index));
                }
            });
            if commit && outcome.is_none() {
                outcome = Some(set_association(&self.chart, id, index, row.association()));
            }
        }
        outcome
    }

    fn transition_panel_ui(
        &self,
        ui: &mut Ui,
        id: ElementId,
        state: &mut PanelState,
    ) -> Option<Result<project_model::SfcChart, project_model::sfc_edit::SfcEditError>> {
        let texts = &self.texts;
        let mut outcome = None;
        Grid::new(("sfc_transition_panel", id.0))
            .num_columns(2)
            .show(ui, |ui| {
                let label = ui.label(texts.condition_field.as_str());
                let response = ui
                    .add(TextEdit::singleline(&mut state.condition).desired_width(140.0))
                    .labelled_by(label.id);
                if finished(&response) {
                    outcome = Some(set_transition_condition(&self.chart, id, &state.condition));
                }
                ui.end_row();
                ui.label("");
                ui.horizontal(|ui| {
                    let mut has_priority = state.priority.is_some();
                    let toggled = ui
                        .checkbox(&mut has_priority, texts.priority.as_str())
                        .changed();
                    let mut value = state.priority.unwrap_or(1);
                    let changed = ui
                        .add_enabled(has_priority, DragValue::new(&mut value).range(0..=u32::MAX))
                        .changed();
                    if toggled || changed {
                        state.priority = has_priority.then_some(value);
                        outcome = Some(set_transition_priority(&self.chart, id, state.priority));
                    }
                });
                ui.end_row();
            });
        outcome
    }
}
