//! Reading POU files of format version 1, whose LD and FBD bodies are graphs of placed
//! elements and connections; everything else in a version 1 file reads as in version 2.

use serde::Deserialize;
use toml::{Table, Value};

use super::chart_conversion::convert_charts;
use crate::{Chart, Pou};

/// Why a version 1 POU file cannot be read.
pub(crate) enum Version1Failure {
    /// The file is not valid TOML, or not a POU (with a line where the parser knows one).
    Toml(toml::de::Error),
    /// Its networks cannot be converted; each message names the body, network and element.
    Networks(Vec<String>),
}

/// Reads the POU named `name` from the text of its version 1 file, converting its LD and FBD
/// networks to version 2.
pub(crate) fn pou_from_version1(name: &str, text: &str) -> Result<Pou, Version1Failure> {
    // A file without graphical networks reads as version 2 does, with line numbers.
    let direct_error = match toml::from_str::<Pou>(text) {
        Ok(pou) => return Ok(pou),
        Err(error) => error,
    };
    let Ok(mut table) = toml::from_str::<Table>(text) else {
        return Err(Version1Failure::Toml(direct_error));
    };
    let mut bodies = graphical_bodies(&mut table, name);
    if bodies.is_empty() {
        return Err(Version1Failure::Toml(direct_error));
    }
    let mut problems = Vec::new();
    for (owner, body) in &mut bodies {
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
        return Err(Version1Failure::Networks(problems));
    }
    Pou::deserialize(Value::Table(table)).map_err(Version1Failure::Toml)
}

/// The LD and FBD body tables of a POU's table that hold networks, each with the name its
/// messages use (`POU 'Main'`, `POU 'Main', method 'Reset'`…).
fn graphical_bodies<'a>(table: &'a mut Table, name: &str) -> Vec<(String, &'a mut Table)> {
    let pou = format!("POU '{name}'");
    let mut bodies = Vec::new();
    for (key, value) in table.iter_mut() {
        match (key.as_str(), value) {
            ("body", Value::Table(body)) => bodies.push((pou.clone(), body)),
            (member @ ("method" | "action"), Value::Array(members)) => {
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
    bodies.retain(|(_, body)| {
        let graphical = matches!(
            body.get("language").and_then(Value::as_str),
            Some("ld" | "fbd")
        );
        graphical && body.contains_key("network")
    });
    bodies
}

fn member_name(table: &Table) -> String {
    table
        .get("name")
        .and_then(Value::as_str)
        .unwrap_or_default()
        .to_owned()
}
