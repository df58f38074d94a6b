//! The actions and transition objects a graphical body adds to its POU (inline action bodies
//! and inline or wired transition conditions), with names that clash with nothing.

use std::collections::HashSet;

use project_model::{Body, PouAction};

/// The objects synthesized for one POU and the names already taken in it.
#[derive(Debug, Default)]
pub(super) struct PouObjects {
    /// Lower-case names of the POU's variables, actions, transitions and methods, and of the
    /// objects synthesized so far.
    taken: HashSet<String>,
    /// The actions synthesized, in the order they were made.
    pub actions: Vec<PouAction>,
    /// The transition objects synthesized, in the order they were made.
    pub transitions: Vec<PouAction>,
    /// How many inline actions were numbered so far (Beremiz numbers them per POU from 1).
    inline_actions: u32,
    /// How many inline conditions were numbered so far.
    inline_conditions: u32,
    /// One sentence per name that had to change because it was taken.
    pub renamed: Vec<String>,
}

impl PouObjects {
    /// Objects for a POU whose variables, actions, transitions and methods are `names`.
    pub fn new<'n>(names: impl IntoIterator<Item = &'n str>) -> Self {
        Self {
            taken: names.into_iter().map(str::to_lowercase).collect(),
            ..Self::default()
        }
    }

    /// Adds the action of an inline body of step `step`, named as Beremiz's generator names
    /// it (`STEP_INLINE1`, numbered per POU), and returns its name.
    pub fn inline_action(&mut self, step: &str, body: Body) -> String {
        self.inline_actions += 1;
        let name = self.fresh(format!("{step}_INLINE{}", self.inline_actions));
        self.actions.push(PouAction {
            name: name.clone(),
            body,
        });
        name
    }

    /// Reserves the name of a transition object for a condition that is more than one
    /// expression, after the step `step` (`STEP_CONDITION1`, numbered per POU); the caller adds
    /// the object to `transitions`.
    pub fn condition_name(&mut self, step: &str) -> String {
        self.inline_conditions += 1;
        self.fresh(format!("{step}_CONDITION{}", self.inline_conditions))
    }

    /// `wanted`, or `wanted_2`, `wanted_3`… when that name is taken (without regard to case).
    fn fresh(&mut self, wanted: String) -> String {
        let mut name = wanted.clone();
        let mut suffix = 1;
        while self.taken.contains(&name.to_lowercase()) {
            suffix += 1;
            name = format!("{wanted}_{suffix}");
        }
        if name != wanted {
            self.renamed.push(format!(
                "`{wanted}` was taken, so the synthesized object is `{name}`"
            ));
        }
        self.taken.insert(name.to_lowercase());
        name
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_taken_name_gets_a_suffix_and_a_note() {
        let mut objects = PouObjects::new(["count_inline1", "Count_INLINE1_2"]);
        let name = objects.inline_action("Count", Body::st("x := 1;"));
        assert_eq!(name, "Count_INLINE1_3");
        assert_eq!(objects.renamed.len(), 1);
        assert_eq!(objects.inline_action("Count", Body::None), "Count_INLINE2");
        assert_eq!(objects.condition_name("Start"), "Start_CONDITION1");
        assert_eq!(objects.actions.len(), 2);
    }
}
