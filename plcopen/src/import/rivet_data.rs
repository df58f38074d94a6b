//! Rivet's own `addData` read back (`docs/plcopen-xml.md` §5.4): objects restored from their
//! entries, the device tree and the application tree from the project entry.

use std::collections::HashMap;

use project_model::{Body, ElementId, Folder, Node, Object, element_signature};

use super::converter::is_rivet_entry;
use super::converter::{Converter, Place};
use super::error::{ImportError, ImportErrorKind};
use super::network_import::ElementIds;
use super::report::Outcome;
use super::vendor_places::object_signature;
use crate::add_data::AddData;
use crate::body::{Body as XmlBody, BodyContent};
use crate::data_type::DataTypeDecl;
use crate::interface::VarList;
use crate::pou::Pou as XmlPou;
use crate::rivet_data::{
    OBJECT_ENTRY, ObjectEntry, ObjectEntryKind, PROJECT_ENTRY, ProjectEntry, RivetDataError,
    VENDOR_ENTRY, parse_object_entry, parse_project_entry, parse_vendor_entry,
};

/// The text of a body written in ST or IL.
fn written_text(body: &XmlBody) -> Option<&str> {
    match &body.content {
        BodyContent::St(text) | BodyContent::Il(text) if body.cfc.is_none() => Some(&text.text),
        _ => None,
    }
}

/// Whether a body restored from Rivet's entry is in the language the document writes for it:
/// another tool may have rewritten an ST body in IL or as a graph while keeping the entry, and
/// then the document wins.
fn same_language(restored: &Body, written: Option<&XmlBody>) -> bool {
    let written_content = written
        .filter(|body| body.cfc.is_none())
        .map(|body| &body.content);
    match (restored, written_content) {
        (Body::St { .. }, Some(BodyContent::St(_)))
        | (Body::Il { .. }, Some(BodyContent::Il(_))) => true,
        (Body::St { .. } | Body::Il { .. }, _) => false,
        (Body::None, _) => true,
        (_, Some(BodyContent::St(text) | BodyContent::Il(text))) => text.text.trim().is_empty(),
        _ => true,
    }
}

/// Puts `text` into `body` when it is an ST or IL body (whose text the object's file leaves
/// out).
fn fill_text(body: &mut Body, text: Option<&str>) {
    if let (Some(slot), Some(text)) = (body.text_mut(), text) {
        text.clone_into(slot);
    }
}

