//! The merge of an imported project into an open one (`docs/plcopen-xml.md` §6.3): what it
//! adds, what clashes with what is there, and the project that applying it gives.

use crate::vendor_data::{is_place_of, vendor_prefix};
use crate::{Folder, Node, Object, ObjectKind, Project, Task, same_identifier};

/// What a merge adds or replaces, for the open project and an imported one.
///
/// The plan is computed from the two projects; each clash carries a choice the user may change
/// (skipping the imported thing by default, so nothing the user wrote is overwritten unless they
/// ask). [`MergePlan::apply`] gives the merged project and leaves both inputs untouched.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct MergePlan {
    /// What is added without clashing, in the imported project's order: objects, tasks, then
    /// the program calls of the imported tasks.
    pub additions: Vec<MergeItem>,
    /// What clashes with the open project, in the same order, each with its choice.
    pub clashes: Vec<MergeClash>,
    /// What the imported project holds that a merge never takes (its controller, dialect,
    /// name and devices: the open project's stay).
    pub ignored: Vec<IgnoredPart>,
}

/// A thing of a project a merge adds, replaces or skips.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MergeItem {
    /// An application object (POU, data type, global variable list, …).
    Object {
        /// Its kind.
        kind: ObjectKind,
        /// Its name as written.
        name: String,
    },
    /// A task of the task configuration.
    Task {
        /// Its name as written.
        name: String,
    },
    /// A program called by a task.
    ProgramCall {
        /// The calling task's name.
        task: String,
        /// The program's name.
        program: String,
    },
}

/// An imported thing that clashes with one of the open project.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MergeClash {
    /// The imported thing.
    pub imported: MergeItem,
    /// What it clashes with in the open project: an object or task of the same name without
    /// regard to case, or the call of the same program by another task (Rivet runs one instance
    /// of each program, so two tasks may not call it).
    pub existing: MergeItem,
    /// What applying the plan does about it.
    pub choice: ClashChoice,
}

/// What the merge does about a clash.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ClashChoice {
    /// Keep the open project's thing and leave the imported one out.
    #[default]
    Skip,
    /// Put the imported thing in the place of the open project's (for a program call: the
    /// existing task stops calling the program, the imported task calls it).
    Replace,
}

/// A part of the imported project a merge never takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IgnoredPart {
    /// The project's name or description differs.
    ProjectInfo,
    /// The controller (name, address, Modbus map) differs.
    Controller,
    /// The language dialect differs.
    Dialect,
    /// The imported project has I/O areas.
    IoAreas,
    /// The imported project has serial ports.
    SerialPorts,
    /// The imported project has Modbus devices.
    ModbusDevices,
    /// The imported project has axes.
    Axes,
}

impl MergeItem {
    /// The item's name (for a program call, the program's).
    pub fn name(&self) -> &str {
        match self {
            Self::Object { name, .. } | Self::Task { name } => name,
            Self::ProgramCall { program, .. } => program,
        }
    }

    fn object(object: &Object) -> Self {
        Self::Object {
            kind: object.kind(),
            name: object.name().to_owned(),
        }
    }
}

impl MergePlan {
    /// The plan of merging `imported` into `open`, every clash skipped.
    pub fn new(open: &Project, imported: &Project) -> Self {
        let mut plan = Self::default();
        for object in imported.application.objects() {
            let item = MergeItem::object(object);
            match open.application.object(object.name()) {
                Some(existing) => plan.clash(item, MergeItem::object(existing)),
                None => plan.additions.push(item),
            }
        }
        for task in &imported.tasks {
            let item = MergeItem::Task {
                name: task.name.clone(),
            };
            match open.task(&task.name) {
                Some(existing) => plan.clash(
                    item,
                    MergeItem::Task {
                        name: existing.name.clone(),
                    },
                ),
                None => plan.additions.push(item),
            }
        }
        for task in &imported.tasks {
            for program in &task.programs {
                let item = MergeItem::ProgramCall {
                    task: task.name.clone(),
                    program: program.clone(),
                };
                match other_caller(open, &task.name, program) {
                    Some(existing) => plan.clash(
                        item,
                        MergeItem::ProgramCall {
                            task: existing.name.clone(),
                            program: program.clone(),
                        },
                    ),
                    None => plan.additions.push(item),
                }
            }
        }
        plan.ignored = ignored_parts(open, imported);
        plan
    }

