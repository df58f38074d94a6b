//! F11: the project is checked and compiled on a snapshot in a background thread, so typing
//! never waits for the compiler and a crash of the compiler loses nothing the user wrote.

use std::collections::HashMap;
use std::ops::Range;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::mpsc::{self, TryRecvError};
use std::time::{Duration, Instant};

use compiler::lower::ElementPlace;
use compiler::{CompileError, Severity};
use project_model::{Project, TextTarget};

use super::i18n::{Language, RefusalText};
use super::online::BuiltImage;
use super::tree_node::TreeNode;

/// One diagnostic of a build, with everything the messages panel shows and needs to jump.
#[derive(Clone, Debug, PartialEq)]
pub struct BuildMessage {
    /// Error or warning.
    pub severity: Severity,
    /// The stable code, such as `E0101`.
    pub code: String,
    /// The file, relative to the project folder.
    pub file: PathBuf,
    /// The 1-based line in that file, 0 when the finding is in data without a line.
    pub line: usize,
    /// The 1-based column, 0 when unknown.
    pub column: usize,
    /// What was found.
    pub message: String,
    /// The tree node to open.
    pub node: Option<TreeNode>,
    /// The body and byte range to show, for findings in Structured Text bodies.
    pub place: Option<(TextTarget, Range<usize>)>,
    /// The network and element to show, for findings in LD and FBD bodies.
    pub element: Option<ElementPlace>,
}

/// Why a build produced no program although the checker found no error.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BuildFailure {
    /// The build thread did not start, with the system's reason.
    NoThread(String),
    /// The code generator cannot compile something the checker accepts, or hit a limit; the
    /// compiler's message names the place, like the checker's findings.
    Unsupported(String),
    /// The compiler found errors the checker did not report.
    HiddenErrors,
    /// The build thread died without an outcome.
    CompilerStopped,
}

impl BuildFailure {
    /// The failure as the user reads it, in `language`.
    pub fn text(&self, language: Language) -> String {
        match self {
            Self::NoThread(reason) => {
                RefusalText::BuildNoThread.fill(language, &[("reason", reason)])
            }
            Self::Unsupported(message) => message.clone(),
            Self::HiddenErrors => RefusalText::BuildHiddenErrors.get(language).to_owned(),
            Self::CompilerStopped => RefusalText::BuildCompilerStopped.get(language).to_owned(),
        }
    }
}

/// What a build produced.
#[derive(Clone, Debug)]
pub struct BuildOutcome {
    /// The project revision that was built.
    pub revision: u64,
    /// Every error and warning.
    pub messages: Vec<BuildMessage>,
    /// The program, when the project compiles.
    pub image: Option<BuiltImage>,
    /// Why no program came out although the checker found no error (a limit, or a crash).
    pub failure: Option<BuildFailure>,
    /// How long it took.
    pub elapsed: Duration,
}

impl BuildOutcome {
    /// The number of errors and warnings.
    pub fn counts(&self) -> (usize, usize) {
        let errors = self
            .messages
            .iter()
            .filter(|m| m.severity == Severity::Error)
            .count();
        (errors, self.messages.len() - errors)
    }
}

/// A build running in the background.
pub struct BuildJob {
    revision: u64,
    outcome: mpsc::Receiver<BuildOutcome>,
}

impl BuildJob {
    /// Starts building `project` (a snapshot of the model at `revision`).
    pub fn start(project: Project, revision: u64) -> Self {
        let (send, outcome) = mpsc::channel();
        let spawned = std::thread::Builder::new()
            .name("rivet-build".into())
            .spawn(move || {
                let _ = send.send(build(&project, revision));
            });
        if let Err(error) = spawned {
            let (send, failed) = mpsc::channel();
            let failure = BuildFailure::NoThread(error.to_string());
            let _ = send.send(crashed(revision, failure));
            return Self {
                revision,
                outcome: failed,
            };
        }
        Self { revision, outcome }
    }

    /// The revision being built.
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The outcome once the build ended; a build thread that died reports a crash.
    pub fn poll(&self) -> Option<BuildOutcome> {
        match self.outcome.try_recv() {
            Ok(outcome) => Some(outcome),
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => {
                Some(crashed(self.revision, BuildFailure::CompilerStopped))
            }
        }
    }
}

fn crashed(revision: u64, failure: BuildFailure) -> BuildOutcome {
    BuildOutcome {
        revision,
        messages: Vec::new(),
        image: None,
        failure: Some(failure),
        elapsed: Duration::ZERO,
    }
}

