//! POUs with their actions, transitions and CODESYS methods → POU objects.

use project_model::{Body, Method, Network, Object, PouAction, PouKind, element_signature};

use super::body_fault::BodyFault;
use super::cfc_chart::{CfcDialect, fbd_graph_to_cfc};
use super::converter::{Converter, Place, comment, is_rivet_entry};
use super::error::{ImportError, ImportErrorKind};
use super::network_import::{ElementIds, NetworkOutcome};
use super::pou_objects::PouObjects;
use super::report::Outcome;
use super::rivet_attributes::rivet_attributes;
use super::sfc_chart::SfcChartBuilder;
use super::type_text::type_text;
use super::unconverted_body::UnconvertedBody;
use super::vendor_places::element_place;
use crate::body::{Body as XmlBody, BodyContent};
use crate::interface::Interface;
use crate::pou::{Pou, PouLocation, PouType};

/// Where a body stands in the document, for errors and the report.
pub(super) struct BodyAt<'p> {
    /// The element that holds the body: a POU, action, transition or method, or for a body
    /// inside an SFC body the SFC object it belongs to.
    pub holder: &'p Place,
    /// The path of the element that holds the language element (`…/body`, an inline body's
    /// `…/inline`), or of the SFC body a wired condition's objects stand in.
    pub body_path: String,
    /// The path of the element whose children are the body's objects (`…/body/LD`), or of the
    /// SFC body a wired condition's objects stand in.
    pub objects_path: String,
    /// The path of an object the import added to the body (the coil at a wired condition's
    /// end), and the path its errors and report entries name instead (the condition).
    pub invented: Option<(String, String)>,
}

/// Whether an FBD body carries Rivet's marker of a CFC chart (the `…/language` entry holding
/// `<language name="CFC"/>`).
fn is_rivet_cfc(body: &XmlBody) -> bool {
    matches!(body.content, BodyContent::Fbd(_))
        && rivet_attributes(&body.add_data, "language")
            .is_some_and(|attributes| attributes.get("name").is_some_and(|name| name == "CFC"))
}

