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
    /// Gestures with the same key that follow each other join this step (typing a word is one
    /// undo step, not one per character).
    pub merge_key: Option<String>,
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
            merge_key: None,
        });
        self.revision += 1;
        Ok(())
    }

    /// Applies the edits of a gesture that continues the previous one when both carry the same
    /// `merge_key` (consecutive characters typed in one body): they join the last undo step.
    /// Otherwise, or when the last step is the saved state or was undone, it is a step of its
    /// own. If any edit fails the project is unchanged.
    pub fn apply_merging(
        &mut self,
        project: &mut Project,
        label: impl Into<String>,
        edits: Vec<Edit>,
        merge_key: &str,
    ) -> Result<(), EditError> {
        let at_save_point = self.save_point == Some(self.undo.len());
        let joins = self.redo.is_empty()
            && !at_save_point
            && self
                .undo
                .last()
                .is_some_and(|last| last.merge_key.as_deref() == Some(merge_key));
        if !joins {
            self.apply(project, label, edits)?;
            if let Some(last) = self.undo.last_mut() {
                last.merge_key = Some(merge_key.to_owned());
            }
            return Ok(());
        }
        let mut inverse = match Edit::Group(edits.clone()).apply(project)? {
            Edit::Group(inverse) => inverse,
            other => vec![other],
        };
        if let Some(last) = self.undo.last_mut() {
            last.forward.extend(edits);
            // The newest change is undone first.
            inverse.append(&mut last.inverse);
            last.inverse = inverse;
        }
        self.revision += 1;
        Ok(())
    }

    /// Ends merging: the next gesture starts its own undo step whatever its key.
    pub fn break_merging(&mut self) {
        if let Some(last) = self.undo.last_mut() {
            last.merge_key = None;
        }
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

    #[test]
    fn typing_merges_into_one_step_until_the_key_changes_or_a_save() {
        let mut project = Project::default();
        project
            .application
            .children
            .push(crate::Node::Object(crate::Object::Pou(crate::Pou {
                name: "Main".into(),
                kind: crate::PouKind::Program,
                return_type: None,
                extends: None,
                implements: Vec::new(),
                comment: String::new(),
                variables: Vec::new(),
                body: crate::Body::st(""),
                methods: Vec::new(),
                properties: Vec::new(),
                actions: Vec::new(),
                transitions: Vec::new(),
            })));
        let typed = |at: usize, text: &str| {
            vec![Edit::ReplaceText {
                target: crate::TextTarget::Pou("Main".into()),
                range: at..at,
                text: text.into(),
            }]
        };
        let body = |project: &Project| match project.application.object("Main") {
            Some(crate::Object::Pou(pou)) => pou.body.st_text().unwrap_or_default().to_owned(),
            _ => String::new(),
        };
        let mut history = History::new();
        for (at, c) in ["a", "b", "c"].iter().enumerate() {
            history
                .apply_merging(&mut project, "Typing", typed(at, c), "typing Main")
                .unwrap_or_else(|e| panic!("{e}"));
        }
        assert_eq!(body(&project), "abc");
        history.undo(&mut project).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(body(&project), "");
        history.redo(&mut project).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(body(&project), "abc");
        // After a save the next character starts a new step, so undo returns to the saved text.
        history.mark_saved();
        history
            .apply_merging(&mut project, "Typing", typed(3, "d"), "typing Main")
            .unwrap_or_else(|e| panic!("{e}"));
        history.undo(&mut project).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(body(&project), "abc");
        assert!(!history.is_dirty());
        // A different key starts a new step too.
        history
            .apply_merging(&mut project, "Typing", typed(3, "x"), "typing Main")
            .unwrap_or_else(|e| panic!("{e}"));
        history.break_merging();
        history
            .apply_merging(&mut project, "Typing", typed(4, "y"), "typing Main")
            .unwrap_or_else(|e| panic!("{e}"));
        history.undo(&mut project).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(body(&project), "abcx");
    }

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
