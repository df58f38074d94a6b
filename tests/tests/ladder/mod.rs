//! LD and FBD bodies compiled and run cycle after cycle: every element alone and in
//! combination, each checked against values computed here in Rust, and a property test that a
//! random network and the Structured Text a user would write for it agree on random inputs.
//!
//! The network is the body of a function block `Ld` with inputs `a`…`d`, outputs `q`, `r`,
//! `s` and a marker `m`; the program `Main` feeds it one element of each input array per
//! cycle and keeps its outputs in arrays, which are read after the run.

use std::collections::HashMap;

use program_image::ProgramImage;
use project_model::{
    BlockCall, BlockInput, BlockOutput, Body, Branch, Coil, CoilKind, Edge, ElementId, FlowNode,
    Network, NetworkOutput, Object, Operand, Parallel,
};
use proptest::prelude::*;
use runtime::simulation::Simulation;

const INPUTS: [&str; 4] = ["a", "b", "c", "d"];
const OUTPUTS: [&str; 4] = ["q", "r", "s", "m"];

/// The source of the block `name` with `body` (empty for a graphical body set later).
fn block_source(name: &str, body: &str, extra: &str) -> String {
    format!(
        "FUNCTION_BLOCK {name}
VAR_INPUT a, b, c, d : BOOL; END_VAR
VAR_OUTPUT q, r, s, m : BOOL; END_VAR
VAR x, y, n : INT; t : TON; {extra} END_VAR
{body}
END_FUNCTION_BLOCK
"
    )
}

/// The driver: one element of each input array per cycle into each block, their outputs
/// kept per cycle (`Main.<block>_<output>`).
fn driver(blocks: &[&str], inputs: &[Vec<bool>; 4]) -> String {
    let cycles = inputs[0].len();
    let mut declarations = String::new();
    let mut body = String::new();
    for (name, values) in INPUTS.iter().zip(inputs) {
        let list: Vec<&str> = values
            .iter()
            .map(|v| if *v { "TRUE" } else { "FALSE" })
            .collect();
        declarations.push_str(&format!(
            "i_{name} : ARRAY[0..{}] OF BOOL := [{}];\n",
            cycles - 1,
            list.join(", ")
        ));
    }
    for block in blocks {
        declarations.push_str(&format!("fb_{block} : {block};\n"));
        body.push_str(&format!(
            "fb_{block}(a := i_a[i], b := i_b[i], c := i_c[i], d := i_d[i]);\n"
        ));
        for output in OUTPUTS {
            declarations.push_str(&format!(
                "{block}_{output} : ARRAY[0..{}] OF BOOL;\n",
                cycles - 1
            ));
            body.push_str(&format!("{block}_{output}[i] := fb_{block}.{output};\n"));
        }
    }
    format!(
        "PROGRAM Main\nVAR\ni : INT;\n{declarations}END_VAR\nIF i < {cycles} THEN\n{body}i := i + 1;\nEND_IF;\nEND_PROGRAM\n"
    )
}

/// Compiles `source` with the block `Ld`'s body replaced by `networks`.
#[track_caller]
fn compile(source: &str, networks: Vec<Network>) -> ProgramImage {
    let built = compiler::SourceProject::new(source);
    assert!(
        built.parse.errors().is_empty(),
        "{:?}",
        built.parse.errors()
    );
    let mut project = built.project;
    if let Some(Object::Pou(ld)) = project.application.object_mut("Ld") {
        ld.body = Body::Ld { networks };
    }
    match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found
                .iter()
                .filter(|d| d.diagnostic.severity == compiler::Severity::Error)
                .map(|d| format!("{:?}: {}", d.element, d.diagnostic.message))
                .collect();
            panic!("the network does not check: {errors:#?}")
        }
        Err(error) => panic!("the network does not compile: {error}"),
    }
}

/// Runs the blocks over the input sequences and gives each `<block>_<output>` per cycle.
#[track_caller]
fn run(source: &str, networks: Vec<Network>, cycles: usize) -> HashMap<String, Vec<bool>> {
    let image = compile(source, networks);
    let simulation = crate::simulate(image, cycles as u64 + 1);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    let mut values = HashMap::new();
    for symbol in &simulation.engine().image().symbols {
        let Some(name) = symbol.path.strip_prefix("Main.") else {
            continue;
        };
        if !name.contains('_') || name.starts_with("fb_") || name.starts_with("i_") {
            continue;
        }
        let text = runtime::value::read(simulation.engine(), &symbol.path)
            .expect("readable")
            .to_string();
        let list = text
            .trim_matches(|c| c == '[' || c == ']')
            .split(", ")
            .map(|v| v == "TRUE")
            .collect();
        values.insert(name.to_owned(), list);
    }
    values
}

