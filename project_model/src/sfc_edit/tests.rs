//! Tests of the SFC edits: each keeps the chart valid or names the rule it would break.

use super::*;
use crate::network::ElementId;
use crate::sfc::{ActionAssociation, ActionQualifier, SfcChart, SfcNode};

/// A short description of a sequence, for readable expectations: `S:Init`, `T:FALSE`, `J:Init`,
/// `A[..|..]`, `P[..|..]`, `M:Name(..)`.
fn shape(nodes: &[SfcNode]) -> String {
    nodes
        .iter()
        .map(|node| match node {
            SfcNode::Step(step) => format!("S:{}", step.name),
            SfcNode::Transition(transition) => format!("T:{}", transition.condition),
            SfcNode::Jump(jump) => format!("J:{}", jump.target),
            SfcNode::Alternative(branches) => format!("A[{}]", branches_shape(branches)),
            SfcNode::Parallel(branches) => format!("P[{}]", branches_shape(branches)),
            SfcNode::Macro(macro_step) => {
                format!("M:{}({})", macro_step.name, shape(&macro_step.body))
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

fn branches_shape(branches: &crate::sfc::SfcBranches) -> String {
    branches
        .branches
        .iter()
        .map(|branch| shape(&branch.nodes))
        .collect::<Vec<_>>()
        .join(" | ")
}

/// `Init, T(2), Step1(4), T(5), Jump(3)`: a chart with two steps.
fn two_steps() -> SfcChart {
    insert_step_transition_after(&SfcChart::new_body(), ElementId(2)).unwrap()
}

fn id_of(chart: &SfcChart, name: &str) -> ElementId {
    let mut found = None;
    walk::visit_nodes(&chart.sequence, &mut |node| match node {
        SfcNode::Step(step) if step.name == name => found = Some(step.id),
        SfcNode::Macro(macro_step) if macro_step.name == name => found = Some(macro_step.id),
        _ => {}
    });
    found.unwrap()
}

#[test]
fn a_step_transition_pair_goes_after_a_transition_step_first_with_fresh_ids() {
    let chart = two_steps();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE S:Step1 T:FALSE J:Init"
    );
    assert_eq!(chart.sequence[2].id(), ElementId(4));
    assert_eq!(chart.sequence[3].id(), ElementId(5));
    check_structure(&chart).unwrap();
}

#[test]
fn a_pair_after_a_step_puts_the_transition_first() {
    let chart = insert_step_transition_after(&two_steps(), ElementId(1)).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE S:Step2 T:FALSE S:Step1 T:FALSE J:Init"
    );
}

#[test]
fn a_pair_before_the_initial_step_makes_a_new_initial_step() {
    let chart = insert_step_transition_before(&SfcChart::new_body(), ElementId(1)).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Step1 T:FALSE S:Init T:FALSE J:Init"
    );
}

#[test]
fn nothing_goes_after_a_jump() {
    let refusal = insert_step_transition_after(&SfcChart::new_body(), ElementId(3)).unwrap_err();
    assert_eq!(
        refusal,
        SfcEditError::Structure {
            rule: SfcRule::JumpIsLast,
            element: ElementId(3)
        }
    );
    assert_eq!(
        refusal.to_string(),
        "element 3: a jump is the last element of its sequence"
    );
}

#[test]
fn an_alternative_branch_wraps_the_selected_transition_and_gets_one_on_the_right() {
    let chart = insert_alternative_branch(&two_steps(), &[ElementId(2)]).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init A[T:FALSE | T:FALSE] S:Step1 T:FALSE J:Init"
    );
    let SfcNode::Alternative(branches) = &chart.sequence[1] else {
        panic!("no alternative");
    };
    assert_eq!(branches.id, ElementId(6));
    assert_eq!(branches.branches[1].nodes[0].id(), ElementId(7));
}

#[test]
fn an_alternative_branch_around_a_step_is_refused() {
    assert_eq!(
        insert_alternative_branch(&two_steps(), &[ElementId(4)]),
        Err(SfcEditError::NotATransition(ElementId(4)))
    );
}

