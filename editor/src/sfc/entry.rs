//! The text field over a node: a step's name, a transition's condition (with completion of
//! variables and transition objects through `DiagramServices`), a jump's target (completing
//! step names), an action association.

use egui::text::{CCursor, CCursorRange};
use egui::{Id, Key, Rect, TextEdit, pos2, vec2};
use project_model::sfc_edit::{
    add_association, find_node, rename_step, set_association, set_jump_target,
    set_transition_condition, step_names,
};
use project_model::{ActionAssociation, ActionQualifier, ElementId, SfcNode};

use super::editor::{FrameResult, SfcEditor};
use super::layout::{ACTION_ROW_PX, STEP_HEIGHT_PX, TEXT_GAP_PX};
use crate::diagram::field::{MAX_CANDIDATES, accepted_text, candidate_list_ui};
use crate::{CompletionItem, CompletionKind, DiagramServices};

/// The least width of the field, in points.
const MIN_FIELD_WIDTH_PX: f32 = 160.0;

/// What a text field edits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum EntryTarget {
    /// A step's or macro step's name.
    StepName(ElementId),
    /// A transition's condition.
    Condition(ElementId),
    /// A jump's target.
    JumpTarget(ElementId),
    /// The action of a step's association `index`.
    AssociationAction(ElementId, usize),
    /// A new association of a step, typed as `[qualifier] action [time]`.
    NewAssociation(ElementId),
}

/// An open text field; lives until it is committed or cancelled.
#[derive(Clone, Debug)]
pub(super) struct Entry {
    /// What it edits.
    pub target: EntryTarget,
    /// The text typed so far.
    pub text: String,
    /// Whether the field has been given focus (done once, in its first frame).
    focused: bool,
    /// The candidate the arrows moved to, if any.
    highlighted: Option<usize>,
}

impl Entry {
    /// A field editing `target`, starting with `text`.
    pub fn new(target: EntryTarget, text: String) -> Self {
        Self {
            target,
            text,
            focused: false,
            highlighted: None,
        }
    }
}

/// Where the identifier being typed at the end of `text` begins: completion replaces only it.
fn word_start(text: &str) -> usize {
    text.char_indices()
        .rev()
        .take_while(|(_, c)| c.is_alphanumeric() || *c == '_' || *c == '.')
        .last()
        .map_or(text.len(), |(index, _)| index)
}

/// A typed association, `[qualifier] action [time]` (`L Fill T#5s`, or `Fill` for N).
fn parse_association(text: &str) -> ActionAssociation {
    let words: Vec<&str> = text.split_whitespace().collect();
    let qualifier = words.first().and_then(|word| {
        ActionQualifier::ALL
            .into_iter()
            .find(|qualifier| qualifier.as_str().eq_ignore_ascii_case(word))
    });
    let rest = match (qualifier, words.len()) {
        (Some(_), 2..) => &words[1..],
        _ => &words[..],
    };
    ActionAssociation {
        action: rest.first().copied().unwrap_or_default().to_owned(),
        qualifier: if rest.len() < words.len() {
            qualifier.unwrap_or_default()
        } else {
            ActionQualifier::N
        },
        duration: rest.get(1).map(|time| (*time).to_owned()),
        indicator: rest.get(2).map(|indicator| (*indicator).to_owned()),
    }
}

impl SfcEditor {
    /// Opens the text field of the single selected node, with `typed` replacing its text when
    /// the user started typing on the canvas.
    pub(super) fn open_entry(&mut self, typed: Option<&str>) {
        if self.read_only {
            return;
        }
        let [id] = self.selection[..] else {
            return;
        };
        let (target, text) = match find_node(&self.chart, id) {
            Some(SfcNode::Step(step)) => (EntryTarget::StepName(id), step.name.clone()),
            Some(SfcNode::Macro(macro_step)) => {
                (EntryTarget::StepName(id), macro_step.name.clone())
            }
            Some(SfcNode::Transition(transition)) => {
                (EntryTarget::Condition(id), transition.condition.clone())
            }
            Some(SfcNode::Jump(jump)) => (EntryTarget::JumpTarget(id), jump.target.clone()),
            _ => return,
        };
        let text = typed.map_or(text, str::to_owned);
        self.entry = Some(Entry::new(target, text));
    }

    /// Opens the field over the action of association `index` of step `id`.
    pub(super) fn open_association_entry(&mut self, id: ElementId, index: usize) {
        if self.read_only {
            return;
        }
        if let Some(SfcNode::Step(step)) = find_node(&self.chart, id)
            && let Some(association) = step.actions.get(index)
        {
            self.entry = Some(Entry::new(
                EntryTarget::AssociationAction(id, index),
                association.action.clone(),
            ));
        }
    }

