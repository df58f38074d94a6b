//! The device editors' refusals in the user's language: every [`Refusal`] and every
//! [`DeviceProblem`] mapped to a template of [`DeviceText`], so a new variant cannot compile without
//! its words.

use compiler::ide::{AddressError, ChannelBindingError, ChannelVariableError, Unplaceable};
use editor::{Refusal, RefusalWords};
use project_model::{ChannelDirection, DeviceProblem, ModbusTable};

use super::i18n::{DeviceText, Language};

/// The words the device editors give a refusal in `language`.
pub(crate) fn refusal_words(language: Language) -> RefusalWords {
    RefusalWords::new(move |refusal| describe_refusal(refusal, language))
}

/// Why a device editor refused a value, in `language`.
pub(crate) fn describe_refusal(refusal: &Refusal, language: Language) -> String {
    let fill = |text: DeviceText, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    match refusal {
        Refusal::Problem(problem) => describe_problem(problem, language),
        Refusal::Address(error) => describe_address(error, language),
        Refusal::ChannelVariable(error) => describe_channel_variable(error, language),
        Refusal::ChannelBinding(error) => describe_channel_binding(error, language),
        Refusal::BitTableAddress { address } => {
            fill(DeviceText::BitTableAddress, &[("address", address)])
        }
        Refusal::RegisterTableAddress { address } => {
            fill(DeviceText::RegisterTableAddress, &[("address", address)])
        }
        Refusal::NoSerialPorts => fill(DeviceText::NoSerialPorts, &[]),
        Refusal::NotANumber { text } => fill(DeviceText::NotANumber, &[("text", text)]),
        Refusal::NotAWholeNumber { text, min, max } => fill(
            DeviceText::NotAWholeNumber,
            &[("text", text), ("min", min), ("max", max)],
        ),
    }
}

