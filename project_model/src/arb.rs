//! Proptest strategies for the model, used by the round-trip and undo property tests.
//!
//! The model types derive `Arbitrary` when the `proptest` feature is on; these helpers keep the
//! generated values within what a project file can hold (identifiers for names, finite numbers,
//! short lists) and [`project`] makes the names in a project unique as the loader requires.

use proptest::prelude::*;

use crate::{Body, Folder, GlobalVarList, Node, Object, Pou, Project};

/// An IEC identifier of one to eight characters, sometimes with a Chinese letter.
pub fn ident() -> impl Strategy<Value = String> {
    "[A-Za-z_输送][A-Za-z0-9_带]{0,7}"
}

/// A finite `f64`; NaN would make equality checks meaningless.
pub fn finite() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        -1.0e6..1.0e6f64,
        proptest::num::f64::NORMAL | proptest::num::f64::ZERO,
    ]
}

/// A list of at most three elements, to keep nested structures small.
pub fn small_vec<T: Arbitrary>() -> impl Strategy<Value = Vec<T>> {
    proptest::collection::vec(any::<T>(), 0..3)
}

/// A list of at most three identifiers.
pub fn ident_vec() -> impl Strategy<Value = Vec<String>> {
    proptest::collection::vec(ident(), 0..3)
}

/// Free text, including line breaks, quotes and non-ASCII characters.
pub fn text() -> impl Strategy<Value = String> {
    prop_oneof![Just(String::new()), "[ -~\n\t\"'\\\\中文]{0,40}"]
}

/// An optional short text.
pub fn opt_text() -> impl Strategy<Value = Option<String>> {
    proptest::option::of(text())
}

/// A folder holding only objects, so generated trees stay finite.
pub fn leaf_folder() -> impl Strategy<Value = Folder> {
    let children = proptest::collection::vec(any::<Object>().prop_map(Node::Object), 0..3);
    (ident(), children).prop_map(|(name, children)| Folder { name, children })
}

/// A project whose object and folder names are unique, as a loaded project's are. It always
/// holds at least one POU with an ST body and one global variable list, so text and variable
/// edits have something to work on.
pub fn project() -> impl Strategy<Value = Project> {
    (
        any::<Project>(),
        any::<Pou>(),
        any::<GlobalVarList>(),
        text(),
    )
        .prop_map(|(mut project, mut pou, gvl, body)| {
            pou.body = Body::St { text: body };
            project
                .application
                .children
                .push(Node::Object(Object::Pou(pou)));
            project
                .application
                .children
                .push(Node::Object(Object::Gvl(gvl)));
            // The root folder is the application itself; its name is not stored.
            project.application.name.clear();
            let mut counter = 0usize;
            make_names_unique(&mut project.application, &mut counter);
            project
        })
}

/// Appends a running number to every name in the tree, so no two objects or folders collide.
fn make_names_unique(folder: &mut Folder, counter: &mut usize) {
    for node in &mut folder.children {
        *counter += 1;
        match node {
            Node::Folder(child) => {
                child.name = format!("{}_{counter}", child.name);
                make_names_unique(child, counter);
            }
            Node::Object(object) => {
                let name = format!("{}_{counter}", object.name());
                object.set_name(name);
                if let Object::Pou(pou) = object {
                    make_member_names_unique(pou);
                }
            }
        }
    }
}

/// Methods, properties and actions get files named after them, so their names must differ too.
fn make_member_names_unique(pou: &mut Pou) {
    let names = pou
        .methods
        .iter_mut()
        .map(|method| &mut method.name)
        .chain(pou.properties.iter_mut().map(|property| &mut property.name))
        .chain(pou.actions.iter_mut().map(|action| &mut action.name));
    for (index, name) in names.enumerate() {
        *name = format!("{name}_{index}");
    }
}
