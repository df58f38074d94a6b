//! The cells of a channel row that only a device the runtime masters has: count (the studio's
//! own poll reads one value per channel), direction, function code (the choices
//! `docs/modbus-master.md` §2.2 allows for the table, direction and size), trigger and trigger
//! variable, what a read channel holds on error, and the error flag.

use compiler::ide::check_channel_variable;
use egui::{RichText, Ui};
use project_model::{
    ChannelDirection, ChannelErrorAction, ChannelTrigger, ModbusBinding, ModbusDataType,
    ModbusTable, Project,
};

use super::DeviceTexts;
use super::form::Form;
use super::refusal::Refusal;
use super::texts::fill;

/// Draws the master's cells of `binding`'s row, each a column of the channel table.
pub(crate) fn channel_master_cells_ui(
    ui: &mut Ui,
    row: &mut Form<'_, ModbusBinding>,
    project: &Project,
    texts: &DeviceTexts,
    binding: &ModbusBinding,
) {
    // A count the variable does not fit is taken, and the row says why it does not fit: going
    // from one value to an array changes the count and the variable in two edits.
    row.field("count", &texts.count, 50.0).whole_ui(
        ui,
        binding.count,
        0..=u16::MAX,
        |item, count| item.count = count,
    );
    let directions = [
        (texts.read.clone(), ChannelDirection::Read),
        (texts.write.clone(), ChannelDirection::Write),
    ];
    row.field("direction", &texts.direction, 70.0).combo_ui(
        ui,
        binding.direction,
        &directions,
        |item, direction| {
            // A function code and an error action belong to one direction only: the other
            // direction's would be a problem the user did not ask for.
            item.direction = direction;
            item.function_code = None;
            item.on_error = ChannelErrorAction::KeepLastValue;
        },
    );
    let codes = function_code_choices(texts, binding);
    row.field("function code", &texts.function_code, 190.0)
        .combo_ui(ui, binding.function_code, &codes, |item, code| {
            item.function_code = code
        });
    let triggers = [
        (texts.cyclic.clone(), ChannelTrigger::Cyclic),
        (texts.rising_edge.clone(), ChannelTrigger::RisingEdge),
    ];
    // A rising edge without its variable is refused by the model, so choosing it waits for the
    // variable: the trigger shows "Rising edge" and the variable's field asks for one, whose
    // edit sets both.
    row.field("trigger", &texts.trigger, 100.0)
        .pending_combo_ui(
            ui,
            binding.trigger,
            &triggers,
            |trigger| trigger == ChannelTrigger::RisingEdge && binding.trigger_variable.is_none(),
            |item, trigger| {
                item.trigger = trigger;
                if trigger == ChannelTrigger::Cyclic {
                    item.trigger_variable = None;
                }
                Ok(())
            },
        );
    let hint = if row.is_pending("trigger") {
        texts.trigger_variable_hint.as_str()
    } else {
        ""
    };
    let trigger_variable = binding.trigger_variable.clone().unwrap_or_default();
    row.field("trigger variable", &texts.trigger_variable, 150.0)
        .suffix(hint)
        .typed_ui(ui, &trigger_variable, |item, text| {
            // Naming a trigger variable asks for the rising edge it triggers on; clearing it
            // makes the channel cyclic again.
            item.trigger_variable = bool_variable(project, text)?;
            item.trigger = if item.trigger_variable.is_some() {
                ChannelTrigger::RisingEdge
            } else {
                ChannelTrigger::Cyclic
            };
            Ok(text.to_owned())
        });
    if binding.direction == ChannelDirection::Read {
        let actions = [
            (
                texts.keep_last_value.clone(),
                ChannelErrorAction::KeepLastValue,
            ),
            (texts.set_to_zero.clone(), ChannelErrorAction::SetToZero),
        ];
        row.field("on error", &texts.on_error, 120.0).combo_ui(
            ui,
            binding.on_error,
            &actions,
            |item, action| item.on_error = action,
        );
    } else {
        ui.label(RichText::new(&texts.not_applicable).weak());
    }
    let error_flag = binding.error_flag.clone().unwrap_or_default();
    row.field("error flag", &texts.error_flag, 150.0)
        .typed_ui(ui, &error_flag, |item, text| {
            item.error_flag = bool_variable(project, text)?;
            Ok(text.to_owned())
        });
}

