//! A transition of an SFC graph and its condition → a [`Transition`] (docs/plcopen-xml.md
//! §4.2): a reference, an inline body, or a wire from objects of the same body (an inVariable,
//! contacts, an LD graph into a transition object of LD networks, an FBD graph into one of a
//! CFC chart).

use std::collections::{HashMap, HashSet, VecDeque};

use project_model::{Body, PouAction, Transition};

use super::body_fault::BodyFault;
use super::cfc_chart::{CfcChartBuilder, CfcDialect};
use super::converter::comment;
use super::pous::BodyAt;
use super::sfc_chart::SfcChartBuilder;
use crate::add_data::AddData;
use crate::body::{Body as XmlBody, BodyContent};
use crate::body_object::{BodyObject, ObjectKind, Size};
use crate::connection::{Connection, ConnectionPointIn};
use crate::ld::{Coil, Edge};
use crate::sfc::{Condition, ConditionForm, SfcTransition};

/// A condition as the chart writes it.
struct ConditionText {
    /// An ST expression, or the name of a transition object.
    text: String,
    /// Whether `text` names a transition object (negating it calls it: `NOT Name()`).
    names_object: bool,
}

impl<'o> SfcChartBuilder<'o, '_> {
    /// The transition `object`.
    pub(super) fn transition(
        &mut self,
        object: &BodyObject,
        transition: &SfcTransition,
    ) -> Result<Transition, BodyFault> {
        let id = self.fresh_id();
        let Some(condition) = &transition.condition else {
            return Err(self.error_at(object.local_id, "the transition has no condition"));
        };
        Ok(Transition {
            id,
            condition: self.condition(object, condition)?,
            priority: transition.priority,
            comment: comment(object.documentation.as_ref()),
        })
    }

    fn condition(
        &mut self,
        object: &BodyObject,
        condition: &Condition,
    ) -> Result<String, BodyFault> {
        let converted = match &condition.form {
            ConditionForm::Reference(name) => ConditionText {
                text: name.trim().to_owned(),
                names_object: true,
            },
            ConditionForm::Inline { body, .. } => match &body.content {
                BodyContent::St(text) => match st_expression(&text.text) {
                    Some(expression) => ConditionText {
                        text: expression,
                        names_object: false,
                    },
                    None => {
                        let name = self.pou_objects.condition_name(&self.last_step.clone());
                        self.pou_objects.transitions.push(PouAction {
                            name: name.clone(),
                            body: Body::st(text.text.clone()),
                        });
                        ConditionText {
                            text: name,
                            names_object: true,
                        }
                    }
                },
                // An IL condition ends with its value as the current result, as an IL
                // transition object does (docs/instruction-list.md).
                BodyContent::Il(text) => {
                    let name = self.pou_objects.condition_name(&self.last_step.clone());
                    self.pou_objects.transitions.push(PouAction {
                        name: name.clone(),
                        body: Body::Il {
                            text: text.text.clone(),
                        },
                    });
                    ConditionText {
                        text: name,
                        names_object: true,
                    }
                }
                other => {
                    return Err(BodyFault::NotConverted(format!(
                        "the inline condition of the transition at line {} is {}, whose body has no variable to write the condition to",
                        object.line,
                        other.language()
                    )));
                }
            },
            ConditionForm::Connection(point) => self.wired_condition(object, point)?,
        };
        Ok(
            match (condition.negated == Some(true), converted.names_object) {
                (false, _) => converted.text,
                (true, true) => format!("NOT {}()", converted.text),
                (true, false) => format!("NOT ({})", converted.text),
            },
        )
    }

    /// A condition wired from objects of the body: an `inVariable`'s expression (CODESYS), the
    /// expression of contacts from a left rail, a transition object whose LD networks are the
    /// LD graph that drives the wire, or one whose CFC body is the FBD graph that drives it.
    fn wired_condition(
        &mut self,
        object: &BodyObject,
        point: &ConnectionPointIn,
    ) -> Result<ConditionText, BodyFault> {
        let [connection] = point.connections.as_slice() else {
            return Err(self.error_at(
                object.local_id,
                &format!(
                    "the transition's condition has {} wires; it takes one",
                    point.connections.len()
                ),
            ));
        };
        let source = self.object(connection.ref_local_id)?;
        if let ObjectKind::InVariable(variable) = &source.kind
            && !matches!(variable.edge, Some(Edge::Rising | Edge::Falling))
        {
            self.used.insert(source.local_id);
            let expression = variable.expression.trim();
            return Ok(ConditionText {
                text: if variable.negated == Some(true) {
                    format!("NOT ({expression})")
                } else {
                    expression.to_owned()
                },
                names_object: false,
            });
        }
        let graph = self.driving_graph(source.local_id)?;
        if graph.iter().any(|object| is_ld_object(&object.kind)) {
            // Contacts in series and parallel from a left rail are a boolean expression.
            // The walk recurses per contact: a bounded budget keeps its stack small.
            if let Some(text) = self.contact_expression(source.local_id, graph.len().min(256)) {
                for part in &graph {
                    self.used.insert(part.local_id);
                }
                self.note_condition_coils(&graph);
                return Ok(ConditionText {
                    text,
                    names_object: false,
                });
            }
            return self.ld_condition(object, connection, &graph);
        }
        let name = self.pou_objects.condition_name(&self.last_step.clone());
        let mut builder = CfcChartBuilder::new(
            graph.clone(),
            CfcDialect::Beremiz,
            &self.body_path,
            object.line,
            self.bodies.structures(),
        );
        builder.build()?;
        let from = builder.source_of(connection, &self.place(object))?;
        builder.add_output(&name, from);
        let chart = builder.finish()?;
        for part in &graph {
            self.used.insert(part.local_id);
        }
        let (instances, edges) = stateful_parts(&graph);
        if instances + edges > 0 {
            self.note(
                object,
                format!("condition '{name}'"),
                &stateful_note(instances, edges),
            );
        }
        self.pou_objects.transitions.push(PouAction {
            name: name.clone(),
            body: Body::Cfc { chart },
        });
        Ok(ConditionText {
            text: name,
            names_object: true,
        })
    }

    /// A condition wired from an LD graph that is more than contacts (`graph`, the objects that
    /// drive the wire `connection` into the condition of `transition`): a transition object
    /// whose LD networks are the graph without its coils, with a coil writing the object's name
    /// at the wire's end.
    fn ld_condition(
        &mut self,
        transition: &BodyObject,
        connection: &Connection,
        graph: &[&'o BodyObject],
    ) -> Result<ConditionText, BodyFault> {
        let name = self.pou_objects.condition_name(&self.last_step.clone());
        let taken: HashSet<u64> = self.all_objects().iter().map(|o| o.local_id).collect();
        // Any id no object of the body has: the body holds fewer ids than there are.
        let mut coil_id = 0;
        while taken.contains(&coil_id) {
            coil_id += 1;
        }
        // Beremiz's generator writes no coil of a condition: each passes its power on, so
        // whatever reads a coil reads what powers it.
        let (objects, into_condition) = without_coils(graph, connection);
        let coil = BodyObject {
            local_id: coil_id,
            execution_order_id: None,
            global_id: None,
            // Where the wire ends, so the networks order their branches as drawn.
            position: transition.position,
            size: Size::default(),
            kind: ObjectKind::Coil(Coil {
                variable: name.clone(),
                negated: None,
                edge: None,
                storage: None,
                input: Some(ConnectionPointIn {
                    rel_position: None,
                    connections: into_condition,
                    expression: None,
                    add_data: AddData::default(),
                }),
                output: None,
            }),
            add_data: AddData::default(),
            documentation: None,
            line: transition.line,
            column: transition.column,
        };
        let objects: Vec<BodyObject> = objects.into_iter().chain([coil]).collect();
        let body = XmlBody {
            worksheet_name: None,
            global_id: None,
            content: BodyContent::Ld(objects),
            cfc: None,
            add_data: AddData::default(),
            documentation: None,
            line: transition.line,
        };
        let holder = self.place(transition);
        let at = BodyAt {
            holder: &holder,
            body_path: self.body_path.clone(),
            objects_path: self.body_path.clone(),
            // The coil is the import's own: what concerns it concerns the condition.
            invented: Some((
                format!("{}/coil[@localId='{coil_id}']", self.body_path),
                format!("{}/condition", holder.path),
            )),
        };
        let what = format!("condition '{name}'");
        let converted = self
            .bodies
            .nested_body(&body, &at, &what, self.pou_objects)
            .map_err(|fault| match fault {
                BodyFault::NotConverted(reason) => BodyFault::NotConverted(format!(
                    "the condition of the transition at line {} is wired from an LD graph that cannot be converted: {reason}",
                    transition.line
                )),
                error @ BodyFault::Error(..) => error,
            })?;
        for part in graph {
            self.used.insert(part.local_id);
        }
        self.note_condition_coils(graph);
        let (instances, edges) = stateful_parts(graph);
        if instances + edges > 0 {
            self.note(transition, what, &stateful_note(instances, edges));
        }
        self.pou_objects.transitions.push(PouAction {
            name: name.clone(),
            body: converted,
        });
        Ok(ConditionText {
            text: name,
            names_object: true,
        })
    }

    /// The expression of a network of contacts from a left power rail ending at `local_id`:
    /// a contact is its variable (`NOT v` when negated) ANDed with what powers it, parallel
    /// wires are ORed; a coil passes its power on. `None` when the network holds anything else
    /// (a block, an edge contact), or is deeper than `budget` (a ring).
    fn contact_expression(&self, local_id: u64, budget: usize) -> Option<String> {
        let budget = budget.checked_sub(1)?;
        let object = self.object(local_id).ok()?;
        match &object.kind {
            ObjectKind::LeftPowerRail(_) => Some("TRUE".to_owned()),
            ObjectKind::Contact(contact) => {
                if matches!(contact.edge, Some(Edge::Rising | Edge::Falling)) {
                    return None;
                }
                let variable = contact.variable.trim();
                let operand = if contact.negated == Some(true) {
                    format!("NOT {variable}")
                } else {
                    variable.to_owned()
                };
                let power = self.power_expression(contact.input.as_ref()?, budget)?;
                Some(if power == "TRUE" {
                    operand
                } else {
                    format!("{power} AND {operand}")
                })
            }
            // A coil of a condition passes its power on and writes nothing (§4.2).
            ObjectKind::Coil(coil) => self.power_expression(coil.input.as_ref()?, budget),
            _ => None,
        }
    }

    /// The power that reaches `point` as an expression: its wires' expressions ORed.
    fn power_expression(&self, point: &ConnectionPointIn, budget: usize) -> Option<String> {
        let mut powers = Vec::new();
        for connection in &point.connections {
            powers.push(self.contact_expression(connection.ref_local_id, budget)?);
        }
        match powers.as_slice() {
            [] => None,
            [one] => Some(one.clone()),
            several => Some(format!("({})", several.join(" OR "))),
        }
    }

    /// Reports each coil of `graph`, the objects of a condition: Beremiz's generator passes a
    /// condition's coil's power on without writing its variable, and so does the import.
    fn note_condition_coils(&mut self, graph: &[&'o BodyObject]) {
        for part in graph {
            if let ObjectKind::Coil(coil) = &part.kind {
                // A coil that feeds several conditions is reported once.
                let path = self.place(part).path;
                if self.report.iter().any(|entry| entry.path == path) {
                    continue;
                }
                self.note(
                    part,
                    format!("coil '{}'", coil.variable.trim()),
                    "a coil in a transition's condition passes its power on and writes nothing, as in Beremiz's generator",
                );
            }
        }
    }

    /// The objects that drive `local_id` (itself included), back through wires and from a
    /// continuation to its connectors, in document order.
    fn driving_graph(&self, local_id: u64) -> Result<Vec<&'o BodyObject>, BodyFault> {
        let mut seen: HashSet<u64> = HashSet::new();
        let mut queue = VecDeque::from([local_id]);
        while let Some(id) = queue.pop_front() {
            if !seen.insert(id) {
                continue;
            }
            let object = self.object(id)?;
            if let ObjectKind::Continuation(continuation) = &object.kind {
                for candidate in self.all_objects() {
                    if matches!(&candidate.kind, ObjectKind::Connector(connector)
                        if connector.name.eq_ignore_ascii_case(&continuation.name))
                    {
                        queue.push_back(candidate.local_id);
                    }
                }
            }
            for point in object.kind.graph_inputs() {
                for connection in &point.connections {
                    queue.push_back(connection.ref_local_id);
                }
            }
        }
        Ok(self
            .all_objects()
            .iter()
            .filter(|object| seen.contains(&object.local_id))
            .collect())
    }
}

