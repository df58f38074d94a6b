//! The editor of an I/O area: its direction, start byte, size and comment, with overlaps with
//! the other areas of its direction refused in place.

use egui::Ui;
use project_model::{Edit, IoArea, IoDirection, ListEdit, Project, io_area_problems};

use super::field::DeviceEditorState;
use super::form::Form;
use super::{DeviceEdit, DeviceTexts, checked_edit};

/// Draws the settings of the I/O area at `index` of `project` and returns the edits of this
/// frame's gesture; nothing when there is no such area.
pub fn io_area_editor_ui(
    ui: &mut Ui,
    project: &Project,
    index: usize,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
) -> Option<DeviceEdit> {
    let area = project.io_areas.get(index)?;
    state.follow(area);
    let node = area.name.as_str();
    let areas = &project.io_areas;
    let problems = |area: &IoArea| io_area_problems(areas, Some(index), area);
    let change = |label: String, item: IoArea| {
        checked_edit(label, area, item, problems, |item| {
            Edit::IoAreas(ListEdit::Replace { index, item })
        })
    };
    let directions = [
        (texts.inputs.clone(), IoDirection::Input),
        (texts.outputs.clone(), IoDirection::Output),
        (texts.markers.clone(), IoDirection::Memory),
    ];
    let letter = area.direction.area_letter();
    let last = (u64::from(area.start_byte) + u64::from(area.size_bytes)).saturating_sub(1);
    let span = format!("%{letter}B{} … %{letter}B{last}", area.start_byte);
    let mut form = Form::node(state, texts, area, node, &change);
    form.grid_ui(ui, ("io area editor", index), |form, ui| {
        form.field("direction", &texts.direction, 120.0).combo_ui(
            ui,
            area.direction,
            &directions,
            |item, direction| item.direction = direction,
        );
        form.field("start", &texts.start_byte, 80.0)
            .suffix(&span)
            .whole_ui(ui, area.start_byte, 0..=u32::MAX, |item, start| {
                item.start_byte = start;
            });
        form.field("size", &texts.size, 80.0)
            .suffix(&texts.bytes)
            .whole_ui(ui, area.size_bytes, 0..=u32::MAX, |item, size| {
                item.size_bytes = size;
            });
        form.field("comment", &texts.comment, 320.0)
            .text_ui(ui, &area.comment, |item, comment| item.comment = comment);
    });
    form.finish()
}
