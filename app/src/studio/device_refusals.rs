//! The device editors' refusals in the user's language: every [`Refusal`] and every
//! [`DeviceProblem`] mapped to a template of [`Text`], so a new variant cannot compile without
//! its words.

use compiler::ide::{AddressError, ChannelVariableError};
use editor::{Refusal, RefusalWords};
use project_model::{DeviceProblem, ModbusTable};

use super::i18n::{Language, Text};

/// The words the device editors give a refusal in `language`.
pub(crate) fn refusal_words(language: Language) -> RefusalWords {
    RefusalWords::new(move |refusal| describe_refusal(refusal, language))
}

/// Why a device editor refused a value, in `language`.
pub(crate) fn describe_refusal(refusal: &Refusal, language: Language) -> String {
    let fill = |text: Text, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    match refusal {
        Refusal::Problem(problem) => describe_problem(problem, language),
        Refusal::Address(error) => describe_address(error, language),
        Refusal::ChannelVariable(error) => describe_channel_variable(error, language),
        Refusal::BitTableAddress { address } => {
            fill(Text::DeviceBitTableAddress, &[("address", address)])
        }
        Refusal::RegisterTableAddress { address } => {
            fill(Text::DeviceRegisterTableAddress, &[("address", address)])
        }
        Refusal::NotANumber { text } => fill(Text::DeviceNotANumber, &[("text", text)]),
        Refusal::NotAWholeNumber { text, min, max } => fill(
            Text::DeviceNotAWholeNumber,
            &[("text", text), ("min", min), ("max", max)],
        ),
    }
}

/// A problem of a device tree node's settings, in `language`.
pub(crate) fn describe_problem(problem: &DeviceProblem, language: Language) -> String {
    let fill = |text: Text, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    let word = |english: &str| word(english, language);
    match problem {
        DeviceProblem::InvalidName { kind, name } => fill(
            Text::DeviceProblemInvalidName,
            &[("kind", &word(kind)), ("name", name)],
        ),
        DeviceProblem::DuplicateName { kind, name } => fill(
            Text::DeviceProblemDuplicateName,
            &[("kind", &word(kind)), ("name", name)],
        ),
        DeviceProblem::EmptyHost => fill(Text::DeviceProblemEmptyHost, &[]),
        DeviceProblem::ZeroPort => fill(Text::DeviceProblemZeroPort, &[]),
        DeviceProblem::EmptyRangeAddress { row } => fill(
            Text::DeviceProblemEmptyRangeAddress,
            &[("row", &row.to_string())],
        ),
        DeviceProblem::EmptyRange { row } => {
            fill(Text::DeviceProblemEmptyRange, &[("row", &row.to_string())])
        }
        DeviceProblem::RangePastEnd { row, start, count } => fill(
            Text::DeviceProblemRangePastEnd,
            &[
                ("row", &row.to_string()),
                ("start", &start.to_string()),
                ("count", &count.to_string()),
            ],
        ),
        DeviceProblem::RangesOverlap { row, other } => fill(
            Text::DeviceProblemRangesOverlap,
            &[("row", &row.to_string()), ("other", &other.to_string())],
        ),
        DeviceProblem::ZeroSize => fill(Text::DeviceProblemZeroSize, &[]),
        DeviceProblem::AreaPastEnd {
            start_byte,
            size_bytes,
            limit,
        } => fill(
            Text::DeviceProblemAreaPastEnd,
            &[
                ("start_byte", &start_byte.to_string()),
                ("size_bytes", &size_bytes.to_string()),
                ("limit", &limit.to_string()),
            ],
        ),
        DeviceProblem::AreasOverlap {
            direction,
            first,
            last,
            other,
        } => {
            let byte = |number: u32| format!("%{}B{number}", direction.area_letter());
            if first == last {
                fill(
                    Text::DeviceProblemAreaByteOverlaps,
                    &[("byte", &byte(*first)), ("other", other)],
                )
            } else {
                fill(
                    Text::DeviceProblemAreaBytesOverlap,
                    &[
                        ("first", &byte(*first)),
                        ("last", &byte(*last)),
                        ("other", other),
                    ],
                )
            }
        }
        DeviceProblem::ZeroPollInterval => fill(Text::DeviceProblemZeroPollInterval, &[]),
        DeviceProblem::ZeroTimeout => fill(Text::DeviceProblemZeroTimeout, &[]),
        DeviceProblem::EmptyVariable { row } => fill(
            Text::DeviceProblemEmptyVariable,
            &[("row", &row.to_string())],
        ),
        DeviceProblem::InvalidVariable { row, variable } => fill(
            Text::DeviceProblemInvalidVariable,
            &[("row", &row.to_string()), ("variable", variable)],
        ),
        DeviceProblem::ChannelPastEnd {
            row,
            address,
            width,
        } => fill(
            Text::DeviceProblemChannelPastEnd,
            &[
                ("row", &row.to_string()),
                ("address", &address.to_string()),
                ("width", &width.to_string()),
            ],
        ),
        DeviceProblem::ChannelsOverlap {
            row,
            variable,
            other,
            other_variable,
        } => fill(
            Text::DeviceProblemChannelsOverlap,
            &[
                ("row", &row.to_string()),
                ("variable", variable),
                ("other", &other.to_string()),
                ("other_variable", other_variable),
            ],
        ),
        DeviceProblem::TableTypeMismatch {
            row,
            table,
            data_type,
        } => fill(
            Text::DeviceProblemTableTypeMismatch,
            &[
                ("row", &row.to_string()),
                ("table", &table_word(*table, language)),
                ("data_type", data_type.iec_name()),
            ],
        ),
        DeviceProblem::NoSuchTask(task) => fill(Text::DeviceProblemNoSuchTask, &[("task", task)]),
        DeviceProblem::EmptyUnit => fill(Text::DeviceProblemEmptyUnit, &[]),
        DeviceProblem::NotFinite { field } => {
            fill(Text::DeviceProblemNotFinite, &[("field", &word(field))])
        }
        DeviceProblem::ModuloNotPositive(value) => fill(
            Text::DeviceProblemModuloNotPositive,
            &[("value", &value.to_string())],
        ),
        DeviceProblem::LimitsInverted { min, max } => fill(
            Text::DeviceProblemLimitsInverted,
            &[("min", &min.to_string()), ("max", &max.to_string())],
        ),
        DeviceProblem::DynamicLimitNotPositive { field, value } => fill(
            Text::DeviceProblemDynamicLimitNotPositive,
            &[("field", &word(field)), ("value", &value.to_string())],
        ),
        DeviceProblem::ZeroScaling { field } => {
            fill(Text::DeviceProblemZeroScaling, &[("field", &word(field))])
        }
    }
}

