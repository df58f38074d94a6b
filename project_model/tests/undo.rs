//! Property test: applying any edit and then its inverse restores the project exactly, and a
//! failing edit leaves it untouched.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use proptest::prelude::*;
use proptest::sample::Index;

use project_model::arb;
use project_model::{
    Axis, Body, Controller, Dialect, Edit, History, IoArea, ListEdit, ModbusDevice, Node, Object,
    Project, SerialPort, Task, TextTarget, TreeEdit, VarOwner, Variable, max_element_id,
};

/// A list edit on a list of `len` items, with indices chosen by `index`.
fn list_edit<T: Arbitrary + Clone + std::fmt::Debug + 'static>(
    len: usize,
) -> impl Strategy<Value = ListEdit<T>> {
    let pick = move |index: Index, extra: usize| index.index(len + extra);
    prop_oneof![
        (any::<Index>(), any::<T>()).prop_map(move |(i, item)| ListEdit::Insert {
            index: pick(i, 1),
            item
        }),
        any::<Index>().prop_map(move |i| ListEdit::Remove { index: pick(i, 1) }),
        (any::<Index>(), any::<T>()).prop_map(move |(i, item)| ListEdit::Replace {
            index: pick(i, 1),
            item
        }),
        (any::<Index>(), any::<Index>()).prop_map(move |(a, b)| ListEdit::Move {
            from: pick(a, 1),
            to: pick(b, 1)
        }),
    ]
}

/// Every folder path of the tree, the root first.
fn folder_paths(project: &Project) -> Vec<Vec<String>> {
    fn walk(folder: &project_model::Folder, path: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
        out.push(path.clone());
        for node in &folder.children {
            if let Node::Folder(child) = node {
                path.push(child.name.clone());
                walk(child, path, out);
                path.pop();
            }
        }
    }
    let mut out = Vec::new();
    walk(&project.application, &mut Vec::new(), &mut out);
    out
}

