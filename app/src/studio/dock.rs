//! The docking layout: device tree on the left, documents in the middle, messages, watch,
//! forces, trace and tasks at the bottom, properties on the right. The user may drag tabs
//! anywhere; the layout (open documents included) is saved between runs.

use egui_tiles::{Container, SimplificationOptions, Tile, TileId, Tiles, Tree};
use serde::{Deserialize, Serialize};

use super::pane::Pane;
use super::tree_node::TreeNode;

/// The key under which the layout is kept in eframe's storage.
pub const LAYOUT_KEY: &str = "rivet.layout";

/// The tiles of the studio window.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Dock {
    /// The egui_tiles tree.
    pub tree: Tree<Pane>,
    /// The tab group new documents open in, when no document is open to find it by.
    editor_area: TileId,
}

impl Default for Dock {
    fn default() -> Self {
        let mut tiles = Tiles::default();
        let devices = tiles.insert_pane(Pane::Devices);
        let devices = tiles.insert_tab_tile(vec![devices]);
        let editor_area = tiles.insert_tab_tile(Vec::new());
        let bottom: Vec<TileId> = [
            Pane::Messages,
            Pane::Watch,
            Pane::Forces,
            Pane::Trace,
            Pane::Tasks,
        ]
        .into_iter()
        .map(|pane| tiles.insert_pane(pane))
        .collect();
        let bottom = tiles.insert_tab_tile(bottom);
        let middle = tiles.insert_vertical_tile(vec![editor_area, bottom]);
        let properties = tiles.insert_pane(Pane::Properties);
        let properties = tiles.insert_tab_tile(vec![properties]);
        let root = tiles.insert_horizontal_tile(vec![devices, middle, properties]);
        set_shares(&mut tiles, middle, &[(editor_area, 0.68), (bottom, 0.32)]);
        set_shares(
            &mut tiles,
            root,
            &[(devices, 0.18), (middle, 0.64), (properties, 0.18)],
        );
        Self {
            tree: Tree::new(egui::Id::unique("rivet_dock"), root, tiles),
            editor_area,
        }
    }
}

fn set_shares(tiles: &mut Tiles<Pane>, container: TileId, shares: &[(TileId, f32)]) {
    if let Some(Tile::Container(Container::Linear(linear))) = tiles.get_mut(container) {
        for &(child, share) in shares {
            linear.shares.set_share(child, share);
        }
    }
}

impl Dock {
    /// The simplifications applied after each frame: empty tab groups stay (the editor area
    /// must survive closing its last document), every pane keeps a tab.
    pub fn simplification_options() -> SimplificationOptions {
        SimplificationOptions {
            prune_empty_tabs: false,
            all_panes_must_have_tabs: true,
            ..SimplificationOptions::default()
        }
    }

    /// A saved layout, checked: one with a tool pane missing (from an older version) is
    /// replaced by the default, so no tool is ever out of reach.
    pub fn restored(saved: Option<Dock>) -> Self {
        match saved {
            Some(dock)
                if Pane::TOOLS
                    .iter()
                    .all(|pane| dock.tree.tiles.find_pane(pane).is_some()) =>
            {
                dock
            }
            _ => Self::default(),
        }
    }

    /// Shows `node` in a tab: brings its tab forward if open, else opens it in the editor area.
    pub fn open_document(&mut self, node: TreeNode) {
        let pane = Pane::Document(node);
        if self.tree.tiles.find_pane(&pane).is_none() {
            let group = self.editor_group();
            let id = self.tree.tiles.insert_pane(pane.clone());
            if let Some(Tile::Container(container)) = self.tree.tiles.get_mut(group) {
                container.add_child(id);
            }
        }
        self.show(&pane);
    }

    /// Brings `pane`'s tab forward; a debugging pane not in the layout yet (they are not in
    /// the default one) is added beside the messages first.
    pub fn show(&mut self, pane: &Pane) {
        if matches!(pane, Pane::Breakpoints | Pane::CallStack)
            && self.tree.tiles.find_pane(pane).is_none()
        {
            let beside = self
                .tree
                .tiles
                .find_pane(&Pane::Messages)
                .and_then(|messages| self.tree.tiles.parent_of(messages));
            let id = self.tree.tiles.insert_pane(pane.clone());
            match beside.and_then(|group| self.tree.tiles.get_mut(group)) {
                Some(Tile::Container(container)) => container.add_child(id),
                _ => {
                    let group = self.editor_group();
                    if let Some(Tile::Container(container)) = self.tree.tiles.get_mut(group) {
                        container.add_child(id);
                    }
                }
            }
        }
        self.tree
            .make_active(|_, tile| matches!(tile, Tile::Pane(p) if p == pane));
    }

