//! Reading POU files of format versions 1 and 2, whose graphical bodies are graphs of placed
//! elements and connections: LD and FBD in version 1, CFC and SFC in both. Everything else in
//! such a file reads as in the current version.

use serde::Deserialize;
use toml::{Table, Value};

use super::chart_conversion::convert_charts;
use super::graph_chart::Chart;
use super::older_charts::{cfc_from_graph, sfc_from_graph};
use crate::Pou;

/// Why a POU file of an older format version cannot be read.
pub(crate) enum OlderFailure {
    /// The file is not valid TOML, or not a POU (with a line where the parser knows one).
    Toml(toml::de::Error),
    /// Its graphical bodies cannot be converted; each message names the body, network and
    /// element.
    Networks(Vec<String>),
}

/// Reads the POU named `name` from the text of its file of format `version` (1 or 2),
/// converting its graphical bodies to the current version.
pub(crate) fn pou_from_older(version: u32, name: &str, text: &str) -> Result<Pou, OlderFailure> {
    // A file without graphical bodies reads as the current version does, with line numbers.
    let direct_error = match toml::from_str::<Pou>(text) {
        Ok(pou) => return Ok(pou),
        Err(error) => error,
    };
    let Ok(mut table) = toml::from_str::<Table>(text) else {
        return Err(OlderFailure::Toml(direct_error));
    };
    let mut bodies = graphical_bodies(&mut table, name);
    if bodies.is_empty() {
        return Err(OlderFailure::Toml(direct_error));
    }
    let mut problems = Vec::new();
    for (owner, body) in &mut bodies {
        if let Some(chart) = body.remove("chart") {
            convert_chart(owner, body, chart, &mut problems);
            continue;
        }
        if version > 1 {
            continue;
        }
        let Some(networks) = body.remove("network") else {
            continue;
        };
        let charts = match Vec::<Chart>::deserialize(networks) {
            Ok(charts) => charts,
            Err(error) => {
                problems.push(format!(
                    "{owner}: a version 1 network is not valid: {}",
                    error.message().trim_end()
                ));
                continue;
            }
        };
        match convert_charts(&charts) {
            Ok(networks) => match Value::try_from(&networks) {
                Ok(value) => {
                    body.insert("network".into(), value);
                }
                Err(error) => problems.push(format!("{owner}: {error}")),
            },
            Err(found) => problems.extend(
                found
                    .into_iter()
                    .map(|problem| format!("{owner}, {problem}")),
            ),
        }
    }
    drop(bodies);
    if !problems.is_empty() {
        return Err(OlderFailure::Networks(problems));
    }
    Pou::deserialize(Value::Table(table)).map_err(OlderFailure::Toml)
}

/// Converts the graph `chart` of a CFC or SFC `body` in place, or adds why it cannot be.
fn convert_chart(owner: &str, body: &mut Table, chart: Value, problems: &mut Vec<String>) {
    let language = body
        .get("language")
        .and_then(Value::as_str)
        .unwrap_or_default();
    let graph = match Chart::deserialize(chart) {
        Ok(graph) => graph,
        Err(error) => {
            problems.push(format!(
                "{owner}: the chart is not valid: {}",
                error.message().trim_end()
            ));
            return;
        }
    };
    let converted = if language == "sfc" {
        sfc_from_graph(&graph).and_then(|chart| Value::try_from(&chart).map_err(to_messages))
    } else {
        cfc_from_graph(&graph).and_then(|chart| Value::try_from(&chart).map_err(to_messages))
    };
    match converted {
        Ok(value) => {
            body.insert("chart".into(), value);
        }
        Err(found) => problems.extend(found.into_iter().map(|p| format!("{owner}, {p}"))),
    }
}

fn to_messages(error: toml::ser::Error) -> Vec<String> {
    vec![error.to_string()]
}

/// The graphical body tables of a POU's table that hold networks or charts, each with the name its
/// messages use (`POU 'Main'`, `POU 'Main', method 'Reset'`…).
fn graphical_bodies<'a>(table: &'a mut Table, name: &str) -> Vec<(String, &'a mut Table)> {
    let pou = format!("POU '{name}'");
    let mut bodies = Vec::new();
    for (key, value) in table.iter_mut() {
        match (key.as_str(), value) {
            ("body", Value::Table(body)) => bodies.push((pou.clone(), body)),
            (member @ ("method" | "action" | "transition"), Value::Array(members)) => {
                for member_table in members.iter_mut().filter_map(Value::as_table_mut) {
                    let member_name = member_name(member_table);
                    if let Some(Value::Table(body)) = member_table.get_mut("body") {
                        bodies.push((format!("{pou}, {member} '{member_name}'"), body));
                    }
                }
            }
            ("property", Value::Array(properties)) => {
                for property in properties.iter_mut().filter_map(Value::as_table_mut) {
                    let property_name = member_name(property);
                    for (accessor, value) in property.iter_mut() {
                        if let ("get" | "set", Value::Table(accessor_table)) =
                            (accessor.as_str(), value)
                            && let Some(Value::Table(body)) = accessor_table.get_mut("body")
                        {
                            bodies.push((
                                format!("{pou}, property '{property_name}' ({accessor})"),
                                body,
                            ));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    bodies.retain(
        |(_, body)| match body.get("language").and_then(Value::as_str) {
            Some("ld" | "fbd") => body.contains_key("network"),
            Some("cfc" | "sfc") => body.contains_key("chart"),
            _ => false,
        },
    );
    bodies
}

fn member_name(table: &Table) -> String {
    table
        .get("name")
        .and_then(Value::as_str)
        .unwrap_or_default()
        .to_owned()
}
