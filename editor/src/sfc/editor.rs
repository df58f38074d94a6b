//! `SfcEditor`: the state of one SFC body's editor and its public face.

use egui::{Id, Pos2, Rect, ScrollArea, Ui, UiBuilder, pos2, vec2};
use project_model::sfc_edit::{SfcEditError, find_node};
use project_model::{ElementId, SfcChart, SfcNode};

use super::commands::SfcCommand;
use super::entry::Entry;
use super::layout::{SfcLayout, sfc_layout};
use super::texts::SfcTexts;
use super::types::{SfcChange, SfcDiagnostic, SfcOnline, SfcOnlineCommand, SfcOutput};
use crate::DiagramServices;
use crate::EditorPalette;
use crate::diagram::toolbox::drag_or_click_ui;

/// The width of the toolbox column, in points.
const TOOLBOX_WIDTH_PX: f32 = 150.0;
/// The width of the properties panel, in points.
const PANEL_WIDTH_PX: f32 = 260.0;

/// The SFC editor of one body: a structured chart laid out automatically, edited by commands
/// on the selection. It never changes the model: each gesture comes out as one [`SfcChange`]
/// holding the whole new chart, which the app applies as `Edit::ReplaceChart`. It lives as
/// long as the document is open and is never saved.
pub struct SfcEditor {
    /// The chart as the model holds it, with this frame's changes applied.
    pub(super) chart: SfcChart,
    /// The layout of the shown sequence, recomputed when the chart or the level changes.
    pub(super) layout: SfcLayout,
    /// The macro steps zoomed into, outermost first; empty for the chart itself.
    pub(super) macro_path: Vec<ElementId>,
    /// The selected nodes.
    pub(super) selection: Vec<ElementId>,
    /// The zoom factor.
    pub(super) zoom: f32,
    /// The text field open over a node, if any.
    pub(super) entry: Option<Entry>,
    /// The last refusal, shown until the next command.
    pub(super) refusal: Option<SfcEditError>,
    /// The findings, by element.
    pub(super) diagnostics: Vec<SfcDiagnostic>,
    /// The online state while logged in.
    pub(super) online: Option<SfcOnline>,
    /// The names of the POU's transition objects, marked on transitions that use them.
    pub(super) transition_objects: Vec<String>,
    /// The names of the POU's actions, offered when an association's action is typed.
    pub(super) action_names: Vec<String>,
    /// The words.
    pub(super) texts: SfcTexts,
    /// Whether edits are refused (while online, or for a read-only project).
    pub(super) read_only: bool,
    /// Whether the canvas should take the keyboard focus in its next frame.
    pub(super) focus_requested: bool,
    /// Commands asked for between frames, run at the start of the next.
    pub(super) pending_commands: Vec<SfcCommand>,
    /// The property panel's texts being typed, for the element it shows.
    pub(super) panel: Option<super::panel::PanelState>,
    /// Where the canvas's content began on screen in the last frame.
    pub(super) last_origin: Pos2,
    /// The selection the view last scrolled to, so a new selection (an inserted step, a
    /// revealed finding) is scrolled into view once and the user's own scrolling is kept.
    pub(super) scrolled_to: Vec<ElementId>,
    /// The debugger's breakpoints, halt and flow marks, as the app gave them.
    pub(super) debug_marks: crate::BodyDebugMarks,
}

/// What one frame collects for its output.
#[derive(Default)]
pub(super) struct FrameResult {
    /// The chart after this frame's gesture, if it changed.
    pub change: Option<SfcChange>,
    /// The online action asked for this frame.
    pub online: Option<SfcOnlineCommand>,
    /// Why this frame's command did nothing.
    pub refusal: Option<SfcEditError>,
    /// Where F9 or the context menu asked for a breakpoint.
    pub toggle_breakpoint: Option<crate::BodyPlace>,
}

impl SfcEditor {
    /// An editor showing `chart`, nothing selected.
    pub fn new(chart: &SfcChart) -> Self {
        Self {
            layout: sfc_layout(&chart.sequence, true),
            chart: chart.clone(),
            macro_path: Vec::new(),
            selection: Vec::new(),
            zoom: 1.0,
            entry: None,
            refusal: None,
            diagnostics: Vec::new(),
            online: None,
            transition_objects: Vec::new(),
            action_names: Vec::new(),
            texts: SfcTexts::default(),
            read_only: false,
            focus_requested: false,
            scrolled_to: Vec::new(),
            debug_marks: crate::BodyDebugMarks::default(),
            pending_commands: Vec::new(),
            panel: None,
            last_origin: Pos2::ZERO,
        }
    }

