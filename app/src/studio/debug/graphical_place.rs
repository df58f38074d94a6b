//! Breakpoints and halts in graphical bodies (LD, FBD, CFC, SFC; `docs/debugging.md` §3): a
//! network or element of a body, the statement the compiler made of it and back. A graphical
//! body is compiled as Structured Text with each element's statement on a line of its own, so
//! the lowered text's lines lead from statements to elements and back.

use compiler::lower::LoweredBody;
use compiler::origin::Origin;
use project_model::{ElementId, TextTarget};
use serde::{Deserialize, Serialize};

/// A network of a graphical body, or one element of it: in LD and FBD a network (its first
/// statement) or a coil, box or assignment; in CFC (network 0) an element with an execution
/// order; in SFC (network 0) a step (its actions) or a transition (its test).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct GraphicalPlace {
    /// The body as `rivet check` names it: the POU (`Interlock`), a method's or action's
    /// body after a dot (`FB_Motor.Start`), a property's accessor after another
    /// (`FB_Motor.Speed.get`).
    pub body: String,
    /// The network's index in the body, from 0 (shown from 1); 0 in CFC and SFC.
    pub network: usize,
    /// The element's stable id (`ElementId`), or `None` for the network itself.
    pub element: Option<u32>,
}

impl GraphicalPlace {
    /// The place `place` of the editor of the body `target`.
    pub fn of_editor(target: &TextTarget, place: editor::BodyPlace) -> Self {
        Self {
            body: body_name(target),
            network: place.network,
            element: place.element.map(|id| id.0),
        }
    }

    /// The place as the editor marks it.
    pub fn in_editor(&self) -> editor::BodyPlace {
        editor::BodyPlace {
            network: self.network,
            element: self.element.map(ElementId),
        }
    }

    /// `POU:NETWORK[:ELEMENT]` with the network from 1, as the command line writes it after
    /// the file.
    pub fn command_line(&self) -> String {
        match self.element {
            Some(element) => format!("{}:{}:{element}", self.body, self.network + 1),
            None => format!("{}:{}", self.body, self.network + 1),
        }
    }
}

/// The name `rivet check` and the image give the body `target` (`FB_Motor.Speed.get`).
pub fn body_name(target: &TextTarget) -> String {
    match target {
        TextTarget::Pou(pou) => pou.clone(),
        TextTarget::Method {
            pou,
            method: member,
        }
        | TextTarget::Action {
            pou,
            action: member,
        }
        | TextTarget::Transition {
            pou,
            transition: member,
        } => format!("{pou}.{member}"),
        TextTarget::Property { pou, property, get } => {
            format!("{pou}.{property}.{}", if *get { "get" } else { "set" })
        }
    }
}

/// The body named `body` (as [`body_name`] names it) of a POU of `project`.
pub fn body_target(project: &project_model::Project, body: &str) -> Option<TextTarget> {
    let pou_name = body.split('.').next()?;
    let pou = project
        .application
        .objects()
        .into_iter()
        .find_map(|object| match object {
            project_model::Object::Pou(pou) if pou.name.eq_ignore_ascii_case(pou_name) => Some(pou),
            _ => None,
        })?;
    let name = || pou.name.clone();
    let mut targets = vec![TextTarget::Pou(name())];
    targets.extend(pou.methods.iter().map(|method| TextTarget::Method {
        pou: name(),
        method: method.name.clone(),
    }));
    for property in &pou.properties {
        for get in [true, false] {
            targets.push(TextTarget::Property {
                pou: name(),
                property: property.name.clone(),
                get,
            });
        }
    }
    targets.extend(pou.actions.iter().map(|action| TextTarget::Action {
        pou: name(),
        action: action.name.clone(),
    }));
    targets.extend(
        pou.transitions
            .iter()
            .map(|transition| TextTarget::Transition {
                pou: name(),
                transition: transition.name.clone(),
            }),
    );
    targets
        .into_iter()
        .find(|target| body_name(target).eq_ignore_ascii_case(body))
}

/// The network and element whose statement is on `line` (from 1) of the lowered text of
/// `body`: where a halt, a frame or a flow mark reported by line goes in the editor.
pub fn place_at_line(body: &LoweredBody, line: u32) -> Option<editor::BodyPlace> {
    match body.origin_at_line(line)? {
        Origin::Element {
            network, element, ..
        } => Some(editor::BodyPlace { network, element }),
        Origin::Text { .. } => None,
    }
}

/// The network and element of every line of a lowered body's text, worked out in one pass
/// when the body is lowered (a project revision), so the marks of a halt and of every flow
/// line are looked up each frame rather than searched for in the text.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BodyLines {
    /// The lowered text's file as the image's line table names it (`/` between folders).
    pub text_file: String,
    /// Line by line (line 1 first), the place its statement comes from.
    places: Vec<Option<editor::BodyPlace>>,
}

