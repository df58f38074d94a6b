//! Generated text that remembers which element (and pin) each of its byte ranges comes from.

use std::ops::Range;

use project_model::ElementId;

/// A recorded byte range of generated text and the element it belongs to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Span {
    /// The bytes, from the start of the fragment (or, once in a body, of the body's text).
    pub range: Range<usize>,
    /// The network's index in its body.
    pub network: usize,
    /// The element; `None` for the network itself (its label).
    pub element: Option<ElementId>,
    /// The pin, when the range belongs to one pin of a box.
    pub pin: Option<String>,
    /// The range is text the user typed (an operand), so its names are the user's.
    pub user: bool,
    /// The range repeats text that is compiled elsewhere in the body too (an SFC condition
    /// kept for its probe), so what the checker finds in it is found there already.
    pub shadow: bool,
}

/// A piece of generated text with its recorded ranges.
#[derive(Clone, Debug, Default)]
pub(crate) struct Fragment {
    /// The text.
    pub text: String,
    /// The recorded ranges, in the order they were recorded (outer ranges are recorded after
    /// the ranges they contain).
    pub spans: Vec<Span>,
}

impl Fragment {
    /// Plain text with no recorded range.
    pub fn plain(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            spans: Vec::new(),
        }
    }

    /// Appends plain text.
    pub fn push_str(&mut self, text: &str) {
        self.text.push_str(text);
    }

    /// Appends another fragment, moving its ranges to where it lands.
    pub fn push(&mut self, other: Fragment) {
        let shift = self.text.len();
        self.text.push_str(&other.text);
        self.spans.extend(other.spans.into_iter().map(|mut span| {
            span.range = span.range.start + shift..span.range.end + shift;
            span
        }));
    }

    /// Records the whole fragment as belonging to `element` (and `pin`) of `network`.
    pub fn mark(mut self, network: usize, element: Option<ElementId>, pin: Option<&str>) -> Self {
        self.spans.push(Span {
            range: 0..self.text.len(),
            network,
            element,
            pin: pin.map(str::to_owned),
            user: false,
            shadow: false,
        });
        self
    }

    /// Records the whole fragment as a second copy of text of `element` compiled elsewhere
    /// in the body, whose findings are dropped.
    pub fn mark_shadow(mut self, network: usize, element: ElementId) -> Self {
        self.spans.push(Span {
            range: 0..self.text.len(),
            network,
            element: Some(element),
            pin: None,
            user: false,
            shadow: true,
        });
        self
    }

    /// Records the whole fragment as text the user typed into `element`.
    pub fn mark_user(mut self, network: usize, element: ElementId, pin: Option<&str>) -> Self {
        self.spans.push(Span {
            range: 0..self.text.len(),
            network,
            element: Some(element),
            pin: pin.map(str::to_owned),
            user: true,
            shadow: false,
        });
        self
    }
}

/// Concatenates fragments and plain text into one fragment.
macro_rules! frag {
    ($($part:expr),* $(,)?) => {{
        let mut out = $crate::lower::fragment::Fragment::default();
        $( $crate::lower::fragment::Append::append_to($part, &mut out); )*
        out
    }};
}
pub(crate) use frag;

/// What [`frag!`] can append: plain text or a fragment.
pub(crate) trait Append {
    /// Appends `self` to `out`.
    fn append_to(self, out: &mut Fragment);
}

impl Append for &str {
    fn append_to(self, out: &mut Fragment) {
        out.push_str(self);
    }
}

impl Append for String {
    fn append_to(self, out: &mut Fragment) {
        out.push_str(&self);
    }
}

impl Append for &String {
    fn append_to(self, out: &mut Fragment) {
        out.push_str(self);
    }
}

impl Append for Fragment {
    fn append_to(self, out: &mut Fragment) {
        out.push(self);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn appended_fragments_keep_their_ranges_where_they_land() {
        let inner = Fragment::plain("a").mark_user(0, ElementId(3), None);
        let whole = frag!("x := ", inner, ";").mark(0, Some(ElementId(4)), None);
        assert_eq!(whole.text, "x := a;");
        assert_eq!(whole.spans[0].range, 5..6);
        assert_eq!(whole.spans[0].element, Some(ElementId(3)));
        assert_eq!(whole.spans[1].range, 0..7);
    }
}
