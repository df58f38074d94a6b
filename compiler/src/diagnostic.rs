//! Diagnostics: what the compiler reports, each with a stable code documented in
//! `docs/diagnostics/<CODE>.md`.

use std::ops::Range;

/// How serious a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// Worth a look; the program still builds.
    Warning,
    /// The program cannot be built.
    Error,
}

/// Defines `Code` with each code's identifier, severity and title in one place.
macro_rules! codes {
    ($($variant:ident = $id:literal, $severity:ident, $title:literal;)*) => {
        /// The stable codes of diagnostics. A code never changes meaning once released.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Code {
            $(
                #[doc = $title]
                $variant,
            )*
        }

        impl Code {
            /// Every code, in order.
            pub const ALL: &'static [Code] = &[$(Code::$variant),*];

            /// The code as written in messages and doc page names, such as `E0001`.
            pub fn id(self) -> &'static str {
                match self { $(Code::$variant => $id,)* }
            }

            /// The default severity.
            pub fn severity(self) -> Severity {
                match self { $(Code::$variant => Severity::$severity,)* }
            }

            /// A one-line title, the heading of the code's doc page.
            pub fn title(self) -> &'static str {
                match self { $(Code::$variant => $title,)* }
            }
        }
    };
}

codes! {
    UnexpectedToken = "E0001", Error, "Unexpected token";
    UnterminatedComment = "E0002", Error, "Comment or pragma not closed";
    UnterminatedString = "E0003", Error, "String not closed";
    InvalidCharacter = "E0004", Error, "Character that is not part of Structured Text";
    NestingTooDeep = "E0005", Error, "Nesting too deep";
    UnknownName = "E0101", Error, "Unknown name";
    UnknownType = "E0102", Error, "Unknown type";
    UnknownProgram = "E0103", Error, "Task calls something that is not a program";
    TypeMismatch = "E0104", Error, "Value of the wrong type";
    InvalidOperands = "E0105", Error, "Operator not defined for its operands";
    InvalidCall = "E0106", Error, "Call does not match what is called";
    NotAssignable = "E0107", Error, "Assignment to something that cannot be written";
    DuplicateName = "E0108", Error, "Name declared twice";
    NotConstant = "E0109", Error, "Constant expression needed";
    InvalidAddress = "E0110", Error, "Invalid direct address";
    IndexOutOfRange = "E0111", Error, "Index or bit outside the declared range";
    Inaccessible = "E0112", Error, "Member not visible from outside";
    ReservedName = "E0113", Error, "Name with two underscores in a row";
    InvalidNetwork = "E0114", Error, "LD or FBD element that cannot be compiled";
    UncompiledChart = "E0115", Error, "CFC or SFC chart that cannot be compiled yet";
    DuplicateStep = "E0116", Error, "SFC step declared twice";
    InitialStep = "E0117", Error, "SFC chart without exactly one initial step";
    UnknownStep = "E0118", Error, "Transition naming an unknown step";
    UnknownAction = "E0119", Error, "Action association naming no action or BOOL variable";
    QualifierTime = "E0120", Error, "Action qualifier with a missing or needless duration";
    NotATime = "E0121", Error, "SFC duration that is not a TIME";
    SfcFlagType = "E0122", Error, "SFC flag declared with the wrong type";
    UnknownStepAction = "E0123", Error, "Step property naming no action";
    SfcOutsideInstance = "E0124", Error, "SFC chart outside a program or function block";
    InvalidTransitionPriority = "E0125", Error, "Transition with an invalid priority or without a condition";
    ConnectionWithoutSource = "E0126", Error, "CFC connection mark without a source";
    DuplicateConnectionSource = "E0127", Error, "CFC connection mark name given to two sources";
    InvalidCfcElement = "E0128", Error, "CFC element that cannot be compiled";
    ConnectionLoop = "E0129", Error, "CFC connection marks that feed only each other";
    RetiredOperator = "E0130", Error, "Operator that CODESYS V3 no longer compiles";
    SystemOperatorUnavailable = "E0131", Error, "CODESYS system operator the runtime does not provide";
    BitAddressWithoutLocation = "E0132", Error, "BITADR of something without a direct address";
    OpenArrayOutsideInOut = "E0133", Error, "Array with open bounds outside a VAR_IN_OUT parameter";
    UnwritablePlace = "E0134", Error, "THIS, SUPER or a property used where a variable is needed";
    BitByReference = "E0135", Error, "Single bit passed by reference or given to ADR";
    InvalidIlInstruction = "E0136", Error, "Instruction List line that is not an instruction";
    IlLabel = "E0137", Error, "Instruction List jump to a missing label, or a label declared twice";
    IlParenthesis = "E0138", Error, "Instruction List parentheses that do not match";
    IlNoCurrentResult = "E0139", Error, "Instruction List operator without a current result";
    ModbusUncopyableVariable = "E0140", Error, "Modbus channel bound to something the runtime cannot copy";
    ModbusChannelType = "E0141", Error, "Modbus channel variable of the wrong type";
    ModbusDoubleWrite = "E0142", Error, "Variable written by two Modbus channels";
    ModbusDeviceSetting = "E0143", Error, "Modbus device or serial port setting the runtime cannot use";
    ModbusChannelSetting = "E0144", Error, "Modbus channel setting the runtime cannot use";
    ModbusFlagType = "E0145", Error, "Modbus status, error flag or trigger variable of the wrong type";
    UnusedVariable = "W0001", Warning, "Variable never used";
    UnassignedVariable = "W0002", Warning, "Variable read but never written";
    OverlappingAddresses = "W0003", Warning, "Located variables overlap";
    AssignmentToInput = "W0004", Warning, "Input assigned inside its POU";
    DuplicateCaseLabel = "W0005", Warning, "CASE label already covered";
    AddressSizeMismatch = "W0006", Warning, "Located variable's type does not match the address size";
    ImplicitNarrowing = "W0012", Warning, "Integer value narrowed or its sign changed implicitly";
    ImplicitRealRounding = "W0013", Warning, "Integer converted implicitly to a real that may round it";
    ImplicitRealToInteger = "W0014", Warning, "Real converted implicitly to an integer, rounded";
    ModbusReadVariableWritten = "W0015", Warning, "Variable of a Modbus read channel also written by the program";
    ModbusPollFasterThanTask = "W0016", Warning, "Modbus device polled more often than its task copies its values";
}

