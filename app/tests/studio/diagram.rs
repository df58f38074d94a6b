//! Editing LD and FBD in the studio: a rung built by keyboard only goes to the model one undo
//! step per gesture, undo and redo restore the networks, a network is copied and pasted, a type
//! error is shown at its element after the live check, and power flows while online.

use crate::support::{example_copy, login_with_download, wait_until};
use app::studio::StudioApp;
use egui::{Event, Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{
    Body, ElementId, FlowNode, Network, NetworkOutput, Object, TextTarget, same_identifier,
};

fn interlock() -> TextTarget {
    TextTarget::Pou("Interlock".to_owned())
}

/// The Interlock's networks as the model holds them.
fn networks(app: &StudioApp) -> Vec<Network> {
    match app
        .session()
        .unwrap()
        .project
        .application
        .object("Interlock")
    {
        Some(Object::Pou(pou)) => match &pou.body {
            Body::Ld { networks } => networks.clone(),
            other => panic!("the Interlock is not LD: {other:?}"),
        },
        _ => Vec::new(),
    }
}

/// The studio on `project` in a window tall enough to show every network of the Interlock.
fn tall_studio(project: &std::path::Path) -> Harness<'static, StudioApp> {
    let app = StudioApp::new(app::studio::Settings::default(), Some(project.to_owned()));
    let mut harness = Harness::builder()
        .with_size([1400.0, 1800.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness
}

/// Opens the Interlock and gives its diagram the keyboard focus.
fn open_interlock(harness: &mut Harness<'_, StudioApp>) {
    harness.get_by_label("Interlock").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.run_steps(3);
    // A click into the first network's area focuses the canvas and selects that network.
    let canvas = harness.get_by_label("Implementation of Interlock").rect();
    click_at(harness, canvas.min + egui::vec2(200.0, 60.0));
    harness.run_steps(2);
}

fn command(harness: &mut Harness<'_, StudioApp>, key: Key) {
    harness.key_press_modifiers(Modifiers::COMMAND, key);
    harness.run_steps(3);
}

fn type_and_enter(harness: &mut Harness<'_, StudioApp>, text: &str) {
    harness.event(Event::Text(text.to_owned()));
    harness.run_steps(3);
    harness.key_press(Key::Enter);
    harness.run_steps(3);
}

/// The network holding one contact on `operand` driving a coil on `coil`, and its index.
fn rung_of(networks: &[Network], operand: &str, coil: &str) -> Option<(usize, ElementId)> {
    networks.iter().enumerate().find_map(|(index, network)| {
        let contact = match network.rung.as_slice() {
            [FlowNode::Operand(contact)] if same_identifier(&contact.text, operand) => contact.id,
            _ => return None,
        };
        matches!(
            network.outputs.as_slice(),
            [NetworkOutput::Coil(c)] if same_identifier(&c.variable, coil)
        )
        .then_some((index, contact))
    })
}

/// Builds a new network `operand` → `coil` in front of the selected one by keyboard only.
fn build_rung(harness: &mut Harness<'_, StudioApp>, operand: &str, coil: &str) {
    command(harness, Key::I);
    command(harness, Key::K);
    type_and_enter(harness, operand);
    command(harness, Key::A);
    type_and_enter(harness, coil);
}

/// Clicks at `pos` with the primary button, as a mouse does.
fn click_at(harness: &mut Harness<'_, StudioApp>, pos: egui::Pos2) {
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
}

/// Clicks the element `id` of the Interlock where the editor drew it.
fn click_element(harness: &mut Harness<'_, StudioApp>, id: ElementId) {
    let rect = harness
        .state()
        .diagram_editor(&interlock())
        .and_then(|editor| editor.element_screen_rect(id))
        .expect("the element is drawn");
    click_at(harness, rect.center());
    harness.run_steps(2);
}

#[test]
fn a_rung_built_by_keyboard_is_undone_and_redone_step_by_step() {
    let project = example_copy(|_| {});
    let mut harness = tall_studio(project.path());
    open_interlock(&mut harness);
    let original = networks(harness.state());

    build_rung(&mut harness, "xRunEnabled", "xHorn");
    let built = networks(harness.state());
    assert_eq!(built.len(), original.len() + 1);
    let (_, contact) = rung_of(&built, "xRunEnabled", "xHorn").expect("the rung is in the model");

    // A contact in parallel below the new one.
    click_element(&mut harness, contact);
    command(&mut harness, Key::R);
    type_and_enter(&mut harness, "xRunRequest");
    let with_parallel = networks(harness.state());
    let group = with_parallel
        .iter()
        .find_map(|network| match network.rung.as_slice() {
            [FlowNode::Parallel(group)] => Some(group.clone()),
            _ => None,
        });
    let group = group.expect("a parallel group in the new rung");
    assert_eq!(group.branches.len(), 2);

    // Each gesture was one undo step: the parallel operand, the parallel contact, the coil's
    // variable, the coil, the contact's operand, the contact, the network.
    for _ in 0..7 {
        harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        harness.run_steps(2);
    }
    assert_eq!(networks(harness.state()), original);
    assert_eq!(
        harness
            .state()
            .diagram_editor(&interlock())
            .map(|editor| editor.networks().to_vec()),
        Some(original.clone())
    );
    for _ in 0..7 {
        harness.key_press_modifiers(Modifiers::COMMAND, Key::Y);
        harness.run_steps(2);
    }
    assert_eq!(networks(harness.state()), with_parallel);
}

#[test]
fn a_network_is_copied_and_pasted_below_itself() {
    let project = example_copy(|_| {});
    let mut harness = tall_studio(project.path());
    open_interlock(&mut harness);
    let original = networks(harness.state());
    // A click right of the last network's elements selects the network as a whole.
    let last = original.len() - 1;
    let NetworkOutput::Coil(coil) = &original[last].outputs[0] else {
        panic!("the last network ends in a coil");
    };
    let rect = harness
        .state()
        .diagram_editor(&interlock())
        .and_then(|editor| editor.element_screen_rect(coil.id))
        .expect("the coil is drawn");
    click_at(
        &mut harness,
        rect.center() + egui::vec2(rect.width() * 2.0 + 40.0, 0.0),
    );
    harness.run_steps(2);
    harness.event(Event::Copy);
    harness.run_steps(2);
    harness.event(Event::Paste(String::new()));
    harness.run_steps(3);
    let pasted = networks(harness.state());
    assert_eq!(pasted.len(), original.len() + 1);
    assert_eq!(pasted[..original.len()], original[..]);
    // The copy has the same structure with fresh ids.
    assert_eq!(pasted[last + 1].title, original[last].title);
    assert_eq!(pasted[last + 1].rung.len(), original[last].rung.len());
    assert_ne!(pasted[last + 1], original[last]);
}

#[test]
fn a_type_error_is_shown_at_its_element_after_the_live_check() {
    let project = example_copy(|_| {});
    let mut harness = tall_studio(project.path());
    open_interlock(&mut harness);
    // A TIME variable is no contact.
    build_rung(&mut harness, "tWarningElapsed", "xHorn");
    let (network, contact) =
        rung_of(&networks(harness.state()), "tWarningElapsed", "xHorn").expect("the rung");
    wait_until(&mut harness, "the finding at the contact", |app| {
        app.diagram_editor(&interlock()).is_some_and(|editor| {
            editor.diagnostics().iter().any(|diagnostic| {
                diagnostic.network == network
                    && diagnostic.element == Some(contact)
                    && diagnostic.severity == editor::Severity::Error
            })
        })
    });
    // Hovering the contact shows the message.
    let rect = harness
        .state()
        .diagram_editor(&interlock())
        .and_then(|editor| editor.element_screen_rect(contact))
        .expect("the contact is drawn");
    harness.hover_at(rect.center());
    harness.run_steps(3);
    assert!(harness.query_by_label_contains("E0").is_some());

    // After F11 the finding is listed as file:POU:network:element; a click selects the contact.
    harness.key_press(Key::Escape);
    harness.run_steps(2);
    harness.key_press(Key::F11);
    wait_until(&mut harness, "the build", |app| {
        !app.is_building() && app.last_build().is_some()
    });
    harness.run_steps(2);
    let place = format!(":Interlock:{}:{}", network + 1, contact.0);
    harness.get_by_label_contains(&place).click();
    harness.run_steps(4);
    let selected = harness
        .state()
        .diagram_editor(&interlock())
        .map(|editor| editor.selection().elements.clone());
    assert_eq!(selected, Some(vec![contact]));
}

#[test]
fn power_flows_through_a_true_contact_while_online() {
    let project = example_copy(|_| {});
    let mut harness = tall_studio(project.path());
    open_interlock(&mut harness);
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    // The horn's rung reads the request through contact 14; force the request TRUE by clicking
    // the contact, typing the value and pressing F7, as in ST.
    wait_until(&mut harness, "the online values", |app| {
        app.diagram_editor(&interlock())
            .and_then(|editor| editor.online())
            .is_some_and(|online| online.values.contains_key(&(ElementId(14), None)))
    });
    click_element(&mut harness, ElementId(14));
    type_and_enter(&mut harness, "TRUE");
    harness.key_press(Key::F7);
    wait_until(&mut harness, "power through the forced contact", |app| {
        app.diagram_editor(&interlock())
            .and_then(|editor| editor.online())
            .is_some_and(|online| {
                online.power.get(&ElementId(14)) == Some(&true)
                    && online
                        .values
                        .get(&(ElementId(14), None))
                        .is_some_and(|value| value.text == "TRUE" && value.forced)
            })
    });
}

#[test]
fn an_operand_bound_to_a_modbus_device_shows_the_value_the_program_uses() {
    let project = example_copy(|_| {});
    let mut harness = tall_studio(project.path());
    harness.get_by_label("Scaling").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.run_steps(3);
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    // GVL_Machine.rBeltSpeedActual is bound to the belt drive, unreachable here; its operands
    // (3 and 10) still show the program's copy, as the recipe's speed (8) does.
    let scaling = TextTarget::Pou("Scaling".to_owned());
    wait_until(&mut harness, "the values of every operand", |app| {
        app.diagram_editor(&scaling)
            .and_then(|editor| editor.online())
            .is_some_and(|online| {
                [3, 8, 10]
                    .iter()
                    .all(|id| online.values.contains_key(&(ElementId(*id), None)))
            })
    });
}

/// The Interlock's variables as `name : type`.
fn variables(app: &StudioApp) -> Vec<String> {
    match app
        .session()
        .unwrap()
        .project
        .application
        .object("Interlock")
    {
        Some(Object::Pou(pou)) => pou
            .variables
            .iter()
            .map(|v| format!("{} : {}", v.name, v.ty))
            .collect(),
        _ => Vec::new(),
    }
}

#[test]
fn a_box_instance_is_declared_in_the_same_undo_step_and_an_unknown_block_refused() {
    let project = example_copy(|_| {});
    let mut harness = tall_studio(project.path());
    open_interlock(&mut harness);
    build_rung(&mut harness, "xRunEnabled", "xHorn");
    let (_, contact) =
        rung_of(&networks(harness.state()), "xRunEnabled", "xHorn").expect("the rung");
    click_element(&mut harness, contact);

    command(&mut harness, Key::B);
    type_and_enter(&mut harness, "TOON");
    let status = harness.state().status().map(|s| s.text.clone());
    assert_eq!(
        status.as_deref(),
        Some("no function or function block is called 'TOON'")
    );

    let before_box = (networks(harness.state()), variables(harness.state()));
    command(&mut harness, Key::B);
    type_and_enter(&mut harness, "TOF");
    let without_instance = (networks(harness.state()), variables(harness.state()));
    type_and_enter(&mut harness, "tofHorn");
    assert!(
        variables(harness.state()).contains(&"tofHorn : TOF".to_owned()),
        "{:?}",
        variables(harness.state())
    );
    let named = networks(harness.state());
    assert!(
        named
            .iter()
            .any(|network| network.rung.iter().any(|node| matches!(
                node,
                FlowNode::Block(block) if block.type_name == "TOF" && block.instance == "tofHorn"
            )))
    );
    // One Ctrl+Z takes back the instance's name and its declaration together.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run_steps(2);
    assert_eq!(
        (networks(harness.state()), variables(harness.state())),
        without_instance
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run_steps(2);
    assert_eq!(
        (networks(harness.state()), variables(harness.state())),
        before_box
    );
}