#[test]
fn a_run_ending_in_a_step_cannot_be_an_alternative_branch() {
    let refusal =
        insert_alternative_branch(&two_steps(), &[ElementId(2), ElementId(4)]).unwrap_err();
    assert!(matches!(
        refusal,
        SfcEditError::Structure {
            rule: SfcRule::TransitionNeedsStepAfter,
            ..
        }
    ));
}

#[test]
fn a_parallel_branch_wraps_the_selected_step_and_a_third_branch_can_be_added() {
    let chart = insert_parallel_branch(&two_steps(), &[ElementId(4)]).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE P[S:Step1 | S:Step2] T:FALSE J:Init"
    );
    let chart = add_branch(&chart, ElementId(6)).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE P[S:Step1 | S:Step2 | S:Step3] T:FALSE J:Init"
    );
}

#[test]
fn the_initial_step_cannot_open_a_parallel_branch() {
    assert_eq!(
        insert_parallel_branch(&two_steps(), &[ElementId(1)]),
        Err(SfcEditError::Structure {
            rule: SfcRule::MainStartsWithStep,
            element: ElementId(6)
        })
    );
}

#[test]
fn a_selection_that_is_not_one_run_is_refused() {
    assert_eq!(
        insert_parallel_branch(&two_steps(), &[ElementId(1), ElementId(4)]),
        Err(SfcEditError::NotARun)
    );
}

#[test]
fn a_jump_goes_only_after_the_last_transition_of_a_branch() {
    assert_eq!(
        insert_jump_after(&two_steps(), ElementId(2), "Init"),
        Err(SfcEditError::JumpNotAtEnd(ElementId(2)))
    );
    let chart = insert_alternative_branch(&two_steps(), &[ElementId(2)]).unwrap();
    let chart = insert_jump_after(&chart, ElementId(7), "init").unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init A[T:FALSE | T:FALSE J:init] S:Step1 T:FALSE J:Init"
    );
    assert_eq!(
        insert_jump_after(
            &insert_alternative_branch(&two_steps(), &[ElementId(2)]).unwrap(),
            ElementId(7),
            "Nowhere"
        ),
        Err(SfcEditError::UnknownStep("Nowhere".into()))
    );
}

#[test]
fn a_jump_target_is_set_to_an_existing_step_only() {
    let chart = set_jump_target(&two_steps(), ElementId(3), "Step1").unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE S:Step1 T:FALSE J:Step1"
    );
    assert_eq!(
        set_jump_target(&two_steps(), ElementId(3), "Other"),
        Err(SfcEditError::UnknownStep("Other".into()))
    );
    assert_eq!(
        set_jump_target(&two_steps(), ElementId(2), "Init"),
        Err(SfcEditError::NotAJump(ElementId(2)))
    );
}

#[test]
fn a_macro_step_is_inserted_holding_one_step_and_a_run_is_wrapped_into_one() {
    let chart = insert_macro_step_after(&two_steps(), ElementId(2)).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE M:Macro1(S:Step2) T:FALSE S:Step1 T:FALSE J:Init"
    );
    let chart = insert_step_transition_after(&two_steps(), ElementId(4)).unwrap();
    let wrapped = wrap_in_macro(&chart, &[ElementId(4), ElementId(7), ElementId(6)]).unwrap();
    assert_eq!(
        shape(&wrapped.sequence),
        "S:Init T:FALSE M:Macro1(S:Step1 T:FALSE S:Step2) T:FALSE J:Init"
    );
    assert_eq!(
        wrap_in_macro(&chart, &[ElementId(4), ElementId(7)]),
        // The refusal names the node out of place (the step after the macro step), as the
        // load message does.
        Err(SfcEditError::Structure {
            rule: SfcRule::StepNeedsTransitionAfter,
            element: ElementId(6)
        })
    );
}

#[test]
fn deleting_a_step_takes_its_transition_with_it() {
    let chart = delete_nodes(&two_steps(), &[ElementId(4)]).unwrap();
    assert_eq!(shape(&chart.sequence), "S:Init T:FALSE J:Init");
    let chart = delete_nodes(&two_steps(), &[ElementId(2)]).unwrap();
    assert_eq!(shape(&chart.sequence), "S:Init T:FALSE J:Init");
    assert_eq!(chart.sequence[1].id(), ElementId(5));
}

