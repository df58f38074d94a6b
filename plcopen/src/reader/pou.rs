//! POUs, interfaces, variables, data types and values.

use super::body::read_body;
use super::context::{Context, Node, Read, child, children_named, elements};
use crate::data_type::{DataType, DataTypeDecl, Dimension, EnumValue, Value, ValueItem};
use crate::error::ReadErrorKind;
use crate::interface::{Interface, VarList, VarListKind, Variable};
use crate::pou::{Action, Method, Pou, PouLocation, PouType, Transition};

/// Reads a `pou` element.
pub(super) fn read_pou(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
    location: PouLocation,
) -> Read<Pou> {
    let name = context.required(node, "name")?.to_owned();
    let pou_type = context.required_parsed(
        node,
        "pouType",
        "function, functionBlock or program",
        |text| match text {
            "function" => Some(PouType::Function),
            "functionBlock" => Some(PouType::FunctionBlock),
            "program" => Some(PouType::Program),
            _ => None,
        },
    )?;
    let mut pou = Pou {
        name,
        pou_type,
        global_id: context.optional(node, "globalId"),
        interface: None,
        actions: Vec::new(),
        transitions: Vec::new(),
        bodies: Vec::new(),
        methods: Vec::new(),
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        location,
        line: context.line(node),
        column: context.line_column(node).1,
    };
    for element in elements(node) {
        match element.tag_name().name() {
            "interface" => pou.interface = Some(read_interface(context, element)?),
            "actions" => {
                context.only_children(element, &["action"], "actions, which holds only action")?;
                for action in children_named(element, "action") {
                    pou.actions.push(Action {
                        name: context.required(action, "name")?.to_owned(),
                        global_id: context.optional(action, "globalId"),
                        body: read_body(context, context.required_child(action, "body")?)?,
                        add_data: context.add_data(action)?,
                        documentation: context.documentation(action),
                    });
                }
            }
            "transitions" => {
                context.only_children(
                    element,
                    &["transition"],
                    "transitions, which holds only transition",
                )?;
                for transition in children_named(element, "transition") {
                    pou.transitions.push(Transition {
                        name: context.required(transition, "name")?.to_owned(),
                        global_id: context.optional(transition, "globalId"),
                        body: read_body(context, context.required_child(transition, "body")?)?,
                        add_data: context.add_data(transition)?,
                        documentation: context.documentation(transition),
                    });
                }
            }
            "body" => pou.bodies.push(read_body(context, element)?),
            "addData" => pou.methods = read_methods(context, element)?,
            "documentation" => {}
            _ => return Err(context.unexpected(element, "pou")),
        }
    }
    Ok(pou)
}

/// CODESYS methods: `addData/data[…/method]/Method`.
fn read_methods(context: &Context<'_, '_>, add_data: Node<'_, '_>) -> Read<Vec<Method>> {
    let mut methods = Vec::new();
    for data in children_named(add_data, "data") {
        let is_method = data
            .attribute("name")
            .is_some_and(|name| name.ends_with("/method"));
        if !is_method {
            continue;
        }
        for method in children_named(data, "Method") {
            let mut bodies = Vec::new();
            for body in children_named(method, "body") {
                bodies.push(read_body(context, body)?);
            }
            methods.push(Method {
                name: context.required(method, "name")?.to_owned(),
                object_id: context.optional(method, "ObjectId"),
                interface: child(method, "interface")
                    .map(|interface| read_interface(context, interface))
                    .transpose()?,
                bodies,
                add_data: context.add_data(method)?,
                documentation: context.documentation(method),
            });
        }
    }
    Ok(methods)
}

