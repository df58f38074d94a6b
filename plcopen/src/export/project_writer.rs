//! The document's frame: headers, the application's objects in order, instances and Rivet's
//! project data.

use std::collections::HashSet;

use project_model::{Folder, Node, Object, Project, TaskKind};

use super::ExportOptions;
use super::error::ExportError;
use super::xml_writer::XmlWriter;

/// The PLCopen v2.01 namespace.
pub(super) const PLCOPEN_NAMESPACE: &str = "http://www.plcopen.org/xml/tc6_0201";

/// The XHTML namespace of formatted text.
pub(super) const XHTML_NAMESPACE: &str = "http://www.w3.org/1999/xhtml";

/// The `creationDateTime` of every export: the schema requires one, and the export must give the
/// same bytes for the same project, so it is fixed rather than taken from the clock.
pub(crate) const CREATION_DATE_TIME: &str = "1970-01-01T00:00:00";

/// The name of the one resource the controller's tasks and lists are written in.
pub(super) const RESOURCE_NAME: &str = "Application";

/// One export in progress.
pub(super) struct ProjectWriter<'p> {
    /// The project exported.
    pub project: &'p Project,
    /// The document so far.
    pub xml: XmlWriter,
    /// The places of the vendor data written so far (§5.5), but for elements' places.
    pub written_places: HashSet<String>,
    /// The elements' entries written into their elements so far, by index in the project's
    /// vendor data: one place may also hold entries another element had (§5.5), which go to
    /// the leftovers.
    pub written_element_entries: HashSet<usize>,
    /// The transition objects of the POU being written, which SFC conditions may name.
    pub transition_names: Vec<String>,
    /// What the export writes beyond PLCopen's elements.
    pub options: ExportOptions,
}

impl<'p> ProjectWriter<'p> {
    /// An export of `project` that has written the XML declaration.
    pub fn new(project: &'p Project, options: ExportOptions) -> Result<Self, ExportError> {
        Ok(Self {
            project,
            xml: XmlWriter::new()?,
            written_places: HashSet::new(),
            written_element_entries: HashSet::new(),
            transition_names: Vec::new(),
            options,
        })
    }

    /// Writes the whole document and gives its bytes.
    pub fn write(mut self) -> Result<Vec<u8>, ExportError> {
        let project = self.project;
        self.xml.start(
            "project",
            &[
                ("xmlns", PLCOPEN_NAMESPACE),
                ("xmlns:xhtml", XHTML_NAMESPACE),
            ],
        )?;
        self.xml.context = "the project's header".into();
        self.xml.empty(
            "fileHeader",
            &[
                ("companyName", "Rivet"),
                ("productName", "Rivet"),
                ("productVersion", env!("CARGO_PKG_VERSION")),
                (
                    "creationDateTime",
                    project
                        .vendor_data
                        .creation_date_time
                        .as_deref()
                        .unwrap_or(CREATION_DATE_TIME),
                ),
            ],
        )?;
        self.xml
            .start("contentHeader", &[("name", &project.name)])?;
        if !project.description.is_empty() {
            self.xml
                .text_element("Comment", &[], &project.description)?;
        }
        self.xml.start("coordinateInfo", &[])?;
        for language in ["fbd", "ld", "sfc"] {
            self.xml.start(language, &[])?;
            self.xml.empty("scaling", &[("x", "10"), ("y", "10")])?;
            self.xml.end(language)?;
        }
        self.xml.end("coordinateInfo")?;
        self.vendor_add_data("contentHeader")?;
        self.xml.end("contentHeader")?;

        let objects = project.application.objects();
        self.xml.start("types", &[])?;
        self.xml.start("dataTypes", &[])?;
        for object in &objects {
            if let Object::DataType(data_type) = object {
                self.data_type(data_type)?;
            }
        }
        self.xml.end("dataTypes")?;
        self.xml.start("pous", &[])?;
        for object in &objects {
            if let Object::Pou(pou) = object {
                self.pou(pou)?;
            }
        }
        self.xml.end("pous")?;
        self.xml.end("types")?;

        self.instances(&objects)?;
        self.xml.start("addData", &[])?;
        self.vendor_entries("project")?;
        self.project_entry()?;
        for object in &objects {
            match object {
                Object::CamTable(_) | Object::Trace(_) | Object::WatchList(_) => {
                    self.object_entry(object)?;
                }
                Object::Pou(_) | Object::Gvl(_) | Object::DataType(_) => {}
            }
        }
        self.leftover_vendor_entries()?;
        self.xml.end("addData")?;
        self.xml.end("project")?;
        Ok(self.xml.finish())
    }

    /// The controller as one configuration with one resource: its tasks with their programs and
    /// the global variable lists.
    fn instances(&mut self, objects: &[&Object]) -> Result<(), ExportError> {
        let project = self.project;
        self.xml.start("instances", &[])?;
        self.xml.start("configurations", &[])?;
        self.xml.context = format!("controller '{}'", project.controller.name);
        self.xml
            .start("configuration", &[("name", &project.controller.name)])?;
        self.xml.start("resource", &[("name", RESOURCE_NAME)])?;
        for task in &project.tasks {
            self.xml.context = format!("task '{}'", task.name);
            let priority = task.priority.to_string();
            let mut attributes = vec![("name", task.name.as_str())];
            let interval;
            match &task.kind {
                TaskKind::Cyclic { interval_us } => {
                    interval = interval_text(*interval_us);
                    attributes.push(("interval", &interval));
                }
                TaskKind::Event { trigger } => attributes.push(("single", trigger)),
                TaskKind::Freewheeling => {}
            }
            attributes.push(("priority", &priority));
            let place = format!("task:{}", task.name);
            if task.programs.is_empty() && !self.has_vendor_entries(&place) {
                self.xml.empty("task", &attributes)?;
                continue;
            }
            self.xml.start("task", &attributes)?;
            for program in &task.programs {
                self.xml
                    .empty("pouInstance", &[("name", program), ("typeName", program)])?;
            }
            self.vendor_add_data(&place)?;
            self.xml.end("task")?;
        }
        for object in objects {
            if let Object::Gvl(list) = object {
                self.global_list(list)?;
            }
        }
        self.vendor_add_data("resource")?;
        self.xml.end("resource")?;
        self.vendor_add_data("configuration")?;
        self.xml.end("configuration")?;
        self.xml.end("configurations")?;
        self.xml.end("instances")
    }
}

/// A cyclic task's interval as an IEC duration: milliseconds when whole, else microseconds.
pub(super) fn interval_text(interval_us: u32) -> String {
    if interval_us.is_multiple_of(1000) {
        format!("T#{}ms", interval_us / 1000)
    } else {
        format!("T#{interval_us}us")
    }
}

/// The application tree depth first, as the project entry lists it: each folder by its path and
/// each object by its folder's path and its name.
pub(super) fn tree_nodes(
    folder: &Folder,
    path: &mut Vec<String>,
    nodes: &mut Vec<(Vec<String>, Option<String>)>,
) {
    for node in &folder.children {
        match node {
            Node::Folder(child) => {
                path.push(child.name.clone());
                nodes.push((path.clone(), None));
                tree_nodes(child, path, nodes);
                path.pop();
            }
            Node::Object(object) => nodes.push((path.clone(), Some(object.name().to_owned()))),
        }
    }
}