impl Converter<'_> {
    /// The project entry of the document, if Rivet wrote it.
    pub fn rivet_project(&self) -> Result<Option<ProjectEntry>, ImportError> {
        let Some(entry) = self
            .document
            .add_data
            .entries
            .iter()
            .find(|entry| entry.name == PROJECT_ENTRY)
        else {
            return Ok(None);
        };
        let place = Place {
            path: format!("project/addData/data[@name='{PROJECT_ENTRY}']"),
            line: 1,
            column: 1,
        };
        parse_project_entry(&entry.xml)
            .map(Some)
            .map_err(|error| self.error(&place, ImportErrorKind::RivetData(error)))
    }

    /// The object entry among `add_data`, checked to be of `kind`.
    fn rivet_object(
        &self,
        add_data: &AddData,
        kind: ObjectEntryKind,
        place: &Place,
    ) -> Result<Option<ObjectEntry>, ImportError> {
        let Some(entry) = add_data
            .entries
            .iter()
            .find(|entry| entry.name == OBJECT_ENTRY)
        else {
            return Ok(None);
        };
        let parsed = parse_object_entry(&entry.xml)
            .map_err(|error| self.error(place, ImportErrorKind::RivetData(error)))?;
        if parsed.kind != kind {
            let error = RivetDataError::WrongKind {
                found: parsed.kind.as_str(),
                expected: kind.as_str(),
            };
            return Err(self.error(place, ImportErrorKind::RivetData(error)));
        }
        Ok(Some(parsed))
    }

    /// The object's file from its entry's TOML.
    fn rivet_toml<T: serde::de::DeserializeOwned>(
        &self,
        entry: &ObjectEntry,
        place: &Place,
    ) -> Result<T, ImportError> {
        toml::from_str(&entry.toml).map_err(|source| {
            let error = RivetDataError::ObjectToml {
                kind: entry.kind.as_str(),
                name: entry.name.clone(),
                source: Box::new(source),
            };
            self.error(place, ImportErrorKind::RivetData(error))
        })
    }

    /// Restores a POU from its Rivet entry, with the ST texts of its body, actions, transitions
    /// and methods taken from the document (where another tool may have changed them) and those
    /// of its property accessors from the entry. False when the POU has no entry.
    pub fn rivet_pou(&mut self, pou: &XmlPou, place: &Place) -> Result<bool, ImportError> {
        let Some(entry) = self.rivet_object(&pou.add_data, ObjectEntryKind::Pou, place)? else {
            return Ok(false);
        };
        let mut restored: project_model::Pou = self.rivet_toml(&entry, place)?;
        // A body the document writes in another language than the entry: the document wins,
        // and the POU is converted from it like any other tool's.
        let languages_agree = same_language(&restored.body, pou.bodies.first())
            && restored.actions.iter().all(|action| {
                let written = pou
                    .actions
                    .iter()
                    .find(|written| written.name == action.name);
                same_language(&action.body, written.map(|written| &written.body))
            })
            && restored.transitions.iter().all(|transition| {
                let written = pou
                    .transitions
                    .iter()
                    .find(|written| written.name == transition.name);
                same_language(&transition.body, written.map(|written| &written.body))
            })
            && restored.methods.iter().all(|method| {
                let written = pou
                    .methods
                    .iter()
                    .find(|written| written.name == method.name);
                same_language(
                    &method.body,
                    written.and_then(|written| written.bodies.first()),
                )
            });
        if !languages_agree {
            return Ok(false);
        }
        restored.name = pou.name.clone();
        fill_text(
            &mut restored.body,
            pou.bodies.first().and_then(written_text),
        );
        for action in &mut restored.actions {
            let text = pou
                .actions
                .iter()
                .find(|written| written.name == action.name)
                .and_then(|written| written_text(&written.body));
            fill_text(&mut action.body, text);
        }
        for transition in &mut restored.transitions {
            let text = pou
                .transitions
                .iter()
                .find(|written| written.name == transition.name)
                .and_then(|written| written_text(&written.body));
            fill_text(&mut transition.body, text);
        }
        for method in &mut restored.methods {
            let text = pou
                .methods
                .iter()
                .find(|written| written.name == method.name)
                .and_then(|written| written.bodies.first())
                .and_then(written_text);
            fill_text(&mut method.body, text);
        }
        for property in &mut restored.properties {
            for (accessor, key) in [(&mut property.get, "get"), (&mut property.set, "set")] {
                let key = format!("{}.{key}", property.name);
                let text = entry
                    .st
                    .iter()
                    .find(|(written, _)| *written == key)
                    .map(|(_, text)| text.as_str());
                if let Some(accessor) = accessor {
                    fill_text(&mut accessor.body, text);
                }
            }
        }
        self.keep_pou_vendor_data(pou, place, &restored.body);
        // Another tool may have changed the declarations and kept Rivet's entry: when the
        // document declares other names than the entry, its declarations win.
        let (variables, return_type) = self.interface(
            pou.interface.as_ref(),
            &format!("{}/interface", place.path),
            place,
        )?;
        let mut note = "restored from Rivet's data";
        if !same_names(&variables, &restored.variables) {
            restored.variables = variables;
            restored.return_type = return_type;
            note = "restored from Rivet's data; its declarations from the document, which declares other names";
        }
        let what = format!("POU '{}'", pou.name);
        self.add_object("POU", Object::Pou(restored), place)?;
        self.report
            .push(Outcome::Converted, what, &place.path, place.line, note);
        Ok(true)
    }

    /// Keeps the vendor data of a POU restored from Rivet's entry, as the conversion of a POU
    /// keeps it (§2.6); the entries of the objects of its LD or FBD body go with the elements
    /// of `restored_body` whose ids the objects carry as `localId`s (§5.5).
    fn keep_pou_vendor_data(&mut self, pou: &XmlPou, place: &Place, restored_body: &Body) {
        let (path, line) = (place.path.as_str(), place.line);
        for entry in &pou.add_data.entries {
            if !entry.name.ends_with("/method") && !is_rivet_entry(&entry.name) {
                self.keep_vendor_entry(entry, path, line);
            }
        }
        let body_path = format!("{path}/body");
        for body in &pou.bodies {
            self.opaque(&body.add_data, &body_path, body.line);
        }
        if let (Some(body), Body::Ld { networks } | Body::Fbd { networks }) =
            (pou.bodies.first(), restored_body)
        {
            let objects = body.content.objects();
            let has_entries = objects.iter().any(|object| {
                object
                    .add_data
                    .entries
                    .iter()
                    .any(|entry| !is_rivet_entry(&entry.name))
            });
            if has_entries {
                // Rivet's export writes each element with its id as `localId`; the objects it
                // adds (rails, AND and OR boxes) take ids no element has. Another tool may
                // have renumbered or added objects since: an object goes with the element of
                // its id only when it is that element (same kind, box type, operand text or
                // coil variable); the others' entries are reported not converted.
                let mut signatures = HashMap::new();
                for network in networks {
                    network.for_each_element(&mut |element| {
                        signatures.insert(u64::from(element.id().0), element_signature(element));
                    });
                }
                let element_ids: ElementIds = objects
                    .iter()
                    .filter(|object| {
                        let element = signatures.get(&object.local_id);
                        object_signature(object).is_some_and(|signature| {
                            element.is_some_and(|element| signature.eq_ignore_ascii_case(element))
                        })
                    })
                    .filter_map(|object| {
                        let id = u32::try_from(object.local_id).ok()?;
                        Some((object.local_id, ElementId(id)))
                    })
                    .collect();
                let objects_path = format!("{body_path}/{}", body.content.language());
                self.opaque_objects(
                    objects,
                    &objects_path,
                    Some((&body_path, &element_ids, networks.as_slice())),
                );
            }
        }
        // The interface's entries are kept by its conversion (`rivet_pou`).
        for action in &pou.actions {
            let action_path = format!("{path}/actions/action[@name='{}']", action.name);
            self.opaque(&action.add_data, &action_path, action.body.line);
        }
        for transition in &pou.transitions {
            let transition_path =
                format!("{path}/transitions/transition[@name='{}']", transition.name);
            self.opaque(&transition.add_data, &transition_path, transition.body.line);
        }
        for method in &pou.methods {
            let method_path = format!("{path}/addData/data/Method[@name='{}']", method.name);
            self.opaque(&method.add_data, &method_path, line);
        }
    }

    /// Keeps the vendor data of the tasks and their program instances when Rivet's project
    /// entry gives the tasks.
    fn keep_task_vendor_data(&mut self) {
        let document = self.document;
        for configuration in &document.configurations {
            for resource in &configuration.resources {
                for task in &resource.tasks {
                    let path = format!(
                        "project/instances/configurations/configuration[@name='{}']/resource[@name='{}']/task[@name='{}']",
                        configuration.name, resource.name, task.name
                    );
                    self.opaque(&task.add_data, &path, task.line);
                    for instance in &task.pou_instances {
                        let instance_path =
                            format!("{path}/pouInstance[@name='{}']", instance.name);
                        self.opaque(&instance.add_data, &instance_path, task.line);
                    }
                }
            }
        }
    }

    /// Keeps the imported file's creation date (unless it is the export's fixed one) and puts the
    /// vendor data in its order: by place, and within a place as the file had it.
    pub fn keep_header(&mut self, document: &crate::Document) {
        // v1.0 files write `2007-07-07 11:58:26`, which the v2.01 schema refuses; the date is
        // kept in the schema's form, and not at all when it has none.
        let date = document
            .file_header
            .creation_date_time
            .replacen(' ', "T", 1);
        if date != crate::export::CREATION_DATE_TIME && is_date_time(&date) {
            self.project.vendor_data.creation_date_time = Some(date);
        }
        self.project
            .vendor_data
            .entries
            .sort_by(|a, b| a.place.cmp(&b.place));
    }

    /// Restores a data type from its Rivet entry; false when it has none.
    pub fn rivet_data_type(
        &mut self,
        declaration: &DataTypeDecl,
        place: &Place,
    ) -> Result<bool, ImportError> {
        let Some(entry) =
            self.rivet_object(&declaration.add_data, ObjectEntryKind::DataType, place)?
        else {
            return Ok(false);
        };
        let mut restored: project_model::DataType = self.rivet_toml(&entry, place)?;
        restored.name = declaration.name.clone();
        self.opaque(&declaration.add_data, &place.path, place.line);
        if let crate::DataType::Struct { members } = &declaration.base_type {
            for member in members {
                let path = format!(
                    "{}/baseType/struct/variable[@name='{}']",
                    place.path, member.name
                );
                self.opaque(&member.add_data, &path, member.line);
            }
        }
        let what = format!("data type '{}'", declaration.name);
        self.add_object("data type", Object::DataType(restored), place)?;
        self.report.push(
            Outcome::Converted,
            what,
            &place.path,
            place.line,
            "restored from Rivet's data",
        );
        Ok(true)
    }

    /// The names of the lists among `lists` that carry a Rivet entry: the export writes a list
    /// whose variables' flags differ as several `globalVars` of its name, the last with the entry.
    pub fn rivet_list_names(lists: &[VarList]) -> Vec<String> {
        lists
            .iter()
            .filter(|list| list.add_data.entries.iter().any(|e| e.name == OBJECT_ENTRY))
            .filter_map(|list| list.name.clone())
            .collect()
    }

    /// Restores a global variable list from its Rivet entry, carried by the last of `parts`
    /// (the `globalVars` of its name); false when it has none.
    pub fn rivet_list(&mut self, parts: &[VarList], place: &Place) -> Result<bool, ImportError> {
        let Some(last) = parts.last() else {
            return Ok(false);
        };
        let Some(entry) = self.rivet_object(&last.add_data, ObjectEntryKind::Gvl, place)? else {
            return Ok(false);
        };
        let mut restored: project_model::GlobalVarList = self.rivet_toml(&entry, place)?;
        restored.name = last.name.clone().unwrap_or(entry.name);
        let mut declared = Vec::new();
        for part in parts {
            self.opaque(&part.add_data, &place.path, place.line);
            for variable in &part.variables {
                let path = format!("{}/variable[@name='{}']", place.path, variable.name);
                self.opaque(&variable.add_data, &path, variable.line);
                declared.push(variable.name.as_str());
            }
        }
        let mut note = "restored from Rivet's data";
        let same = declared.len() == restored.variables.len()
            && declared
                .iter()
                .zip(&restored.variables)
                .all(|(written, kept)| *written == kept.name);
        if !same {
            // Another tool changed the list and kept Rivet's entry: the document's declarations
            // win (their vendor data is already kept above).
            let mut converted = Vec::new();
            for part in parts {
                let report_length = self.report.entries.len();
                let kept_length = self.project.vendor_data.entries.len();
                converted.extend(self.variables(
                    std::slice::from_ref(part),
                    &place.path,
                    place.line,
                )?);
                // The entries were kept above; drop the second keeping of the same entries.
                self.report.entries.truncate(report_length);
                self.project.vendor_data.entries.truncate(kept_length);
            }
            restored.variables = converted;
            note = "restored from Rivet's data; its variables from the document, which declares other names";
        }
        let what = format!("global variable list '{}'", restored.name);
        self.add_object("global variable list", Object::Gvl(restored), place)?;
        self.report
            .push(Outcome::Converted, what, &place.path, place.line, note);
        Ok(true)
    }

    /// Applies the project entry: the device tree, the dialect, the tasks, the cams, traces and
    /// watch lists of the project's `addData`, and the application tree's folders and order.
    pub fn apply_rivet_project(&mut self, entry: ProjectEntry) -> Result<(), ImportError> {
        let project = &mut self.project;
        project.name = entry.name;
        project.description = entry.description;
        project.dialect = entry.dialect;
        project.controller = entry.controller;
        project.tasks = entry.tasks;
        project.io_areas = entry.io_areas;
        project.serial_ports = entry.serial_ports;
        project.modbus_devices = entry.modbus_devices;
        project.axes = entry.axes;
        self.keep_task_vendor_data();
        for data in &self.document.add_data.entries {
            if data.name == VENDOR_ENTRY {
                let place = Place {
                    path: format!("project/addData/data[@name='{VENDOR_ENTRY}']"),
                    line: 1,
                    column: 1,
                };
                let kept = parse_vendor_entry(&data.xml)
                    .map_err(|error| self.error(&place, ImportErrorKind::RivetData(error)))?;
                self.project.vendor_data.entries.push(kept);
                continue;
            }
            if data.name != OBJECT_ENTRY {
                continue;
            }
            let place = Place {
                path: format!("project/addData/data[@name='{OBJECT_ENTRY}']"),
                line: 1,
                column: 1,
            };
            let object_entry = parse_object_entry(&data.xml)
                .map_err(|error| self.error(&place, ImportErrorKind::RivetData(error)))?;
            let object = match object_entry.kind {
                ObjectEntryKind::Cam => {
                    let mut cam: project_model::CamTable =
                        self.rivet_toml(&object_entry, &place)?;
                    cam.name = object_entry.name.clone();
                    Object::CamTable(cam)
                }
                ObjectEntryKind::Trace => {
                    let mut trace: project_model::TraceConfig =
                        self.rivet_toml(&object_entry, &place)?;
                    trace.name = object_entry.name.clone();
                    Object::Trace(trace)
                }
                ObjectEntryKind::Watch => {
                    let mut watch: project_model::WatchList =
                        self.rivet_toml(&object_entry, &place)?;
                    watch.name = object_entry.name.clone();
                    Object::WatchList(watch)
                }
                ObjectEntryKind::Pou | ObjectEntryKind::DataType | ObjectEntryKind::Gvl => {
                    let error = RivetDataError::MisplacedObject(object_entry.kind.as_str());
                    return Err(self.error(&place, ImportErrorKind::RivetData(error)));
                }
            };
            let what = format!("{} '{}'", object_entry.kind.as_str(), object_entry.name);
            self.add_object("object", object, &place)?;
            self.report.push(
                Outcome::Converted,
                what,
                &place.path,
                1,
                "restored from Rivet's data",
            );
        }
        // The objects converted stand at the root in document order; the tree puts them back in
        // their folders and order. Objects the tree does not name (added by another tool) follow.
        let mut pool: Vec<Object> = std::mem::take(&mut self.project.application.children)
            .into_iter()
            .filter_map(|node| match node {
                Node::Object(object) => Some(object),
                Node::Folder(_) => None,
            })
            .collect();
        let mut root = Folder::default();
        for node in entry.nodes {
            let Some(name) = node.object else {
                place(&mut root, &node.folder, None);
                continue;
            };
            let Some(at) = pool.iter().position(|object| object.name() == name) else {
                continue;
            };
            place(&mut root, &node.folder, Some(pool.remove(at)));
        }
        root.children.extend(pool.into_iter().map(Node::Object));
        self.project.application = root;
        Ok(())
    }
}

