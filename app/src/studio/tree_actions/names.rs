//! Names of device tree nodes: what makes one acceptable, and fresh names for new nodes.

use compiler::syntax::SyntaxKind;
use project_model::{EditError, Node, Project, is_valid_identifier, same_identifier};

use super::refusal::Refusal;

/// Where a name must be unique. Application objects share one namespace (they are global
/// names of the program); folders only need to differ from their siblings; each list of the
/// device tree is a namespace of its own.
#[derive(Clone, Copy, Debug)]
pub enum NameScope<'a> {
    /// Application objects (POUs, lists, types, cams, traces, watch lists).
    Object,
    /// Folders directly inside the folder with this path.
    Folder(&'a [String]),
    /// Tasks.
    Task,
    /// I/O areas.
    IoArea,
    /// Modbus devices.
    ModbusDevice,
    /// Motion axes.
    Axis,
    /// Serial ports.
    SerialPort,
}

impl NameScope<'_> {
    /// Whether `name` is already used in the scope by something other than `except` (the node
    /// being renamed keeps its own name available, so a change of case is allowed).
    pub fn is_taken(self, project: &Project, name: &str, except: Option<&str>) -> bool {
        let clashes = |other: &str| {
            same_identifier(other, name) && except.is_none_or(|except| except != other)
        };
        match self {
            Self::Object => project
                .application
                .objects()
                .iter()
                .any(|object| clashes(object.name())),
            Self::Folder(parent) => project.application.folder(parent).is_some_and(|folder| {
                folder
                    .children
                    .iter()
                    .any(|node| matches!(node, Node::Folder(f) if clashes(&f.name)))
            }),
            Self::Task => project.tasks.iter().any(|task| clashes(&task.name)),
            Self::IoArea => project.io_areas.iter().any(|area| clashes(&area.name)),
            Self::ModbusDevice => project.modbus_devices.iter().any(|d| clashes(&d.name)),
            Self::Axis => project.axes.iter().any(|axis| clashes(&axis.name)),
            Self::SerialPort => project.serial_ports.iter().any(|port| clashes(&port.name)),
        }
    }
}

/// Why `name` cannot be given to a node in `scope`, or `None` when it can. `except` is the
/// node's current name when it is being renamed.
pub fn name_problem(
    project: &Project,
    scope: NameScope<'_>,
    name: &str,
    except: Option<&str>,
) -> Option<Refusal> {
    identifier_problem(name).or_else(|| {
        scope
            .is_taken(project, name, except)
            .then(|| EditError::DuplicateName(name.to_owned()).into())
    })
}

/// Why `name` cannot name anything at all (empty, not an identifier, a keyword), or `None`.
pub fn identifier_problem(name: &str) -> Option<Refusal> {
    if name.is_empty() {
        return Some(Refusal::EmptyName);
    }
    if !is_valid_identifier(name) {
        return Some(EditError::InvalidName(name.to_owned()).into());
    }
    if SyntaxKind::from_keyword(&name.to_uppercase()).is_some() {
        return Some(Refusal::Keyword(name.to_owned()));
    }
    None
}

/// The first of `base`, `base_1`, `base_2`, … that `taken` does not reject.
///
/// A base that already ends in `_<number>` loses that suffix first, so a copy of `POU_1` is
/// called `POU_2` rather than `POU_1_1`.
pub fn unique_name(base: &str, taken: impl Fn(&str) -> bool) -> String {
    let stem = match base.rsplit_once('_') {
        Some((stem, number))
            if !stem.is_empty()
                && !number.is_empty()
                && number.chars().all(|c| c.is_ascii_digit()) =>
        {
            stem
        }
        _ => base,
    };
    if !taken(base) {
        return base.to_owned();
    }
    (1..)
        .map(|number| format!("{stem}_{number}"))
        .find(|candidate| !taken(candidate))
        .unwrap_or_else(|| base.to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::studio::i18n::Language;

    #[test]
    fn fresh_names_count_up_from_the_stem() {
        let used = ["POU", "POU_1", "Task_3"];
        let taken = |name: &str| used.iter().any(|u| same_identifier(u, name));
        assert_eq!(unique_name("GVL", taken), "GVL");
        assert_eq!(unique_name("POU", taken), "POU_2");
        assert_eq!(unique_name("pou_1", taken), "pou_2");
        assert_eq!(unique_name("Task_3", taken), "Task_1");
    }

    #[test]
    fn keywords_invalid_identifiers_and_duplicates_are_refused() {
        let mut project = Project::default();
        project.tasks.push(project_model::Task {
            name: "MainTask".into(),
            kind: project_model::TaskKind::Freewheeling,
            priority: 1,
            watchdog: None,
            programs: Vec::new(),
        });
        let problem = |name: &str, except| name_problem(&project, NameScope::Task, name, except);
        assert!(
            problem("1st", None)
                .is_some_and(|p| p.text(Language::English).contains("not a valid name"))
        );
        assert!(problem("if", None).is_some_and(|p| p.text(Language::English).contains("keyword")));
        assert!(
            problem("maintask", None)
                .is_some_and(|p| p.text(Language::English).contains("already used"))
        );
        assert_eq!(problem("MAINTASK", Some("MainTask")), None);
        assert_eq!(problem("Other", None), None);
    }
}
