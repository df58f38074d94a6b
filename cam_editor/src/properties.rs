//! The cam's properties, edited in place as in the CODESYS properties dialog: master and slave
//! ranges and units, period, continuity requirements and compile format. A value that is not a
//! number or leaves a range empty is refused with the reason and never applied.

use egui::{Grid, Ui};
use project_model::{CamCompileFormat, CamRange, CamTable};
use thiserror::Error;

use crate::cam_edit::{CamEditError, key_points, set_key_point};
use crate::convert::{Curve, curve_of};
use crate::editor::{Frame, Gesture};
use crate::number_field::{Drafts, number_text, parse_number};
use crate::texts::CamEditorTexts;

/// The number of elements a table format starts with (the predefined CODESYS tables hold 128
/// or 256).
const DEFAULT_ELEMENTS: u32 = 256;

/// Draws the properties of `frame.cam`; a committed field or a changed choice gives the gesture.
pub(crate) fn properties_ui(
    ui: &mut Ui,
    drafts: &mut Drafts,
    frame: &Frame<'_>,
) -> Option<Gesture> {
    let texts = frame.texts;
    let cam = frame.cam;
    let mut gesture = None;
    Grid::new(("cam properties", &cam.name))
        .num_columns(4)
        .spacing([12.0, 6.0])
        .show(ui, |ui| {
            for is_master in [true, false] {
                let axis = if is_master {
                    &texts.master
                } else {
                    &texts.slave
                };
                let range = if is_master { &cam.master } else { &cam.slave };
                ui.strong(axis);
                for (which, word) in [(0, &texts.start), (1, &texts.end)] {
                    let label = format!("{axis} {word}");
                    let value = if which == 0 { range.start } else { range.end };
                    if let Some(text) =
                        drafts.field_ui(ui, &label, &number_text(value), 90.0, frame.read_only)
                    {
                        match range_edit(cam, is_master, which == 0, &text, texts) {
                            Ok(changed) => gesture = Some(Gesture::edit(label, changed)),
                            Err(reason) => drafts.refuse(&label, text, reason.to_string()),
                        }
                    }
                }
                let label = format!("{axis} {}", texts.unit);
                if let Some(text) = drafts.field_ui(ui, &label, &range.unit, 60.0, frame.read_only)
                {
                    let mut changed = cam.clone();
                    let target = if is_master {
                        &mut changed.master
                    } else {
                        &mut changed.slave
                    };
                    target.unit = text.trim().to_owned();
                    gesture = Some(Gesture::edit(label, changed));
                }
                ui.end_row();
            }
        });
    ui.add_space(8.0);
    ui.add_enabled_ui(!frame.read_only, |ui| {
        ui.strong(&texts.period);
        let mut smooth = cam.period.smooth_transition;
        if ui.checkbox(&mut smooth, &texts.smooth_transition).changed() {
            let mut changed = cam.clone();
            changed.period.smooth_transition = smooth;
            gesture = Some(Gesture::edit(texts.smooth_transition.clone(), changed));
        }
        ui.horizontal(|ui| {
            ui.label(&texts.slave_period);
            let label = texts.slave_period.clone();
            let shown = cam.period.slave_period.map(number_text).unwrap_or_default();
            if let Some(text) = drafts.field_ui(ui, &label, &shown, 90.0, frame.read_only) {
                let trimmed = text.trim();
                if trimmed.is_empty() {
                    let mut changed = cam.clone();
                    changed.period.slave_period = None;
                    gesture = Some(Gesture::edit(label, changed));
                } else {
                    match parse_number(trimmed).filter(|period| *period != 0.0) {
                        Some(period) => {
                            let mut changed = cam.clone();
                            changed.period.slave_period = Some(period);
                            gesture = Some(Gesture::edit(label, changed));
                        }
                        None => {
                            let reason = format!("\"{trimmed}\" {}", texts.not_a_number);
                            drafts.refuse(&label, text, reason);
                        }
                    }
                }
            }
        });
        ui.add_space(8.0);
        ui.strong(&texts.continuity);
        ui.horizontal(|ui| {
            let flags = cam.continuity;
            let mut values = [
                flags.position,
                flags.velocity,
                flags.acceleration,
                flags.jerk,
            ];
            let names = [
                &texts.position,
                &texts.velocity,
                &texts.acceleration,
                &texts.jerk,
            ];
            let mut toggled = None;
            for (index, name) in names.into_iter().enumerate() {
                if ui.checkbox(&mut values[index], name).changed() {
                    toggled = Some(name);
                }
            }
            if let Some(name) = toggled {
                let mut changed = cam.clone();
                let [position, velocity, acceleration, jerk] = values;
                changed.continuity = project_model::CamContinuity {
                    position,
                    velocity,
                    acceleration,
                    jerk,
                };
                gesture = Some(Gesture::edit(
                    format!("{} {name}", texts.continuity),
                    changed,
                ));
            }
        });
        ui.add_space(8.0);
        ui.strong(&texts.compile_format);
        let elements = match cam.compile_format {
            CamCompileFormat::Table1d { elements } | CamCompileFormat::Table2d { elements } => {
                elements
            }
            CamCompileFormat::Segments | CamCompileFormat::Xyva => DEFAULT_ELEMENTS,
        };
        ui.horizontal(|ui| {
            let choices = [
                (CamCompileFormat::Segments, &texts.format_segments),
                (CamCompileFormat::Xyva, &texts.format_xyva),
                (
                    CamCompileFormat::Table1d { elements },
                    &texts.format_table_1d,
                ),
                (
                    CamCompileFormat::Table2d { elements },
                    &texts.format_table_2d,
                ),
            ];
            for (format, text) in choices {
                let current =
                    std::mem::discriminant(&format) == std::mem::discriminant(&cam.compile_format);
                if ui.radio(current, text).clicked() && !current {
                    gesture = Some(format_edit(cam, format, text));
                }
            }
        });
        if matches!(
            cam.compile_format,
            CamCompileFormat::Table1d { .. } | CamCompileFormat::Table2d { .. }
        ) {
            ui.horizontal(|ui| {
                ui.label(&texts.elements);
                let label = texts.elements.clone();
                if let Some(text) =
                    drafts.field_ui(ui, &label, &elements.to_string(), 90.0, frame.read_only)
                {
                    match text.trim().parse::<u32>() {
                        Ok(count) if count >= 2 => {
                            let mut changed = cam.clone();
                            changed.compile_format = match cam.compile_format {
                                CamCompileFormat::Table2d { .. } => {
                                    CamCompileFormat::Table2d { elements: count }
                                }
                                _ => CamCompileFormat::Table1d { elements: count },
                            };
                            gesture = Some(Gesture::edit(label, changed));
                        }
                        Ok(_) => {
                            drafts.refuse(&label, text, texts.too_few_elements.clone());
                        }
                        Err(_) => {
                            let reason = format!("\"{}\" {}", text.trim(), texts.not_an_integer);
                            drafts.refuse(&label, text, reason);
                        }
                    }
                }
            });
        }
    });
    gesture
}