/// True when two declaration lists name the same variables in the same order.
fn same_names(document: &[project_model::Variable], entry: &[project_model::Variable]) -> bool {
    document.len() == entry.len()
        && document
            .iter()
            .zip(entry)
            .all(|(written, kept)| written.name == kept.name)
}

/// True for an `xs:dateTime`: `YYYY-MM-DDTHH:MM:SS`, optionally with a fraction of a second and
/// a zone (`Z` or `±HH:MM`).
fn is_date_time(text: &str) -> bool {
    let digits =
        |part: &str, count: usize| part.len() == count && part.bytes().all(|b| b.is_ascii_digit());
    let Some((date, time)) = text.split_once('T') else {
        return false;
    };
    let date_parts: Vec<&str> = date.split('-').collect();
    let date_ok =
        matches!(date_parts.as_slice(), [y, m, d] if digits(y, 4) && digits(m, 2) && digits(d, 2));
    let (time, zone) = match time.find(['Z', '+', '-']) {
        Some(at) => time.split_at(at),
        None => (time, ""),
    };
    let zone_ok = zone.is_empty()
        || zone == "Z"
        || matches!(zone[1..].split_once(':'), Some((h, m)) if digits(h, 2) && digits(m, 2));
    let (clock, fraction) = time.split_once('.').unwrap_or((time, "0"));
    let clock_parts: Vec<&str> = clock.split(':').collect();
    let clock_ok =
        matches!(clock_parts.as_slice(), [h, m, s] if digits(h, 2) && digits(m, 2) && digits(s, 2));
    let fraction_ok = !fraction.is_empty() && fraction.bytes().all(|b| b.is_ascii_digit());
    date_ok && clock_ok && fraction_ok && zone_ok
}