/// Whether `kind` belongs to LD only.
fn is_ld_object(kind: &ObjectKind) -> bool {
    matches!(
        kind,
        ObjectKind::Contact(_)
            | ObjectKind::Coil(_)
            | ObjectKind::LeftPowerRail(_)
            | ObjectKind::RightPowerRail(_)
    )
}

/// How many function block instances and edge detections (edge contacts, edge pins of blocks)
/// the objects of a condition hold: the parts with state, which Beremiz runs every cycle.
fn stateful_parts(graph: &[&BodyObject]) -> (usize, usize) {
    let is_edge = |edge: Option<Edge>| matches!(edge, Some(Edge::Rising | Edge::Falling));
    let mut instances = 0;
    let mut edges = 0;
    for part in graph {
        match &part.kind {
            ObjectKind::Block(block) => {
                if block.instance_name.is_some() {
                    instances += 1;
                }
                edges += block
                    .inputs
                    .iter()
                    .chain(&block.in_outs)
                    .chain(&block.outputs)
                    .filter(|pin| is_edge(pin.edge))
                    .count();
            }
            ObjectKind::Contact(contact) if is_edge(contact.edge) => edges += 1,
            _ => {}
        }
    }
    (instances, edges)
}

/// The report's note on a condition with `instances` function block instances and `edges`
/// edge detections (docs/plcopen-xml.md §4.2, the decision).
fn stateful_note(instances: usize, edges: usize) -> String {
    format!(
        "it holds {instances} function block instance(s) and {edges} edge detection(s), which Beremiz runs every cycle (its action COMPUTE_FUNCTION_BLOCKS) and Rivet only when the transition is tested: an edge that comes while the step is inactive is consumed in Beremiz and seen by Rivet when the step becomes active"
    )
}

