//! How the docking layout draws each pane and which tabs may close.

use egui::{RichText, Ui};
use egui_tiles::{Behavior, SimplificationOptions, Tile, TileId, Tiles, UiResponse};

use super::command::{Command, Commands};
use super::device_documents;
use super::device_tree::devices_pane_ui;
use super::dock::Dock;
use super::document_view::{document_ui, settings_ui};
use super::i18n::{Language, Text};
use super::pane::Pane;
use super::pane_states::PaneStates;
use super::panes;
use super::reveal::Reveal;
use super::task_editor::task_editor_ui;
use super::tree_node::TreeNode;
use super::view::StudioView;

/// The egui_tiles behaviour of the studio: it draws each pane from the studio's view and the
/// pane's own state, and lets only document tabs close. Panes change nothing else: they emit
/// commands.
pub(crate) struct PaneBehavior<'a> {
    /// What every pane reads.
    pub view: StudioView<'a>,
    /// What each pane keeps between frames.
    pub panes: &'a mut PaneStates,
    /// Where panes put their commands.
    pub commands: &'a mut Commands,
}

impl Behavior<Pane> for PaneBehavior<'_> {
    fn pane_ui(&mut self, ui: &mut Ui, _tile_id: TileId, pane: &mut Pane) -> UiResponse {
        let view = self.view;
        let states = &mut *self.panes;
        let commands = &mut *self.commands;
        egui::Frame::new().inner_margin(4).show(ui, |ui| {
            ui.set_min_size(ui.available_size());
            match pane {
                Pane::Devices => devices_pane_ui(view, &mut states.tree_edit, commands, ui),
                Pane::Properties => properties_ui(view, ui),
                Pane::Document(node) => document_pane_ui(view, states, commands, ui, node),
                Pane::Messages => panes::messages_ui(view, commands, ui),
                Pane::Watch => panes::watch_ui(view, &mut states.watch, commands, ui),
                Pane::Forces => panes::forces_ui(view, commands, ui),
                Pane::Trace => {
                    let (trace, plot) = (&mut states.trace, &mut states.trace_view);
                    panes::trace_ui(view, trace, plot, commands, ui)
                }
                Pane::Tasks => panes::tasks_ui(view, commands, ui),
                Pane::Breakpoints => {
                    panes::breakpoints_ui(view, &mut states.breakpoints, commands, ui);
                }
                Pane::CallStack => {
                    panes::call_stack_ui(view, &mut states.texts.graphical, commands, ui);
                }
            }
        });
        UiResponse::None
    }

    fn tab_title_for_pane(&mut self, pane: &Pane) -> egui::WidgetText {
        let language = self.view.language;
        match pane {
            Pane::Document(TreeNode::TaskConfiguration) => {
                Text::TaskConfiguration.get(language).into()
            }
            Pane::Document(node) => {
                let project = self.view.project();
                node.title(project).into()
            }
            Pane::Messages => {
                let count = panes::message_count(self.view);
                if count > 0 {
                    format!("{} ({count})", pane.tool_title(language)).into()
                } else {
                    pane.tool_title(language).into()
                }
            }
            Pane::Forces => {
                let count = self.view.online.forced_values().len();
                if count > 0 {
                    format!("{} ({count})", pane.tool_title(language)).into()
                } else {
                    pane.tool_title(language).into()
                }
            }
            tool => tool.tool_title(language).into(),
        }
    }

    fn is_tab_closable(&self, tiles: &Tiles<Pane>, tile_id: TileId) -> bool {
        matches!(tiles.get(tile_id), Some(Tile::Pane(Pane::Document(_))))
    }

    fn simplification_options(&self) -> SimplificationOptions {
        Dock::simplification_options()
    }
}

fn properties_ui(view: StudioView<'_>, ui: &mut Ui) {
    let (Some(project), Some(node)) = (view.project(), view.selection) else {
        ui.label(RichText::new(Text::OpenObjectHint.get(view.language)).weak());
        return;
    };
    ui.strong(node.title(Some(project)));
    ui.separator();
    egui::ScrollArea::both()
        .id_salt("properties")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            if let TreeNode::Object(name) = node
                && let Some(object) = project.application.object(name)
            {
                object_summary_ui(ui, object, view.language);
            } else {
                settings_ui(ui, project, node);
            }
        });
}