/// A problem of a device tree node's settings, in `language`.
pub(crate) fn describe_problem(problem: &DeviceProblem, language: Language) -> String {
    let fill = |text: DeviceText, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    let word = |english: &str| word(english, language);
    match problem {
        DeviceProblem::InvalidName { kind, name } => fill(
            DeviceText::ProblemInvalidName,
            &[("kind", &word(kind)), ("name", name)],
        ),
        DeviceProblem::DuplicateName { kind, name } => fill(
            DeviceText::ProblemDuplicateName,
            &[("kind", &word(kind)), ("name", name)],
        ),
        DeviceProblem::EmptyHost => fill(DeviceText::ProblemEmptyHost, &[]),
        DeviceProblem::ZeroPort => fill(DeviceText::ProblemZeroPort, &[]),
        DeviceProblem::EmptyRangeAddress { row } => fill(
            DeviceText::ProblemEmptyRangeAddress,
            &[("row", &row.to_string())],
        ),
        DeviceProblem::EmptyRange { row } => {
            fill(DeviceText::ProblemEmptyRange, &[("row", &row.to_string())])
        }
        DeviceProblem::RangePastEnd { row, start, count } => fill(
            DeviceText::ProblemRangePastEnd,
            &[
                ("row", &row.to_string()),
                ("start", &start.to_string()),
                ("count", &count.to_string()),
            ],
        ),
        DeviceProblem::RangesOverlap { row, other } => fill(
            DeviceText::ProblemRangesOverlap,
            &[("row", &row.to_string()), ("other", &other.to_string())],
        ),
        DeviceProblem::ZeroSize => fill(DeviceText::ProblemZeroSize, &[]),
        DeviceProblem::AreaPastEnd {
            start_byte,
            size_bytes,
            limit,
        } => fill(
            DeviceText::ProblemAreaPastEnd,
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
                    DeviceText::ProblemAreaByteOverlaps,
                    &[("byte", &byte(*first)), ("other", other)],
                )
            } else {
                fill(
                    DeviceText::ProblemAreaBytesOverlap,
                    &[
                        ("first", &byte(*first)),
                        ("last", &byte(*last)),
                        ("other", other),
                    ],
                )
            }
        }
        DeviceProblem::ZeroPollInterval => fill(DeviceText::ProblemZeroPollInterval, &[]),
        DeviceProblem::ZeroTimeout => fill(DeviceText::ProblemZeroTimeout, &[]),
        DeviceProblem::EmptyVariable { row } => fill(
            DeviceText::ProblemEmptyVariable,
            &[("row", &row.to_string())],
        ),
        DeviceProblem::InvalidVariable { row, variable } => fill(
            DeviceText::ProblemInvalidVariable,
            &[("row", &row.to_string()), ("variable", variable)],
        ),
        DeviceProblem::ChannelPastEnd {
            row,
            address,
            width,
        } => fill(
            DeviceText::ProblemChannelPastEnd,
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
            DeviceText::ProblemChannelsOverlap,
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
            DeviceText::ProblemTableTypeMismatch,
            &[
                ("row", &row.to_string()),
                ("table", &table_word(*table, language)),
                ("data_type", data_type.iec_name()),
            ],
        ),
        DeviceProblem::EmptySerialPort => fill(DeviceText::ProblemEmptySerialPort, &[]),
        DeviceProblem::NoSuchSerialPort(port) => {
            fill(DeviceText::ProblemNoSuchSerialPort, &[("port", port)])
        }
        DeviceProblem::RtuWithoutTask => fill(DeviceText::ProblemRtuWithoutTask, &[]),
        DeviceProblem::RtuUnitId(unit_id) => fill(
            DeviceText::ProblemRtuUnitId,
            &[("unit_id", &unit_id.to_string())],
        ),
        DeviceProblem::TimeoutTooLong(timeout_ms) => fill(
            DeviceText::ProblemTimeoutTooLong,
            &[("timeout_ms", &timeout_ms.to_string())],
        ),
        DeviceProblem::PollIntervalTooLong(poll_interval_ms) => fill(
            DeviceText::ProblemPollIntervalTooLong,
            &[("poll_interval_ms", &poll_interval_ms.to_string())],
        ),
        DeviceProblem::MissingPollInterval => fill(DeviceText::ProblemMissingPollInterval, &[]),
        DeviceProblem::ReadGapTooLarge(gap) => fill(
            DeviceText::ProblemReadGapTooLarge,
            &[("gap", &gap.to_string())],
        ),
        DeviceProblem::ZeroCount { row } => {
            fill(DeviceText::ProblemZeroCount, &[("row", &row.to_string())])
        }
        DeviceProblem::ChannelTooLong {
            row,
            count,
            span,
            limit,
        } => fill(
            DeviceText::ProblemChannelTooLong,
            &[
                ("row", &row.to_string()),
                ("count", &count.to_string()),
                ("span", &span.to_string()),
                ("limit", &limit.to_string()),
            ],
        ),
        DeviceProblem::WriteToReadOnlyTable { row, table } => fill(
            DeviceText::ProblemWriteToReadOnlyTable,
            &[
                ("row", &row.to_string()),
                ("table", &table_word(*table, language)),
            ],
        ),
        DeviceProblem::FunctionCodeOnRead { row, code } => fill(
            DeviceText::ProblemFunctionCodeOnRead,
            &[("row", &row.to_string()), ("code", &code.to_string())],
        ),
        DeviceProblem::FunctionCodeMisfit { row, code, table } => fill(
            DeviceText::ProblemFunctionCodeMisfit,
            &[
                ("row", &row.to_string()),
                ("code", &code.to_string()),
                ("table", &table_word(*table, language)),
            ],
        ),
        DeviceProblem::SingleWriteTooWide { row, code, span } => fill(
            DeviceText::ProblemSingleWriteTooWide,
            &[
                ("row", &row.to_string()),
                ("code", &code.to_string()),
                ("span", &span.to_string()),
            ],
        ),
        DeviceProblem::TriggerVariableWithoutEdge { row } => fill(
            DeviceText::ProblemTriggerVariableWithoutEdge,
            &[("row", &row.to_string())],
        ),
        DeviceProblem::EdgeWithoutTriggerVariable { row } => fill(
            DeviceText::ProblemEdgeWithoutTriggerVariable,
            &[("row", &row.to_string())],
        ),
        DeviceProblem::OnErrorOnWrite { row } => fill(
            DeviceText::ProblemOnErrorOnWrite,
            &[("row", &row.to_string())],
        ),
        DeviceProblem::EmptyDevice => fill(DeviceText::ProblemEmptyDevice, &[]),
        DeviceProblem::UnsupportedBaudRate(baud_rate) => fill(
            DeviceText::ProblemUnsupportedBaudRate,
            &[("baud_rate", &baud_rate.to_string())],
        ),
        DeviceProblem::UnsupportedDataBits(data_bits) => fill(
            DeviceText::ProblemUnsupportedDataBits,
            &[("data_bits", &data_bits.to_string())],
        ),
        DeviceProblem::UnsupportedStopBits(stop_bits) => fill(
            DeviceText::ProblemUnsupportedStopBits,
            &[("stop_bits", &stop_bits.to_string())],
        ),
        DeviceProblem::InterFrameDelayTooLong(delay_us) => fill(
            DeviceText::ProblemInterFrameDelayTooLong,
            &[("delay_us", &delay_us.to_string())],
        ),
        DeviceProblem::NoSuchTask(task) => fill(DeviceText::ProblemNoSuchTask, &[("task", task)]),
        DeviceProblem::EmptyUnit => fill(DeviceText::ProblemEmptyUnit, &[]),
        DeviceProblem::NotFinite { field } => {
            fill(DeviceText::ProblemNotFinite, &[("field", &word(field))])
        }
        DeviceProblem::ModuloNotPositive(value) => fill(
            DeviceText::ProblemModuloNotPositive,
            &[("value", &value.to_string())],
        ),
        DeviceProblem::LimitsInverted { min, max } => fill(
            DeviceText::ProblemLimitsInverted,
            &[("min", &min.to_string()), ("max", &max.to_string())],
        ),
        DeviceProblem::DynamicLimitNotPositive { field, value } => fill(
            DeviceText::ProblemDynamicLimitNotPositive,
            &[("field", &word(field)), ("value", &value.to_string())],
        ),
        DeviceProblem::ZeroScaling { field } => {
            fill(DeviceText::ProblemZeroScaling, &[("field", &word(field))])
        }
    }
}

