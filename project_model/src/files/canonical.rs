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
/// would not fit on a line puts one value on each line. The chain (`rung`) and `output` lists
/// of an LD/FBD network are an indented tree of inline tables instead, one element a line, so
/// the structure reads at a glance and an edit is a small diff. Fails with the serialiser's
/// error when `value` has no TOML form.
pub(crate) fn to_canonical_toml<T: Serialize>(value: &T) -> Result<String, toml_edit::ser::Error> {
    let document = toml_edit::ser::to_document(value)?;
    let mut root = document.as_table().clone();
    expand(&mut root);
    Ok(DocumentMut::from(root).to_string())
}

fn expand(table: &mut Table) {
    expand_table(table, false);
}

/// Expands `table`; `is_network` tells that it is an LD/FBD network, whose `rung` and
/// `output` lists are laid out as an indented tree rather than as arrays of tables.
fn expand_table(table: &mut Table, is_network: bool) {
    table.decor_mut().clear();
    table.set_implicit(false);
    let is_sfc_body = table.get("language").and_then(Item::as_str) == Some("sfc");
    for (mut key, item) in table.iter_mut() {
        key.leaf_decor_mut().clear();
        if is_sfc_body && key.get() == "chart" {
            expand_sfc_chart(item);
            continue;
        }
        let holds_networks = key.get() == "network";
        let is_tree = is_network && matches!(key.get(), "rung" | "output");
        if key.get() == "chart"
            && let Some(chart) = cfc_chart_table(item)
        {
            *item = Item::Table(chart);
            continue;
        }
        let replacement = match item {
            Item::Value(Value::Array(array)) if is_tree && is_array_of_tables(array) => {
                format_tree(array, 0, true);
                array.decor_mut().clear();
                array.decor_mut().set_prefix(" ");
                None
            }
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
                        expand_table(&mut child, holds_networks);
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
                for child in tables.iter_mut() {
                    expand_table(child, holds_networks);
                }
                None
            }
            Item::None => None,
        };
        if let Some(replacement) = replacement {
            *item = replacement;
        }
    }
}

/// Lays out an SFC body's chart as a standard table whose `node` list is an indented tree of
/// inline tables, one node a line, with branches and macro bodies nested inside their node
/// (section 4.3 of `docs/project-format.md`): the chart's structure reads at a glance and a
/// step added is one added line in a diff.
fn expand_sfc_chart(item: &mut Item) {
    let mut chart = match std::mem::take(item) {
        Item::Value(Value::InlineTable(inline)) => inline.into_table(),
        Item::Table(table) => table,
        other => {
            *item = other;
            return;
        }
    };
    chart.decor_mut().clear();
    chart.set_implicit(false);
    for (mut key, child) in chart.iter_mut() {
        key.leaf_decor_mut().clear();
        if let Item::Value(value) = child {
            match value {
                Value::Array(nodes) if key.get() == "node" && is_array_of_tables(nodes) => {
                    format_tree(nodes, 0, true);
                    nodes.decor_mut().clear();
                    nodes.decor_mut().set_prefix(" ");
                }
                other => format_value(other),
            }
        }
    }
    *item = Item::Table(chart);
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

/// Lays out the elements of a network's chain or outputs (a list of structures) as an
/// indented tree: each element is an inline table, on a line of its own at `level + 1` levels
/// of indentation when the list is `always_expanded`, holds a spread list, or would not fit on
/// its line; lists inside the elements (branches, box pins, sources) follow the same rule one
/// level deeper. A contact added to a rung is then one added line in a diff.
fn format_tree(array: &mut Array, level: usize, always_expanded: bool) {
    for element in array.iter_mut() {
        match element {
            Value::InlineTable(inline) => format_tree_element(inline, level),
            other => format_contents(other),
        }
    }
    array.fmt();
    let one_line = array.to_string();
    let spread = always_expanded
        || one_line.contains('\n')
        || one_line.len() + INDENT.len() * (level + 1) > MAX_INLINE_WIDTH;
    if spread {
        let inner = format!("\n{}", INDENT.repeat(level + 1));
        for element in array.iter_mut() {
            element.decor_mut().set_prefix(inner.as_str());
            element.decor_mut().set_suffix("");
        }
        array.set_trailing(format!("\n{}", INDENT.repeat(level)));
        array.set_trailing_comma(true);
    }
}

/// Formats one element of a tree list at `level`: its own lists stay on its line while the
/// line fits; otherwise they are spread one at a time, the longest first, until every line
/// does.
fn format_tree_element(inline: &mut InlineTable, level: usize) {
    let mut spread: Vec<String> = Vec::new();
    loop {
        for (key, child) in inline.iter_mut() {
            match child {
                Value::Array(list) if is_array_of_tables(list) => {
                    format_tree(list, level + 1, spread.iter().any(|name| name == key.get()));
                }
                other => format_contents(other),
            }
        }
        inline.fmt();
        let text = inline.to_string();
        let indent = INDENT.len() * (level + 1);
        let widest = text
            .lines()
            .enumerate()
            .map(|(index, line)| {
                if index == 0 {
                    line.len() + indent
                } else {
                    line.len()
                }
            })
            .max()
            .unwrap_or(0);
        if widest <= MAX_INLINE_WIDTH {
            return;
        }
        let longest = inline
            .iter()
            .filter(|(key, value)| {
                value.as_array().is_some_and(is_array_of_tables)
                    && !spread.iter().any(|name| name == key)
            })
            .max_by_key(|(_, value)| value.to_string().len())
            .map(|(key, _)| key.to_owned());
        match longest {
            Some(key) => spread.push(key),
            None => return,
        }
    }
}

/// A CFC chart (a `chart` holding `element` and `wire` lists, no SFC `node`s) as a standard
/// table whose lists put one element and one wire on each line, whatever its width, so moving
/// an element or re-routing a wire is a one-line diff; `None` for anything else.
fn cfc_chart_table(item: &Item) -> Option<Table> {
    let mut chart = match item {
        Item::Value(Value::InlineTable(inline)) => inline.clone().into_table(),
        Item::Table(table) => table.clone(),
        _ => return None,
    };
    let is_cfc = (chart.contains_key("element") || chart.contains_key("wire"))
        && !chart.contains_key("node");
    if !is_cfc {
        return None;
    }
    chart.decor_mut().clear();
    chart.set_implicit(false);
    for (mut key, item) in chart.iter_mut() {
        key.leaf_decor_mut().clear();
        let Item::Value(value) = item else { continue };
        if let Value::Array(list) = value {
            for entry in list.iter_mut() {
                format_on_one_line(entry);
                entry.decor_mut().set_prefix(format!("\n{INDENT}"));
                entry.decor_mut().set_suffix("");
            }
            list.set_trailing("\n");
            list.set_trailing_comma(true);
        } else {
            format_on_one_line(value);
        }
        value.decor_mut().clear();
        value.decor_mut().set_prefix(" ");
    }
    Some(chart)
}

/// Gives a value the canonical spacing on one line, however long.
fn format_on_one_line(value: &mut Value) {
    match value {
        Value::InlineTable(inline) => {
            for (_, child) in inline.iter_mut() {
                format_on_one_line(child);
            }
            inline.fmt();
        }
        Value::Array(array) => {
            array.iter_mut().for_each(format_on_one_line);
            array.fmt();
        }
        _ => {}
    }
}

/// One level of indentation in a spread list.
const INDENT: &str = "    ";

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
#[cfg(test)]
#[path = "canonical_tests.rs"]
mod tests;
