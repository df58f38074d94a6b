//! The declaration table driven through its accessibility tree, as a user with a keyboard and a
//! mouse would, with the edits it returns applied the way the app applies them.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::collections::HashMap;

use editor::VariableTable;
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{ListEdit, VarSection, Variable};

/// What the app would hold: the variables, the warnings it computed, and every edit returned.
struct App {
    variables: Vec<Variable>,
    warnings: HashMap<String, String>,
    edits: Vec<(String, ListEdit<Variable>)>,
    selected: Option<usize>,
}

fn harness(variables: Vec<Variable>, warnings: HashMap<String, String>) -> Harness<'static, App> {
    let app = App {
        variables,
        warnings,
        edits: Vec::new(),
        selected: None,
    };
    let mut harness = Harness::builder()
        .with_size([1000.0, 400.0])
        .build_ui_state(
            |ui, app: &mut App| {
                let output = VariableTable::new("Main").show(ui, &app.variables, &app.warnings);
                app.selected = output.selected;
                if let Some((label, edit)) = output.edit {
                    // The app applies the edit after the frame, as one undo step.
                    edit.clone().apply(&mut app.variables).unwrap();
                    app.edits.push((label, edit));
                }
            },
            app,
        );
    harness.run();
    harness
}

fn variables() -> Vec<Variable> {
    vec![
        Variable {
            section: VarSection::VarInput,
            address: Some("%IX0.0".to_owned()),
            comment: "start button".to_owned(),
            ..Variable::new("xStart", "BOOL")
        },
        Variable::new("rSpeed", "REAL"),
        Variable::new("iCount", "INT"),
    ]
}

/// Replaces the whole text of the cell labelled `label` with `text`, as typing over a
/// selection does.
fn type_over(harness: &mut Harness<'static, App>, label: &str, text: &str) {
    harness.get_by_label(label).focus();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.run();
    harness.get_by_label(label).type_text(text);
    harness.run();
}

#[test]
fn editing_a_name_and_pressing_enter_returns_one_replace_with_the_new_name() {
    let mut harness = harness(variables(), HashMap::new());
    type_over(&mut harness, "Name of xStart", "xGo");
    // Nothing is returned while typing.
    assert!(harness.state().edits.is_empty());
    harness.key_press(Key::Enter);
    harness.run();
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1, "{edits:?}");
    let (label, edit) = &edits[0];
    assert_eq!(label, "Name of xStart");
    let ListEdit::Replace { index: 0, item } = edit else {
        panic!("expected a Replace of row 0, got {edit:?}");
    };
    assert_eq!(item.name, "xGo");
    // The rest of the row is kept.
    assert_eq!(item.address.as_deref(), Some("%IX0.0"));
    assert_eq!(item.comment, "start button");
    assert_eq!(harness.state().selected, Some(0));
}

#[test]
fn a_duplicate_name_is_refused_in_place() {
    let mut harness = harness(variables(), HashMap::new());
    type_over(&mut harness, "Name of rSpeed", "XSTART");
    harness.key_press(Key::Enter);
    harness.run();
    assert!(harness.state().edits.is_empty());
    assert!(
        harness
            .query_by_label_contains("'XSTART' is already declared here")
            .is_some()
    );
}

#[test]
fn an_address_that_does_not_fit_the_type_shows_the_reason_and_returns_no_edit() {
    let mut harness = harness(variables(), HashMap::new());
    type_over(&mut harness, "Address of rSpeed", "%QW4");
    // The reason shows while typing, before anything is committed.
    let reason = "%QW4 is 16 bits but REAL needs 32: use %QD2";
    assert!(harness.query_by_label_contains(reason).is_some());
    harness.key_press(Key::Enter);
    harness.run();
    assert!(
        harness.state().edits.is_empty(),
        "{:?}",
        harness.state().edits
    );
    // It stays in view after the cell lost focus, until the user fixes it.
    assert!(harness.query_by_label_contains(reason).is_some());
    type_over(&mut harness, "Address of rSpeed", "%QD2");
    harness.key_press(Key::Enter);
    harness.run();
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1, "{edits:?}");
    assert!(matches!(
        &edits[0].1,
        ListEdit::Replace { index: 1, item } if item.address.as_deref() == Some("%QD2")
    ));
    assert!(harness.query_by_label_contains(reason).is_none());
}

