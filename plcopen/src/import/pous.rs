//! POUs with their actions, transitions and CODESYS methods → POU objects.

use project_model::{Body, Method, Object, PouAction, PouKind};

use super::converter::{Converter, Place, comment, is_rivet_entry};
use super::error::{ImportError, ImportErrorKind};
use super::network_import::NetworkOutcome;
use super::report::Outcome;
use super::type_text::type_text;
use crate::body::{Body as XmlBody, BodyContent};
use crate::interface::Interface;
use crate::pou::{Pou, PouLocation, PouType};

/// Why a body is not converted by this part of the import.
const LATER: &str = "CFC, SFC and IL bodies are converted by a later part of the import";

/// What became of one body.
enum BodyOutcome {
    /// The Rivet body.
    Converted(Body),
    /// Not converted, for the reason given (the report's note).
    NotConverted(String),
}

/// The language of a body as the report names it (CODESYS CFC stands beside an empty ST).
fn language(body: &XmlBody) -> &'static str {
    if body.cfc.is_some() {
        "CFC"
    } else {
        body.content.language()
    }
}

/// The ST text of a body, or `None` when it is in another language.
fn st_text(body: &XmlBody) -> Option<String> {
    match &body.content {
        BodyContent::St(text) if body.cfc.is_none() => Some(text.text.clone()),
        _ => None,
    }
}

