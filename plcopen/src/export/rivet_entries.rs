//! Rivet's own `addData` entries (§5.4): the project entry and one entry per object.

use project_model::{GlobalVarList, Object};
use serde::Serialize;

use super::error::ExportError;
use super::project_writer::{ProjectWriter, tree_nodes};
use crate::rivet_data::{
    OBJECT_ENTRY, ObjectEntryKind, PROJECT_ENTRY, ProjectEntry, RIVET_NAMESPACE, TreeNode,
};

/// The TOML of `value`; `object` names it in the error.
pub(super) fn toml_text<T: Serialize>(value: &T, object: &str) -> Result<String, ExportError> {
    toml::to_string(value).map_err(|error| ExportError::RivetData {
        object: object.to_owned(),
        message: error.to_string(),
    })
}

impl ProjectWriter<'_> {
    /// Writes the project entry: the device tree, the dialect and the application tree.
    pub(super) fn project_entry(&mut self) -> Result<(), ExportError> {
        let project = self.project;
        self.xml.context = "the project's Rivet data".into();
        let mut nodes = Vec::new();
        tree_nodes(&project.application, &mut Vec::new(), &mut nodes);
        let entry = ProjectEntry {
            name: project.name.clone(),
            description: project.description.clone(),
            dialect: project.dialect,
            controller: project.controller.clone(),
            tasks: project.tasks.clone(),
            io_areas: project.io_areas.clone(),
            serial_ports: project.serial_ports.clone(),
            modbus_devices: project.modbus_devices.clone(),
            axes: project.axes.clone(),
            nodes: nodes
                .into_iter()
                .map(|(folder, object)| TreeNode { folder, object })
                .collect(),
        };
        let toml = toml_text(&entry, &self.xml.context)?;
        self.xml.start(
            "data",
            &[("name", PROJECT_ENTRY), ("handleUnknown", "preserve")],
        )?;
        self.xml.start("project", &[("xmlns", RIVET_NAMESPACE)])?;
        self.xml.cdata(&toml)?;
        self.xml.end("project")?;
        self.xml.end("data")
    }

    /// Writes the entry of a cam table, trace or watch list, which PLCopen has no element for.
    pub(super) fn object_entry(&mut self, object: &Object) -> Result<(), ExportError> {
        let (kind, what) = match object {
            Object::CamTable(_) => (ObjectEntryKind::Cam, "cam table"),
            Object::Trace(_) => (ObjectEntryKind::Trace, "trace"),
            Object::WatchList(_) => (ObjectEntryKind::Watch, "watch list"),
            Object::Pou(_) => (ObjectEntryKind::Pou, "POU"),
            Object::Gvl(_) => (ObjectEntryKind::Gvl, "global variable list"),
            Object::DataType(_) => (ObjectEntryKind::DataType, "data type"),
        };
        self.xml.context = format!("{what} '{}'", object.name());
        let toml = match object {
            Object::CamTable(cam) => toml_text(cam, &self.xml.context)?,
            Object::Trace(trace) => toml_text(trace, &self.xml.context)?,
            Object::WatchList(watch) => toml_text(watch, &self.xml.context)?,
            Object::Pou(pou) => toml_text(pou, &self.xml.context)?,
            Object::Gvl(list) => toml_text(list, &self.xml.context)?,
            Object::DataType(data_type) => toml_text(data_type, &self.xml.context)?,
        };
        self.entry(kind, object.name(), &toml, &[])
    }

    /// Writes a list's `addData` with its entry.
    pub(super) fn list_add_data(&mut self, list: &GlobalVarList) -> Result<(), ExportError> {
        let toml = toml_text(list, &self.xml.context)?;
        self.xml.start("addData", &[])?;
        self.vendor_entries(&format!("gvl:{}", list.name))?;
        self.entry(ObjectEntryKind::Gvl, &list.name, &toml, &[])?;
        self.xml.end("addData")
    }

    /// Writes one object entry: the object's file as TOML and the ST texts its file leaves to
    /// `.st` files that PLCopen has no place for, each under its key.
    pub(super) fn entry(
        &mut self,
        kind: ObjectEntryKind,
        name: &str,
        toml: &str,
        st: &[(String, &str)],
    ) -> Result<(), ExportError> {
        let restorable = matches!(
            kind,
            ObjectEntryKind::Pou | ObjectEntryKind::DataType | ObjectEntryKind::Gvl
        );
        if restorable && !self.options.object_entries {
            return Ok(());
        }
        self.xml.start(
            "data",
            &[("name", OBJECT_ENTRY), ("handleUnknown", "preserve")],
        )?;
        self.xml.start(
            "object",
            &[
                ("xmlns", RIVET_NAMESPACE),
                ("kind", kind.as_str()),
                ("name", name),
            ],
        )?;
        self.xml.start("toml", &[])?;
        self.xml.cdata(toml)?;
        self.xml.end("toml")?;
        for (key, text) in st {
            self.xml.start("st", &[("body", key)])?;
            self.xml.cdata(text)?;
            self.xml.end("st")?;
        }
        self.xml.end("object")?;
        self.xml.end("data")
    }
}
