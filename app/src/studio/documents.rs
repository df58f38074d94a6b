//! The tab area: one tab per open document, docked with egui_tiles.

use egui::Ui;
use egui_tiles::{Behavior, Tile, TileId, Tiles, Tree, UiResponse};
use project_model::Project;

use super::document_view::document_ui;
use super::i18n::Language;
use super::tree_node::TreeNode;

/// The open documents and how their tabs are laid out.
///
/// It lives as long as the studio window; opening another project closes every tab.
pub struct Documents {
    tree: Tree<TreeNode>,
}

impl Default for Documents {
    fn default() -> Self {
        Self {
            tree: Tree::new_tabs(egui::Id::unique("rivet_documents"), Vec::new()),
        }
    }
}

impl Documents {
    /// Shows `node` in a tab: brings its tab forward if open, else opens a new one.
    pub fn open(&mut self, node: TreeNode) {
        if self.tree.tiles.find_pane(&node).is_none() {
            let pane = self.tree.tiles.insert_pane(node.clone());
            // New tabs join the first tab group (the user may have split the area into
            // several); with none left, a new group holding the old layout is made the root.
            let tab_group = self.tree.tiles.iter().find_map(|(id, tile)| {
                matches!(tile, Tile::Container(egui_tiles::Container::Tabs(_))).then_some(*id)
            });
            match tab_group {
                Some(group) => {
                    if let Some(Tile::Container(container)) = self.tree.tiles.get_mut(group) {
                        container.add_child(pane);
                    }
                }
                None => {
                    let mut children: Vec<TileId> = self.tree.root().into_iter().collect();
                    children.push(pane);
                    let root = self.tree.tiles.insert_tab_tile(children);
                    self.tree.root = Some(root);
                }
            }
        }
        self.tree
            .make_active(|_, tile| matches!(tile, Tile::Pane(pane) if *pane == node));
    }

    /// Closes every tab.
    pub fn close_all(&mut self) {
        *self = Self::default();
    }

    /// The documents with a tab, in no particular order.
    pub fn open_documents(&self) -> Vec<TreeNode> {
        self.tree
            .tiles
            .iter()
            .filter_map(|(_, tile)| match tile {
                Tile::Pane(pane) => Some(pane.clone()),
                Tile::Container(_) => None,
            })
            .collect()
    }

    /// Whether no tab is open.
    pub fn is_empty(&self) -> bool {
        self.open_documents().is_empty()
    }

    /// Draws the tabs and the active documents.
    pub fn ui(&mut self, ui: &mut Ui, project: Option<&Project>, language: Language) {
        let mut behavior = DocumentBehavior { project, language };
        self.tree.ui(&mut behavior, ui);
    }
}

struct DocumentBehavior<'a> {
    project: Option<&'a Project>,
    language: Language,
}

impl Behavior<TreeNode> for DocumentBehavior<'_> {
    fn pane_ui(&mut self, ui: &mut Ui, _tile_id: TileId, pane: &mut TreeNode) -> UiResponse {
        if let Some(project) = self.project {
            document_ui(ui, project, pane, self.language);
        }
        UiResponse::None
    }

    fn tab_title_for_pane(&mut self, pane: &TreeNode) -> egui::WidgetText {
        pane.title(self.project).into()
    }

    fn is_tab_closable(&self, _tiles: &Tiles<TreeNode>, _tile_id: TileId) -> bool {
        true
    }

    fn simplification_options(&self) -> egui_tiles::SimplificationOptions {
        egui_tiles::SimplificationOptions {
            all_panes_must_have_tabs: true,
            ..Default::default()
        }
    }
}
