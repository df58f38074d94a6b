//! Rivet's type and value texts as PLCopen `dataType` and `value` elements.
//!
//! Declarations hold types and values as the text the user wrote. The forms the schema has
//! elements for are written as those elements so other tools see an array as an array; any other
//! text (a constant's expression in a bound, an inline enumeration, a type the schema does not
//! name such as `LTIME`) is written as `derived` or `simpleValue` with the text, which every
//! reader keeps as written.

use super::error::ExportError;
use super::xml_writer::XmlWriter;

/// The elementary types the v2.01 schema writes as empty elements.
const ELEMENTARY: [&str; 19] = [
    "BOOL", "BYTE", "WORD", "DWORD", "LWORD", "SINT", "INT", "DINT", "LINT", "USINT", "UINT",
    "UDINT", "ULINT", "REAL", "LREAL", "TIME", "DATE", "DT", "TOD",
];

/// Writes the element of the type `text` (the content of a `type`, `baseType` or `returnType`).
pub(super) fn write_type(writer: &mut XmlWriter, text: &str) -> Result<(), ExportError> {
    let trimmed = text.trim();
    if ELEMENTARY.contains(&trimmed) {
        return writer.empty(trimmed, &[]);
    }
    if let Some((wide, length)) = string_type(trimmed) {
        let name = if wide { "wstring" } else { "string" };
        return match length {
            Some(length) => writer.empty(name, &[("length", length)]),
            None => writer.empty(name, &[]),
        };
    }
    if let Some((ranges, base)) = array_type(trimmed) {
        writer.start("array", &[])?;
        for (lower, upper) in ranges {
            writer.empty("dimension", &[("lower", lower), ("upper", upper)])?;
        }
        writer.start("baseType", &[])?;
        write_type(writer, base)?;
        writer.end("baseType")?;
        return writer.end("array");
    }
    if let Some(base) = strip_keyword(trimmed, "POINTER TO ") {
        writer.start("pointer", &[])?;
        writer.start("baseType", &[])?;
        write_type(writer, base)?;
        writer.end("baseType")?;
        return writer.end("pointer");
    }
    if let Some((base, lower, upper)) = subrange_type(trimmed) {
        let name = if base.starts_with('U') {
            "subrangeUnsigned"
        } else {
            "subrangeSigned"
        };
        writer.start(name, &[])?;
        writer.empty("range", &[("lower", lower), ("upper", upper)])?;
        writer.start("baseType", &[])?;
        writer.empty(base, &[])?;
        writer.end("baseType")?;
        return writer.end(name);
    }
    writer.empty("derived", &[("name", text)])
}

/// Writes the `value` content of the initial value `text`: `arrayValue` for `[…]`,
/// `structValue` for `(member := …, …)`, else `simpleValue` with the text.
pub(super) fn write_value(writer: &mut XmlWriter, text: &str) -> Result<(), ExportError> {
    let trimmed = text.trim();
    if let Some(inner) = trimmed
        .strip_prefix('[')
        .and_then(|rest| rest.strip_suffix(']'))
        && let Some(items) = split_items(inner)
    {
        writer.start("arrayValue", &[])?;
        for item in items {
            match repetition(item) {
                Some((count, value)) => {
                    writer.start("value", &[("repetitionValue", count)])?;
                    write_value(writer, value)?;
                }
                None => {
                    writer.start("value", &[])?;
                    write_value(writer, item)?;
                }
            }
            writer.end("value")?;
        }
        return writer.end("arrayValue");
    }
    if let Some(inner) = trimmed
        .strip_prefix('(')
        .and_then(|rest| rest.strip_suffix(')'))
        && let Some(items) = split_items(inner)
        && let Some(members) = items
            .iter()
            .map(|item| member(item))
            .collect::<Option<Vec<_>>>()
    {
        writer.start("structValue", &[])?;
        for (name, value) in members {
            writer.start("value", &[("member", name)])?;
            write_value(writer, value)?;
            writer.end("value")?;
        }
        return writer.end("structValue");
    }
    writer.empty("simpleValue", &[("value", text)])
}

/// `STRING`, `STRING(n)`, `WSTRING`, `WSTRING(n)` with a decimal length.
fn string_type(text: &str) -> Option<(bool, Option<&str>)> {
    let (wide, rest) = if let Some(rest) = text.strip_prefix("WSTRING") {
        (true, rest)
    } else {
        (false, text.strip_prefix("STRING")?)
    };
    if rest.is_empty() {
        return Some((wide, None));
    }
    let length = rest.strip_prefix('(')?.strip_suffix(')')?;
    is_decimal(length).then_some((wide, Some(length)))
}

/// `ARRAY[l..u, …] OF T` with integer bounds.
fn array_type(text: &str) -> Option<(Vec<(&str, &str)>, &str)> {
    let rest = strip_keyword(text, "ARRAY")?
        .trim_start()
        .strip_prefix('[')?;
    let close = rest.find(']')?;
    let base = strip_keyword(rest[close + 1..].trim_start(), "OF ")?;
    let mut ranges = Vec::new();
    for range in rest[..close].split(',') {
        let (lower, upper) = range.trim().split_once("..")?;
        let (lower, upper) = (lower.trim(), upper.trim());
        if !is_integer(lower) || !is_integer(upper) {
            return None;
        }
        ranges.push((lower, upper));
    }
    Some((ranges, base))
}

