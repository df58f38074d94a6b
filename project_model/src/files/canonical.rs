//! The canonical text of a TOML file: the same model always gives the same bytes.

use serde::Serialize;
use toml_edit::{Array, ArrayOfTables, DocumentMut, InlineTable, Item, Table, Value};

/// Inline tables and arrays longer than this are spread over several lines.
const MAX_INLINE_WIDTH: usize = 100;

/// Serialises `value` as TOML in the project's canonical form.
///
/// Keys keep the order of the model's fields. Lists of structures become arrays of tables
/// (`[[variable]]`); small structures of plain values stay inline on their key's line
/// (`kind = { type = "cyclic", interval_us = 10000 }`); a structure that holds lists of
/// structures or would not fit on a line becomes a standard table; a list of plain values that
/// would not fit on a line puts one value on each line.
pub(crate) fn to_canonical_toml<T: Serialize>(value: &T) -> Result<String, String> {
    let document = toml_edit::ser::to_document(value).map_err(|error| error.to_string())?;
    let mut root = document.as_table().clone();
    expand(&mut root);
    Ok(DocumentMut::from(root).to_string())
}

fn expand(table: &mut Table) {
    table.decor_mut().clear();
    table.set_implicit(false);
    for (mut key, item) in table.iter_mut() {
        key.leaf_decor_mut().clear();
        let replacement = match item {
            Item::Value(Value::InlineTable(inline)) if must_expand(inline) => {
                let mut child = inline.clone().into_table();
                expand(&mut child);
                Some(Item::Table(child))
            }
            Item::Value(Value::Array(array)) if is_array_of_tables(array) => {
                let mut tables = ArrayOfTables::new();
                for value in array.iter() {
                    if let Some(inline) = value.as_inline_table() {
                        let mut child = inline.clone().into_table();
                        expand(&mut child);
                        tables.push(child);
                    }
                }
                Some(Item::ArrayOfTables(tables))
            }
            Item::Value(value) => {
                format_value(value);
                None
            }
            Item::Table(child) => {
                expand(child);
                None
            }
            Item::ArrayOfTables(tables) => {
                tables.iter_mut().for_each(expand);
                None
            }
            Item::None => None,
        };
        if let Some(replacement) = replacement {
            *item = replacement;
        }
    }
}

/// A non-empty array whose every element is a structure.
fn is_array_of_tables(array: &Array) -> bool {
    !array.is_empty() && array.iter().all(Value::is_inline_table)
}

/// Whether an inline table must become a standard table.
fn must_expand(inline: &InlineTable) -> bool {
    let has_nested_list = inline.iter().any(|(_, value)| match value {
        Value::Array(array) => is_array_of_tables(array),
        Value::InlineTable(child) => must_expand(child),
        _ => false,
    });
    if has_nested_list {
        return true;
    }
    let mut probe = inline.clone();
    probe.fmt();
    probe.to_string().len() > MAX_INLINE_WIDTH
}

/// Gives a value the canonical spacing: `{ a = 1, b = 2 }`, `["a", "b"]`, or one array element
/// per line when the array is too long.
fn format_value(value: &mut Value) {
    format_contents(value);
    value.decor_mut().clear();
    value.decor_mut().set_prefix(" ");
}

/// Formats what is inside an inline table or array, leaving the value's own decor alone.
fn format_contents(value: &mut Value) {
    match value {
        Value::InlineTable(inline) => {
            for (_, child) in inline.iter_mut() {
                format_contents(child);
            }
            inline.fmt();
        }
        Value::Array(array) => {
            array.iter_mut().for_each(format_contents);
            array.fmt();
            if array.to_string().len() > MAX_INLINE_WIDTH {
                for element in array.iter_mut() {
                    element.decor_mut().set_prefix("\n    ");
                    element.decor_mut().set_suffix("");
                }
                array.set_trailing("\n");
                array.set_trailing_comma(true);
            }
        }
        _ => {}
    }
}
