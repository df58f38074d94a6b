//! The editors of the open CFC and SFC bodies and what each was last given, so each frame gives
//! it only what changed.

use std::collections::HashMap;

use editor::{CfcDiagnostic, CfcEditor, SfcDiagnostic, SfcEditor};
use project_model::{CfcChart, SfcChart, TextTarget};

use crate::studio::i18n::Language;

use super::chart_texts::{cfc_texts, sfc_texts};

/// One CFC body's editor.
pub(super) struct CfcDocument {
    /// The editor.
    pub editor: CfcEditor,
    /// The project revision whose chart the editor holds; `None` after the editor made a
    /// change, so the model's answer (taken or refused) is brought in next frame.
    pub synced: Option<u64>,
    /// The language of the editor's words.
    language: Language,
    /// The markers last given.
    diagnostics: Vec<CfcDiagnostic>,
    /// Whether the editor was last made read-only.
    read_only: bool,
}

impl CfcDocument {
    /// An editor of `chart`, in line with the project at `revision`.
    fn new(chart: &CfcChart, revision: u64) -> Self {
        let mut editor = CfcEditor::new(chart);
        editor.set_texts(cfc_texts(Language::default()));
        Self {
            editor,
            synced: Some(revision),
            language: Language::default(),
            diagnostics: Vec::new(),
            read_only: false,
        }
    }

    /// Gives the editor the model's `chart` when the project changed since it last took it.
    pub(super) fn sync(&mut self, chart: &CfcChart, revision: u64) {
        if self.synced != Some(revision) {
            self.editor.set_chart(chart);
            self.synced = Some(revision);
        }
    }

    /// Puts the editor's words in `language` on a switch of language.
    pub(super) fn set_language(&mut self, language: Language) {
        if self.language != language {
            self.language = language;
            self.editor.set_texts(cfc_texts(language));
        }
    }

    /// Makes the editor read-only (while logged in) or editable, on a change only: making it
    /// read-only closes its open field, which must stay open for a value prepared online.
    pub(super) fn set_read_only(&mut self, read_only: bool) {
        if self.read_only != read_only {
            self.read_only = read_only;
            self.editor.set_read_only(read_only);
        }
    }

    /// Gives the editor `diagnostics` when they differ from the ones it shows.
    pub(super) fn set_diagnostics(&mut self, diagnostics: Vec<CfcDiagnostic>) {
        if self.diagnostics != diagnostics {
            self.diagnostics = diagnostics.clone();
            self.editor.set_diagnostics(diagnostics);
        }
    }
}

/// One SFC body's editor.
pub(super) struct SfcDocument {
    /// The editor.
    pub editor: SfcEditor,
    /// The project revision whose chart the editor holds; `None` after the editor made a
    /// change.
    pub synced: Option<u64>,
    /// The language of the editor's words.
    language: Language,
    /// Whether the editor was last made read-only.
    read_only: bool,
}

impl SfcDocument {
    /// An editor of `chart`, in line with the project at `revision`.
    fn new(chart: &SfcChart, revision: u64) -> Self {
        let mut editor = SfcEditor::new(chart);
        editor.set_texts(sfc_texts(Language::default()));
        Self {
            editor,
            synced: Some(revision),
            language: Language::default(),
            read_only: false,
        }
    }

    /// Gives the editor the model's `chart` (and the POU's action and transition object names)
    /// when the project changed since it last took them.
    pub(super) fn sync(
        &mut self,
        chart: &SfcChart,
        revision: u64,
        actions: impl FnOnce() -> Vec<String>,
        transitions: impl FnOnce() -> Vec<String>,
    ) {
        if self.synced != Some(revision) {
            self.editor.set_chart(chart);
            self.editor.set_action_names(actions());
            self.editor.set_transition_objects(transitions());
            self.synced = Some(revision);
        }
    }

    /// Puts the editor's words in `language` on a switch of language.
    pub(super) fn set_language(&mut self, language: Language) {
        if self.language != language {
            self.language = language;
            self.editor.set_texts(sfc_texts(language));
        }
    }

    /// Makes the editor read-only (while logged in) or editable, on a change only.
    pub(super) fn set_read_only(&mut self, read_only: bool) {
        if self.read_only != read_only {
            self.read_only = read_only;
            self.editor.set_read_only(read_only);
        }
    }

    /// Gives the editor `diagnostics` when they differ from the ones it shows.
    pub(super) fn set_diagnostics(&mut self, diagnostics: Vec<SfcDiagnostic>) {
        if self.editor.diagnostics() != diagnostics.as_slice() {
            self.editor.set_diagnostics(diagnostics);
        }
    }
}

/// The chart editors of the open documents, by body.
#[derive(Default)]
pub(super) struct ChartDocuments {
    /// The CFC editors.
    pub cfc: HashMap<TextTarget, CfcDocument>,
    /// The SFC editors.
    pub sfc: HashMap<TextTarget, SfcDocument>,
}

impl ChartDocuments {
    /// The CFC editor of `target`, made for `chart` when it is new.
    pub(super) fn cfc(
        &mut self,
        target: &TextTarget,
        chart: &CfcChart,
        revision: u64,
    ) -> &mut CfcDocument {
        self.cfc
            .entry(target.clone())
            .or_insert_with(|| CfcDocument::new(chart, revision))
    }

    /// The SFC editor of `target`, made for `chart` when it is new.
    pub(super) fn sfc(
        &mut self,
        target: &TextTarget,
        chart: &SfcChart,
        revision: u64,
    ) -> &mut SfcDocument {
        self.sfc
            .entry(target.clone())
            .or_insert_with(|| SfcDocument::new(chart, revision))
    }
}