/// Reads an `interface` element.
pub(super) fn read_interface(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<Interface> {
    let mut interface = Interface {
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        ..Interface::default()
    };
    for element in elements(node) {
        let name = element.tag_name().name();
        if name == "returnType" {
            interface.return_type = Some(read_type_holder(context, element)?);
        } else if VarListKind::from_element(name).is_some() {
            interface.var_lists.push(read_var_list(context, element)?);
        } else if name != "addData" && name != "documentation" {
            return Err(context.unexpected(element, "interface"));
        }
    }
    Ok(interface)
}

/// Reads a variable list (`localVars`, `globalVars`, …) by its element name.
pub(super) fn read_var_list(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<VarList> {
    let Some(kind) = VarListKind::from_element(node.tag_name().name()) else {
        return Err(context.unexpected(node, "a list of variables"));
    };
    Ok(VarList {
        kind,
        name: context.optional(node, "name"),
        constant: context.optional_bool(node, "constant")?.unwrap_or(false),
        retain: context.optional_bool(node, "retain")?.unwrap_or(false),
        nonretain: context.optional_bool(node, "nonretain")?.unwrap_or(false),
        persistent: context.optional_bool(node, "persistent")?.unwrap_or(false),
        nonpersistent: context
            .optional_bool(node, "nonpersistent")?
            .unwrap_or(false),
        variables: read_variables(context, node)?,
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        line: context.line(node),
        column: context.line_column(node).1,
    })
}

fn read_variables(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<Vec<Variable>> {
    context.only_children(node, &["variable"], "a list of variables")?;
    let mut variables = Vec::new();
    for variable in children_named(node, "variable") {
        context.only_children(variable, &["type", "initialValue"], "a variable")?;
        variables.push(Variable {
            name: context.required(variable, "name")?.to_owned(),
            address: context.optional(variable, "address"),
            global_id: context.optional(variable, "globalId"),
            data_type: read_type_holder(context, context.required_child(variable, "type")?)?,
            initial_value: child(variable, "initialValue")
                .map(|value| read_value_holder(context, value))
                .transpose()?,
            add_data: context.add_data(variable)?,
            documentation: context.documentation(variable),
            line: context.line(variable),
            column: context.line_column(variable).1,
        });
    }
    Ok(variables)
}

/// Reads a `dataType` element of `types/dataTypes`.
pub(super) fn read_data_type_decl(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
) -> Read<DataTypeDecl> {
    context.only_children(node, &["baseType", "initialValue"], "a dataType")?;
    Ok(DataTypeDecl {
        name: context.required(node, "name")?.to_owned(),
        base_type: read_type_holder(context, context.required_child(node, "baseType")?)?,
        initial_value: child(node, "initialValue")
            .map(|value| read_value_holder(context, value))
            .transpose()?,
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        line: context.line(node),
        column: context.line_column(node).1,
    })
}

/// Reads an element that holds one type (`type`, `baseType`, `returnType`).
pub(super) fn read_type_holder(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<DataType> {
    let mut types = elements(node).filter(|element| {
        let name = element.tag_name().name();
        name != "addData" && name != "documentation"
    });
    let Some(type_node) = types.next() else {
        return Err(context.error(node, ReadErrorKind::MissingElement { element: "a type" }));
    };
    if let Some(extra) = types.next() {
        return Err(context.unexpected(extra, "an element that holds one type"));
    }
    read_type(context, type_node)
}

/// The elementary and generic type elements of the schema, and CODESYS's additions.
const ELEMENTARY_TYPES: &[&str] = &[
    "BOOL",
    "BYTE",
    "WORD",
    "DWORD",
    "LWORD",
    "SINT",
    "INT",
    "DINT",
    "LINT",
    "USINT",
    "UINT",
    "UDINT",
    "ULINT",
    "REAL",
    "LREAL",
    "TIME",
    "DATE",
    "DT",
    "TOD",
    "LTIME",
    "LDATE",
    "LDT",
    "LTOD",
    "CHAR",
    "WCHAR",
    "ANY",
    "ANY_DERIVED",
    "ANY_ELEMENTARY",
    "ANY_MAGNITUDE",
    "ANY_NUM",
    "ANY_REAL",
    "ANY_INT",
    "ANY_BIT",
    "ANY_STRING",
    "ANY_DATE",
];

/// Reads one type element.
fn read_type(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<DataType> {
    let name = node.tag_name().name();
    if let Some(elementary) = ELEMENTARY_TYPES.iter().find(|known| **known == name) {
        return Ok(DataType::Elementary((*elementary).to_owned()));
    }
    let base = |context: &Context<'_, '_>| -> Read<Box<DataType>> {
        Ok(Box::new(read_type_holder(
            context,
            context.required_child(node, "baseType")?,
        )?))
    };
    Ok(match name {
        "string" | "wstring" => DataType::String {
            wide: name == "wstring",
            length: context.optional(node, "length"),
        },
        "array" => {
            let mut dimensions = Vec::new();
            for dimension in children_named(node, "dimension") {
                dimensions.push(Dimension {
                    lower: context.required(dimension, "lower")?.to_owned(),
                    upper: context.required(dimension, "upper")?.to_owned(),
                });
            }
            if dimensions.is_empty() {
                return Err(context.error(
                    node,
                    ReadErrorKind::MissingElement {
                        element: "dimension",
                    },
                ));
            }
            DataType::Array {
                dimensions,
                base: base(context)?,
            }
        }
        "derived" => DataType::Derived {
            name: context.required(node, "name")?.to_owned(),
        },
        "enum" => {
            let values_node = context.required_child(node, "values")?;
            let mut values = Vec::new();
            for value in children_named(values_node, "value") {
                values.push(EnumValue {
                    name: context.required(value, "name")?.to_owned(),
                    value: context.optional(value, "value"),
                });
            }
            DataType::Enum {
                values,
                base: child(node, "baseType")
                    .map(|base_node| read_type_holder(context, base_node).map(Box::new))
                    .transpose()?,
            }
        }
        "struct" => DataType::Struct {
            members: read_variables(context, node)?,
        },
        "subrangeSigned" | "subrangeUnsigned" => {
            let range = context.required_child(node, "range")?;
            DataType::Subrange {
                signed: name == "subrangeSigned",
                lower: context.required(range, "lower")?.to_owned(),
                upper: context.required(range, "upper")?.to_owned(),
                base: base(context)?,
            }
        }
        "pointer" => DataType::Pointer {
            base: base(context)?,
        },
        _ => return Err(context.unexpected(node, "a type")),
    })
}

/// Reads an element that holds one value (`initialValue`, an array or structure element).
pub(super) fn read_value_holder(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<Value> {
    let Some(value_node) = elements(node).find(|element| {
        let name = element.tag_name().name();
        name != "addData" && name != "documentation"
    }) else {
        return Err(context.error(node, ReadErrorKind::MissingElement { element: "a value" }));
    };
    match value_node.tag_name().name() {
        "simpleValue" => Ok(Value::Simple(
            context.optional(value_node, "value").unwrap_or_default(),
        )),
        "arrayValue" => Ok(Value::Array(read_value_items(
            context,
            value_node,
            "repetitionValue",
        )?)),
        "structValue" => Ok(Value::Struct(read_value_items(
            context, value_node, "member",
        )?)),
        _ => Err(context.unexpected(value_node, "a value")),
    }
}

fn read_value_items(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
    key: &str,
) -> Read<Vec<ValueItem>> {
    let mut items = Vec::new();
    for item in children_named(node, "value") {
        items.push(ValueItem {
            key: context.optional(item, key),
            value: read_value_holder(context, item)?,
        });
    }
    Ok(items)
}
