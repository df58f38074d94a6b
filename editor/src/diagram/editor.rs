//! [`DiagramEditor`]: its state, what the app sets each frame and the frame itself.

use std::collections::{HashMap, HashSet};

use egui::scroll_area::ScrollSource;
use egui::{Pos2, Rect, ScrollArea, Ui, UiBuilder, Vec2, pos2, vec2};
use project_model::{BodySplice, ElementId, Network};

use super::commands::{DiagramCommand, DiagramSelection};
use super::entry::Entry;
use super::fbd_layout::fbd_layout;
use super::ld_layout::ld_layout;
use super::paint::cell_size_px;
use super::placed::NetworkLayout;
use super::texts::DiagramTexts;
use super::types::{
    DiagramChange, DiagramOnline, DiagramOutput, DiagramRefusal, DiagramServices, DiagramView,
    ElementDiagnostic, InstanceDeclaration, PreparedOperand,
};
use crate::{BodyDebugMarks, BodyPlace, Severity};

/// The height of a network's header (number, title, comment), in points at zoom 1.
pub(super) const HEADER_HEIGHT_PX: f32 = 40.0;
/// The space between two networks, in points at zoom 1.
pub(super) const NETWORK_GAP_PX: f32 = 18.0;
/// The margin left of the networks that holds their numbers, in points at zoom 1.
pub(super) const LEFT_MARGIN_PX: f32 = 48.0;
/// The width of the toolbox, in points.
const TOOLBOX_WIDTH_PX: f32 = 120.0;

/// The combined LD/FBD editor of one graphical body.
///
/// The app keeps one per open body and, every frame:
/// - calls [`DiagramEditor::set_networks`] with the model's networks (nothing happens when they
///   are the same; after undo, redo or a reload the editor takes the new ones);
/// - sets diagnostics ([`DiagramEditor::set_diagnostics`]) and, while logged in, the online
///   values ([`DiagramEditor::set_online`]) when they change;
/// - calls [`DiagramEditor::show`] with a label and its [`DiagramServices`];
/// - applies [`DiagramOutput::change`] as the model's `Edit::SpliceNetworks` after the frame,
///   together with [`DiagramOutput::declare_instance`] as one undo step, and handles
///   [`DiagramOutput::prepared`] as a value to write or force.
pub struct DiagramEditor {
    /// The networks shown: the model's, with this editor's changes applied at once.
    pub(super) networks: Vec<Network>,
    /// The layout of each network in the current view.
    pub(super) layouts: Vec<NetworkLayout>,
    /// The top of each network's header in the content, in points at zoom 1.
    pub(super) tops_px: Vec<f32>,
    /// The size of the content at zoom 1, in points.
    pub(super) content_px: Vec2,
    /// LD or FBD.
    pub(super) view: DiagramView,
    /// Points on screen per point of content.
    pub(super) zoom: f32,
    /// A scroll offset to apply in the next frame (after a zoom or a pan).
    pub(super) pending_offset: Option<Vec2>,
    /// The scroll offset of the last frame.
    pub(super) scroll_offset: Vec2,
    /// What is selected.
    pub(super) selection: DiagramSelection,
    /// The open text field over an element, header or insertion, if any.
    pub(super) entry: Option<Entry>,
    /// Whether the input assistant (F2) is open.
    pub(super) assistant_open: bool,
    /// The diagnostics, as the app gave them.
    pub(super) diagnostics: Vec<ElementDiagnostic>,
    /// The worst severity on each element.
    pub(super) marks: HashMap<ElementId, Severity>,
    /// The worst severity on each pin of a box, for the findings that name a pin.
    pub(super) pin_marks: HashMap<(ElementId, String), Severity>,
    /// The online values; `None` while offline.
    pub(super) online: Option<DiagramOnline>,
    /// The words shown.
    pub(super) texts: DiagramTexts,
    /// Set by [`DiagramEditor::request_focus`], honoured by the next `show`.
    pub(super) focus_requested: bool,
    /// Set when the selection moved by keyboard and must be scrolled into view.
    pub(super) scroll_to_selection: bool,
    /// Where a rubber band selection started, in content points at zoom 1.
    pub(super) rubber_band_from: Option<Pos2>,
    /// Commands from the app's menus, run at the next `show`.
    pub(super) pending_commands: Vec<DiagramCommand>,
    /// Whether changes are refused (online without online change).
    pub(super) read_only: bool,
    /// The screen position of the content's top-left corner in the last frame.
    pub(super) last_origin: Pos2,
    /// The input pin of the selected box the user clicked, if any: typing enters its operand
    /// and negation negates it.
    pub(super) selected_pin: Option<String>,
    /// The networks the last frame painted.
    pub(super) visible: std::ops::Range<usize>,
    /// The debugger's breakpoints, halt and flow marks, as the app gave them.
    pub(super) debug_marks: BodyDebugMarks,
}