    /// The chart shown.
    pub fn chart(&self) -> &SfcChart {
        &self.chart
    }

    /// Shows the model's `chart`; a no-op when it is the one shown. A selection or macro level
    /// that no longer exists is dropped.
    pub fn set_chart(&mut self, chart: &SfcChart) {
        if *chart == self.chart {
            return;
        }
        self.chart = chart.clone();
        self.selection
            .retain(|id| find_node(&self.chart, *id).is_some());
        let valid_levels = self
            .macro_path
            .iter()
            .take_while(|id| matches!(find_node(&self.chart, **id), Some(SfcNode::Macro(_))))
            .count();
        self.macro_path.truncate(valid_levels);
        self.panel = None;
        self.relayout();
    }

    /// Sets the words shown.
    pub fn set_texts(&mut self, texts: SfcTexts) {
        self.texts = texts;
    }

    /// Sets the names of the POU's transition objects (`Pou::transitions`).
    pub fn set_transition_objects(&mut self, names: Vec<String>) {
        self.transition_objects = names;
    }

    /// Sets the names of the POU's actions, offered for action associations and step actions.
    pub fn set_action_names(&mut self, names: Vec<String>) {
        self.action_names = names;
    }

    /// Sets the findings shown at their elements.
    pub fn set_diagnostics(&mut self, diagnostics: Vec<SfcDiagnostic>) {
        self.diagnostics = diagnostics;
    }

    /// The findings shown.
    pub fn diagnostics(&self) -> &[SfcDiagnostic] {
        &self.diagnostics
    }

    /// The debugger's marks to draw until replaced; an empty value removes them.
    pub fn set_debug_marks(&mut self, marks: crate::BodyDebugMarks) {
        self.debug_marks = marks;
    }

    /// The debugger's marks being drawn.
    pub fn debug_marks(&self) -> &crate::BodyDebugMarks {
        &self.debug_marks
    }

    /// Where a breakpoint toggled now would go: the one selected step or transition (the
    /// chart is network 0); `None` for anything else, which has no statement of its own.
    pub fn breakpoint_place(&self) -> Option<crate::BodyPlace> {
        let [id] = self.selection[..] else {
            return None;
        };
        matches!(
            find_node(&self.chart, id),
            Some(SfcNode::Step(_) | SfcNode::Transition(_))
        )
        .then_some(crate::BodyPlace {
            network: 0,
            element: Some(id),
        })
    }

    /// Sets the online state (`None` when logged out).
    pub fn set_online(&mut self, online: Option<SfcOnline>) {
        self.online = online;
    }

    /// The online state shown.
    pub fn online(&self) -> Option<&SfcOnline> {
        self.online.as_ref()
    }

    /// Refuses (`true`) or allows edits; online commands stay available.
    pub fn set_read_only(&mut self, read_only: bool) {
        self.read_only = read_only;
        if read_only {
            self.entry = None;
        }
    }

    /// The selected nodes.
    pub fn selection(&self) -> &[ElementId] {
        &self.selection
    }

    /// Selects `ids` (an empty list clears the selection).
    pub fn select(&mut self, ids: Vec<ElementId>) {
        if ids != self.selection {
            self.panel = None;
        }
        self.selection = ids;
    }

    /// Shows the level holding node `id` (opening the macro steps around it) and selects it,
    /// as a double-click on a finding does.
    pub fn reveal(&mut self, id: ElementId) {
        self.macro_path = macro_path_to(&self.chart.sequence, id).unwrap_or_default();
        self.relayout();
        self.select(vec![id]);
    }

    /// The macro steps zoomed into, outermost first.
    pub fn macro_path(&self) -> &[ElementId] {
        &self.macro_path
    }

    /// Gives the canvas the keyboard focus in the next frame.
    pub fn request_focus(&mut self) {
        self.focus_requested = true;
    }

    /// Runs `command` on the selection at the start of the next frame, as the app's menu does.
    pub fn run_command(&mut self, command: SfcCommand) {
        self.pending_commands.push(command);
    }

    /// The layout of the shown level.
    pub fn layout(&self) -> &SfcLayout {
        &self.layout
    }