#[test]
fn deleting_the_last_jump_is_refused_with_the_rule() {
    let refusal = delete_nodes(&two_steps(), &[ElementId(3)]).unwrap_err();
    assert_eq!(
        refusal,
        SfcEditError::Structure {
            rule: SfcRule::MainEndsWithJump,
            element: ElementId(5)
        }
    );
}

#[test]
fn deleting_a_step_a_jump_targets_is_refused() {
    assert_eq!(
        delete_nodes(&two_steps(), &[ElementId(1)]),
        Err(SfcEditError::UnknownStep("Init".into()))
    );
}

#[test]
fn deleting_the_step_of_a_lone_transition_is_refused_as_it_needs_a_transition() {
    let refusal = delete_nodes(&SfcChart::new_body(), &[ElementId(2)]).unwrap_err();
    assert!(matches!(
        refusal,
        SfcEditError::Structure { .. } | SfcEditError::UnknownStep(_)
    ));
}

#[test]
fn deleting_a_branch_of_two_dissolves_the_branch() {
    let chart = insert_parallel_branch(&two_steps(), &[ElementId(4)]).unwrap();
    let chart = delete_nodes(&chart, &[ElementId(7)]).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE S:Step1 T:FALSE J:Init"
    );
    let chart = insert_alternative_branch(&two_steps(), &[ElementId(2)]).unwrap();
    let chart = delete_nodes(&chart, &[ElementId(7)]).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE S:Step1 T:FALSE J:Init"
    );
}

#[test]
fn deleting_the_last_step_of_a_parallel_branch_takes_the_transition_before_it() {
    let chart = insert_parallel_branch(&two_steps(), &[ElementId(4)]).unwrap();
    let chart = insert_step_transition_after(&chart, ElementId(7)).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE P[S:Step1 | S:Step2 T:FALSE S:Step3] T:FALSE J:Init"
    );
    let step3 = id_of(&chart, "Step3");
    let chart = delete_nodes(&chart, &[step3]).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE P[S:Step1 | S:Step2] T:FALSE J:Init"
    );
}

#[test]
fn deleting_a_whole_branch_takes_what_is_inside_it() {
    let chart = insert_parallel_branch(&two_steps(), &[ElementId(4)]).unwrap();
    let chart = delete_nodes(&chart, &[ElementId(6), ElementId(4), ElementId(7)]).unwrap();
    assert_eq!(shape(&chart.sequence), "S:Init T:FALSE J:Init");
}

#[test]
fn renaming_a_step_renames_the_jumps_to_it_and_refuses_duplicates() {
    let chart = rename_step(&two_steps(), ElementId(1), "Start").unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Start T:FALSE S:Step1 T:FALSE J:Start"
    );
    assert_eq!(
        rename_step(&two_steps(), ElementId(1), "STEP1"),
        Err(SfcEditError::DuplicateName("STEP1".into()))
    );
    assert_eq!(
        rename_step(&two_steps(), ElementId(1), "a b"),
        Err(SfcEditError::InvalidName("a b".into()))
    );
    assert_eq!(
        rename_step(&two_steps(), ElementId(1), "x__y"),
        Err(SfcEditError::InvalidName("x__y".into()))
    );
    assert_eq!(
        rename_step(&two_steps(), ElementId(2), "X"),
        Err(SfcEditError::NotAStep(ElementId(2)))
    );
}

#[test]
fn conditions_and_priorities_are_set_and_an_empty_condition_is_refused() {
    let chart =
        set_transition_condition(&two_steps(), ElementId(2), " start AND NOT stop ").unwrap();
    let chart = set_transition_priority(&chart, ElementId(2), Some(3)).unwrap();
    let Some(SfcNode::Transition(transition)) = find_node(&chart, ElementId(2)) else {
        panic!("no transition");
    };
    assert_eq!(transition.condition, "start AND NOT stop");
    assert_eq!(transition.priority, Some(3));
    assert_eq!(
        set_transition_condition(&chart, ElementId(2), "  "),
        Err(SfcEditError::EmptyCondition(ElementId(2)))
    );
}