/// Why a text is not a direct address, in `language`.
fn describe_address(error: &AddressError, language: Language) -> String {
    let fill = |text: DeviceText, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    match error {
        AddressError::NoPercent { text } => fill(DeviceText::AddressNoPercent, &[("text", text)]),
        AddressError::NoArea { text } => fill(DeviceText::AddressNoArea, &[("text", text)]),
        AddressError::NoSize { text } => fill(DeviceText::AddressNoSize, &[("text", text)]),
        AddressError::NotANumber { text, part } => fill(
            DeviceText::AddressNotANumber,
            &[("text", text), ("part", part)],
        ),
        AddressError::NoSuchBit { text, bit } => fill(
            DeviceText::AddressNoSuchBit,
            &[("text", text), ("bit", &bit.to_string())],
        ),
    }
}

/// Why a variable cannot be bound to a channel, in `language`.
fn describe_channel_variable(error: &ChannelVariableError, language: Language) -> String {
    let fill = |text: DeviceText, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    match error {
        ChannelVariableError::NoSuchVariable(path) => {
            fill(DeviceText::NoSuchVariable, &[("path", path)])
        }
        ChannelVariableError::TypeMismatch {
            path,
            declared,
            data_type,
            expected,
        } => {
            let expected = joined_by_or(expected, language);
            fill(
                DeviceText::VariableTypeMismatch,
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

/// Why a variable does not fit a runtime device's channel (its data type and count), in
/// `language`.
fn describe_channel_binding(error: &ChannelBindingError, language: Language) -> String {
    let fill = |text: DeviceText, pairs: &[(&str, &str)]| fill(text.get(language), pairs);
    match error {
        ChannelBindingError::NoSuchVariable(path) => {
            fill(DeviceText::NoSuchVariable, &[("path", path)])
        }
        ChannelBindingError::NoFixedPlace { path, what } => fill(
            DeviceText::BindingNoFixedPlace,
            &[
                ("path", path),
                ("what", unplaceable_word(*what).get(language)),
            ],
        ),
        ChannelBindingError::StaticElsewhere { path, symbol } => fill(
            DeviceText::BindingStaticElsewhere,
            &[("path", path), ("symbol", symbol)],
        ),
        ChannelBindingError::Constant { path } => {
            fill(DeviceText::BindingConstant, &[("path", path)])
        }
        ChannelBindingError::AtBitAddress {
            path,
            address,
            count,
        } => fill(
            DeviceText::BindingAtBitAddress,
            &[
                ("path", path),
                ("address", address),
                ("count", &count.to_string()),
            ],
        ),
        ChannelBindingError::Misfit { path, misfit } => {
            // The data type as the project file and the build's message spell it.
            let data_type = misfit.data_type.file_name();
            let values = if misfit.count == 1 {
                fill(DeviceText::OneChannelValue, &[("data_type", data_type)])
            } else {
                fill(
                    DeviceText::ChannelValues,
                    &[
                        ("count", &misfit.count.to_string()),
                        ("data_type", data_type),
                    ],
                )
            };
            let expected = joined_by_or(&misfit.expected, language);
            let template = match misfit.direction {
                ChannelDirection::Read => DeviceText::ChannelMisfitReads,
                ChannelDirection::Write => DeviceText::ChannelMisfitWrites,
            };
            fill(
                template,
                &[
                    ("path", path),
                    ("values", &values),
                    ("declared", &misfit.declared),
                    ("expected", &expected),
                ],
            )
        }
    }
}

/// The fitting types or declarations joined by the word "or" of `language`: `UINT or WORD`.
fn joined_by_or(expected: &[String], language: Language) -> String {
    expected.join(&format!(" {} ", DeviceText::WordOr.get(language)))
}

/// What a bound path names that has no place between cycles, in a sentence.
fn unplaceable_word(what: Unplaceable) -> DeviceText {
    match what {
        Unplaceable::VarTemp => DeviceText::UnplaceableVarTemp,
        Unplaceable::VarInOut => DeviceText::UnplaceableVarInOut,
        Unplaceable::VarExternal => DeviceText::UnplaceableVarExternal,
        Unplaceable::FunctionVariable => DeviceText::UnplaceableFunctionVariable,
        Unplaceable::Method => DeviceText::UnplaceableMethod,
        Unplaceable::Property => DeviceText::UnplaceableProperty,
        Unplaceable::AxisOrCam => DeviceText::UnplaceableAxisOrCam,
    }
}

/// A Modbus table's name inside a sentence: `holding register`.
fn table_word(table: ModbusTable, language: Language) -> String {
    let text = match table {
        ModbusTable::Coil => DeviceText::Coil,
        ModbusTable::DiscreteInput => DeviceText::DiscreteInput,
        ModbusTable::HoldingRegister => DeviceText::HoldingRegister,
        ModbusTable::InputRegister => DeviceText::InputRegister,
    };
    text.get(language).to_lowercase()
}

/// The word `project_model`'s checks name a node kind or an axis field with, in `language`; a
/// word the checks start using before it is translated here stays in English.
fn word(english: &str, language: Language) -> String {
    let text = match english {
        "controller" => DeviceText::WordController,
        "I/O area" => DeviceText::WordIoArea,
        "Modbus device" => DeviceText::WordModbusDevice,
        "serial port" => DeviceText::WordSerialPort,
        "axis" => DeviceText::WordAxis,
        "modulo period" => DeviceText::WordModuloPeriod,
        "negative software limit" => DeviceText::WordNegativeSoftwareLimit,
        "positive software limit" => DeviceText::WordPositiveSoftwareLimit,
        "velocity" => DeviceText::WordVelocity,
        "acceleration" => DeviceText::WordAcceleration,
        "deceleration" => DeviceText::WordDeceleration,
        "jerk" => DeviceText::WordJerk,
        "scaling numerator" => DeviceText::WordScalingNumerator,
        "scaling denominator" => DeviceText::WordScalingDenominator,
        "numerator" => DeviceText::WordNumerator,
        "denominator" => DeviceText::WordDenominator,
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
