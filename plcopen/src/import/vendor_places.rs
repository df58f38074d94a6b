//! Where another tool's `addData` entry stood, as the place `project_model::VendorEntry` names
//! (`docs/plcopen-xml.md` §2.6), worked out from the element path the import reports.

use project_model::ElementId;

use crate::body_object::{BodyObject, ObjectKind};

/// The place of an entry found in the element at `path`. Entries of elements the export does
/// not write an `addData` for (a variable list, a structure's member, a method, a program
/// instance) go to the nearest element it does: the interface, the data type, the POU, the task.
pub(super) fn vendor_place(path: &str) -> String {
    if let Some((name, rest)) = after_named(path, "pou") {
        let pou = format!("pou:{name}");
        if rest.is_empty() || rest.contains("/Method[") || rest.contains("/addData/") {
            return pou;
        }
        if rest == "/body" {
            return format!("{pou}/body");
        }
        if let Some((variable, _)) = after_named(rest, "variable")
            && rest.starts_with("/interface/")
        {
            return format!("{pou}/variable:{variable}");
        }
        if rest.starts_with("/interface") {
            return format!("{pou}/interface");
        }
        if let Some((action, "")) = after_named(rest, "action") {
            return format!("{pou}/action:{action}");
        }
        if let Some((transition, "")) = after_named(rest, "transition") {
            return format!("{pou}/transition:{transition}");
        }
        return pou;
    }
    if let Some((name, _)) = after_named(path, "dataType") {
        return format!("type:{name}");
    }
    if let Some((list, rest)) = after_named(path, "globalVars") {
        return list_place(list, rest);
    }
    if let Some(at) = path.find("/globalVars/") {
        // An unnamed list is converted into a list named after its configuration or resource.
        let owner = path[..at]
            .rsplit("[@name='")
            .next()
            .and_then(|tail| tail.strip_suffix("']"))
            .unwrap_or("");
        return list_place(owner, &path[at + "/globalVars".len()..]);
    }
    if let Some((name, _)) = after_named(path, "task") {
        return format!("task:{name}");
    }
    if after_named(path, "resource").is_some() {
        return "resource".to_owned();
    }
    if after_named(path, "configuration").is_some() {
        return "configuration".to_owned();
    }
    if path.ends_with("/contentHeader") {
        return "contentHeader".to_owned();
    }
    "project".to_owned()
}

/// The place of an entry of the object that became element `id` of the body at `body_path`
/// (`pou:Main/body/element:7`), where the export writes that body's elements with their ids as
/// `localId`s and so can put the entry back: a POU's own LD or FBD body. `None` for the bodies
/// of actions, transitions and methods, whose vendor data goes to their POU.
pub(super) fn element_place(body_path: &str, id: ElementId) -> Option<String> {
    let body = vendor_place(body_path);
    body.ends_with("/body")
        .then(|| format!("{body}/element:{}", id.0))
}

/// The signature (`project_model::element_signature`) of the element an object of Rivet's own
/// export stands for, so that an object another tool renumbered or added is not taken for the
/// element whose id it carries (§5.5); `None` for objects that stand for no one element.
pub(super) fn object_signature(object: &BodyObject) -> Option<String> {
    Some(match &object.kind {
        ObjectKind::Block(block) => {
            let has_en = block
                .inputs
                .first()
                .is_some_and(|pin| pin.formal_parameter.eq_ignore_ascii_case("EN"));
            if has_en {
                format!("block {} EN", block.type_name)
            } else {
                format!("block {}", block.type_name)
            }
        }
        ObjectKind::InVariable(variable) => format!("operand {}", variable.expression.trim()),
        ObjectKind::Contact(contact) => format!("operand {}", contact.variable.trim()),
        ObjectKind::OutVariable(variable) => format!("coil {}", variable.expression.trim()),
        ObjectKind::Coil(coil) => format!("coil {}", coil.variable.trim()),
        ObjectKind::Jump(jump) => format!("jump {}", jump.label),
        ObjectKind::Return(_) => "return".to_owned(),
        _ => return None,
    })
}

/// The place in a global variable list: the list, or one of its variables.
fn list_place(list: &str, rest: &str) -> String {
    match after_named(rest, "variable") {
        Some((variable, "")) => format!("gvl:{list}/variable:{variable}"),
        _ => format!("gvl:{list}"),
    }
}

/// The name of the last `element[@name='…']` in `path` and what follows it.
fn after_named<'p>(path: &'p str, element: &str) -> Option<(&'p str, &'p str)> {
    let marker = format!("{element}[@name='");
    let start = path.rfind(&marker)? + marker.len();
    // The marker must start a path segment (`pou[`, not `xpou[`).
    let segment_start = start - marker.len();
    if segment_start > 0 && !path[..segment_start].ends_with('/') {
        return None;
    }
    let end = start + path[start..].find("']")?;
    Some((&path[start..end], &path[end + 2..]))
}

#[cfg(test)]
mod tests {
    use project_model::ElementId;

    use super::{element_place, vendor_place};

    #[test]
    fn places_name_the_object_and_the_element_below_it() {
        let pou = "project/types/pous/pou[@name='Main']";
        assert_eq!(vendor_place(pou), "pou:Main");
        assert_eq!(vendor_place(&format!("{pou}/body")), "pou:Main/body");
        assert_eq!(
            vendor_place(&format!("{pou}/interface")),
            "pou:Main/interface"
        );
        assert_eq!(
            vendor_place(&format!("{pou}/interface/localVars")),
            "pou:Main/interface"
        );
        assert_eq!(
            vendor_place(&format!("{pou}/interface/localVars/variable[@name='x']")),
            "pou:Main/variable:x"
        );
        assert_eq!(
            vendor_place(&format!("{pou}/actions/action[@name='A']")),
            "pou:Main/action:A"
        );
        assert_eq!(
            vendor_place(&format!(
                "{pou}/addData/data[@name='http://www.3s-software.com/plcopenxml/method']/Method[@name='M']"
            )),
            "pou:Main"
        );
        assert_eq!(
            vendor_place(
                "project/types/dataTypes/dataType[@name='T']/baseType/struct/variable[@name='m']"
            ),
            "type:T"
        );
        let resource =
            "project/instances/configurations/configuration[@name='c']/resource[@name='r']";
        assert_eq!(vendor_place(resource), "resource");
        assert_eq!(
            vendor_place(&format!(
                "{resource}/task[@name='t']/pouInstance[@name='i']"
            )),
            "task:t"
        );
        assert_eq!(
            vendor_place(&format!(
                "{resource}/globalVars[@name='G']/variable[@name='v']"
            )),
            "gvl:G/variable:v"
        );
        assert_eq!(
            vendor_place(&format!("{resource}/globalVars/variable[@name='v']")),
            "gvl:r/variable:v"
        );
        assert_eq!(vendor_place("project/contentHeader"), "contentHeader");
        assert_eq!(
            element_place(&format!("{pou}/body"), ElementId(7)).as_deref(),
            Some("pou:Main/body/element:7")
        );
        assert_eq!(
            element_place(
                &format!("{pou}/actions/action[@name='A']/body"),
                ElementId(7)
            ),
            None
        );
        assert_eq!(vendor_place("project"), "project");
    }
}