    /// Where the open field goes, in content points at zoom 1.
    pub(super) fn entry_rect(&self) -> Option<Rect> {
        let entry = self.entry.as_ref()?;
        let beside = |id: ElementId| {
            let placed = self.layout.element(id)?;
            Some(Rect::from_min_size(
                pos2(placed.text_pos.x, placed.text_pos.y - 11.0),
                vec2(MIN_FIELD_WIDTH_PX, 22.0),
            ))
        };
        match entry.target {
            EntryTarget::StepName(id) => self.layout.element(id).map(|placed| placed.rect),
            EntryTarget::Condition(id) | EntryTarget::JumpTarget(id) => beside(id),
            EntryTarget::AssociationAction(id, index) => {
                let actions = self.layout.element(id)?.actions?;
                Some(Rect::from_min_size(
                    pos2(
                        actions.action_x,
                        actions.rect.top() + index as f32 * ACTION_ROW_PX,
                    ),
                    vec2(MIN_FIELD_WIDTH_PX, ACTION_ROW_PX),
                ))
            }
            EntryTarget::NewAssociation(id) => {
                let placed = self.layout.element(id)?;
                let top = placed.actions.map_or(placed.rect.top(), |actions| {
                    actions.rect.top() + actions.rect.height().max(STEP_HEIGHT_PX)
                });
                Some(Rect::from_min_size(
                    pos2(placed.rect.right() + TEXT_GAP_PX, top),
                    vec2(MIN_FIELD_WIDTH_PX, 22.0),
                ))
            }
        }
    }

    /// The completions for what is typed in the field.
    fn candidates(&self, entry: &Entry, services: &dyn DiagramServices) -> Vec<CompletionItem> {
        let word = &entry.text[word_start(&entry.text)..];
        let named = |names: &[String], kind: CompletionKind| -> Vec<CompletionItem> {
            names
                .iter()
                .filter(|name| {
                    name.to_lowercase().starts_with(&word.to_lowercase()) && !word.is_empty()
                })
                .map(|name| CompletionItem {
                    label: name.clone(),
                    kind,
                    detail: String::new(),
                })
                .collect()
        };
        match entry.target {
            EntryTarget::StepName(_) => Vec::new(),
            EntryTarget::JumpTarget(_) => named(&step_names(&self.chart), CompletionKind::Variable),
            EntryTarget::Condition(_) => {
                let mut items = named(&self.transition_objects, CompletionKind::Function);
                if !word.is_empty() {
                    items.extend(services.variables(word));
                }
                items
            }
            EntryTarget::AssociationAction(..) | EntryTarget::NewAssociation(_) => {
                let mut items = named(&self.action_names, CompletionKind::Function);
                if !word.is_empty() {
                    items.extend(services.variables(word));
                }
                items
            }
        }
    }

