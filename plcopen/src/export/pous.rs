//! POUs with their interfaces, bodies, actions, transitions and methods.

use project_model::{Body, Pou, PouKind, Variable};

use super::error::ExportError;
use super::project_writer::ProjectWriter;
use super::rivet_entries::toml_text;
use super::type_xml::write_type;
use crate::rivet_data::ObjectEntryKind;

/// The name CODESYS gives the `addData` entry of a method.
const CODESYS_METHOD_ENTRY: &str = "http://www.3s-software.com/plcopenxml/method";

impl ProjectWriter<'_> {
    /// Writes one POU. An interface is written as a function block without body (PLCopen has no
    /// interfaces); Rivet's entry keeps what it is, what it extends and implements, its
    /// properties, and the access and abstractness of its methods.
    pub(super) fn pou(&mut self, pou: &Pou) -> Result<(), ExportError> {
        self.xml.context = format!("POU '{}'", pou.name);
        let pou_type = match pou.kind {
            PouKind::Program => "program",
            PouKind::FunctionBlock | PouKind::Interface => "functionBlock",
            PouKind::Function => "function",
        };
        self.xml
            .start("pou", &[("name", &pou.name), ("pouType", pou_type)])?;
        self.interface(pou.return_type.as_deref(), &pou.variables)?;
        if !pou.actions.is_empty() {
            self.xml.start("actions", &[])?;
            for action in &pou.actions {
                self.xml.context = format!("action '{}.{}'", pou.name, action.name);
                self.xml.start("action", &[("name", &action.name)])?;
                self.body(&action.body, true)?;
                self.xml.end("action")?;
            }
            self.xml.end("actions")?;
        }
        if !pou.transitions.is_empty() {
            self.xml.start("transitions", &[])?;
            for transition in &pou.transitions {
                self.xml.context = format!("transition '{}.{}'", pou.name, transition.name);
                self.xml
                    .start("transition", &[("name", &transition.name)])?;
                self.body(&transition.body, true)?;
                self.xml.end("transition")?;
            }
            self.xml.end("transitions")?;
        }
        self.xml.context = format!("POU '{}'", pou.name);
        self.body(&pou.body, false)?;
        self.xml.start("addData", &[])?;
        for method in &pou.methods {
            self.xml.context = format!("method '{}.{}'", pou.name, method.name);
            self.xml.start(
                "data",
                &[
                    ("name", CODESYS_METHOD_ENTRY),
                    ("handleUnknown", "implementation"),
                ],
            )?;
            self.xml.start("Method", &[("name", &method.name)])?;
            self.interface(method.return_type.as_deref(), &method.variables)?;
            self.body(&method.body, false)?;
            self.xml.empty("addData", &[])?;
            self.documentation(&method.comment)?;
            self.xml.end("Method")?;
            self.xml.end("data")?;
        }
        self.xml.context = format!("POU '{}'", pou.name);
        let toml = toml_text(pou, &self.xml.context)?;
        let mut accessor_texts = Vec::new();
        for property in &pou.properties {
            for (accessor, key) in [(&property.get, "get"), (&property.set, "set")] {
                if let Some(text) = accessor.as_ref().and_then(|a| a.body.st_text()) {
                    accessor_texts.push((format!("{}.{key}", property.name), text));
                }
            }
        }
        self.entry(ObjectEntryKind::Pou, &pou.name, &toml, &accessor_texts)?;
        self.xml.end("addData")?;
        self.documentation(&pou.comment)?;
        self.xml.end("pou")
    }

    /// Writes an `interface` when there is a return type or a declaration.
    fn interface(
        &mut self,
        return_type: Option<&str>,
        variables: &[Variable],
    ) -> Result<(), ExportError> {
        if return_type.is_none() && variables.is_empty() {
            return Ok(());
        }
        self.xml.start("interface", &[])?;
        if let Some(return_type) = return_type {
            self.xml.start("returnType", &[])?;
            write_type(&mut self.xml, return_type)?;
            self.xml.end("returnType")?;
        }
        self.variable_lists(variables)?;
        self.xml.end("interface")
    }

    /// Writes a body; `required` where the schema requires one (actions, transitions), so an
    /// empty one is written for a body without implementation.
    fn body(&mut self, body: &Body, required: bool) -> Result<(), ExportError> {
        match body {
            Body::St { text } => self.st_body(text),
            Body::None if required => self.st_body(""),
            Body::None => Ok(()),
            Body::Ld { .. } | Body::Fbd { .. } | Body::Cfc { .. } | Body::Sfc { .. } => {
                self.graphical_body(body, required)
            }
        }
    }

    fn st_body(&mut self, text: &str) -> Result<(), ExportError> {
        self.xml.start("body", &[])?;
        self.xml.start("ST", &[])?;
        self.formatted_text(text)?;
        self.xml.end("ST")?;
        self.xml.end("body")
    }
}
