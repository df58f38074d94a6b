//! The interface languages.

use serde::{Deserialize, Serialize};

/// The interface language, chosen in the settings and remembered between runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Language {
    /// English.
    #[default]
    English,
    /// Simplified Chinese.
    SimplifiedChinese,
}

impl Language {
    /// Every language, in the order the settings menu lists them.
    pub const ALL: [Self; 2] = [Self::English, Self::SimplifiedChinese];

    /// The language's own name, shown in the settings menu.
    pub fn native_name(self) -> &'static str {
        match self {
            Self::English => "English",
            Self::SimplifiedChinese => "简体中文",
        }
    }
}
