use super::*;
use crate::{DataType, GlobalVarList, Node, TaskKind, TypeDefinition};

fn list(name: &str, comment: &str) -> Object {
    Object::Gvl(GlobalVarList {
        name: name.into(),
        comment: comment.into(),
        ..GlobalVarList::default()
    })
}

fn alias(name: &str, ty: &str) -> Object {
    Object::DataType(DataType {
        name: name.into(),
        comment: String::new(),
        definition: TypeDefinition::Alias {
            ty: ty.into(),
            initial: None,
        },
    })
}

fn task(name: &str, programs: &[&str]) -> Task {
    Task {
        name: name.into(),
        kind: TaskKind::Freewheeling,
        priority: 1,
        watchdog: None,
        programs: programs.iter().map(|&program| program.to_owned()).collect(),
    }
}

fn project(objects: Vec<Object>, tasks: Vec<Task>) -> Project {
    let mut project = Project::default();
    project.application.children = objects.into_iter().map(Node::Object).collect();
    project.tasks = tasks;
    project
}

fn names(project: &Project) -> Vec<(String, String)> {
    project
        .application
        .objects()
        .into_iter()
        .map(|object| (object.name().to_owned(), comment_of(object)))
        .collect()
}

fn comment_of(object: &Object) -> String {
    match object {
        Object::Gvl(gvl) => gvl.comment.clone(),
        Object::DataType(data_type) => data_type.comment.clone(),
        _ => String::new(),
    }
}

fn pairs(list: &[(&str, &str)]) -> Vec<(String, String)> {
    list.iter()
        .map(|&(name, comment)| (name.to_owned(), comment.to_owned()))
        .collect()
}

#[test]
fn objects_without_a_clash_are_added_at_the_end_and_clashes_are_skipped_by_default() {
    let open = project(vec![list("Globals", "mine"), alias("Speed", "INT")], vec![]);
    let imported = project(
        vec![list("GLOBALS", "theirs"), list("Io", "theirs")],
        vec![],
    );
    let plan = MergePlan::new(&open, &imported);
    assert_eq!(
        plan.additions,
        vec![MergeItem::Object {
            kind: ObjectKind::Gvl,
            name: "Io".into()
        }]
    );
    assert_eq!(
        plan.clashes,
        vec![MergeClash {
            imported: MergeItem::Object {
                kind: ObjectKind::Gvl,
                name: "GLOBALS".into()
            },
            existing: MergeItem::Object {
                kind: ObjectKind::Gvl,
                name: "Globals".into()
            },
            choice: ClashChoice::Skip,
        }]
    );
    let merged = plan.apply(&open, &imported);
    assert_eq!(
        names(&merged),
        pairs(&[("Globals", "mine"), ("Speed", ""), ("Io", "theirs")])
    );
}

#[test]
fn a_replaced_object_takes_the_place_of_the_existing_one_even_of_another_kind() {
    let open = project(vec![alias("Speed", "INT"), list("Globals", "mine")], vec![]);
    let imported = project(vec![list("speed", "theirs")], vec![]);
    let mut plan = MergePlan::new(&open, &imported);
    plan.choose_all(ClashChoice::Replace);
    let merged = plan.apply(&open, &imported);
    assert_eq!(
        names(&merged),
        pairs(&[("speed", "theirs"), ("Globals", "mine")])
    );
    assert!(matches!(merged.application.objects()[0], Object::Gvl(_)));
}

#[test]
fn applying_leaves_the_rest_of_the_open_project_as_it_was() {
    let mut open = project(vec![list("Globals", "mine")], vec![]);
    open.name = "Line 3".into();
    open.controller.host = "10.0.0.7".into();
    let mut imported = project(vec![], vec![]);
    imported.name = "Other".into();
    imported.dialect = crate::Dialect::IecStrict;
    imported
        .serial_ports
        .push(crate::SerialPort::new("RS485", "/dev/ttyS1"));
    let plan = MergePlan::new(&open, &imported);
    assert_eq!(
        plan.ignored,
        vec![
            IgnoredPart::ProjectInfo,
            IgnoredPart::Controller,
            IgnoredPart::Dialect,
            IgnoredPart::SerialPorts
        ]
    );
    assert_eq!(plan.apply(&open, &imported), open);
}

#[test]
fn a_task_of_an_existing_name_is_skipped_or_replaces_the_existing_one_in_place() {
    let open = project(vec![], vec![task("Fast", &["A"]), task("Slow", &["B"])]);
    let imported = project(vec![], vec![task("FAST", &["C"]), task("Event", &["D"])]);
    let mut plan = MergePlan::new(&open, &imported);
    assert_eq!(
        plan.clashes[0].existing,
        MergeItem::Task {
            name: "Fast".into()
        }
    );
    let skipped = plan.apply(&open, &imported);
    let task_names = |project: &Project| -> Vec<(String, Vec<String>)> {
        project
            .tasks
            .iter()
            .map(|task| (task.name.clone(), task.programs.clone()))
            .collect()
    };
    assert_eq!(
        task_names(&skipped),
        vec![
            ("Fast".into(), vec!["A".into()]),
            ("Slow".into(), vec!["B".into()]),
            ("Event".into(), vec!["D".into()]),
        ]
    );
    plan.choose_all(ClashChoice::Replace);
    let replaced = plan.apply(&open, &imported);
    assert_eq!(
        task_names(&replaced),
        vec![
            ("FAST".into(), vec!["C".into()]),
            ("Slow".into(), vec!["B".into()]),
            ("Event".into(), vec!["D".into()]),
        ]
    );
}