    /// Shows the open field over `anchor` (on screen) with its completions.
    pub(super) fn entry_ui(
        &mut self,
        ctx: &egui::Context,
        id: Id,
        anchor: Rect,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        let Some(mut entry) = self.entry.take() else {
            return;
        };
        let field_id = id.with("entry");
        let candidates = self.candidates(&entry, services);
        let shown = candidates.len().min(MAX_CANDIDATES);
        if shown > 0 && entry.focused {
            let (down, up) = ctx.input_mut(|input| {
                (
                    input.consume_key(egui::Modifiers::NONE, Key::ArrowDown),
                    input.consume_key(egui::Modifiers::NONE, Key::ArrowUp),
                )
            });
            if down {
                entry.highlighted = Some(entry.highlighted.map_or(0, |h| (h + 1) % shown));
            }
            if up {
                entry.highlighted = Some(
                    entry
                        .highlighted
                        .map_or(shown - 1, |h| (h + shown - 1) % shown),
                );
            }
        }
        let highlighted = entry.highlighted.filter(|index| *index < shown);
        let label = self.entry_label(&entry.target);
        let mut commit = None;
        let mut cancel = false;
        let mut left = false;
        let accept = |typed: &str, candidate: &str| {
            let start = word_start(typed);
            format!(
                "{}{}",
                &typed[..start],
                accepted_text(&typed[start..], candidate)
            )
        };
        let area = egui::Area::new(field_id.with("area"))
            .order(egui::Order::Foreground)
            .fixed_pos(anchor.left_top())
            .show(ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    let response = ui.add(
                        TextEdit::singleline(&mut entry.text)
                            .id(field_id)
                            .desired_width(anchor.width().max(MIN_FIELD_WIDTH_PX))
                            .hint_text(label.clone()),
                    );
                    response
                        .widget_info(|| egui::WidgetInfo::text_edit(true, "", &entry.text, &label));
                    if !entry.focused {
                        entry.focused = true;
                        response.request_focus();
                        let mut state = TextEdit::load_state(ctx, field_id).unwrap_or_default();
                        let end = CCursor::new(entry.text.chars().count());
                        state.cursor.set_char_range(Some(CCursorRange::one(end)));
                        state.store(ctx, field_id);
                    }
                    if ui.input(|input| input.key_pressed(Key::Escape)) {
                        cancel = true;
                    } else if response.lost_focus() {
                        // Tab takes the first (or highlighted) completion; Enter takes the
                        // highlighted one, else what was typed.
                        let (enter, tab) = ui.input(|input| {
                            (input.key_pressed(Key::Enter), input.key_pressed(Key::Tab))
                        });
                        if enter || tab {
                            let chosen = if tab {
                                highlighted.or((shown > 0).then_some(0))
                            } else {
                                highlighted
                            };
                            commit = Some(match chosen {
                                Some(index) => accept(&entry.text, &candidates[index].label),
                                None => entry.text.clone(),
                            });
                        } else {
                            left = true;
                        }
                    }
                    if let Some(index) = candidate_list_ui(ui, &candidates, highlighted) {
                        commit = Some(accept(&entry.text, &candidates[index].label));
                    }
                });
            });
        if cancel {
            self.focus_requested = true;
            return;
        }
        let by_leaving = left && commit.is_none() && !area.response.contains_pointer();
        if by_leaving {
            commit = Some(entry.text.clone());
        }
        match commit {
            Some(text) => {
                if !by_leaving {
                    self.focus_requested = true;
                }
                self.commit_entry(&entry.target, text.trim(), frame);
            }
            None => self.entry = Some(entry),
        }
    }

    /// The field's accessible name.
    fn entry_label(&self, target: &EntryTarget) -> String {
        let texts = &self.texts;
        match target {
            EntryTarget::StepName(_) => texts.step_name_field.clone(),
            EntryTarget::Condition(_) => texts.condition_field.clone(),
            EntryTarget::JumpTarget(_) => texts.jump_target_field.clone(),
            EntryTarget::AssociationAction(..) => texts.action.clone(),
            EntryTarget::NewAssociation(_) => texts.action_association.clone(),
        }
    }

    /// Applies what was typed.
    fn commit_entry(&mut self, target: &EntryTarget, text: &str, frame: &mut FrameResult) {
        let chart = &self.chart;
        let result = match *target {
            EntryTarget::StepName(id) => rename_step(chart, id, text),
            EntryTarget::Condition(id) => set_transition_condition(chart, id, text),
            EntryTarget::JumpTarget(id) => set_jump_target(chart, id, text),
            EntryTarget::AssociationAction(id, index) => match find_node(chart, id) {
                Some(SfcNode::Step(step)) => match step.actions.get(index) {
                    Some(association) => set_association(
                        chart,
                        id,
                        index,
                        ActionAssociation {
                            action: text.to_owned(),
                            ..association.clone()
                        },
                    ),
                    None => return,
                },
                _ => return,
            },
            EntryTarget::NewAssociation(id) => add_association(chart, id, parse_association(text)),
        };
        let unchanged = result.as_ref().is_ok_and(|new| new == chart);
        if !unchanged {
            self.apply(result, frame);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_typed_association_reads_its_qualifier_action_and_time() {
        let association = parse_association("L Fill T#5s");
        assert_eq!(association.qualifier, ActionQualifier::L);
        assert_eq!(association.action, "Fill");
        assert_eq!(association.duration.as_deref(), Some("T#5s"));
        let association = parse_association("Fill");
        assert_eq!(association.qualifier, ActionQualifier::N);
        assert_eq!(association.action, "Fill");
        assert_eq!(association.duration, None);
        // A lone word that spells a qualifier is the action's name.
        assert_eq!(parse_association("S").action, "S");
    }

    #[test]
    fn completion_replaces_only_the_word_being_typed() {
        assert_eq!(word_start("start AND st"), 10);
        assert_eq!(word_start("a.b"), 0);
        assert_eq!(word_start("x AND "), 6);
    }
}