impl BodyLines {
    /// The places of every line of `body`'s lowered text.
    pub fn of(body: &LoweredBody) -> Self {
        let mut start = 0;
        let places = body
            .text
            .split_inclusive('\n')
            .map(|text| {
                // The statement of a line, as `LoweredBody::origin_at_line` takes it.
                let offset = start + (text.len() - text.trim_start().len());
                start += text.len();
                match body.origins.origin(offset..offset + text.trim().len())? {
                    Origin::Element {
                        network, element, ..
                    } => Some(editor::BodyPlace { network, element }),
                    Origin::Text { .. } => None,
                }
            })
            .collect();
        Self {
            text_file: body.text_file.to_string_lossy().replace('\\', "/"),
            places,
        }
    }

    /// Whether some line's statement comes from `place`: an element computed inside another's
    /// statement (an operator box such as ADD feeding a coil) has none, nor has an empty
    /// network.
    pub fn has_statement(&self, place: editor::BodyPlace) -> bool {
        self.places.iter().flatten().any(|at| {
            at.network == place.network && (place.element.is_none() || at.element == place.element)
        })
    }

    /// The place of line `line` (from 1), as [`place_at_line`] gives it.
    pub fn place_at(&self, line: u32) -> Option<editor::BodyPlace> {
        let index = usize::try_from(line).ok()?.checked_sub(1)?;
        self.places.get(index).copied().flatten()
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

    use super::*;

    #[test]
    fn a_body_name_leads_back_to_its_target() {
        let project = project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        assert_eq!(
            body_target(&project, "Interlock"),
            Some(TextTarget::Pou("Interlock".into()))
        );
        assert_eq!(body_target(&project, "Interlock.Nope"), None);
        assert_eq!(body_target(&project, "Nope"), None);
    }

    #[test]
    fn bodies_are_named_as_the_checker_names_them() {
        assert_eq!(body_name(&TextTarget::Pou("Main".into())), "Main");
        let getter = TextTarget::Property {
            pou: "FB".into(),
            property: "Speed".into(),
            get: true,
        };
        assert_eq!(body_name(&getter), "FB.Speed.get");
        let action = TextTarget::Action {
            pou: "FB".into(),
            action: "Reset".into(),
        };
        let place = GraphicalPlace::of_editor(
            &action,
            editor::BodyPlace {
                network: 2,
                element: Some(ElementId(5)),
            },
        );
        assert_eq!(place.command_line(), "FB.Reset:3:5");
        assert_eq!(place.in_editor().element, Some(ElementId(5)));
    }

    #[test]
    fn every_step_and_transition_of_an_sfc_chart_has_a_statement_in_the_image() {
        let project = project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        let lowered = compiler::lower::lower_project(&project).bodies;
        let body = lowered.iter().find(|body| body.pou == "PackCycle").unwrap();
        let image = compiler::compile_project(&project).unwrap();
        let bodies = crate::debug_bodies::GraphicalBodies::of_project(&project);
        let Some(project_model::Object::Pou(pou)) = project.application.object("PackCycle") else {
            panic!("the example has the PackCycle");
        };
        let project_model::Body::Sfc { chart } = &pou.body else {
            panic!("the PackCycle is SFC");
        };
        let mut ids = Vec::new();
        collect_node_ids(&chart.sequence, &mut ids);
        assert!(ids.len() >= 9, "{ids:?}");
        for id in ids {
            let place = editor::BodyPlace {
                network: 0,
                element: Some(id),
            };
            // Offline, F9 looks at the lowered text; logged in, the breakpoint needs the
            // image's statement.
            assert!(
                BodyLines::of(body).has_statement(place),
                "{id:?} has no line"
            );
            let breakpoint = crate::studio::debug::BreakpointPlace::graphical(
                "application/PackCycle.pou.toml",
                GraphicalPlace {
                    body: "PackCycle".to_owned(),
                    network: 0,
                    element: Some(id.0),
                },
            );
            assert!(
                crate::studio::debug::statement_of_place(&breakpoint, &image, &bodies).is_some(),
                "{id:?} has no statement in the image"
            );
        }
    }

    /// The ids of the steps and transitions of `nodes`, in branches too.
    fn collect_node_ids(nodes: &[project_model::SfcNode], ids: &mut Vec<ElementId>) {
        for node in nodes {
            match node {
                project_model::SfcNode::Step(step) => ids.push(step.id),
                project_model::SfcNode::Transition(transition) => ids.push(transition.id),
                project_model::SfcNode::Alternative(branches)
                | project_model::SfcNode::Parallel(branches) => {
                    for branch in &branches.branches {
                        collect_node_ids(&branch.nodes, ids);
                    }
                }
                _ => {}
            }
        }
    }
}