/// Why a range end typed into the properties was refused. The texts are the editor's, already in
/// the user's language, so the refusal reads as it is shown.
#[derive(Debug, Error)]
enum RangeEditError {
    /// The text is not a number.
    #[error("\"{text}\" {not_a_number}")]
    NotANumber {
        /// The typed text, trimmed.
        text: String,
        /// The translated "is not a number".
        not_a_number: String,
    },
    /// The start would not be below the end; the translated reason.
    #[error("{0}")]
    StartNotBelowEnd(String),
    /// The cam has no key point to hold the master range end; the translated reason.
    #[error("{0}")]
    InvalidCam(String),
    /// Moving the key point would leave an invalid cam.
    #[error(transparent)]
    Edit(#[from] CamEditError),
}

/// The cam with one end of the master or slave range set from `text`. The master range's ends
/// are the first and the last key point, so they move too, and the cam must stay valid.
fn range_edit(
    cam: &CamTable,
    is_master: bool,
    is_start: bool,
    text: &str,
    texts: &CamEditorTexts,
) -> Result<CamTable, RangeEditError> {
    let value = parse_number(text).ok_or_else(|| RangeEditError::NotANumber {
        text: text.trim().to_owned(),
        not_a_number: texts.not_a_number.clone(),
    })?;
    let range = if is_master { &cam.master } else { &cam.slave };
    let (start, end) = if is_start {
        (value, range.end)
    } else {
        (range.start, value)
    };
    if start >= end {
        return Err(RangeEditError::StartNotBelowEnd(
            texts.start_not_below_end.clone(),
        ));
    }
    if !is_master {
        let mut changed = cam.clone();
        changed.slave = CamRange {
            start,
            end,
            unit: cam.slave.unit.clone(),
        };
        return Ok(changed);
    }
    let points = key_points(cam);
    let index = if is_start {
        0
    } else {
        points.len().saturating_sub(1)
    };
    let Some(point) = points.get(index) else {
        return Err(RangeEditError::InvalidCam(texts.invalid_cam.clone()));
    };
    let moved = project_model::CamKeyPoint {
        master: value,
        ..*point
    };
    Ok(set_key_point(cam, index, moved)?)
}

/// The cam with another compile format. XYVA holds only Line and Poly5 segments, so a cam with
/// another law is refused with motion's message naming the segment.
fn format_edit(cam: &CamTable, format: CamCompileFormat, label: &str) -> Gesture {
    let mut changed = cam.clone();
    changed.compile_format = format;
    if format == CamCompileFormat::Xyva
        && let Ok(Curve::Segmented(curve)) = curve_of(cam)
        && let Err(error) = curve.xyva_points()
    {
        return Gesture::Refused(label.to_owned(), error.to_string());
    }
    Gesture::edit(label.to_owned(), changed)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;

    #[test]
    fn a_refused_range_end_names_the_text_or_the_reason() {
        let cam = CamTable::codesys_default("Cam");
        let texts = CamEditorTexts::default();
        let refused = range_edit(&cam, true, true, " 12x ", &texts).unwrap_err();
        assert_eq!(refused.to_string(), "\"12x\" is not a number");
        let refused = range_edit(&cam, false, true, "1e9", &texts).unwrap_err();
        assert_eq!(refused.to_string(), "the start must be below the end");
        let changed = range_edit(&cam, false, false, "1e9", &texts).unwrap();
        assert_eq!(changed.slave.end, 1e9);
    }
}