/// The function codes a channel may choose: the default of its table and direction (none
/// stored), the single write (5 or 6) when the channel is one coil or register, the multiple
/// write (15 or 16); a read has only its default. A code the file holds that is none of these
/// is offered too, so the cell shows it (the device checks say why it does not fit).
pub(crate) fn function_code_choices(
    texts: &DeviceTexts,
    binding: &ModbusBinding,
) -> Vec<(String, Option<u8>)> {
    let coils = binding.table == ModbusTable::Coil;
    let default_code = binding.default_function_code();
    let mut choices = vec![(
        fill(&texts.default_code, &[("code", &default_code.to_string())]),
        None,
    )];
    let writable = matches!(
        binding.table,
        ModbusTable::Coil | ModbusTable::HoldingRegister
    );
    if binding.direction == ChannelDirection::Write && writable {
        let (single, multiple) = if coils {
            (&texts.write_single_coil, &texts.write_multiple_coils)
        } else {
            (
                &texts.write_single_register,
                &texts.write_multiple_registers,
            )
        };
        if binding.span() == 1 {
            choices.push((single.clone(), Some(if coils { 5 } else { 6 })));
        }
        choices.push((multiple.clone(), Some(if coils { 15 } else { 16 })));
    }
    if let Some(code) = binding.function_code
        && !choices.iter().any(|(_, choice)| *choice == Some(code))
    {
        choices.push((code.to_string(), Some(code)));
    }
    choices
}

/// `None` for an empty path, else the path when it names a BOOL of the project (a trigger
/// variable or an error flag).
fn bool_variable(project: &Project, text: &str) -> Result<Option<String>, Refusal> {
    if text.is_empty() {
        return Ok(None);
    }
    check_channel_variable(project, text, ModbusDataType::Bool)?;
    Ok(Some(text.to_owned()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn codes(binding: &ModbusBinding) -> Vec<Option<u8>> {
        function_code_choices(&DeviceTexts::default(), binding)
            .into_iter()
            .map(|(_, code)| code)
            .collect()
    }

    #[test]
    fn a_read_offers_only_its_table_s_code_named_in_the_default() {
        let binding = ModbusBinding::new(
            "GVL.iIn",
            ModbusTable::InputRegister,
            0,
            ModbusDataType::Int16,
        );
        let choices = function_code_choices(&DeviceTexts::default(), &binding);
        assert_eq!(choices, vec![("Default (4)".to_owned(), None)]);
    }

    #[test]
    fn a_write_of_one_register_offers_6_and_16_and_a_wider_one_only_16() {
        let mut binding = ModbusBinding::new(
            "GVL.iOut",
            ModbusTable::HoldingRegister,
            0,
            ModbusDataType::Int16,
        );
        binding.direction = ChannelDirection::Write;
        assert_eq!(codes(&binding), vec![None, Some(6), Some(16)]);
        binding.data_type = ModbusDataType::Real;
        assert_eq!(codes(&binding), vec![None, Some(16)]);
        let mut coil = ModbusBinding::new("GVL.x", ModbusTable::Coil, 0, ModbusDataType::Bool);
        coil.direction = ChannelDirection::Write;
        assert_eq!(codes(&coil), vec![None, Some(5), Some(15)]);
        coil.count = 8;
        assert_eq!(codes(&coil), vec![None, Some(15)]);
    }

    #[test]
    fn a_code_that_does_not_fit_is_still_shown() {
        let mut binding = ModbusBinding::new(
            "GVL.iOut",
            ModbusTable::HoldingRegister,
            0,
            ModbusDataType::Real,
        );
        binding.direction = ChannelDirection::Write;
        binding.function_code = Some(6);
        assert_eq!(codes(&binding), vec![None, Some(16), Some(6)]);
    }

    #[test]
    fn trigger_variables_and_error_flags_are_bools_or_nothing() {
        let project = project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        assert_eq!(bool_variable(&project, ""), Ok(None));
        assert_eq!(
            bool_variable(&project, "GVL_Machine.xDriveReady"),
            Ok(Some("GVL_Machine.xDriveReady".into()))
        );
        let wrong = bool_variable(&project, "GVL_Machine.rBeltSpeedActual").unwrap_err();
        assert!(wrong.to_string().contains("declare it as BOOL"), "{wrong}");
    }
}
