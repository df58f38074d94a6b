//! `globalVars` of configurations and resources → global variable lists.

use project_model::{GlobalVarList, Object};

use super::converter::{Converter, Place, comment, is_rivet_entry};
use super::error::ImportError;
use super::report::Outcome;
use crate::interface::VarList;

impl Converter<'_> {
    /// Converts the global variable lists of every configuration and resource, in document order.
    pub fn globals(&mut self) -> Result<(), ImportError> {
        let document = self.document;
        for configuration in &document.configurations {
            let path = format!(
                "project/instances/configurations/configuration[@name='{}']",
                configuration.name
            );
            let line = configuration.line;
            self.lists(&configuration.global_vars, &configuration.name, &path)?;
            for variable in &configuration.config_vars {
                self.report.push(
                    Outcome::NotConverted,
                    format!("configVariable '{}'", variable.instance_path_and_name),
                    &format!("{path}/configVars"),
                    line,
                    "Rivet maps instance addresses in VAR_CONFIG of a global variable list; write it there",
                );
            }
            for variable in &configuration.access_vars {
                self.report.push(
                    Outcome::NotConverted,
                    format!("accessVariable '{}'", variable.alias),
                    &format!("{path}/accessVars"),
                    line,
                    "Rivet has no access paths",
                );
            }
            self.opaque(&configuration.add_data, &path, line);
            for resource in &configuration.resources {
                let resource_path = format!("{path}/resource[@name='{}']", resource.name);
                let resource_line = resource.line;
                self.lists(&resource.global_vars, &resource.name, &resource_path)?;
                // CODESYS writes its POUs into a resource's `addData`; they were read as POUs.
                for entry in &resource.add_data.entries {
                    if !entry.name.ends_with("/pou") {
                        self.keep_vendor_entry(entry, &resource_path, resource_line);
                    }
                }
            }
        }
        Ok(())
    }

    /// Converts the lists of one configuration or resource: a named list becomes a list of that
    /// name, the unnamed ones together one list named after `owner_name`.
    fn lists(
        &mut self,
        lists: &[VarList],
        owner_name: &str,
        owner_path: &str,
    ) -> Result<(), ImportError> {
        let mut unnamed: Option<(GlobalVarList, Place)> = None;
        let restored = Self::rivet_list_names(lists);
        let mut named_here: Vec<String> = Vec::new();
        for list in lists {
            if let Some(name) = &list.name
                && restored.contains(name)
            {
                let place = Place {
                    path: format!("{owner_path}/globalVars[@name='{name}']"),
                    line: list.line,
                    column: list.column,
                };
                // Only the last list of the name carries the entry; the others are its parts.
                let has_entry = list
                    .add_data
                    .entries
                    .iter()
                    .any(|entry| is_rivet_entry(&entry.name));
                if has_entry {
                    let parts: Vec<VarList> = lists
                        .iter()
                        .filter(|part| part.name.as_ref() == Some(name))
                        .cloned()
                        .collect();
                    self.rivet_list(&parts, &place)?;
                }
                continue;
            }
            let variables = self.variables(std::slice::from_ref(list), owner_path, list.line)?;
            let (list_line, list_column) = (list.line, list.column);
            match &list.name {
                // Lists of one name in one configuration or resource are parts of one list
                // (Rivet's export writes a list whose variables' flags differ so).
                Some(name) if named_here.contains(name) => {
                    if let Some(Object::Gvl(gvl)) = self.project.application.object_mut(name) {
                        gvl.variables.extend(variables);
                    }
                }
                Some(name) => {
                    named_here.push(name.clone());
                    let gvl = GlobalVarList {
                        name: name.clone(),
                        comment: comment(list.documentation.as_ref()),
                        variables,
                    };
                    let place = Place {
                        path: format!("{owner_path}/globalVars[@name='{name}']"),
                        line: list.line,
                        column: list.column,
                    };
                    self.add_gvl(gvl, place)?;
                }
                None => {
                    let (gvl, _) = unnamed.get_or_insert_with(|| {
                        let list = GlobalVarList {
                            name: owner_name.to_owned(),
                            comment: String::new(),
                            variables: Vec::new(),
                        };
                        let place = Place {
                            path: format!("{owner_path}/globalVars"),
                            line: list_line,
                            column: list_column,
                        };
                        (list, place)
                    });
                    if gvl.comment.is_empty() {
                        gvl.comment = comment(list.documentation.as_ref());
                    }
                    gvl.variables.extend(variables);
                }
            }
        }
        if let Some((gvl, place)) = unnamed {
            self.add_gvl(gvl, place)?;
        }
        Ok(())
    }

    fn add_gvl(&mut self, gvl: GlobalVarList, place: Place) -> Result<(), ImportError> {
        let what = format!("global variable list '{}'", gvl.name);
        self.add_object("global variable list", Object::Gvl(gvl), &place)?;
        self.report
            .push(Outcome::Converted, what, &place.path, place.line, "");
        Ok(())
    }
}