/// Runs the LD block `Ld` (declaring `extra`) over `inputs` and gives its outputs per cycle.
#[track_caller]
fn run_ld(
    networks: Vec<Network>,
    inputs: [Vec<bool>; 4],
    extra: &str,
) -> HashMap<String, Vec<bool>> {
    let source = format!(
        "{}{}",
        block_source("Ld", "", extra),
        driver(&["Ld"], &inputs)
    );
    run(&source, networks, inputs[0].len())
}

fn bits(text: &str) -> Vec<bool> {
    text.chars().map(|c| c == '1').collect()
}

fn contact(id: u32, text: &str, negated: bool, edge: Edge) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(id),
        text: text.into(),
        negated,
        edge,
    })
}

fn no(id: u32, text: &str) -> FlowNode {
    contact(id, text, false, Edge::None)
}

fn coil(id: u32, variable: &str, kind: CoilKind) -> NetworkOutput {
    NetworkOutput::Coil(Coil {
        id: ElementId(id),
        variable: variable.into(),
        kind,
    })
}

fn rung(nodes: Vec<FlowNode>, outputs: Vec<NetworkOutput>) -> Network {
    Network {
        rung: nodes,
        outputs,
        ..Network::default()
    }
}

fn input(pin: &str, source: Vec<FlowNode>) -> BlockInput {
    BlockInput {
        pin: pin.into(),
        source,
        ..BlockInput::default()
    }
}

fn output(pin: &str, assign: &str) -> BlockOutput {
    BlockOutput {
        pin: pin.into(),
        assign: assign.into(),
        ..BlockOutput::default()
    }
}

/// Every combination of `a`, `b`, `c`, `d` over 16 cycles.
fn all_combinations() -> [Vec<bool>; 4] {
    std::array::from_fn(|bit| (0..16).map(|cycle| cycle >> bit & 1 == 1).collect())
}

#[test]
fn series_and_parallel_contacts_and_negated_coils_follow_the_boolean_algebra() {
    let inputs = all_combinations();
    let networks = vec![rung(
        vec![
            no(1, "a"),
            FlowNode::Parallel(Parallel {
                id: ElementId(2),
                branches: vec![
                    Branch {
                        rung: vec![no(3, "b")],
                    },
                    Branch {
                        rung: vec![contact(4, "c", true, Edge::None), no(5, "d")],
                    },
                ],
            }),
        ],
        vec![
            coil(6, "q", CoilKind::Normal),
            coil(7, "r", CoilKind::Negated),
        ],
    )];
    let values = run_ld(networks, inputs.clone(), "");
    let expected: Vec<bool> = (0..16)
        .map(|i| inputs[0][i] && (inputs[1][i] || !inputs[2][i] && inputs[3][i]))
        .collect();
    assert_eq!(values["Ld_q"], expected);
    let negated: Vec<bool> = expected.iter().map(|v| !v).collect();
    assert_eq!(values["Ld_r"], negated);
}

#[test]
fn set_and_reset_coils_latch_and_the_later_one_wins() {
    // Network 1 sets q on a, network 2 resets it on b: when both, the reset (later) wins.
    // In one network, r is set then reset by the same power: reset wins, and s, set after
    // the reset, is still set (the power is not re-derived per coil).
    let a = bits("0110001000");
    let b = bits("0001101000");
    let inputs = [a.clone(), b.clone(), bits("0100000010"), vec![false; 10]];
    let networks = vec![
        rung(vec![no(1, "a")], vec![coil(2, "q", CoilKind::Set)]),
        rung(vec![no(3, "b")], vec![coil(4, "q", CoilKind::Reset)]),
        rung(
            vec![no(5, "c")],
            vec![
                coil(6, "r", CoilKind::Set),
                coil(7, "r", CoilKind::Reset),
                coil(8, "s", CoilKind::Set),
            ],
        ),
    ];
    let values = run_ld(networks, inputs, "");
    let mut q = false;
    let expected: Vec<bool> = (0..10)
        .map(|i| {
            if a[i] {
                q = true;
            }
            if b[i] {
                q = false;
            }
            q
        })
        .collect();
    assert_eq!(values["Ld_q"], expected);
    assert_eq!(values["Ld_r"], vec![false; 10]);
    assert_eq!(values["Ld_s"], bits("0111111111"));
}

