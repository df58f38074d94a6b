use crate::{
    Body, Coil, Edit, EditError, ElementId, FlowNode, Method, Network, NetworkOutput, Node, Object,
    Operand, Pou, PouKind, Project, TextTarget,
};

/// A network with a contact and a coil of ids `id` and `id + 1`, labelled `label`.
fn network(id: u32, label: &str) -> Network {
    Network {
        label: label.into(),
        rung: vec![FlowNode::Operand(Operand {
            id: ElementId(id),
            text: "a".into(),
            ..Operand::default()
        })],
        outputs: vec![NetworkOutput::Coil(Coil {
            id: ElementId(id + 1),
            variable: "q".into(),
            ..Coil::default()
        })],
        ..Network::default()
    }
}

/// A project with LD program `Main` (networks A, B, C) whose method `Reset` is FBD with one
/// network, and ST program `Text`.
fn project() -> Project {
    let main = Pou {
        name: "Main".into(),
        kind: PouKind::FunctionBlock,
        return_type: None,
        extends: None,
        implements: Vec::new(),
        comment: String::new(),
        variables: Vec::new(),
        body: Body::Ld {
            networks: vec![network(1, "A"), network(3, "B"), network(5, "C")],
        },
        methods: vec![Method {
            name: "Reset".into(),
            return_type: None,
            access: Default::default(),
            is_abstract: false,
            comment: String::new(),
            variables: Vec::new(),
            body: Body::Fbd {
                networks: vec![network(1, "")],
            },
        }],
        properties: Vec::new(),
        actions: Vec::new(),
        transitions: Vec::new(),
    };
    let text = Pou {
        name: "Text".into(),
        body: Body::St {
            text: "x := 1;".into(),
        },
        methods: Vec::new(),
        ..main.clone()
    };
    let mut project = Project::default();
    project.application.children = vec![
        Node::Object(Object::Pou(main)),
        Node::Object(Object::Pou(text)),
    ];
    project
}

fn labels(project: &Project) -> Vec<String> {
    match project.application.object("Main") {
        Some(Object::Pou(Pou {
            body: Body::Ld { networks },
            ..
        })) => networks.iter().map(|n| n.label.clone()).collect(),
        other => panic!("{other:?}"),
    }
}

fn splice(target: TextTarget, at: usize, remove: usize, insert: Vec<Network>) -> Edit {
    Edit::SpliceNetworks {
        target,
        at,
        remove,
        insert,
    }
}

fn main() -> TextTarget {
    TextTarget::Pou("Main".into())
}

#[test]
fn a_splice_replaces_networks_and_its_inverse_puts_them_back() {
    let mut edited = project();
    let inverse = splice(main(), 1, 1, vec![network(7, "X"), network(9, "Y")])
        .apply(&mut edited)
        .unwrap();
    assert_eq!(labels(&edited), ["A", "X", "Y", "C"]);
    assert_eq!(
        inverse,
        splice(main(), 1, 2, vec![network(3, "B")]),
        "the inverse removes what was inserted and inserts what was removed"
    );
    let redo = inverse.apply(&mut edited).unwrap();
    assert_eq!(edited, project());
    redo.apply(&mut edited).unwrap();
    assert_eq!(labels(&edited), ["A", "X", "Y", "C"]);
}

#[test]
fn inserting_deleting_and_editing_a_method_body_are_splices() {
    let reset = TextTarget::Method {
        pou: "Main".into(),
        method: "Reset".into(),
    };
    let mut edited = project();
    let undo_insert = splice(reset.clone(), 1, 0, vec![network(3, "")])
        .apply(&mut edited)
        .unwrap();
    let undo_delete = splice(reset.clone(), 0, 1, Vec::new())
        .apply(&mut edited)
        .unwrap();
    undo_delete.apply(&mut edited).unwrap();
    undo_insert.apply(&mut edited).unwrap();
    assert_eq!(edited, project());
    let mut appended = project();
    splice(main(), 3, 0, vec![network(11, "")])
        .apply(&mut appended)
        .unwrap();
    assert_eq!(labels(&appended), ["A", "B", "C", ""]);
}

#[track_caller]
fn refused(edit: Edit, expected: EditError) {
    let mut edited = project();
    assert_eq!(edit.apply(&mut edited), Err(expected));
    assert_eq!(edited, project(), "a refused splice changed the project");
}

#[test]
fn a_body_that_is_not_ld_or_fbd_or_a_range_past_its_end_is_refused() {
    refused(
        splice(
            TextTarget::Pou("Text".into()),
            0,
            0,
            vec![Network::default()],
        ),
        EditError::NotNetworks("'Text'".into()),
    );
    refused(
        splice(main(), 2, 2, Vec::new()),
        EditError::NetworkRangeOutOfRange {
            at: 2,
            remove: 2,
            len: 3,
        },
    );
    refused(
        splice(main(), usize::MAX, 2, Vec::new()),
        EditError::NetworkRangeOutOfRange {
            at: usize::MAX,
            remove: 2,
            len: 3,
        },
    );
    refused(
        splice(TextTarget::Pou("Missing".into()), 0, 0, Vec::new()),
        EditError::NoSuchObject("Missing".into()),
    );
}

#[test]
fn a_splice_that_would_break_the_body_is_refused_with_the_element() {
    refused(
        splice(main(), 1, 0, vec![network(5, "")]),
        EditError::InvalidObject(
            "'Main': network 4 'C', element 5: two elements have the id 5; the other is in \
             network 2"
                .into(),
        ),
    );
    refused(
        splice(main(), 0, 1, vec![network(20, "c")]),
        EditError::InvalidObject(
            "'Main': network 3 'C': the label 'C' is also the label of network 1".into(),
        ),
    );
}
