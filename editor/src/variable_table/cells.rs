//! The text columns of the declaration table: what each shows of a variable, how typed text goes
//! back into one, and what makes the text acceptable.

use std::collections::HashMap;

use project_model::Variable;

use crate::TableTexts;

/// A column edited as text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum TextColumn {
    Name,
    Address,
    Type,
    Initial,
    Comment,
}

impl TextColumn {
    /// The column's title in `texts`, also part of each cell's accessible label ("Address of
    /// xStart").
    pub(crate) fn title(self, texts: &TableTexts) -> &str {
        match self {
            Self::Name => &texts.name,
            Self::Address => &texts.address,
            Self::Type => &texts.data_type,
            Self::Initial => &texts.initial_value,
            Self::Comment => &texts.comment,
        }
    }

    /// What the cell shows of `variable`.
    pub(crate) fn text(self, variable: &Variable) -> String {
        match self {
            Self::Name => variable.name.clone(),
            Self::Address => variable.address.clone().unwrap_or_default(),
            Self::Type => variable.ty.clone(),
            Self::Initial => variable.initial.clone().unwrap_or_default(),
            Self::Comment => variable.comment.clone(),
        }
    }

    /// `variable` with this column set to `text`. An empty address or initial value means none;
    /// names, types and addresses lose surrounding spaces, which never mean anything there.
    pub(crate) fn with_text(self, variable: &Variable, text: &str) -> Variable {
        let mut changed = variable.clone();
        let optional = |text: &str| (!text.trim().is_empty()).then(|| text.trim().to_owned());
        match self {
            Self::Name => changed.name = text.trim().to_owned(),
            Self::Address => changed.address = optional(text),
            Self::Type => changed.ty = text.trim().to_owned(),
            Self::Initial => changed.initial = optional(text),
            Self::Comment => changed.comment = text.to_owned(),
        }
        changed
    }
}

/// Why the cell of `column` in row `row` cannot hold `text`, judged against the other rows and
/// the row's type; `None` when it can.
pub(crate) fn cell_error(
    variables: &[Variable],
    row: usize,
    column: TextColumn,
    text: &str,
) -> Option<String> {
    let variable = variables.get(row)?;
    let candidate = column.with_text(variable, text);
    match column {
        TextColumn::Name => name_error(variables, row, &candidate.name),
        TextColumn::Address => address_error(&candidate),
        TextColumn::Type if candidate.ty.is_empty() => {
            Some("every variable needs a type, such as BOOL or INT".to_owned())
        }
        TextColumn::Type | TextColumn::Initial | TextColumn::Comment => None,
    }
}

/// Why `name` cannot name row `row`: not an IEC identifier, or taken by another row (names are
/// compared without regard to case, as IEC 61131-3 does).
fn name_error(variables: &[Variable], row: usize, name: &str) -> Option<String> {
    if name.is_empty() {
        return Some("every variable needs a name".to_owned());
    }
    if !project_model::is_valid_identifier(name) {
        return Some(format!(
            "'{name}' is not an identifier: start with a letter or '_', then letters, digits or '_'"
        ));
    }
    let taken = variables
        .iter()
        .enumerate()
        .any(|(index, other)| index != row && project_model::same_identifier(&other.name, name));
    taken.then(|| format!("'{name}' is already declared here"))
}

/// Why `variable`'s address does not fit it, if it has one.
pub(crate) fn address_error(variable: &Variable) -> Option<String> {
    let address = variable.address.as_deref()?;
    compiler::ide::check_address(address, &variable.ty)
        .err()
        .map(|error| error.to_string())
}

/// The overlap warnings of a project grouped by variable name, for one declaring object: what
/// [`crate::VariableTable::show`] takes. `owner` is the POU or list shown (`POU.Method` for a
/// method's declarations).
pub fn overlap_warnings(
    overlaps: &[compiler::ide::Overlap],
    owner: &str,
) -> HashMap<String, String> {
    let mut warnings: HashMap<String, String> = HashMap::new();
    for overlap in overlaps {
        for located in [&overlap.first, &overlap.second] {
            if project_model::same_identifier(&located.owner, owner) {
                let entry = warnings.entry(located.name.clone()).or_default();
                if !entry.is_empty() {
                    entry.push('\n');
                }
                entry.push_str(&overlap.message());
            }
        }
    }
    warnings
}

/// A name for a new variable that no row uses yet: `Var1`, `Var2`, …
pub(crate) fn fresh_name(variables: &[Variable]) -> String {
    (1..)
        .map(|number| format!("Var{number}"))
        .find(|name| {
            !variables
                .iter()
                .any(|variable| project_model::same_identifier(&variable.name, name))
        })
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows() -> Vec<Variable> {
        vec![
            Variable::new("xStart", "BOOL"),
            Variable {
                address: Some("%QW4".to_owned()),
                ..Variable::new("rSpeed", "REAL")
            },
        ]
    }

    #[test]
    fn names_must_be_identifiers_and_unique_without_regard_to_case() {
        let rows = rows();
        assert!(cell_error(&rows, 1, TextColumn::Name, "XSTART").is_some());
        assert!(cell_error(&rows, 1, TextColumn::Name, "1x").is_some());
        assert!(cell_error(&rows, 1, TextColumn::Name, " ").is_some());
        assert_eq!(cell_error(&rows, 0, TextColumn::Name, "xStart"), None);
        assert_eq!(cell_error(&rows, 1, TextColumn::Name, "rSpeed2"), None);
        // Chinese names are identifiers, as in CODESYS with Unicode identifiers.
        assert_eq!(cell_error(&rows, 1, TextColumn::Name, "速度"), None);
    }

    #[test]
    fn addresses_are_checked_against_the_rows_type() {
        let rows = rows();
        let error = cell_error(&rows, 1, TextColumn::Address, "%QW4").unwrap();
        assert!(error.contains("use %QD2"), "{error}");
        assert_eq!(cell_error(&rows, 1, TextColumn::Address, "%QD2"), None);
        assert_eq!(cell_error(&rows, 1, TextColumn::Address, ""), None);
        assert_eq!(address_error(&rows[1]).as_deref(), Some(error.as_str()));
    }

    #[test]
    fn empty_optional_cells_clear_the_value() {
        let rows = rows();
        assert_eq!(TextColumn::Address.with_text(&rows[1], "  ").address, None);
        assert_eq!(
            TextColumn::Initial
                .with_text(&rows[0], " TRUE ")
                .initial
                .as_deref(),
            Some("TRUE")
        );
        assert_eq!(fresh_name(&rows), "Var1");
    }
}
