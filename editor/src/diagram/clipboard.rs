//! The structure a graphical editor copied, kept in the egui context so that every editor of
//! its kind (LD/FBD, CFC) in the studio pastes it, with the text the system clipboard got for
//! other applications. A paste takes the structure only while the system clipboard still holds
//! that text; other text is typed into the selected element instead.

use std::sync::Arc;

use egui::{Context, Id};

/// What a copy put in the context: the copied structure and the text given to the system
/// clipboard with it.
pub(crate) struct Copied<T> {
    /// The text the system clipboard got.
    pub text: String,
    /// The copied structure.
    pub structure: T,
}

/// Gives the system clipboard `words` (the empty ones left out) joined by spaces, and keeps
/// `structure` under `id` for the editors' pastes.
pub(crate) fn copy_structure<T: Send + Sync + 'static>(
    ctx: &Context,
    id: Id,
    words: impl IntoIterator<Item = String>,
    structure: T,
) {
    let text = words
        .into_iter()
        .filter(|word| !word.is_empty())
        .collect::<Vec<_>>()
        .join(" ");
    ctx.copy_text(text.clone());
    keep_structure(ctx, id, text, structure);
}

/// Keeps `structure` under `id` as the copy of `text`, leaving the system clipboard alone (a
/// paste moves the kept copy so that the next paste lands beside it).
pub(crate) fn keep_structure<T: Send + Sync + 'static>(
    ctx: &Context,
    id: Id,
    text: String,
    structure: T,
) {
    ctx.data_mut(|data| data.insert_temp(id, Arc::new(Copied { text, structure })));
}

/// The structure copied last under `id`, when a paste of `text` pastes it: the system
/// clipboard still holds the text the copy gave it, or the paste came from a menu without
/// text.
pub(crate) fn copied_structure<T: Send + Sync + 'static>(
    ctx: &Context,
    id: Id,
    text: &str,
) -> Option<Arc<Copied<T>>> {
    ctx.data(|data| data.get_temp::<Arc<Copied<T>>>(id))
        .filter(|copied| text.is_empty() || copied.text == text)
}