/// `INT(l..u)` with an elementary integer base and integer bounds.
fn subrange_type(text: &str) -> Option<(&str, &str, &str)> {
    let open = text.find('(')?;
    let base = &text[..open];
    const INTEGERS: [&str; 8] = [
        "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT",
    ];
    if !INTEGERS.contains(&base) {
        return None;
    }
    let (lower, upper) = text[open + 1..].strip_suffix(')')?.split_once("..")?;
    (is_integer(lower) && is_integer(upper)).then_some((base, lower, upper))
}

/// `text` after `keyword` (compared without regard to ASCII case).
fn strip_keyword<'t>(text: &'t str, keyword: &str) -> Option<&'t str> {
    let head = text.get(..keyword.len())?;
    head.eq_ignore_ascii_case(keyword)
        .then(|| &text[keyword.len()..])
}

fn is_decimal(text: &str) -> bool {
    !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit())
}

fn is_integer(text: &str) -> bool {
    is_decimal(text.strip_prefix('-').unwrap_or(text))
}

/// The items of a list split at the commas outside brackets, parentheses and quotes, trimmed;
/// `None` when an item is empty or the brackets do not match.
fn split_items(text: &str) -> Option<Vec<&str>> {
    let mut items = Vec::new();
    let mut depth = 0usize;
    let mut quote: Option<char> = None;
    let mut start = 0;
    for (at, c) in text.char_indices() {
        match (quote, c) {
            (Some(open), c) if c == open => quote = None,
            (Some(_), _) => {}
            (None, '\'' | '"') => quote = Some(c),
            (None, '(' | '[') => depth += 1,
            (None, ')' | ']') => depth = depth.checked_sub(1)?,
            (None, ',') if depth == 0 => {
                items.push(text[start..at].trim());
                start = at + 1;
            }
            _ => {}
        }
    }
    if depth != 0 || quote.is_some() {
        return None;
    }
    items.push(text[start..].trim());
    (!items.iter().any(|item| item.is_empty())).then_some(items)
}

/// `count(value)` of an array value.
fn repetition(item: &str) -> Option<(&str, &str)> {
    let open = item.find('(')?;
    let count = &item[..open];
    let value = item[open + 1..].strip_suffix(')')?;
    (is_decimal(count) && !value.trim().is_empty()).then_some((count, value.trim()))
}

/// `member := value` of a structure value.
fn member(item: &str) -> Option<(&str, &str)> {
    let (name, value) = item.split_once(":=")?;
    let name = name.trim();
    let identifier = !name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == '_');
    (identifier && !value.trim().is_empty()).then_some((name, value.trim()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn type_xml(text: &str) -> String {
        let mut writer = XmlWriter::new().unwrap();
        write_type(&mut writer, text).unwrap();
        let xml = String::from_utf8(writer.finish()).unwrap();
        xml.lines().skip(1).map(str::trim).collect()
    }

    fn value_xml(text: &str) -> String {
        let mut writer = XmlWriter::new().unwrap();
        write_value(&mut writer, text).unwrap();
        let xml = String::from_utf8(writer.finish()).unwrap();
        xml.lines().skip(1).map(str::trim).collect()
    }

    #[test]
    fn types_the_schema_names_become_its_elements() {
        assert_eq!(type_xml("INT"), "<INT/>");
        assert_eq!(type_xml("STRING(20)"), "<string length=\"20\"/>");
        assert_eq!(type_xml("WSTRING"), "<wstring/>");
        assert_eq!(
            type_xml("ARRAY[0..9, -1..1] OF BOOL"),
            "<array><dimension lower=\"0\" upper=\"9\"/><dimension lower=\"-1\" upper=\"1\"/><baseType><BOOL/></baseType></array>"
        );
        assert_eq!(
            type_xml("POINTER TO ST_Recipe"),
            "<pointer><baseType><derived name=\"ST_Recipe\"/></baseType></pointer>"
        );
        assert_eq!(
            type_xml("UINT(1..5)"),
            "<subrangeUnsigned><range lower=\"1\" upper=\"5\"/><baseType><UINT/></baseType></subrangeUnsigned>"
        );
    }

    #[test]
    fn other_type_texts_are_derived_names_as_written() {
        assert_eq!(type_xml("LTIME"), "<derived name=\"LTIME\"/>");
        assert_eq!(
            type_xml("ARRAY[1..N] OF INT"),
            "<derived name=\"ARRAY[1..N] OF INT\"/>"
        );
        assert_eq!(type_xml("STRING(LEN)"), "<derived name=\"STRING(LEN)\"/>");
    }

    #[test]
    fn array_and_structure_values_become_their_elements() {
        assert_eq!(
            value_xml("[1, 3(0)]"),
            "<arrayValue><value><simpleValue value=\"1\"/></value><value repetitionValue=\"3\"><simpleValue value=\"0\"/></value></arrayValue>"
        );
        assert_eq!(
            value_xml("(x := 1, s := 'a,b')"),
            "<structValue><value member=\"x\"><simpleValue value=\"1\"/></value><value member=\"s\"><simpleValue value=\"'a,b'\"/></value></structValue>"
        );
        assert_eq!(value_xml("T#2s"), "<simpleValue value=\"T#2s\"/>");
        assert_eq!(value_xml("(1 + 2)"), "<simpleValue value=\"(1 + 2)\"/>");
    }
}
