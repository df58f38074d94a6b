use project_model::{IoDirection, ModbusDataType};

use super::*;

/// One refusal of every kind, with every word the checks put into their sentences.
fn every_refusal() -> Vec<Refusal> {
    let mut problems = vec![
        DeviceProblem::EmptyHost,
        DeviceProblem::ZeroPort,
        DeviceProblem::EmptyRangeAddress { row: 1 },
        DeviceProblem::EmptyRange { row: 2 },
        DeviceProblem::RangePastEnd {
            row: 1,
            start: 65530,
            count: 10,
        },
        DeviceProblem::RangesOverlap { row: 2, other: 1 },
        DeviceProblem::ZeroSize,
        DeviceProblem::AreaPastEnd {
            start_byte: 10,
            size_bytes: 4,
            limit: 12,
        },
        DeviceProblem::AreasOverlap {
            direction: IoDirection::Output,
            first: 1,
            last: 1,
            other: "DO_16".into(),
        },
        DeviceProblem::AreasOverlap {
            direction: IoDirection::Input,
            first: 1,
            last: 3,
            other: "DI_16".into(),
        },
        DeviceProblem::ZeroPollInterval,
        DeviceProblem::ZeroTimeout,
        DeviceProblem::EmptyVariable { row: 3 },
        DeviceProblem::InvalidVariable {
            row: 3,
            variable: "1x".into(),
        },
        DeviceProblem::ChannelPastEnd {
            row: 1,
            address: 65535,
            width: 2,
        },
        DeviceProblem::ChannelsOverlap {
            row: 2,
            variable: "GVL.a".into(),
            other: 1,
            other_variable: "GVL.b".into(),
        },
        DeviceProblem::TableTypeMismatch {
            row: 1,
            table: ModbusTable::Coil,
            data_type: ModbusDataType::Real,
        },
        DeviceProblem::EmptySerialPort,
        DeviceProblem::NoSuchSerialPort("RS232".into()),
        DeviceProblem::RtuWithoutTask,
        DeviceProblem::RtuUnitId(0),
        DeviceProblem::TimeoutTooLong(60_001),
        DeviceProblem::PollIntervalTooLong(3_600_001),
        DeviceProblem::MissingPollInterval,
        DeviceProblem::ReadGapTooLarge(126),
        DeviceProblem::ZeroCount { row: 2 },
        DeviceProblem::ChannelTooLong {
            row: 1,
            count: 62,
            span: 124,
            limit: 123,
        },
        DeviceProblem::WriteToReadOnlyTable {
            row: 3,
            table: ModbusTable::InputRegister,
        },
        DeviceProblem::WriteToReadOnlyTable {
            row: 3,
            table: ModbusTable::DiscreteInput,
        },
        DeviceProblem::FunctionCodeOnRead { row: 1, code: 3 },
        DeviceProblem::FunctionCodeMisfit {
            row: 1,
            code: 6,
            table: ModbusTable::Coil,
        },
        DeviceProblem::FunctionCodeMisfit {
            row: 1,
            code: 5,
            table: ModbusTable::HoldingRegister,
        },
        DeviceProblem::SingleWriteTooWide {
            row: 4,
            code: 6,
            span: 2,
        },
        DeviceProblem::TriggerVariableWithoutEdge { row: 1 },
        DeviceProblem::EdgeWithoutTriggerVariable { row: 1 },
        DeviceProblem::OnErrorOnWrite { row: 2 },
        DeviceProblem::EmptyDevice,
        DeviceProblem::UnsupportedBaudRate(14400),
        DeviceProblem::UnsupportedDataBits(6),
        DeviceProblem::UnsupportedStopBits(3),
        DeviceProblem::InterFrameDelayTooLong(1_000_001),
        DeviceProblem::NoSuchTask("Fast".into()),
        DeviceProblem::EmptyUnit,
        DeviceProblem::ModuloNotPositive(0.0),
        DeviceProblem::LimitsInverted {
            min: 10.0,
            max: -2.5,
        },
    ];
    for kind in [
        "controller",
        "I/O area",
        "serial port",
        "Modbus device",
        "axis",
    ] {
        let name = "1st".to_owned();
        problems.push(DeviceProblem::InvalidName {
            kind,
            name: name.clone(),
        });
        problems.push(DeviceProblem::DuplicateName { kind, name });
    }
    for field in [
        "modulo period",
        "negative software limit",
        "positive software limit",
        "scaling numerator",
        "scaling denominator",
    ] {
        problems.push(DeviceProblem::NotFinite { field });
    }
    for field in ["velocity", "acceleration", "deceleration", "jerk"] {
        problems.push(DeviceProblem::NotFinite { field });
        problems.push(DeviceProblem::DynamicLimitNotPositive { field, value: -1.5 });
    }
    for field in ["numerator", "denominator"] {
        problems.push(DeviceProblem::ZeroScaling { field });
    }
    let text = || "%QX4.9".to_owned();
    let mut refusals: Vec<Refusal> = problems.into_iter().map(Refusal::from).collect();
    refusals.extend(
        [
            AddressError::NoPercent { text: text() },
            AddressError::NoArea { text: text() },
            AddressError::NoSize { text: text() },
            AddressError::NotANumber {
                text: text(),
                part: "x".into(),
            },
            AddressError::NoSuchBit {
                text: text(),
                bit: 9,
            },
        ]
        .map(Refusal::from),
    );
    refusals.extend(
        [
            ChannelVariableError::NoSuchVariable("GVL.x".into()),
            ChannelVariableError::TypeMismatch {
                path: "GVL.x".into(),
                declared: "REAL".into(),
                data_type: "UINT".into(),
                expected: vec!["UINT".into(), "WORD".into()],
            },
        ]
        .map(Refusal::from),
    );
    let misfit =
        |direction, count, declared: &str, expected: &[&str]| ChannelBindingError::Misfit {
            path: "GVL.x".into(),
            misfit: compiler::ide::ChannelMisfit {
                direction,
                data_type: ModbusDataType::Int16,
                count,
                declared: declared.into(),
                expected: expected.iter().map(|name| (*name).to_owned()).collect(),
            },
        };
    refusals.extend(
        [
            ChannelBindingError::NoSuchVariable("GVL.x".into()),
            misfit(ChannelDirection::Read, 1, "REAL", &["INT"]),
            misfit(
                ChannelDirection::Write,
                8,
                "INT",
                &["ARRAY[0..7] OF UINT", "ARRAY[0..7] OF WORD"],
            ),
            ChannelBindingError::StaticElsewhere {
                path: "Main.fb.iShared".into(),
                symbol: "FB_Base.iShared".into(),
            },
            ChannelBindingError::Constant {
                path: "GVL.iLimit".into(),
            },
            ChannelBindingError::AtBitAddress {
                path: "GVL.axBits".into(),
                address: "%IX0.0".into(),
                count: 8,
            },
        ]
        .map(Refusal::from),
    );
    refusals.extend(
        [
            Unplaceable::VarTemp,
            Unplaceable::VarInOut,
            Unplaceable::VarExternal,
            Unplaceable::FunctionVariable,
            Unplaceable::Method,
            Unplaceable::Property,
            Unplaceable::AxisOrCam,
        ]
        .map(|what| {
            Refusal::from(ChannelBindingError::NoFixedPlace {
                path: "Main.x".into(),
                what,
            })
        }),
    );
    refusals.extend([
        Refusal::BitTableAddress {
            address: "%QX4.1".into(),
        },
        Refusal::RegisterTableAddress {
            address: "%IB2".into(),
        },
        Refusal::NotANumber {
            text: "fast".into(),
        },
        Refusal::NotAWholeNumber {
            text: "300".into(),
            min: "0".into(),
            max: "255".into(),
        },
    ]);
    refusals
}

