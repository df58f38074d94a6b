//! Reversible edits of ordered lists, shared by every list in the model.

/// An edit of a `Vec<T>`: insert, remove, replace or move one item.
#[derive(Clone, Debug, PartialEq)]
pub enum ListEdit<T> {
    /// Inserts `item` before position `index` (`index == len` appends).
    Insert {
        /// Where the item goes.
        index: usize,
        /// The new item.
        item: T,
    },
    /// Removes the item at `index`.
    Remove {
        /// Which item.
        index: usize,
    },
    /// Replaces the item at `index` with `item`.
    Replace {
        /// Which item.
        index: usize,
        /// The new value.
        item: T,
    },
    /// Moves the item at `from` so that it ends up at `to`.
    Move {
        /// Where the item is.
        from: usize,
        /// Where the item ends up.
        to: usize,
    },
}

/// Why a list edit could not be applied: an index past the end, given with the list's length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndexOutOfRange {
    /// The index asked for.
    pub index: usize,
    /// The list's length.
    pub len: usize,
}

impl<T> ListEdit<T> {
    /// Applies the edit to `list` and returns the edit that undoes it.
    ///
    /// The list is unchanged when an index is out of range.
    pub fn apply(self, list: &mut Vec<T>) -> Result<Self, IndexOutOfRange> {
        let len = list.len();
        let check = |index: usize, limit: usize| {
            if index < limit {
                Ok(())
            } else {
                Err(IndexOutOfRange { index, len })
            }
        };
        match self {
            Self::Insert { index, item } => {
                check(index, len + 1)?;
                list.insert(index, item);
                Ok(Self::Remove { index })
            }
            Self::Remove { index } => {
                check(index, len)?;
                let item = list.remove(index);
                Ok(Self::Insert { index, item })
            }
            Self::Replace { index, item } => {
                check(index, len)?;
                let old = std::mem::replace(&mut list[index], item);
                Ok(Self::Replace { index, item: old })
            }
            Self::Move { from, to } => {
                check(from, len)?;
                check(to, len)?;
                let item = list.remove(from);
                list.insert(to, item);
                Ok(Self::Move { from: to, to: from })
            }
        }
    }

    /// The item the edit puts into the list, if any, for validation before applying.
    pub fn new_item(&self) -> Option<&T> {
        match self {
            Self::Insert { item, .. } | Self::Replace { item, .. } => Some(item),
            Self::Remove { .. } | Self::Move { .. } => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_list_edit_is_undone_by_its_inverse() {
        let original = vec![1, 2, 3, 4];
        let edits = [
            ListEdit::Insert { index: 4, item: 9 },
            ListEdit::Remove { index: 0 },
            ListEdit::Replace { index: 2, item: 7 },
            ListEdit::Move { from: 0, to: 3 },
            ListEdit::Move { from: 3, to: 1 },
        ];
        for edit in edits {
            let mut list = original.clone();
            let inverse = edit.clone().apply(&mut list).unwrap();
            assert_ne!(list, original, "{edit:?} changed nothing");
            inverse.apply(&mut list).unwrap();
            assert_eq!(list, original, "{edit:?} was not undone");
        }
    }

    #[test]
    fn out_of_range_edits_fail_and_leave_the_list_alone() {
        let mut list = vec![1, 2];
        let error = ListEdit::Remove { index: 2 }.apply(&mut list).unwrap_err();
        assert_eq!(error, IndexOutOfRange { index: 2, len: 2 });
        assert!(ListEdit::Move { from: 0, to: 2 }.apply(&mut list).is_err());
        assert!(
            ListEdit::Insert { index: 3, item: 0 }
                .apply(&mut list)
                .is_err()
        );
        assert_eq!(list, vec![1, 2]);
    }
}
