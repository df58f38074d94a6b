//! From generated text back to networks, elements and pins: the origin map, and findings of
//! the checker and the code generator moved onto the elements they are about.

use std::ops::Range;

use super::fragment::Span;
use super::{ElementPlace, LoweredProject};
use crate::codegen::{CodegenError, Within};
use crate::diagnostic::Diagnostic;
use crate::origin::Origin;
use crate::sema::ProjectDiagnostic;

/// The recorded ranges of a lowered body's text, each with its network, element and pin.
///
/// Ranges nest like the text (an element's statement contains its pins' expressions), and
/// every statement lies in a recorded range, so a range maps to the innermost recorded range
/// around it.
#[derive(Clone, Debug, Default)]
pub struct OriginMap {
    /// The recorded ranges, inner ones before the ranges that contain them.
    spans: Vec<Span>,
}

impl OriginMap {
    /// The map of `spans`.
    pub(crate) fn new(spans: Vec<Span>) -> Self {
        Self { spans }
    }

    /// Where the bytes `range` of the lowered text come from: the innermost element (and pin)
    /// whose text contains them, or `None` for bytes outside every statement (whitespace).
    pub fn origin(&self, range: Range<usize>) -> Option<Origin> {
        self.span(range).map(|span| Origin::Element {
            network: span.network,
            element: span.element,
            pin: span.pin.clone(),
        })
    }

    /// The byte range of the text the user typed into `element` (or its `pin`) inside the
    /// lowered text, if the element has one there.
    pub fn user_range(
        &self,
        network: usize,
        element: project_model::ElementId,
        pin: Option<&str>,
    ) -> Option<Range<usize>> {
        self.spans
            .iter()
            .find(|span| {
                span.user
                    && span.network == network
                    && span.element == Some(element)
                    && span.pin.as_deref() == pin
            })
            .map(|span| span.range.clone())
    }

    /// The innermost recorded range containing `range`, else the innermost containing its
    /// start.
    pub(crate) fn span(&self, range: Range<usize>) -> Option<&Span> {
        let innermost = |fits: &dyn Fn(&Span) -> bool| {
            self.spans
                .iter()
                .enumerate()
                .filter(|(_, span)| fits(span))
                .min_by_key(|(index, span)| (span.range.len(), *index))
                .map(|(_, span)| span)
        };
        innermost(&|span| span.range.start <= range.start && range.end <= span.range.end)
            .or_else(|| innermost(&|span| span.range.contains(&range.start)))
    }
}

impl LoweredProject<'_> {
    /// What the lowering itself found (unknown labels, empty operands, names with `__`), at
    /// their elements.
    pub(crate) fn findings(&self) -> Vec<ProjectDiagnostic> {
        let mut found = Vec::new();
        for body in &self.bodies {
            for finding in &body.findings {
                found.push(ProjectDiagnostic {
                    file: body.file.clone(),
                    declaration: None,
                    element: Some(ElementPlace {
                        pou: body.pou.clone(),
                        target: body.target.clone(),
                        network: finding.network,
                        element: finding.element,
                        pin: finding.pin.clone(),
                    }),
                    diagnostic: Diagnostic::new(finding.code, 0..0, finding.message.clone()),
                });
            }
        }
        for body in &self.il {
            found.extend(body.findings().iter().cloned());
        }
        found
    }

    /// The checker's findings on the lowered project, those in lowered bodies moved onto their
    /// elements with messages in the user's words; findings about hidden declarations (which
    /// the user cannot act on) are dropped.
    pub(crate) fn locate(&self, found: Vec<ProjectDiagnostic>) -> Vec<ProjectDiagnostic> {
        if self.bodies.is_empty() && self.il.is_empty() {
            return found;
        }
        found
            .into_iter()
            .filter_map(|mut finding| {
                if let Some(name) = &finding.declaration {
                    let hidden = self
                        .bodies
                        .iter()
                        .any(|body| body.file == finding.file && body.is_hidden(name))
                        || self.il.iter().any(|body| body.is_hidden(name));
                    return (!hidden).then_some(finding);
                }
                if let Some(body) = self
                    .il
                    .iter()
                    .find(|body| body.has_text_file(&finding.file))
                {
                    return Some(body.locate(finding));
                }
                let Some(body) = self.body_of_text_file(&finding.file) else {
                    return Some(finding);
                };
                let range = finding.diagnostic.range.clone();
                let span = body.origins.span(range.clone());
                if span.is_some_and(|span| span.shadow) {
                    return None;
                }
                finding.element = Some(match span {
                    Some(span) => body.place_of(span),
                    None => ElementPlace {
                        pou: body.pou.clone(),
                        target: body.target.clone(),
                        network: 0,
                        element: None,
                        pin: None,
                    },
                });
                // Inside what the user typed, the range stays, relative to that text.
                finding.diagnostic.range = match span {
                    Some(span) if span.user => {
                        range.start.saturating_sub(span.range.start)
                            ..range
                                .end
                                .min(span.range.end)
                                .saturating_sub(span.range.start)
                    }
                    _ => 0..0,
                };
                finding.diagnostic.message = body.describe(&finding.diagnostic.message);
                finding.file = body.file.clone();
                Some(finding)
            })
            .collect()
    }

    /// A code generation error in a lowered body, with the POU's file and the element
    /// instead of the generated text's file and line.
    pub(crate) fn locate_error(&self, error: CodegenError) -> CodegenError {
        let CodegenError::Unsupported {
            mut message,
            mut location,
        } = error
        else {
            return error;
        };
        // An IL body's text has the IL file's lines, so only the file's name changes.
        for place in &mut location.within {
            if let Within::File(name) = place
                && let Some(il_file) = self.il_file_of(std::path::Path::new(name.as_str()))
            {
                *name = il_file.to_string_lossy().into_owned();
            }
        }
        let body = location.within.iter().find_map(|place| match place {
            Within::File(name) => self
                .bodies
                .iter()
                .find(|body| body.text_file.to_string_lossy() == name.as_str()),
            _ => None,
        });
        if let Some(body) = body {
            message = body.describe(&message);
            for place in &mut location.within {
                match place {
                    Within::File(name) => *name = body.file.to_string_lossy().into_owned(),
                    Within::Statement(statement) => {
                        if let Origin::Text { range } = &statement.origin
                            && let Some(origin) = body.origins.origin(range.clone())
                        {
                            statement.origin = origin;
                        }
                    }
                    Within::Pou(_) | Within::Declaration(_) => {}
                }
            }
        }
        CodegenError::Unsupported { message, location }
    }
}