fn association(
    action: &str,
    qualifier: ActionQualifier,
    duration: Option<&str>,
) -> ActionAssociation {
    ActionAssociation {
        action: action.into(),
        qualifier,
        duration: duration.map(Into::into),
        indicator: None,
    }
}

#[test]
fn associations_are_added_changed_moved_and_removed() {
    let chart = add_association(
        &two_steps(),
        ElementId(4),
        association("Fill", ActionQualifier::N, None),
    )
    .unwrap();
    let chart = add_association(
        &chart,
        ElementId(4),
        association("Heat", ActionQualifier::L, Some("T#2s")),
    )
    .unwrap();
    let chart = move_association(&chart, ElementId(4), 1, 0).unwrap();
    let chart = set_association(
        &chart,
        ElementId(4),
        1,
        association("Drain", ActionQualifier::S, None),
    )
    .unwrap();
    let Some(SfcNode::Step(step)) = find_node(&chart, ElementId(4)) else {
        panic!("no step");
    };
    let actions: Vec<&str> = step.actions.iter().map(|a| a.action.as_str()).collect();
    assert_eq!(actions, ["Heat", "Drain"]);
    let chart = remove_association(&chart, ElementId(4), 0).unwrap();
    let Some(SfcNode::Step(step)) = find_node(&chart, ElementId(4)) else {
        panic!("no step");
    };
    assert_eq!(step.actions.len(), 1);
    assert_eq!(
        remove_association(&chart, ElementId(4), 5),
        Err(SfcEditError::NoSuchAssociation {
            step: ElementId(4),
            index: 5
        })
    );
}

#[test]
fn a_timed_qualifier_needs_a_time_and_an_untimed_one_takes_none() {
    assert_eq!(
        add_association(
            &two_steps(),
            ElementId(4),
            association("Fill", ActionQualifier::D, None)
        ),
        Err(SfcEditError::MissingDuration("D"))
    );
    assert_eq!(
        add_association(
            &two_steps(),
            ElementId(4),
            association("Fill", ActionQualifier::N, Some("T#1s"))
        ),
        Err(SfcEditError::UnexpectedDuration("N"))
    );
    assert_eq!(
        add_association(
            &two_steps(),
            ElementId(4),
            association(" ", ActionQualifier::N, None)
        ),
        Err(SfcEditError::EmptyAction)
    );
}

#[test]
fn step_properties_store_empty_texts_as_none() {
    let properties = StepProperties {
        min_time: Some("T#1s".into()),
        max_time: Some(" ".into()),
        entry_action: Some("Enter".into()),
        ..StepProperties::default()
    };
    let chart = set_step_properties(&two_steps(), ElementId(4), properties).unwrap();
    let Some(SfcNode::Step(step)) = find_node(&chart, ElementId(4)) else {
        panic!("no step");
    };
    assert_eq!(step.min_time.as_deref(), Some("T#1s"));
    assert_eq!(step.max_time, None);
    assert_eq!(step.entry_action.as_deref(), Some("Enter"));
}

#[test]
fn a_pasted_pair_gets_fresh_ids_and_unique_names() {
    let chart = two_steps();
    let copied = copy_nodes(&chart, &[ElementId(4), ElementId(5)]).unwrap();
    let pasted = paste_after(&chart, ElementId(4), &copied).unwrap_err();
    assert!(matches!(
        pasted,
        SfcEditError::Structure {
            rule: SfcRule::StepNeedsTransitionAfter,
            ..
        }
    ));
    let chart = paste_after(&chart, ElementId(2), &copied).unwrap();
    assert_eq!(
        shape(&chart.sequence),
        "S:Init T:FALSE S:Step2 T:FALSE S:Step1 T:FALSE J:Init"
    );
    assert_eq!(chart.sequence[2].id(), ElementId(6));
    assert_eq!(chart.sequence[3].id(), ElementId(7));
    assert_eq!(max_sfc_id(&chart), 7);
}

