//! The cam table: rows alternate key point (X, Y, V, A, J) and segment (law and the derived
//! minimum and maximum position, maximum velocity and acceleration), as in the CODESYS cam
//! table; a point table shows its (X, Y) rows and its interpolation.

use egui::{ComboBox, Role, Ui, WidgetInfo};
use egui_extras::{Column, TableBuilder};
use project_model::{CamKeyPoint, CamProfile, CamTable, MotionLaw, PointInterpolation};

use crate::cam_edit::{delete_key_point, insert_key_point, key_points, set_key_point, set_law};
use crate::editor::{CurveView, Frame, Gesture};
use crate::number_field::{Drafts, number_text, parse_number, rounded_text};

/// Every law the model knows, in the order the law menu lists them.
const LAWS: [MotionLaw; 9] = [
    MotionLaw::Line,
    MotionLaw::Poly3,
    MotionLaw::Poly5,
    MotionLaw::Poly7,
    MotionLaw::ModifiedSine,
    MotionLaw::ModifiedTrapezoid,
    MotionLaw::Cycloid,
    MotionLaw::SimpleHarmonic,
    MotionLaw::InclinedSine,
];

/// The height of a table row in points.
const ROW_HEIGHT: f32 = 24.0;

/// A column of key points: its header, how to read it and how to write it.
type KeyColumn = (
    &'static str,
    fn(&CamKeyPoint) -> f64,
    fn(&mut CamKeyPoint, f64),
);

/// The five columns of a key point.
const KEY_COLUMNS: [KeyColumn; 5] = [
    ("X", |p| p.master, |p, v| p.master = v),
    ("Y", |p| p.slave, |p, v| p.slave = v),
    ("V", |p| p.velocity, |p, v| p.velocity = v),
    ("A", |p| p.acceleration, |p, v| p.acceleration = v),
    ("J", |p| p.jerk, |p, v| p.jerk = v),
];

/// Draws the table of `frame.cam`; a committed cell, a law chosen or a row inserted or deleted
/// gives the gesture.
pub(crate) fn table_ui(
    ui: &mut Ui,
    drafts: &mut Drafts,
    frame: &Frame<'_>,
    view: &mut CurveView,
) -> Option<Gesture> {
    match &frame.cam.profile {
        CamProfile::Segments { .. } => segments_ui(ui, drafts, frame, view),
        CamProfile::Points { interpolation, .. } => points_ui(ui, drafts, frame, *interpolation),
    }
}

