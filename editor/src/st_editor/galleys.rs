//! A cache of laid-out lines, so a line is shaped again only when its text, highlighting or
//! inline boxes change.

use std::collections::HashMap;
use std::sync::Arc;

use egui::Galley;

/// Galleys keyed by a hash of everything that shapes them; entries unused for a frame are
/// dropped, so the cache holds about the visible lines.
#[derive(Default)]
pub struct GalleyCache {
    /// The galleys used this frame.
    current: HashMap<u64, Arc<Galley>>,
    /// The galleys of the last frame not used yet this frame.
    previous: HashMap<u64, Arc<Galley>>,
}

impl GalleyCache {
    /// Starts a frame: what the last frame did not use is forgotten.
    pub fn begin_frame(&mut self) {
        self.previous = std::mem::take(&mut self.current);
    }

    /// The galley for `key`, laid out by `layout` when it is not cached.
    pub fn get(&mut self, key: u64, layout: impl FnOnce() -> Arc<Galley>) -> Arc<Galley> {
        if let Some(galley) = self.current.get(&key) {
            return galley.clone();
        }
        let galley = self.previous.remove(&key).unwrap_or_else(layout);
        self.current.insert(key, galley.clone());
        galley
    }
}
