//! Folding ranges: blocks that span several lines.

use std::ops::Range;

use super::trimmed_range;
use crate::syntax::SyntaxKind::*;
use crate::syntax::parse;

/// The byte ranges an editor can fold: POUs, members, sections, types, control statements and
/// comments of more than one line, in source order.
pub fn folding_ranges(text: &str) -> Vec<Range<usize>> {
    let root = parse(text).syntax();
    let mut ranges: Vec<Range<usize>> = root
        .descendants_with_tokens()
        .filter_map(|element| match element {
            rowan::NodeOrToken::Node(node) => matches!(
                node.kind(),
                POU | METHOD_DECL
                    | PROPERTY_DECL
                    | ACTION_DECL
                    | INTERFACE_DECL
                    | TYPE_DECL
                    | VAR_BLOCK
                    | IF_STMT
                    | CASE_STMT
                    | FOR_STMT
                    | WHILE_STMT
                    | REPEAT_STMT
                    | STEP_DECL
                    | TRANSITION_DECL
                    | CONFIGURATION_DECL
                    | RESOURCE_DECL
            )
            .then(|| trimmed_range(&node)),
            rowan::NodeOrToken::Token(token) => (token.kind() == BLOCK_COMMENT).then(|| {
                let range = token.text_range();
                usize::from(range.start())..usize::from(range.end())
            }),
        })
        .filter(|range| text[range.clone()].contains('\n'))
        .collect();
    ranges.sort_by_key(|range| (range.start, std::cmp::Reverse(range.end)));
    ranges
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_of_several_lines_fold() {
        let text = "PROGRAM P\nVAR\n  x : INT;\nEND_VAR\nIF x > 0 THEN\n  x := 0;\nEND_IF\nIF x THEN x := 1; END_IF\n(* a\n b *)\nEND_PROGRAM";
        let folded: Vec<&str> = folding_ranges(text)
            .iter()
            .map(|r| text[r.clone()].lines().next().unwrap_or(""))
            .collect();
        assert_eq!(folded, vec!["PROGRAM P", "VAR", "IF x > 0 THEN", "(* a"]);
    }
}
