//! Choosing the implementation language of new POUs, methods, actions, transitions and
//! properties in the device tree's dialogs.

use app::studio::TreeNode;
use egui::Key;
use egui_kittest::kittest::Queryable as _;
use project_model::{Body, Object, Pou, Project};

use super::tree::{
    enter_text, example_copy, menu, project, set_text, shortcut, studio, undo_label,
};

fn pou<'p>(project: &'p Project, name: &str) -> &'p Pou {
    match project.application.object(name) {
        Some(Object::Pou(pou)) => pou,
        other => panic!("{name} is not a POU: {other:?}"),
    }
}

fn networks(body: &Body) -> usize {
    match body {
        Body::Ld { networks } | Body::Fbd { networks } => networks.len(),
        other => panic!("not an LD or FBD body: {other:?}"),
    }
}

#[test]
fn a_pou_added_in_ladder_has_one_network_and_the_next_dialog_proposes_ladder_again() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "Application", "Add POU…");
    harness.get_by_label("Ladder Diagram (LD)").click();
    harness.run();
    enter_text(&mut harness, "Name", "PRG_Interlock");
    let added = pou(project(&harness), "PRG_Interlock");
    assert!(matches!(added.body, Body::Ld { .. }));
    assert_eq!(networks(&added.body), 1);
    assert!(
        harness
            .state()
            .open_documents()
            .contains(&TreeNode::Object("PRG_Interlock".into()))
    );

    // The dialog remembers the language: the next POU is in LD without choosing it again.
    // (The application is marked changed now.)
    menu(&mut harness, "Application *", "Add POU…");
    enter_text(&mut harness, "Name", "PRG_Second");
    assert!(matches!(
        pou(project(&harness), "PRG_Second").body,
        Body::Ld { .. }
    ));

    // The empty network is saved and read back.
    shortcut(&mut harness, Key::S);
    let loaded = project_model::load_project(dir.path()).unwrap().project;
    assert_eq!(networks(&pou(&loaded, "PRG_Interlock").body), 1);
}

#[test]
fn an_action_in_fbd_is_added_to_a_function_block_from_its_context_menu_and_undone() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "FB_Conveyor", "Add action…");
    harness.get_by_label("Function Block Diagram (FBD)").click();
    harness.run();
    enter_text(&mut harness, "Name", "Clean");

    let action = pou(project(&harness), "FB_Conveyor")
        .actions
        .last()
        .cloned();
    let action = action.expect("FB_Conveyor has no action");
    assert_eq!(action.name, "Clean");
    assert!(matches!(action.body, Body::Fbd { .. }));
    assert_eq!(networks(&action.body), 1);
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Add action Clean to FB_Conveyor")
    );
    // The POU opened with the new action in its part selector.
    assert!(harness.query_by_label("Action Clean").is_some());

    shortcut(&mut harness, Key::Z);
    assert!(pou(project(&harness), "FB_Conveyor").actions.is_empty());
    assert!(harness.query_by_label("Action Clean").is_none());
}

#[test]
fn a_method_name_the_function_block_uses_is_refused_and_a_free_one_opens_its_body() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "FB_Conveyor", "Add method…");
    // `Reset` is already a method of FB_Conveyor: names compare without case.
    set_text(&mut harness, "Name", "reset");
    assert!(
        harness
            .query_by_label_contains("the name 'reset' is already used")
            .is_some()
    );
    set_text(&mut harness, "Name", "Jog");
    set_text(&mut harness, "Return type", "BOOL");
    harness.get_by_label("OK").click();
    harness.run();

    let method = pou(project(&harness), "FB_Conveyor")
        .methods
        .last()
        .cloned();
    let method = method.expect("FB_Conveyor has no method");
    assert_eq!(method.name, "Jog");
    assert_eq!(method.return_type.as_deref(), Some("BOOL"));
    assert_eq!(method.body, Body::st(""));
    // The document shows the new method's implementation.
    assert!(
        harness
            .query_by_label("Implementation of FB_Conveyor.Jog")
            .is_some()
    );
}

#[test]
fn a_transition_is_added_to_a_program_from_its_context_menu_and_opens_on_its_body() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "Main", "Add transition…");
    harness.get_by_label("Structured Text (ST)").click();
    harness.run();
    enter_text(&mut harness, "Name", "Ready");

    let transition = pou(project(&harness), "Main").transitions.last().cloned();
    let transition = transition.expect("Main has no transition");
    assert_eq!(transition.name, "Ready");
    assert_eq!(transition.body, Body::st(""));
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Add transition Ready to Main")
    );
    // The document shows the new transition's body.
    assert!(
        harness
            .query_by_label("Implementation of Main.Ready")
            .is_some()
    );
    // The part selector leads away from the transition and back to it.
    harness.get_by_label("Implementation").click();
    harness.run();
    assert!(
        harness
            .query_by_label("Implementation of Main.Ready")
            .is_none()
    );
    harness.get_by_label("Transition Ready").click();
    harness.run();
    assert!(
        harness
            .query_by_label("Implementation of Main.Ready")
            .is_some()
    );

    shortcut(&mut harness, Key::Z);
    assert!(pou(project(&harness), "Main").transitions.is_empty());
}