#[test]
fn the_new_chart_passes_the_structure_check_and_broken_ones_do_not() {
    check_structure(&SfcChart::new_body()).unwrap();
    let mut chart = SfcChart::new_body();
    chart.sequence.pop();
    assert_eq!(
        check_structure(&chart),
        Err(SfcEditError::Structure {
            rule: SfcRule::MainEndsWithJump,
            element: ElementId(2)
        })
    );
    let mut chart = SfcChart::new_body();
    chart.sequence.remove(1);
    assert_eq!(
        check_structure(&chart),
        Err(SfcEditError::Structure {
            rule: SfcRule::StepNeedsTransitionAfter,
            element: ElementId(3)
        })
    );
    assert_eq!(step_names(&two_steps()), ["Init", "Step1"]);
}

/// A chart whose second node is `middle`, between the initial step and a jump back to it.
fn chart_around(middle: Vec<SfcNode>) -> SfcChart {
    let mut chart = SfcChart::new_body();
    chart.sequence.splice(1..2, middle);
    chart
}

fn step(id: u32, name: &str) -> SfcNode {
    SfcNode::step(ElementId(id), name)
}

fn transition(id: u32) -> SfcNode {
    SfcNode::Transition(crate::sfc::Transition {
        id: ElementId(id),
        condition: "TRUE".into(),
        ..crate::sfc::Transition::default()
    })
}

fn branches(id: u32, branches: Vec<Vec<SfcNode>>) -> crate::sfc::SfcBranches {
    crate::sfc::SfcBranches::new(ElementId(id), branches)
}

#[track_caller]
fn broken_rule(chart: &SfcChart) -> SfcRule {
    match check_structure(chart) {
        Err(SfcEditError::Structure { rule, .. }) => rule,
        other => panic!("expected a broken rule, got {other:?}"),
    }
}

#[test]
fn each_branch_rule_is_named() {
    let one_branch = chart_around(vec![SfcNode::Alternative(branches(
        10,
        vec![vec![transition(11)]],
    ))]);
    assert_eq!(broken_rule(&one_branch), SfcRule::TwoBranches);
    let step_first = chart_around(vec![SfcNode::Alternative(branches(
        10,
        vec![vec![transition(11)], vec![step(12, "A"), transition(13)]],
    ))]);
    assert_eq!(
        broken_rule(&step_first),
        SfcRule::AlternativeBeginsWithTransition
    );
    let parallel_ends_in_transition = chart_around(vec![
        transition(9),
        SfcNode::Parallel(branches(
            10,
            vec![vec![step(11, "A")], vec![step(12, "B"), transition(13)]],
        )),
        transition(14),
    ]);
    assert_eq!(
        broken_rule(&parallel_ends_in_transition),
        SfcRule::ParallelEndsWithStep
    );
}

#[test]
fn a_macro_step_holds_no_jump_and_begins_with_a_step() {
    let macro_chart = chart_around(vec![
        transition(9),
        SfcNode::Macro(crate::sfc::MacroStep {
            id: ElementId(10),
            name: "M".into(),
            comment: String::new(),
            body: vec![step(11, "A"), transition(12), step(13, "B")],
        }),
        transition(14),
    ]);
    check_structure(&macro_chart).unwrap();
    let mut broken = macro_chart.clone();
    if let SfcNode::Macro(macro_step) = &mut broken.sequence[2] {
        macro_step.body = vec![transition(11)];
    }
    assert_eq!(broken_rule(&broken), SfcRule::MacroBeginsAndEndsWithStep);
    let mut jumping = macro_chart.clone();
    if let SfcNode::Macro(macro_step) = &mut jumping.sequence[2] {
        macro_step.body = vec![
            step(11, "A"),
            SfcNode::Alternative(branches(
                15,
                vec![
                    vec![
                        transition(16),
                        SfcNode::Jump(crate::sfc::Jump {
                            id: ElementId(17),
                            target: "A".into(),
                        }),
                    ],
                    vec![transition(18)],
                ],
            )),
            step(13, "B"),
        ];
    }
    assert_eq!(broken_rule(&jumping), SfcRule::NoJumpInMacro);
    let duplicate = chart_around(vec![transition(9), step(10, "INIT"), transition(11)]);
    assert_eq!(
        check_structure(&duplicate),
        // The first of the two steps sharing the name is named, as loading reports it first.
        Err(SfcEditError::DuplicateName("Init".into()))
    );
}
