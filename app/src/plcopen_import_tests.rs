//! Writing an imported project into a new folder: only into a missing or empty one, and nothing
//! left behind when it fails.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use project_model::{GlobalVarList, Node, Object, Project};

use super::*;

fn project_with_list(name: &str) -> Project {
    let mut project = Project {
        name: "Imported".into(),
        ..Project::default()
    };
    project
        .application
        .children
        .push(Node::Object(Object::Gvl(GlobalVarList {
            name: name.into(),
            ..GlobalVarList::default()
        })));
    project
}

#[test]
fn a_new_project_is_written_into_a_missing_or_empty_folder_and_nothing_else_is_left() {
    let temp = tempfile::tempdir().unwrap();
    let missing = temp.path().join("missing");
    write_new_project(&project_with_list("Globals"), &missing).unwrap();
    assert!(missing.join("application/Globals.gvl.toml").is_file());
    let empty = temp.path().join("empty");
    std::fs::create_dir(&empty).unwrap();
    write_new_project(&project_with_list("Globals"), &empty).unwrap();
    assert!(empty.join("rivet.toml").is_file());
    // No staging folder stays beside them.
    assert_eq!(std::fs::read_dir(temp.path()).unwrap().count(), 2);
}

#[test]
fn a_project_that_cannot_be_saved_leaves_neither_the_target_nor_the_staging_folder() {
    let temp = tempfile::tempdir().unwrap();
    let target = temp.path().join("project");
    let error = write_new_project(&project_with_list("not a name"), &target).unwrap_err();
    assert!(matches!(error, NewProjectError::Save(_)), "{error}");
    assert!(
        error.to_string().ends_with("nothing was written"),
        "{error}"
    );
    assert_eq!(std::fs::read_dir(temp.path()).unwrap().count(), 0);
}

#[test]
fn a_file_in_the_way_or_a_busy_folder_is_refused_untouched() {
    let temp = tempfile::tempdir().unwrap();
    let file = temp.path().join("file");
    std::fs::write(&file, "mine").unwrap();
    let error = write_new_project(&project_with_list("Globals"), &file).unwrap_err();
    assert!(matches!(error, NewProjectError::NotAFolder(_)), "{error}");
    let busy = temp.path().join("busy");
    std::fs::create_dir(&busy).unwrap();
    std::fs::write(busy.join("notes.txt"), "mine").unwrap();
    let error = write_new_project(&project_with_list("Globals"), &busy).unwrap_err();
    assert!(matches!(error, NewProjectError::NotEmpty(_)), "{error}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "mine");
    assert_eq!(std::fs::read_dir(&busy).unwrap().count(), 1);
    assert_eq!(std::fs::read_dir(temp.path()).unwrap().count(), 2);
}
