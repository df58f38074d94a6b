//! The diagram editors of the open LD/FBD bodies and the lowering their online values are read
//! through.

use std::collections::HashMap;

use compiler::lower::LoweredBody;
use editor::{CfcEditor, DiagramEditor, DiagramView, ElementDiagnostic, SfcEditor};
use project_model::{Network, Pou, Project, TextTarget};

use crate::studio::debug::BodyLines;
use crate::studio::i18n::Language;

use super::chart_documents::ChartDocuments;
use super::online_values::{BodyProbes, ProbePath};
use super::texts::diagram_texts;

/// One body's editor and what it was last given, so each frame gives it only what changed.
pub(super) struct DiagramDocument {
    /// The editor.
    pub editor: DiagramEditor,
    /// The project revision whose networks the editor holds; `None` after the editor made a
    /// change, so the model's answer (taken or refused) is brought in next frame.
    pub synced: Option<u64>,
    /// The language of the editor's words.
    language: Language,
    /// The markers last given.
    diagnostics: Vec<ElementDiagnostic>,
    /// Whether the editor was last made read-only.
    read_only: bool,
}

impl DiagramDocument {
    /// Gives the editor the model's `networks` when the project changed since it last took
    /// them: comparing every network each frame would cost as much as drawing them.
    pub(super) fn sync(&mut self, networks: &[Network], revision: u64) {
        if self.synced != Some(revision) {
            self.editor.set_networks(networks);
            self.synced = Some(revision);
        }
    }

    /// Puts the editor's words in `language` on a switch of language.
    pub(super) fn set_language(&mut self, language: Language) {
        if self.language != language {
            self.language = language;
            self.editor.set_texts(diagram_texts(language));
        }
    }

    /// Makes the editor read-only (while logged in) or editable on a change only: making it
    /// read-only closes its open field, which must stay open for a value prepared online.
    pub(super) fn set_read_only(&mut self, read_only: bool) {
        if self.read_only != read_only {
            self.read_only = read_only;
            self.editor.set_read_only(read_only);
        }
    }

    /// Gives the editor `diagnostics` when they differ from the ones it shows.
    pub(super) fn set_diagnostics(&mut self, diagnostics: Vec<ElementDiagnostic>) {
        if self.diagnostics != diagnostics {
            self.diagnostics = diagnostics.clone();
            self.editor.set_diagnostics(diagnostics);
        }
    }
}

/// Every diagram editor of the open documents, by body.
#[derive(Default)]
pub struct GraphicalDocuments {
    /// The editors, by body.
    pub(super) documents: HashMap<TextTarget, DiagramDocument>,
    /// The lowering the online values and faults are read through.
    pub(super) lowering: LoweringCache,
    /// The editors of the CFC and SFC bodies.
    pub(super) charts: ChartDocuments,
    /// Whether the CFC editors show the execution order; `None` until the user chose, when each
    /// editor shows its default.
    pub(super) show_execution_order: Option<bool>,
    /// The network, element, step or transition selected in the graphical editor that has the
    /// keyboard focus this frame, taken by the text documents as the place the Debug menu's
    /// "Toggle breakpoint" and "Run to cursor" act on.
    pub(crate) focused_place: Option<crate::studio::debug::BreakpointPlace>,
}

/// The lowered LD/FBD bodies of one project revision, for their probes and the origins of
/// faults, and the probes' paths on the target per body and instance; made again only when the
/// project changes (lowering or resolving every frame is too slow).
#[derive(Default)]
pub(super) struct LoweringCache {
    /// The revision lowered and its bodies.
    lowered: Option<(u64, Vec<LoweredBody>)>,
    /// The probes' paths of each body shown for an instance, at the lowered revision.
    paths: HashMap<(TextTarget, String), Vec<ProbePath>>,
    /// The places of the lines of each lowered body, made when the debugger first marks it
    /// at the lowered revision.
    lines: HashMap<TextTarget, BodyLines>,
    /// The `.pou.toml` file of each POU asked for, and the revision they are of (kept apart
    /// from the lowering, which breakpoints alone do not need).
    pou_files: (u64, HashMap<String, String>),
}

impl LoweringCache {
    /// Lowers `project` again when `revision` is not the one lowered, forgetting what was
    /// worked out from the last lowering.
    fn lower(&mut self, project: &Project, revision: u64) {
        if self
            .lowered
            .as_ref()
            .is_none_or(|(seen, _)| *seen != revision)
        {
            let bodies = compiler::lower::lower_project(project).bodies;
            self.lowered = Some((revision, bodies));
            self.paths.clear();
            self.lines.clear();
        }
    }

    /// Every lowered body of `project` at `revision`, lowering the project again when it
    /// changed.
    pub(super) fn bodies(&mut self, project: &Project, revision: u64) -> &[LoweredBody] {
        self.lower(project, revision);
        self.lowered.as_ref().map_or(&[], |(_, bodies)| bodies)
    }

    /// The places of the lines of the lowered body `target` of `project` at `revision`, worked
    /// out once per revision; `None` for a body that is not lowered.
    pub(super) fn body_lines(
        &mut self,
        project: &Project,
        revision: u64,
        target: &TextTarget,
    ) -> Option<&BodyLines> {
        self.lower(project, revision);
        if !self.lines.contains_key(target) {
            let body = self
                .lowered
                .as_ref()?
                .1
                .iter()
                .find(|body| body.target == *target)?;
            self.lines.insert(target.clone(), BodyLines::of(body));
        }
        self.lines.get(target)
    }

