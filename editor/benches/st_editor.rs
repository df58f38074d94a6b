//! Frame time of the Structured Text editor on a 20,000-line POU, headless in an egui context:
//! a frame that scrolls to a new place, a frame that types one character, and a scrolling
//! frame with 500 inline values; and of the diagram editor on a 500-network LD body while an
//! element is dragged over it (`diagram_frames`); and of the CFC editor on a 300-element chart
//! while a box is dragged (`cfc_frames`). Run with `cargo bench -p editor`.

#![allow(missing_docs)] // criterion_group! writes an undocumented function.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};

#[path = "st_editor/cfc_frames.rs"]
mod cfc_frames;
#[path = "st_editor/diagram_frames.rs"]
mod diagram_frames;
use editor::{InlineValue, KeywordCompletions, StEditor};
use egui::{Context, Event, RawInput, Rect, pos2, vec2};

/// The number of lines of the benchmark's POU body.
const LINES: usize = 20_000;

/// A body of `LINES` lines: assignments, comments with Chinese text and IF blocks.
fn long_body() -> String {
    let mut text = String::with_capacity(LINES * 48);
    let mut line = 0;
    while line < LINES {
        let i = line;
        text.push_str(&format!("IF counter_{i} > {i} THEN // 计数 {i}\n"));
        for j in 0..8 {
            text.push_str(&format!(
                "    counter_{i} := counter_{i} + {j}; (* step {j} *) motor_{j}.speed := 1.5;\n"
            ));
        }
        text.push_str("END_IF;\n");
        line += 10;
    }
    text
}

fn input(events: Vec<Event>, time_s: Option<f64>) -> RawInput {
    RawInput {
        screen_rect: Some(Rect::from_min_size(pos2(0.0, 0.0), vec2(1280.0, 900.0))),
        events,
        time: time_s,
        ..RawInput::default()
    }
}

fn frame(ctx: &Context, editor: &mut StEditor, events: Vec<Event>) {
    frame_at(ctx, editor, events, None);
}

/// A frame at egui time `time_s`, or 1/60 s after the last one.
fn frame_at(ctx: &Context, editor: &mut StEditor, events: Vec<Event>, time_s: Option<f64>) {
    let mut output = ctx.run_ui(input(events, time_s), |ui| {
        let output = editor.show(ui, "Body", &KeywordCompletions);
        black_box(output.changes);
    });
    black_box(output.shapes.len());
    // No renderer takes the font atlas updates; egui insists they are handled or cleared.
    output.textures_delta.clear();
}

/// A context and an editor that has taken focus, with the caret at `line`.
fn setup(text: &str, line_offset: usize) -> (Context, StEditor) {
    let ctx = Context::default();
    let mut editor = StEditor::new(text);
    editor.reveal(line_offset..line_offset);
    editor.request_focus();
    for _ in 0..3 {
        frame(&ctx, &mut editor, Vec::new());
    }
    (ctx, editor)
}

fn line_starts(text: &str) -> Vec<usize> {
    std::iter::once(0)
        .chain(text.match_indices('\n').map(|(at, _)| at + 1))
        .collect()
}

fn benchmarks(c: &mut Criterion) {
    let text = long_body();
    let starts = line_starts(&text);

    let (ctx, mut editor) = setup(&text, starts[LINES / 2]);
    let mut at = 0usize;
    c.bench_function("scroll to a new place (20k lines)", |b| {
        b.iter(|| {
            at = (at + 997) % LINES;
            editor.reveal(starts[at]..starts[at]);
            frame(&ctx, &mut editor, Vec::new());
        });
    });

    let (ctx, mut editor) = setup(&text, starts[LINES / 2] + 4);
    c.bench_function("type a character (20k lines)", |b| {
        b.iter(|| frame(&ctx, &mut editor, vec![Event::Text("a".to_owned())]));
    });

    // Typing pauses: one frame types, the next comes 0.2 s later and parses again; only the
    // second is timed.
    let (ctx, mut editor) = setup(&text, starts[LINES / 2] + 4);
    let mut time_s = 100.0;
    c.bench_function("re-parse after typing pauses (20k lines)", |b| {
        b.iter_custom(|iterations| {
            let mut total = Duration::ZERO;
            for _ in 0..iterations {
                time_s += 0.2;
                frame_at(
                    &ctx,
                    &mut editor,
                    vec![Event::Text("a".to_owned())],
                    Some(time_s),
                );
                time_s += 0.2;
                let start = Instant::now();
                frame_at(&ctx, &mut editor, Vec::new(), Some(time_s));
                total += start.elapsed();
            }
            total
        });
    });

    let (ctx, mut editor) = setup(&text, starts[1000]);
    let values: Vec<InlineValue> = (1000..1500)
        .map(|line| {
            let start = starts[line];
            let name = text[start..]
                .find("counter_")
                .map_or(start, |at| start + at);
            let end = text[name..].find(' ').map_or(name, |at| name + at);
            InlineValue {
                range: name..end,
                text: format!("{line}"),
                changed: line % 3 == 0,
                forced: line % 7 == 0,
            }
        })
        .collect();
    editor.set_inline_values(values);
    let mut at = 1000usize;
    c.bench_function("scroll with 500 inline values (20k lines)", |b| {
        b.iter(|| {
            at = if at >= 1480 { 1000 } else { at + 3 };
            editor.reveal(starts[at]..starts[at]);
            frame(&ctx, &mut editor, Vec::new());
        });
    });
}

criterion_group!(
    benches,
    benchmarks,
    diagram_frames::benchmarks,
    cfc_frames::benchmarks
);
criterion_main!(benches);
