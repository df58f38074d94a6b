//! LD compile speed: `cargo bench -p compiler --bench ladder`.
//!
//! Builds one program of 10,000 LD networks (series and parallel contacts, edge contacts,
//! set, reset and normal coils, a timer box every tenth network) and prints the median times
//! of lowering it, of checking it and of compiling it into an image (check included).
//! Issue 14 asks for the compile under 1 s.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::time::{Duration, Instant};

use compiler::SourceProject;
use project_model::{
    BlockCall, BlockInput, BlockOutput, Body, Branch, Coil, CoilKind, Edge, ElementId, FlowNode,
    Network, NetworkOutput, Object, Operand, Parallel, Project,
};

const NETWORKS: usize = 10_000;

fn contact(id: &mut u32, text: String, negated: bool, edge: Edge) -> FlowNode {
    *id += 1;
    FlowNode::Operand(Operand {
        id: ElementId(*id),
        text,
        negated,
        edge,
    })
}

fn coil(id: &mut u32, variable: String, kind: CoilKind) -> NetworkOutput {
    *id += 1;
    NetworkOutput::Coil(Coil {
        id: ElementId(*id),
        variable,
        kind,
    })
}

/// Network `n`: `x[n] AND (y[n] OR NOT z[n]) AND P(e[n])`, a timer on every tenth, driving a
/// coil, a set and a reset coil.
fn network(n: usize, id: &mut u32) -> Network {
    let at = n % 100;
    let mut rung = vec![contact(id, format!("x[{at}]"), false, Edge::None)];
    *id += 1;
    let parallel = *id;
    rung.push(FlowNode::Parallel(Parallel {
        id: ElementId(parallel),
        branches: vec![
            Branch {
                rung: vec![contact(id, format!("y[{at}]"), false, Edge::None)],
            },
            Branch {
                rung: vec![contact(id, format!("z[{at}]"), true, Edge::None)],
            },
        ],
    }));
    if n.is_multiple_of(3) {
        rung.push(contact(id, format!("e[{at}]"), false, Edge::Rising));
    }
    if n.is_multiple_of(10) {
        *id += 1;
        let block = *id;
        let pt = contact(id, "T#100ms".to_owned(), false, Edge::None);
        rung.push(FlowNode::Block(BlockCall {
            id: ElementId(block),
            type_name: "TON".into(),
            instance: format!("t[{at}]"),
            inputs: vec![
                BlockInput {
                    pin: "IN".into(),
                    ..BlockInput::default()
                },
                BlockInput {
                    pin: "PT".into(),
                    source: vec![pt],
                    ..BlockInput::default()
                },
            ],
            outputs: vec![
                BlockOutput {
                    pin: "Q".into(),
                    ..BlockOutput::default()
                },
                BlockOutput {
                    pin: "ET".into(),
                    ..BlockOutput::default()
                },
            ],
        }));
    }
    let outputs = vec![
        coil(id, format!("q[{at}]"), CoilKind::Normal),
        coil(id, format!("s[{at}]"), CoilKind::Set),
        coil(id, format!("r[{at}]"), CoilKind::Reset),
    ];
    Network {
        rung,
        outputs,
        ..Network::default()
    }
}

fn project() -> Project {
    let source = "PROGRAM Main
VAR x, y, z, e, q, s, r : ARRAY[0..99] OF BOOL; t : ARRAY[0..99] OF TON; END_VAR
END_PROGRAM
";
    let mut project = SourceProject::new(source).project;
    let mut id = 0;
    let networks = (0..NETWORKS).map(|n| network(n, &mut id)).collect();
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = Body::Ld { networks };
    }
    project
}

fn median(runs: usize, mut work: impl FnMut()) -> Duration {
    let mut times: Vec<Duration> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            work();
            start.elapsed()
        })
        .collect();
    times.sort();
    times[runs / 2]
}

fn main() {
    let project = project();
    let image = compiler::compile_project(&project).expect("the networks compile");
    let instructions: usize = image.pous.iter().map(|pou| pou.code.len()).sum();
    let lower = median(5, || {
        std::hint::black_box(compiler::lower::lower_project(&project));
    });
    let check = median(5, || {
        std::hint::black_box(compiler::sema::check_project(&project));
    });
    let compile = median(5, || {
        std::hint::black_box(compiler::compile_project(&project).is_ok());
    });
    println!(
        "ladder: {NETWORKS} LD networks ({instructions} instructions): lower {:.1} ms, lower + check {:.1} ms, compile (lower + check + code) {:.1} ms (target < 1000 ms)",
        lower.as_secs_f64() * 1e3,
        check.as_secs_f64() * 1e3,
        compile.as_secs_f64() * 1e3,
    );
}
