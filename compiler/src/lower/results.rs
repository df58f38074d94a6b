//! A function or operator box's result stored in a hidden variable of its type, so its
//! output pin has a live value online like every other pin (`docs/graphical-semantics.md`
//! §4.5).

use project_model::{BlockCall, ElementId};

use super::ProbeKind;
use super::fragment::Fragment;
use super::network::BodyLowering;
use super::value::Value;

impl BodyLowering<'_> {
    /// Declares the hidden variable that holds the result of `block` (output `index`, whose
    /// value is `expression`), records it as the pin's probe and returns its name and whether
    /// it is a BOOL; `None`
    /// when the result has no type a variable can have (an untyped constant such as `1 + 2`,
    /// or an expression the checker refuses, which it then reports at the box).
    pub(super) fn result_variable(
        &mut self,
        block: &BlockCall,
        index: usize,
        expression: &Value,
    ) -> Option<(String, bool)> {
        let pin = block.outputs.get(index)?.pin.trim().to_owned();
        let typing = self.typing_text(&expression.frag.text);
        let ty = (self.type_of)(&typing)?;
        let name = self.declare(
            block.id,
            &format!("_{pin}"),
            &ty,
            format!("the output {pin} of element {}", block.id.0),
        );
        self.probe(block.id, Some(&pin), ProbeKind::Value, name.clone());
        self.results.insert(name.to_lowercase(), typing);
        Some((name, ty.eq_ignore_ascii_case("BOOL")))
    }

    /// The stored result `name` of `block`'s output `pin`, as a value later elements read.
    pub(super) fn result_value(
        &self,
        block: ElementId,
        pin: &str,
        name: &str,
        boolean: bool,
    ) -> Value {
        Value::stable(
            Fragment::plain(name).mark(self.network, Some(block), Some(pin)),
            boolean,
            Some(block),
        )
    }

    /// `text` over the user's names only: a stored result is replaced by the expression it
    /// holds, and every other hidden name (a stored power, an enable or a trigger's output,
    /// all BOOL) by `TRUE`, so the checker types it in the POU as the user declared it.
    fn typing_text(&self, text: &str) -> String {
        let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
        let mut out = String::with_capacity(text.len());
        let mut rest = text;
        let mut after_word = false;
        while let Some(c) = rest.chars().next() {
            if !word(c) || after_word {
                out.push(c);
                after_word = word(c) || c == '#';
                rest = &rest[c.len_utf8()..];
                continue;
            }
            let end = rest.find(|c: char| !word(c)).unwrap_or(rest.len());
            let (name, tail) = rest.split_at(end);
            rest = tail;
            after_word = true;
            if !name.starts_with("__") {
                out.push_str(name);
                continue;
            }
            match self.results.get(&name.to_lowercase()) {
                Some(held) => {
                    out.push('(');
                    out.push_str(held);
                    out.push(')');
                }
                None => {
                    out.push_str("TRUE");
                    // A trigger's output is read as `__e2_trig.Q`.
                    if let Some(after) = rest.strip_prefix(".Q").or(rest.strip_prefix(".q"))
                        && !after.starts_with(word)
                    {
                        rest = after;
                    }
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lower::Callee;

    #[test]
    fn hidden_names_are_replaced_by_what_they_hold_for_typing() {
        let classify = |_: &str| Callee::Unknown;
        let type_of = |_: &str| None;
        let mut lowering = BodyLowering::new("__".into(), &classify, &type_of);
        lowering
            .results
            .insert("__e4_out".into(), "x * (-2)".into());
        assert_eq!(
            lowering.typing_text("LIMIT(MN := 0, IN := __e4_OUT, MX := T#5s) > a__b"),
            "LIMIT(MN := 0, IN := (x * (-2)), MX := T#5s) > a__b"
        );
        assert_eq!(
            lowering.typing_text("__e2_trig.Q AND __e3_EN OR __e2_trig.Quality"),
            "TRUE AND TRUE OR TRUE.Quality"
        );
    }
}
