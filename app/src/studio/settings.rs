//! Settings remembered between runs of the studio.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::debug::Breakpoints;

use super::i18n::Language;
use super::online::TargetKind;

/// The key under which the settings are kept in eframe's storage.
pub const SETTINGS_KEY: &str = "rivet.settings";

/// User preferences kept in eframe's storage (a RON file in the platform's config folder).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Settings {
    /// The interface language.
    pub language: Language,
    /// The colour theme.
    pub theme: Theme,
    /// The target the studio logs in to.
    pub target: TargetKind,
    /// The breakpoints of each project, by its folder: kept with the studio, not in the
    /// project, as they belong to one user's debugging (`docs/debugging.md` §3).
    pub breakpoints: BTreeMap<String, Breakpoints>,
}

impl Settings {
    /// The key of `dir`'s breakpoints in [`Settings::breakpoints`].
    pub fn project_key(dir: &std::path::Path) -> String {
        dir.to_string_lossy().into_owned()
    }
}

/// The colour theme.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Theme {
    /// Dark background.
    #[default]
    Dark,
    /// Light background.
    Light,
}

impl Theme {
    /// The egui theme to apply.
    pub fn egui_theme(self) -> egui::Theme {
        match self {
            Self::Dark => egui::Theme::Dark,
            Self::Light => egui::Theme::Light,
        }
    }
}