/// Why a text is not a direct address, in `language`.
fn describe_address(error: &AddressError, language: Language) -> String {
    let fill = |text: Text, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    match error {
        AddressError::NoPercent { text } => fill(Text::DeviceAddressNoPercent, &[("text", text)]),
        AddressError::NoArea { text } => fill(Text::DeviceAddressNoArea, &[("text", text)]),
        AddressError::NoSize { text } => fill(Text::DeviceAddressNoSize, &[("text", text)]),
        AddressError::NotANumber { text, part } => fill(
            Text::DeviceAddressNotANumber,
            &[("text", text), ("part", part)],
        ),
        AddressError::NoSuchBit { text, bit } => fill(
            Text::DeviceAddressNoSuchBit,
            &[("text", text), ("bit", &bit.to_string())],
        ),
    }
}

/// Why a variable cannot be bound to a channel, in `language`.
fn describe_channel_variable(error: &ChannelVariableError, language: Language) -> String {
    let fill = |text: Text, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    match error {
        ChannelVariableError::NoSuchVariable(path) => {
            fill(Text::DeviceNoSuchVariable, &[("path", path)])
        }
        ChannelVariableError::TypeMismatch {
            path,
            declared,
            data_type,
            expected,
        } => {
            // The fitting types come joined by the English "or": `UINT or WORD`.
            let or = format!(" {} ", Text::DeviceWordOr.get(language));
            let expected = expected.replace(" or ", &or);
            fill(
                Text::DeviceVariableTypeMismatch,
                &[
                    ("path", path),
                    ("declared", declared),
                    ("data_type", data_type),
                    ("expected", &expected),
                ],
            )
        }
    }
}

/// A Modbus table's name inside a sentence: `holding register`.
fn table_word(table: ModbusTable, language: Language) -> String {
    let text = match table {
        ModbusTable::Coil => Text::DeviceCoil,
        ModbusTable::DiscreteInput => Text::DeviceDiscreteInput,
        ModbusTable::HoldingRegister => Text::DeviceHoldingRegister,
        ModbusTable::InputRegister => Text::DeviceInputRegister,
    };
    text.get(language).to_lowercase()
}

/// The word `project_model`'s checks name a node kind or an axis field with, in `language`; a
/// word the checks start using before it is translated here stays in English.
fn word(english: &str, language: Language) -> String {
    let text = match english {
        "controller" => Text::DeviceWordController,
        "I/O area" => Text::DeviceWordIoArea,
        "Modbus device" => Text::DeviceWordModbusDevice,
        "axis" => Text::DeviceWordAxis,
        "modulo period" => Text::DeviceWordModuloPeriod,
        "negative software limit" => Text::DeviceWordNegativeSoftwareLimit,
        "positive software limit" => Text::DeviceWordPositiveSoftwareLimit,
        "velocity" => Text::DeviceWordVelocity,
        "acceleration" => Text::DeviceWordAcceleration,
        "deceleration" => Text::DeviceWordDeceleration,
        "jerk" => Text::DeviceWordJerk,
        "scaling numerator" => Text::DeviceWordScalingNumerator,
        "scaling denominator" => Text::DeviceWordScalingDenominator,
        "numerator" => Text::DeviceWordNumerator,
        "denominator" => Text::DeviceWordDenominator,
        other => return other.to_owned(),
    };
    text.get(language).to_owned()
}

/// `template` with each `{key}` replaced by its value.
fn fill(template: &str, pairs: &[(&str, &str)]) -> String {
    pairs
        .iter()
        .fold(template.to_owned(), |text, (key, value)| {
            text.replace(&format!("{{{key}}}"), value)
        })
}

#[cfg(test)]
#[path = "device_refusals_tests.rs"]
mod tests;
