//! Frame time of the CFC editor on a 300-element chart while a box is dragged: every frame
//! takes the model's chart (as the app hands it over), moves the pointer, routes again the
//! wires of the dragged box for its new place and paints the elements and wires in view.
//! Prints the median and the 95th percentile of the frame times; the target is under
//! 8 ms.

#![allow(clippy::print_stdout)] // The percentiles are the report of a bench binary.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::Criterion;
use editor::{BlockSignature, CfcEditor, CompletionItem, DiagramServices};
use egui::{Context, Event, Modifiers, PointerButton, Pos2, RawInput, Rect, pos2, vec2};
use project_model::{
    CfcBox, CfcChart, CfcElement, CfcElementKind, CfcPin, CoilKind, ElementId, PinRef, Wire,
};

/// The number of groups of four elements (two inputs, an ADD box, an output).
const GROUPS: u32 = 75;
/// Groups per row of the chart.
const GROUPS_PER_ROW: u32 = 5;

/// Services that know nothing: dragging asks them nothing.
struct NoServices;

impl DiagramServices for NoServices {
    fn variables(&self, _prefix: &str) -> Vec<CompletionItem> {
        Vec::new()
    }

    fn blocks(&self, _prefix: &str) -> Vec<CompletionItem> {
        Vec::new()
    }

    fn structure_members(&self, _type_name: &str) -> Option<Vec<String>> {
        None
    }

    fn signature(&self, _type_name: &str) -> Option<BlockSignature> {
        None
    }

    fn is_declared(&self, _name: &str) -> bool {
        true
    }
}

/// 300 elements: groups of `a_i + b_i -> y_i`, five groups a row, each output feeding the
/// next group's first input through its variable, so wires are short and realistic.
fn chart() -> CfcChart {
    let mut chart = CfcChart::default();
    let pin = |name: &str| CfcPin {
        name: name.to_owned(),
        ..CfcPin::default()
    };
    for group in 0..GROUPS {
        let (x, y) = (
            (group % GROUPS_PER_ROW) as i32 * 44,
            (group / GROUPS_PER_ROW) as i32 * 10,
        );
        let first = group * 4;
        let place = |offset: u32, dx: i32, dy: i32, order: Option<u32>, kind| CfcElement {
            id: ElementId(first + offset),
            x: x + dx,
            y: y + dy,
            order,
            kind,
        };
        chart.elements.extend([
            place(
                0,
                0,
                2,
                None,
                CfcElementKind::Input {
                    expression: format!("speed_{group}"),
                },
            ),
            place(
                1,
                0,
                5,
                None,
                CfcElementKind::Input {
                    expression: format!("offset_{group}"),
                },
            ),
            place(
                2,
                16,
                0,
                Some(group * 2),
                CfcElementKind::Box(CfcBox {
                    type_name: "ADD".to_owned(),
                    instance: String::new(),
                    inputs: vec![pin("IN1"), pin("IN2")],
                    outputs: vec![pin("OUT")],
                }),
            ),
            place(
                3,
                30,
                2,
                Some(group * 2 + 1),
                CfcElementKind::Output {
                    expression: format!("setpoint_{group}"),
                    coil: CoilKind::Normal,
                },
            ),
        ]);
        let wire = |from: u32, from_pin: &str, to: u32, to_pin: &str| Wire {
            from: PinRef {
                element: ElementId(first + from),
                pin: from_pin.to_owned(),
            },
            to: PinRef {
                element: ElementId(first + to),
                pin: to_pin.to_owned(),
            },
            points: Vec::new(),
        };
        chart.wires.extend([
            wire(0, "", 2, "IN1"),
            wire(1, "", 2, "IN2"),
            wire(2, "OUT", 3, ""),
        ]);
    }
    chart
}

fn input(events: Vec<Event>) -> RawInput {
    RawInput {
        screen_rect: Some(Rect::from_min_size(pos2(0.0, 0.0), vec2(1280.0, 900.0))),
        events,
        ..RawInput::default()
    }
}

/// Runs one frame, tessellated as a real one is.
fn frame(ctx: &Context, editor: &mut CfcEditor, chart: &CfcChart, events: Vec<Event>) {
    let mut output = ctx.run_ui(input(events), |ui| {
        // The app hands the model's chart over every frame.
        editor.set_chart(chart);
        let output = editor.show(ui, "Body", &NoServices);
        black_box(output.change);
    });
    output.textures_delta.clear();
    black_box(ctx.tessellate(std::mem::take(&mut output.shapes), output.pixels_per_point));
}

fn button(pos: Pos2, pressed: bool) -> Event {
    Event::PointerButton {
        pos,
        button: PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    }
}

/// The frame-time benchmark of the CFC editor.
pub fn benchmarks(c: &mut Criterion) {
    let chart = chart();
    assert_eq!(chart.elements.len(), 300);
    let ctx = Context::default();
    let mut editor = CfcEditor::new(&chart);
    for _ in 0..3 {
        frame(&ctx, &mut editor, &chart, Vec::new());
    }
    // The box of the second group of the second row, well inside the view: its frame is
    // 16 grid units right of its group and 12 points a unit, past the 154-point toolbox.
    let grab = pos2(154.0 + (44.0 + 19.0) * 12.0, 30.0 + (10.0 + 3.0) * 12.0);
    frame(&ctx, &mut editor, &chart, vec![Event::PointerMoved(grab)]);
    frame(&ctx, &mut editor, &chart, vec![button(grab, true)]);
    let path: Vec<Pos2> = (0..40)
        .map(|step| {
            let step = step as f32;
            grab + vec2((step * 37.0) % 240.0 - 120.0, (step * 23.0) % 160.0 - 80.0)
        })
        .collect();
    frame(
        &ctx,
        &mut editor,
        &chart,
        vec![Event::PointerMoved(path[1])],
    );
    assert_eq!(
        editor.selection().elements,
        vec![ElementId(GROUPS_PER_ROW * 4 + 4 + 2)],
        "the press took the box"
    );
    let mut at = 0;
    let mut samples = Vec::new();
    c.bench_function("drag a box over a 300-element CFC", |b| {
        b.iter_custom(|iterations| {
            let mut total = Duration::ZERO;
            for _ in 0..iterations {
                at = (at + 1) % path.len();
                let start = Instant::now();
                frame(
                    &ctx,
                    &mut editor,
                    &chart,
                    vec![Event::PointerMoved(path[at])],
                );
                let elapsed = start.elapsed();
                samples.push(elapsed);
                total += elapsed;
            }
            total
        });
    });
    // Still dragging: the release would have changed the chart.
    frame(&ctx, &mut editor, &chart, vec![button(path[at], false)]);
    assert!(
        samples.is_empty() || editor.chart() != &chart,
        "the drag ended during the benchmark"
    );
    samples.sort();
    let percentile = |p: usize| samples.get(samples.len() * p / 100).copied();
    if let (Some(p50), Some(p95)) = (percentile(50), percentile(95)) {
        println!(
            "CFC editor, 300 elements, dragging a box: frame time median {:.3} ms, 95th percentile {:.3} ms over {} frames",
            p50.as_secs_f64() * 1000.0,
            p95.as_secs_f64() * 1000.0,
            samples.len()
        );
    }
}
