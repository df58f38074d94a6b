//! Where a probe's variable is read on the target: the lowering names it relative to the POU's
//! instance (`xStart`, `tonDelay.Q`, a hidden `__e7`) or as a global (`GVL_IO.xStart`).

use project_model::{Object, Pou, Project, VarSection};

/// The path on the target of the probe variable `path` of a body of `pou` shown for the
/// instance at `instance` (`Interlock`, `Main.fbConveyor`): the instance's own variables and the
/// lowering's hidden ones are prefixed with it, a global variable gets its list's name, a path
/// through a list stays as written. `None` for what has no place on the target (a method's or
/// function's local, which lives on the stack, or a constant of a type).
pub(super) fn target_path(
    project: &Project,
    pou: &Pou,
    instance: &str,
    path: &str,
) -> Option<String> {
    let first = path.split('.').next().unwrap_or(path).trim();
    if first.is_empty() {
        return None;
    }
    // The lowering's hidden variables are declared in the POU's `VAR`.
    let own = first.starts_with("__")
        || pou.variables.iter().any(|variable| {
            variable.name.eq_ignore_ascii_case(first) && variable.section != VarSection::VarTemp
        });
    if own {
        return Some(format!("{instance}.{path}"));
    }
    for object in project.application.objects() {
        let Object::Gvl(gvl) = object else { continue };
        if gvl.name.eq_ignore_ascii_case(first) {
            return Some(path.to_owned());
        }
        if gvl
            .variables
            .iter()
            .any(|v| v.name.eq_ignore_ascii_case(first))
        {
            return Some(format!("{}.{path}", gvl.name));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> Project {
        project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"))
    }

    fn interlock(project: &Project) -> &Pou {
        match project.application.object("Interlock") {
            Some(Object::Pou(pou)) => pou,
            other => panic!("no Interlock: {other:?}"),
        }
    }

    #[test]
    fn own_hidden_and_global_variables_get_their_target_paths() {
        let project = example();
        let pou = interlock(&project);
        let path = |probe: &str| target_path(&project, pou, "Interlock", probe);
        assert_eq!(
            path("xRunRequest").as_deref(),
            Some("Interlock.xRunRequest")
        );
        assert_eq!(
            path("tonStartWarning.Q").as_deref(),
            Some("Interlock.tonStartWarning.Q")
        );
        assert_eq!(path("__e3").as_deref(), Some("Interlock.__e3"));
        assert_eq!(
            path("GVL_IO.xStartButton").as_deref(),
            Some("GVL_IO.xStartButton")
        );
        assert_eq!(path("xStartButton").as_deref(), Some("GVL_IO.xStartButton"));
        assert_eq!(path("nowhere"), None);
    }

    #[test]
    fn every_probe_of_the_interlock_has_a_target_path() {
        let project = example();
        let pou = interlock(&project);
        let lowered = compiler::lower::lower_project(&project);
        let body = lowered
            .bodies
            .iter()
            .find(|body| body.pou == "Interlock")
            .expect("the Interlock is lowered");
        assert!(!body.probes.is_empty());
        for probe in &body.probes {
            assert!(
                target_path(&project, pou, "Interlock", &probe.path).is_some(),
                "{probe:?}"
            );
        }
    }
}
