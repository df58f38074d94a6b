//! `types/dataTypes` → data type objects.

use project_model::{EnumValue, Object, StructMember, TypeDefinition};

use super::converter::{Converter, Place, comment};
use super::error::{ImportError, ImportErrorKind};
use super::report::Outcome;
use super::type_text::{type_text, value_text};
use crate::data_type::{DataType, DataTypeDecl};

impl Converter<'_> {
    /// Converts every data type in document order.
    pub fn data_types(&mut self) -> Result<(), ImportError> {
        for declaration in &self.document.data_types {
            let place = Place {
                path: format!(
                    "project/types/dataTypes/dataType[@name='{}']",
                    declaration.name
                ),
                line: declaration.line,
                column: declaration.column,
            };
            if self.rivet_data_type(declaration, &place)? {
                continue;
            }
            let definition = self.definition(declaration, &place)?;
            let data_type = project_model::DataType {
                name: declaration.name.clone(),
                comment: comment(declaration.documentation.as_ref()),
                definition,
            };
            self.add_object("data type", Object::DataType(data_type), &place)?;
            self.report.push(
                Outcome::Converted,
                format!("data type '{}'", declaration.name),
                &place.path,
                place.line,
                "",
            );
            self.opaque(&declaration.add_data, &place.path, place.line);
        }
        Ok(())
    }

    fn definition(
        &mut self,
        declaration: &DataTypeDecl,
        place: &Place,
    ) -> Result<TypeDefinition, ImportError> {
        let inexpressible = |converter: &Self, message: String| {
            converter.error(place, ImportErrorKind::InexpressibleType(message))
        };
        Ok(match &declaration.base_type {
            DataType::Struct { members } => {
                let mut converted = Vec::with_capacity(members.len());
                for member in members {
                    let ty = type_text(&member.data_type).map_err(|message| {
                        inexpressible(self, format!("member `{}`: {message}", member.name))
                    })?;
                    let member_path = format!(
                        "{}/baseType/struct/variable[@name='{}']",
                        place.path, member.name
                    );
                    if let Some(address) = &member.address {
                        self.report.push(
                            Outcome::NotConverted,
                            format!("address '{address}' of member '{}'", member.name),
                            &member_path,
                            member.line,
                            "Rivet's structure members have no located address",
                        );
                    }
                    self.opaque(&member.add_data, &member_path, member.line);
                    converted.push(StructMember {
                        name: member.name.clone(),
                        ty,
                        initial: member.initial_value.as_ref().map(value_text),
                        comment: comment(member.documentation.as_ref()),
                    });
                }
                TypeDefinition::Struct {
                    extends: None,
                    members: converted,
                }
            }
            DataType::Enum { values, base } => {
                if let Some(initial) = &declaration.initial_value {
                    self.report.push(
                        Outcome::NotConverted,
                        format!(
                            "initial value '{}' of enumeration '{}'",
                            value_text(initial),
                            declaration.name
                        ),
                        &place.path,
                        place.line,
                        "Rivet's enumerations start at their first value",
                    );
                }
                let base = match base {
                    Some(base) => Some(
                        type_text(base).map_err(|error| inexpressible(self, error.to_string()))?,
                    ),
                    None => None,
                };
                TypeDefinition::Enum {
                    base,
                    values: values
                        .iter()
                        .map(|value| EnumValue {
                            name: value.name.clone(),
                            value: value.value.clone(),
                            comment: String::new(),
                        })
                        .collect(),
                }
            }
            other => TypeDefinition::Alias {
                ty: type_text(other).map_err(|error| inexpressible(self, error.to_string()))?,
                initial: declaration.initial_value.as_ref().map(value_text),
            },
        })
    }
}