#[test]
fn edge_contacts_see_edges_across_cycles_even_while_the_power_is_off() {
    // q: b AND P(a). a rises at cycle 1 while b is FALSE: that edge is consumed, so q stays
    // FALSE at cycle 2 (a short-circuiting evaluator would report it there).
    // r: N(c) alone; s: a P coil on d.
    let a = bits("0110111001");
    let b = bits("0011111111");
    let c = bits("1100110001");
    let d = bits("0110001101");
    let values = run_ld(
        vec![
            rung(
                vec![no(1, "b"), contact(2, "a", false, Edge::Rising)],
                vec![coil(3, "q", CoilKind::Normal)],
            ),
            rung(
                vec![contact(4, "c", false, Edge::Falling)],
                vec![coil(5, "r", CoilKind::Normal)],
            ),
            rung(vec![no(6, "d")], vec![coil(7, "s", CoilKind::Rising)]),
        ],
        [a.clone(), b.clone(), c.clone(), d.clone()],
        "",
    );
    let edge = |values: &[bool], rising: bool| -> Vec<bool> {
        let mut previous = false;
        values
            .iter()
            .map(|&v| {
                let fired = if rising {
                    v && !previous
                } else {
                    !v && previous
                };
                previous = v;
                fired
            })
            .collect()
    };
    let rising_a = edge(&a, true);
    let q: Vec<bool> = (0..10).map(|i| b[i] && rising_a[i]).collect();
    assert_eq!(values["Ld_q"], q);
    assert_eq!(values["Ld_r"], edge(&c, false));
    assert_eq!(values["Ld_s"], edge(&d, true));
}

#[test]
fn a_box_with_en_false_is_skipped_its_outputs_hold_and_its_eno_is_false() {
    // x := x + 1 runs only while a; q is the box's ENO; r is the timer's Q through EN.
    let a = bits("1101100111");
    let networks = vec![
        rung(
            vec![
                no(1, "a"),
                FlowNode::Block(BlockCall {
                    id: ElementId(2),
                    type_name: "ADD".into(),
                    instance: String::new(),
                    inputs: vec![
                        input("EN", vec![]),
                        input("IN1", vec![no(3, "x")]),
                        input("IN2", vec![no(4, "1")]),
                    ],
                    outputs: vec![output("ENO", "q"), output("OUT", "x")],
                }),
            ],
            vec![],
        ),
        rung(
            vec![FlowNode::Block(BlockCall {
                id: ElementId(5),
                type_name: "GE".into(),
                instance: String::new(),
                inputs: vec![
                    input("IN1", vec![no(6, "x")]),
                    input("IN2", vec![no(7, "3")]),
                ],
                outputs: vec![output("OUT", "")],
            })],
            vec![coil(8, "r", CoilKind::Normal)],
        ),
    ];
    let values = run_ld(
        networks,
        [a.clone(), vec![false; 10], vec![false; 10], vec![false; 10]],
        "",
    );
    assert_eq!(values["Ld_q"], a);
    let mut x = 0;
    let r: Vec<bool> = a
        .iter()
        .map(|&enabled| {
            if enabled {
                x += 1;
            }
            x >= 3
        })
        .collect();
    assert_eq!(values["Ld_r"], r);
}

#[test]
fn jumps_skip_networks_forwards_and_loop_backwards() {
    // Network 0: n := 0. Network 1 (label Again): n := n + 1. Network 2: jump back while
    // n < 3. Network 3: a jumps over network 4 (q toggles) to network 5 (label Done:
    // r := n = 3).
    let mut again = rung(
        vec![FlowNode::Block(BlockCall {
            id: ElementId(3),
            type_name: "ADD".into(),
            instance: String::new(),
            inputs: vec![
                input("IN1", vec![no(4, "n")]),
                input("IN2", vec![no(5, "1")]),
            ],
            outputs: vec![output("OUT", "n")],
        })],
        vec![],
    );
    again.label = "Again".into();
    let mut done = rung(vec![no(12, "n = 3")], vec![coil(13, "r", CoilKind::Normal)]);
    done.label = "Done".into();
    let networks = vec![
        rung(
            vec![FlowNode::Block(BlockCall {
                id: ElementId(1),
                type_name: "MOVE".into(),
                instance: String::new(),
                inputs: vec![input("IN", vec![no(2, "0")])],
                outputs: vec![output("OUT", "n")],
            })],
            vec![],
        ),
        again,
        rung(
            vec![no(6, "n < 3")],
            vec![NetworkOutput::Jump {
                id: ElementId(7),
                label: "Again".into(),
            }],
        ),
        rung(
            vec![no(8, "a")],
            vec![NetworkOutput::Jump {
                id: ElementId(9),
                label: "Done".into(),
            }],
        ),
        rung(vec![no(10, "q")], vec![coil(11, "q", CoilKind::Negated)]),
        done,
    ];
    let a = bits("10100110");
    let values = run_ld(
        networks,
        [a.clone(), vec![false; 8], vec![false; 8], vec![false; 8]],
        "",
    );
    let mut toggled = false;
    let q: Vec<bool> = a
        .iter()
        .map(|&skipped| {
            if !skipped {
                toggled = !toggled;
            }
            toggled
        })
        .collect();
    assert_eq!(values["Ld_q"], q);
    assert_eq!(values["Ld_r"], vec![true; 8]);
}

