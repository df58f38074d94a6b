//! Questions about a body in its project: hover, go to definition, find references, completion,
//! and the diagnostics of one POU after an edit.
//!
//! Each answer is computed from the project as it is now, checking only what the question
//! needs: the body asked about (hover, definition, completion), the bodies that mention a name
//! (references), or one POU (diagnostics).

use std::ops::Range;
use std::path::PathBuf;

use project_model::{Project, StBody, TextTarget};

pub use crate::sema::{Completion, Definition, DefinitionKind, ProjectDiagnostic};

/// What hovering over a name shows.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Hover {
    /// The name's byte range in the body.
    pub range: Range<usize>,
    /// The declaration (`iCount : INT := 0`, `FUNCTION F_Scale : REAL`) and, for values,
    /// their type there.
    pub text: String,
}

/// One place that refers to a declaration.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Reference {
    /// The body's file, relative to the project folder.
    pub file: PathBuf,
    /// The body.
    pub target: TextTarget,
    /// The name's byte range in the body.
    pub range: Range<usize>,
}

fn body<'p>(project: &'p Project, target: &TextTarget) -> Option<StBody<'p>> {
    project_model::st_body_files(project)
        .into_iter()
        .find(|body| body.target == *target)
}

/// What the name at byte `offset` of a body refers to, with its range and type.
fn resolution_at(
    project: &Project,
    target: &TextTarget,
    offset: usize,
) -> Option<crate::sema::Resolution> {
    let body = body(project, target)?;
    crate::sema::body_resolutions(project, &body)
        .into_iter()
        .find(|resolution| resolution.range.start <= offset && offset <= resolution.range.end)
}

/// The hover text for the name at byte `offset` of the body `target`.
pub fn hover(project: &Project, target: &TextTarget, offset: usize) -> Option<Hover> {
    let resolution = resolution_at(project, target, offset)?;
    let definition = &resolution.definition;
    let mut text = definition.detail.clone();
    let declared_in = match (&definition.object, &definition.container) {
        (Some(object), Some(container)) if !object.is_empty() => format!("{object}.{container}"),
        (Some(object), None) if !object.is_empty() => object.clone(),
        _ => String::new(),
    };
    if !declared_in.is_empty() && definition.kind == DefinitionKind::Variable {
        text.push_str(&format!("\ndeclared in {declared_in}"));
    }
    Some(Hover {
        range: resolution.range,
        text,
    })
}

/// The declaration of the name at byte `offset` of the body `target`: its object (the file to
/// open) and name (the declaration to show there).
pub fn definition(project: &Project, target: &TextTarget, offset: usize) -> Option<Definition> {
    resolution_at(project, target, offset).map(|resolution| resolution.definition)
}

/// Every place in the project's bodies that refers to the same declaration as the name at byte
/// `offset` of the body `target`, this one included.
pub fn references(project: &Project, target: &TextTarget, offset: usize) -> Vec<Reference> {
    let Some(resolution) = resolution_at(project, target, offset) else {
        return Vec::new();
    };
    crate::sema::references_to(project, &resolution.definition)
        .into_iter()
        .map(|(file, target, range)| Reference {
            file,
            target,
            range,
        })
        .collect()
}

/// Completion candidates at byte `offset` of the body `target`.
pub fn completions(project: &Project, target: &TextTarget, offset: usize) -> Vec<Completion> {
    match body(project, target) {
        Some(body) => crate::sema::completions(project, &body, offset),
        None => Vec::new(),
    }
}

/// A name in a body that online monitoring can show a value for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MonitoredName {
    /// The name's byte range in the body (the last name of a member chain such as
    /// `fbConveyor.tonStart.ET` covers `ET` only).
    pub range: Range<usize>,
    /// The variable's path on the target, such as `Main.fbConveyor.tonStart.ET` or
    /// `GVL_IO.xStartButton`.
    pub path: String,
}