/// An edit that fits `project` most of the time; some are invalid on purpose (an index past
/// the end, a name already taken, a folder moved into itself) to check that failures change
/// nothing.
fn edit_for(project: &Project) -> BoxedStrategy<Edit> {
    let folders = folder_paths(project);
    let object_names: Vec<String> = project
        .application
        .objects()
        .iter()
        .map(|object| object.name().to_owned())
        .collect();
    let pou_texts: Vec<(String, usize)> = project
        .application
        .objects()
        .iter()
        .filter_map(|object| match object {
            Object::Pou(pou) => pou
                .body
                .st_text()
                .map(|text| (pou.name.clone(), text.len())),
            _ => None,
        })
        .collect();
    let var_owners: Vec<(VarOwner, usize)> = project
        .application
        .objects()
        .iter()
        .filter_map(|object| match object {
            Object::Pou(pou) => Some((VarOwner::Pou(pou.name.clone()), pou.variables.len())),
            Object::Gvl(gvl) => Some((VarOwner::Gvl(gvl.name.clone()), gvl.variables.len())),
            _ => None,
        })
        .collect();
    // Every POU body, with its number of networks (0 for ST) and the id above its elements'.
    let bodies: Vec<(TextTarget, usize, u32)> = project
        .application
        .objects()
        .iter()
        .filter_map(|object| match object {
            Object::Pou(pou) => Some(match &pou.body {
                Body::Ld { networks } | Body::Fbd { networks } => (
                    TextTarget::Pou(pou.name.clone()),
                    networks.len(),
                    max_element_id(networks).0 + 1,
                ),
                _ => (TextTarget::Pou(pou.name.clone()), 0, 1),
            }),
            _ => None,
        })
        .collect();
    let objects: Vec<Object> = project.application.objects().into_iter().cloned().collect();
    let child_counts: Vec<usize> = folders
        .iter()
        .map(|path| {
            project
                .application
                .folder(path)
                .map_or(0, |folder| folder.children.len())
        })
        .collect();

    let folders_a = folders.clone();
    let counts_a = child_counts.clone();
    let tree_insert = (
        any::<Index>(),
        any::<Index>(),
        any::<Object>(),
        "[A-Z][a-z]{0,4}",
    )
        .prop_map(move |(f, i, mut object, name)| {
            let folder_index = f.index(folders_a.len());
            // Fresh names do not collide with generated ones, which all contain a `_`.
            object.set_name(format!("New{name}"));
            Edit::Tree(TreeEdit::Insert {
                folder: folders_a[folder_index].clone(),
                index: i.index(counts_a[folder_index] + 1),
                node: Node::Object(object),
            })
        });
    let folders_b = folders.clone();
    let counts_b = child_counts.clone();
    let tree_remove = (any::<Index>(), any::<Index>()).prop_map(move |(f, i)| {
        let folder_index = f.index(folders_b.len());
        Edit::Tree(TreeEdit::Remove {
            folder: folders_b[folder_index].clone(),
            index: i.index(counts_b[folder_index] + 1),
        })
    });
    let folders_c = folders.clone();
    let counts_c = child_counts.clone();
    let tree_move = (
        any::<Index>(),
        any::<Index>(),
        any::<Index>(),
        any::<Index>(),
    )
        .prop_map(move |(f, i, g, j)| {
            let from = f.index(folders_c.len());
            let to = g.index(folders_c.len());
            Edit::Tree(TreeEdit::Move {
                from_folder: folders_c[from].clone(),
                from_index: i.index(counts_c[from] + 1),
                to_folder: folders_c[to].clone(),
                to_index: j.index(counts_c[to] + 1),
            })
        });
    let folders_d = folders;
    let counts_d = child_counts;
    let names_d = object_names;
    let tree_rename = (
        any::<Index>(),
        any::<Index>(),
        any::<Index>(),
        "[A-Z][a-z]{0,4}",
        any::<bool>(),
    )
        .prop_map(move |(f, i, n, fresh, reuse)| {
            let folder_index = f.index(folders_d.len());
            // Sometimes reuse an existing name, which must be refused.
            let name = if reuse && !names_d.is_empty() {
                names_d[n.index(names_d.len())].clone()
            } else {
                format!("Renamed{fresh}")
            };
            Edit::Tree(TreeEdit::Rename {
                folder: folders_d[folder_index].clone(),
                index: i.index(counts_d[folder_index] + 1),
                name,
            })
        });
    // Mostly a new version of an existing object of the same kind; sometimes another kind or
    // a missing name, which must be refused.
    let replace_object = (any::<Index>(), any::<Object>(), any::<bool>()).prop_map(
        move |(n, mut object, same_kind)| {
            if let Some(old) = (!objects.is_empty()).then(|| &objects[n.index(objects.len())]) {
                if same_kind {
                    object = old.clone();
                    if let Object::Pou(pou) = &mut object {
                        pou.comment.push_str(" changed");
                    }
                    if let Object::Gvl(gvl) = &mut object {
                        gvl.comment.push_str(" changed");
                    }
                }
                object.set_name(old.name().to_owned());
            }
            Edit::ReplaceObject(object)
        },
    );
    let owners = var_owners;
    let variables = any::<Index>().prop_flat_map(move |n| {
        let (owner, len) = if owners.is_empty() {
            (VarOwner::Pou("Missing".into()), 0)
        } else {
            owners[n.index(owners.len())].clone()
        };
        list_edit::<Variable>(len).prop_map(move |edit| Edit::Variables {
            owner: owner.clone(),
            edit,
        })
    });
    let texts = pou_texts;
    let replace_text = (any::<Index>(), any::<Index>(), any::<Index>(), arb::text()).prop_map(
        move |(n, a, b, text)| {
            let (pou, len) = if texts.is_empty() {
                ("Missing".to_owned(), 0)
            } else {
                texts[n.index(texts.len())].clone()
            };
            // Byte offsets may fall inside a character, which must be refused.
            let (a, b) = (a.index(len + 1), b.index(len + 1));
            Edit::ReplaceText {
                target: TextTarget::Pou(pou),
                range: a.min(b)..a.max(b),
                text,
            }
        },
    );

    // Mostly a splice inside an LD/FBD body; sometimes past its end, into an ST body, or with
    // labels that clash, which must be refused.
    let splice_networks = any::<Index>().prop_flat_map(move |n| {
        let (target, len, next_id) = if bodies.is_empty() {
            (TextTarget::Pou("Missing".into()), 0, 1)
        } else {
            bodies[n.index(bodies.len())].clone()
        };
        (0..len + 2, 0..3usize, arb::networks_from(next_id)).prop_map(
            move |(at, remove, insert)| Edit::SpliceNetworks {
                target: target.clone(),
                at,
                remove,
                insert,
            },
        )
    });

    let single = prop_oneof![
        (arb::text(), arb::text())
            .prop_map(|(name, description)| Edit::SetProjectInfo { name, description }),
        any::<Controller>().prop_map(Edit::SetController),
        any::<Dialect>().prop_map(Edit::SetDialect),
        list_edit::<Task>(project.tasks.len()).prop_map(Edit::Tasks),
        list_edit::<IoArea>(project.io_areas.len()).prop_map(Edit::IoAreas),
        list_edit::<SerialPort>(project.serial_ports.len()).prop_map(Edit::SerialPorts),
        list_edit::<ModbusDevice>(project.modbus_devices.len()).prop_map(Edit::ModbusDevices),
        list_edit::<Axis>(project.axes.len()).prop_map(Edit::Axes),
        tree_insert,
        tree_remove,
        tree_move,
        tree_rename,
        replace_object,
        variables,
        replace_text,
        splice_networks,
    ]
    .boxed();
    prop_oneof![
        4 => single.clone(),
        1 => proptest::collection::vec(single, 2..4).prop_map(Edit::Group),
    ]
    .boxed()
}

fn project_and_edit() -> impl Strategy<Value = (Project, Edit)> {
    arb::project().prop_flat_map(|project| {
        let edit = edit_for(&project);
        (Just(project), edit)
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn applying_an_edit_then_its_inverse_restores_the_project((project, edit) in project_and_edit()) {
        let mut edited = project.clone();
        match edit.apply(&mut edited) {
            Ok(inverse) => {
                let redo = inverse.apply(&mut edited).expect("an inverse always applies");
                prop_assert_eq!(&edited, &project);
                // The inverse of the inverse redoes the edit.
                let mut redone = project.clone();
                let again = redo.apply(&mut redone).expect("a redo always applies");
                again.apply(&mut redone).expect("and undoes again");
                prop_assert_eq!(&redone, &project);
            }
            Err(_) => prop_assert_eq!(&edited, &project),
        }
    }

    #[test]
    fn history_undo_and_redo_walk_back_and_forth((project, edit) in project_and_edit()) {
        let mut edited = project.clone();
        let mut history = History::new();
        if history.apply(&mut edited, "edit", vec![edit]).is_ok() {
            let after = edited.clone();
            prop_assert!(history.undo(&mut edited).unwrap().is_some());
            prop_assert_eq!(&edited, &project);
            prop_assert!(!history.is_dirty());
            prop_assert!(history.redo(&mut edited).unwrap().is_some());
            prop_assert_eq!(&edited, &after);
        } else {
            prop_assert_eq!(&edited, &project);
            prop_assert!(!history.is_dirty());
        }
    }
}
