//! The toolbox: every CFC element. A click arms an element, which the next click on the
//! canvas places (Ctrl+click places it again and keeps it armed, as in CODESYS); an element
//! can also be dragged onto the canvas.

use egui::{Id, ScrollArea, Sense, Ui};

use super::editor::CfcEditor;
use super::types::CfcTool;

impl CfcEditor {
    /// The name of `tool` in the user's language.
    pub(super) fn tool_name(&self, tool: CfcTool) -> &str {
        let texts = &self.texts;
        match tool {
            CfcTool::Input => &texts.input,
            CfcTool::Output => &texts.output,
            CfcTool::Box => &texts.block,
            CfcTool::Jump => &texts.jump,
            CfcTool::Label => &texts.label,
            CfcTool::Return => &texts.return_,
            CfcTool::Composer => &texts.composer,
            CfcTool::Selector => &texts.selector,
            CfcTool::Comment => &texts.comment,
            CfcTool::ConnectionSource => &texts.connection_source,
            CfcTool::ConnectionSink => &texts.connection_sink,
            CfcTool::InputPin => &texts.input_pin,
            CfcTool::ControlPoint => &texts.control_point,
        }
    }

    pub(super) fn toolbox_ui(&mut self, ui: &mut Ui, id: Id) {
        ui.strong(&self.texts.toolbox);
        ScrollArea::vertical()
            .id_salt(id.with("toolbox"))
            .auto_shrink([false, false])
            .show(ui, |ui| {
                ui.add_enabled_ui(!self.read_only, |ui| {
                    for tool in CfcTool::ALL {
                        let armed = self.tool == Some(tool);
                        let name = self.tool_name(tool).to_owned();
                        let response = ui
                            .selectable_label(armed, name)
                            .interact(Sense::click_and_drag());
                        if response.clicked() {
                            self.tool = if armed { None } else { Some(tool) };
                        }
                        response.dnd_set_drag_payload(tool);
                    }
                });
            });
    }
}