#[test]
fn every_refusal_reads_in_english_as_its_own_text() {
    for refusal in every_refusal() {
        assert_eq!(
            describe_refusal(&refusal, Language::English),
            refusal.to_string()
        );
    }
}

#[test]
fn every_refusal_has_its_own_chinese_words() {
    for refusal in every_refusal() {
        let english = describe_refusal(&refusal, Language::English);
        let chinese = describe_refusal(&refusal, Language::SimplifiedChinese);
        assert!(!chinese.trim().is_empty(), "{refusal:?}");
        assert_ne!(chinese, english, "{refusal:?}");
        assert!(!chinese.contains('{'), "{chinese}");
    }
}

#[test]
fn the_words_inside_a_chinese_reason_are_chinese_too() {
    let duplicate = DeviceProblem::DuplicateName {
        kind: "Modbus device",
        name: "Drive".into(),
    };
    assert_eq!(
        describe_problem(&duplicate, Language::SimplifiedChinese),
        "名称 'Drive' 已被另一个Modbus 设备使用"
    );
    let limit = DeviceProblem::DynamicLimitNotPositive {
        field: "jerk",
        value: 0.0,
    };
    assert_eq!(
        describe_problem(&limit, Language::SimplifiedChinese),
        "加加速度限值为 0；必须大于 0"
    );
}

#[test]
fn every_kind_and_field_word_the_checks_use_has_chinese_words() {
    for english in [
        "controller",
        "I/O area",
        "Modbus device",
        "serial port",
        "axis",
        "modulo period",
        "negative software limit",
        "positive software limit",
        "velocity",
        "acceleration",
        "deceleration",
        "jerk",
        "scaling numerator",
        "scaling denominator",
        "numerator",
        "denominator",
    ] {
        assert_eq!(word(english, Language::English), english);
        assert_ne!(word(english, Language::SimplifiedChinese), english);
    }
}

#[test]
fn a_chinese_misfit_joins_its_declarations_by_chinese_or_and_spaces_its_count_once() {
    let misfit = |count, expected: &[&str]| {
        Refusal::from(ChannelBindingError::Misfit {
            path: "GVL.x".into(),
            misfit: compiler::ide::ChannelMisfit {
                direction: ChannelDirection::Write,
                data_type: ModbusDataType::Uint16,
                count,
                declared: "INT".into(),
                expected: expected.iter().map(|name| (*name).to_owned()).collect(),
            },
        })
    };
    assert_eq!(
        describe_refusal(
            &misfit(8, &["ARRAY[0..7] OF UINT", "ARRAY[0..7] OF WORD"]),
            Language::SimplifiedChinese
        ),
        "'GVL.x'：通道写入 8 个 uint16 值，但变量声明为 INT：请将其声明为 ARRAY[0..7] OF UINT 或 ARRAY[0..7] OF WORD"
    );
    assert_eq!(
        describe_refusal(&misfit(1, &["UINT", "WORD"]), Language::SimplifiedChinese),
        "'GVL.x'：通道写入 1 个 uint16 值，但变量声明为 INT：请将其声明为 UINT 或 WORD"
    );
}
