//! A transition of an SFC graph and its condition → a [`Transition`] (docs/plcopen-xml.md
//! §4.2): a reference, an inline body, or a wire from objects of the same body (an inVariable,
//! contacts, an LD graph into a transition object of LD networks, an FBD graph into one of a
//! CFC chart).

use std::collections::{HashSet, VecDeque};

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
        );
        builder.build()?;
        let from = builder.source_of(connection, &self.place(object))?;
        builder.add_output(&name, from);
        let chart = builder.finish()?;
        for part in &graph {
            self.used.insert(part.local_id);
        }
        if graph.iter().any(
            |part| matches!(&part.kind, ObjectKind::Block(block) if block.instance_name.is_some()),
        ) {
            self.note(
                object,
                format!("condition '{name}'"),
                "Beremiz runs the blocks of an SFC body every cycle; Rivet runs them when the transition is tested",
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
    /// whose LD networks are the graph, with a coil writing the object's name at the wire's end.
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
                    connections: vec![connection.clone()],
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
        let objects: Vec<BodyObject> = graph
            .iter()
            .map(|part| (*part).clone())
            .chain([coil])
            .collect();
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
        let runs_with_state = graph.iter().any(|part| match &part.kind {
            ObjectKind::Block(block) => block.instance_name.is_some(),
            ObjectKind::Coil(_) => true,
            _ => false,
        });
        if runs_with_state {
            self.note(
                transition,
                what,
                "Beremiz runs the blocks and coils of an SFC body every cycle; Rivet runs them when the transition is tested",
            );
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
    /// wires are ORed. `None` when the network holds anything else (a coil, a block, an edge
    /// contact), or is deeper than `budget` (a ring).
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
                let connections = &contact.input.as_ref()?.connections;
                let mut powers = Vec::new();
                for connection in connections {
                    powers.push(self.contact_expression(connection.ref_local_id, budget)?);
                }
                let power = match powers.as_slice() {
                    [] => return None,
                    [one] => one.clone(),
                    several => format!("({})", several.join(" OR ")),
                };
                Some(if power == "TRUE" {
                    operand
                } else {
                    format!("{power} AND {operand}")
                })
            }
            _ => None,
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
            for point in graph_inputs(&object.kind) {
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

/// The connection points through which an FBD or LD object reads others.
fn graph_inputs(kind: &ObjectKind) -> Vec<&ConnectionPointIn> {
    match kind {
        ObjectKind::Block(block) => block
            .inputs
            .iter()
            .chain(&block.in_outs)
            .filter_map(|pin| pin.input.as_ref())
            .collect(),
        ObjectKind::VendorElement(element) => element
            .inputs
            .iter()
            .chain(&element.in_outs)
            .filter_map(|pin| pin.input.as_ref())
            .collect(),
        ObjectKind::OutVariable(variable) => variable.input.iter().collect(),
        ObjectKind::InOutVariable(variable) => variable.input.iter().collect(),
        ObjectKind::Connector(connector) => connector.input.iter().collect(),
        ObjectKind::Contact(contact) => contact.input.iter().collect(),
        ObjectKind::Coil(coil) => coil.input.iter().collect(),
        ObjectKind::RightPowerRail(rail) => rail.inputs.iter().collect(),
        _ => Vec::new(),
    }
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