/// Checks and compiles `project`.
pub fn build(project: &Project, revision: u64) -> BuildOutcome {
    let started = Instant::now();
    let messages = messages(project);
    let has_errors = messages.iter().any(|m| m.severity == Severity::Error);
    let (image, failure) = if has_errors {
        (None, None)
    } else {
        match compiler::compile_project(project) {
            Ok(image) => {
                let bytes = image.encode();
                let hash = program_image::identity_of(&bytes);
                let tasks = image.tasks.iter().map(|task| task.name.clone()).collect();
                (
                    Some(BuiltImage {
                        bytes: Arc::new(bytes),
                        hash,
                        tasks,
                        program: Arc::new(image),
                        project: Arc::new(project.clone()),
                    }),
                    None,
                )
            }
            Err(CompileError::Unsupported(error)) => {
                (None, Some(BuildFailure::Unsupported(error.to_string())))
            }
            Err(CompileError::Diagnostics(_)) => (None, Some(BuildFailure::HiddenErrors)),
        }
    };
    BuildOutcome {
        revision,
        messages,
        image,
        failure,
        elapsed: started.elapsed(),
    }
}

/// The checker's findings with lines, columns and the places to jump to.
fn messages(project: &Project) -> Vec<BuildMessage> {
    let bodies: HashMap<PathBuf, (String, TextTarget, &str)> =
        project_model::text_body_files(project)
            .into_iter()
            .map(|body| (body.file, (body.pou.name.clone(), body.target, body.text)))
            .collect();
    let objects: HashMap<PathBuf, String> = project_model::object_files(project)
        .into_iter()
        .map(|(file, object)| (file, object.name().to_owned()))
        .collect();
    compiler::sema::check_project(project)
        .into_iter()
        .map(|found| {
            let diagnostic = found.diagnostic;
            let body = bodies
                .get(&found.file)
                .filter(|_| found.declaration.is_none());
            let (line, column) = match body {
                Some((_, _, text)) => line_column(text, diagnostic.range.start),
                None => (0, 0),
            };
            let node = match (body, &found.element) {
                (Some((pou, _, _)), _) => Some(TreeNode::Object(pou.clone())),
                (None, Some(place)) => Some(TreeNode::Object(place.pou.clone())),
                (None, None) => objects.get(&found.file).cloned().map(TreeNode::Object),
            };
            let message = match &found.declaration {
                Some(name) => format!("{name}: {}", diagnostic.message),
                None => diagnostic.message,
            };
            BuildMessage {
                severity: diagnostic.severity,
                code: diagnostic.code.id().to_owned(),
                file: found.file,
                line,
                column,
                message,
                node,
                place: body.map(|(_, target, _)| (target.clone(), diagnostic.range.clone())),
                element: found.element,
            }
        })
        .collect()
}

/// The 1-based line and column (in characters) of byte `offset` in `text`.
pub fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |s| s.chars().count()) + 1;
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_columns_count_characters_from_one() {
        assert_eq!(line_column("a := 1;\n中b := 2;", 0), (1, 1));
        assert_eq!(line_column("a := 1;\n中b := 2;", 8), (2, 1));
        assert_eq!(line_column("a := 1;\n中b := 2;", 11), (2, 2));
        // An offset inside a character or past the end is clamped, never a panic.
        assert_eq!(line_column("中", 1), (1, 1));
        assert_eq!(line_column("ab", 99), (1, 3));
    }

    #[test]
    fn the_example_builds_and_a_broken_body_reports_its_line() {
        let mut project = project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        let outcome = build(&project, 1);
        assert_eq!(outcome.counts().0, 0, "{:?}", outcome.messages);
        assert!(outcome.image.is_some());

        let edit = project_model::Edit::ReplaceText {
            target: TextTarget::Pou("Main".into()),
            range: 0..0,
            text: "x := ;\n\nundefinedThing := 1;\n".into(),
        };
        edit.apply(&mut project)
            .unwrap_or_else(|error| panic!("{error}"));
        let outcome = build(&project, 2);
        assert!(outcome.image.is_none());
        let first = &outcome.messages[0];
        assert_eq!(first.file, PathBuf::from("application/Main.st"));
        assert_eq!(first.line, 1);
        assert_eq!(first.node, Some(TreeNode::Object("Main".into())));
        assert!(
            outcome.messages.iter().any(|m| m.line == 3),
            "{:?}",
            outcome.messages
        );
    }

    #[test]
    fn a_finding_in_a_ladder_body_names_its_network_and_element() {
        let mut project = project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        let Some(project_model::Object::Pou(interlock)) =
            project.application.object_mut("Interlock")
        else {
            panic!("the example has the LD program Interlock");
        };
        let project_model::Body::Ld { networks } = &mut interlock.body else {
            panic!("Interlock is drawn in LD");
        };
        let project_model::FlowNode::Operand(contact) = &mut networks[3].rung[1] else {
            panic!("the horn's second element is a contact");
        };
        contact.text = "xNoSuchSignal".into();
        let id = contact.id;
        let outcome = build(&project, 2);
        assert!(outcome.image.is_none());
        let found = outcome
            .messages
            .iter()
            .find(|m| m.element.is_some())
            .unwrap_or_else(|| panic!("{:?}", outcome.messages));
        assert_eq!(found.file, PathBuf::from("application/Interlock.pou.toml"));
        assert_eq!(found.node, Some(TreeNode::Object("Interlock".into())));
        assert!(found.message.contains("xNoSuchSignal"), "{}", found.message);
        let place = found.element.as_ref().map(|p| (p.network, p.element));
        assert_eq!(place, Some((3, Some(id))));
    }
}
