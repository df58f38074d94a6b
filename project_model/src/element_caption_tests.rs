//! Tests of element captions, on the example project's LD and CFC bodies.

use serde::Deserialize;

use crate::{Body, ElementId};

/// The body of a `.pou.toml` file; the rest of the file is not needed here.
#[derive(Deserialize)]
struct PouFile {
    body: Body,
}

fn body_of(text: &str) -> Body {
    toml::from_str::<PouFile>(text)
        .map(|file| file.body)
        .unwrap()
}

#[test]
fn ld_elements_are_named_by_their_variable_box_instance_or_nothing() {
    let body = body_of(include_str!(
        "../../assets/examples/packaging_machine/application/Interlock.pou.toml"
    ));
    let caption = |network, id| body.element_caption(network, ElementId(id));
    assert_eq!(caption(0, 1).as_deref(), Some("GVL_IO.xStartButton"));
    assert_eq!(caption(0, 4).as_deref(), Some("xRunRequest"));
    assert_eq!(caption(2, 11).as_deref(), Some("tonStartWarning: TON"));
    // A parallel group names nothing; an id of another network is not found in this one.
    assert_eq!(caption(1, 5), None);
    assert_eq!(caption(0, 13), None);
    assert_eq!(caption(9, 1), None);
}

#[test]
fn cfc_elements_are_named_by_their_expression_or_box_type() {
    let body = body_of(include_str!(
        "../../assets/examples/packaging_machine/application/TempControl.pou.toml"
    ));
    let caption = |id| body.element_caption(0, ElementId(id));
    assert_eq!(caption(2).as_deref(), Some("SUB"));
    assert_eq!(caption(9).as_deref(), Some("rHeater"));
    assert_eq!(caption(1).as_deref(), Some("rSetpoint"));
    // A comment names nothing.
    assert_eq!(caption(13), None);
}

#[test]
fn a_pou_finds_its_own_and_its_members_bodies_by_name() {
    let pou: crate::Pou = toml::from_str(include_str!(
        "../../assets/examples/packaging_machine/application/PackCycle.pou.toml"
    ))
    .unwrap();
    assert!(matches!(pou.body_named(""), Some(Body::Sfc { .. })));
    assert!(pou.body_named("CountPackage").is_some());
    assert!(pou.body_named("Missing").is_none());
    assert!(pou.body_named("Missing.get").is_none());
}
