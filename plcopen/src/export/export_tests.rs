//! Tests of the whole export over small projects.

use project_model::{Body, Node, Object, Pou, PouKind, Project, Variable};

use super::export;

fn small_project() -> Project {
    let mut project = Project {
        name: "Demo".into(),
        ..Project::default()
    };
    let mut main = Pou {
        name: "Main".into(),
        kind: PouKind::Program,
        return_type: None,
        extends: None,
        implements: Vec::new(),
        comment: "The main program".into(),
        variables: vec![Variable::new("count", "INT")],
        body: Body::st("count := count + 1;\n"),
        methods: Vec::new(),
        properties: Vec::new(),
        actions: Vec::new(),
        transitions: Vec::new(),
    };
    main.variables[0].initial = Some("5".into());
    project
        .application
        .children
        .push(Node::Object(Object::Pou(main)));
    project
}

#[test]
fn the_same_project_gives_the_same_bytes() {
    let project = small_project();
    assert_eq!(export(&project).unwrap(), export(&project).unwrap());
}

#[test]
fn the_export_is_read_back_by_the_reader() {
    let bytes = export(&small_project()).unwrap();
    let document = crate::read_bytes(&bytes, "demo.xml").unwrap();
    assert_eq!(document.pous.len(), 1);
    assert_eq!(document.pous[0].name, "Main");
    assert_eq!(document.content_header.name, "Demo");
}
