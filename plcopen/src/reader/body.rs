//! Bodies and the objects of graphical bodies.

use super::checks::check_body;
use super::context::{Context, Node, Read, child, children_named, elements};
use crate::body::{Body, BodyContent};
use crate::body_object::{BodyObject, ObjectKind, Size};
use crate::connection::{Connection, ConnectionPointIn, ConnectionPointOut};
use crate::document::Dialect;
use crate::error::ReadErrorKind;
use crate::fbd::{
    Block, BlockPin, Connector, Continuation, InOutVariable, InVariable, Jump, Label, OutVariable,
    Return, VendorElement,
};
use crate::ld::{Coil, Contact, Edge, LeftPowerRail, RightPowerRail, Storage};
use crate::sfc::{
    ActionBlock, ActionBlockAction, ActionContent, Condition, ConditionForm, Convergence,
    Divergence, JumpStep, MacroStep, Qualifier, SfcTransition, Step,
};

/// Reads a `body` (or an element of type body: `inline`), its language and CODESYS's CFC.
pub(super) fn read_body(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<Body> {
    let mut content = None;
    for element in elements(node) {
        let language = element.tag_name().name();
        let read = match language {
            "ST" => BodyContent::St(context.formatted_text(element)),
            "IL" => BodyContent::Il(context.formatted_text(element)),
            "FBD" => BodyContent::Fbd(read_objects(context, element)?),
            "LD" => BodyContent::Ld(read_objects(context, element)?),
            "SFC" => BodyContent::Sfc(read_objects(context, element)?),
            "addData" | "documentation" => continue,
            _ => return Err(context.unexpected(element, "a body (ST, IL, FBD, LD or SFC)")),
        };
        if content.is_some() {
            return Err(context.unexpected(element, "a body that already has its language"));
        }
        content = Some(read);
    }
    let Some(content) = content else {
        return Err(context.error(
            node,
            ReadErrorKind::MissingElement {
                element: "ST, IL, FBD, LD or SFC",
            },
        ));
    };
    let mut cfc = None;
    if let Some(add_data) = child(node, "addData") {
        for data in children_named(add_data, "data") {
            let is_cfc = data
                .attribute("name")
                .is_some_and(|name| name.ends_with("/cfc"));
            if let Some(chart) = child(data, "CFC").filter(|_| is_cfc) {
                cfc = Some(read_objects(context, chart)?);
            }
        }
    }
    Ok(Body {
        worksheet_name: context.optional(node, "WorksheetName"),
        global_id: context.optional(node, "globalId"),
        content,
        cfc,
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        line: context.line(node),
    })
}

/// Reads the objects of a graphical body in document order and checks their ids and links.
fn read_objects(context: &Context<'_, '_>, language: Node<'_, '_>) -> Read<Vec<BodyObject>> {
    let mut objects = Vec::new();
    for element in elements(language) {
        objects.push(read_object(context, element)?);
    }
    check_body(context, language, &objects)?;
    Ok(objects)
}

fn read_object(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<BodyObject> {
    let kind = read_kind(context, node)?;
    let (line, column) = context.line_column(node);
    Ok(BodyObject {
        local_id: context.required_u64(node, "localId")?,
        execution_order_id: context.optional_u64(node, "executionOrderId")?,
        global_id: context.optional(node, "globalId"),
        position: context.child_point(node, "position")?,
        size: Size {
            width: context.optional_decimal(node, "width")?,
            height: context.optional_decimal(node, "height")?,
        },
        kind,
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        line,
        column,
    })
}

/// The children each object may have besides `position`, `addData` and `documentation`; `None`
/// for an element that is no body object.
fn allowed_children(element: &str) -> Option<&'static [&'static str]> {
    const IN: &str = "connectionPointIn";
    const OUT: &str = "connectionPointOut";
    const PINS: [&str; 3] = ["inputVariables", "inOutVariables", "outputVariables"];
    Some(match element {
        "block" => &PINS,
        "inVariable" => &[OUT, "expression"],
        "outVariable" => &[IN, "expression"],
        "inOutVariable" => &[IN, OUT, "expression"],
        "jump" | "return" | "connector" | "rightPowerRail" | "jumpStep" => &[IN],
        "continuation" | "leftPowerRail" => &[OUT],
        "comment" | "error" => &["content"],
        "vendorElement" => &["alternativeText", PINS[0], PINS[1], PINS[2]],
        "contact" | "coil" => &[IN, OUT, "variable"],
        "step" => &[IN, OUT, "connectionPointOutAction"],
        "macroStep" => &[IN, OUT, "body"],
        "transition" => &[IN, OUT, "condition"],
        "selectionDivergence"
        | "selectionConvergence"
        | "simultaneousDivergence"
        | "simultaneousConvergence" => &[IN, OUT],
        "actionBlock" => &[IN, "action"],
        "label" => &[],
        _ => return None,
    })
}

fn read_kind(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<ObjectKind> {
    if let Some(allowed) = allowed_children(node.tag_name().name()) {
        let mut allowed_here = vec!["position"];
        allowed_here.extend_from_slice(allowed);
        context.only_children(node, &allowed_here, "this kind of body object")?;
    }
    let input = || point_in(context, node, "connectionPointIn");
    let output = || point_out(context, node, "connectionPointOut");
    let expression =
        || -> Read<String> { Ok(context.simple_text(context.required_child(node, "expression")?)) };
    let negated = |name| context.optional_bool(node, name);
    let edge = |name| context.optional_parsed(node, name, "none, rising or falling", Edge::parse);
    let storage = |name| context.optional_parsed(node, name, "none, set or reset", Storage::parse);
    Ok(match node.tag_name().name() {
        "block" => {
            let (inputs, in_outs, outputs) = pins(context, node)?;
            ObjectKind::Block(Block {
                type_name: context.required(node, "typeName")?.to_owned(),
                instance_name: context.optional(node, "instanceName"),
                inputs,
                in_outs,
                outputs,
            })
        }
        "inVariable" => ObjectKind::InVariable(InVariable {
            expression: expression()?,
            negated: negated("negated")?,
            edge: edge("edge")?,
            storage: storage("storage")?,
            output: output()?,
        }),
        "outVariable" => ObjectKind::OutVariable(OutVariable {
            expression: expression()?,
            negated: negated("negated")?,
            edge: edge("edge")?,
            storage: storage("storage")?,
            input: input()?,
        }),
        "inOutVariable" => ObjectKind::InOutVariable(InOutVariable {
            expression: expression()?,
            negated_in: negated("negatedIn")?,
            edge_in: edge("edgeIn")?,
            storage_in: storage("storageIn")?,
            negated_out: negated("negatedOut")?,
            edge_out: edge("edgeOut")?,
            storage_out: storage("storageOut")?,
            input: input()?,
            output: output()?,
        }),
        "label" => ObjectKind::Label(Label {
            label: context.required(node, "label")?.to_owned(),
        }),
        "jump" => ObjectKind::Jump(Jump {
            label: context.required(node, "label")?.to_owned(),
            input: input()?,
        }),
        "return" => ObjectKind::Return(Return { input: input()? }),
        "connector" => ObjectKind::Connector(Connector {
            name: context.required(node, "name")?.to_owned(),
            input: input()?,
        }),
        "continuation" => ObjectKind::Continuation(Continuation {
            name: context.required(node, "name")?.to_owned(),
            output: output()?,
        }),
        "comment" => {
            ObjectKind::Comment(context.formatted_text(context.required_child(node, "content")?))
        }
        "error" => {
            ObjectKind::Error(context.formatted_text(context.required_child(node, "content")?))
        }
        "vendorElement" => {
            let (inputs, in_outs, outputs) = pins(context, node)?;
            ObjectKind::VendorElement(VendorElement {
                alternative_text: context
                    .formatted_text(context.required_child(node, "alternativeText")?),
                inputs,
                in_outs,
                outputs,
            })
        }
        "leftPowerRail" => ObjectKind::LeftPowerRail(LeftPowerRail {
            outputs: children_named(node, "connectionPointOut")
                .map(|point| read_point_out(context, point))
                .collect::<Read<_>>()?,
        }),
        "rightPowerRail" => ObjectKind::RightPowerRail(RightPowerRail {
            inputs: children_named(node, "connectionPointIn")
                .map(|point| read_point_in(context, point))
                .collect::<Read<_>>()?,
        }),
        "contact" | "coil" => {
            let variable = context.simple_text(context.required_child(node, "variable")?);
            let (negated, edge, storage) =
                (negated("negated")?, edge("edge")?, storage("storage")?);
            let (input, output) = (input()?, output()?);
            if node.tag_name().name() == "contact" {
                ObjectKind::Contact(Contact {
                    variable,
                    negated,
                    edge,
                    storage,
                    input,
                    output,
                })
            } else {
                ObjectKind::Coil(Coil {
                    variable,
                    negated,
                    edge,
                    storage,
                    input,
                    output,
                })
            }
        }
        "step" => ObjectKind::Step(Step {
            name: context.required(node, "name")?.to_owned(),
            initial: context.optional_bool(node, "initialStep")?.unwrap_or(false),
            negated: negated("negated")?,
            input: input()?,
            output: output()?,
            action_output: point_out(context, node, "connectionPointOutAction")?,
        }),
        "macroStep" => ObjectKind::MacroStep(MacroStep {
            name: context.optional(node, "name"),
            body: child(node, "body")
                .map(|body| read_body(context, body).map(Box::new))
                .transpose()?,
            input: input()?,
            output: output()?,
        }),
        "jumpStep" => ObjectKind::JumpStep(JumpStep {
            target_name: context.required(node, "targetName")?.to_owned(),
            input: input()?,
        }),
        "transition" => ObjectKind::Transition(SfcTransition {
            priority: context.optional_parsed(node, "priority", "an unsigned integer", |text| {
                text.parse().ok()
            })?,
            condition: child(node, "condition")
                .map(|condition| read_condition(context, condition))
                .transpose()?,
            input: input()?,
            output: output()?,
        }),
        "selectionDivergence" | "simultaneousDivergence" => {
            let divergence = Divergence {
                name: context.optional(node, "name"),
                input: input()?,
                outputs: children_named(node, "connectionPointOut")
                    .map(|point| read_point_out(context, point))
                    .collect::<Read<_>>()?,
            };
            if node.tag_name().name() == "selectionDivergence" {
                ObjectKind::SelectionDivergence(divergence)
            } else {
                ObjectKind::SimultaneousDivergence(divergence)
            }
        }
        "selectionConvergence" | "simultaneousConvergence" => {
            let convergence = Convergence {
                inputs: children_named(node, "connectionPointIn")
                    .map(|point| read_point_in(context, point))
                    .collect::<Read<_>>()?,
                output: output()?,
            };
            if node.tag_name().name() == "selectionConvergence" {
                ObjectKind::SelectionConvergence(convergence)
            } else {
                ObjectKind::SimultaneousConvergence(convergence)
            }
        }
        "actionBlock" => ObjectKind::ActionBlock(ActionBlock {
            negated: negated("negated")?,
            input: input()?,
            actions: children_named(node, "action")
                .map(|action| read_action(context, action))
                .collect::<Read<_>>()?,
        }),
        _ => {
            return Err(context.unexpected(node, "a graphical body (FBD, LD, SFC or CFC objects)"));
        }
    })
}

/// The input, in-out and output pins of a block or vendor element.
fn pins(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
) -> Read<(Vec<BlockPin>, Vec<BlockPin>, Vec<BlockPin>)> {
    let list = |name: &str| -> Read<Vec<BlockPin>> {
        let Some(container) = child(node, name) else {
            return Ok(Vec::new());
        };
        children_named(container, "variable")
            .map(|pin| read_pin(context, pin))
            .collect()
    };
    Ok((
        list("inputVariables")?,
        list("inOutVariables")?,
        list("outputVariables")?,
    ))
}

fn read_pin(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<BlockPin> {
    context.only_children(node, &["connectionPointIn", "connectionPointOut"], "a pin")?;
    Ok(BlockPin {
        formal_parameter: context.required(node, "formalParameter")?.to_owned(),
        negated: context.optional_bool(node, "negated")?,
        edge: context.optional_parsed(node, "edge", "none, rising or falling", Edge::parse)?,
        storage: context.optional_parsed(node, "storage", "none, set or reset", Storage::parse)?,
        hidden: context.optional_bool(node, "hidden")?,
        input: point_in(context, node, "connectionPointIn")?,
        output: point_out(context, node, "connectionPointOut")?,
        documentation: context.documentation(node),
    })
}

fn point_in(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
    name: &str,
) -> Read<Option<ConnectionPointIn>> {
    child(node, name)
        .map(|point| read_point_in(context, point))
        .transpose()
}

fn point_out(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
    name: &str,
) -> Read<Option<ConnectionPointOut>> {
    child(node, name)
        .map(|point| read_point_out(context, point))
        .transpose()
}

/// Reads a `connectionPointIn` (or, for v1.0 conditions, any element holding `connection`s).
fn read_point_in(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<ConnectionPointIn> {
    if node.tag_name().name() == "connectionPointIn" {
        context.only_children(
            node,
            &["relPosition", "connection", "expression"],
            "a connectionPointIn",
        )?;
    }
    let mut connections = Vec::new();
    for connection in children_named(node, "connection") {
        let mut points = Vec::new();
        for point in children_named(connection, "position") {
            points.push(context.point(point)?);
        }
        connections.push(Connection {
            ref_local_id: context.required_u64(connection, "refLocalId")?,
            formal_parameter: context.optional(connection, "formalParameter"),
            global_id: context.optional(connection, "globalId"),
            points,
            add_data: context.add_data(connection)?,
        });
    }
    Ok(ConnectionPointIn {
        rel_position: context.child_point(node, "relPosition")?,
        connections,
        expression: child(node, "expression").map(|expression| context.simple_text(expression)),
        add_data: context.add_data(node)?,
    })
}

fn read_point_out(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<ConnectionPointOut> {
    context.only_children(node, &["relPosition", "expression"], "a connectionPointOut")?;
    Ok(ConnectionPointOut {
        rel_position: context.child_point(node, "relPosition")?,
        formal_parameter: context.optional(node, "formalParameter"),
        expression: child(node, "expression").map(|expression| context.simple_text(expression)),
        add_data: context.add_data(node)?,
    })
}

fn read_condition(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<Condition> {
    let negated = context.optional_bool(node, "negated")?;
    let form = if let Some(reference) = child(node, "reference") {
        ConditionForm::Reference(context.required(reference, "name")?.to_owned())
    } else if let Some(point) = child(node, "connectionPointIn") {
        ConditionForm::Connection(read_point_in(context, point)?)
    } else if let Some(inline) = child(node, "inline") {
        ConditionForm::Inline {
            name: context.optional(inline, "name"),
            body: Box::new(read_body(context, inline)?),
        }
    } else if child(node, "connection").is_some() {
        // v1.0 wrote the connections straight into the condition.
        ConditionForm::Connection(read_point_in(context, node)?)
    } else {
        return Err(context.error(
            node,
            ReadErrorKind::MissingElement {
                element: "reference, connectionPointIn or inline",
            },
        ));
    };
    Ok(Condition { negated, form })
}

fn read_action(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<ActionBlockAction> {
    // v1.0 actions have no localId; Beremiz gives them 0.
    let local_id = if context.dialect == Dialect::V10 {
        context.optional_u64(node, "localId")?.unwrap_or(0)
    } else {
        context.required_u64(node, "localId")?
    };
    let content = if let Some(reference) = child(node, "reference") {
        ActionContent::Reference(context.required(reference, "name")?.to_owned())
    } else if let Some(inline) = child(node, "inline") {
        ActionContent::Inline(Box::new(read_body(context, inline)?))
    } else {
        return Err(context.error(
            node,
            ReadErrorKind::MissingElement {
                element: "reference or inline",
            },
        ));
    };
    Ok(ActionBlockAction {
        local_id,
        execution_order_id: context.optional_u64(node, "executionOrderId")?,
        qualifier: context.optional_parsed(
            node,
            "qualifier",
            "an action qualifier (N, R, S, P, P0, P1, L, D, DS, DL, SD, SL)",
            Qualifier::parse,
        )?,
        duration: context.optional(node, "duration"),
        indicator: context.optional(node, "indicator"),
        rel_position: context.child_point(node, "relPosition")?,
        content,
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
    })
}
