//! The editor of an I/O area: its direction, start byte, size and comment, with overlaps with
//! the other areas of its direction refused in place.

use egui::Ui;
use project_model::{Edit, IoArea, IoDirection, ListEdit, Project, io_area_problems};

use super::field::{DeviceEditorState, FieldId, combo_ui, parse_whole, row_ui, text_field_ui};
use super::{DeviceEdit, DeviceTexts, field_label, keep, refuse_new, set_label};

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
    let set = |field: &str, value: &str, item: IoArea| {
        refuse_new(
            io_area_problems(areas, Some(index), area),
            io_area_problems(areas, Some(index), &item),
        )?;
        Ok(DeviceEdit {
            label: set_label(texts, field, node, value),
            edits: vec![Edit::IoAreas(ListEdit::Replace { index, item })],
        })
    };
    let directions = [
        (texts.inputs.clone(), IoDirection::Input),
        (texts.outputs.clone(), IoDirection::Output),
        (texts.markers.clone(), IoDirection::Memory),
    ];
    let letter = area.direction.area_letter();
    let mut out = None;
    egui::Grid::new(("io area editor", index))
        .num_columns(2)
        .spacing([12.0, 6.0])
        .show(ui, |ui| {
            let label = field_label(texts, &texts.direction, node);
            let field = FieldId {
                key: "direction",
                label: &label,
                width: 120.0,
            };
            row_ui(ui, &texts.direction, |ui| {
                keep(
                    &mut out,
                    combo_ui(
                        ui,
                        state,
                        texts,
                        field,
                        area.direction,
                        &directions,
                        |direction| {
                            let name = directions
                                .iter()
                                .find(|(_, value)| *value == direction)
                                .map(|(text, _)| text.as_str())
                                .unwrap_or_default();
                            set(
                                &texts.direction,
                                name,
                                IoArea {
                                    direction,
                                    ..area.clone()
                                },
                            )
                        },
                    ),
                );
            });
            let label = field_label(texts, &texts.start_byte, node);
            let field = FieldId {
                key: "start",
                label: &label,
                width: 80.0,
            };
            let last = (u64::from(area.start_byte) + u64::from(area.size_bytes)).saturating_sub(1);
            let span = format!("%{letter}B{} … %{letter}B{last}", area.start_byte);
            row_ui(ui, &texts.start_byte, |ui| {
                let current = area.start_byte.to_string();
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &current, &span, |text| {
                        let start_byte = parse_whole(text, 0u32, u32::MAX)?;
                        set(
                            &texts.start_byte,
                            text,
                            IoArea {
                                start_byte,
                                ..area.clone()
                            },
                        )
                    }),
                );
            });
            let label = field_label(texts, &texts.size, node);
            let field = FieldId {
                key: "size",
                label: &label,
                width: 80.0,
            };
            row_ui(ui, &texts.size, |ui| {
                let current = area.size_bytes.to_string();
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &current, &texts.bytes, |text| {
                        let size_bytes = parse_whole(text, 0u32, u32::MAX)?;
                        set(
                            &texts.size,
                            text,
                            IoArea {
                                size_bytes,
                                ..area.clone()
                            },
                        )
                    }),
                );
            });
            let label = field_label(texts, &texts.comment, node);
            let field = FieldId {
                key: "comment",
                label: &label,
                width: 320.0,
            };
            row_ui(ui, &texts.comment, |ui| {
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &area.comment, "", |text| {
                        set(
                            &texts.comment,
                            text,
                            IoArea {
                                comment: text.to_owned(),
                                ..area.clone()
                            },
                        )
                    }),
                );
            });
        });
    out
}
