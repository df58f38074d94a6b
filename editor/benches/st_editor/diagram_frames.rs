//! Frame time of the diagram editor on a 500-network LD body while a toolbox element is dragged
//! over it: every frame takes the model's networks (as the app hands them over), moves the
//! pointer, finds the nearest insertion point and paints the networks in view with their "+"
//! marks. Prints the 95th percentile of the frame times, the
//! figure the target (under 8 ms) is about.

#![allow(clippy::print_stdout)] // The percentiles are the report of a bench binary.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::Criterion;
use editor::{
    BlockSignature, CompletionItem, DiagramEditor, DiagramServices, DiagramView, ToolboxItem,
};
use egui::{Context, DragAndDrop, Event, RawInput, Rect, pos2, vec2};
use project_model::{
    BlockCall, BlockInput, BlockOutput, Branch, Coil, CoilKind, ElementId, FlowNode, Network,
    NetworkOutput, Operand, Parallel,
};

/// The number of networks of the benchmark's body.
const NETWORKS: usize = 500;

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

/// A rung of a real interlock: three contacts, a parallel latch, a timer and two coils.
fn network(index: usize, next_id: &mut u32) -> Network {
    let mut id = || {
        *next_id += 1;
        ElementId(*next_id)
    };
    let contact = |id: ElementId, text: String, negated: bool| {
        FlowNode::Operand(Operand {
            id,
            text,
            negated,
            ..Operand::default()
        })
    };
    Network {
        title: format!("Step {index}"),
        comment: format!("Interlock of station {index}"),
        rung: vec![
            contact(id(), format!("start_{index}"), false),
            contact(id(), format!("guard_closed_{index}"), false),
            FlowNode::Parallel(Parallel {
                id: id(),
                branches: vec![
                    Branch {
                        rung: vec![contact(id(), format!("manual_{index}"), false)],
                    },
                    Branch {
                        rung: vec![
                            contact(id(), format!("running_{index}"), false),
                            contact(id(), format!("stop_{index}"), true),
                        ],
                    },
                ],
            }),
            FlowNode::Block(BlockCall {
                id: id(),
                type_name: "TON".to_owned(),
                instance: format!("delay_{index}"),
                inputs: vec![
                    BlockInput {
                        pin: "IN".to_owned(),
                        ..BlockInput::default()
                    },
                    BlockInput {
                        pin: "PT".to_owned(),
                        source: vec![contact(id(), "T#2S".to_owned(), false)],
                        ..BlockInput::default()
                    },
                ],
                outputs: vec![
                    BlockOutput {
                        pin: "Q".to_owned(),
                        ..BlockOutput::default()
                    },
                    BlockOutput {
                        pin: "ET".to_owned(),
                        assign: format!("elapsed_{index}"),
                        ..BlockOutput::default()
                    },
                ],
            }),
        ],
        outputs: vec![
            NetworkOutput::Coil(Coil {
                id: id(),
                variable: format!("running_{index}"),
                kind: CoilKind::Normal,
            }),
            NetworkOutput::Coil(Coil {
                id: id(),
                variable: format!("done_{index}"),
                kind: CoilKind::Set,
            }),
        ],
        ..Network::default()
    }
}

fn input(events: Vec<Event>) -> RawInput {
    RawInput {
        screen_rect: Some(Rect::from_min_size(pos2(0.0, 0.0), vec2(1280.0, 900.0))),
        events,
        ..RawInput::default()
    }
}

/// Runs one frame; returns the number of shapes it painted.
fn frame(ctx: &Context, editor: &mut DiagramEditor, events: Vec<Event>) -> usize {
    let mut output = ctx.run_ui(input(events), |ui| {
        let output = editor.show(ui, "Body", &NoServices);
        black_box(output.change);
    });
    // No renderer takes the font atlas updates; egui insists they are handled or cleared.
    output.textures_delta.clear();
    let shapes = output.shapes.len();
    // A real frame also turns the shapes into triangles; that cost belongs to the figure.
    black_box(ctx.tessellate(std::mem::take(&mut output.shapes), output.pixels_per_point));
    black_box(shapes)
}