/// Puts `object` into the folder at `path` below `root`, creating the folders missing; with
/// no object, only the folders.
fn place(root: &mut Folder, path: &[String], object: Option<Object>) {
    create_folders(root, path);
    let node = object.map(Node::Object);
    match root.folder_mut(path) {
        Some(folder) => folder.children.extend(node),
        None => root.children.extend(node),
    }
}

fn create_folders(folder: &mut Folder, path: &[String]) {
    let Some((first, rest)) = path.split_first() else {
        return;
    };
    let exists = folder
        .children
        .iter()
        .any(|node| matches!(node, Node::Folder(child) if child.name == *first));
    if !exists {
        folder.children.push(Node::Folder(Folder {
            name: first.clone(),
            children: Vec::new(),
        }));
    }
    for node in &mut folder.children {
        if let Node::Folder(child) = node
            && child.name == *first
        {
            create_folders(child, rest);
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::is_date_time;

    #[test]
    fn dates_are_kept_only_in_the_schema_form() {
        assert!(is_date_time("2016-10-24T18:09:22"));
        assert!(is_date_time("2024-07-12T16:04:57.123+02:00"));
        assert!(is_date_time("2024-07-12T16:04:57Z"));
        assert!(!is_date_time("2007-07-07 11:58:26"));
        assert!(!is_date_time("yesterday"));
        assert!(!is_date_time("2024-07-12T16:04"));
    }
}
