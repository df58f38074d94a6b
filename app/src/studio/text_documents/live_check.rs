//! Diagnostics as you type: the POU being edited is checked on a thread once typing rests, and
//! results for an older text are dropped.

use std::collections::HashMap;
use std::sync::mpsc;
use std::time::{Duration, Instant};

use compiler::sema::ProjectDiagnostic;
use project_model::Project;

/// How long typing must rest before the POU is checked.
pub const CHECK_DELAY: Duration = Duration::from_millis(300);

/// The last check of each POU, and the one running.
#[derive(Default)]
pub struct LiveCheck {
    /// Each POU's findings with the revision they belong to.
    results: HashMap<String, (u64, Vec<ProjectDiagnostic>)>,
    running: Option<(String, u64, mpsc::Receiver<Vec<ProjectDiagnostic>>)>,
    /// The revision last seen and when, to wait for typing to rest.
    last_change: Option<(u64, Instant)>,
}

impl LiveCheck {
    /// The findings of `pou` for `revision`, or the last ones while a newer check is pending.
    pub fn findings(&self, pou: &str) -> Option<&(u64, Vec<ProjectDiagnostic>)> {
        self.results.get(pou)
    }

    /// Takes in a finished check, and starts checking `pou` at `revision` once typing rested.
    /// Returns whether it waits for something (so the UI asks for another frame).
    pub fn update(&mut self, project: &Project, pou: &str, revision: u64) -> bool {
        if let Some((name, checked, receiver)) = &self.running {
            match receiver.try_recv() {
                Ok(found) => {
                    self.results.insert(name.clone(), (*checked, found));
                    self.running = None;
                }
                Err(mpsc::TryRecvError::Empty) => return true,
                Err(mpsc::TryRecvError::Disconnected) => {
                    // The checker crashed on this text; the editor keeps it and the next edit
                    // tries again.
                    self.results.insert(name.clone(), (*checked, Vec::new()));
                    self.running = None;
                }
            }
        }
        if self
            .results
            .get(pou)
            .is_some_and(|(seen, _)| *seen == revision)
        {
            return false;
        }
        let now = Instant::now();
        match self.last_change {
            Some((seen, at)) if seen == revision => {
                if now.duration_since(at) < CHECK_DELAY {
                    return true;
                }
            }
            _ => {
                self.last_change = Some((revision, now));
                // A document opened on a project nobody edits is checked at once.
                if !self.results.contains_key(pou) {
                    self.start(project, pou, revision);
                }
                return true;
            }
        }
        self.start(project, pou, revision);
        true
    }

    fn start(&mut self, project: &Project, pou: &str, revision: u64) {
        let (send, receive) = mpsc::channel();
        let snapshot = project.clone();
        let name = pou.to_owned();
        let spawned = std::thread::Builder::new()
            .name("rivet-check".into())
            .spawn(move || {
                let _ = send.send(compiler::ide::pou_diagnostics(&snapshot, &name));
            });
        if spawned.is_ok() {
            self.running = Some((pou.to_owned(), revision, receive));
        }
    }
}