#[test]
fn tab_commits_the_cell_and_moves_to_the_next_one() {
    let mut harness = harness(variables(), HashMap::new());
    type_over(&mut harness, "Name of iCount", "iTotal");
    harness.key_press(Key::Tab);
    harness.run();
    assert_eq!(harness.state().edits.len(), 1);
    assert_eq!(harness.state().variables[2].name, "iTotal");
    assert!(harness.get_by_label("Address of iTotal").is_focused());
}

#[test]
fn delete_returns_a_remove_of_the_selected_row() {
    let mut harness = harness(variables(), HashMap::new());
    harness.get_by_label("Type of rSpeed").click();
    harness.run();
    assert_eq!(harness.state().selected, Some(1));
    harness.get_by_label("Delete").click();
    harness.run();
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1, "{edits:?}");
    assert_eq!(edits[0].1, ListEdit::Remove { index: 1 });
    assert_eq!(edits[0].0, "Delete variable rSpeed");
    assert_eq!(harness.state().variables.len(), 2);
}

#[test]
fn insert_and_move_return_list_edits() {
    let mut harness = harness(variables(), HashMap::new());
    harness.get_by_label("Name of xStart").click();
    harness.run();
    harness.get_by_label("Insert below").click();
    harness.run();
    harness.get_by_label("Move down").click();
    harness.run();
    let edits: Vec<&ListEdit<Variable>> = harness.state().edits.iter().map(|(_, e)| e).collect();
    assert!(matches!(
        edits[0],
        ListEdit::Insert { index: 1, item } if item.name == "Var1" && item.section == VarSection::VarInput
    ));
    assert_eq!(*edits[1], ListEdit::Move { from: 1, to: 2 });
    let names: Vec<&str> = harness
        .state()
        .variables
        .iter()
        .map(|v| v.name.as_str())
        .collect();
    assert_eq!(names, ["xStart", "rSpeed", "Var1", "iCount"]);
}

#[test]
fn a_check_box_returns_a_replace_with_the_flag() {
    let mut harness = harness(variables(), HashMap::new());
    harness.get_by_label("Retain of iCount").click();
    harness.run();
    assert!(harness.state().variables[2].retain);
    assert_eq!(harness.state().edits[0].0, "Retain of iCount");
}

#[test]
fn an_overlap_warning_is_a_mark_with_the_warning_as_label_and_hover_text() {
    let warning =
        "GVL.xStart at %IX0.0 overlaps GVL.bInputs at %IB0: writing one changes the other";
    let warnings = HashMap::from([("xStart".to_owned(), warning.to_owned())]);
    let mut harness = harness(variables(), warnings);
    let label = format!("Warning for xStart: {warning}");
    harness.get_by_label(&label).hover();
    harness.run();
    // The tooltip shows the same text.
    assert!(
        harness
            .query_all_by_label_contains("overlaps GVL.bInputs")
            .count()
            >= 2
    );
    assert!(
        harness
            .query_by_label_contains("Warning for rSpeed")
            .is_none()
    );
}

#[test]
fn a_read_only_table_returns_no_edits() {
    let mut harness = Harness::new_ui_state(
        |ui, edits: &mut Vec<ListEdit<Variable>>| {
            let output =
                VariableTable::new("ro")
                    .read_only(true)
                    .show(ui, &variables(), &HashMap::new());
            edits.extend(output.edit.map(|(_, edit)| edit));
        },
        Vec::new(),
    );
    harness.run();
    assert!(harness.query_by_label("Delete").is_none());
    assert!(harness.query_by_label_contains("start button").is_some());
    harness.get_by_label("Retain of xStart").click();
    harness.run();
    assert!(harness.state().is_empty());
}

#[test]
fn escape_abandons_what_was_typed() {
    let mut harness = harness(variables(), HashMap::new());
    type_over(&mut harness, "Address of rSpeed", "%QW4");
    assert!(harness.query_by_label_contains("needs 32").is_some());
    harness.key_press(Key::Escape);
    harness.run();
    assert!(harness.state().edits.is_empty());
    assert!(harness.query_by_label_contains("needs 32").is_none());
    assert_eq!(
        harness.get_by_label("Address of rSpeed").value().as_deref(),
        Some("")
    );
}