impl Converter<'_> {
    /// The Rivet body of `body`, or the reason it is not converted; `place` is the element that
    /// holds the body and `what` names it in the report.
    fn body(
        &mut self,
        body: &XmlBody,
        place: &Place,
        what: &str,
    ) -> Result<BodyOutcome, ImportError> {
        if let Some(text) = st_text(body) {
            return Ok(BodyOutcome::Converted(Body::St { text }));
        }
        Ok(match self.networks(body, place, what)? {
            Some(NetworkOutcome::Networks(networks)) => {
                BodyOutcome::Converted(match body.content {
                    BodyContent::Ld(_) => Body::Ld { networks },
                    _ => Body::Fbd { networks },
                })
            }
            Some(NetworkOutcome::NotANetwork { reason }) => BodyOutcome::NotConverted(format!(
                "its {} body is not a set of networks: {reason}",
                language(body)
            )),
            None => BodyOutcome::NotConverted(format!("its body is {}; {LATER}", language(body))),
        })
    }

    /// Converts every POU whose body is ST (or that has none), in document order.
    pub fn pous(&mut self) -> Result<(), ImportError> {
        for pou in &self.document.pous {
            self.pou(pou)?;
        }
        Ok(())
    }

    fn pou(&mut self, pou: &Pou) -> Result<(), ImportError> {
        let path = match &pou.location {
            PouLocation::Types => format!("project/types/pous/pou[@name='{}']", pou.name),
            PouLocation::Resource {
                configuration,
                resource,
            } => format!(
                "project/instances/configurations/configuration[@name='{configuration}']/resource[@name='{resource}']/addData/data/pou[@name='{}']",
                pou.name
            ),
        };
        let place = Place {
            path,
            line: pou.line,
            column: pou.column,
        };
        if self.rivet_pou(pou, &place)? {
            return Ok(());
        }
        let what = format!("POU '{}'", pou.name);
        let body = match pou.bodies.first() {
            None => Body::None,
            Some(first) => match self.body(first, &place, &what)? {
                BodyOutcome::Converted(body) => body,
                BodyOutcome::NotConverted(note) => {
                    self.report
                        .push(Outcome::NotConverted, what, &place.path, place.line, note);
                    return Ok(());
                }
            },
        };
        for extra in pou.bodies.iter().skip(1) {
            self.report.push(
                Outcome::NotConverted,
                format!("second {} body of POU '{}'", language(extra), pou.name),
                &format!("{}/body", place.path),
                extra.line,
                "Rivet's POUs have one body",
            );
        }
        let (variables, return_type) = self.interface(
            pou.interface.as_ref(),
            &format!("{}/interface", place.path),
            &place,
        )?;
        let mut converted = project_model::Pou {
            name: pou.name.clone(),
            kind: match pou.pou_type {
                PouType::Program => PouKind::Program,
                PouType::FunctionBlock => PouKind::FunctionBlock,
                PouType::Function => PouKind::Function,
            },
            return_type,
            extends: None,
            implements: Vec::new(),
            comment: comment(pou.documentation.as_ref()),
            variables,
            body,
            methods: Vec::new(),
            properties: Vec::new(),
            actions: Vec::new(),
            transitions: Vec::new(),
        };
        for action in &pou.actions {
            let action_path = format!("{}/actions/action[@name='{}']", place.path, action.name);
            self.opaque(&action.add_data, &action_path, action.body.line);
            let action_place = Place {
                path: action_path.clone(),
                line: action.body.line,
                column: 1,
            };
            let what = format!("action '{}.{}'", pou.name, action.name);
            match self.body(&action.body, &action_place, &what)? {
                BodyOutcome::Converted(body) => {
                    converted.actions.push(PouAction {
                        name: action.name.clone(),
                        body,
                    });
                    self.report.push(
                        Outcome::Converted,
                        format!("action '{}.{}'", pou.name, action.name),
                        &action_path,
                        action.body.line,
                        "",
                    );
                }
                BodyOutcome::NotConverted(note) => self.report.push(
                    Outcome::NotConverted,
                    what,
                    &action_path,
                    action.body.line,
                    note,
                ),
            }
        }
        for transition in &pou.transitions {
            let transition_path = format!(
                "{}/transitions/transition[@name='{}']",
                place.path, transition.name
            );
            self.opaque(&transition.add_data, &transition_path, transition.body.line);
            let transition_place = Place {
                path: transition_path.clone(),
                line: transition.body.line,
                column: 1,
            };
            let what = format!("transition '{}.{}'", pou.name, transition.name);
            match self.body(&transition.body, &transition_place, &what)? {
                BodyOutcome::Converted(body) => {
                    converted.transitions.push(PouAction {
                        name: transition.name.clone(),
                        body,
                    });
                    self.report.push(
                        Outcome::Converted,
                        format!("transition '{}.{}'", pou.name, transition.name),
                        &transition_path,
                        transition.body.line,
                        "",
                    );
                }
                BodyOutcome::NotConverted(note) => self.report.push(
                    Outcome::NotConverted,
                    what,
                    &transition_path,
                    transition.body.line,
                    note,
                ),
            }
        }
        let method_entry = pou
            .add_data
            .entry_ending_with("/method")
            .map_or("", |entry| entry.name.as_str());
        for method in &pou.methods {
            let method_path = format!(
                "{}/addData/data[@name='{method_entry}']/Method[@name='{}']",
                place.path, method.name
            );
            let what = format!("method '{}.{}'", pou.name, method.name);
            let method_place = Place {
                path: method_path.clone(),
                line: place.line,
                column: place.column,
            };
            let body = match method.bodies.first() {
                None => Body::None,
                Some(first) => match self.body(first, &method_place, &what)? {
                    BodyOutcome::Converted(body) => body,
                    BodyOutcome::NotConverted(note) => {
                        self.report.push(
                            Outcome::NotConverted,
                            what,
                            &method_path,
                            place.line,
                            note,
                        );
                        continue;
                    }
                },
            };
            let (variables, return_type) = self.interface(
                method.interface.as_ref(),
                &format!("{method_path}/interface"),
                &place,
            )?;
            self.opaque(&method.add_data, &method_path, place.line);
            converted.methods.push(Method {
                name: method.name.clone(),
                return_type,
                access: project_model::AccessSpecifier::Public,
                is_abstract: false,
                comment: comment(method.documentation.as_ref()),
                variables,
                body,
            });
            self.report
                .push(Outcome::Converted, what, &method_path, place.line, "");
        }
        for body in &pou.bodies {
            self.opaque(&body.add_data, &format!("{}/body", place.path), body.line);
        }
        self.add_object("POU", Object::Pou(converted), &place)?;
        self.report.push(
            Outcome::Converted,
            format!("POU '{}'", pou.name),
            &place.path,
            place.line,
            "",
        );
        // The methods were read from the POU's own `addData`; the other entries are opaque.
        for entry in &pou.add_data.entries {
            if !entry.name.ends_with("/method") && !is_rivet_entry(&entry.name) {
                self.keep_vendor_entry(entry, &place.path, place.line);
            }
        }
        Ok(())
    }

    /// The declarations and return type of an interface.
    pub(super) fn interface(
        &mut self,
        interface: Option<&Interface>,
        path: &str,
        place: &Place,
    ) -> Result<(Vec<project_model::Variable>, Option<String>), ImportError> {
        let Some(interface) = interface else {
            return Ok((Vec::new(), None));
        };
        let return_type = match &interface.return_type {
            Some(data_type) => Some(type_text(data_type).map_err(|message| {
                self.error(place, ImportErrorKind::InexpressibleType(message))
            })?),
            None => None,
        };
        let variables = self.variables(&interface.var_lists, path, place.line)?;
        self.opaque(&interface.add_data, path, place.line);
        Ok((variables, return_type))
    }
}