#[test]
fn a_program_another_task_calls_is_not_called_twice() {
    let open = project(vec![], vec![task("Fast", &["Main", "Io"])]);
    let imported = project(vec![], vec![task("Slow", &["main", "Extra"])]);
    let mut plan = MergePlan::new(&open, &imported);
    assert_eq!(
        plan.clashes,
        vec![MergeClash {
            imported: MergeItem::ProgramCall {
                task: "Slow".into(),
                program: "main".into()
            },
            existing: MergeItem::ProgramCall {
                task: "Fast".into(),
                program: "main".into()
            },
            choice: ClashChoice::Skip,
        }]
    );
    assert!(plan.additions.contains(&MergeItem::ProgramCall {
        task: "Slow".into(),
        program: "Extra".into()
    }));
    let skipped = plan.apply(&open, &imported);
    assert_eq!(skipped.tasks[0].programs, vec!["Main", "Io"]);
    assert_eq!(skipped.tasks[1].programs, vec!["Extra"]);
    plan.choose_all(ClashChoice::Replace);
    let replaced = plan.apply(&open, &imported);
    assert_eq!(replaced.tasks[0].programs, vec!["Io"]);
    assert_eq!(replaced.tasks[1].programs, vec!["main", "Extra"]);
}

#[test]
fn a_task_replacing_one_of_its_name_does_not_clash_with_that_task_s_calls() {
    let open = project(vec![], vec![task("Main_Task", &["Main"])]);
    let imported = project(vec![], vec![task("Main_Task", &["Main"])]);
    let plan = MergePlan::new(&open, &imported);
    assert_eq!(plan.clashes.len(), 1);
    assert!(matches!(plan.clashes[0].imported, MergeItem::Task { .. }));
}

#[test]
fn a_clash_the_plan_does_not_know_of_is_skipped() {
    let open = project(vec![list("Globals", "mine")], vec![]);
    let imported = project(vec![list("Globals", "theirs")], vec![]);
    let plan = MergePlan::new(&Project::default(), &imported);
    assert!(plan.clashes.is_empty());
    assert_eq!(
        names(&plan.apply(&open, &imported)),
        pairs(&[("Globals", "mine")])
    );
}

#[test]
fn objects_go_into_the_folder_of_their_path_made_where_missing() {
    let mut open = project(vec![list("Globals", "mine")], vec![]);
    open.application.children.push(Node::Folder(Folder {
        name: "Types".into(),
        children: vec![Node::Object(alias("Speed", "INT"))],
    }));
    let mut imported = Project::default();
    imported.application.children = vec![
        Node::Folder(Folder {
            name: "Types".into(),
            children: vec![Node::Object(alias("Length", "REAL"))],
        }),
        Node::Folder(Folder {
            name: "Io".into(),
            children: vec![Node::Object(list("Inputs", "theirs"))],
        }),
    ];
    let merged = MergePlan::new(&open, &imported).apply(&open, &imported);
    assert_eq!(
        merged.application.locate("Length"),
        Some((vec!["Types".to_owned()], 1))
    );
    assert_eq!(
        merged.application.locate("Inputs"),
        Some((vec!["Io".to_owned()], 0))
    );
    assert_eq!(merged.application.children.len(), 3);
}

fn entry(place: &str, xml: &str) -> crate::VendorEntry {
    crate::VendorEntry {
        place: place.into(),
        xml: xml.into(),
        signature: None,
    }
}

#[test]
fn the_vendor_data_of_what_is_taken_comes_along_and_that_of_what_is_replaced_goes() {
    let mut open = project(vec![list("Globals", "mine"), list("Kept", "mine")], vec![]);
    open.vendor_data.entries = vec![
        entry("gvl:Globals", "<data>open globals</data>"),
        entry("gvl:Globals/variable:x", "<data>open x</data>"),
        entry("gvl:Kept", "<data>open kept</data>"),
        // Left by a deleted list whose name the imported `New` takes: it must not go into it.
        entry("gvl:New", "<data>stale new</data>"),
    ];
    let mut imported = project(
        vec![
            list("globals", "theirs"),
            list("Kept", "theirs"),
            list("New", "theirs"),
        ],
        vec![],
    );
    imported.vendor_data.entries = vec![
        entry("gvl:globals", "<data>imported globals</data>"),
        entry("gvl:Kept", "<data>imported kept</data>"),
        entry("gvl:New/variable:y", "<data>imported y</data>"),
        entry("gvl:Newer", "<data>of nothing merged</data>"),
        entry("project", "<data>imported project</data>"),
    ];
    let mut plan = MergePlan::new(&open, &imported);
    for clash in &mut plan.clashes {
        if clash.imported.name() == "globals" {
            clash.choice = ClashChoice::Replace;
        }
    }
    let merged = plan.apply(&open, &imported);
    let kept: Vec<&str> = merged
        .vendor_data
        .entries
        .iter()
        .map(|entry| entry.xml.as_str())
        .collect();
    assert_eq!(
        kept,
        [
            "<data>open kept</data>",
            "<data>imported y</data>",
            "<data>imported globals</data>"
        ]
    );
}
