//! The words of the declaration table and the I/O mapping view, so the app can show them in the
//! user's language. Labels that name a variable are templates with `{name}`-style placeholders,
//! because languages put the parts in different orders ("Address of xStart", "xStart 的地址").

/// Every word the variable table and the I/O mapping view show; `Default` is English.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TableTexts {
    /// Column title: the variable's section (`VAR_INPUT`, …).
    pub section: String,
    /// Column title: the name.
    pub name: String,
    /// Column title: the direct address.
    pub address: String,
    /// Column title: the data type.
    pub data_type: String,
    /// Column title: the initial value.
    pub initial_value: String,
    /// Column title: the retain, persistent and constant flags.
    pub flags: String,
    /// Column title: the comment.
    pub comment: String,
    /// The retain flag, shown on hover of its check box.
    pub retain: String,
    /// The persistent flag.
    pub persistent: String,
    /// The constant flag.
    pub constant: String,
    /// Toolbar and menu entry: insert a variable above the selected row.
    pub insert_above: String,
    /// Toolbar and menu entry: insert a variable below the selected row.
    pub insert_below: String,
    /// Toolbar and menu entry: delete the selected variable.
    pub delete: String,
    /// Toolbar and menu entry: move the selected variable up.
    pub move_up: String,
    /// Toolbar and menu entry: move the selected variable down.
    pub move_down: String,
    /// The hover text of the handle that drags a variable.
    pub drag_hint: String,
    /// A cell's accessible label and the undo label of its change: `{column}`, `{name}`.
    pub cell_of: String,
    /// The accessible label of the drag handle: `{path}`.
    pub drag_path: String,
    /// The accessible label of an overlap warning mark: `{name}`, `{warning}`.
    pub warning_for: String,
    /// Undo label of an inserted variable: `{name}`.
    pub insert_variable: String,
    /// Undo label of a deleted variable: `{name}`.
    pub delete_variable: String,
    /// Undo label of a variable moved up: `{name}`.
    pub move_variable_up: String,
    /// Undo label of a variable moved down: `{name}`.
    pub move_variable_down: String,
    /// I/O mapping: the controller has no I/O areas.
    pub no_io_areas: String,
    /// I/O mapping: the heading of located variables that fall outside every area.
    pub outside_areas: String,
    /// I/O mapping: an input area.
    pub inputs: String,
    /// I/O mapping: an output area.
    pub outputs: String,
    /// I/O mapping: a marker area.
    pub markers: String,
    /// I/O mapping column: the channel's address.
    pub channel: String,
    /// I/O mapping column: the variable bound to a channel.
    pub variable: String,
    /// I/O mapping column: how the bound variable is declared.
    pub declared_as: String,
    /// I/O mapping column: the Modbus table of a binding.
    pub modbus_table: String,
    /// I/O mapping: a Modbus device without bindings.
    pub no_binding: String,
    /// I/O mapping: a binding naming a variable that is not declared: `{path}`.
    pub not_declared: String,
    /// Modbus table: coils.
    pub coil: String,
    /// Modbus table: discrete inputs.
    pub discrete_input: String,
    /// Modbus table: holding registers.
    pub holding_register: String,
    /// Modbus table: input registers.
    pub input_register: String,
}

impl Default for TableTexts {
    fn default() -> Self {
        let s = str::to_owned;
        Self {
            section: s("Section"),
            name: s("Name"),
            address: s("Address"),
            data_type: s("Type"),
            initial_value: s("Initial value"),
            flags: s("Flags"),
            comment: s("Comment"),
            retain: s("Retain"),
            persistent: s("Persistent"),
            constant: s("Constant"),
            insert_above: s("Insert above"),
            insert_below: s("Insert below"),
            delete: s("Delete"),
            move_up: s("Move up"),
            move_down: s("Move down"),
            drag_hint: s("Drag into a watch list"),
            cell_of: s("{column} of {name}"),
            drag_path: s("Drag {path}"),
            warning_for: s("Warning for {name}: {warning}"),
            insert_variable: s("Insert variable {name}"),
            delete_variable: s("Delete variable {name}"),
            move_variable_up: s("Move {name} up"),
            move_variable_down: s("Move {name} down"),
            no_io_areas: s("The controller has no I/O areas"),
            outside_areas: s("Located variables outside every I/O area"),
            inputs: s("inputs"),
            outputs: s("outputs"),
            markers: s("markers"),
            channel: s("Channel"),
            variable: s("Variable"),
            declared_as: s("Declared as"),
            modbus_table: s("Table"),
            no_binding: s("No variable is bound to this device"),
            not_declared: s("{path} (not declared)"),
            coil: s("Coil"),
            discrete_input: s("Discrete input"),
            holding_register: s("Holding register"),
            input_register: s("Input register"),
        }
    }
}

/// `template` with each `{key}` replaced by its value.
pub(crate) fn fill(template: &str, values: &[(&str, &str)]) -> String {
    values
        .iter()
        .fold(template.to_owned(), |text, (key, value)| {
            text.replace(&format!("{{{key}}}"), value)
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn templates_take_their_parts_in_any_order() {
        let english = TableTexts::default();
        assert_eq!(
            fill(
                &english.cell_of,
                &[("column", "Address"), ("name", "xStart")]
            ),
            "Address of xStart"
        );
        assert_eq!(
            fill(
                "{name} 的{column}",
                &[("column", "地址"), ("name", "xStart")]
            ),
            "xStart 的地址"
        );
    }
}
