//! Undo and redo of edits, with a save point for the dirty flag.

use crate::{Edit, EditError, Project};

/// One undo step: the edits of one user gesture and the edits that undo them.
#[derive(Clone, Debug, PartialEq)]
pub struct Transaction {
    /// What the user did, for the Edit menu ("Undo Rename").
    pub label: String,
    /// The edits as applied, in order (used by redo).
    pub forward: Vec<Edit>,
    /// The edits that undo them, in the order they must be applied.
    pub inverse: Vec<Edit>,
}

/// The undo and redo stacks of an open project.
///
/// It lives as long as the project is open and is never saved.
#[derive(Clone, Debug, Default)]
pub struct History {
    undo: Vec<Transaction>,
    redo: Vec<Transaction>,
    /// The undo depth at which the project equals the saved files; `None` once that state can
    /// no longer be reached by undo or redo.
    save_point: Option<usize>,
    /// Counts every change, so derived data (analysis, layouts) can tell it is stale.
    revision: u64,
}

impl History {
    /// A history for a project just loaded from (or saved to) disk.
    pub fn new() -> Self {
        Self {
            save_point: Some(0),
            ..Self::default()
        }
    }

    /// Applies the edits of one gesture as one undo step.
    ///
    /// If any edit fails, those already applied are undone and the project is unchanged.
    pub fn apply(
        &mut self,
        project: &mut Project,
        label: impl Into<String>,
        edits: Vec<Edit>,
    ) -> Result<(), EditError> {
        let inverse = match Edit::Group(edits.clone()).apply(project)? {
            Edit::Group(inverse) => inverse,
            other => vec![other],
        };
        if self.save_point.is_some_and(|depth| depth > self.undo.len()) {
            // The saved state was in the redo branch that this edit discards.
            self.save_point = None;
        }
        self.redo.clear();
        self.undo.push(Transaction {
            label: label.into(),
            forward: edits,
            inverse,
        });
        self.revision += 1;
        Ok(())
    }

    /// Undoes the last step and returns its label, or `None` when there is nothing to undo.
    pub fn undo(&mut self, project: &mut Project) -> Result<Option<String>, EditError> {
        let Some(transaction) = self.undo.pop() else {
            return Ok(None);
        };
        if let Err(error) = Edit::Group(transaction.inverse.clone()).apply(project) {
            self.undo.push(transaction);
            return Err(error);
        }
        let label = transaction.label.clone();
        self.redo.push(transaction);
        self.revision += 1;
        Ok(Some(label))
    }

    /// Redoes the last undone step and returns its label, or `None` when there is none.
    pub fn redo(&mut self, project: &mut Project) -> Result<Option<String>, EditError> {
        let Some(transaction) = self.redo.pop() else {
            return Ok(None);
        };
        if let Err(error) = Edit::Group(transaction.forward.clone()).apply(project) {
            self.redo.push(transaction);
            return Err(error);
        }
        let label = transaction.label.clone();
        self.undo.push(transaction);
        self.revision += 1;
        Ok(Some(label))
    }

    /// The label of the step Undo would undo.
    pub fn undo_label(&self) -> Option<&str> {
        self.undo.last().map(|t| t.label.as_str())
    }

    /// The label of the step Redo would redo.
    pub fn redo_label(&self) -> Option<&str> {
        self.redo.last().map(|t| t.label.as_str())
    }

    /// Records that the project was just saved.
    pub fn mark_saved(&mut self) {
        self.save_point = Some(self.undo.len());
    }

    /// Whether the project differs from what was last saved or loaded.
    pub fn is_dirty(&self) -> bool {
        self.save_point != Some(self.undo.len())
    }

    /// A counter bumped by every apply, undo and redo.
    pub fn revision(&self) -> u64 {
        self.revision
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rename(name: &str) -> Vec<Edit> {
        vec![Edit::SetProjectInfo {
            name: name.into(),
            description: String::new(),
        }]
    }

    #[test]
    fn undo_and_redo_walk_the_steps_and_track_the_save_point() {
        let mut project = Project::default();
        let mut history = History::new();
        assert!(!history.is_dirty());

        history.apply(&mut project, "Rename", rename("A")).unwrap();
        history.apply(&mut project, "Rename", rename("B")).unwrap();
        assert!(history.is_dirty());
        history.mark_saved();
        assert!(!history.is_dirty());

        assert_eq!(
            history.undo(&mut project).unwrap().as_deref(),
            Some("Rename")
        );
        assert_eq!(project.name, "A");
        assert!(history.is_dirty());
        history.redo(&mut project).unwrap();
        assert_eq!(project.name, "B");
        assert!(!history.is_dirty());

        // Undoing past the save point and editing makes the saved state unreachable.
        history.undo(&mut project).unwrap();
        history.apply(&mut project, "Rename", rename("C")).unwrap();
        assert!(history.is_dirty());
        history.undo(&mut project).unwrap();
        history.undo(&mut project).unwrap();
        assert_eq!(project.name, "");
        assert!(history.is_dirty());
        assert_eq!(history.undo(&mut project).unwrap(), None);
    }

    #[test]
    fn a_failing_gesture_changes_nothing_and_records_nothing() {
        let mut project = Project::default();
        let mut history = History::new();
        let mut edits = rename("A");
        edits.push(Edit::Tasks(crate::ListEdit::Remove { index: 3 }));
        assert!(history.apply(&mut project, "Bad", edits).is_err());
        assert_eq!(project, Project::default());
        assert_eq!(history.undo_label(), None);
        assert!(!history.is_dirty());
    }
}
