//! Debugging graphical bodies in the studio (`docs/debugging.md` §3 and §5): F9 on a selected
//! LD network sets a breakpoint that the Breakpoints pane lists and the diagram draws, a halt
//! reported in the lowered text of an LD body opens it with its element marked, and flow
//! control marks the elements and networks that ran.

use crate::support::{example_copy, studio};
use app::studio::{Breakpoint, BreakpointPlace, GraphicalPlace, HaltedTask, StackFrame, StudioApp};
use editor::{BodyPlace, BreakpointLook};
use egui::{Event, Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::TextTarget;

fn interlock() -> TextTarget {
    TextTarget::Pou("Interlock".to_owned())
}

fn breakpoints(app: &StudioApp) -> Vec<Breakpoint> {
    let dir = &app.session().unwrap().dir;
    app.settings()
        .breakpoints
        .get(&app::studio::Settings::project_key(dir))
        .map(|list| list.all().to_vec())
        .unwrap_or_default()
}

/// Opens the Interlock and clicks its first network's header, which selects that network.
fn open_interlock_first_network(harness: &mut Harness<'_, StudioApp>) {
    harness.get_by_label("Interlock").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.run_steps(3);
    let canvas = harness.get_by_label("Implementation of Interlock").rect();
    // The header of the first network: a click there selects the network, not an element.
    let pos = canvas.min + egui::vec2(200.0, 10.0);
    harness.hover_at(pos);
    harness.step();
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
        harness.step();
    }
    harness.run_steps(2);
}

/// The lowered text file of the Interlock, and a line of it with the place it comes from: the
/// first line whose statement belongs to an element of network `network`.
fn interlock_line(app: &StudioApp, network: usize) -> (String, u32, BodyPlace) {
    let project = &app.session().unwrap().project;
    let lowered = compiler::lower::lower_project(project).bodies;
    let body = lowered.iter().find(|body| body.pou == "Interlock").unwrap();
    let (line, place) = (1..=body.text.lines().count() as u32)
        .find_map(|line| {
            let place = app::studio::place_at_line(body, line)?;
            (place.network == network && place.element.is_some()).then_some((line, place))
        })
        .unwrap();
    (body.text_file.to_string_lossy().into_owned(), line, place)
}

#[test]
fn f9_on_a_selected_ld_network_sets_a_breakpoint_listed_in_the_pane_and_drawn() {
    let project = example_copy(|_| {});
    // Tall enough to show every network of the Interlock.
    let app = StudioApp::new(
        app::studio::Settings::default(),
        Some(project.path().to_owned()),
    );
    let mut harness = Harness::builder()
        .with_size([1400.0, 1800.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    open_interlock_first_network(&mut harness);
    let selected = harness
        .state()
        .diagram_editor(&interlock())
        .unwrap()
        .breakpoint_place();
    assert_eq!(
        selected,
        Some(BodyPlace {
            network: 0,
            element: None
        })
    );
    harness.key_press(Key::F9);
    harness.run_steps(3);
    let place = BreakpointPlace::graphical(
        "application/Interlock.pou.toml",
        GraphicalPlace {
            body: "Interlock".to_owned(),
            network: 0,
            element: None,
        },
    );
    assert_eq!(breakpoints(harness.state()), vec![Breakpoint::at(place)]);
    let marks = harness
        .state()
        .diagram_editor(&interlock())
        .unwrap()
        .debug_marks()
        .clone();
    assert_eq!(marks.breakpoints.len(), 1);
    assert_eq!(marks.breakpoints[0].place, selected.unwrap());
    assert_eq!(marks.breakpoints[0].look, BreakpointLook::Enabled);

    // The plain contact of the last network is computed inside its coil's statement (unlike
    // an edge contact, whose trigger is a statement): it is not offered, and the status line
    // says why.
    let editor = harness.state().diagram_editor(&interlock()).unwrap();
    let last = editor.networks().len() - 1;
    let contact = editor.networks()[last]
        .rung
        .iter()
        .find_map(|node| match node {
            project_model::FlowNode::Operand(operand) => Some(operand.id),
            _ => None,
        })
        .expect("the last network starts with a contact");
    let operand = match editor.networks()[last].element(contact) {
        Some(project_model::ElementRef::Operand(operand)) => operand.text.clone(),
        _ => panic!("the contact is an operand"),
    };
    let at = editor.element_screen_rect(contact).unwrap().center();
    harness.hover_at(at);
    harness.step();
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos: at,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
        harness.step();
    }
    harness.key_press(Key::F9);
    harness.run_steps(3);
    assert_eq!(breakpoints(harness.state()).len(), 1);
    let status = harness.state().status().map(|status| status.text.clone());
    // The status line names the contact as the user knows it: network and operand.
    assert!(
        status.as_deref().is_some_and(|text| text
            .contains(&format!("Interlock: network {}, {operand}", last + 1))
            && text.contains("no statement of its own")),
        "{status:?}"
    );

    // The Breakpoints pane lists it by body and network.
    harness.get_by_label("Debug").click();
    harness.run();
    harness.get_by_label("Breakpoints").click();
    harness.run_steps(2);
    harness.get_by_label("Interlock: network 1");
}

#[test]
fn a_halt_in_an_ld_body_marks_its_element_and_flow_control_its_network() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.run_steps(2);
    let (file, line, place) = interlock_line(harness.state(), 1);
    harness.state_mut().set_halted(vec![HaltedTask {
        task: "MainTask".to_owned(),
        beneath: None,
        frames: vec![StackFrame {
            pou: "Interlock".to_owned(),
            instance: Some("Interlock".to_owned()),
            file: file.clone(),
            line,
        }],
    }]);
    harness.run_steps(4);

    // The halt opens the Interlock with the halted element selected and marked.
    let editor = harness.state().diagram_editor(&interlock()).unwrap();
    assert_eq!(editor.debug_marks().halt, Some(place));
    assert!(!editor.debug_marks().halt_is_caller);
    assert_eq!(editor.breakpoint_place(), Some(place));

    // The Call stack names the halted element by what it reads or writes, not by the line of
    // the text the body was compiled from.
    let caption = match &harness
        .state()
        .session()
        .unwrap()
        .project
        .application
        .object("Interlock")
    {
        Some(project_model::Object::Pou(pou)) => pou
            .body
            .element_caption(place.network, place.element.unwrap())
            .unwrap(),
        _ => panic!("the example has the Interlock"),
    };
    harness.get_by_label(&format!("Interlock: network 2, {caption}"));

    // Flow control marks the network of the lines that ran once switched on.
    harness.state_mut().set_flow(vec![(file, vec![line])]);
    harness.step();
    let editor = harness.state().diagram_editor(&interlock()).unwrap();
    assert!(editor.debug_marks().flow.is_empty());
    harness.get_by_label("Debug").click();
    harness.run();
    harness.get_by_label("Flow control").click();
    harness.run_steps(2);
    let marks = harness
        .state()
        .diagram_editor(&interlock())
        .unwrap()
        .debug_marks()
        .clone();
    assert_eq!(marks.flow, vec![place]);
    assert!(marks.network_flowed(1) && !marks.network_flowed(0));
}