fn segments_ui(
    ui: &mut Ui,
    drafts: &mut Drafts,
    frame: &Frame<'_>,
    view: &mut CurveView,
) -> Option<Gesture> {
    let texts = frame.texts;
    let cam = frame.cam;
    let points = key_points(cam);
    let laws: Vec<MotionLaw> = match &cam.profile {
        CamProfile::Segments { segments, .. } => segments.iter().map(|s| s.law).collect(),
        CamProfile::Points { .. } => Vec::new(),
    };
    let bounds = if view.cam == *cam {
        view.bounds().to_vec()
    } else {
        Vec::new()
    };
    let mut gesture = None;
    let rows = points.len() + laws.len();
    let law_header = capitalized(&texts.law);
    // The table is wider than a narrow document tab; it scrolls sideways rather than hiding
    // the derived columns and the insert buttons.
    egui::ScrollArea::horizontal()
        .id_salt(("cam table scroll", &cam.name))
        .show(ui, |ui| {
            TableBuilder::new(ui)
                .id_salt(("cam table", &cam.name))
                .striped(true)
                .column(Column::auto().at_least(90.0))
                .columns(Column::initial(60.0).at_least(44.0).resizable(true), 5)
                .column(Column::auto().at_least(120.0))
                .columns(Column::initial(76.0).at_least(56.0), 4)
                .column(Column::remainder().at_least(30.0))
                .header(ROW_HEIGHT, |mut header| {
                    let titles = [
                        "",
                        "X",
                        "Y",
                        "V",
                        "A",
                        "J",
                        law_header.as_str(),
                        texts.min_position.as_str(),
                        texts.max_position.as_str(),
                        texts.max_velocity.as_str(),
                        texts.max_acceleration.as_str(),
                        "",
                    ];
                    for title in titles {
                        header.col(|ui| {
                            ui.strong(title);
                        });
                    }
                })
                .body(|body| {
                    body.rows(ROW_HEIGHT, rows, |mut row| {
                        let row_index = row.index();
                        let item = row_index / 2;
                        if row_index % 2 == 0 {
                            let point = points[item];
                            let name = format!("{} {}", texts.key_point, item + 1);
                            row.col(|ui| {
                                ui.label(&name);
                            });
                            for (header, read, write) in KEY_COLUMNS {
                                row.col(|ui| {
                                    let label = format!("{name} {header}");
                                    let shown = number_text(read(&point));
                                    if let Some(text) = drafts.field_ui(
                                        ui,
                                        &label,
                                        &shown,
                                        f32::INFINITY,
                                        frame.read_only,
                                    ) {
                                        gesture = Some(match parse_number(&text) {
                                            Some(value) => {
                                                let mut changed = point;
                                                write(&mut changed, value);
                                                match set_key_point(cam, item, changed) {
                                                    Ok(cam) => Gesture::edit(label, cam),
                                                    Err(error) => {
                                                        drafts.refuse(
                                                            &label,
                                                            text,
                                                            error.to_string(),
                                                        );
                                                        return;
                                                    }
                                                }
                                            }
                                            None => {
                                                let reason =
                                                    format!("\"{text}\" {}", texts.not_a_number);
                                                drafts.refuse(&label, text, reason);
                                                return;
                                            }
                                        });
                                    }
                                });
                            }
                            for _ in 0..5 {
                                row.col(|_| {});
                            }
                            row.col(|ui| {
                                let inner = item > 0 && item + 1 < points.len();
                                if inner && !frame.read_only {
                                    let label = format!("{} {}", texts.delete_key_point, item + 1);
                                    let button = ui.small_button("×").on_hover_text(&label);
                                    button.widget_info(|| {
                                        WidgetInfo::labeled(Role::Button, true, &label)
                                    });
                                    if button.clicked() {
                                        gesture = outcome(label, delete_key_point(cam, item));
                                    }
                                }
                            });
                        } else {
                            let name = format!("{} {}", texts.segment, item + 1);
                            row.col(|ui| {
                                ui.label(&name);
                            });
                            for _ in 0..5 {
                                row.col(|_| {});
                            }
                            row.col(|ui| {
                                let label = format!("{name} {}", texts.law);
                                let current = laws[item];
                                let mut chosen = None;
                                ui.add_enabled_ui(!frame.read_only, |ui| {
                                    let combo = ComboBox::from_id_salt(("cam law", item))
                                        .selected_text(format!("{current:?}"))
                                        .width(ui.available_width())
                                        .show_ui(ui, |ui| {
                                            for law in LAWS {
                                                if ui
                                                    .selectable_label(
                                                        law == current,
                                                        format!("{law:?}"),
                                                    )
                                                    .clicked()
                                                    && law != current
                                                {
                                                    chosen = Some(law);
                                                }
                                            }
                                        });
                                    combo.response.widget_info(|| {
                                        WidgetInfo::labeled(
                                            Role::ComboBox,
                                            !frame.read_only,
                                            &label,
                                        )
                                    });
                                });
                                if let Some(law) = chosen {
                                    gesture = outcome(label, set_law(cam, item, law));
                                }
                            });
                            let values = bounds.get(item).map(|b| {
                                [
                                    b.min_position,
                                    b.max_position,
                                    b.max_abs_velocity,
                                    b.max_abs_acceleration,
                                ]
                            });
                            for column in 0..4 {
                                row.col(|ui| {
                                    if let Some(values) = values {
                                        ui.monospace(rounded_text(values[column]));
                                    }
                                });
                            }
                            row.col(|ui| {
                                if !frame.read_only {
                                    let label = format!("{} {}", texts.insert_key_point, item + 1);
                                    let button = ui.small_button("+").on_hover_text(&label);
                                    button.widget_info(|| {
                                        WidgetInfo::labeled(Role::Button, true, &label)
                                    });
                                    if button.clicked() {
                                        gesture = outcome(label, insert_key_point(cam, item));
                                    }
                                }
                            });
                        }
                    });
                });
        });
    gesture
}

