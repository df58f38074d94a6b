//! Breakpoint conditions compiled once: compiling one builds the whole project again
//! (`compiler::compile_condition`), so the studio keeps each outcome by what it depends on
//! (the image logged in with, the POU and the condition's text) and compiles the new ones on
//! a worker thread, so neither an unchanged breakpoint list nor a changed one holds the UI.

use std::collections::HashMap;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError, channel};

use compiler::ConditionCompileError;
use program_image::ImageHash;
use project_model::Project;

/// What a compiled condition depends on; the cache's key.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ConditionKey {
    /// The identity of the image the studio logged in with (built from the project the
    /// condition is compiled against).
    pub image: ImageHash,
    /// The POU whose scope the condition is compiled in (`FB_Conveyor`, `FB.Method`).
    pub pou: String,
    /// The condition as the user wrote it, trimmed.
    pub condition: String,
}

/// A condition compiled for `BREAK_SET`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CompiledCondition {
    /// The POU's index in the image it was compiled for.
    pub pou: u32,
    /// The encoded condition `BREAK_SET` carries.
    pub bytes: Vec<u8>,
    /// The identity of the image it was compiled for.
    pub image: ImageHash,
}

/// A condition compiled, or the compiler's error saying why it does not compile, shared by
/// the cache and every breakpoint with the same condition.
pub type ConditionOutcome = Result<CompiledCondition, Arc<ConditionCompileError>>;

/// Compiles `key`'s condition against `project`, on the calling thread.
pub fn compile_condition(project: &Project, key: &ConditionKey) -> ConditionOutcome {
    compiler::compile_condition(project, &key.pou, &key.condition)
        .map(|compiled| CompiledCondition {
            pou: compiled.pou,
            bytes: compiled.condition.encode(),
            image: compiled.image,
        })
        .map_err(Arc::new)
}

/// The outcomes known, and the conditions compiling; lives with the login, never saved.
#[derive(Default)]
pub struct ConditionCache {
    /// Each condition's outcome, for the image logged in with (others are dropped).
    outcomes: HashMap<ConditionKey, ConditionOutcome>,
    /// Where the outcomes of the conditions a worker thread compiles arrive.
    compiling: Option<Receiver<Vec<(ConditionKey, ConditionOutcome)>>>,
}

impl ConditionCache {
    /// The outcome of `key`, once it is compiled.
    pub fn get(&self, key: &ConditionKey) -> Option<&ConditionOutcome> {
        self.outcomes.get(key)
    }

    /// Whether every one of `keys` is compiled.
    #[cfg(test)]
    pub fn has_all(&self, keys: &[ConditionKey]) -> bool {
        keys.iter().all(|key| self.outcomes.contains_key(key))
    }

    /// Starts compiling those of `keys` still waiting to be compiled on a worker thread, which
    /// calls `wake` when done (unless a compile is under way already: the rest waits for it).
    /// Outcomes of other images than `keys`' are forgotten. Returns whether some of `keys`
    /// are still to come, to be taken with [`ConditionCache::take_finished`].
    pub fn compile_missing(
        &mut self,
        project: &Arc<Project>,
        keys: &[ConditionKey],
        wake: Option<Arc<dyn Fn() + Send + Sync>>,
    ) -> bool {
        if let Some(first) = keys.first() {
            self.outcomes.retain(|key, _| key.image == first.image);
        }
        let mut missing: Vec<ConditionKey> = Vec::new();
        for key in keys {
            if !self.outcomes.contains_key(key) && !missing.contains(key) {
                missing.push(key.clone());
            }
        }
        if missing.is_empty() {
            return false;
        }
        if self.compiling.is_some() {
            return true;
        }
        let (sender, receiver) = channel();
        let project = Arc::clone(project);
        let spawned = std::thread::Builder::new()
            .name("breakpoint conditions".to_owned())
            .spawn(move || {
                let outcomes = missing
                    .into_iter()
                    .map(|key| {
                        let outcome = compile_condition(&project, &key);
                        (key, outcome)
                    })
                    .collect();
                // The studio may have logged out meanwhile; then nobody waits for these.
                let _ = sender.send(outcomes);
                if let Some(wake) = wake {
                    wake();
                }
            });
        if spawned.is_ok() {
            self.compiling = Some(receiver);
        }
        spawned.is_ok()
    }

    /// Takes in the outcomes of a finished compile; returns whether any arrived.
    pub fn take_finished(&mut self) -> bool {
        let Some(receiver) = &self.compiling else {
            return false;
        };
        match receiver.try_recv() {
            Ok(outcomes) => {
                self.outcomes.extend(outcomes);
                self.compiling = None;
                true
            }
            Err(TryRecvError::Empty) => false,
            Err(TryRecvError::Disconnected) => {
                // The worker ended without an answer (it panicked): its conditions are
                // compiled again on the next request rather than waited for forever.
                self.compiling = None;
                false
            }
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // A panic is a failed test.

    use super::*;

    fn example() -> (Arc<Project>, ImageHash) {
        let project = project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        let image = compiler::compile_project(&project).unwrap().identity();
        (Arc::new(project), image)
    }

    fn key(image: ImageHash, condition: &str) -> ConditionKey {
        ConditionKey {
            image,
            pou: "FB_Conveyor".to_owned(),
            condition: condition.to_owned(),
        }
    }

    /// Waits for the worker's outcomes (the test's only way to know it is done).
    fn finish(cache: &mut ConditionCache) {
        while !cache.take_finished() {
            std::thread::yield_now();
        }
    }

    #[test]
    fn a_condition_is_compiled_once_per_image_pou_and_text() {
        let (project, image) = example();
        let mut cache = ConditionCache::default();
        let keys = vec![key(image, "xStart AND NOT xStop"), key(image, "nope +")];
        assert!(cache.compile_missing(&project, &keys, None));
        // A second request while compiling waits for the same worker.
        assert!(cache.compile_missing(&project, &keys, None));
        finish(&mut cache);
        assert!(cache.has_all(&keys));
        let good = cache.get(&keys[0]).unwrap().as_ref().unwrap();
        assert_eq!(good.image, image);
        assert!(!good.bytes.is_empty());
        assert!(cache.get(&keys[1]).unwrap().is_err());
        // The same list again costs nothing: nothing is compiled.
        assert!(!cache.compile_missing(&project, &keys, None));
        assert!(!cache.take_finished());
        // A changed text is a new key; the others stay.
        let changed = vec![keys[0].clone(), key(image, "xStart")];
        assert!(cache.compile_missing(&project, &changed, None));
        finish(&mut cache);
        assert!(cache.has_all(&changed) && cache.has_all(&keys));
    }

    #[test]
    fn another_image_forgets_the_outcomes_of_the_last() {
        let (project, image) = example();
        let mut cache = ConditionCache::default();
        let old = vec![key(image, "xStart")];
        cache.compile_missing(&project, &old, None);
        finish(&mut cache);
        let other = vec![key([7; 32], "xStart")];
        assert!(cache.compile_missing(&project, &other, None));
        assert!(!cache.has_all(&old));
        finish(&mut cache);
    }
}