/// What the properties pane shows for an application object: its kind and size, not its text
/// (the document tab shows that).
fn object_summary_ui(ui: &mut Ui, object: &project_model::Object, language: Language) {
    use project_model::Object;
    egui::Grid::new("object_summary")
        .num_columns(2)
        .show(ui, |ui| {
            let count =
                |text: Text, name: &str, n: usize| text.get(language).replace(name, &n.to_string());
            let (kind, detail) = match object {
                Object::Pou(pou) => (
                    format!("{:?}", pou.kind),
                    count(Text::PouSummary, "{variables}", pou.variables.len())
                        .replace("{methods}", &pou.methods.len().to_string())
                        .replace("{actions}", &pou.actions.len().to_string())
                        .replace("{transitions}", &pou.transitions.len().to_string()),
                ),
                Object::Gvl(gvl) => (
                    "GVL".to_owned(),
                    count(Text::VariableCount, "{variables}", gvl.variables.len()),
                ),
                Object::DataType(_) => ("DUT".to_owned(), String::new()),
                Object::CamTable(_) => ("CAM".to_owned(), String::new()),
                Object::Trace(trace) => (
                    Text::Trace.get(language).to_owned(),
                    count(Text::TraceSummary, "{variables}", trace.variables.len())
                        .replace("{task}", &trace.task),
                ),
                Object::WatchList(watch) => (
                    Text::WatchList.get(language).to_owned(),
                    count(Text::EntryCount, "{entries}", watch.entries.len()),
                ),
            };
            ui.label(Text::Kind.get(language));
            ui.label(kind);
            ui.end_row();
            if !detail.is_empty() {
                ui.label(Text::Content.get(language));
                ui.label(detail);
                ui.end_row();
            }
        });
}

fn document_pane_ui(
    view: StudioView<'_>,
    states: &mut PaneStates,
    commands: &mut Commands,
    ui: &mut Ui,
    node: &TreeNode,
) {
    // Tasks are edited in place: their editor emits its edits as commands.
    if matches!(node, TreeNode::Task(_) | TreeNode::TaskConfiguration) {
        task_editor_ui(view, &mut states.task_editor, commands, ui, node);
        return;
    }
    // The controller, its I/O areas and the Modbus devices show their I/O mapping.
    if matches!(
        node,
        TreeNode::Controller | TreeNode::IoArea(_) | TreeNode::ModbusDevice(_)
    ) {
        io_document_ui(view, &mut states.devices, commands, ui, node);
        return;
    }
    // Axes and serial ports are edited in place by their device editor, under their title,
    // scrolled.
    if let (TreeNode::Axis(_) | TreeNode::SerialPort(_), Some(project)) = (node, view.project()) {
        let devices = &mut states.devices;
        egui::ScrollArea::vertical()
            .id_salt(("axis document", node))
            .auto_shrink([false, false])
            .show(ui, |ui| {
                ui.add_space(4.0);
                ui.label(RichText::new(node.title(Some(project))).strong());
                ui.separator();
                device_documents::device_editor_ui(
                    ui,
                    project,
                    node,
                    view.language,
                    devices,
                    commands,
                );
            });
        return;
    }
    // Structured Text is edited in place; everything else is shown by the document views.
    if let TreeNode::Object(name) = node {
        let texts = &mut states.texts;
        let shown = super::text_documents::pou_document_ui(view, texts, commands, ui, name)
            || super::text_documents::gvl_document_ui(view, texts, commands, ui, name)
            || super::cam_documents::cam_document_ui(view, &mut states.cams, commands, ui, name);
        if shown {
            return;
        }
    }
    if let Some(project) = view.project() {
        document_ui(ui, project, node, view.language);
    }
}

/// A controller, I/O area or Modbus device document: its editor, then the I/O mapping of
/// every channel with the variable bound to it (a click opens the declaration).
fn io_document_ui(
    view: StudioView<'_>,
    devices: &mut device_documents::DeviceDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    node: &TreeNode,
) {
    let Some(project) = view.project() else {
        return;
    };
    egui::CollapsingHeader::new(RichText::new(node.title(Some(project))).strong())
        .id_salt(("io_document_settings", node))
        .default_open(true)
        .show(ui, |ui| {
            device_documents::modbus_online_part_ui(ui, project, node, view.online, view.language);
            device_documents::device_editor_ui(ui, project, node, view.language, devices, commands);
        });
    ui.separator();
    let texts = super::text_documents::table_texts(view.language);
    let output = editor::io_mapping_ui(ui, project, &texts);
    if let Some((owner, variable)) = output.open {
        // A method's variables belong to its POU's document.
        let object = owner.split('.').next().unwrap_or(&owner).to_owned();
        let container = owner.split_once('.').map(|(_, method)| method.to_owned());
        commands.push(Command::Reveal(
            TreeNode::Object(object),
            Reveal::Declaration {
                container,
                name: variable,
            },
        ));
    }
}