#[test]
fn several_coils_on_one_variable_write_in_order_and_a_return_ends_the_body() {
    // q is written by two networks: the later one's value stays. r is written twice in one
    // network, normal then negated: the negated (later) one stays. Network 3 returns on d, so
    // s := TRUE in network 4 only runs while d is FALSE.
    let inputs = all_combinations();
    let networks = vec![
        rung(vec![no(1, "a")], vec![coil(2, "q", CoilKind::Normal)]),
        rung(vec![no(3, "b")], vec![coil(4, "q", CoilKind::Normal)]),
        rung(
            vec![no(5, "c")],
            vec![
                coil(6, "r", CoilKind::Normal),
                coil(7, "r", CoilKind::Negated),
            ],
        ),
        rung(
            vec![no(8, "d")],
            vec![NetworkOutput::Return { id: ElementId(9) }],
        ),
        rung(vec![], vec![coil(10, "s", CoilKind::Normal)]),
    ];
    let values = run_ld(networks, inputs.clone(), "");
    assert_eq!(values["Ld_q"], inputs[1]);
    let not_c: Vec<bool> = inputs[2].iter().map(|v| !v).collect();
    assert_eq!(values["Ld_r"], not_c);
    // s keeps TRUE once written: it is only ever written TRUE.
    let mut s = false;
    let expected: Vec<bool> = inputs[3]
        .iter()
        .map(|&d| {
            s |= !d;
            s
        })
        .collect();
    assert_eq!(values["Ld_s"], expected);
}

#[test]
fn a_timer_box_in_a_rung_counts_the_task_s_time() {
    // The implicit task runs every 10 ms; t delays a by 30 ms.
    let a = bits("0111111001111");
    let networks = vec![rung(
        vec![
            no(1, "a"),
            FlowNode::Block(BlockCall {
                id: ElementId(2),
                type_name: "TON".into(),
                instance: "t".into(),
                inputs: vec![input("IN", vec![]), input("PT", vec![no(3, "T#30ms")])],
                outputs: vec![output("Q", ""), output("ET", "")],
            }),
        ],
        vec![coil(4, "q", CoilKind::Normal)],
    )];
    let n = a.len();
    let values = run_ld(
        networks,
        [a.clone(), vec![false; n], vec![false; n], vec![false; n]],
        "",
    );
    let mut on_for = 0;
    let expected: Vec<bool> = a
        .iter()
        .map(|&v| {
            on_for = if v { on_for + 1 } else { 0 };
            // The timer starts in the cycle a rises, so it has run 30 ms three cycles later.
            on_for > 3
        })
        .collect();
    assert_eq!(values["Ld_q"], expected);
}

// The property test: random networks of contacts, parallel groups and coils.

/// A random chain of contacts, counter boxes and parallel groups, `depth` levels of nesting
/// at most.
fn chain(depth: u32) -> BoxedStrategy<Vec<Node>> {
    let contact =
        (0..READ.len(), any::<bool>(), 0..4u8).prop_map(|(var, negated, edge)| Node::Contact {
            var,
            negated,
            edge: match edge {
                1 => Edge::Rising,
                2 => Edge::Falling,
                _ => Edge::None,
            },
        });
    let leaf = prop_oneof![4 => contact, 1 => Just(Node::Counter)];
    let node = if depth == 0 {
        leaf.boxed()
    } else {
        prop_oneof![
            3 => leaf,
            1 => proptest::collection::vec(chain(depth - 1), 2..4).prop_map(Node::Parallel),
        ]
        .boxed()
    };
    proptest::collection::vec(node, 1..4).boxed()
}

