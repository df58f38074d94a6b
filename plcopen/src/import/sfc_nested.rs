//! The bodies an SFC body holds beside its sequence (inline action bodies, the LD graph of a
//! wired condition), converted as the POU conversion converts any body (docs/plcopen-xml.md
//! §4.2, §4.3): the chart's walk hands them to it through [`NestedBodies`].

use std::collections::HashSet;

use project_model::Body;

use super::body_fault::BodyFault;
use super::converter::{Converter, Place};
use super::pou_objects::PouObjects;
use super::pous::BodyAt;
use crate::body::Body as XmlBody;

/// The conversion of a body found inside an SFC body. The walk of a chart runs on a thread of
/// its own (it recurses per nested branch), hence `Send`.
pub(super) trait NestedBodies: Send {
    /// `body`, standing at `at` and named `what` in the report, as a Rivet body; its own inline
    /// actions and conditions (an SFC body's) go into `synthesized`. A body that cannot be
    /// converted is [`BodyFault::NotConverted`] with the reason, a wrong one
    /// [`BodyFault::Error`].
    fn nested_body(
        &mut self,
        body: &XmlBody,
        at: &BodyAt<'_>,
        what: &str,
        synthesized: &mut PouObjects,
    ) -> Result<Body, BodyFault>;

    /// The lower-case names of the document's structure types (docs/plcopen-xml.md §4.5).
    fn structures(&self) -> &HashSet<String>;
}

impl NestedBodies for Converter<'_> {
    fn nested_body(
        &mut self,
        body: &XmlBody,
        at: &BodyAt<'_>,
        what: &str,
        synthesized: &mut PouObjects,
    ) -> Result<Body, BodyFault> {
        match self.body_at(body, at, what, synthesized) {
            Ok(Ok(converted)) => Ok(converted),
            Ok(Err(reason)) => Err(BodyFault::NotConverted(reason.to_string())),
            Err(error) => Err(BodyFault::Error(
                Place {
                    path: error.path,
                    line: error.line,
                    column: error.column,
                },
                *error.kind,
            )),
        }
    }

    fn structures(&self) -> &HashSet<String> {
        &self.structures
    }
}
