//! Image snapshots of the studio rendered with the software rasterizer (wgpu on Mesa's
//! lavapipe): the main window, the watch pane online, and the diagram editor's LD and FBD views
//! of one network, offline and online. A changed look fails the test with a
//! diff image beside the snapshot; `UPDATE_SNAPSHOTS=1` accepts the new look.

use app::studio::{Settings, StudioApp};
use egui_kittest::Harness;

#[test]
fn the_main_window_with_the_example_project() {
    let app = StudioApp::new(Settings::default(), Some(assets::example_project_dir()));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .wgpu()
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.run();
    harness.snapshot("main_window");
}

/// Steps until `done` holds, for at most 30 s.
fn wait(harness: &mut Harness<'_, StudioApp>, what: &str, done: impl Fn(&StudioApp) -> bool) {
    let start = std::time::Instant::now();
    while !done(harness.state()) {
        assert!(start.elapsed().as_secs() < 30, "waited for {what}");
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

#[test]
fn the_st_editor_online_with_values_inline() {
    use egui_kittest::kittest::Queryable as _;

    let app = StudioApp::new(Settings::default(), Some(assets::example_project_dir()));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .wgpu()
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness
        .state_mut()
        .open(app::studio::TreeNode::Object("Main".into()));
    harness.step();
    let ctx = harness.ctx.clone();
    harness.state_mut().login(&ctx);
    wait(&mut harness, "the download question", |app| {
        matches!(
            app.online().phase(),
            app::studio::Phase::ConfirmDownload { .. }
        )
    });
    harness.state_mut().confirm_download();
    wait(&mut harness, "the login", |app| {
        *app.online().phase() == app::studio::Phase::Online
    });
    harness.state_mut().start();
    wait(&mut harness, "the inline values", |app| {
        app.online().value("GVL_Machine.udiTotalPackages").is_some()
            && app.online().value("GVL_IO.iBeltSpeedSetpoint").is_some()
            && app.online().target_state() == Some(online::TargetState::Running)
    });
    // Let every value arrive once more, so none is drawn as just changed.
    for _ in 0..20 {
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    // The cycle counter in the status bar differs from run to run.
    let cycle = harness.get_by_label_contains("cycle ").rect();
    harness.mask(cycle);
    harness.snapshot("st_editor_online");
}

#[test]
fn the_st_editor_halted_with_a_breakpoint_and_flow_marks() {
    use egui::{Key, Modifiers};
    use egui_kittest::kittest::Queryable as _;

    // Breakpoints live in the settings, so the example itself is opened: nothing is written.
    let app = StudioApp::new(Settings::default(), Some(assets::example_project_dir()));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .wgpu()
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness
        .state_mut()
        .open(app::studio::TreeNode::Object("Main".into()));
    harness.step();
    // A breakpoint on the statement of line 2 (F9), flow control on, and a halt on line 10.
    harness.get_by_label("Implementation of Main").focus();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Home);
    harness.key_press(Key::ArrowDown);
    harness.key_press(Key::F9);
    harness.step();
    harness.get_by_label("Debug").click();
    harness.run();
    harness.get_by_label("Flow control").click();
    harness.run();
    harness.key_press(Key::Escape);
    harness.run();
    harness.state_mut().set_flow(vec![(
        "application/Main.st".to_owned(),
        vec![2, 6, 7, 10, 11],
    )]);
    harness
        .state_mut()
        .set_halted(vec![app::studio::HaltedTask {
            task: "MainTask".to_owned(),
            beneath: None,
            frames: vec![app::studio::StackFrame {
                pou: "Main".to_owned(),
                instance: Some("Main".to_owned()),
                file: "application/Main.st".to_owned(),
                line: 10,
            }],
        }]);
    harness.run();
    harness.snapshot("st_editor_halted");
}

#[test]
fn the_trace_view_with_cursors() {
    use app::studio::{TraceData, TracePlotView, TraceSample, TraceSeries};

    let samples = (0..200u64)
        .map(|i| TraceSample {
            cycle: 1000 + i,
            time_ns: i * 10_000_000,
            values: vec![
                f64::from(u8::from(i % 50 >= 25)),
                (i as f64 * 0.05).sin() * 100.0,
                (i as f64).min(120.0),
            ],
        })
        .collect();
    let data = TraceData {
        variables: vec![
            TraceSeries {
                path: "GVL_IO.xConveyorMotor".into(),
                color: None,
                is_bool: true,
            },
            TraceSeries {
                path: "GVL_Machine.lrMasterPosition".into(),
                color: None,
                is_bool: false,
            },
            TraceSeries {
                path: "Main.ctuPackages.CV".into(),
                color: None,
                is_bool: false,
            },
        ],
        samples,
        trigger_sample: Some(20),
        cycle_time_ns: Some(10_000_000),
    };
    let mut view = TracePlotView::default();
    view.cursor_a_ms = Some(300.0);
    view.cursor_b_ms = Some(900.0);
    let mut harness = Harness::builder()
        .with_size([1000.0, 560.0])
        .wgpu()
        .build_ui_state(
            move |ui, view: &mut TracePlotView| {
                view.ui(ui, &data);
            },
            view,
        );
    harness.run();
    harness.snapshot("trace_view");
}

/// Services for the diagram snapshots: nothing is typed, so nothing is asked.
struct NoDiagramServices;

impl editor::DiagramServices for NoDiagramServices {
    fn variables(&self, _prefix: &str) -> Vec<editor::CompletionItem> {
        Vec::new()
    }

    fn blocks(&self, _prefix: &str) -> Vec<editor::CompletionItem> {
        Vec::new()
    }

    fn structure_members(&self, _type_name: &str) -> Option<Vec<String>> {
        None
    }

    fn signature(&self, _type_name: &str) -> Option<editor::BlockSignature> {
        None
    }

    fn is_declared(&self, _name: &str) -> bool {
        true
    }
}

/// An interlock rung with every kind of element: an edge contact, a latch in parallel with a
/// normally closed contact, a timer box with an operand and an assigned output, a coil, a set
/// coil and a jump; and an empty network below it.
fn interlock_body() -> Vec<project_model::Network> {
    use project_model::{
        BlockCall, BlockInput, BlockOutput, Branch, Coil, CoilKind, Edge, ElementId, FlowNode,
        Network, NetworkOutput, Operand, Parallel,
    };
    let contact = |id: u32, text: &str, negated: bool, edge: Edge| {
        FlowNode::Operand(Operand {
            id: ElementId(id),
            text: text.into(),
            negated,
            edge,
        })
    };
    let rung = Network {
        title: "Start the motor".into(),
        comment: "Latches until stop".into(),
        label: "start".into(),
        rung: vec![
            contact(1, "start", false, Edge::Rising),
            FlowNode::Parallel(Parallel {
                id: ElementId(2),
                branches: vec![
                    Branch {
                        rung: vec![contact(3, "stop", true, Edge::None)],
                    },
                    Branch {
                        rung: vec![
                            contact(4, "motor", false, Edge::None),
                            contact(5, "enable_from_the_line", false, Edge::None),
                        ],
                    },
                ],
            }),
            FlowNode::Block(BlockCall {
                id: ElementId(6),
                type_name: "TON".into(),
                instance: "delay".into(),
                inputs: vec![
                    BlockInput {
                        pin: "IN".into(),
                        ..BlockInput::default()
                    },
                    BlockInput {
                        pin: "PT".into(),
                        source: vec![contact(7, "T#5S", false, Edge::None)],
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
                        assign: "elapsed".into(),
                        ..BlockOutput::default()
                    },
                ],
            }),
        ],
        outputs: vec![
            NetworkOutput::Coil(Coil {
                id: ElementId(8),
                variable: "motor".into(),
                kind: CoilKind::Normal,
            }),
            NetworkOutput::Coil(Coil {
                id: ElementId(9),
                variable: "lamp".into(),
                kind: CoilKind::Set,
            }),
            NetworkOutput::Jump {
                id: ElementId(10),
                label: "done".into(),
            },
        ],
    };
    vec![rung, Network::default()]
}

#[test]
fn the_diagram_editor_in_ld_and_fbd_offline_and_online() {
    use editor::{DiagramEditor, DiagramOnline, DiagramView, OnlineValue};
    use project_model::ElementId;

    let body = interlock_body();
    // Four harnesses in one test: their results are gathered so every image is checked.
    let mut results = egui_kittest::SnapshotResults::new();
    for (name, view, online) in [
        ("diagram_ld", DiagramView::Ladder, false),
        ("diagram_ld_online", DiagramView::Ladder, true),
        ("diagram_fbd", DiagramView::FunctionBlock, false),
        ("diagram_fbd_online", DiagramView::FunctionBlock, true),
    ] {
        let mut editor = DiagramEditor::new(&body, view);
        editor.select(Some(0), vec![ElementId(3)]);
        if !online {
            // A finding on a box's pin and one on a coil, as the checker reports them.
            let finding = |element: u32, pin: Option<&str>, severity: editor::Severity| {
                editor::ElementDiagnostic {
                    network: 0,
                    element: Some(ElementId(element)),
                    pin: pin.map(str::to_owned),
                    severity,
                    code: "E0000".into(),
                    message: String::new(),
                }
            };
            editor.set_diagnostics(vec![
                finding(6, Some("PT"), editor::Severity::Error),
                finding(9, None, editor::Severity::Warning),
            ]);
        }
        if online {
            let mut values = DiagramOnline::default();
            for id in [1, 2, 4, 5, 6] {
                values.power.insert(ElementId(id), true);
            }
            values.values.insert(
                (ElementId(6), Some("ET".into())),
                OnlineValue {
                    text: "T#1s200ms".into(),
                    forced: false,
                },
            );
            values.values.insert(
                (ElementId(1), None),
                OnlineValue {
                    text: "TRUE".into(),
                    forced: true,
                },
            );
            editor.set_online(Some(values));
        }
        let mut harness = Harness::builder()
            .with_size([2000.0, 420.0])
            .wgpu()
            .build_ui_state(
                |ui, editor: &mut DiagramEditor| {
                    editor.show(ui, "Body of Interlock", &NoDiagramServices);
                },
                editor,
            );
        harness.run_steps(3);
        harness.snapshot(name);
        results.extend_harness(&mut harness);
    }
    results.unwrap();
}

/// The chart of the example's POU `name`.
fn example_body(name: &str) -> project_model::Body {
    let project = project_model::load_project(&assets::example_project_dir())
        .unwrap()
        .project;
    match project.application.object(name) {
        Some(project_model::Object::Pou(pou)) => pou.body.clone(),
        other => panic!("no POU {name}: {other:?}"),
    }
}

#[test]
fn the_cfc_and_sfc_editors_offline_and_online() {
    use editor::{CfcEditor, DiagramOnline, OnlineValue, SfcEditor, SfcOnline, SfcStepOnline};
    use project_model::{Body, ElementId};
    use std::time::Duration;

    let Body::Cfc { chart: cfc } = example_body("TempControl") else {
        panic!("TempControl is not CFC");
    };
    let Body::Sfc { chart: sfc } = example_body("PackCycle") else {
        panic!("PackCycle is not SFC");
    };
    let mut results = egui_kittest::SnapshotResults::new();
    for online in [false, true] {
        let mut editor = CfcEditor::new(&cfc);
        if online {
            let mut values = DiagramOnline::default();
            let value = |text: &str| OnlineValue {
                text: text.to_owned(),
                forced: false,
            };
            for (id, pin, text) in [
                (1, None, "60.0"),
                (2, Some("OUT"), "8.5"),
                (4, Some("OUT"), "17.0"),
                (8, Some("OUT"), "17.0"),
                (9, None, "17.0"),
                (11, Some("OUT"), "0.085"),
                (7, Some("OUT"), "51.585"),
                (12, None, "51.585"),
            ] {
                values
                    .values
                    .insert((ElementId(id), pin.map(str::to_owned)), value(text));
            }
            editor.set_online(Some(values));
        }
        let mut harness = Harness::builder()
            .with_size([1100.0, 360.0])
            .wgpu()
            .build_ui_state(
                |ui, editor: &mut CfcEditor| {
                    editor.show(ui, "Body of TempControl", &NoDiagramServices);
                },
                editor,
            );
        harness.run_steps(3);
        harness.snapshot(if online { "cfc_online" } else { "cfc" });
        results.extend_harness(&mut harness);
    }
    for online in [false, true] {
        let mut editor = SfcEditor::new(&sfc);
        if online {
            // Glue and Position active in the parallel branch, Glue's action on, and Cut's
            // maximum time reported as exceeded.
            let mut state = SfcOnline::default();
            let step = |active: bool, elapsed_ms: u64, over_max_time: bool| SfcStepOnline {
                active,
                elapsed: Duration::from_millis(elapsed_ms),
                over_max_time,
            };
            state.steps.insert(ElementId(1), step(false, 1200, false));
            state.steps.insert(ElementId(4), step(true, 150, false));
            state.steps.insert(ElementId(7), step(true, 150, false));
            state.steps.insert(ElementId(9), step(false, 2100, true));
            state.transitions.insert(ElementId(5), false);
            state.transitions.insert(ElementId(8), true);
            state.actions.insert("xGlue".to_owned(), true);
            editor.set_online(Some(state));
        }
        let mut harness = Harness::builder()
            .with_size([900.0, 760.0])
            .wgpu()
            .build_ui_state(
                |ui, editor: &mut SfcEditor| {
                    editor.show(ui, "Body of PackCycle", &NoDiagramServices);
                },
                editor,
            );
        harness.run_steps(3);
        harness.snapshot(if online { "sfc_online" } else { "sfc" });
        results.extend_harness(&mut harness);
    }
    results.unwrap();
}

#[test]
fn the_diagram_editor_halted_with_breakpoints_and_flow_marks() {
    use editor::{
        BodyBreakpointMark, BodyDebugMarks, BodyPlace, BreakpointLook, DiagramEditor, DiagramView,
    };
    use project_model::ElementId;

    let place = |network: usize, element: Option<u32>| BodyPlace {
        network,
        element: element.map(ElementId),
    };
    let mut editor = DiagramEditor::new(&interlock_body(), DiagramView::Ladder);
    // A breakpoint on the first network and a conditional one on its coil `lamp`, the halt on
    // its timer and the flow bars of the contacts that ran before it.
    editor.set_debug_marks(BodyDebugMarks {
        breakpoints: vec![
            BodyBreakpointMark {
                place: place(0, None),
                look: BreakpointLook::Enabled,
            },
            BodyBreakpointMark {
                place: place(0, Some(9)),
                look: BreakpointLook::Conditional,
            },
        ],
        halt: Some(place(0, Some(6))),
        halt_is_caller: false,
        flow: vec![place(0, Some(1)), place(0, Some(2)), place(0, Some(4))],
    });
    let mut harness = Harness::builder()
        .with_size([1000.0, 300.0])
        .wgpu()
        .build_ui_state(
            |ui, editor: &mut DiagramEditor| {
                editor.show(ui, "Body of Interlock", &NoDiagramServices);
            },
            editor,
        );
    harness.run_steps(3);
    harness.snapshot("diagram_ld_halted");
}