/// A generated element, turned into both the network and the ST a user writes.
#[derive(Clone, Debug)]
enum Node {
    /// A contact on `READ[var]`.
    Contact {
        var: usize,
        negated: bool,
        edge: Edge,
    },
    /// An ADD box with EN counting `x` up while enabled; its ENO passes the power on.
    Counter,
    /// Branches in parallel.
    Parallel(Vec<Vec<Node>>),
}

const READ: [&str; 6] = ["a", "b", "c", "d", "m", "x > 3"];
const WRITTEN: [&str; 4] = ["q", "r", "s", "m"];

fn coil_kind(index: u8) -> CoilKind {
    match index % 6 {
        0 => CoilKind::Normal,
        1 => CoilKind::Negated,
        2 => CoilKind::Set,
        3 => CoilKind::Reset,
        4 => CoilKind::Rising,
        _ => CoilKind::Falling,
    }
}

/// Builds the model network and the user's ST for it, numbering ids, trigger instances and
/// the BOOLs the ST keeps its intermediate results in.
struct Writer {
    next_id: u32,
    declarations: Vec<String>,
    statements: String,
}

impl Writer {
    fn id(&mut self) -> ElementId {
        self.next_id += 1;
        ElementId(self.next_id)
    }

    /// A new BOOL of the ST, set to `value` here.
    fn store(&mut self, value: &str) -> String {
        let name = format!("v{}", self.declarations.len());
        self.declarations.push(format!("{name} : BOOL;"));
        self.statements.push_str(&format!("{name} := {value};\n"));
        name
    }

    fn trigger(&mut self, edge: Edge, clock: &str) -> String {
        let name = format!("tr{}", self.declarations.len());
        let ty = if edge == Edge::Rising {
            "R_TRIG"
        } else {
            "F_TRIG"
        };
        self.declarations.push(format!("{name} : {ty};"));
        self.statements
            .push_str(&format!("{name}(CLK := {clock});\n"));
        format!("{name}.Q")
    }

    /// The chain as model nodes, and the ST expression of the power at its end given the
    /// power `incoming` at its start (statements for boxes and branches written on the way).
    fn chain(&mut self, nodes: &[Node], incoming: String) -> (Vec<FlowNode>, String) {
        let mut flow = Vec::new();
        let mut power = incoming;
        for node in nodes {
            match node {
                Node::Contact { var, negated, edge } => {
                    let id = self.id();
                    flow.push(contact(id.0, READ[*var], *negated, *edge));
                    let mut term = format!("({})", READ[*var]);
                    if *edge != Edge::None {
                        term = self.trigger(*edge, &term);
                    }
                    if *negated {
                        term = format!("NOT {term}");
                    }
                    power = format!("({power}) AND {term}");
                }
                Node::Counter => {
                    let id = self.id();
                    let (one, count) = (self.id(), self.id());
                    flow.push(FlowNode::Block(BlockCall {
                        id,
                        type_name: "ADD".into(),
                        instance: String::new(),
                        inputs: vec![
                            input("EN", vec![]),
                            input("IN1", vec![no(count.0, "x")]),
                            input("IN2", vec![no(one.0, "1")]),
                        ],
                        outputs: vec![output("ENO", ""), output("OUT", "x")],
                    }));
                    let enable = self.store(&power);
                    self.statements
                        .push_str(&format!("IF {enable} THEN x := x + 1; END_IF;\n"));
                    power = enable;
                }
                Node::Parallel(branches) => {
                    let id = self.id();
                    let start = self.store(&power);
                    let mut model = Vec::new();
                    let mut ored = Vec::new();
                    for branch in branches {
                        let (rung, end) = self.chain(branch, start.clone());
                        model.push(Branch { rung });
                        ored.push(self.store(&end));
                    }
                    flow.push(FlowNode::Parallel(Parallel {
                        id,
                        branches: model,
                    }));
                    power = ored.join(" OR ");
                }
            }
        }
        (flow, power)
    }

    /// One network: the power into a variable of its own, then each coil.
    fn network(&mut self, nodes: &[Node], coils: &[(usize, u8)]) -> Network {
        let (flow, power) = self.chain(nodes, "TRUE".to_owned());
        let p = self.store(&power);
        let mut outputs = Vec::new();
        for (variable, kind) in coils {
            let id = self.id();
            let variable = WRITTEN[*variable];
            let kind = coil_kind(*kind);
            outputs.push(coil(id.0, variable, kind));
            let statement = match kind {
                CoilKind::Normal => format!("{variable} := {p};\n"),
                CoilKind::Negated => format!("{variable} := NOT {p};\n"),
                CoilKind::Set => format!("IF {p} THEN {variable} := TRUE; END_IF;\n"),
                CoilKind::Reset => format!("IF {p} THEN {variable} := FALSE; END_IF;\n"),
                CoilKind::Rising | CoilKind::Falling => {
                    let edge = if kind == CoilKind::Rising {
                        Edge::Rising
                    } else {
                        Edge::Falling
                    };
                    let pulse = self.trigger(edge, &p);
                    format!("{variable} := {pulse};\n")
                }
            };
            self.statements.push_str(&statement);
        }
        rung(flow, outputs)
    }
}