/// The pointer's positions over the canvas, visited in turn.
fn pointer_path() -> Vec<egui::Pos2> {
    (0..40)
        .map(|step| {
            let step = step as f32;
            pos2(200.0 + (step * 97.0) % 900.0, 60.0 + (step * 53.0) % 800.0)
        })
        .collect()
}

/// The frame-time benchmarks of the diagram editor.
pub fn benchmarks(c: &mut Criterion) {
    let mut next_id = 0;
    let body: Vec<Network> = (0..NETWORKS)
        .map(|index| network(index, &mut next_id))
        .collect();
    let ctx = Context::default();
    let mut editor = DiagramEditor::new(&body, DiagramView::Ladder);
    // Half-way down the body, so networks above and below exist.
    let middle = body[NETWORKS / 2].rung[0].id();
    editor.reveal(middle);
    for _ in 0..3 {
        frame(&ctx, &mut editor, Vec::new());
    }
    // The payload the toolbox's drag source sets while the user drags a contact.
    DragAndDrop::set_payload(&ctx, ToolboxItem::Contact);
    let path = pointer_path();
    let resting = frame(&ctx, &mut editor, Vec::new());
    let dragging = frame(&ctx, &mut editor, vec![Event::PointerMoved(path[0])]);
    // The "+" marks of the networks in view are painted only while dragging.
    assert!(
        dragging > resting,
        "dragging painted {dragging} shapes, resting {resting}"
    );
    println!("shapes painted per frame: {resting} resting, {dragging} while dragging");
    let mut at = 0;
    let mut samples = Vec::new();
    c.bench_function("drag a contact over a 500-network LD body", |b| {
        b.iter_custom(|iterations| {
            let mut total = Duration::ZERO;
            for _ in 0..iterations {
                at = (at + 1) % path.len();
                let start = Instant::now();
                // The app hands the model's networks over every frame.
                editor.set_networks(&body);
                frame(&ctx, &mut editor, vec![Event::PointerMoved(path[at])]);
                let elapsed = start.elapsed();
                samples.push(elapsed);
                total += elapsed;
            }
            total
        });
    });
    assert!(
        DragAndDrop::has_payload_of_type::<ToolboxItem>(&ctx),
        "the drag ended during the benchmark"
    );
    report("dragging", samples);

    // A keyboard insertion in a network half-way down: the change, the network's new layout
    // and the frame that shows it.
    DragAndDrop::clear_payload(&ctx);
    let mut editor = DiagramEditor::new(&body, DiagramView::Ladder);
    editor.reveal(middle);
    editor.request_focus();
    for _ in 0..3 {
        frame(&ctx, &mut editor, Vec::new());
    }
    let mut samples = Vec::new();
    let ctrl_k = Event::Key {
        key: egui::Key::K,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers: egui::Modifiers::COMMAND,
    };
    c.bench_function("insert a contact by keyboard (500 networks)", |b| {
        b.iter_custom(|iterations| {
            let mut total = Duration::ZERO;
            for _ in 0..iterations {
                // Back to the original network now and then, so the rung stays realistic.
                if editor.networks()[NETWORKS / 2].rung.len() > 40 {
                    editor.set_networks(&body);
                    editor.reveal(middle);
                }
                let start = Instant::now();
                frame(&ctx, &mut editor, vec![ctrl_k.clone()]);
                let elapsed = start.elapsed();
                samples.push(elapsed);
                total += elapsed;
            }
            total
        });
    });
    // Criterion skips a benchmark its filter leaves out (`-- "LD body"`): nothing to check.
    assert!(
        samples.is_empty()
            || editor.networks()[NETWORKS / 2].rung.len() > body[NETWORKS / 2].rung.len(),
        "no contact was inserted"
    );
    report("inserting by keyboard", samples);
}

/// Prints the 95th percentile of `samples`.
fn report(what: &str, mut samples: Vec<Duration>) {
    samples.sort();
    if let Some(p95) = samples.get(samples.len() * 95 / 100) {
        println!(
            "diagram editor, 500 LD networks, {what}: 95th percentile frame time {:.3} ms over {} frames",
            p95.as_secs_f64() * 1000.0,
            samples.len()
        );
    }
}