    /// The tab group documents open in: the one holding a document, else the editor area,
    /// else a new group beside the first tile of the root.
    fn editor_group(&mut self) -> TileId {
        let holding_document = self.tree.tiles.iter().find_map(|(id, tile)| match tile {
            Tile::Pane(Pane::Document(_)) => self.tree.tiles.parent_of(*id),
            _ => None,
        });
        if let Some(group) = holding_document {
            return group;
        }
        if matches!(
            self.tree.tiles.get(self.editor_area),
            Some(Tile::Container(Container::Tabs(_)))
        ) {
            return self.editor_area;
        }
        let group = self.tree.tiles.insert_tab_tile(Vec::new());
        match self.tree.root() {
            Some(root) => {
                if let Some(Tile::Container(container)) = self.tree.tiles.get_mut(root) {
                    container.add_child(group);
                }
            }
            None => self.tree.root = Some(group),
        }
        self.editor_area = group;
        group
    }

    /// Where the editor area is on screen while it holds no document (for a hint to draw
    /// there); `None` when documents are open or the area is gone.
    pub fn empty_editor_area(&self) -> Option<egui::Rect> {
        match self.tree.tiles.get(self.editor_area) {
            Some(Tile::Container(Container::Tabs(tabs))) if tabs.children.is_empty() => {
                self.tree.tiles.rect(self.editor_area)
            }
            _ => None,
        }
    }

    /// The open documents, in no particular order.
    pub fn documents(&self) -> Vec<TreeNode> {
        self.tree
            .tiles
            .iter()
            .filter_map(|(_, tile)| match tile {
                Tile::Pane(Pane::Document(node)) => Some(node.clone()),
                _ => None,
            })
            .collect()
    }

    /// Closes the documents for which `keep` says no.
    pub fn retain_documents(&mut self, mut keep: impl FnMut(&TreeNode) -> bool) {
        let closed: Vec<TileId> = self
            .tree
            .tiles
            .iter()
            .filter_map(|(id, tile)| match tile {
                Tile::Pane(Pane::Document(node)) if !keep(node) => Some(*id),
                _ => None,
            })
            .collect();
        for id in closed {
            self.tree.remove_recursively(id);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn documents_open_once_in_the_editor_area_and_survive_a_round_trip() {
        let mut dock = Dock::default();
        dock.open_document(TreeNode::Object("Main".into()));
        dock.open_document(TreeNode::Object("Main".into()));
        dock.open_document(TreeNode::Task("MainTask".into()));
        let mut open = dock.documents();
        open.sort_by_key(|node| format!("{node:?}"));
        assert_eq!(
            open,
            vec![
                TreeNode::Object("Main".into()),
                TreeNode::Task("MainTask".into())
            ]
        );
        let main = dock
            .tree
            .tiles
            .find_pane(&Pane::Document(TreeNode::Object("Main".into())));
        let task = dock
            .tree
            .tiles
            .find_pane(&Pane::Document(TreeNode::Task("MainTask".into())));
        let parent = |id: Option<TileId>| id.and_then(|id| dock.tree.tiles.parent_of(id));
        assert_eq!(parent(main), parent(task));

        let text = serde_json::to_string(&dock).unwrap_or_default();
        let back: Dock = serde_json::from_str(&text).unwrap_or_default();
        let restored = Dock::restored(Some(back));
        assert_eq!(restored.documents().len(), 2);

        let mut closed = restored.clone();
        closed.retain_documents(|node| matches!(node, TreeNode::Task(_)));
        assert_eq!(closed.documents(), vec![TreeNode::Task("MainTask".into())]);
    }

    #[test]
    fn a_layout_without_a_tool_pane_is_replaced_by_the_default() {
        let mut dock = Dock::default();
        if let Some(watch) = dock.tree.tiles.find_pane(&Pane::Watch) {
            dock.tree.remove_recursively(watch);
        }
        let restored = Dock::restored(Some(dock));
        assert!(restored.tree.tiles.find_pane(&Pane::Watch).is_some());
    }
}
