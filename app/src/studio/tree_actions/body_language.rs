//! The implementation languages a new POU, method, action or property can be written in.

use project_model::{Body, CfcChart, Network, SfcChart};

use crate::studio::i18n::Text;

/// An implementation language the add dialogs offer.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BodyLanguage {
    /// Structured Text.
    #[default]
    St,
    /// Instruction List.
    Il,
    /// Ladder Diagram.
    Ld,
    /// Function Block Diagram.
    Fbd,
    /// Continuous Function Chart.
    Cfc,
    /// Sequential Function Chart.
    Sfc,
}

impl BodyLanguage {
    /// The languages the dialogs offer, in the order they show them.
    pub const OFFERED: [Self; 6] = [
        Self::St,
        Self::Il,
        Self::Ld,
        Self::Fbd,
        Self::Cfc,
        Self::Sfc,
    ];

    /// The body a new POU or member starts with: no text for ST and IL; for LD and FBD one empty
    /// network (no title, comment, label, elements or outputs), as CODESYS creates them, so the
    /// editor opens on a network the user can insert into right away; an empty CFC chart; for
    /// SFC CODESYS's start: the step `Init`, a transition and a jump back to `Init`.
    pub fn empty_body(self) -> Body {
        match self {
            Self::St => Body::st(""),
            Self::Il => Body::Il {
                text: String::new(),
            },
            Self::Ld => Body::Ld {
                networks: vec![Network::default()],
            },
            Self::Fbd => Body::Fbd {
                networks: vec![Network::default()],
            },
            Self::Cfc => Body::Cfc {
                chart: CfcChart::default(),
            },
            Self::Sfc => Body::Sfc {
                chart: SfcChart::new_body(),
            },
        }
    }

    /// The language's name in the dialogs.
    pub fn text(self) -> Text {
        match self {
            Self::St => Text::LanguageSt,
            Self::Il => Text::LanguageIl,
            Self::Ld => Text::LanguageLd,
            Self::Fbd => Text::LanguageFbd,
            Self::Cfc => Text::LanguageCfc,
            Self::Sfc => Text::LanguageSfc,
        }
    }
}

#[cfg(test)]
mod tests {
    use project_model::Language;

    use super::*;

    #[test]
    fn graphical_bodies_start_with_one_empty_network_and_st_with_no_text() {
        assert_eq!(BodyLanguage::St.empty_body(), Body::st(""));
        for (language, model) in [
            (BodyLanguage::Ld, Language::Ld),
            (BodyLanguage::Fbd, Language::Fbd),
        ] {
            let body = language.empty_body();
            assert_eq!(body.language(), model);
            match &body {
                Body::Ld { networks } | Body::Fbd { networks } => {
                    assert_eq!(networks, &[Network::default()]);
                }
                other => panic!("{language:?} gave {other:?}"),
            }
        }
        assert_eq!(
            BodyLanguage::Cfc.empty_body(),
            Body::Cfc {
                chart: CfcChart::default()
            }
        );
        assert_eq!(
            BodyLanguage::Sfc.empty_body(),
            Body::Sfc {
                chart: SfcChart::new_body()
            }
        );
    }
}