/// What a frame collects for its output.
#[derive(Default)]
pub(super) struct FrameResult {
    pub change: Option<DiagramChange>,
    /// The number of networks before the frame's first change, for merging a second one.
    pub networks_before: Option<usize>,
    pub declare_instance: Option<InstanceDeclaration>,
    pub prepared: Option<PreparedOperand>,
    pub refusal: Option<DiagramRefusal>,
    /// Where F9 or the context menu asked for a breakpoint.
    pub toggle_breakpoint: Option<BodyPlace>,
}

impl DiagramEditor {
    /// An editor for `networks`, drawn first in `view`.
    pub fn new(networks: &[Network], view: DiagramView) -> Self {
        let mut editor = Self {
            networks: networks.to_vec(),
            layouts: Vec::new(),
            tops_px: Vec::new(),
            content_px: Vec2::ZERO,
            view,
            zoom: 1.0,
            pending_offset: None,
            scroll_offset: Vec2::ZERO,
            selection: DiagramSelection::default(),
            entry: None,
            assistant_open: false,
            diagnostics: Vec::new(),
            marks: HashMap::new(),
            pin_marks: HashMap::new(),
            online: None,
            texts: DiagramTexts::default(),
            focus_requested: false,
            scroll_to_selection: false,
            rubber_band_from: None,
            pending_commands: Vec::new(),
            read_only: false,
            last_origin: Pos2::ZERO,
            selected_pin: None,
            visible: 0..0,
            debug_marks: BodyDebugMarks::default(),
        };
        editor.relayout_all();
        editor
    }

    /// The networks the editor shows.
    pub fn networks(&self) -> &[Network] {
        &self.networks
    }

    /// Takes the model's networks when they differ from the shown ones (after undo, redo or a
    /// change made elsewhere); only the networks that changed are laid out again.
    pub fn set_networks(&mut self, networks: &[Network]) {
        if self.networks == networks {
            return;
        }
        if self.networks.len() == networks.len() {
            for (index, network) in networks.iter().enumerate() {
                if self.networks[index] != *network {
                    self.networks[index] = network.clone();
                    self.layouts[index] = self.layout_of(index);
                }
            }
            self.place_networks();
        } else {
            self.networks = networks.to_vec();
            self.relayout_all();
        }
        self.clamp_selection();
    }

    /// The view shown.
    pub fn view(&self) -> DiagramView {
        self.view
    }

    /// Switches between the LD and the FBD view.
    pub fn set_view(&mut self, view: DiagramView) {
        if self.view != view {
            self.view = view;
            self.relayout_all();
        }
    }

    /// The selection.
    pub fn selection(&self) -> &DiagramSelection {
        &self.selection
    }

    /// Selects `elements` in network `network` and scrolls them into view.
    pub fn select(&mut self, network: Option<usize>, elements: Vec<ElementId>) {
        self.selection = DiagramSelection { elements, network };
        self.selected_pin = None;
        self.scroll_to_selection = true;
    }

    /// Selects the element `id` (as the messages pane does for a diagnostic) and scrolls to it.
    pub fn reveal(&mut self, id: ElementId) {
        if let Some(network) = self
            .networks
            .iter()
            .position(|network| network.element(id).is_some())
        {
            self.select(Some(network), vec![id]);
        }
    }

    /// Makes the editor take keyboard focus at the next `show`.
    pub fn request_focus(&mut self) {
        self.focus_requested = true;
    }

    /// Runs `command` (from the app's menu) at the next `show`, on the selection.
    pub fn run_command(&mut self, command: DiagramCommand) {
        self.pending_commands.push(command);
    }

    /// In read-only mode the body can be viewed, selected and copied but not changed.
    pub fn set_read_only(&mut self, read_only: bool) {
        self.read_only = read_only;
        if read_only {
            self.entry = None;
        }
    }

    /// The compiler's diagnostics for this body, shown at their elements until replaced.
    pub fn set_diagnostics(&mut self, diagnostics: Vec<ElementDiagnostic>) {
        self.marks.clear();
        self.pin_marks.clear();
        let rank = |severity: &Severity| match severity {
            Severity::Error => 2,
            Severity::Warning => 1,
            Severity::Info => 0,
        };
        for diagnostic in &diagnostics {
            if let Some(id) = diagnostic.element {
                let entry = self.marks.entry(id).or_insert(diagnostic.severity);
                if rank(&diagnostic.severity) > rank(entry) {
                    *entry = diagnostic.severity;
                }
                if let Some(pin) = &diagnostic.pin {
                    let entry = self
                        .pin_marks
                        .entry((id, pin.clone()))
                        .or_insert(diagnostic.severity);
                    if rank(&diagnostic.severity) > rank(entry) {
                        *entry = diagnostic.severity;
                    }
                }
            }
        }
        self.diagnostics = diagnostics;
    }