    /// The `.pou.toml` file of the POU `pou` of `project` at `revision` (as
    /// [`super::breakpoints::pou_file`] names it), found once per revision.
    pub(super) fn pou_file(&mut self, project: &Project, revision: u64, pou: &str) -> &str {
        let (seen, files) = &mut self.pou_files;
        if *seen != revision {
            *seen = revision;
            files.clear();
        }
        files
            .entry(pou.to_owned())
            .or_insert_with(|| super::breakpoints::pou_file(project, pou))
    }

    /// The lowered body `target` of `project` at `revision` and its probes' paths for the
    /// instance at `instance`, lowering the project again when it changed.
    pub(super) fn body(
        &mut self,
        project: &Project,
        pou: &Pou,
        revision: u64,
        target: &TextTarget,
        instance: &str,
    ) -> Option<(&LoweredBody, &[ProbePath])> {
        self.lower(project, revision);
        let body = self
            .lowered
            .as_ref()?
            .1
            .iter()
            .find(|body| body.target == *target)?;
        let paths = self
            .paths
            .entry((target.clone(), instance.to_owned()))
            .or_insert_with(|| {
                BodyProbes {
                    project,
                    pou,
                    instance,
                    lowered: body,
                }
                .paths()
            });
        Some((body, paths))
    }
}

/// The editor of `target` in `documents`, made for `networks` in the view of `language` when
/// it is new.
pub(super) fn document<'d>(
    documents: &'d mut HashMap<TextTarget, DiagramDocument>,
    target: &TextTarget,
    networks: &[Network],
    language: project_model::Language,
    revision: u64,
) -> &'d mut DiagramDocument {
    documents.entry(target.clone()).or_insert_with(|| {
        let mut editor = DiagramEditor::new(networks, DiagramView::of_language(language));
        editor.set_texts(diagram_texts(Language::default()));
        DiagramDocument {
            editor,
            synced: Some(revision),
            language: Language::default(),
            diagnostics: Vec::new(),
            read_only: false,
        }
    })
}

impl GraphicalDocuments {
    /// The graphical body whose lowered text is `file` (as the image's sources name it) and
    /// the network and element of its `line` (from 1): where a halt or a frame of the call
    /// stack is shown. `None` for a Structured Text body.
    pub(crate) fn place_of_line(
        &mut self,
        project: &Project,
        revision: u64,
        file: &str,
        line: u32,
    ) -> Option<(TextTarget, editor::BodyPlace)> {
        // Called for every frame of the call stack each UI frame: the body is found by
        // comparing paths (no string built per body) and its lines come from the cache.
        let wanted = std::path::Path::new(file);
        let target = self
            .lowering
            .bodies(project, revision)
            .iter()
            .find(|body| body.text_file == wanted)?
            .target
            .clone();
        let place = self
            .lowering
            .body_lines(project, revision, &target)?
            .place_at(line)?;
        Some((target, place))
    }

    /// The graphical bodies of `project` at `revision` with the element of each line of their
    /// lowered text, from the lowering kept for the editors.
    pub(crate) fn graphical_bodies(
        &mut self,
        project: &Project,
        revision: u64,
    ) -> crate::debug_bodies::GraphicalBodies {
        crate::debug_bodies::GraphicalBodies::of_lowered(self.lowering.bodies(project, revision))
    }

    /// The diagram editor of `target`, if its document was drawn.
    pub fn editor(&self, target: &TextTarget) -> Option<&DiagramEditor> {
        self.documents.get(target).map(|document| &document.editor)
    }

    /// The CFC editor of `target`, if its document was drawn.
    pub fn cfc_editor(&self, target: &TextTarget) -> Option<&CfcEditor> {
        self.charts.cfc.get(target).map(|document| &document.editor)
    }

    /// The SFC editor of `target`, if its document was drawn.
    pub fn sfc_editor(&self, target: &TextTarget) -> Option<&SfcEditor> {
        self.charts.sfc.get(target).map(|document| &document.editor)
    }

    /// Shows or hides the execution order in every CFC editor (View ▸ Display Execution Order).
    pub fn toggle_execution_order(&mut self) {
        let shown = self.show_execution_order.unwrap_or_else(|| {
            self.charts
                .cfc
                .values()
                .next()
                .is_none_or(|document| document.editor.shows_execution_order())
        });
        self.show_execution_order = Some(!shown);
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // A panic is a failed test.

    use super::*;

    #[test]
    fn a_bodys_lines_and_file_are_worked_out_once_per_revision() {
        let project = project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        let interlock = TextTarget::Pou("Interlock".to_owned());
        let mut cache = LoweringCache::default();
        let lowered = cache
            .bodies(&project, 1)
            .iter()
            .find(|body| body.target == interlock)
            .map(BodyLines::of)
            .unwrap();
        assert_eq!(cache.body_lines(&project, 1, &interlock), Some(&lowered));
        assert_eq!(
            cache.pou_file(&project, 1, "Interlock"),
            "application/Interlock.pou.toml"
        );
        // Another revision is worked out again: here a project without the POU.
        let empty = Project::default();
        assert_eq!(cache.body_lines(&empty, 2, &interlock), None);
        assert_eq!(cache.pou_file(&empty, 2, "Interlock"), "");
    }
}