/// The objects of `graph` without their coils, and the wires of `connection` (into the
/// condition) likewise: each wire from a coil is replaced by the wires into the coil, through
/// chains of coils, as Beremiz's generator passes a coil's power on.
fn without_coils(
    graph: &[&BodyObject],
    connection: &Connection,
) -> (Vec<BodyObject>, Vec<Connection>) {
    let coil_inputs: HashMap<u64, &[Connection]> = graph
        .iter()
        .filter_map(|part| match &part.kind {
            ObjectKind::Coil(coil) => Some((
                part.local_id,
                coil.input
                    .as_ref()
                    .map_or(&[][..], |point| point.connections.as_slice()),
            )),
            _ => None,
        })
        .collect();
    let past_coils = |connections: &[Connection]| -> Vec<Connection> {
        let mut found: Vec<Connection> = Vec::new();
        let mut expanded: HashSet<u64> = HashSet::new();
        let mut stack: Vec<Connection> = connections.iter().rev().cloned().collect();
        while let Some(next) = stack.pop() {
            match coil_inputs.get(&next.ref_local_id) {
                // Each coil once: a ring of coils ends.
                Some(inputs) => {
                    if expanded.insert(next.ref_local_id) {
                        stack.extend(inputs.iter().rev().cloned());
                    }
                }
                None => {
                    let same = |other: &Connection| {
                        other.ref_local_id == next.ref_local_id
                            && other.formal_parameter == next.formal_parameter
                    };
                    if !found.iter().any(same) {
                        found.push(next);
                    }
                }
            }
        }
        found
    };
    let objects = graph
        .iter()
        .filter(|part| !matches!(part.kind, ObjectKind::Coil(_)))
        .map(|part| {
            let mut part = (*part).clone();
            for point in part.kind.graph_inputs_mut() {
                point.connections = past_coils(&point.connections);
            }
            part
        })
        .collect();
    (objects, past_coils(std::slice::from_ref(connection)))
}

/// The expression of an inline ST condition that is one expression (`a AND b`, `a AND b;`),
/// or `None` when it holds statements (a `:=` or a `;` before its end).
pub(super) fn st_expression(text: &str) -> Option<String> {
    let trimmed = text.trim();
    let expression = trimmed.strip_suffix(';').unwrap_or(trimmed).trim();
    if expression.is_empty() || expression.contains(":=") || expression.contains(';') {
        return None;
    }
    Some(expression.to_owned())
}

#[cfg(test)]
mod tests {
    use super::st_expression;

    #[test]
    fn an_expression_is_kept_and_statements_are_not() {
        assert_eq!(st_expression(" NOT Reset ").as_deref(), Some("NOT Reset"));
        assert_eq!(st_expression("a AND b;").as_deref(), Some("a AND b"));
        assert_eq!(st_expression("T1 := a; T1 := T1 OR b;"), None);
        assert_eq!(st_expression("  "), None);
    }
}