type Generated = (Vec<(Vec<Node>, Vec<(usize, u8)>)>, [Vec<bool>; 4]);

fn generated() -> impl Strategy<Value = Generated> {
    let networks = proptest::collection::vec(
        (
            chain(2),
            proptest::collection::vec((0..4usize, 0..6u8), 1..4),
        ),
        1..4,
    );
    let inputs = proptest::array::uniform4(proptest::collection::vec(any::<bool>(), 12));
    (networks, inputs)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn a_random_network_and_the_st_a_user_writes_for_it_agree(generated in generated()) {
        let (networks, inputs) = generated;
        let mut writer = Writer {
            next_id: 0,
            declarations: Vec::new(),
            statements: String::new(),
        };
        let model: Vec<Network> = networks
            .iter()
            .map(|(nodes, coils)| writer.network(nodes, coils))
            .collect();
        let extra = writer.declarations.join(" ");
        let source = format!(
            "{}{}{}",
            block_source("Ld", "", ""),
            block_source("St", &writer.statements, &extra),
            driver(&["Ld", "St"], &inputs)
        );
        let values = run(&source, model, inputs[0].len());
        for output in OUTPUTS {
            prop_assert_eq!(
                &values[&format!("Ld_{output}")],
                &values[&format!("St_{output}")],
                "{} differs; the ST:\n{}", output, writer.statements
            );
        }
    }
}

/// `FUNCTION Both` (a AND b), the action `Counter.Tick` (count + 1 on a rising `pulse`,
/// through an ADD box with EN) and the method `Counter.Reset` (MOVE 0 into count when `now`,
/// returning `now` as its result), all drawn in LD, run from an ST program.
fn members_project(cycles: u64) -> Simulation {
    let source = "FUNCTION Both : BOOL VAR_INPUT a, b : BOOL; END_VAR END_FUNCTION
FUNCTION_BLOCK Counter VAR_INPUT pulse : BOOL; END_VAR VAR_OUTPUT count : INT; END_VAR
METHOD Reset : BOOL VAR_INPUT now : BOOL; END_VAR END_METHOD
ACTION Tick: END_ACTION
END_FUNCTION_BLOCK
PROGRAM Main VAR c : Counter; i : INT; ab : BOOL; r : BOOL; END_VAR
i := i + 1;
c.pulse := (i MOD 2) = 0;
c.Tick();
r := c.Reset(now := i = 7);
ab := Both(a := i > 2, b := i < 5);
END_PROGRAM
";
    let mut project = compiler::SourceProject::new(source).project;
    if let Some(Object::Pou(both)) = project.application.object_mut("Both") {
        both.body = Body::Ld {
            networks: vec![rung(
                vec![no(1, "a"), no(2, "b")],
                vec![coil(3, "Both", CoilKind::Normal)],
            )],
        };
    }
    let Some(Object::Pou(counter)) = project.application.object_mut("Counter") else {
        panic!("no Counter");
    };
    counter.actions[0].body = Body::Ld {
        networks: vec![rung(
            vec![
                contact(1, "pulse", false, Edge::Rising),
                FlowNode::Block(BlockCall {
                    id: ElementId(2),
                    type_name: "ADD".into(),
                    instance: String::new(),
                    inputs: vec![
                        input("EN", vec![]),
                        input("IN1", vec![no(3, "count")]),
                        input("IN2", vec![no(4, "1")]),
                    ],
                    outputs: vec![output("ENO", ""), output("OUT", "count")],
                }),
            ],
            vec![],
        )],
    };
    counter.methods[0].body = Body::Ld {
        networks: vec![rung(
            vec![
                no(1, "now"),
                FlowNode::Block(BlockCall {
                    id: ElementId(2),
                    type_name: "MOVE".into(),
                    instance: String::new(),
                    inputs: vec![input("EN", vec![]), input("IN", vec![no(3, "0")])],
                    outputs: vec![output("ENO", ""), output("OUT", "count")],
                }),
            ],
            vec![coil(4, "Reset", CoilKind::Normal)],
        )],
    };
    let image = match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(error) => panic!("{error}: {error:?}"),
    };
    let simulation = crate::simulate(image, cycles);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    simulation
}

