//! What a document tab shows: POUs, variable lists and types as IEC text; everything else as a
//! property grid.

use editor::CodeView;
use egui::{RichText, Ui};
use project_model::{Body, Object, Pou, Project};

use super::cam_view::cam_view_ui;
use super::i18n::{Language, Text};
use super::property_view::property_view_ui;
use super::tree_node::TreeNode;

/// Draws the document `node` of `project`, read-only.
pub fn document_ui(ui: &mut Ui, project: &Project, node: &TreeNode, language: Language) {
    egui::ScrollArea::both()
        .id_salt(("document", node))
        .auto_shrink([false, false])
        .show(ui, |ui| {
            ui.add_space(4.0);
            match document_content(project, node) {
                Some(content) => content_ui(ui, node, content, language),
                None => {
                    ui.label(
                        RichText::new(format!(
                            "'{}' is no longer part of the project",
                            node.title(Some(project))
                        ))
                        .color(ui.visuals().warn_fg_color),
                    );
                }
            }
        });
}

/// The model data a document shows.
enum Content<'a> {
    Object(&'a Object),
    Controller(&'a project_model::Controller),
    IoArea(&'a project_model::IoArea),
    ModbusDevice(&'a project_model::ModbusDevice),
    Axis(&'a project_model::Axis),
}

fn document_content<'a>(project: &'a Project, node: &TreeNode) -> Option<Content<'a>> {
    match node {
        TreeNode::Object(name) => project.application.object(name).map(Content::Object),
        TreeNode::Controller => Some(Content::Controller(&project.controller)),
        TreeNode::IoArea(name) => project
            .io_areas
            .iter()
            .find(|a| a.name == *name)
            .map(Content::IoArea),
        TreeNode::ModbusDevice(name) => project
            .modbus_devices
            .iter()
            .find(|d| d.name == *name)
            .map(Content::ModbusDevice),
        TreeNode::Axis(name) => project
            .axes
            .iter()
            .find(|a| a.name == *name)
            .map(Content::Axis),
        _ => None,
    }
}

fn content_ui(ui: &mut Ui, node: &TreeNode, content: Content<'_>, language: Language) {
    let salt = format!("{node:?}");
    match content {
        Content::Object(Object::Pou(pou)) => pou_ui(ui, pou, language),
        Content::Object(Object::Gvl(gvl)) => {
            CodeView::new((&salt, "decl"), &gvl.declaration_text()).show(ui);
        }
        Content::Object(Object::DataType(data_type)) => {
            CodeView::new((&salt, "decl"), &data_type.declaration_text()).show(ui);
        }
        Content::Object(Object::CamTable(cam)) => cam_view_ui(ui, cam, language),
        Content::Object(Object::Trace(trace)) => property_view_ui(ui, &salt, trace),
        Content::Object(Object::WatchList(watch)) => property_view_ui(ui, &salt, watch),
        Content::Controller(controller) => property_view_ui(ui, &salt, controller),
        Content::IoArea(area) => property_view_ui(ui, &salt, area),
        Content::ModbusDevice(device) => property_view_ui(ui, &salt, device),
        Content::Axis(axis) => property_view_ui(ui, &salt, axis),
    }
}

/// A POU as CODESYS shows it: declarations above, implementation below, then its methods,
/// properties and actions.
fn pou_ui(ui: &mut Ui, pou: &Pou, language: Language) {
    section_heading(ui, Text::Declarations.get(language));
    CodeView::new((&pou.name, "declarations"), &pou.declaration_text()).show(ui);
    ui.separator();
    section_heading(ui, Text::Implementation.get(language));
    body_ui(ui, (&pou.name, "body"), &pou.body, language);

    for method in &pou.methods {
        ui.separator();
        section_heading(
            ui,
            &format!("{} {}", Text::Method.get(language), method.name),
        );
        CodeView::new(
            (&pou.name, &method.name, "decl"),
            &method.declaration_text(),
        )
        .show(ui);
        body_ui(
            ui,
            (&pou.name, &method.name, "body"),
            &method.body,
            language,
        );
    }
    for property in &pou.properties {
        ui.separator();
        section_heading(
            ui,
            &format!("{} {}", Text::Property.get(language), property.name),
        );
        CodeView::new(
            (&pou.name, &property.name, "decl"),
            &property.declaration_text(),
        )
        .show(ui);
        for (accessor, name) in [(&property.get, "Get"), (&property.set, "Set")] {
            if let Some(accessor) = accessor {
                ui.label(RichText::new(name).strong());
                body_ui(
                    ui,
                    (&pou.name, &property.name, name),
                    &accessor.body,
                    language,
                );
            }
        }
    }
    for action in &pou.actions {
        ui.separator();
        section_heading(
            ui,
            &format!("{} {}", Text::Action.get(language), action.name),
        );
        body_ui(
            ui,
            (&pou.name, &action.name, "action"),
            &action.body,
            language,
        );
    }
}

fn body_ui(ui: &mut Ui, salt: impl egui::AsIdSalt, body: &Body, language: Language) {
    match body {
        Body::None => {
            ui.label(RichText::new(Text::NoImplementation.get(language)).weak());
        }
        Body::St { text } => {
            CodeView::new(salt, text).show(ui);
        }
        graphical => property_view_ui(ui, &format!("{salt:?}"), graphical),
    }
}

fn section_heading(ui: &mut Ui, text: &str) {
    ui.label(RichText::new(text).strong().size(13.0));
}
