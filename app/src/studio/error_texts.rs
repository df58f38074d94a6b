//! The refusals of the project model, the diagram editor, the compiler's literal parser and the
//! app's value parser in the interface language: each variant maps to a [`Text`] template, so a
//! new variant fails to compile until it is translated, and the user never reads a library's English `Display`.

use compiler::literal::LiteralError;
use editor::{CfcRefusal, DiagramRefusal};
use project_model::sfc_edit::{SfcEditError, SfcRule};
use project_model::{CfcEditError, EditError, ElementId, NetworkEditError, PinRef};

use crate::literal_value::ValueError;

use super::i18n::{ChartText, DiagramText, Language, RefusalText};

/// Why an edit of the project was refused, in `language`.
pub fn edit_error_text(error: &EditError, language: Language) -> String {
    match error {
        EditError::NoSuchObject(name) => {
            RefusalText::EditNoSuchObject.fill(language, &[("name", name)])
        }
        EditError::NoSuchFolder(name) => {
            RefusalText::EditNoSuchFolder.fill(language, &[("name", name)])
        }
        EditError::NoSuchMember { pou, what, name } => {
            let what = match *what {
                "method" => RefusalText::WhatMethod.get(language),
                "property" => RefusalText::WhatProperty.get(language),
                "action" => RefusalText::WhatAction.get(language),
                other => other,
            };
            RefusalText::EditNoSuchMember
                .fill(language, &[("pou", pou), ("what", what), ("name", name)])
        }
        EditError::IndexOutOfRange { index, len } => RefusalText::EditIndexOutOfRange.fill(
            language,
            &[("index", &index.to_string()), ("len", &len.to_string())],
        ),
        EditError::InvalidName(name) => {
            RefusalText::EditInvalidName.fill(language, &[("name", name)])
        }
        EditError::DuplicateName(name) => {
            RefusalText::EditDuplicateName.fill(language, &[("name", name)])
        }
        // The reason is the model's own description of the stored content; it names what
        // clashes and is shown as it is.
        EditError::InvalidObject(reason) => {
            RefusalText::EditInvalidObject.fill(language, &[("reason", reason)])
        }
        EditError::NotText(name) => RefusalText::EditNotText.fill(language, &[("name", name)]),
        EditError::BadTextRange { start, end, len } => RefusalText::EditBadTextRange.fill(
            language,
            &[
                ("start", &start.to_string()),
                ("end", &end.to_string()),
                ("len", &len.to_string()),
            ],
        ),
        EditError::MoveIntoItself => RefusalText::EditMoveIntoItself.get(language).to_owned(),
        EditError::KindChanged(name) => {
            RefusalText::EditKindChanged.fill(language, &[("name", name)])
        }
        EditError::NotNetworks(name) => {
            RefusalText::EditNotNetworks.fill(language, &[("name", name)])
        }
        EditError::NotChart(name) => RefusalText::EditNotChart.fill(language, &[("name", name)]),
        EditError::NetworkRangeOutOfRange { at, remove, len } => {
            RefusalText::EditNetworkRangeOutOfRange.fill(
                language,
                &[
                    ("at", &at.to_string()),
                    ("remove", &remove.to_string()),
                    ("len", &len.to_string()),
                ],
            )
        }
    }
}

