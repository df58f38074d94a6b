//! Keyboard navigation: arrows move the selection to the nearest element in their direction
//! within a network, and up and down continue into the neighbouring networks.

use egui::Pos2;

use super::editor::DiagramEditor;
use super::placed::Shape;

/// The direction of an arrow key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Direction {
    Left,
    Right,
    Up,
    Down,
}

impl DiagramEditor {
    /// Moves the selection one element in `direction`.
    pub(super) fn navigate(&mut self, direction: Direction) {
        let Some(index) = self.selection.network else {
            if !self.networks.is_empty() {
                self.select_first_in(0);
            }
            return;
        };
        let Some(current) = self
            .selection
            .elements
            .last()
            .and_then(|id| self.layouts.get(index)?.element(*id))
            .map(|element| element.rect.center())
        else {
            match direction {
                Direction::Up if index > 0 => self.select_first_in(index - 1),
                Direction::Down | Direction::Right | Direction::Left => self.select_first_in(index),
                Direction::Up => {}
            }
            return;
        };
        if let Some(id) = self.nearest(index, current, direction) {
            self.select(Some(index), vec![id]);
            return;
        }
        match direction {
            Direction::Up if index > 0 => self.select_network(index - 1),
            Direction::Down if index + 1 < self.networks.len() => self.select_first_in(index + 1),
            _ => {}
        }
    }

    /// The element of network `index` nearest to `from` in `direction`.
    fn nearest(
        &self,
        index: usize,
        from: Pos2,
        direction: Direction,
    ) -> Option<project_model::ElementId> {
        self.layouts[index]
            .elements
            .iter()
            .filter(|element| element.id.is_some() && !matches!(element.shape, Shape::Group))
            .filter_map(|element| {
                let delta = element.rect.center() - from;
                let (along, across) = match direction {
                    Direction::Left => (-delta.x, delta.y),
                    Direction::Right => (delta.x, delta.y),
                    Direction::Up => (-delta.y, delta.x),
                    Direction::Down => (delta.y, delta.x),
                };
                (along > 0.01).then(|| (element.id, along + 3.0 * across.abs()))
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .and_then(|(id, _)| id)
    }

    /// Selects the top-left element of network `index`, or the network when it is empty.
    fn select_first_in(&mut self, index: usize) {
        let first = self.layouts[index]
            .elements
            .iter()
            .filter(|element| element.id.is_some() && !matches!(element.shape, Shape::Group))
            .min_by(|a, b| {
                (a.rect.min.y, a.rect.min.x)
                    .partial_cmp(&(b.rect.min.y, b.rect.min.x))
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .and_then(|element| element.id);
        self.select(Some(index), first.into_iter().collect());
    }

    /// Selects the last (bottom-right) element of network `index`, or the network.
    fn select_network(&mut self, index: usize) {
        let last = self.layouts[index]
            .elements
            .iter()
            .filter(|element| element.id.is_some() && !matches!(element.shape, Shape::Group))
            .max_by(|a, b| {
                (a.rect.min.y, a.rect.min.x)
                    .partial_cmp(&(b.rect.min.y, b.rect.min.x))
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .and_then(|element| element.id);
        self.select(Some(index), last.into_iter().collect());
    }
}