/// The variables of the body `target` with their paths on the target, for values shown inline
/// while online. `instance` is the path of the instance whose values are shown: the program's
/// name for a program body, an instance path such as `Main.fbConveyor` for a function block's
/// body. Locals of functions and methods (which live on the stack) have no path and are left
/// out, as are names that are not variables. In an Instruction List body, the names are those
/// of its operands.
pub fn monitor_paths(project: &Project, target: &TextTarget, instance: &str) -> Vec<MonitoredName> {
    if let Some(names) = il_monitor_paths(project, target, instance) {
        return names;
    }
    st_monitor_paths(project, target, instance)
}

/// The names of the Instruction List body `target` to show values at, as
/// [`monitor_paths`] gives them: those of its lowered text that lie in an operand, at their
/// place in the IL text; `None` when the body is not IL.
fn il_monitor_paths(
    project: &Project,
    target: &TextTarget,
    instance: &str,
) -> Option<Vec<MonitoredName>> {
    let (TextTarget::Pou(pou)
    | TextTarget::Method { pou, .. }
    | TextTarget::Property { pou, .. }
    | TextTarget::Action { pou, .. }
    | TextTarget::Transition { pou, .. }) = target;
    let is_il = project_model::text_body_files(project)
        .into_iter()
        .any(|body| &body.target == target && body.file.extension().is_some_and(|e| e == "il"));
    if !is_il {
        return None;
    }
    let lowered = crate::lower::lower_project(project);
    let body = lowered
        .il
        .iter()
        .find(|body| body.pou.eq_ignore_ascii_case(pou) && &body.target == target)?;
    let mut names: Vec<MonitoredName> = st_monitor_paths(&lowered.project, target, instance)
        .into_iter()
        .filter_map(|name| {
            body.il_range(name.range).map(|range| MonitoredName {
                range,
                path: name.path,
            })
        })
        .collect();
    names.dedup();
    Some(names)
}

/// [`monitor_paths`] of a Structured Text body.
fn st_monitor_paths(project: &Project, target: &TextTarget, instance: &str) -> Vec<MonitoredName> {
    let Some(body) = body(project, target) else {
        return Vec::new();
    };
    let text = body.text;
    let resolutions = crate::sema::body_resolutions(project, &body);
    let mut out: Vec<MonitoredName> = Vec::new();
    // Names that start a chain without a value of their own (`GVL_IO` in `GVL_IO.xStart`).
    let mut namespaces: Vec<MonitoredName> = Vec::new();
    for resolution in resolutions {
        let definition = &resolution.definition;
        if definition.kind == DefinitionKind::GlobalVarList {
            namespaces.push(MonitoredName {
                range: resolution.range.clone(),
                path: definition.name.clone(),
            });
            continue;
        }
        if definition.kind != DefinitionKind::Variable {
            continue;
        }
        // A member follows a `.` right after the previous name of its chain.
        let before = text[..resolution.range.start.min(text.len())].trim_end();
        let is_member = before.ends_with('.');
        let path = if is_member {
            let dot = before.len() - 1;
            let owner_end = text[..dot].trim_end().len();
            let owner = out
                .iter()
                .rev()
                .chain(namespaces.iter().rev())
                .find(|name| name.range.end == owner_end);
            match owner {
                Some(owner) => format!("{}.{}", owner.path, definition.name),
                None => continue,
            }
        } else {
            match (&definition.object, &definition.container) {
                // Locals of methods and accessors live on the stack.
                (_, Some(_)) => continue,
                (Some(object), None) if object.eq_ignore_ascii_case(&body.pou.name) => {
                    if body.pou.kind == project_model::PouKind::Function {
                        continue;
                    }
                    format!("{instance}.{}", definition.name)
                }
                (Some(object), None) => format!("{object}.{}", definition.name),
                (None, _) => continue,
            }
        };
        out.push(MonitoredName {
            range: resolution.range.clone(),
            path,
        });
    }
    // Members the checker does not name one by one (outputs of standard function blocks,
    // members of structures) follow their owner in the text: `ctuPackages.CV`.
    let mut index = 0;
    while index < out.len() {
        let owner = out[index].clone();
        index += 1;
        let rest = &text[owner.range.end.min(text.len())..];
        let after_space = rest.trim_start();
        let Some(after_dot) = after_space.strip_prefix('.') else {
            continue;
        };
        let member = after_dot.trim_start();
        let length = member
            .char_indices()
            .take_while(|(i, c)| {
                c.is_ascii_alphabetic() || *c == '_' || (*i > 0 && c.is_ascii_digit())
            })
            .count();
        if length == 0 {
            continue;
        }
        let start = text.len() - member.len();
        let range = start..start + length;
        if out.iter().any(|name| name.range == range) {
            continue;
        }
        out.push(MonitoredName {
            range,
            path: format!("{}.{}", owner.path, &member[..length]),
        });
    }
    out.sort_by_key(|name| name.range.start);
    out
}