/// The language of a body as the report names it (CODESYS CFC stands beside an empty ST).
fn language(body: &XmlBody) -> &'static str {
    if body.cfc.is_some() || is_rivet_cfc(body) {
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
        let mut synthesized = PouObjects::new(
            pou.interface
                .iter()
                .flat_map(|interface| &interface.var_lists)
                .flat_map(|list| &list.variables)
                .map(|variable| variable.name.as_str())
                .chain(pou.actions.iter().map(|action| action.name.as_str()))
                .chain(
                    pou.transitions
                        .iter()
                        .map(|transition| transition.name.as_str()),
                )
                .chain(pou.methods.iter().map(|method| method.name.as_str())),
        );
        let body = match pou.bodies.first() {
            None => Body::None,
            Some(first) => match self.body(first, &place, &what, &mut synthesized)? {
                Ok(body) => body,
                Err(note) => {
                    self.report.push(
                        Outcome::NotConverted,
                        what,
                        &place.path,
                        place.line,
                        note.to_string(),
                    );
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
            match self.body(&action.body, &action_place, &what, &mut synthesized)? {
                Ok(body) => {
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
                Err(note) => self.report.push(
                    Outcome::NotConverted,
                    what,
                    &action_path,
                    action.body.line,
                    note.to_string(),
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
            match self.body(&transition.body, &transition_place, &what, &mut synthesized)? {
                Ok(body) => {
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
                Err(note) => self.report.push(
                    Outcome::NotConverted,
                    what,
                    &transition_path,
                    transition.body.line,
                    note.to_string(),
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
                Some(first) => match self.body(first, &method_place, &what, &mut synthesized)? {
                    Ok(body) => body,
                    Err(note) => {
                        self.report.push(
                            Outcome::NotConverted,
                            what,
                            &method_path,
                            place.line,
                            note.to_string(),
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
        self.synthesized(&pou.name, &place, synthesized, &mut converted);
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

    /// The body of the element at `holder` (named `what` in the report) converted, or why it
    /// is not (a full sentence for the report). SFC and CFC bodies add their inline actions and
    /// conditions to `synthesized`; an FBD graph that is not a set of networks becomes a CFC
    /// chart (§3.6).
    fn body(
        &mut self,
        body: &XmlBody,
        holder: &Place,
        what: &str,
        synthesized: &mut PouObjects,
    ) -> Result<Result<Body, UnconvertedBody>, ImportError> {
        let body_path = format!("{}/body", holder.path);
        let at = BodyAt {
            holder,
            objects_path: format!("{body_path}/{}", body.content.language()),
            body_path,
            invented: None,
        };
        self.body_at(body, &at, what, synthesized)
    }

    /// [`Self::body`] for a body that stands at `at`: a POU's, or one inside an SFC body (an
    /// inline action, the LD graph of a wired condition).
    pub(super) fn body_at(
        &mut self,
        body: &XmlBody,
        at: &BodyAt<'_>,
        what: &str,
        synthesized: &mut PouObjects,
    ) -> Result<Result<Body, UnconvertedBody>, ImportError> {
        if let Some(text) = st_text(body) {
            return Ok(Ok(Body::St { text }));
        }
        if let BodyContent::Il(text) = &body.content {
            return Ok(Ok(Body::Il {
                text: text.text.clone(),
            }));
        }
        let path = at.body_path.as_str();
        let mut fallback_note = None;
        if !is_rivet_cfc(body) {
            match self.networks_at(body, at, what)? {
                Some(NetworkOutcome::Networks(networks, element_ids)) => {
                    let objects = body.content.objects();
                    // Only a POU's own body keeps its objects' vendor data with the elements
                    // they became: an inline or condition body's objects stand elsewhere.
                    let own_objects =
                        format!("{}/body/{}", at.holder.path, body.content.language());
                    let elements = (at.objects_path == own_objects).then_some((
                        path,
                        &element_ids,
                        networks.as_slice(),
                    ));
                    self.opaque_objects(objects, &at.objects_path, elements);
                    return Ok(Ok(match body.content {
                        BodyContent::Ld(_) => Body::Ld { networks },
                        _ => Body::Fbd { networks },
                    }));
                }
                Some(NetworkOutcome::NotANetwork { reason }) => {
                    if !matches!(body.content, BodyContent::Fbd(_)) {
                        return Ok(Err(UnconvertedBody::NotNetworks {
                            language: language(body),
                            reason,
                        }));
                    }
                    fallback_note = Some(reason);
                }
                None => {}
            }
        }
        let cfc_entry = body
            .add_data
            .entry_ending_with("/cfc")
            .map_or("", |entry| entry.name.as_str());
        // Where the body's objects stand, for errors and the report.
        let objects_path = match &body.cfc {
            Some(_) => format!("{path}/addData/data[@name='{cfc_entry}']/CFC"),
            None => at.objects_path.clone(),
        };
        let converted = match (&body.cfc, &body.content) {
            (Some(objects), _) => fbd_graph_to_cfc(
                objects,
                CfcDialect::Codesys,
                &objects_path,
                body.line,
                &self.structures,
            )
            .map(|chart| Body::Cfc { chart }),
            (None, BodyContent::Sfc(objects)) => {
                let builder =
                    SfcChartBuilder::new(objects, &objects_path, body.line, synthesized, self);
                builder.chart_on_own_stack().map(|(chart, entries)| {
                    self.report.entries.extend(entries);
                    Body::Sfc { chart }
                })
            }
            (None, BodyContent::Fbd(objects)) if is_rivet_cfc(body) => fbd_graph_to_cfc(
                objects,
                CfcDialect::Rivet,
                &objects_path,
                body.line,
                &self.structures,
            )
            .map(|chart| Body::Cfc { chart }),
            // An FBD graph with feedback or fan-out: a CFC chart runs it as drawn.
            (None, BodyContent::Fbd(objects)) => fbd_graph_to_cfc(
                objects,
                CfcDialect::Beremiz,
                &objects_path,
                body.line,
                &self.structures,
            )
            .map(|chart| Body::Cfc { chart }),
            _ => {
                return Ok(Err(UnconvertedBody::UnsupportedLanguage {
                    language: language(body),
                }));
            }
        };
        if let (Ok(_), Some(reason)) = (&converted, &fallback_note) {
            self.report.push(
                Outcome::Converted,
                format!("FBD body of {what}"),
                path,
                body.line,
                format!("imported as a CFC chart, because the FBD graph is not a set of networks: {reason}"),
            );
        }
        let objects = body.cfc.as_deref().unwrap_or(body.content.objects());
        match converted {
            Ok(converted) => {
                self.opaque_objects(objects, &objects_path, None);
                Ok(Ok(converted))
            }
            Err(BodyFault::NotConverted(reason)) => Ok(Err(match fallback_note {
                Some(network_reason) => UnconvertedBody::NeitherNetworksNorCfc {
                    language: language(body),
                    network_reason,
                    reason,
                },
                None => UnconvertedBody::NotConvertible {
                    language: language(body),
                    reason,
                },
            })),
            Err(BodyFault::Error(place, kind)) => Err(self.error(&place, kind)),
        }
    }

    /// [`Self::networks`] for the body at `at`: the network import names a body
    /// `{holder}/body/LANG`, so the paths of its errors and report entries are moved to where
    /// the body's objects stand (an inline body's `…/inline/LD`, a wired condition's SFC body).
    fn networks_at(
        &mut self,
        body: &XmlBody,
        at: &BodyAt<'_>,
        what: &str,
    ) -> Result<Option<NetworkOutcome>, ImportError> {
        let named = format!("{}/body/{}", at.holder.path, body.content.language());
        let relocated = |path: &mut String| {
            if named != at.objects_path
                && let Some(rest) = path.strip_prefix(named.as_str())
            {
                *path = format!("{}{rest}", at.objects_path);
            }
            if let Some((invented, instead)) = &at.invented
                && let Some(rest) = path.strip_prefix(invented.as_str())
            {
                *path = format!("{instead}{rest}");
            }
        };
        let first_entry = self.report.entries.len();
        let outcome = self.networks(body, at.holder, what);
        for entry in &mut self.report.entries[first_entry..] {
            relocated(&mut entry.path);
        }
        outcome.map_err(|mut error| {
            relocated(&mut error.path);
            error
        })
    }

    /// Keeps the `addData` entries of the objects of a converted body (CODESYS's
    /// `fbdcalltype`, `sfc/element`…) with the element each object became, when `elements`
    /// gives the body's path and that map and the export writes the body's elements with their
    /// ids (a POU's own LD or FBD body, §5.5). The others are reported not converted: the
    /// body's objects are rebuilt, so their entries have no element to go back to (CODESYS's
    /// CFC keeps them inside its `…/cfc` entry, which is kept). Rivet's own entries were read
    /// into the chart.
    pub(super) fn opaque_objects(
        &mut self,
        objects: &[crate::BodyObject],
        path: &str,
        elements: Option<(&str, &ElementIds, &[Network])>,
    ) {
        for object in objects {
            let object_path = format!(
                "{path}/{}[@localId='{}']",
                object.kind.element_name(),
                object.local_id
            );
            // The element's signature goes with the entry so that the export writes it back
            // only into that element, not into another that took its id since (§5.5).
            let place = elements.and_then(|(body_path, ids, networks)| {
                let id = *ids.get(&object.local_id)?;
                let place = element_place(body_path, id)?;
                let element = networks.iter().find_map(|network| network.element(id))?;
                Some((place, element_signature(element)))
            });
            for entry in &object.add_data.entries {
                if is_rivet_entry(&entry.name) {
                    continue;
                }
                match &place {
                    Some((place, signature)) => {
                        self.keep_vendor_entry_at(
                            entry,
                            &object_path,
                            object.line,
                            place.clone(),
                            Some(signature.clone()),
                        );
                    }
                    None => {
                        let entry_path =
                            format!("{object_path}/addData/data[@name='{}']", entry.name);
                        // An object of a wired condition is converted with the condition and
                        // with its SFC body, and may feed several conditions: one entry says it.
                        if !self.reported_object_data.insert(entry_path.clone()) {
                            continue;
                        }
                        self.report.push(
                            Outcome::NotConverted,
                            format!("addData '{}'", entry.name),
                            &entry_path,
                            object.line,
                            "the data of one object of a converted body: Rivet rebuilds the body's objects, so it has no element to go back to",
                        );
                    }
                }
            }
        }
    }

    /// Adds the actions and transition objects synthesized from inline bodies to the POU, and
    /// reports each (and each name changed because it was taken).
    fn synthesized(
        &mut self,
        pou: &str,
        place: &Place,
        synthesized: PouObjects,
        converted: &mut project_model::Pou,
    ) {
        for (kind, objects, note) in [
            (
                "action",
                synthesized.actions,
                "made of an inline action body of an SFC step",
            ),
            (
                "transition",
                synthesized.transitions,
                "made of a transition's inline or wired condition",
            ),
        ] {
            for object in objects {
                self.report.push(
                    Outcome::Converted,
                    format!("{kind} '{pou}.{}'", object.name),
                    &place.path,
                    place.line,
                    note,
                );
                if kind == "action" {
                    converted.actions.push(object);
                } else {
                    converted.transitions.push(object);
                }
            }
        }
        for renamed in synthesized.renamed {
            self.report.push(
                Outcome::Converted,
                format!("POU '{pou}'"),
                &place.path,
                place.line,
                renamed,
            );
        }
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
            Some(data_type) => Some(type_text(data_type).map_err(|error| {
                self.error(place, ImportErrorKind::InexpressibleType(error.to_string()))
            })?),
            None => None,
        };
        let variables = self.variables(&interface.var_lists, path, place.line)?;
        self.opaque(&interface.add_data, path, place.line);
        Ok((variables, return_type))
    }
}
