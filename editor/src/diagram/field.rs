//! The single-line text field with a completion list under it, shared by the LD/FBD and the
//! CFC editors for operands, box types and instances.

use egui::text::{CCursor, CCursorRange};
use egui::{Id, Key, Rect, TextEdit};

use crate::CompletionItem;

/// How many completion candidates the list under the field shows.
pub(crate) const MAX_CANDIDATES: usize = 8;

/// The state of an open field: the text typed and the completion the arrows moved to.
#[derive(Clone, Debug)]
pub(crate) struct CompletionField {
    /// The text typed so far.
    pub text: String,
    /// Whether the field has been given focus (done once, in its first frame).
    pub focused: bool,
    /// The completion the arrow keys moved to, counted from the best one; reset when the text
    /// changes.
    pub highlighted: usize,
    /// The text `highlighted` was chosen for.
    highlighted_for: String,
}

/// What became of a field in a frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum FieldOutcome {
    /// It is still open.
    Open,
    /// Escape closed it; nothing changes.
    Cancelled,
    /// Enter, Tab or a click on a candidate gave this text.
    Committed(String),
    /// A click elsewhere left it with this text (kept, as CODESYS does).
    Left(String),
}

impl CompletionField {
    /// A field holding `text`.
    pub fn new(text: String) -> Self {
        Self {
            highlighted_for: text.clone(),
            text,
            focused: false,
            highlighted: 0,
        }
    }

    /// The candidate Enter or Tab takes: none for an empty field or without candidates, the one
    /// spelled as typed (any case) while nothing was chosen with the arrows, else the one the
    /// arrows moved to.
    fn highlighted_candidate(&self, candidates: &[CompletionItem]) -> Option<usize> {
        if self.text.trim().is_empty() || candidates.is_empty() {
            return None;
        }
        let typed = last_segment(self.text.trim());
        let exact = candidates
            .iter()
            .position(|candidate| candidate.label.eq_ignore_ascii_case(typed));
        let shown = candidates.len().min(MAX_CANDIDATES);
        Some((exact.unwrap_or(0) + self.highlighted) % shown)
    }

    /// Shows the field at `anchor` (screen points) in a popup with the `candidates` under it;
    /// `label` is its hint and accessible name.
    pub fn ui(
        &mut self,
        ctx: &egui::Context,
        field_id: Id,
        anchor: Rect,
        label: &str,
        candidates: &[CompletionItem],
    ) -> FieldOutcome {
        if self.text != self.highlighted_for {
            self.highlighted_for = self.text.clone();
            self.highlighted = 0;
        }
        let shown = candidates.len().min(MAX_CANDIDATES);
        // The arrows move through the candidates, as in the ST editor; they are taken before
        // the field sees them, which would move its cursor instead.
        if shown > 0 && self.focused {
            let (down, up) = ctx.input_mut(|input| {
                (
                    input.consume_key(egui::Modifiers::NONE, Key::ArrowDown),
                    input.consume_key(egui::Modifiers::NONE, Key::ArrowUp),
                )
            });
            if down {
                self.highlighted = (self.highlighted + 1) % shown;
            }
            if up {
                self.highlighted = (self.highlighted + shown - 1) % shown;
            }
        }
        let highlighted = self.highlighted_candidate(candidates);
        let mut commit = None;
        let mut cancel = false;
        let mut left = false;
        let area = egui::Area::new(field_id.with("area"))
            .order(egui::Order::Foreground)
            .fixed_pos(anchor.left_top())
            .show(ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    let width = anchor.width().max(140.0);
                    let response = ui.add(
                        TextEdit::singleline(&mut self.text)
                            .id(field_id)
                            .desired_width(width)
                            .hint_text(label),
                    );
                    response
                        .widget_info(|| egui::WidgetInfo::text_edit(true, "", &self.text, label));
                    if !self.focused {
                        self.focused = true;
                        response.request_focus();
                        let mut state = TextEdit::load_state(ctx, field_id).unwrap_or_default();
                        let end = CCursor::new(self.text.chars().count());
                        state.cursor.set_char_range(Some(CCursorRange::one(end)));
                        state.store(ctx, field_id);
                    }
                    if ui.input(|input| input.key_pressed(Key::Escape)) {
                        cancel = true;
                    } else if response.lost_focus() {
                        // Enter and Tab take the highlighted completion, as CODESYS and the ST
                        // editor do; what was typed stays when nothing is highlighted.
                        if ui.input(|input| {
                            input.key_pressed(Key::Enter) || input.key_pressed(Key::Tab)
                        }) {
                            commit = Some(match highlighted {
                                Some(index) => accepted_text(&self.text, &candidates[index].label),
                                None => self.text.clone(),
                            });
                        } else {
                            left = true;
                        }
                    }
                    if let Some(index) = candidate_list_ui(ui, candidates, highlighted) {
                        commit = Some(accepted_text(&self.text, &candidates[index].label));
                    }
                });
            });
        if cancel {
            return FieldOutcome::Cancelled;
        }
        // A click elsewhere keeps what was typed, as CODESYS does; a click on a candidate in
        // the popup takes the candidate instead.
        if left && commit.is_none() && !area.response.contains_pointer() {
            return FieldOutcome::Left(self.text.clone());
        }
        commit.map_or(FieldOutcome::Open, FieldOutcome::Committed)
    }
}

/// What follows the last dot of `text` (all of it without a dot): the part a member's
/// completion replaces.
fn last_segment(text: &str) -> &str {
    text.rsplit_once('.').map_or(text, |(_, member)| member)
}

/// The field's text once `label` is accepted for what was typed: a member (`Q` after `tonA.`)
/// replaces only what follows the last dot, anything else the whole text.
pub(crate) fn accepted_text(typed: &str, label: &str) -> String {
    match typed.trim().rsplit_once('.') {
        Some((path, _)) if !label.contains('.') => format!("{path}.{label}"),
        _ => label.to_owned(),
    }
}

/// The detail of a completion row without the candidate's own name, which the row already
/// shows (`tWarn : TIME` gives `TIME`, `FUNCTION LIMIT` gives `FUNCTION`).
pub(crate) fn detail_without_label(label: &str, detail: &str) -> String {
    let words: Vec<&str> = detail
        .split_whitespace()
        .filter(|word| !word.eq_ignore_ascii_case(label))
        .collect();
    let words = match words.as_slice() {
        [":", rest @ ..] => rest,
        all => all,
    };
    words.join(" ")
}

/// Lists the first [`MAX_CANDIDATES`] of `candidates` under a field, each with its detail and
/// the `highlighted` one marked; returns the index of the one clicked.
pub(crate) fn candidate_list_ui(
    ui: &mut egui::Ui,
    candidates: &[CompletionItem],
    highlighted: Option<usize>,
) -> Option<usize> {
    let mut clicked = None;
    for (index, candidate) in candidates.iter().take(MAX_CANDIDATES).enumerate() {
        let detail = detail_without_label(&candidate.label, &candidate.detail);
        let text = if detail.is_empty() {
            candidate.label.clone()
        } else {
            format!("{}  {detail}", candidate.label)
        };
        if ui
            .selectable_label(highlighted == Some(index), text)
            .clicked()
        {
            clicked = Some(index);
        }
    }
    clicked
}