#[test]
fn functions_methods_and_actions_drawn_in_ld_run_like_their_st() {
    let read = |simulation: &Simulation, path: &str| {
        runtime::value::read(simulation.engine(), path)
            .unwrap()
            .to_string()
    };
    // Cycle 3: Both(3 > 2, 3 < 5); one rising pulse (cycle 2) counted.
    let early = members_project(3);
    assert_eq!(read(&early, "Main.ab"), "TRUE");
    assert_eq!(read(&early, "Main.c.count"), "1");
    // Pulses rise at cycles 2, 4, 6 (count 3), the reset at 7 clears it, then 8 and 10 count.
    let late = members_project(10);
    assert_eq!(read(&late, "Main.ab"), "FALSE");
    assert_eq!(read(&late, "Main.c.count"), "2");
    assert_eq!(read(&late, "Main.r"), "FALSE");
    let at_reset = members_project(7);
    assert_eq!(read(&at_reset, "Main.r"), "TRUE");
    assert_eq!(read(&at_reset, "Main.c.count"), "0");
}

#[test]
fn fbd_pins_negate_and_detect_edges_and_functions_nest() {
    // q := AND(IN1 := NOT a, IN2 := R_TRIG(b)); y := SEL(G := c, IN0 := 10, IN1 := MAX(x, 3))
    // with x counting cycles; r := GT(y, 4), the SEL box chained into the GT box.
    let a = bits("0010011000");
    let b = bits("0110101101");
    let c = bits("1100110011");
    let and_box = FlowNode::Block(BlockCall {
        id: ElementId(1),
        type_name: "AND".into(),
        instance: String::new(),
        inputs: vec![
            BlockInput {
                pin: "IN1".into(),
                negated: true,
                source: vec![no(2, "a")],
                ..BlockInput::default()
            },
            BlockInput {
                pin: "IN2".into(),
                edge: Edge::Rising,
                source: vec![no(3, "b")],
                ..BlockInput::default()
            },
        ],
        outputs: vec![output("OUT", "")],
    });
    let max_box = FlowNode::Block(BlockCall {
        id: ElementId(7),
        type_name: "MAX".into(),
        instance: String::new(),
        inputs: vec![
            input("IN1", vec![no(8, "x")]),
            input("IN2", vec![no(9, "3")]),
        ],
        outputs: vec![output("OUT", "")],
    });
    let sel_box = FlowNode::Block(BlockCall {
        id: ElementId(5),
        type_name: "SEL".into(),
        instance: String::new(),
        inputs: vec![
            input("G", vec![no(6, "c")]),
            input("IN0", vec![no(10, "10")]),
            input("IN1", vec![max_box]),
        ],
        outputs: vec![output("OUT", "y")],
    });
    let count = rung(
        vec![FlowNode::Block(BlockCall {
            id: ElementId(12),
            type_name: "ADD".into(),
            instance: String::new(),
            inputs: vec![
                input("IN1", vec![no(13, "x")]),
                input("IN2", vec![no(14, "1")]),
            ],
            outputs: vec![output("OUT", "x")],
        })],
        vec![],
    );
    let networks = vec![
        rung(vec![and_box], vec![coil(4, "q", CoilKind::Normal)]),
        count,
        rung(
            vec![
                sel_box,
                FlowNode::Block(BlockCall {
                    id: ElementId(11),
                    type_name: "GT".into(),
                    instance: String::new(),
                    inputs: vec![input("IN1", vec![]), input("IN2", vec![no(16, "4")])],
                    outputs: vec![output("OUT", "")],
                }),
            ],
            vec![coil(15, "r", CoilKind::Normal)],
        ),
    ];
    let source = format!(
        "{}{}",
        block_source("Ld", "", ""),
        driver(&["Ld"], &[a.clone(), b.clone(), c.clone(), vec![false; 10]])
    );
    let built = compiler::SourceProject::new(&source);
    let mut project = built.project;
    if let Some(Object::Pou(ld)) = project.application.object_mut("Ld") {
        ld.body = Body::Fbd { networks };
    }
    let image = match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(error) => panic!("{error}: {error:?}"),
    };
    let simulation = crate::simulate(image, 11);
    let read = |path: &str| -> Vec<bool> {
        let text = runtime::value::read(simulation.engine(), path)
            .unwrap()
            .to_string();
        text.trim_matches(|ch| ch == '[' || ch == ']')
            .split(", ")
            .map(|v| v == "TRUE")
            .collect()
    };
    let mut previous = false;
    let q: Vec<bool> = (0..10)
        .map(|i| {
            let rising = b[i] && !previous;
            previous = b[i];
            !a[i] && rising
        })
        .collect();
    assert_eq!(read("Main.Ld_q"), q);
    // The SEL value is assigned to y and flows on into GT's first input.
    let r: Vec<bool> = (0..10)
        .map(|i| {
            let x = i as i32 + 1;
            let y = if c[i] { x.max(3) } else { 10 };
            y > 4
        })
        .collect();
    assert_eq!(read("Main.Ld_r"), r);
}

