//! The online view of a CFC or SFC body: a CFC chart's values on every pin and wire from the
//! lowering's probes; an SFC chart's active steps, their times, the transitions' values and the
//! active actions from the chart's implicit variables (`docs/sfc-semantics.md`).

use std::collections::{BTreeMap, HashMap};
use std::time::Duration;

use editor::{DiagramOnline, OnlineValue, SfcOnline, SfcStepOnline};
use project_model::{CfcChart, ElementId, Pou, SfcChart, SfcNode, Step};

use super::online_values::{ProbePath, ReadValue};

/// The CFC editor's online view of `chart` from the probes' values (`read` gives the last value
/// of a path, `prepared` the values typed to write or force): each probe's value at its element
/// and pin, which the editor draws at the pin and along the wires leaving it. An input pin
/// driven by a wire shows nothing of its own: the wire's start shows the same value, and both
/// would be written over each other where the wire is short.
pub(super) fn cfc_online(
    chart: &CfcChart,
    probes: &[ProbePath],
    read: impl Fn(&str) -> Option<ReadValue>,
    prepared: &BTreeMap<String, String>,
) -> DiagramOnline {
    let wired = |element: ElementId, pin: &str| {
        chart
            .wires
            .iter()
            .any(|wire| wire.to.element == element && wire.to.pin.eq_ignore_ascii_case(pin))
    };
    let mut values = HashMap::new();
    for probe in probes {
        if let Some(pin) = probe.pin.as_deref()
            && wired(probe.element, pin)
        {
            continue;
        }
        let Some(value) = read(&probe.path) else {
            continue;
        };
        let text = match prepared.get(&probe.path) {
            Some(next) => format!("{} <{next}>", value.text),
            None => value.text,
        };
        values
            .entry((probe.element, probe.pin.clone()))
            .or_insert(OnlineValue {
                text,
                forced: value.forced,
            });
    }
    DiagramOnline {
        power: HashMap::new(),
        values,
    }
}

/// What an SFC chart shows online and the paths it is read from.
pub(super) struct SfcReadings {
    /// The instance's path (`PackCycle`, `Main.fbSequence`).
    pub instance: String,
    /// Each step's `x` and `t`, by element.
    steps: Vec<(ElementId, String, Option<Duration>)>,
    /// The macro steps, with the steps of their bodies.
    macros: Vec<(ElementId, Vec<ElementId>)>,
    /// Each transition's value path, by element (while collecting, each transition with an
    /// empty path).
    transitions: Vec<(ElementId, String)>,
    /// Each associated action's (or BOOL variable's) name and path.
    actions: Vec<(String, String)>,
    /// `SFCError` and `SFCErrorStep` when the POU declares both.
    error_flags: Option<(String, String)>,
    /// `SFCTipMode` when the POU declares it.
    tip_mode: Option<String>,
}

impl SfcReadings {
    /// The readings of `chart`, the body of `pou`, shown for the instance at `instance`;
    /// `transitions` are the lowering's probes of the transitions' values.
    pub(super) fn new(
        pou: &Pou,
        chart: &SfcChart,
        instance: &str,
        transitions: &[ProbePath],
    ) -> Self {
        let mut readings = Self {
            instance: instance.to_owned(),
            steps: Vec::new(),
            macros: Vec::new(),
            transitions: Vec::new(),
            actions: Vec::new(),
            error_flags: None,
            tip_mode: None,
        };
        readings.collect(pou, &chart.sequence);
        // Each transition's value is read through its probe; a transition without one shows
        // no value.
        let mut known = std::mem::take(&mut readings.transitions);
        known.retain_mut(|(id, path)| {
            match transitions
                .iter()
                .find(|probe| probe.element == *id && probe.pin.is_none())
            {
                Some(probe) => {
                    path.clone_from(&probe.path);
                    true
                }
                None => false,
            }
        });
        readings.transitions = known;
        let declared = |name: &str| {
            pou.variables
                .iter()
                .find(|variable| variable.name.eq_ignore_ascii_case(name))
                .map(|variable| format!("{instance}.{}", variable.name))
        };
        readings.error_flags = declared("SFCError").zip(declared("SFCErrorStep"));
        readings.tip_mode = declared("SFCTipMode");
        readings
    }

