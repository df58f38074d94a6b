//! Variable lists → declarations.

use project_model::{VarSection, Variable};

use super::codesys_attributes::codesys_attribute;
use super::converter::{Converter, Place, comment};
use super::error::{ImportError, ImportErrorKind};
use super::report::Outcome;
use super::type_text::{type_text, value_text};
use crate::interface::{VarList, VarListKind};

/// The element name of a list kind, for paths.
fn element_name(kind: VarListKind) -> &'static str {
    match kind {
        VarListKind::Local => "localVars",
        VarListKind::Temp => "tempVars",
        VarListKind::Input => "inputVars",
        VarListKind::Output => "outputVars",
        VarListKind::InOut => "inOutVars",
        VarListKind::External => "externalVars",
        VarListKind::Global => "globalVars",
        VarListKind::Access => "accessVars",
    }
}

impl Converter<'_> {
    /// The declarations of `lists` in document order, each variable with its list's section and
    /// flags; `owner` is the path of the element holding the lists, `line` its line.
    pub fn variables(
        &mut self,
        lists: &[VarList],
        owner: &str,
        line: u32,
    ) -> Result<Vec<Variable>, ImportError> {
        let mut converted = Vec::new();
        for list in lists {
            let list_path = format!("{owner}/{}", element_name(list.kind));
            let section = match list.kind {
                VarListKind::Local => VarSection::Var,
                VarListKind::Temp => VarSection::VarTemp,
                VarListKind::Input => VarSection::VarInput,
                VarListKind::Output => VarSection::VarOutput,
                VarListKind::InOut => VarSection::VarInOut,
                VarListKind::External => VarSection::VarExternal,
                VarListKind::Global => VarSection::VarGlobal,
                VarListKind::Access => {
                    self.report.push(
                        Outcome::NotConverted,
                        format!("accessVars list of {} variables", list.variables.len()),
                        &list_path,
                        line,
                        "Rivet has no access paths",
                    );
                    continue;
                }
            };
            self.opaque(&list.add_data, &list_path, line);
            for variable in &list.variables {
                let place = Place {
                    path: format!("{list_path}/variable[@name='{}']", variable.name),
                    line: variable.line,
                    column: variable.column,
                };
                let mut ty = type_text(&variable.data_type).map_err(|error| {
                    self.error(
                        &place,
                        ImportErrorKind::InexpressibleType(error.to_string()),
                    )
                })?;
                let mut variable_section = section;
                // CODESYS writes a variable-length array (`VAR_IN_OUT a : ARRAY[*] OF INT`) as
                // a pointer to its element type, with the declaration in two attributes.
                if let Some(array) = codesys_attribute(&variable.add_data, "variable_length_array")
                {
                    ty = array;
                    if codesys_attribute(&variable.add_data, "variable_length_array_original_scope")
                        .is_some_and(|scope| scope.eq_ignore_ascii_case("inout"))
                    {
                        variable_section = VarSection::VarInOut;
                    }
                }
                self.opaque(&variable.add_data, &place.path, place.line);
                converted.push(Variable {
                    name: variable.name.clone(),
                    section: variable_section,
                    ty,
                    initial: variable.initial_value.as_ref().map(value_text),
                    address: variable.address.clone(),
                    constant: list.constant,
                    retain: list.retain,
                    persistent: list.persistent,
                    comment: comment(variable.documentation.as_ref()),
                });
            }
        }
        Ok(converted)
    }
}