/// Why a literal is not a value, in `language`.
pub fn literal_error_text(error: &LiteralError, language: Language) -> String {
    let (template, text, extra) = match error {
        LiteralError::UnknownBase { base } => {
            return RefusalText::LitUnknownBase.fill(language, &[("base", base)]);
        }
        LiteralError::NoDigits { text } => (RefusalText::LitNoDigits, text, None),
        LiteralError::BadDigit { text, base } => {
            let template = match base {
                2 => RefusalText::LitBadDigitBinary,
                8 => RefusalText::LitBadDigitOctal,
                16 => RefusalText::LitBadDigitHex,
                _ => RefusalText::LitBadDigitDecimal,
            };
            (template, text, None)
        }
        LiteralError::NotANumber { text } => (RefusalText::LitNotANumber, text, None),
        LiteralError::NoValue { text } => (RefusalText::LitNoValue, text, None),
        LiteralError::NoUnit { text } => (RefusalText::LitNoUnit, text, None),
        LiteralError::NoNumber { text, rest } => {
            (RefusalText::LitNoNumber, text, Some(("rest", rest)))
        }
        LiteralError::BadNumber { text, number } => {
            (RefusalText::LitBadNumber, text, Some(("number", number)))
        }
        LiteralError::UnknownUnit { text, rest } => {
            (RefusalText::LitUnknownUnit, text, Some(("rest", rest)))
        }
        LiteralError::NotADate { text } => (RefusalText::LitNotADate, text, None),
        LiteralError::NoSuchDate { text } => (RefusalText::LitNoSuchDate, text, None),
        LiteralError::NotATimeOfDay { text } => (RefusalText::LitNotATimeOfDay, text, None),
        LiteralError::NotADateAndTime { text } => (RefusalText::LitNotADateAndTime, text, None),
        LiteralError::NoHash { text } => (RefusalText::LitNoHash, text, None),
    };
    match extra {
        Some((key, value)) => template.fill(language, &[("text", text), (key, value)]),
        None => template.fill(language, &[("text", text)]),
    }
}

/// Why a typed value is not one of its variable's type, in `language`.
pub fn value_error_text(error: &ValueError, language: Language) -> String {
    match error {
        ValueError::NotAString(text) => {
            RefusalText::ValueNotAString.fill(language, &[("text", text)])
        }
        ValueError::TooLong { text, length } => RefusalText::ValueTooLong
            .fill(language, &[("text", text), ("length", &length.to_string())]),
        ValueError::NotWritable => RefusalText::ValueNotWritable.get(language).to_owned(),
        ValueError::NotAValue { text, ty } => {
            RefusalText::ValueNotAValue.fill(language, &[("text", text), ("ty", ty)])
        }
        ValueError::BadLiteral { text, ty, error } => RefusalText::ValueBadLiteral.fill(
            language,
            &[
                ("text", text),
                ("ty", ty),
                ("reason", &literal_error_text(error, language)),
            ],
        ),
        ValueError::OutOfRange { text, ty } => {
            RefusalText::ValueOutOfRange.fill(language, &[("text", text), ("ty", ty)])
        }
    }
}

/// Why a command of the LD/FBD editor did nothing, in `language`.
pub fn diagram_refusal_text(refusal: &DiagramRefusal, language: Language) -> String {
    match refusal {
        DiagramRefusal::Edit(error) => network_edit_error_text(error, language),
        DiagramRefusal::UnknownBlock(name) => {
            DiagramText::UnknownBlock.fill(language, &[("name", name)])
        }
    }
}

/// Why a structural operation does not apply to the selection, in `language`.
pub fn network_edit_error_text(error: &NetworkEditError, language: Language) -> String {
    match error {
        NetworkEditError::NoSuchNetwork { index, count } => DiagramText::NoSuchNetwork.fill(
            language,
            &[
                ("number", &(index + 1).to_string()),
                ("count", &count.to_string()),
            ],
        ),
        NetworkEditError::NoSuchElement { id } => {
            DiagramText::NoSuchElement.fill(language, &[("id", &id.0.to_string())])
        }
        // The operation's name is English for logs; the user reads which element refused.
        NetworkEditError::NotApplicable { id, operation: _ } => {
            DiagramText::NotApplicable.fill(language, &[("id", &id.0.to_string())])
        }
        NetworkEditError::NotOneChain => DiagramText::NotOneChain.get(language).to_owned(),
        NetworkEditError::NothingSelected => DiagramText::NothingSelected.get(language).to_owned(),
    }
}

/// Why a CFC gesture or command did nothing, in `language`.
pub fn cfc_refusal_text(refusal: &CfcRefusal, language: Language) -> String {
    match refusal {
        CfcRefusal::Edit(error) => cfc_edit_error_text(error, language),
        CfcRefusal::UnknownBlock(name) => {
            ChartText::CfcUnknownBlock.fill(language, &[("name", name)])
        }
        CfcRefusal::UnknownStructure(name) => {
            ChartText::CfcUnknownStructure.fill(language, &[("name", name)])
        }
        CfcRefusal::NotANumber(text) => ChartText::CfcNotANumber.fill(language, &[("text", text)]),
    }
}