fn pack_cycle() -> TextTarget {
    TextTarget::Pou("PackCycle".to_owned())
}

/// The SFC chart of the PackCycle as the model holds it.
fn pack_cycle_chart(app: &StudioApp) -> project_model::SfcChart {
    match app
        .session()
        .unwrap()
        .project
        .application
        .object("PackCycle")
    {
        Some(project_model::Object::Pou(pou)) => match &pou.body {
            project_model::Body::Sfc { chart } => chart.clone(),
            other => panic!("the PackCycle is not SFC: {other:?}"),
        },
        _ => panic!("the example has the PackCycle"),
    }
}

#[test]
fn a_halt_in_an_sfc_chart_marks_its_step_and_f9_sets_a_breakpoint_named_by_the_step() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.run_steps(2);
    let chart = pack_cycle_chart(harness.state());
    let project = harness.state().session().unwrap().project.clone();
    let lowered = compiler::lower::lower_project(&project).bodies;
    let body = lowered
        .iter()
        .find(|body| body.target == pack_cycle())
        .unwrap();
    // The first line of the chart's text that comes from a step: where its actions run.
    let (line, place, step) = (1..=body.text.lines().count() as u32)
        .find_map(|line| {
            let place = app::studio::place_at_line(body, line)?;
            match project_model::sfc_edit::find_node(&chart, place.element?) {
                Some(project_model::SfcNode::Step(step)) => Some((line, place, step.clone())),
                _ => None,
            }
        })
        .expect("a step of the PackCycle has a statement");
    harness.state_mut().set_halted(vec![HaltedTask {
        task: "MainTask".to_owned(),
        beneath: None,
        frames: vec![StackFrame {
            pou: "PackCycle".to_owned(),
            instance: Some("PackCycle".to_owned()),
            file: body.text_file.to_string_lossy().into_owned(),
            line,
        }],
    }]);
    harness.run_steps(4);
    let editor = harness.state().sfc_editor(&pack_cycle()).unwrap();
    assert_eq!(editor.debug_marks().halt, Some(place));
    assert_eq!(editor.selection(), [step.id]);

    // F9 on the selected step sets a breakpoint the pane names by the step.
    harness.get_by_label("Implementation of PackCycle").focus();
    harness.step();
    harness.key_press(Key::F9);
    harness.run_steps(3);
    let set = breakpoints(harness.state());
    assert_eq!(set.len(), 1);
    let graphical = set[0].place.graphical.clone().unwrap();
    assert_eq!(graphical.element, Some(step.id.0));
    assert_eq!(set[0].place.file, "application/PackCycle.pou.toml");
    let marks = harness
        .state()
        .sfc_editor(&pack_cycle())
        .unwrap()
        .debug_marks()
        .clone();
    assert_eq!(marks.breakpoints.len(), 1);
    assert_eq!(marks.breakpoints[0].place, place);
    harness.get_by_label("Debug").click();
    harness.run();
    harness.get_by_label("Breakpoints").click();
    harness.run_steps(2);
    harness.get_by_label(&format!("PackCycle: step {}", step.name));

    // The Debug menu's "Toggle breakpoint" acts on the step selected last, as on the caret.
    harness.get_by_label("Debug").click();
    harness.run();
    harness.get_by_label_contains("Toggle breakpoint").click();
    harness.run_steps(2);
    assert!(breakpoints(harness.state()).is_empty());
}
