//! Declarations as PLCopen variable lists, and formatted text.

use project_model::{GlobalVarList, VarSection, Variable};

use super::error::ExportError;
use super::project_writer::ProjectWriter;
use super::type_xml::{write_type, write_value};

/// The list element a section's variables are written in. PLCopen has no static, instance or
/// configuration lists: those are written as local or global lists, and Rivet's object entry
/// keeps the section.
pub(super) fn list_element(section: VarSection) -> &'static str {
    match section {
        VarSection::Var | VarSection::VarStat | VarSection::VarInst => "localVars",
        VarSection::VarInput => "inputVars",
        VarSection::VarOutput => "outputVars",
        VarSection::VarInOut => "inOutVars",
        VarSection::VarGlobal | VarSection::VarConfig => "globalVars",
        VarSection::VarExternal => "externalVars",
        VarSection::VarTemp => "tempVars",
    }
}

impl ProjectWriter<'_> {
    /// Writes `variables` as lists in declaration order: consecutive variables of one list
    /// element and the same flags share a list.
    /// `owner` is the place of the POU whose variables they are (§5.5), `None` for a method.
    pub(super) fn variable_lists(
        &mut self,
        variables: &[Variable],
        owner: Option<&str>,
    ) -> Result<(), ExportError> {
        for run in runs(variables, |variable| list_element(variable.section)) {
            let element = run
                .first()
                .map_or("localVars", |variable| list_element(variable.section));
            let part = ListPart {
                name: None,
                entry_of: None,
                comment: "",
                owner,
            };
            self.variable_list(element, run, part)?;
        }
        Ok(())
    }

    /// Writes a global variable list as `globalVars` named after it (more than one when its
    /// variables' flags differ); the first carries its comment, the last its entries.
    pub(super) fn global_list(&mut self, list: &GlobalVarList) -> Result<(), ExportError> {
        self.xml.context = format!("global variable list '{}'", list.name);
        let name = list.name.as_str();
        let lists = runs(&list.variables, |_| "globalVars");
        if lists.is_empty() {
            self.xml.start("globalVars", &[("name", name)])?;
            self.list_add_data(list)?;
            self.documentation(&list.comment)?;
            return self.xml.end("globalVars");
        }
        let last = lists.len() - 1;
        let owner = format!("gvl:{name}");
        for (index, run) in lists.into_iter().enumerate() {
            let part = ListPart {
                name: Some(name),
                entry_of: (index == last).then_some(list),
                comment: if index == 0 { &list.comment } else { "" },
                owner: Some(&owner),
            };
            self.variable_list("globalVars", run, part)?;
        }
        Ok(())
    }

    /// One list element.
    fn variable_list(
        &mut self,
        element: &'static str,
        variables: &[Variable],
        part: ListPart<'_>,
    ) -> Result<(), ExportError> {
        let mut attributes = Vec::new();
        if let Some(name) = part.name {
            attributes.push(("name", name));
        }
        if let Some(first) = variables.first() {
            if first.constant {
                attributes.push(("constant", "true"));
            }
            if first.retain {
                attributes.push(("retain", "true"));
            }
            if first.persistent {
                attributes.push(("persistent", "true"));
            }
        }
        self.xml.start(element, &attributes)?;
        for variable in variables {
            let place = part
                .owner
                .map(|owner| format!("{owner}/variable:{}", variable.name));
            self.variable(variable, place.as_deref())?;
        }
        if let Some(list) = part.entry_of {
            self.list_add_data(list)?;
        }
        self.documentation(part.comment)?;
        self.xml.end(element)
    }

    fn variable(&mut self, variable: &Variable, place: Option<&str>) -> Result<(), ExportError> {
        let mut attributes = vec![("name", variable.name.as_str())];
        if let Some(address) = &variable.address {
            attributes.push(("address", address));
        }
        self.xml.start("variable", &attributes)?;
        self.xml.start("type", &[])?;
        write_type(&mut self.xml, &variable.ty)?;
        self.xml.end("type")?;
        if let Some(initial) = &variable.initial {
            self.xml.start("initialValue", &[])?;
            write_value(&mut self.xml, initial)?;
            self.xml.end("initialValue")?;
        }
        if let Some(place) = place {
            self.vendor_add_data(place)?;
        }
        self.documentation(&variable.comment)?;
        self.xml.end("variable")
    }

    /// Writes `documentation` with the text in an XHTML paragraph, unless the text is empty.
    pub(super) fn documentation(&mut self, text: &str) -> Result<(), ExportError> {
        if text.is_empty() {
            return Ok(());
        }
        self.xml.start("documentation", &[])?;
        self.formatted_text(text)?;
        self.xml.end("documentation")
    }

    /// Writes the content of a `formattedText`: `<xhtml:p>` with the text as CDATA, as Beremiz
    /// writes it.
    pub(super) fn formatted_text(&mut self, text: &str) -> Result<(), ExportError> {
        self.xml.start("xhtml:p", &[])?;
        self.xml.cdata(text)?;
        self.xml.end("xhtml:p")
    }
}

/// What a list element carries besides its variables.
struct ListPart<'a> {
    /// The list's `name` (global variable lists).
    name: Option<&'a str>,
    /// The list whose entries (vendor and Rivet's) the element carries.
    entry_of: Option<&'a GlobalVarList>,
    /// The list's comment, as `documentation`.
    comment: &'a str,
    /// The place of the variables' owner (§5.5), `None` for a method's.
    owner: Option<&'a str>,
}

/// Consecutive variables with the same list element and flags.
fn runs(variables: &[Variable], element: impl Fn(&Variable) -> &'static str) -> Vec<&[Variable]> {
    let key = |variable: &Variable| {
        (
            element(variable),
            variable.constant,
            variable.retain,
            variable.persistent,
        )
    };
    let mut runs = Vec::new();
    let mut start = 0;
    for at in 1..=variables.len() {
        if at == variables.len() || key(&variables[at]) != key(&variables[start]) {
            runs.push(&variables[start..at]);
            start = at;
        }
    }
    runs
}
