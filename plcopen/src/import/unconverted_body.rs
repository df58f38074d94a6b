//! Why a body the document holds soundly did not become part of the project: the note of its
//! `NotConverted` report entry.

use thiserror::Error;

/// Why one body was not converted; its text is a full sentence without the final period,
/// about the body's holder ("its … body …").
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub(super) enum UnconvertedBody {
    /// An LD body whose graph is not a set of networks (LD has no CFC fallback).
    #[error("its {language} body is not a set of networks: {reason}")]
    NotNetworks {
        /// The body's language, as the report names it.
        language: &'static str,
        /// Why the graph is not a set of networks, naming the element.
        reason: String,
    },
    /// A body in a language Rivet does not convert.
    #[error("its body is {language}, which Rivet does not convert")]
    UnsupportedLanguage {
        /// The body's language, as the report names it.
        language: &'static str,
    },
    /// An FBD graph that is neither a set of networks nor a chart the CFC import converts.
    #[error(
        "its body is {language}: it is not a set of networks ({network_reason}), nor a CFC chart: {reason}"
    )]
    NeitherNetworksNorCfc {
        /// The body's language, as the report names it.
        language: &'static str,
        /// Why the graph is not a set of networks.
        network_reason: String,
        /// Why the graph is not a CFC chart either.
        reason: String,
    },
    /// A CFC or SFC body (or an FBD one read as CFC) that holds something the import does not
    /// convert.
    #[error("its body is {language}: {reason}")]
    NotConvertible {
        /// The body's language, as the report names it.
        language: &'static str,
        /// What it holds that is not converted.
        reason: String,
    },
}

#[cfg(test)]
mod tests {
    use super::UnconvertedBody;

    #[test]
    fn each_reason_reads_as_the_report_note() {
        let not_networks = UnconvertedBody::NotNetworks {
            language: "LD",
            reason: "element 3 feeds itself".into(),
        };
        assert_eq!(
            not_networks.to_string(),
            "its LD body is not a set of networks: element 3 feeds itself"
        );
        let unsupported = UnconvertedBody::UnsupportedLanguage { language: "SFC" };
        assert_eq!(
            unsupported.to_string(),
            "its body is SFC, which Rivet does not convert"
        );
        let neither = UnconvertedBody::NeitherNetworksNorCfc {
            language: "FBD",
            network_reason: "a loop".into(),
            reason: "no outputs".into(),
        };
        assert_eq!(
            neither.to_string(),
            "its body is FBD: it is not a set of networks (a loop), nor a CFC chart: no outputs"
        );
        let not_convertible = UnconvertedBody::NotConvertible {
            language: "CFC",
            reason: "a macro box".into(),
        };
        assert_eq!(not_convertible.to_string(), "its body is CFC: a macro box");
    }
}