/// `message` with each hidden name (a whole identifier, any case) replaced by its words.
pub(crate) fn describe_hidden(message: &str, descriptions: &[(String, String)]) -> String {
    if !message.contains("__") {
        return message.to_owned();
    }
    let mut out = message.to_owned();
    let mut sorted: Vec<&(String, String)> = descriptions.iter().collect();
    // Longer names first, so `__e5_trig` is not read as `__e5`.
    sorted.sort_by_key(|(name, _)| std::cmp::Reverse(name.len()));
    for (name, words) in sorted {
        // ASCII lower case keeps every byte where it is, so offsets found in the lower-case
        // text are offsets of the message.
        let lower_name = name.to_ascii_lowercase();
        let mut from = 0;
        while let Some(at) = out[from..]
            .to_ascii_lowercase()
            .find(&lower_name)
            .map(|at| at + from)
        {
            let end = at + name.len();
            let boundary = |c: Option<char>| !c.is_some_and(|c| c.is_alphanumeric() || c == '_');
            if boundary(out[..at].chars().next_back()) && boundary(out[end..].chars().next()) {
                out.replace_range(at..end, words);
                from = at + words.len();
            } else {
                from = end;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::ElementId;

    fn span(range: Range<usize>, element: u32, user: bool) -> Span {
        Span {
            range,
            network: 0,
            element: Some(ElementId(element)),
            pin: None,
            user,
            shadow: false,
        }
    }

    #[test]
    fn a_range_maps_to_the_innermost_element_around_it() {
        let map = OriginMap::new(vec![span(5..6, 1, true), span(0..12, 2, false)]);
        assert_eq!(
            map.origin(5..6),
            Some(Origin::Element {
                network: 0,
                element: Some(ElementId(1)),
                pin: None
            })
        );
        assert!(matches!(
            map.origin(0..7),
            Some(Origin::Element {
                element: Some(ElementId(2)),
                ..
            })
        ));
        assert_eq!(map.origin(20..21), None);
    }

    #[test]
    fn hidden_names_are_replaced_by_their_words_as_whole_names() {
        let words = [
            ("__e5".to_owned(), "the power flow of element 5".to_owned()),
            ("__e5_trig".to_owned(), "the edge of element 5".to_owned()),
        ];
        assert_eq!(
            describe_hidden("'__E5' and '__e5_trig.Q' but not __e55", &words),
            "'the power flow of element 5' and 'the edge of element 5.Q' but not __e55"
        );
        assert_eq!(
            describe_hidden("「İ」 reads __e5", &words),
            "「İ」 reads the power flow of element 5"
        );
    }
}