    /// The diagnostics shown, as the app gave them.
    pub fn diagnostics(&self) -> &[ElementDiagnostic] {
        &self.diagnostics
    }

    /// The online values shown; `None` when offline.
    pub fn online(&self) -> Option<&DiagramOnline> {
        self.online.as_ref()
    }

    /// The online values to show; `None` when offline.
    pub fn set_online(&mut self, online: Option<DiagramOnline>) {
        self.online = online;
    }

    /// The user-visible words, in the app's language.
    pub fn set_texts(&mut self, texts: DiagramTexts) {
        self.texts = texts;
    }

    /// The debugger's marks to draw until replaced; an empty value removes them.
    pub fn set_debug_marks(&mut self, marks: BodyDebugMarks) {
        self.debug_marks = marks;
    }

    /// The debugger's marks being drawn.
    pub fn debug_marks(&self) -> &BodyDebugMarks {
        &self.debug_marks
    }

    /// Where a breakpoint toggled now would go: the one selected element, or the selected
    /// network when no element is selected; `None` for no selection or several elements.
    pub fn breakpoint_place(&self) -> Option<BodyPlace> {
        match self.selection.elements.as_slice() {
            [element] => Some(BodyPlace {
                network: self
                    .networks
                    .iter()
                    .position(|network| network.element(*element).is_some())?,
                element: Some(*element),
            }),
            [] => Some(BodyPlace {
                network: self.selection.network?,
                element: None,
            }),
            _ => None,
        }
    }

    /// The layout of network `index` in the current view.
    pub fn layout(&self, index: usize) -> Option<&NetworkLayout> {
        self.layouts.get(index)
    }

    /// Where element `id` was drawn in the last frame, in screen points.
    pub fn element_screen_rect(&self, id: ElementId) -> Option<Rect> {
        let index = self
            .networks
            .iter()
            .position(|network| network.element(id).is_some())?;
        let cells = self.layouts.get(index)?.element(id)?.rect;
        let origin = self.network_origin_px(index);
        let min = origin + cells.min.to_vec2() * self.cell_px();
        let max = origin + cells.max.to_vec2() * self.cell_px();
        Some(Rect::from_min_max(
            self.last_origin + min.to_vec2() * self.zoom,
            self.last_origin + max.to_vec2() * self.zoom,
        ))
    }

    /// The size of a grid cell of the current view at zoom 1, in points.
    pub(super) fn cell_px(&self) -> Vec2 {
        cell_size_px(self.view)
    }

    /// The zoom factor (1 is 100 %).
    pub fn zoom(&self) -> f32 {
        self.zoom
    }

    /// The range of networks the last frame painted.
    pub fn visible_networks(&self) -> std::ops::Range<usize> {
        self.visible.clone()
    }

    /// Shows the editor filling the available space: a view toggle, the toolbox and the canvas.
    /// `label` is its accessible name and keeps its state apart from other editors.
    pub fn show(
        &mut self,
        ui: &mut Ui,
        label: &str,
        services: &dyn DiagramServices,
    ) -> DiagramOutput {
        let id = ui.make_persistent_id(("diagram_editor", label));
        let mut frame = FrameResult::default();
        for command in std::mem::take(&mut self.pending_commands) {
            self.command(command, &mut frame);
        }
        self.top_bar_ui(ui);
        let available = ui.available_rect_before_wrap();
        let toolbox =
            Rect::from_min_size(available.min, vec2(TOOLBOX_WIDTH_PX, available.height()));
        let canvas =
            Rect::from_min_max(pos2(toolbox.right() + 4.0, available.top()), available.max);
        ui.scope_builder(UiBuilder::new().max_rect(toolbox), |ui| {
            self.toolbox_ui(ui, id, services, &mut frame);
        });
        let response = ui
            .scope_builder(UiBuilder::new().max_rect(canvas), |ui| {
                let mut area = ScrollArea::both()
                    .id_salt(id.with("scroll"))
                    .auto_shrink([false, false])
                    .scroll_source(ScrollSource::SCROLL_BAR | ScrollSource::MOUSE_WHEEL);
                if let Some(offset) = self.pending_offset.take() {
                    area = area.scroll_offset(offset);
                }
                let output = area.show_viewport(ui, |ui, viewport| {
                    self.canvas_ui(ui, id, label, viewport, services, &mut frame)
                });
                self.scroll_offset = output.state.clamped_offset();
                output.inner
            })
            .inner;
        ui.advance_cursor_after_rect(available);
        self.assistant_ui(ui.ctx(), id, services, &mut frame);
        DiagramOutput {
            response,
            change: frame.change,
            declare_instance: frame.declare_instance,
            prepared: frame.prepared,
            refusal: frame.refusal,
            toggle_breakpoint: frame.toggle_breakpoint,
        }
    }