/// Sets the located BOOL or REAL at `path` in `simulation`, as the I/O or a peer would.
fn set_value(simulation: &mut Simulation, path: &str, value: f64) {
    let place =
        runtime::value::resolve(simulation.engine().image(), path).expect("the path resolves");
    let region = simulation.engine_mut().region_mut(place.region);
    let offset = usize::try_from(place.offset).expect("an offset in memory");
    match place.bit {
        Some(bit) => {
            let mask = 1u8 << bit;
            if value != 0.0 {
                region[offset] |= mask;
            } else {
                region[offset] &= !mask;
            }
        }
        None => {
            #[allow(clippy::cast_possible_truncation)]
            let bytes = (value as f32).to_le_bytes();
            region[offset..offset + 4].copy_from_slice(&bytes);
        }
    }
}

/// The example project's ladder interlock and FBD scaling, run as its tasks run them: the
/// start button latches the request, the horn sounds for the two seconds of the TON, then the
/// belt is enabled; stop resets the request; the FBD program scales and limits the belt speed.
#[test]
fn the_example_project_s_ladder_and_fbd_programs_run_in_its_tasks() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../assets/examples/packaging_machine");
    let loaded = project_model::load_project(&dir).expect("the example loads");
    let image = match compiler::compile_project(&loaded.project) {
        Ok(image) => image,
        Err(error) => panic!("{error}"),
    };
    // The example under both engines first, compared after each of 1,000 cycles without
    // inputs; the checks below write between runs, on the default engine.
    crate::simulate(image.clone(), 1000);
    let mut simulation = Simulation::new(image).expect("the image loads");
    let read = |simulation: &Simulation, path: &str| {
        runtime::value::read(simulation.engine(), path)
            .expect("readable")
            .to_string()
    };
    // The fastest task runs every 2 ms, so five cycles are one 10 ms cycle of the main task.
    simulation.run(5);
    assert_eq!(read(&simulation, "Interlock.xRunRequest"), "FALSE");
    set_value(&mut simulation, "GVL_IO.xStartButton", 1.0);
    simulation.run(10);
    set_value(&mut simulation, "GVL_IO.xStartButton", 0.0);
    simulation.run(10);
    assert_eq!(read(&simulation, "Interlock.xRunRequest"), "TRUE");
    assert_eq!(read(&simulation, "Interlock.xHorn"), "TRUE");
    assert_eq!(read(&simulation, "Interlock.xRunEnabled"), "FALSE");
    // Two seconds later the TON is done: the belt may run and the horn stops.
    simulation.run(1000);
    assert_eq!(read(&simulation, "Interlock.xRunEnabled"), "TRUE");
    assert_eq!(read(&simulation, "Interlock.xHorn"), "FALSE");
    assert_eq!(read(&simulation, "Interlock.tWarningElapsed"), "T#2s");
    // Stop resets the request, and with it the timer and the enable.
    set_value(&mut simulation, "GVL_IO.xStopButton", 1.0);
    simulation.run(10);
    assert_eq!(read(&simulation, "Interlock.xRunRequest"), "FALSE");
    assert_eq!(read(&simulation, "Interlock.xRunEnabled"), "FALSE");

    // 2,500 mm/s is 125 % of the drive's 2,000 mm/s, limited to 100 %; the recipe's set point
    // is 50 mm/s.
    set_value(&mut simulation, "GVL_Machine.rBeltSpeedActual", 2500.0);
    simulation.run(10);
    assert_eq!(read(&simulation, "Scaling.rBeltLoad"), "100");
    assert_eq!(read(&simulation, "Scaling.rSpeedDeviation"), "2450");
    set_value(&mut simulation, "GVL_Machine.rBeltSpeedActual", 500.0);
    simulation.run(10);
    assert_eq!(read(&simulation, "Scaling.rBeltLoad"), "25");
    assert_eq!(read(&simulation, "Scaling.xOverspeed"), "FALSE");
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
}