/// Why a CFC chart edit does not apply, in `language`.
pub fn cfc_edit_error_text(error: &CfcEditError, language: Language) -> String {
    let id = |id: &ElementId| id.0.to_string();
    let pin = |text: ChartText, pin: &PinRef| {
        text.fill(
            language,
            &[("id", &id(&pin.element)), ("pin", pin.pin.as_str())],
        )
    };
    match error {
        CfcEditError::NoElement(element) => {
            ChartText::CfcNoElement.fill(language, &[("id", &id(element))])
        }
        CfcEditError::NothingSelected => ChartText::CfcNothingSelected.get(language).to_owned(),
        CfcEditError::NotAnOutput(at) => pin(ChartText::CfcNotAnOutput, at),
        CfcEditError::NotAnInput(at) => pin(ChartText::CfcNotAnInput, at),
        CfcEditError::SelfConnection(element) => {
            ChartText::CfcSelfConnection.fill(language, &[("id", &id(element))])
        }
        CfcEditError::NoWire(at) => pin(ChartText::CfcNoWire, at),
        CfcEditError::NoControlPoint { to, index } => ChartText::CfcNoControlPoint.fill(
            language,
            &[("id", &id(&to.element)), ("index", &index.to_string())],
        ),
        CfcEditError::NotExecutable(element) => {
            ChartText::CfcNotExecutable.fill(language, &[("id", &id(element))])
        }
        CfcEditError::OrderOutOfRange { order, count } => ChartText::CfcOrderOutOfRange.fill(
            language,
            &[("order", &order.to_string()), ("count", &count.to_string())],
        ),
        // The operation's name is English for logs; the user reads which element refused.
        CfcEditError::WrongKind {
            operation: _,
            id: element,
        } => ChartText::CfcWrongKind.fill(language, &[("id", &id(element))]),
        CfcEditError::NotExtensible { type_name } => {
            ChartText::CfcNotExtensible.fill(language, &[("type", type_name)])
        }
    }
}

/// Why an SFC chart edit does not apply, in `language`.
pub fn sfc_edit_error_text(error: &SfcEditError, language: Language) -> String {
    let id = |id: &ElementId| id.0.to_string();
    let at = |text: ChartText, element: &ElementId| text.fill(language, &[("id", &id(element))]);
    match error {
        SfcEditError::Structure { rule, element } => ChartText::SfcStructure.fill(
            language,
            &[
                ("id", &id(element)),
                ("rule", sfc_rule_text(*rule, language)),
            ],
        ),
        SfcEditError::EmptySelection => ChartText::SfcEmptySelection.get(language).to_owned(),
        SfcEditError::NoSuchElement(element) => at(ChartText::SfcNoSuchElement, element),
        SfcEditError::NotAStep(element) => at(ChartText::SfcNotAStep, element),
        SfcEditError::NotATransition(element) => at(ChartText::SfcNotATransition, element),
        SfcEditError::NotABranch(element) => at(ChartText::SfcNotABranch, element),
        SfcEditError::NotAJump(element) => at(ChartText::SfcNotAJump, element),
        SfcEditError::NotARun => ChartText::SfcNotARun.get(language).to_owned(),
        SfcEditError::JumpNotAtEnd(element) => at(ChartText::SfcJumpNotAtEnd, element),
        SfcEditError::InvalidName(name) => {
            ChartText::SfcInvalidName.fill(language, &[("name", name)])
        }
        SfcEditError::DuplicateName(name) => {
            ChartText::SfcDuplicateName.fill(language, &[("name", name)])
        }
        SfcEditError::UnknownStep(name) => {
            ChartText::SfcUnknownStep.fill(language, &[("name", name)])
        }
        SfcEditError::EmptyCondition(element) => at(ChartText::SfcEmptyCondition, element),
        SfcEditError::EmptyAction => ChartText::SfcEmptyAction.get(language).to_owned(),
        SfcEditError::MissingDuration(qualifier) => {
            ChartText::SfcMissingDuration.fill(language, &[("qualifier", qualifier)])
        }
        SfcEditError::UnexpectedDuration(qualifier) => {
            ChartText::SfcUnexpectedDuration.fill(language, &[("qualifier", qualifier)])
        }
        SfcEditError::NoSuchAssociation { step, index } => ChartText::SfcNoSuchAssociation.fill(
            language,
            &[("id", &id(step)), ("index", &index.to_string())],
        ),
        SfcEditError::EmptyClipboard => ChartText::SfcEmptyClipboard.get(language).to_owned(),
    }
}