/// One finding of the compiler about the source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// The stable code.
    pub code: Code,
    /// Error or warning.
    pub severity: Severity,
    /// The primary span in bytes of the source the diagnostic is about.
    pub range: Range<usize>,
    /// What was found and what was expected.
    pub message: String,
}

impl Diagnostic {
    /// A diagnostic with the code's default severity.
    pub fn new(code: Code, range: Range<usize>, message: impl Into<String>) -> Self {
        Self {
            code,
            severity: code.severity(),
            range,
            message: message.into(),
        }
    }
}

/// The 1-based line and column (in characters) of byte `offset` in `text`.
pub fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = floor_char_boundary(text, offset.min(text.len()));
    let before = &text[..offset];
    let line_start = before.rfind('\n').map_or(0, |index| index + 1);
    let line = before.matches('\n').count() + 1;
    let column = before[line_start..].chars().count() + 1;
    (line, column)
}

fn floor_char_boundary(text: &str, mut offset: usize) -> usize {
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    offset
}

impl Diagnostic {
    /// Renders the diagnostic as `file:line:col: severity[CODE]: message` followed by the source
    /// line with the span underlined, the form terminals and editors link to.
    pub fn render(&self, file: &str, text: &str) -> String {
        let (line, column) = line_column(text, self.range.start);
        let severity = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        let start = floor_char_boundary(text, self.range.start.min(text.len()));
        let line_start = text[..start].rfind('\n').map_or(0, |index| index + 1);
        let line_end = text[start..]
            .find('\n')
            .map_or(text.len(), |index| start + index);
        let source_line = text[line_start..line_end].trim_end_matches('\r');
        let end = floor_char_boundary(text, self.range.end.clamp(start, line_end));
        let width = text[start..end].chars().count().max(1);
        let number = line.to_string();
        let gutter = " ".repeat(number.len());
        // Tabs keep their width in the underline so the caret sits under the span.
        let lead: String = text[line_start..start]
            .chars()
            .map(|c| if c == '\t' { '\t' } else { ' ' })
            .collect();
        format!(
            "{file}:{line}:{column}: {severity}[{}]: {}\n{gutter} |\n{number} | {source_line}\n{gutter} | {lead}{}\n",
            self.code.id(),
            self.message,
            "^".repeat(width)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rendered_diagnostic_points_at_its_span() {
        let text = "x := 1;\ny := 中文 + ;\n";
        let start = text.rfind(';').unwrap();
        let diagnostic = Diagnostic::new(
            Code::UnexpectedToken,
            start..start + 1,
            "expected an expression, found ';'",
        );
        assert_eq!(
            diagnostic.render("Main.st", text),
            "Main.st:2:11: error[E0001]: expected an expression, found ';'\n  |\n2 | y := 中文 + ;\n  |           ^\n"
        );
    }
}