/// `text` with its first letter in upper case, for a column header made of a label word.
fn capitalized(text: &str) -> String {
    let mut chars = text.chars();
    match chars.next() {
        Some(first) => first.to_uppercase().chain(chars).collect(),
        None => String::new(),
    }
}

fn points_ui(
    ui: &mut Ui,
    drafts: &mut Drafts,
    frame: &Frame<'_>,
    interpolation: PointInterpolation,
) -> Option<Gesture> {
    let texts = frame.texts;
    let cam = frame.cam;
    let mut gesture = None;
    ui.horizontal(|ui| {
        ui.label(&texts.interpolation);
        ui.add_enabled_ui(!frame.read_only, |ui| {
            for (choice, text) in [
                (PointInterpolation::Linear, &texts.linear),
                (PointInterpolation::Cubic, &texts.cubic),
            ] {
                if ui.radio(interpolation == choice, text).clicked() && interpolation != choice {
                    let mut changed = cam.clone();
                    if let CamProfile::Points { interpolation, .. } = &mut changed.profile {
                        *interpolation = choice;
                    }
                    gesture = Some(Gesture::edit(texts.interpolation.clone(), changed));
                }
            }
        });
    });
    let points = key_points(cam);
    TableBuilder::new(ui)
        .id_salt(("cam points", &cam.name))
        .striped(true)
        .column(Column::auto().at_least(70.0))
        .columns(Column::initial(100.0).at_least(60.0).resizable(true), 2)
        .column(Column::remainder().at_least(60.0))
        .header(ROW_HEIGHT, |mut header| {
            for title in ["", "X", "Y", ""] {
                header.col(|ui| {
                    ui.strong(title);
                });
            }
        })
        .body(|body| {
            body.rows(ROW_HEIGHT, points.len(), |mut row| {
                let index = row.index();
                let point = points[index];
                let name = format!("{} {}", texts.row, index + 1);
                row.col(|ui| {
                    ui.label(&name);
                });
                for (header, read, write) in &KEY_COLUMNS[..2] {
                    row.col(|ui| {
                        let label = format!("{name} {header}");
                        if let Some(text) = drafts.field_ui(
                            ui,
                            &label,
                            &number_text(read(&point)),
                            f32::INFINITY,
                            frame.read_only,
                        ) {
                            match parse_number(&text) {
                                Some(value) => {
                                    let mut changed = point;
                                    write(&mut changed, value);
                                    match set_key_point(cam, index, changed) {
                                        Ok(cam) => gesture = Some(Gesture::edit(label, cam)),
                                        Err(error) => {
                                            drafts.refuse(&label, text, error.to_string())
                                        }
                                    }
                                }
                                None => {
                                    let reason = format!("\"{text}\" {}", texts.not_a_number);
                                    drafts.refuse(&label, text, reason);
                                }
                            }
                        }
                    });
                }
                row.col(|ui| {
                    if frame.read_only {
                        return;
                    }
                    if index + 1 < points.len() {
                        let label = format!("{} {}", texts.insert_key_point, index + 1);
                        let button = ui.small_button("+").on_hover_text(&label);
                        button.widget_info(|| WidgetInfo::labeled(Role::Button, true, &label));
                        if button.clicked() {
                            gesture = outcome(label, insert_key_point(cam, index));
                        }
                    }
                    if points.len() > 2 {
                        let label = format!("{} {}", texts.delete_key_point, index + 1);
                        let button = ui.small_button("×").on_hover_text(&label);
                        button.widget_info(|| WidgetInfo::labeled(Role::Button, true, &label));
                        if button.clicked() {
                            gesture = outcome(label, delete_key_point(cam, index));
                        }
                    }
                });
            });
        });
    gesture
}

/// A changed cam as an edit, or its error as a refusal of the control `label`.
fn outcome(label: String, result: Result<CamTable, crate::CamEditError>) -> Option<Gesture> {
    Some(match result {
        Ok(cam) => Gesture::edit(label, cam),
        Err(error) => Gesture::Refused(label, error.to_string()),
    })
}
