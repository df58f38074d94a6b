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
        let place = format!("pou:{}", pou.name);
        self.transition_names = pou.transitions.iter().map(|t| t.name.clone()).collect();
        self.interface(pou.return_type.as_deref(), &pou.variables, Some(&place))?;
        if !pou.actions.is_empty() {
            self.xml.start("actions", &[])?;
            for action in &pou.actions {
                self.xml.context = format!("action '{}.{}'", pou.name, action.name);
                self.xml.start("action", &[("name", &action.name)])?;
                self.body(&action.body, true, None)?;
                self.vendor_add_data(&format!("{place}/action:{}", action.name))?;
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
                self.body(&transition.body, true, None)?;
                self.vendor_add_data(&format!("{place}/transition:{}", transition.name))?;
                self.xml.end("transition")?;
            }
            self.xml.end("transitions")?;
        }
        self.xml.context = format!("POU '{}'", pou.name);
        self.body(&pou.body, false, Some(&format!("{place}/body")))?;
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
            self.interface(method.return_type.as_deref(), &method.variables, None)?;
            self.body(&method.body, false, None)?;
            self.xml.empty("addData", &[])?;
            self.documentation(&method.comment)?;
            self.xml.end("Method")?;
            self.xml.end("data")?;
        }
        self.xml.context = format!("POU '{}'", pou.name);
        self.vendor_entries(&place)?;
        let toml = toml_text(pou, &self.xml.context)?;
        let mut accessor_texts = Vec::new();
        for property in &pou.properties {
            for (accessor, key) in [(&property.get, "get"), (&property.set, "set")] {
                if let Some(text) = accessor.as_ref().and_then(|a| a.body.text()) {
                    accessor_texts.push((format!("{}.{key}", property.name), text));
                }
            }
        }
        self.entry(ObjectEntryKind::Pou, &pou.name, &toml, &accessor_texts)?;
        self.xml.end("addData")?;
        self.documentation(&pou.comment)?;
        self.xml.end("pou")
    }

    /// Writes an `interface` when there is a return type, a declaration or vendor data; `owner`
    /// is the place of the POU (§5.5), `None` for a method.
    fn interface(
        &mut self,
        return_type: Option<&str>,
        variables: &[Variable],
        owner: Option<&str>,
    ) -> Result<(), ExportError> {
        let place = owner.map(|owner| format!("{owner}/interface"));
        let vendor = place
            .as_deref()
            .is_some_and(|place| self.has_vendor_entries(place));
        if return_type.is_none() && variables.is_empty() && !vendor {
            return Ok(());
        }
        self.xml.start("interface", &[])?;
        if let Some(return_type) = return_type {
            self.xml.start("returnType", &[])?;
            write_type(&mut self.xml, return_type)?;
            self.xml.end("returnType")?;
        }
        self.variable_lists(variables, owner)?;
        if let Some(place) = &place {
            self.vendor_add_data(place)?;
        }
        self.xml.end("interface")
    }

    /// Writes a body; `required` where the schema requires one (actions, transitions), so an
    /// empty one is written for a body without implementation; `place` names the body's vendor
    /// data (§5.5).
    fn body(
        &mut self,
        body: &Body,
        required: bool,
        place: Option<&str>,
    ) -> Result<(), ExportError> {
        match body {
            Body::St { text } => self.st_body(text, place),
            Body::Il { text } => self.il_body(text, place),
            Body::None if required => self.st_body("", place),
            Body::None => Ok(()),
            Body::Ld { .. } | Body::Fbd { .. } | Body::Cfc { .. } | Body::Sfc { .. } => {
                self.graphical_body(body, required, place)
            }
        }
    }

    /// Writes an Instruction List body: its text as `IL`, like ST's.
    fn il_body(&mut self, text: &str, place: Option<&str>) -> Result<(), ExportError> {
        self.text_body("IL", text, place)
    }

    fn st_body(&mut self, text: &str, place: Option<&str>) -> Result<(), ExportError> {
        self.text_body("ST", text, place)
    }

    /// Writes a textual body: `language` is its element (`ST`, `IL`).
    pub(super) fn text_body(
        &mut self,
        language: &str,
        text: &str,
        place: Option<&str>,
    ) -> Result<(), ExportError> {
        self.xml.start("body", &[])?;
        self.xml.start(language, &[])?;
        self.formatted_text(text)?;
        self.xml.end(language)?;
        if let Some(place) = place {
            self.vendor_add_data(place)?;
        }
        self.xml.end("body")
    }
}
