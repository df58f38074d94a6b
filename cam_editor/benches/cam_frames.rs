//! Frame time of the cam editor on a 10,000-point cam while a key point is dragged, headless in
//! an egui context: each frame moves the pointer, lays the editor out and tessellates the
//! shapes. Criterion measures the mean; a second pass of 400 frames prints the median and the
//! 95th percentile. Run with `cargo bench -p cam_editor`.

#![allow(missing_docs)] // criterion_group! writes an undocumented function.
#![allow(clippy::print_stderr)] // The percentile report is the point of the second pass.
#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed benchmark.

use std::hint::black_box;
use std::time::Instant;

use cam_editor::{CamEditor, CamEditorTexts};
use criterion::{Criterion, criterion_group, criterion_main};
use egui::{Context, Event, PointerButton, Pos2, RawInput, Rect, pos2, vec2};
use project_model::{CamProfile, CamTable, CamTablePoint, PointInterpolation};

/// The number of points of the benchmark's cam.
const POINTS: usize = 10_000;

/// A cubic point table of `POINTS` rows over 0 to 360 degrees: a sine with a ripple, so every
/// pixel column holds key points of different heights.
fn big_cam() -> CamTable {
    let mut cam = CamTable::codesys_default("Big");
    let points = (0..POINTS)
        .map(|i| {
            let master = 360.0 * i as f64 / (POINTS - 1) as f64;
            let radians = master.to_radians();
            CamTablePoint {
                master,
                slave: 180.0 * (1.0 - radians.cos()) + 2.0 * (radians * 50.0).sin(),
            }
        })
        .collect();
    cam.profile = CamProfile::Points {
        interpolation: PointInterpolation::Cubic,
        points,
    };
    cam
}

/// One frame with `events`: layout and tessellation, as a renderer would ask for.
fn frame(ctx: &Context, editor: &mut CamEditor, cam: &CamTable, events: Vec<Event>) {
    let texts = CamEditorTexts::default();
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(pos2(0.0, 0.0), vec2(1000.0, 900.0))),
        events,
        ..RawInput::default()
    };
    let mut output = ctx.run_ui(input, |ui| {
        let output = editor.show(ui, cam, None, &texts, false);
        black_box(output.edit);
    });
    let shapes = std::mem::take(&mut output.shapes);
    let meshes = ctx.tessellate(shapes, output.pixels_per_point);
    black_box(meshes.len());
    // No renderer takes the font atlas updates; egui insists they are handled or cleared.
    output.textures_delta.clear();
}

fn button(pos: Pos2, pressed: bool) -> Event {
    Event::PointerButton {
        pos,
        button: PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::NONE,
    }
}

/// A context and an editor with key point 5,000 grabbed and moved a little.
fn dragging(cam: &CamTable) -> (Context, CamEditor, Pos2) {
    let ctx = Context::default();
    let mut editor = CamEditor::new();
    for _ in 0..3 {
        frame(&ctx, &mut editor, cam, Vec::new());
    }
    let at = editor
        .key_point_screen_pos(cam, POINTS / 2)
        .expect("the middle key point is drawn");
    frame(&ctx, &mut editor, cam, vec![Event::PointerMoved(at)]);
    frame(&ctx, &mut editor, cam, vec![button(at, true)]);
    for step in 1..=5 {
        let to = at + vec2(0.0, step as f32 * 2.0);
        frame(&ctx, &mut editor, cam, vec![Event::PointerMoved(to)]);
    }
    assert!(editor.is_dragging_key_point(), "the drag did not start");
    (ctx, editor, at + vec2(0.0, 10.0))
}

fn benchmarks(c: &mut Criterion) {
    let cam = big_cam();
    let (ctx, mut editor, grabbed) = dragging(&cam);
    let mut step = 0u32;
    c.bench_function("drag a key point (10,000-point cam)", |b| {
        b.iter(|| {
            step += 1;
            let to = grabbed + vec2(0.0, (step % 40) as f32 - 20.0);
            frame(&ctx, &mut editor, &cam, vec![Event::PointerMoved(to)]);
        });
    });

    let (ctx, mut editor, grabbed) = dragging(&cam);
    let mut times_ms: Vec<f64> = (0..400)
        .map(|step| {
            let to = grabbed + vec2(0.0, (step % 40) as f32 - 20.0);
            let start = Instant::now();
            frame(&ctx, &mut editor, &cam, vec![Event::PointerMoved(to)]);
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    assert!(editor.is_dragging_key_point(), "the drag ended");
    times_ms.sort_by(f64::total_cmp);
    let at = |percent: usize| times_ms[(times_ms.len() * percent / 100).min(times_ms.len() - 1)];
    eprintln!(
        "drag frame of a {POINTS}-point cam: median {:.2} ms, 95th percentile {:.2} ms \
         (10th {:.2}, 25th {:.2}, 75th {:.2}, 90th {:.2}, max {:.2})",
        at(50),
        at(95),
        at(10),
        at(25),
        at(75),
        at(90),
        at(100)
    );
}

criterion_group!(benches, benchmarks);
criterion_main!(benches);
