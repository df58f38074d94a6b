//! Data types as `types/dataTypes/dataType`.

use project_model::{DataType, TypeDefinition};

use super::error::ExportError;
use super::project_writer::ProjectWriter;
use super::rivet_entries::toml_text;
use super::type_xml::{write_type, write_value};
use crate::rivet_data::ObjectEntryKind;

impl ProjectWriter<'_> {
    /// Writes one data type: structures and unions as `struct` (PLCopen has no union; Rivet's
    /// entry keeps which it is and what a structure extends), enumerations as `enum`, aliases as
    /// their type.
    pub(super) fn data_type(&mut self, data_type: &DataType) -> Result<(), ExportError> {
        self.xml.context = format!("data type '{}'", data_type.name);
        self.xml.start("dataType", &[("name", &data_type.name)])?;
        self.xml.start("baseType", &[])?;
        let mut initial = None;
        match &data_type.definition {
            TypeDefinition::Struct { members, .. } | TypeDefinition::Union { members } => {
                self.xml.start("struct", &[])?;
                for member in members {
                    self.xml.start("variable", &[("name", &member.name)])?;
                    self.xml.start("type", &[])?;
                    write_type(&mut self.xml, &member.ty)?;
                    self.xml.end("type")?;
                    if let Some(value) = &member.initial {
                        self.xml.start("initialValue", &[])?;
                        write_value(&mut self.xml, value)?;
                        self.xml.end("initialValue")?;
                    }
                    self.documentation(&member.comment)?;
                    self.xml.end("variable")?;
                }
                self.xml.end("struct")?;
            }
            // The schema wants at least one value; an enumeration without any is written as its
            // base type, and Rivet's entry keeps what it is.
            TypeDefinition::Enum { base, values } if values.is_empty() => {
                write_type(&mut self.xml, base.as_deref().unwrap_or("INT"))?;
            }
            TypeDefinition::Enum { base, values } => {
                self.xml.start("enum", &[])?;
                self.xml.start("values", &[])?;
                for value in values {
                    let mut attributes = vec![("name", value.name.as_str())];
                    if let Some(number) = &value.value {
                        attributes.push(("value", number));
                    }
                    self.xml.empty("value", &attributes)?;
                }
                self.xml.end("values")?;
                if let Some(base) = base {
                    self.xml.start("baseType", &[])?;
                    write_type(&mut self.xml, base)?;
                    self.xml.end("baseType")?;
                }
                self.xml.end("enum")?;
            }
            TypeDefinition::Alias { ty, initial: value } => {
                write_type(&mut self.xml, ty)?;
                initial = value.as_deref();
            }
        }
        self.xml.end("baseType")?;
        if let Some(value) = initial {
            self.xml.start("initialValue", &[])?;
            write_value(&mut self.xml, value)?;
            self.xml.end("initialValue")?;
        }
        self.xml.start("addData", &[])?;
        self.vendor_entries(&format!("type:{}", data_type.name))?;
        let toml = toml_text(data_type, &self.xml.context)?;
        self.entry(ObjectEntryKind::DataType, &data_type.name, &toml, &[])?;
        self.xml.end("addData")?;
        self.documentation(&data_type.comment)?;
        self.xml.end("dataType")
    }
}