/// The diagnostics of one POU, its declarations and all its bodies: what the editor shows
/// after an edit of that POU.
pub fn pou_diagnostics(project: &Project, pou: &str) -> Vec<ProjectDiagnostic> {
    crate::sema::check_pou(project, pou)
}

#[cfg(test)]
mod monitor_tests {
    use super::*;

    #[test]
    fn names_of_the_example_program_get_their_paths_on_the_target() {
        let project = project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        let names = monitor_paths(&project, &TextTarget::Pou("Main".into()), "Main");
        let paths: Vec<&str> = names.iter().map(|n| n.path.as_str()).collect();
        assert!(paths.contains(&"GVL_IO.xStartButton"), "{paths:?}");
        assert!(paths.contains(&"Main.fbConveyor.xMotorOn"), "{paths:?}");
        assert!(paths.contains(&"Main.ctuPackages.CV"), "{paths:?}");
        // Every range covers the last name of its path.
        let text = project_model::st_body_files(&project)
            .into_iter()
            .find(|b| b.target == TextTarget::Pou("Main".into()))
            .map(|b| b.text.to_owned())
            .unwrap_or_default();
        for name in &names {
            let last = name.path.rsplit('.').next().unwrap_or_default();
            assert!(
                text[name.range.clone()].eq_ignore_ascii_case(last),
                "{name:?}"
            );
        }
        // A function block's body is shown for one instance.
        let fb = monitor_paths(
            &project,
            &TextTarget::Pou("FB_Conveyor".into()),
            "Main.fbConveyor",
        );
        assert!(
            fb.iter().any(|n| n.path == "Main.fbConveyor.xMotorOn"),
            "{fb:?}"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source_project::SourceProject;

    const SOURCE: &str = "TYPE E_State : (Idle := 0, Run := 5); END_TYPE
VAR_GLOBAL
    xStart : BOOL;
END_VAR
FUNCTION_BLOCK FB_Motor
VAR_INPUT xRun : BOOL; END_VAR
VAR_OUTPUT xRunning : BOOL; END_VAR
VAR iHidden : INT; END_VAR
xRunning := xRun;
iHidden := 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    iCount : INT := 3; 
    fbMotor : FB_Motor;
    eState : E_State;
END_VAR
iCount := iCount + 1;
fbMotor(xRun := xStart);
IF fbMotor.xRunning THEN eState := Run; END_IF
iCount := LIMIT(0, iCount, 10);
fbMotor.
END_PROGRAM
";

    fn main_body() -> (SourceProject, TextTarget, String) {
        let source = SourceProject::new(SOURCE);
        let body = project_model::st_body_files(&source.project)
            .into_iter()
            .find(|body| body.pou.name == "Main")
            .expect("Main has a body");
        let text = body.text.to_owned();
        let target = body.target.clone();
        (source, target, text)
    }

    fn at(text: &str, needle: &str) -> usize {
        text.find(needle).expect("the needle is in the text") + 1
    }

    #[test]
    fn hover_shows_declarations_and_standard_signatures() {
        let (source, target, text) = main_body();
        let hover = hover(&source.project, &target, at(&text, "iCount")).expect("hover");
        assert_eq!(hover.text, "iCount : INT := 3\ndeclared in Main");
        assert_eq!(&text[hover.range], "iCount");
        let hover = hover_text(&source, &target, at(&text, "Run;"));
        assert_eq!(hover, "E_State.Run = 5");
        let hover = hover_text(&source, &target, at(&text, "LIMIT"));
        assert_eq!(
            hover,
            "FUNCTION LIMIT(MN : ANY_ELEMENTARY, IN : ANY_ELEMENTARY, MX : ANY_ELEMENTARY) : ANY_ELEMENTARY"
        );
        let hover = hover_text(&source, &target, at(&text, "xRunning"));
        assert_eq!(hover, "xRunning : BOOL\ndeclared in FB_Motor");
    }

    /// A BCD conversion's result is the bit string of its argument's width, not ANY_BIT.
    #[test]
    fn hover_shows_the_width_of_a_bcd_code() {
        let source = SourceProject::new(
            "PROGRAM Main\nVAR w : WORD; l : LWORD; i : INT; END_VAR\n\
             w := INT_TO_BCD(i) OR w; l := LINT_TO_BCD(LINT#5) XOR l;\nEND_PROGRAM\n",
        );
        let body = project_model::st_body_files(&source.project)
            .into_iter()
            .find(|body| body.pou.name == "Main")
            .expect("Main has a body");
        let text = body.text.to_owned();
        assert_eq!(
            hover_text(&source, &body.target, at(&text, "INT_TO_BCD")),
            "FUNCTION INT_TO_BCD(IN : ANY_INT) : WORD"
        );
        assert_eq!(
            hover_text(&source, &body.target, at(&text, "LINT_TO_BCD")),
            "FUNCTION LINT_TO_BCD(IN : LINT) : LWORD"
        );
    }

    fn hover_text(source: &SourceProject, target: &TextTarget, offset: usize) -> String {
        hover(&source.project, target, offset).expect("hover").text
    }

    #[test]
    fn definition_and_references_follow_declarations_across_bodies() {
        let (source, target, text) = main_body();
        let found = definition(&source.project, &target, at(&text, "xStart")).expect("definition");
        assert_eq!(found.kind, DefinitionKind::Variable);
        assert_eq!(found.object.as_deref(), Some("GVL"));
        let found = definition(&source.project, &target, at(&text, "fbMotor.xRunning") + 8)
            .expect("definition");
        assert_eq!(
            (found.kind, found.object.as_deref()),
            (DefinitionKind::Variable, Some("FB_Motor"))
        );
        // xRunning is written in FB_Motor's body and read in Main's.
        let places = references(&source.project, &target, at(&text, "fbMotor.xRunning") + 8);
        let mut owners: Vec<String> = places.iter().map(|r| format!("{:?}", r.target)).collect();
        owners.sort();
        assert_eq!(places.len(), 2, "{places:?}");
        assert!(
            owners[0].contains("FB_Motor") && owners[1].contains("Main"),
            "{owners:?}"
        );
        // iCount appears four times in Main.
        assert_eq!(
            references(&source.project, &target, at(&text, "iCount")).len(),
            4
        );
    }

    #[test]
    fn completion_offers_members_after_a_dot_and_visible_names_elsewhere() {
        let (source, target, text) = main_body();
        let after_dot = text.rfind("fbMotor.").expect("the dot") + "fbMotor.".len();
        let labels: Vec<String> = completions(&source.project, &target, after_dot)
            .into_iter()
            .map(|c| c.label)
            .collect();
        // From outside, the hidden local of the function block is not offered.
        assert_eq!(labels, ["xRun", "xRunning"]);
        let start = at(&text, "eState :=") - 1;
        let labels: Vec<String> = completions(&source.project, &target, start + 2)
            .into_iter()
            .map(|c| c.label)
            .collect();
        assert!(labels.contains(&"eState".to_owned()), "{labels:?}");
        assert!(
            labels.iter().all(|l| l.to_lowercase().starts_with("es")),
            "{labels:?}"
        );
    }

    #[test]
    fn one_pou_is_checked_alone() {
        let (source, _, _) = main_body();
        let found = pou_diagnostics(&source.project, "Main");
        // Main's only finding is the incomplete `fbMotor.` line.
        assert!(!found.is_empty());
        assert!(
            found
                .iter()
                .all(|d| d.file.to_string_lossy().contains("Main")),
            "{found:?}"
        );
    }
}