    fn clash(&mut self, imported: MergeItem, existing: MergeItem) {
        self.clashes.push(MergeClash {
            imported,
            existing,
            choice: ClashChoice::Skip,
        });
    }

    /// Sets the choice of every clash.
    pub fn choose_all(&mut self, choice: ClashChoice) {
        for clash in &mut self.clashes {
            clash.choice = choice;
        }
    }

    /// The choice for an imported thing: that of its clash, or `None` when it does not clash.
    fn choice(&self, imported: &MergeItem) -> Option<ClashChoice> {
        self.clashes
            .iter()
            .find(|clash| clash.imported == *imported)
            .map(|clash| clash.choice)
    }

    /// The project that merging `imported` into `open` by this plan gives: `open` with the
    /// imported objects added at the end of their folder (the folder of the same path, made
    /// when `open` has none; a replacing one takes the place of the one it replaces), the
    /// imported tasks added at the end of the
    /// task list (or in the place of the one they replace) with their program calls, and
    /// everything else of `open` as it was.
    ///
    /// The clashes are found again from the two projects, so a clash the plan does not list
    /// (the projects changed since it was made) is skipped: nothing is overwritten unasked.
    pub fn apply(&self, open: &Project, imported: &Project) -> Project {
        let mut merged = open.clone();
        // The vendor data of what the merge takes goes with it; that of what it replaces goes.
        let mut taken = Vec::new();
        let mut replaced = Vec::new();
        for (path, object) in objects_with_paths(&imported.application) {
            let item = MergeItem::object(object);
            match open.application.object(object.name()) {
                Some(existing) => {
                    if self.choice(&item) == Some(ClashChoice::Replace)
                        && let Some(slot) = merged.application.object_mut(existing.name())
                    {
                        replaced.push(vendor_prefix(existing.kind(), existing.name()));
                        taken.push(vendor_prefix(object.kind(), object.name()));
                        *slot = object.clone();
                    }
                }
                None => {
                    taken.push(vendor_prefix(object.kind(), object.name()));
                    push_into(&mut merged.application, &path, object.clone());
                }
            }
        }
        for task in &imported.tasks {
            let item = MergeItem::Task {
                name: task.name.clone(),
            };
            let existing = open.task(&task.name).map(|existing| existing.name.clone());
            let replace = match &existing {
                Some(_) if self.choice(&item) != Some(ClashChoice::Replace) => continue,
                Some(name) => Some(name.as_str()),
                None => None,
            };
            let added = self.task_with_calls(open, task, &mut merged);
            if let Some(name) = replace {
                replaced.push(Some(format!("task:{name}")));
            }
            taken.push(Some(format!("task:{}", task.name)));
            match replace.and_then(|name| position_of_task(&merged.tasks, name)) {
                Some(index) => merged.tasks[index] = added,
                None => merged.tasks.push(added),
            }
        }
        let replaced: Vec<String> = replaced.into_iter().flatten().collect();
        let taken: Vec<String> = taken.into_iter().flatten().collect();
        let entries = &mut merged.vendor_data.entries;
        // The open project's entries of what the import takes go: a replaced object's, and the
        // leftovers of a deleted object whose name an added one takes (they would be written
        // into it).
        entries.retain(|entry| {
            !replaced
                .iter()
                .chain(&taken)
                .any(|prefix| is_place_of(&entry.place, prefix))
        });
        entries.extend(
            imported
                .vendor_data
                .entries
                .iter()
                .filter(|entry| taken.iter().any(|prefix| is_place_of(&entry.place, prefix)))
                .cloned(),
        );
        // The vendor data is ordered by place (`VendorData::entries`); the sort is stable, so
        // the entries of one place stay in their order.
        entries.sort_by(|left, right| left.place.cmp(&right.place));
        merged
    }

