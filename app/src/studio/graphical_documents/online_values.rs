//! The online view of one LD/FBD body: the lowering's probes read through `Online`, the power
//! derived where none was stored, and the prepared values shown beside their operands.

use std::collections::{BTreeMap, HashMap};

use compiler::lower::{LoweredBody, ProbeKind};
use editor::{DiagramOnline, OnlineValue};
use project_model::{ElementId, Network, Pou, Project};

use super::power::{PowerReadings, network_power};
use super::probe_paths::target_path;

/// One value read from the target: its text and whether it is forced.
pub(super) struct ReadValue {
    /// The value as an IEC literal.
    pub text: String,
    /// Whether the variable is forced.
    pub forced: bool,
}

/// One probe with its variable's path on the target.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct ProbePath {
    /// The element.
    pub element: ElementId,
    /// The pin of a box, or `EN`; `None` for the element itself.
    pub pin: Option<String>,
    /// What the value is.
    pub kind: ProbeKind,
    /// The variable's path on the target.
    pub path: String,
}

/// Where the body's probes are read and what the editor shows of them.
pub(super) struct BodyProbes<'a> {
    /// The project, for the globals' paths.
    pub project: &'a Project,
    /// The POU the body belongs to.
    pub pou: &'a Pou,
    /// The instance whose values are shown (`Interlock`, `Main.fbConveyor`).
    pub instance: &'a str,
    /// The lowered body with its probes.
    pub lowered: &'a LoweredBody,
}

impl BodyProbes<'_> {
    /// Every probe's element, pin, kind and path on the target, in the lowering's order.
    pub(super) fn paths(&self) -> Vec<ProbePath> {
        self.lowered
            .probes
            .iter()
            .filter_map(|probe| {
                Some(ProbePath {
                    element: probe.element,
                    pin: probe.pin.clone(),
                    kind: probe.kind,
                    path: target_path(self.project, self.pou, self.instance, &probe.path)?,
                })
            })
            .collect()
    }

    /// The path on the target of an operand typed in the body, for a prepared value.
    pub(super) fn operand_path(&self, operand: &str) -> Option<String> {
        target_path(self.project, self.pou, self.instance, operand)
    }
}

/// The editor's online view of `networks` from the probes' values (`read` gives the last value
/// of a path, `prepared` the values typed to write or force).
pub(super) fn diagram_online(
    networks: &[Network],
    probes: &[ProbePath],
    read: impl Fn(&str) -> Option<ReadValue>,
    prepared: &BTreeMap<String, String>,
) -> DiagramOnline {
    let mut readings = PowerReadings::default();
    let mut values = HashMap::new();
    for ProbePath {
        element,
        pin,
        kind,
        path,
    } in probes
    {
        let Some(value) = read(path) else { continue };
        let on = boolean(&value.text);
        match (kind, pin.as_deref()) {
            (ProbeKind::Power, None) => {
                if let Some(on) = on {
                    readings.power.insert(*element, on);
                }
            }
            (ProbeKind::Edge, None) => {
                if let Some(on) = on {
                    readings.edges.insert(*element, on);
                }
            }
            // A pin's edge detection is not drawn; its value is the pin's own.
            (ProbeKind::Edge, Some(_)) => {}
            (ProbeKind::Value | ProbeKind::Power, pin) => {
                if let Some(on) = on {
                    match pin {
                        None => {
                            readings.values.insert(*element, on);
                        }
                        Some(pin) if *kind == ProbeKind::Value => {
                            readings.pins.insert((*element, pin.to_uppercase()), on);
                        }
                        Some(_) => {}
                    }
                }
                let text = match prepared.get(path) {
                    Some(next) => format!("{} <{next}>", value.text),
                    None => value.text,
                };
                values.insert(
                    (*element, pin.map(str::to_owned)),
                    OnlineValue {
                        text,
                        forced: value.forced,
                    },
                );
            }
        }
    }
    let mut power = HashMap::new();
    for network in networks {
        power.extend(network_power(network, &readings));
    }
    DiagramOnline { power, values }
}