/// An SFC structural rule in `language`.
fn sfc_rule_text(rule: SfcRule, language: Language) -> &'static str {
    match rule {
        SfcRule::MainStartsWithStep => ChartText::RuleMainStartsWithStep,
        SfcRule::MainEndsWithJump => ChartText::RuleMainEndsWithJump,
        SfcRule::StepNeedsTransitionAfter => ChartText::RuleStepNeedsTransitionAfter,
        SfcRule::TransitionNeedsStepAfter => ChartText::RuleTransitionNeedsStepAfter,
        SfcRule::JumpIsLast => ChartText::RuleJumpIsLast,
        SfcRule::TwoBranches => ChartText::RuleTwoBranches,
        SfcRule::AlternativeBeginsWithTransition => ChartText::RuleAlternativeBeginsWithTransition,
        SfcRule::AlternativeEndsWithTransitionOrJump => {
            ChartText::RuleAlternativeEndsWithTransitionOrJump
        }
        SfcRule::ParallelBeginsWithStep => ChartText::RuleParallelBeginsWithStep,
        SfcRule::ParallelEndsWithStep => ChartText::RuleParallelEndsWithStep,
        SfcRule::MacroBeginsAndEndsWithStep => ChartText::RuleMacroBeginsAndEndsWithStep,
        SfcRule::NoJumpInMacro => ChartText::RuleNoJumpInMacro,
        SfcRule::SequenceNotEmpty => ChartText::RuleSequenceNotEmpty,
        SfcRule::UniqueIds => ChartText::RuleUniqueIds,
    }
    .get(language)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(value: &str) -> String {
        value.to_owned()
    }

    /// One error of every variant; the `match` in each function keeps this list complete.
    fn edit_errors() -> Vec<EditError> {
        vec![
            EditError::NoSuchObject(text("Main")),
            EditError::NoSuchFolder(text("Folder/Sub")),
            EditError::NoSuchMember {
                pou: text("Motor"),
                what: "method",
                name: text("Start"),
            },
            EditError::NoSuchMember {
                pou: text("Motor"),
                what: "property",
                name: text("Speed"),
            },
            EditError::NoSuchMember {
                pou: text("Motor"),
                what: "action",
                name: text("Reset"),
            },
            EditError::IndexOutOfRange { index: 3, len: 2 },
            EditError::InvalidName(text("1st")),
            EditError::DuplicateName(text("Main")),
            EditError::InvalidObject(text("two methods are named Start")),
            EditError::NotText(text("Main")),
            EditError::BadTextRange {
                start: 4,
                end: 2,
                len: 9,
            },
            EditError::MoveIntoItself,
            EditError::KindChanged(text("Main")),
            EditError::NotNetworks(text("Main")),
            EditError::NotChart(text("Main")),
            EditError::NetworkRangeOutOfRange {
                at: 4,
                remove: 2,
                len: 5,
            },
        ]
    }

    fn literal_errors() -> Vec<LiteralError> {
        let t = || text("T#5x");
        let mut errors = vec![
            LiteralError::UnknownBase { base: text("7") },
            LiteralError::NoDigits { text: text("16#") },
            LiteralError::NotANumber { text: t() },
            LiteralError::NoValue { text: text("T#") },
            LiteralError::NoUnit { text: text("T#5") },
            LiteralError::NoNumber {
                text: text("T#ms"),
                rest: text("ms"),
            },
            LiteralError::BadNumber {
                text: t(),
                number: text("1.2.3"),
            },
            LiteralError::UnknownUnit {
                text: t(),
                rest: text("x"),
            },
            LiteralError::NotADate { text: t() },
            LiteralError::NoSuchDate { text: t() },
            LiteralError::NotATimeOfDay { text: t() },
            LiteralError::NotADateAndTime { text: t() },
            LiteralError::NoHash { text: t() },
        ];
        for base in [2, 8, 10, 16] {
            errors.push(LiteralError::BadDigit { text: t(), base });
        }
        errors
    }

    #[test]
    fn every_edit_error_reads_as_its_english_message_and_has_chinese() {
        for error in edit_errors() {
            assert_eq!(
                edit_error_text(&error, Language::English),
                error.to_string()
            );
            let chinese = edit_error_text(&error, Language::SimplifiedChinese);
            assert!(!chinese.contains('{'), "{chinese}");
            if !matches!(error, EditError::InvalidObject(_)) {
                assert_ne!(chinese, error.to_string());
            }
        }
    }

    #[test]
    fn every_value_error_reads_as_its_english_message_and_has_chinese() {
        let errors = [
            ValueError::NotAString(text("abc")),
            ValueError::TooLong {
                text: text("too long"),
                length: 3,
            },
            ValueError::NotWritable,
            ValueError::NotAValue {
                text: text("maybe"),
                ty: "BOOL",
            },
            ValueError::BadLiteral {
                text: text("16#G"),
                ty: "INT",
                error: LiteralError::BadDigit {
                    text: text("16#G"),
                    base: 16,
                },
            },
            ValueError::OutOfRange {
                text: text("300"),
                ty: "SINT",
            },
        ];
        for error in errors {
            assert_eq!(
                value_error_text(&error, Language::English),
                error.to_string()
            );
            let chinese = value_error_text(&error, Language::SimplifiedChinese);
            assert!(!chinese.contains('{'), "{chinese}");
            assert_ne!(chinese, error.to_string());
        }
    }

    #[test]
    fn every_literal_error_reads_as_its_english_message_and_has_chinese() {
        for error in literal_errors() {
            assert_eq!(
                literal_error_text(&error, Language::English),
                error.to_string()
            );
            let chinese = literal_error_text(&error, Language::SimplifiedChinese);
            assert!(!chinese.contains('{'), "{chinese}");
            assert_ne!(chinese, error.to_string());
        }
    }

    #[test]
    fn every_diagram_refusal_reads_as_its_english_message_and_has_chinese() {
        let refusals = vec![
            DiagramRefusal::Edit(NetworkEditError::NoSuchNetwork { index: 2, count: 2 }),
            DiagramRefusal::Edit(NetworkEditError::NoSuchElement { id: ElementId(7) }),
            DiagramRefusal::Edit(NetworkEditError::NotApplicable {
                id: ElementId(7),
                operation: "inserting in series",
            }),
            DiagramRefusal::Edit(NetworkEditError::NotOneChain),
            DiagramRefusal::Edit(NetworkEditError::NothingSelected),
            DiagramRefusal::UnknownBlock(text("TOON")),
        ];
        for refusal in &refusals {
            let english = diagram_refusal_text(refusal, Language::English);
            let chinese = diagram_refusal_text(refusal, Language::SimplifiedChinese);
            match refusal {
                // The model's English names its operation for logs; the user reads the element.
                DiagramRefusal::Edit(NetworkEditError::NotApplicable { .. }) => {
                    assert_eq!(english, "the command does not apply to element 7");
                }
                DiagramRefusal::Edit(error) => assert_eq!(english, error.to_string()),
                DiagramRefusal::UnknownBlock(_) => assert!(english.contains("'TOON'")),
            }
            assert_ne!(english, chinese, "{refusal:?} has no Chinese");
            assert!(!chinese.contains('{'), "{chinese}");
        }
    }

    #[test]
    fn every_chart_refusal_reads_as_its_english_message_and_has_chinese() {
        let pin = || PinRef {
            element: ElementId(3),
            pin: "IN1".to_owned(),
        };
        let cfc = vec![
            CfcEditError::NoElement(ElementId(3)),
            CfcEditError::NothingSelected,
            CfcEditError::NotAnOutput(pin()),
            CfcEditError::NotAnInput(pin()),
            CfcEditError::SelfConnection(ElementId(3)),
            CfcEditError::NoWire(pin()),
            CfcEditError::NoControlPoint {
                to: pin(),
                index: 2,
            },
            CfcEditError::NotExecutable(ElementId(3)),
            CfcEditError::OrderOutOfRange { order: 9, count: 4 },
            CfcEditError::WrongKind {
                operation: "negating a pin",
                id: ElementId(3),
            },
            CfcEditError::NotExtensible {
                type_name: "SUB".to_owned(),
            },
        ];
        for error in &cfc {
            let english = cfc_edit_error_text(error, Language::English);
            let chinese = cfc_edit_error_text(error, Language::SimplifiedChinese);
            match error {
                // The model's English names its operation for logs; the user reads the element.
                CfcEditError::WrongKind { .. } => {
                    assert_eq!(english, "the command does not apply to element 3");
                }
                _ => assert_eq!(english, error.to_string()),
            }
            assert_ne!(english, chinese, "{error:?} has no Chinese");
            assert!(!chinese.contains('{'), "{chinese}");
        }
        for refusal in [
            CfcRefusal::UnknownBlock("TOON".to_owned()),
            CfcRefusal::UnknownStructure("ST_Nope".to_owned()),
            CfcRefusal::NotANumber("x".to_owned()),
        ] {
            let chinese = cfc_refusal_text(&refusal, Language::SimplifiedChinese);
            assert_ne!(cfc_refusal_text(&refusal, Language::English), chinese);
            assert!(!chinese.contains('{'), "{chinese}");
        }
        let name = || "Fill".to_owned();
        let mut sfc = vec![
            SfcEditError::EmptySelection,
            SfcEditError::NoSuchElement(ElementId(3)),
            SfcEditError::NotAStep(ElementId(3)),
            SfcEditError::NotATransition(ElementId(3)),
            SfcEditError::NotABranch(ElementId(3)),
            SfcEditError::NotAJump(ElementId(3)),
            SfcEditError::NotARun,
            SfcEditError::JumpNotAtEnd(ElementId(3)),
            SfcEditError::InvalidName(name()),
            SfcEditError::DuplicateName(name()),
            SfcEditError::UnknownStep(name()),
            SfcEditError::EmptyCondition(ElementId(3)),
            SfcEditError::EmptyAction,
            SfcEditError::MissingDuration("L"),
            SfcEditError::UnexpectedDuration("N"),
            SfcEditError::NoSuchAssociation {
                step: ElementId(3),
                index: 1,
            },
            SfcEditError::EmptyClipboard,
        ];
        sfc.extend(
            [
                SfcRule::MainStartsWithStep,
                SfcRule::MainEndsWithJump,
                SfcRule::StepNeedsTransitionAfter,
                SfcRule::TransitionNeedsStepAfter,
                SfcRule::JumpIsLast,
                SfcRule::TwoBranches,
                SfcRule::AlternativeBeginsWithTransition,
                SfcRule::AlternativeEndsWithTransitionOrJump,
                SfcRule::ParallelBeginsWithStep,
                SfcRule::ParallelEndsWithStep,
                SfcRule::MacroBeginsAndEndsWithStep,
                SfcRule::NoJumpInMacro,
                SfcRule::SequenceNotEmpty,
            ]
            .map(|rule| SfcEditError::Structure {
                rule,
                element: ElementId(3),
            }),
        );
        for error in &sfc {
            let english = sfc_edit_error_text(error, Language::English);
            let chinese = sfc_edit_error_text(error, Language::SimplifiedChinese);
            assert_eq!(english, error.to_string());
            assert_ne!(english, chinese, "{error:?} has no Chinese");
            assert!(!chinese.contains('{'), "{chinese}");
        }
    }
}
