//! The project element: headers, types, instances, and the XML comments outside `addData`.

use super::context::{Context, Node, Read, child, children_named, elements};
use super::pou::{read_data_type_decl, read_pou, read_var_list};
use super::upgrade;
use crate::data_type::Value;
use crate::document::{Dialect, Document, XmlComment};
use crate::header::{ContentHeader, CoordinateInfo, FileHeader};
use crate::instances::{
    AccessVariable, ConfigVariable, Configuration, PouInstance, Resource, Task,
};
use crate::pou::PouLocation;

/// Reads the root `project` element.
pub(super) fn read_project(context: &Context<'_, '_>, root: Node<'_, '_>) -> Read<Document> {
    for element in elements(root) {
        match element.tag_name().name() {
            "fileHeader" | "contentHeader" | "types" | "instances" | "addData"
            | "documentation" => {}
            _ => return Err(context.unexpected(element, "project")),
        }
    }
    let file_header = read_file_header(context, context.required_child(root, "fileHeader")?)?;
    let content_header =
        read_content_header(context, context.required_child(root, "contentHeader")?)?;
    let mut data_types = Vec::new();
    let mut pous = Vec::new();
    // v1.0 and v2.01 require `types`; an export with nothing in it is still a project, so a missing
    // `types` reads as empty rather than refusing the file.
    if let Some(types) = child(root, "types") {
        context.only_children(types, &["dataTypes", "pous"], "types")?;
        if let Some(list) = child(types, "dataTypes") {
            context.only_children(list, &["dataType"], "dataTypes, which holds only dataType")?;
            for data_type in children_named(list, "dataType") {
                data_types.push(read_data_type_decl(context, data_type)?);
            }
        }
        if let Some(list) = child(types, "pous") {
            context.only_children(list, &["pou"], "pous, which holds only pou")?;
            for pou in children_named(list, "pou") {
                pous.push(read_pou(context, pou, PouLocation::Types)?);
            }
        }
    }
    let mut configurations = Vec::new();
    if let Some(instances) = child(root, "instances") {
        context.only_children(instances, &["configurations"], "instances")?;
    }
    if let Some(instances) = child(root, "instances")
        && let Some(list) = child(instances, "configurations")
    {
        context.only_children(
            list,
            &["configuration"],
            "configurations, which holds only configuration",
        )?;
        for configuration in children_named(list, "configuration") {
            configurations.push(read_configuration(context, configuration, &mut pous)?);
        }
    }
    Ok(Document {
        file_name: context.file_name.to_owned(),
        dialect: context.dialect,
        file_header,
        content_header,
        data_types,
        pous,
        configurations,
        add_data: context.add_data(root)?,
        documentation: context.documentation(root),
        xml_comments: xml_comments(context, root),
    })
}

