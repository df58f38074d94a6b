//! What the declaration table remembers between frames: the selected row and the text typed
//! into cells that is not in the model yet.

use std::collections::HashMap;

use project_model::{ListEdit, Variable};

use super::cells::{self, TextColumn};
use crate::TableTexts;
use crate::table_texts::fill;

/// Kept in egui's memory under the table's id; never saved.
#[derive(Clone, Debug, Default)]
pub(crate) struct TableState {
    /// The row the toolbar acts on.
    pub(crate) selected: Option<usize>,
    /// Text typed into a cell, by row and column, until it is committed or abandoned. A draft
    /// that fails validation stays, so its error stays in view until the user fixes it.
    pub(crate) drafts: HashMap<(usize, TextColumn), Draft>,
}

/// Text typed into one cell.
#[derive(Clone, Debug)]
pub(crate) struct Draft {
    /// The row's variable when typing began: if the model changes underneath (an undo, another
    /// view), the draft no longer applies and is dropped.
    pub(crate) original: Variable,
    /// The text as typed.
    pub(crate) text: String,
}

impl TableState {
    /// Forgets drafts and a selection that no longer fit `variables`.
    pub(crate) fn forget_stale(&mut self, variables: &[Variable]) {
        self.drafts
            .retain(|(row, _), draft| variables.get(*row) == Some(&draft.original));
        if self.selected.is_some_and(|row| row >= variables.len()) {
            self.selected = None;
        }
    }
}

/// A row gesture from the toolbar or a row's context menu.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum RowAction {
    /// A new variable before the row.
    InsertAbove(usize),
    /// A new variable after the row (at the end when the index is the length).
    InsertBelow(usize),
    /// Deletes the row.
    Delete(usize),
    /// Swaps the row with the one above.
    MoveUp(usize),
    /// Swaps the row with the one below.
    MoveDown(usize),
}

impl RowAction {
    /// The edit the gesture makes, with its undo label, and the row selected afterwards; `None`
    /// when it would do nothing (moving the first row up).
    pub(crate) fn edit(
        self,
        variables: &[Variable],
        new_section: project_model::VarSection,
        texts: &TableTexts,
    ) -> Option<(String, ListEdit<Variable>, Option<usize>)> {
        let labelled = |template: &str, name: &str| fill(template, &[("name", name)]);
        let name = |row: usize| variables.get(row).map(|v| v.name.clone());
        let new_variable = |neighbour: Option<usize>| Variable {
            section: neighbour
                .and_then(|row| variables.get(row))
                .map_or(new_section, |v| v.section),
            ..Variable::new(cells::fresh_name(variables), "BOOL")
        };
        match self {
            Self::InsertAbove(row) | Self::InsertBelow(row) => {
                let index = match self {
                    Self::InsertAbove(_) => row.min(variables.len()),
                    _ => (row + 1).min(variables.len()),
                };
                let neighbour = variables.get(row).map(|_| row);
                let item = new_variable(neighbour);
                let label = labelled(&texts.insert_variable, &item.name);
                Some((label, ListEdit::Insert { index, item }, Some(index)))
            }
            Self::Delete(row) => {
                let label = labelled(&texts.delete_variable, &name(row)?);
                let selected = (row + 1 < variables.len())
                    .then_some(row)
                    .or_else(|| row.checked_sub(1));
                Some((label, ListEdit::Remove { index: row }, selected))
            }
            Self::MoveUp(row) => {
                let to = row.checked_sub(1)?;
                let label = labelled(&texts.move_variable_up, &name(row)?);
                Some((label, ListEdit::Move { from: row, to }, Some(to)))
            }
            Self::MoveDown(row) => {
                let to = row + 1;
                if to >= variables.len() {
                    return None;
                }
                let label = labelled(&texts.move_variable_down, &name(row)?);
                Some((label, ListEdit::Move { from: row, to }, Some(to)))
            }
        }
    }
}
