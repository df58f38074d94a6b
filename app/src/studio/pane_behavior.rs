//! How the docking layout draws each pane and which tabs may close.

use egui::{RichText, Ui};
use egui_tiles::{Behavior, SimplificationOptions, Tile, TileId, Tiles, UiResponse};

use super::device_documents;
use super::device_tree::devices_pane_ui;
use super::dock::Dock;
use super::document_view::{document_ui, settings_ui};
use super::i18n::Text;
use super::pane::Pane;
use super::panes;
use super::studio_app::{Command, Studio};
use super::task_editor::task_editor_ui;
use super::tree_node::TreeNode;

/// The egui_tiles behaviour of the studio: it draws panes from the studio's state and lets
/// only document tabs close.
pub(crate) struct PaneBehavior<'a> {
    pub studio: &'a mut Studio,
}

impl Behavior<Pane> for PaneBehavior<'_> {
    fn pane_ui(&mut self, ui: &mut Ui, _tile_id: TileId, pane: &mut Pane) -> UiResponse {
        let studio = &mut *self.studio;
        egui::Frame::new().inner_margin(4).show(ui, |ui| {
            ui.set_min_size(ui.available_size());
            match pane {
                Pane::Devices => devices_pane_ui(studio, ui),
                Pane::Properties => properties_ui(studio, ui),
                Pane::Document(node) => document_pane_ui(studio, ui, node),
                Pane::Messages => panes::messages_ui(studio, ui),
                Pane::Watch => panes::watch_ui(studio, ui),
                Pane::Forces => panes::forces_ui(studio, ui),
                Pane::Trace => panes::trace_ui(studio, ui),
                Pane::Tasks => panes::tasks_ui(studio, ui),
            }
        });
        UiResponse::None
    }

    fn tab_title_for_pane(&mut self, pane: &Pane) -> egui::WidgetText {
        let language = self.studio.settings.language;
        match pane {
            Pane::Document(TreeNode::TaskConfiguration) => {
                Text::TaskConfiguration.get(language).into()
            }
            Pane::Document(node) => {
                let project = self.studio.session.as_ref().map(|s| &s.project);
                node.title(project).into()
            }
            Pane::Messages => {
                let count = panes::message_count(self.studio);
                if count > 0 {
                    format!("{} ({count})", pane.tool_title(language)).into()
                } else {
                    pane.tool_title(language).into()
                }
            }
            Pane::Forces => {
                let count = self.studio.online.forced_values().len();
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

fn properties_ui(studio: &mut Studio, ui: &mut Ui) {
    let (Some(session), Some(node)) = (&studio.session, &studio.selection) else {
        ui.label(RichText::new(Text::OpenObjectHint.get(studio.settings.language)).weak());
        return;
    };
    let project = &session.project;
    ui.strong(node.title(Some(project)));
    ui.separator();
    egui::ScrollArea::both()
        .id_salt("properties")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            if let TreeNode::Object(name) = node
                && let Some(object) = project.application.object(name)
            {
                object_summary_ui(ui, object);
            } else {
                settings_ui(ui, project, node);
            }
        });
}

/// What the properties pane shows for an application object: its kind and size, not its text
/// (the document tab shows that).
fn object_summary_ui(ui: &mut Ui, object: &project_model::Object) {
    use project_model::Object;
    egui::Grid::new("object_summary")
        .num_columns(2)
        .show(ui, |ui| {
            let (kind, detail) = match object {
                Object::Pou(pou) => (
                    format!("{:?}", pou.kind),
                    format!(
                        "{} variables, {} methods, {} actions",
                        pou.variables.len(),
                        pou.methods.len(),
                        pou.actions.len()
                    ),
                ),
                Object::Gvl(gvl) => (
                    "GVL".to_owned(),
                    format!("{} variables", gvl.variables.len()),
                ),
                Object::DataType(_) => ("DUT".to_owned(), String::new()),
                Object::CamTable(_) => ("CAM".to_owned(), String::new()),
                Object::Trace(trace) => (
                    "Trace".to_owned(),
                    format!("{} variables, task {}", trace.variables.len(), trace.task),
                ),
                Object::WatchList(watch) => (
                    "Watch list".to_owned(),
                    format!("{} entries", watch.entries.len()),
                ),
            };
            ui.label("Kind");
            ui.label(kind);
            ui.end_row();
            if !detail.is_empty() {
                ui.label("Content");
                ui.label(detail);
                ui.end_row();
            }
        });
}

fn document_pane_ui(studio: &mut Studio, ui: &mut Ui, node: &TreeNode) {
    // Tasks are edited in place, so their editor needs the studio to queue its edits.
    if matches!(node, TreeNode::Task(_) | TreeNode::TaskConfiguration) {
        task_editor_ui(studio, ui, node);
        return;
    }
    // The controller, its I/O areas and the Modbus devices show their I/O mapping.
    if matches!(
        node,
        TreeNode::Controller | TreeNode::IoArea(_) | TreeNode::ModbusDevice(_)
    ) {
        io_document_ui(studio, ui, node);
        return;
    }
    // Axes are edited in place by their device editor.
    if let (TreeNode::Axis(_), Some(session)) = (node, &studio.session) {
        let language = studio.settings.language;
        let (devices, pending) = (&mut studio.devices, &mut studio.pending);
        device_documents::axis_document_ui(ui, &session.project, node, language, devices, pending);
        return;
    }
    // Structured Text is edited in place; everything else is shown by the document views.
    if let TreeNode::Object(name) = node {
        let shown = super::text_documents::pou_document_ui(studio, ui, name)
            || super::text_documents::gvl_document_ui(studio, ui, name)
            || super::cam_documents::cam_document_ui(studio, ui, name);
        if shown {
            return;
        }
    }
    if let Some(session) = &studio.session {
        document_ui(ui, &session.project, node);
    }
}

/// A controller, I/O area or Modbus device document: its editor, then the I/O mapping of
/// every channel with the variable bound to it (a click opens the declaration).
fn io_document_ui(studio: &mut Studio, ui: &mut Ui, node: &TreeNode) {
    let Some(session) = &studio.session else {
        return;
    };
    let project = &session.project;
    egui::CollapsingHeader::new(RichText::new(node.title(Some(project))).strong())
        .id_salt(("io_document_settings", node))
        .default_open(true)
        .show(ui, |ui| {
            let language = studio.settings.language;
            let (devices, pending) = (&mut studio.devices, &mut studio.pending);
            device_documents::device_editor_ui(ui, project, node, language, devices, pending);
        });
    ui.separator();
    let texts = super::text_documents::table_texts(studio.settings.language);
    let output = editor::io_mapping_ui(ui, project, &texts);
    if let Some((owner, variable)) = output.open {
        // A method's variables belong to its POU's document.
        let object = owner.split('.').next().unwrap_or(&owner).to_owned();
        let container = owner.split_once('.').map(|(_, method)| method.to_owned());
        studio.pending.push(Command::Reveal(
            TreeNode::Object(object),
            super::text_documents::Reveal::Declaration {
                container,
                name: variable,
            },
        ));
    }
}