    /// Collects the steps, macro steps and actions of `nodes`; returns the steps' ids.
    fn collect(&mut self, pou: &Pou, nodes: &[SfcNode]) -> Vec<ElementId> {
        let mut ids = Vec::new();
        for node in nodes {
            match node {
                SfcNode::Step(step) => {
                    ids.push(step.id);
                    self.step(pou, step);
                }
                SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                    for branch in &branches.branches {
                        ids.extend(self.collect(pou, &branch.nodes));
                    }
                }
                SfcNode::Macro(macro_step) => {
                    let inner = self.collect(pou, &macro_step.body);
                    ids.extend(inner.iter().copied());
                    self.macros.push((macro_step.id, inner));
                }
                SfcNode::Transition(transition) => {
                    self.transitions.push((transition.id, String::new()));
                }
                SfcNode::Jump(_) => {}
            }
        }
        ids
    }

    /// Records the step's paths and its actions' paths.
    fn step(&mut self, pou: &Pou, step: &Step) {
        let instance = &self.instance;
        let max_time = step
            .max_time
            .as_deref()
            .and_then(|text| compiler::literal::parse_duration(text.trim()).ok())
            .and_then(|nanoseconds| u64::try_from(nanoseconds).ok())
            .map(Duration::from_nanos);
        self.steps
            .push((step.id, format!("{instance}.{}", step.name), max_time));
        for association in &step.actions {
            let name = association.action.trim();
            if self.actions.iter().any(|(known, _)| known == name) {
                continue;
            }
            // An action object is active by its flag; a BOOL variable by its own value.
            let path = if pou
                .actions
                .iter()
                .any(|action| action.name.eq_ignore_ascii_case(name))
            {
                format!("{instance}._{name}.x")
            } else if pou
                .variables
                .iter()
                .any(|variable| variable.name.eq_ignore_ascii_case(name))
            {
                format!("{instance}.{name}")
            } else {
                continue;
            };
            self.actions.push((name.to_owned(), path));
        }
    }

    /// Every path read from the target for this chart.
    pub(super) fn paths(&self) -> Vec<String> {
        let mut paths = Vec::new();
        for (_, step, _) in &self.steps {
            paths.push(format!("{step}.x"));
            paths.push(format!("{step}.t"));
            // Read too, so the target has resolved it when the user activates the step.
            paths.push(format!("{step}._x"));
        }
        paths.extend(self.transitions.iter().map(|(_, path)| path.clone()));
        paths.extend(self.actions.iter().map(|(_, path)| path.clone()));
        if let Some((error, step)) = &self.error_flags {
            paths.push(error.clone());
            paths.push(step.clone());
        }
        paths.extend(self.tip_mode.iter().cloned());
        paths
    }

    /// The editor's online view from the values `read` gives.
    pub(super) fn online(&self, read: impl Fn(&str) -> Option<String>) -> SfcOnline {
        let boolean = |path: &str| read(path).is_some_and(|text| text == "TRUE");
        // The step the chart reports as timed out, when it declares its error flags.
        let error_step = self.error_flags.as_ref().and_then(|(error, step)| {
            boolean(error)
                .then(|| read(step))
                .flatten()
                .map(|text| text.trim_matches('\'').to_owned())
        });
        let mut online = SfcOnline::default();
        for (id, step, max_time) in &self.steps {
            let active = boolean(&format!("{step}.x"));
            let elapsed = read(&format!("{step}.t"))
                .and_then(|text| compiler::literal::parse_duration(&text).ok())
                .and_then(|nanoseconds| u64::try_from(nanoseconds).ok())
                .map(Duration::from_nanos)
                .unwrap_or_default();
            let name = step.rsplit('.').next().unwrap_or(step);
            let over_max_time = error_step
                .as_deref()
                .is_some_and(|timed_out| timed_out.eq_ignore_ascii_case(name))
                || (active && max_time.is_some_and(|max| elapsed > max));
            online.steps.insert(
                *id,
                SfcStepOnline {
                    active,
                    elapsed,
                    over_max_time,
                },
            );
        }
        for (id, inner) in &self.macros {
            let active = inner
                .iter()
                .any(|step| online.steps.get(step).is_some_and(|state| state.active));
            online.steps.insert(
                *id,
                SfcStepOnline {
                    active,
                    ..SfcStepOnline::default()
                },
            );
        }
        for (id, path) in &self.transitions {
            if let Some(text) = read(path) {
                online.transitions.insert(*id, text == "TRUE");
            }
        }
        for (name, path) in &self.actions {
            online.actions.insert(name.clone(), boolean(path));
        }
        online.tip_mode = self.tip_mode.as_deref().is_some_and(boolean);
        online
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use compiler::lower::ProbeKind;
    use project_model::{Body, Object, Project};

    fn example() -> Project {
        project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"))
    }

    #[test]
    fn the_pack_cycle_shows_its_active_step_time_out_and_actions() {
        let project = example();
        let Some(Object::Pou(pou)) = project.application.object("PackCycle") else {
            panic!("no PackCycle");
        };
        let Body::Sfc { chart } = &pou.body else {
            panic!("PackCycle is not SFC");
        };
        let transitions = [
            ProbePath {
                element: ElementId(10),
                pin: None,
                kind: ProbeKind::Power,
                path: "PackCycle.__t10".to_owned(),
            },
            ProbePath {
                // A step's probe is not a transition's value.
                element: ElementId(9),
                pin: None,
                kind: ProbeKind::Power,
                path: "PackCycle.Cut.x".to_owned(),
            },
        ];
        let readings = SfcReadings::new(pou, chart, "PackCycle", &transitions);
        let paths = readings.paths();
        for path in [
            "PackCycle.Wait.x",
            "PackCycle.Cut.t",
            "PackCycle.xCut",
            "PackCycle._CountPackage.x",
            "PackCycle.SFCError",
            "PackCycle.__t10",
        ] {
            assert!(paths.iter().any(|known| known == path), "{path}: {paths:?}");
        }
        let values = HashMap::from([
            ("PackCycle.Cut.x", "TRUE"),
            ("PackCycle.Cut.t", "T#2s500ms"),
            ("PackCycle.Wait.x", "FALSE"),
            ("PackCycle.xCut", "TRUE"),
            ("PackCycle.__t10", "FALSE"),
        ]);
        let online = readings.online(|path| values.get(path).map(|value| (*value).to_owned()));
        let cut = online.steps[&ElementId(9)];
        assert!(cut.active);
        assert_eq!(cut.elapsed, Duration::from_millis(2500));
        assert!(cut.over_max_time, "T#2s500ms is over the max time T#2S");
        assert!(!online.steps[&ElementId(1)].active);
        assert_eq!(online.transitions.get(&ElementId(10)), Some(&false));
        assert!(!online.transitions.contains_key(&ElementId(9)));
        assert_eq!(online.actions.get("xCut"), Some(&true));
        assert_eq!(online.actions.get("CountPackage"), Some(&false));
    }

    #[test]
    fn the_chart_reports_the_step_that_timed_out() {
        let project = example();
        let Some(Object::Pou(pou)) = project.application.object("PackCycle") else {
            panic!("no PackCycle");
        };
        let Body::Sfc { chart } = &pou.body else {
            panic!("PackCycle is not SFC");
        };
        let readings = SfcReadings::new(pou, chart, "PackCycle", &[]);
        let values = HashMap::from([
            ("PackCycle.SFCError", "TRUE"),
            ("PackCycle.SFCErrorStep", "'Glue'"),
        ]);
        let online = readings.online(|path| values.get(path).map(|value| (*value).to_owned()));
        assert!(online.steps[&ElementId(4)].over_max_time);
        assert!(!online.steps[&ElementId(9)].over_max_time);
    }

    #[test]
    fn cfc_values_are_keyed_by_element_and_pin_with_prepared_values() {
        let probe = |id: u32, pin: Option<&str>, path: &str| ProbePath {
            element: ElementId(id),
            pin: pin.map(str::to_owned),
            kind: ProbeKind::Value,
            path: path.to_owned(),
        };
        let probes = [
            probe(1, None, "P.a"),
            probe(2, Some("OUT"), "P.__b"),
            probe(2, Some("IN1"), "P.a"),
        ];
        // Element 1's value drives the box's IN1 through a wire.
        let chart = CfcChart {
            wires: vec![project_model::Wire {
                from: project_model::PinRef {
                    element: ElementId(1),
                    pin: String::new(),
                },
                to: project_model::PinRef {
                    element: ElementId(2),
                    pin: "IN1".to_owned(),
                },
                points: Vec::new(),
            }],
            ..CfcChart::default()
        };
        let read = |path: &str| {
            Some(ReadValue {
                text: if path == "P.a" { "1.5" } else { "3.0" }.to_owned(),
                forced: path == "P.a",
            })
        };
        let prepared = BTreeMap::from([("P.a".to_owned(), "2.0".to_owned())]);
        let online = cfc_online(&chart, &probes, read, &prepared);
        let a = &online.values[&(ElementId(1), None)];
        assert_eq!(a.text, "1.5 <2.0>");
        assert!(a.forced);
        assert_eq!(
            online.values[&(ElementId(2), Some("OUT".to_owned()))].text,
            "3.0"
        );
        assert!(
            !online
                .values
                .contains_key(&(ElementId(2), Some("IN1".to_owned())))
        );
    }
}