    fn top_bar_ui(&mut self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            let mut view = self.view;
            ui.selectable_value(&mut view, DiagramView::Ladder, &self.texts.ladder_view);
            ui.selectable_value(
                &mut view,
                DiagramView::FunctionBlock,
                &self.texts.function_block_view,
            );
            self.set_view(view);
            ui.separator();
            ui.label(format!("{:.0} %", self.zoom * 100.0))
                .on_hover_text(&self.texts.zoom);
        });
    }

    /// Applies a structural edit: to the shown networks at once, and to the frame's change.
    pub(super) fn apply_splice(&mut self, splice: BodySplice, frame: &mut FrameResult) {
        let before = self.networks.len();
        let change = DiagramChange {
            at: splice.at,
            remove: splice.remove,
            insert: splice.insert,
        };
        change.apply(&mut self.networks);
        let replaced = change.at..change.at + change.insert.len();
        frame.change = Some(match (frame.change.take(), frame.networks_before) {
            // A second change in one frame (a menu command and a key) merges into one.
            (Some(_), Some(first_before)) => DiagramChange {
                at: 0,
                remove: first_before,
                insert: self.networks.clone(),
            },
            _ => {
                frame.networks_before = Some(before);
                change
            }
        });
        if self.networks.len() == before {
            // The networks kept their indices: only the replaced ones change their layout.
            for index in replaced {
                self.layouts[index] = self.layout_of(index);
            }
            self.place_networks();
        } else {
            self.relayout_all();
        }
        if let Some(focus) = splice.focus {
            let network = self
                .networks
                .iter()
                .position(|network| network.element(focus).is_some());
            self.select(network, vec![focus]);
        } else {
            self.select(
                splice
                    .focus_network
                    .filter(|index| *index < self.networks.len()),
                Vec::new(),
            );
        }
    }

    pub(super) fn layout_of(&self, index: usize) -> NetworkLayout {
        match self.view {
            DiagramView::Ladder => ld_layout(&self.networks[index], index),
            DiagramView::FunctionBlock => fbd_layout(&self.networks[index], index),
        }
    }

    fn relayout_all(&mut self) {
        self.layouts = (0..self.networks.len())
            .map(|index| self.layout_of(index))
            .collect();
        self.place_networks();
        self.clamp_selection();
    }

    /// Stacks the networks: each takes its header, its drawing and a gap.
    fn place_networks(&mut self) {
        let mut top = 0.0;
        let mut width: f32 = 0.0;
        self.tops_px.clear();
        for layout in &self.layouts {
            self.tops_px.push(top);
            top += HEADER_HEIGHT_PX + layout.size.y * self.cell_px().y + NETWORK_GAP_PX;
            width = width.max(layout.size.x * self.cell_px().x);
        }
        self.tops_px.push(top);
        self.content_px = vec2(
            LEFT_MARGIN_PX + width + 2.0 * self.cell_px().x,
            top + self.cell_px().y,
        );
    }

    fn clamp_selection(&mut self) {
        let networks = &self.networks;
        self.selection.elements.retain(|id| {
            networks
                .iter()
                .any(|network| network.element(*id).is_some())
        });
        if self
            .selection
            .network
            .is_some_and(|index| index >= networks.len())
        {
            self.selection.network = networks.len().checked_sub(1);
        }
    }

    /// The networks whose blocks overlap content rows `top..bottom` (points at zoom 1).
    pub(super) fn networks_between(&self, top: f32, bottom: f32) -> std::ops::Range<usize> {
        let count = self.networks.len();
        let first = self.tops_px[1..]
            .partition_point(|end| *end <= top)
            .min(count);
        let last = self.tops_px[..count].partition_point(|start| *start < bottom);
        first..last.max(first)
    }

    /// The top-left corner of network `index`'s drawing, in content points at zoom 1.
    pub(super) fn network_origin_px(&self, index: usize) -> Pos2 {
        pos2(LEFT_MARGIN_PX, self.tops_px[index] + HEADER_HEIGHT_PX)
    }

    /// The elements selected, as a set for painting.
    pub(super) fn selected_set(&self) -> HashSet<ElementId> {
        self.selection.elements.iter().copied().collect()
    }
}