    /// The imported `task` with the program calls it keeps; the calls it takes over are
    /// removed from the tasks of `merged` that made them.
    fn task_with_calls(&self, open: &Project, task: &Task, merged: &mut Project) -> Task {
        let mut added = task.clone();
        added.programs.clear();
        for program in &task.programs {
            let Some(caller) = other_caller(open, &task.name, program) else {
                added.programs.push(program.clone());
                continue;
            };
            let item = MergeItem::ProgramCall {
                task: task.name.clone(),
                program: program.clone(),
            };
            if self.choice(&item) != Some(ClashChoice::Replace) {
                continue;
            }
            if let Some(index) = position_of_task(&merged.tasks, &caller.name) {
                merged.tasks[index]
                    .programs
                    .retain(|called| !same_identifier(called, program));
            }
            added.programs.push(program.clone());
        }
        added
    }
}

/// The task of `open`, other than the one named `task`, that calls `program`.
fn other_caller<'a>(open: &'a Project, task: &str, program: &str) -> Option<&'a Task> {
    open.tasks.iter().find(|existing| {
        !same_identifier(&existing.name, task)
            && existing
                .programs
                .iter()
                .any(|called| same_identifier(called, program))
    })
}

/// Every object below `folder` with the path of the folder holding it, depth first in tree
/// order (the order of [`Folder::objects`]).
fn objects_with_paths(folder: &Folder) -> Vec<(Vec<String>, &Object)> {
    let mut found = Vec::new();
    collect_objects(folder, &mut Vec::new(), &mut found);
    found
}

fn collect_objects<'a>(
    folder: &'a Folder,
    path: &mut Vec<String>,
    found: &mut Vec<(Vec<String>, &'a Object)>,
) {
    for node in &folder.children {
        match node {
            Node::Folder(child) => {
                path.push(child.name.clone());
                collect_objects(child, path, found);
                path.pop();
            }
            Node::Object(object) => found.push((path.clone(), object)),
        }
    }
}

/// Adds `object` at the end of the folder at `path` below `root`, making the folders that are
/// missing (at the end of their parent).
fn push_into(root: &mut Folder, path: &[String], object: Object) {
    let Some((first, rest)) = path.split_first() else {
        root.children.push(Node::Object(object));
        return;
    };
    let existing = root.children.iter_mut().find_map(|node| match node {
        Node::Folder(child) if child.name == *first => Some(child),
        _ => None,
    });
    if let Some(child) = existing {
        push_into(child, rest, object);
        return;
    }
    let mut child = Folder {
        name: first.clone(),
        children: Vec::new(),
    };
    push_into(&mut child, rest, object);
    root.children.push(Node::Folder(child));
}

fn position_of_task(tasks: &[Task], name: &str) -> Option<usize> {
    tasks
        .iter()
        .position(|task| same_identifier(&task.name, name))
}

fn ignored_parts(open: &Project, imported: &Project) -> Vec<IgnoredPart> {
    let mut ignored = Vec::new();
    if open.name != imported.name || open.description != imported.description {
        ignored.push(IgnoredPart::ProjectInfo);
    }
    if open.controller != imported.controller {
        ignored.push(IgnoredPart::Controller);
    }
    if open.dialect != imported.dialect {
        ignored.push(IgnoredPart::Dialect);
    }
    if !imported.io_areas.is_empty() {
        ignored.push(IgnoredPart::IoAreas);
    }
    if !imported.serial_ports.is_empty() {
        ignored.push(IgnoredPart::SerialPorts);
    }
    if !imported.modbus_devices.is_empty() {
        ignored.push(IgnoredPart::ModbusDevices);
    }
    if !imported.axes.is_empty() {
        ignored.push(IgnoredPart::Axes);
    }
    ignored
}

#[cfg(test)]
#[path = "merge_plan_tests.rs"]
mod tests;