/// A Boolean value as the target writes it.
fn boolean(text: &str) -> Option<bool> {
    match text {
        "TRUE" => Some(true),
        "FALSE" => Some(false),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::{Coil, FlowNode, NetworkOutput, Operand};

    #[test]
    fn values_power_and_prepared_values_come_from_the_probes() {
        let network = Network {
            rung: vec![FlowNode::Operand(Operand {
                id: ElementId(1),
                text: "xA".to_owned(),
                ..Operand::default()
            })],
            outputs: vec![NetworkOutput::Coil(Coil {
                id: ElementId(2),
                variable: "xB".to_owned(),
                ..Coil::default()
            })],
            ..Network::default()
        };
        let probe = |id: u32, path: &str| ProbePath {
            element: ElementId(id),
            pin: None,
            kind: ProbeKind::Value,
            path: path.to_owned(),
        };
        let probes = vec![probe(1, "P.xA"), probe(2, "P.xB")];
        let read = |path: &str| {
            Some(ReadValue {
                text: if path == "P.xA" { "TRUE" } else { "FALSE" }.to_owned(),
                forced: path == "P.xA",
            })
        };
        let prepared = BTreeMap::from([("P.xB".to_owned(), "TRUE".to_owned())]);
        let online = diagram_online(&[network], &probes, read, &prepared);
        assert!(online.power[&ElementId(1)]);
        assert!(online.power[&ElementId(2)]);
        let a = &online.values[&(ElementId(1), None)];
        assert_eq!(a.text, "TRUE");
        assert!(a.forced);
        assert_eq!(online.values[&(ElementId(2), None)].text, "FALSE <TRUE>");
    }

    #[test]
    fn an_fbd_comparison_box_shows_its_output_and_passes_it_as_power() {
        use project_model::{BlockCall, BlockInput, BlockOutput, Body, Object};
        let input = |pin: &str, id: u32, text: &str| BlockInput {
            pin: pin.to_owned(),
            source: vec![FlowNode::Operand(Operand {
                id: ElementId(id),
                text: text.to_owned(),
                ..Operand::default()
            })],
            ..BlockInput::default()
        };
        let network = Network {
            rung: vec![FlowNode::Block(BlockCall {
                id: ElementId(1),
                type_name: "GT".to_owned(),
                instance: String::new(),
                inputs: vec![input("IN1", 2, "nLevel"), input("IN2", 3, "10")],
                outputs: vec![BlockOutput {
                    pin: "OUT".to_owned(),
                    ..BlockOutput::default()
                }],
            })],
            outputs: vec![NetworkOutput::Coil(Coil {
                id: ElementId(4),
                variable: "xHigh".to_owned(),
                ..Coil::default()
            })],
            ..Network::default()
        };
        let mut project = compiler::SourceProject::new(
            "PROGRAM Main\nVAR nLevel : INT; xHigh : BOOL; END_VAR\nEND_PROGRAM\n",
        )
        .project;
        let Some(Object::Pou(main)) = project.application.object_mut("Main") else {
            panic!("no Main");
        };
        main.body = Body::Fbd {
            networks: vec![network.clone()],
        };
        let lowered = compiler::lower::lower_project(&project);
        let Some(Object::Pou(pou)) = project.application.object("Main") else {
            panic!("no Main");
        };
        let probes = BodyProbes {
            project: &project,
            pou,
            instance: "Main",
            lowered: &lowered.bodies[0],
        }
        .paths();
        let out = probes
            .iter()
            .find(|probe| probe.element == ElementId(1) && probe.pin.as_deref() == Some("OUT"))
            .unwrap_or_else(|| panic!("the GT box's output has no probe: {probes:#?}"));
        let out_path = out.path.clone();
        let read = |path: &str| {
            (path == out_path || path == "Main.nLevel").then(|| ReadValue {
                text: if path == out_path { "TRUE" } else { "12" }.to_owned(),
                forced: false,
            })
        };
        let online = diagram_online(&[network], &probes, read, &BTreeMap::new());
        assert_eq!(
            online.values[&(ElementId(1), Some("OUT".to_owned()))].text,
            "TRUE"
        );
        assert!(online.power[&ElementId(1)]);
        assert!(online.power[&ElementId(4)]);
    }
}
