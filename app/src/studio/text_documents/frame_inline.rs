//! The values of a halted function's or method's locals shown inline in its body: each name
//! of a local in the text (not a member after a `.`, not in a comment or a string) gets the
//! value `FRAME_READ` gave, as the names of an instance get theirs from the watch.

use editor::InlineValue;
use project_model::TextTarget;

/// The name the image gives the POU of a body: `F_Scale`, `FB_Conveyor.Reset` for a method or
/// action; `None` for a property's accessor, whose frames the debugger names otherwise.
pub(super) fn image_name(target: &TextTarget) -> Option<String> {
    match target {
        TextTarget::Pou(name) => Some(name.clone()),
        TextTarget::Method { pou, method } => Some(format!("{pou}.{method}")),
        TextTarget::Action { pou, action } => Some(format!("{pou}.{action}")),
        _ => None,
    }
}

/// The inline values of `locals` (name, value) at each of their names in `text`.
pub(super) fn frame_inline_values(text: &str, locals: &[(String, String)]) -> Vec<InlineValue> {
    let mut values = Vec::new();
    if locals.is_empty() {
        return values;
    }
    let bytes = text.as_bytes();
    let mut at = 0;
    while at < bytes.len() {
        let rest = &text[at..];
        if rest.starts_with("//") {
            at += rest.find('\n').unwrap_or(rest.len());
        } else if rest.starts_with("(*") {
            at += rest.find("*)").map_or(rest.len(), |end| end + 2);
        } else if rest.starts_with('\'') || rest.starts_with('"') {
            let quote = &rest[..1];
            at += rest[1..].find(quote).map_or(rest.len(), |end| end + 2);
        } else if bytes[at].is_ascii_alphabetic() || bytes[at] == b'_' {
            let end = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .map_or(text.len(), |length| at + length);
            let member = text[..at].trim_end().ends_with('.');
            let word = &text[at..end];
            if !member
                && let Some((_, value)) = locals
                    .iter()
                    .find(|(name, _)| name.eq_ignore_ascii_case(word))
            {
                values.push(InlineValue {
                    range: at..end,
                    text: value.clone(),
                    changed: false,
                    forced: false,
                });
            }
            at = end;
        } else {
            at += rest.chars().next().map_or(1, char::len_utf8);
        }
    }
    values
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_name_of_a_local_gets_its_value_but_not_members_comments_or_strings() {
        let text = "// rIn scaled\nrOut := rIn * 2.0; (* rIn *) s := 'rIn'; x := fb.rIn + RIN;";
        let locals = vec![
            ("rIn".to_owned(), "1.5".to_owned()),
            ("rOut".to_owned(), "0.0".to_owned()),
        ];
        let values = frame_inline_values(text, &locals);
        let shown: Vec<(&str, &str)> = values
            .iter()
            .map(|value| (&text[value.range.clone()], value.text.as_str()))
            .collect();
        assert_eq!(shown, vec![("rOut", "0.0"), ("rIn", "1.5"), ("RIN", "1.5")]);
        assert!(frame_inline_values(text, &[]).is_empty());
    }

    #[test]
    fn a_method_body_is_named_as_the_image_names_it() {
        let method = TextTarget::Method {
            pou: "FB_Conveyor".to_owned(),
            method: "Reset".to_owned(),
        };
        assert_eq!(image_name(&method).as_deref(), Some("FB_Conveyor.Reset"));
        assert_eq!(
            image_name(&TextTarget::Pou("F_Scale".to_owned())).as_deref(),
            Some("F_Scale")
        );
    }
}