    /// Where node `id` was drawn on screen in the last frame, if it is on the shown level.
    pub fn element_screen_rect(&self, id: ElementId) -> Option<Rect> {
        let placed = self.layout.element(id)?;
        Some(self.to_screen(placed.rect))
    }

    /// The zoom factor.
    pub fn zoom(&self) -> f32 {
        self.zoom
    }

    /// Shows the editor filling the available space: the macro path and zoom on top, the
    /// toolbox at the left, the chart, and the properties of the selected element at the right.
    /// `label` is the canvas's accessible name and keeps its state apart from other editors.
    pub fn show(&mut self, ui: &mut Ui, label: &str, services: &dyn DiagramServices) -> SfcOutput {
        let id = ui.make_persistent_id(("sfc_editor", label));
        let mut frame = FrameResult::default();
        for command in std::mem::take(&mut self.pending_commands) {
            self.command(ui.ctx(), command, &mut frame);
        }
        self.top_bar_ui(ui);
        let available = ui.available_rect_before_wrap();
        let toolbox =
            Rect::from_min_size(available.min, vec2(TOOLBOX_WIDTH_PX, available.height()));
        let panel_shown = self.panel_target().is_some();
        let panel_left = if panel_shown {
            available.right() - PANEL_WIDTH_PX
        } else {
            available.right()
        };
        let canvas = Rect::from_min_max(
            pos2(toolbox.right() + 4.0, available.top()),
            pos2(panel_left - 4.0, available.bottom()),
        );
        ui.scope_builder(UiBuilder::new().max_rect(toolbox), |ui| {
            self.toolbox_ui(ui, &mut frame);
        });
        let response = ui
            .scope_builder(UiBuilder::new().max_rect(canvas), |ui| {
                ScrollArea::both()
                    .id_salt(id.with("scroll"))
                    .auto_shrink([false, false])
                    .show(ui, |ui| self.canvas_ui(ui, id, label, services, &mut frame))
                    .inner
            })
            .inner;
        if panel_shown {
            let panel = Rect::from_min_max(pos2(panel_left, available.top()), available.max);
            ui.scope_builder(UiBuilder::new().max_rect(panel), |ui| {
                ScrollArea::vertical()
                    .id_salt(id.with("panel"))
                    .show(ui, |ui| self.panel_ui(ui, &mut frame));
            });
        }
        ui.advance_cursor_after_rect(available);
        if frame.refusal.is_some() {
            self.refusal.clone_from(&frame.refusal);
        }
        SfcOutput {
            response,
            change: frame.change,
            online: frame.online,
            refusal: frame.refusal,
            toggle_breakpoint: frame.toggle_breakpoint,
        }
    }