fn read_file_header(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<FileHeader> {
    Ok(FileHeader {
        company_name: context.required(node, "companyName")?.to_owned(),
        company_url: context.optional(node, "companyURL"),
        product_name: context.required(node, "productName")?.to_owned(),
        product_version: context.required(node, "productVersion")?.to_owned(),
        product_release: context.optional(node, "productRelease"),
        creation_date_time: context.required(node, "creationDateTime")?.to_owned(),
        content_description: context.optional(node, "contentDescription"),
    })
}

fn read_content_header(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<ContentHeader> {
    context.only_children(
        node,
        &["Comment", "coordinateInfo", "addDataInfo"],
        "contentHeader",
    )?;
    let coordinates = context.required_child(node, "coordinateInfo")?;
    let scaling = |language: &'static str| -> Read<_> {
        let language_node = context.required_child(coordinates, language)?;
        context.point(context.required_child(language_node, "scaling")?)
    };
    Ok(ContentHeader {
        name: context.required(node, "name")?.to_owned(),
        version: context.optional(node, "version"),
        modification_date_time: context.optional(node, "modificationDateTime"),
        organization: context.optional(node, "organization"),
        author: context.optional(node, "author"),
        language: context.optional(node, "language"),
        comment: child(node, "Comment").map(|comment| context.simple_text(comment)),
        coordinate_info: CoordinateInfo {
            page_size: context.child_point(coordinates, "pageSize")?,
            fbd_scaling: scaling("fbd")?,
            ld_scaling: scaling("ld")?,
            sfc_scaling: scaling("sfc")?,
        },
        add_data_info: child(node, "addDataInfo").map(|info| context.source(info).to_owned()),
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
    })
}

fn read_configuration(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
    pous: &mut Vec<crate::pou::Pou>,
) -> Read<Configuration> {
    let name = context.required(node, "name")?.to_owned();
    let mut configuration = Configuration {
        name: name.clone(),
        global_id: context.optional(node, "globalId"),
        resources: Vec::new(),
        global_vars: Vec::new(),
        access_vars: Vec::new(),
        config_vars: Vec::new(),
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        line: context.line(node),
        column: context.line_column(node).1,
    };
    for element in elements(node) {
        match element.tag_name().name() {
            "resource" => configuration
                .resources
                .push(read_resource(context, element, &name, pous)?),
            "globalVars" => configuration
                .global_vars
                .push(read_var_list(context, element)?),
            "accessVars" => {
                context.only_children(
                    element,
                    &["accessVariable"],
                    "accessVars, which holds only accessVariable",
                )?;
                for variable in children_named(element, "accessVariable") {
                    configuration.access_vars.push(AccessVariable {
                        alias: context.required(variable, "alias")?.to_owned(),
                        instance_path_and_name: context
                            .required(variable, "instancePathAndName")?
                            .to_owned(),
                        direction: context.optional(variable, "direction"),
                        data_type: optional_type(context, variable)?,
                    });
                }
            }
            "configVars" => {
                context.only_children(
                    element,
                    &["configVariable"],
                    "configVars, which holds only configVariable",
                )?;
                for variable in children_named(element, "configVariable") {
                    configuration.config_vars.push(ConfigVariable {
                        instance_path_and_name: context
                            .required(variable, "instancePathAndName")?
                            .to_owned(),
                        address: context.optional(variable, "address"),
                        data_type: optional_type(context, variable)?,
                        initial_value: optional_value(context, variable)?,
                    });
                }
            }
            "addData" | "documentation" => {}
            _ => return Err(context.unexpected(element, "configuration")),
        }
    }
    Ok(configuration)
}

fn optional_type(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
) -> Read<Option<crate::data_type::DataType>> {
    child(node, "type")
        .map(|data_type| super::pou::read_type_holder(context, data_type))
        .transpose()
}

fn optional_value(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<Option<Value>> {
    child(node, "initialValue")
        .map(|value| super::pou::read_value_holder(context, value))
        .transpose()
}

fn read_resource(
    context: &Context<'_, '_>,
    node: Node<'_, '_>,
    configuration: &str,
    pous: &mut Vec<crate::pou::Pou>,
) -> Read<Resource> {
    let name = context.required(node, "name")?.to_owned();
    let mut resource = Resource {
        name: name.clone(),
        global_id: context.optional(node, "globalId"),
        tasks: Vec::new(),
        global_vars: Vec::new(),
        pou_instances: Vec::new(),
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        line: context.line(node),
        column: context.line_column(node).1,
    };
    for element in elements(node) {
        match element.tag_name().name() {
            "task" => resource.tasks.push(read_task(context, element)?),
            "globalVars" => resource.global_vars.push(read_var_list(context, element)?),
            "pouInstance" => resource
                .pou_instances
                .push(read_pou_instance(context, element)?),
            "addData" | "documentation" => {}
            _ => return Err(context.unexpected(element, "resource")),
        }
    }
    // CODESYS writes the application's POUs in the resource's addData.
    if let Some(add_data) = child(node, "addData") {
        for data in children_named(add_data, "data") {
            let is_pou = data
                .attribute("name")
                .is_some_and(|data_name| data_name.ends_with("/pou"));
            if !is_pou {
                continue;
            }
            for pou in children_named(data, "pou") {
                let location = PouLocation::Resource {
                    configuration: configuration.to_owned(),
                    resource: name.clone(),
                };
                pous.push(read_pou(context, pou, location)?);
            }
        }
    }
    Ok(resource)
}

fn read_task(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<Task> {
    context.only_children(node, &["pouInstance"], "a task")?;
    let priority =
        context.required_parsed(node, "priority", "an integer from 0 to 65535", |text| {
            text.parse::<u16>().ok().map(u32::from)
        })?;
    let interval = match (context.dialect, node.attribute("interval")) {
        (Dialect::V10, Some(written)) => Some(upgrade::interval_v10(written).ok_or_else(|| {
            context.attribute_error(
                node,
                "interval",
                crate::error::ReadErrorKind::BadAttribute {
                    attribute: "interval",
                    value: written.to_owned(),
                    expected: "a v1.0 duration such as 00:00:00.100000",
                },
            )
        })?),
        (_, written) => written.map(str::to_owned),
    };
    let mut pou_instances = Vec::new();
    for instance in children_named(node, "pouInstance") {
        pou_instances.push(read_pou_instance(context, instance)?);
    }
    Ok(Task {
        name: context.required(node, "name")?.to_owned(),
        priority,
        interval,
        single: context.optional(node, "single"),
        global_id: context.optional(node, "globalId"),
        pou_instances,
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
        line: context.line(node),
        column: context.line_column(node).1,
    })
}

fn read_pou_instance(context: &Context<'_, '_>, node: Node<'_, '_>) -> Read<PouInstance> {
    // v1.0 named the attribute `type`.
    let type_attribute = if context.dialect == Dialect::V10 && node.attribute("typeName").is_none()
    {
        "type"
    } else {
        "typeName"
    };
    Ok(PouInstance {
        name: context.required(node, "name")?.to_owned(),
        type_name: context.required(node, type_attribute)?.to_owned(),
        global_id: context.optional(node, "globalId"),
        add_data: context.add_data(node)?,
        documentation: context.documentation(node),
    })
}

/// Every XML comment outside `addData`, with the path of its parent and its place among the
/// parent's elements.
fn xml_comments(context: &Context<'_, '_>, root: Node<'_, '_>) -> Vec<XmlComment> {
    let mut comments = Vec::new();
    let mut pending = vec![root];
    while let Some(node) = pending.pop() {
        let mut elements_before = 0;
        for node_child in node.children() {
            if node_child.is_comment() {
                comments.push(XmlComment {
                    text: node_child.text().unwrap_or("").to_owned(),
                    parent_path: super::context::element_path(node),
                    elements_before,
                    line: context.line(node_child),
                });
            } else if node_child.is_element() {
                elements_before += 1;
                if node_child.tag_name().name() != "addData" {
                    pending.push(node_child);
                }
            }
        }
    }
    comments.sort_by_key(|comment| comment.line);
    comments
}
