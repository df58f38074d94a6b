//! IEC 61131-3 identifiers as the project model accepts them.

/// Tells whether `name` is an identifier: a letter or `_`, then letters, digits or `_`.
///
/// Letters include every Unicode letter, so Chinese names are accepted as in CODESYS with
/// Unicode identifiers enabled. Object names become file names, so this also keeps path
/// separators, dots and spaces out of them.
pub fn is_valid_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    let Some(first) = chars.next() else {
        return false;
    };
    (first.is_alphabetic() || first == '_') && chars.all(|c| c.is_alphanumeric() || c == '_')
}

/// Compares two identifiers as IEC 61131-3 does: without regard to case.
pub fn same_identifier(a: &str, b: &str) -> bool {
    a.chars()
        .flat_map(char::to_lowercase)
        .eq(b.chars().flat_map(char::to_lowercase))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identifiers_accept_letters_digits_underscores_and_chinese() {
        assert!(is_valid_identifier("Main"));
        assert!(is_valid_identifier("_fb1"));
        assert!(is_valid_identifier("输送带"));
        assert!(!is_valid_identifier(""));
        assert!(!is_valid_identifier("1abc"));
        assert!(!is_valid_identifier("a.b"));
        assert!(!is_valid_identifier("a b"));
        assert!(!is_valid_identifier("../x"));
    }

    #[test]
    fn identifiers_compare_without_case() {
        assert!(same_identifier("MAIN", "main"));
        assert!(!same_identifier("Main", "Mains"));
    }
}