    fn top_bar_ui(&mut self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            if ui.link(&self.texts.chart).clicked() && !self.macro_path.is_empty() {
                self.macro_path.clear();
                self.after_level_change();
            }
            let mut leave_to = None;
            for (depth, macro_id) in self.macro_path.iter().enumerate() {
                ui.label("›");
                let name = match find_node(&self.chart, *macro_id) {
                    Some(SfcNode::Macro(macro_step)) => macro_step.name.clone(),
                    _ => String::new(),
                };
                if ui.link(name).clicked() {
                    leave_to = Some(depth + 1);
                }
            }
            if let Some(depth) = leave_to {
                self.macro_path.truncate(depth);
                self.after_level_change();
            }
            ui.separator();
            ui.label(format!("{:.0} %", self.zoom * 100.0))
                .on_hover_text(&self.texts.zoom);
            let palette = EditorPalette::of(ui);
            // Findings about the chart as a whole have no element to stand at.
            for diagnostic in self.diagnostics.iter().filter(|d| d.element.is_none()) {
                ui.separator();
                let color = match diagnostic.severity {
                    crate::Severity::Error => palette.error,
                    crate::Severity::Warning => palette.warning,
                    _ => palette.info,
                };
                ui.colored_label(
                    color,
                    format!("{}: {}", diagnostic.code, diagnostic.message),
                );
            }
            if let Some(refusal) = &self.refusal {
                ui.separator();
                ui.colored_label(palette.error, (self.texts.refusal)(refusal));
            }
        });
    }

    fn toolbox_ui(&mut self, ui: &mut Ui, frame: &mut FrameResult) {
        ui.strong(&self.texts.toolbox);
        ui.add_enabled_ui(!self.read_only, |ui| {
            for command in super::commands::INSERTIONS {
                let text = self.command_text(command).to_owned();
                // Clicked, it inserts at the selection; dragged, at the node it is dropped on.
                let button = egui::Button::new(text).min_size(vec2(TOOLBOX_WIDTH_PX - 8.0, 22.0));
                if drag_or_click_ui(ui, button, command).clicked() {
                    self.command(ui.ctx(), command, frame);
                    self.focus_requested = true;
                }
            }
        });
    }

    /// The words of `command` in menus and the toolbox.
    pub(super) fn command_text(&self, command: SfcCommand) -> &str {
        let texts = &self.texts;
        match command {
            SfcCommand::InsertStepTransitionAfter => &texts.step_transition,
            SfcCommand::InsertStepTransitionBefore => &texts.step_transition_before,
            SfcCommand::InsertAlternativeBranch => &texts.alternative_branch,
            SfcCommand::InsertParallelBranch => &texts.parallel_branch,
            SfcCommand::AddBranch => &texts.add_branch,
            SfcCommand::InsertJump => &texts.jump,
            SfcCommand::InsertMacroStep => &texts.macro_step,
            SfcCommand::WrapInMacro => &texts.wrap_in_macro,
            SfcCommand::AddActionAssociation => &texts.action_association,
            SfcCommand::Delete => &texts.delete,
            SfcCommand::Copy => &texts.copy,
            SfcCommand::Paste => &texts.paste,
            SfcCommand::EditText => &texts.edit_text,
            SfcCommand::OpenMacro => &texts.open_macro,
            SfcCommand::LeaveMacro => &texts.leave_macro,
            SfcCommand::ToggleStepActive => &texts.activate_step,
            SfcCommand::FireTransition => &texts.fire_transition,
        }
    }

    /// The nodes of the shown level.
    pub(super) fn shown_nodes(&self) -> &[SfcNode] {
        match self
            .macro_path
            .last()
            .and_then(|id| find_node(&self.chart, *id))
        {
            Some(SfcNode::Macro(macro_step)) => &macro_step.body,
            _ => &self.chart.sequence,
        }
    }

    pub(super) fn relayout(&mut self) {
        let main = self.macro_path.is_empty();
        self.layout = sfc_layout(self.shown_nodes(), main);
    }

    pub(super) fn after_level_change(&mut self) {
        self.selection.clear();
        self.entry = None;
        self.panel = None;
        self.relayout();
    }

    /// A rectangle of the content (zoom 1) on screen.
    pub(super) fn to_screen(&self, rect: Rect) -> Rect {
        Rect::from_min_max(
            self.last_origin + rect.min.to_vec2() * self.zoom,
            self.last_origin + rect.max.to_vec2() * self.zoom,
        )
    }

    /// Takes `result` of an edit: the new chart is shown and becomes the frame's change, or the
    /// refusal is kept. Returns whether it was applied.
    pub(super) fn apply(
        &mut self,
        result: Result<SfcChart, SfcEditError>,
        frame: &mut FrameResult,
    ) -> bool {
        match result {
            // An edit that changes nothing (a field left as it was) is no undo step.
            Ok(chart) if chart == self.chart => {
                self.refusal = None;
                true
            }
            Ok(chart) => {
                self.chart = chart.clone();
                self.selection
                    .retain(|id| find_node(&self.chart, *id).is_some());
                self.panel = None;
                self.refusal = None;
                self.relayout();
                frame.change = Some(SfcChange { chart });
                true
            }
            Err(error) => {
                frame.refusal = Some(error);
                false
            }
        }
    }

    /// The canvas's id, for the focus.
    pub(super) fn canvas_id(id: Id) -> Id {
        id.with("canvas")
    }
}

/// The macro steps around node `id`, outermost first, or `None` if it is not in `nodes`.
fn macro_path_to(nodes: &[SfcNode], id: ElementId) -> Option<Vec<ElementId>> {
    for node in nodes {
        if node.id() == id {
            return Some(Vec::new());
        }
        match node {
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                for branch in &branches.branches {
                    if let Some(path) = macro_path_to(&branch.nodes, id) {
                        return Some(path);
                    }
                }
            }
            SfcNode::Macro(macro_step) => {
                if let Some(mut path) = macro_path_to(&macro_step.body, id) {
                    path.insert(0, macro_step.id);
                    return Some(path);
                }
            }
            SfcNode::Step(_) | SfcNode::Transition(_) | SfcNode::Jump(_) => {}
        }
    }
    None
}
