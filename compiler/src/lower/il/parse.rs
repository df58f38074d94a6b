//! The Instruction List parser: one instruction per line, with labels, comments and the
//! operand written as Structured Text (`docs/instruction-list.md` §1).

use std::ops::Range;

use crate::diagnostic::Code;

/// A parsed IL body: its lines in order, and what could not be read.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct IlProgram {
    /// The instructions and labels, in text order.
    pub items: Vec<IlItem>,
    /// The lines that could not be read.
    pub errors: Vec<IlError>,
}

/// A label or an instruction of an IL body.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum IlItem {
    /// `Name:`, the place a jump goes to.
    Label {
        /// The label as written.
        name: String,
        /// Its bytes in the text.
        range: Range<usize>,
    },
    /// One instruction.
    Instruction(Instruction),
}

/// One instruction: an operator with its modifiers and operand.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Instruction {
    /// What it does.
    pub operator: Operator,
    /// The `N` modifier: the operand (or for `ST`, the stored value; for `JMP`, `CAL` and
    /// `RET`, the condition) is negated.
    pub negated: bool,
    /// The `C` modifier of `JMP`, `CAL` and `RET`: done only when the current result is TRUE
    /// (FALSE with `N`).
    pub conditional: bool,
    /// The `(` modifier: the operation waits for the `)` and takes the result of the
    /// instructions between.
    pub deferred: bool,
    /// The operand, as written, with its bytes in the text; for a call with its arguments.
    pub operand: Option<(String, Range<usize>)>,
    /// The instruction's bytes in the text (without comments and blanks around it).
    pub range: Range<usize>,
}

/// The operators of IL.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Operator {
    /// `LD`: the current result becomes the operand.
    Load,
    /// `ST`: the operand becomes the current result.
    Store,
    /// `S`: the operand is set to TRUE when the current result is TRUE.
    Set,
    /// `R`: the operand is set to FALSE when the current result is TRUE.
    Reset,
    /// `NOT`: the current result is negated.
    Not,
    /// An operator between the current result and the operand.
    Binary(Binary),
    /// `JMP` to the label in the operand.
    Jump,
    /// `CAL`: the function block instance in the operand is called.
    Call,
    /// `RET`: the POU returns.
    Return,
    /// `)`: the deferred operation is done.
    Close,
    /// `S1`, `R1`, `CLK`, `CU`, `CD`, `PV`, `IN`, `PT`: the instance in the operand is called
    /// with this input set to the current result.
    BlockInput(String),
    /// Any other name: the function of that name is called with the current result as its
    /// first argument and the operand's values as the others.
    Function(String),
}

/// The operators written between the current result and an operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Binary {
    /// `AND` (also `&`).
    And,
    /// `OR`.
    Or,
    /// `XOR`.
    Xor,
    /// `ADD`.
    Add,
    /// `SUB`.
    Sub,
    /// `MUL`.
    Mul,
    /// `DIV`.
    Div,
    /// `MOD`.
    Mod,
    /// `GT`.
    Gt,
    /// `GE`.
    Ge,
    /// `EQ`.
    Eq,
    /// `NE`.
    Ne,
    /// `LE`.
    Le,
    /// `LT`.
    Lt,
}

impl Binary {
    /// The Structured Text operator.
    pub fn st(self) -> &'static str {
        match self {
            Self::And => "AND",
            Self::Or => "OR",
            Self::Xor => "XOR",
            Self::Add => "+",
            Self::Sub => "-",
            Self::Mul => "*",
            Self::Div => "/",
            Self::Mod => "MOD",
            Self::Gt => ">",
            Self::Ge => ">=",
            Self::Eq => "=",
            Self::Ne => "<>",
            Self::Le => "<=",
            Self::Lt => "<",
        }
    }

    /// Whether `N` may follow it (the bit operators only).
    fn negatable(self) -> bool {
        matches!(self, Self::And | Self::Or | Self::Xor)
    }

    fn of(word: &str) -> Option<Self> {
        Some(match word {
            "AND" | "&" => Self::And,
            "OR" => Self::Or,
            "XOR" => Self::Xor,
            "ADD" => Self::Add,
            "SUB" => Self::Sub,
            "MUL" => Self::Mul,
            "DIV" => Self::Div,
            "MOD" => Self::Mod,
            "GT" => Self::Gt,
            "GE" => Self::Ge,
            "EQ" => Self::Eq,
            "NE" => Self::Ne,
            "LE" => Self::Le,
            "LT" => Self::Lt,
            _ => return None,
        })
    }
}

/// A line that could not be read, with its code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct IlError {
    /// The code of the diagnostic.
    pub code: Code,
    /// The bytes it is about.
    pub range: Range<usize>,
    /// What is wrong and what was expected.
    pub message: String,
}

/// The inputs of the standard function blocks that IEC 61131-3 ed. 2 lets an instruction set
/// while calling the instance (`CU Counter1`).
const BLOCK_INPUTS: [&str; 8] = ["S1", "R1", "CLK", "CU", "CD", "PV", "IN", "PT"];

/// Parses an IL body.
pub(crate) fn parse(text: &str) -> IlProgram {
    let code = without_comments(text);
    let mut program = IlProgram::default();
    let mut start = 0;
    let lines: Vec<Range<usize>> = code
        .split_inclusive('\n')
        .map(|line| {
            let range = start..start + line.len();
            start += line.len();
            range
        })
        .collect();
    let mut index = 0;
    while index < lines.len() {
        let mut line = lines[index].clone();
        index += 1;
        // A call's arguments may continue on the next lines until the parentheses close.
        while depth(call_part(&code[line.clone()])) > 0 && index < lines.len() {
            line.end = lines[index].end;
            index += 1;
        }
        parse_line(&code, line, &mut program);
    }
    program
}

/// `text` with every comment replaced by blanks (line breaks kept), so byte offsets and lines
/// stay those of the text; quoted strings are kept as they are.
fn without_comments(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = bytes.to_vec();
    let mut at = 0;
    let blank = |out: &mut Vec<u8>, range: Range<usize>| {
        for byte in &mut out[range] {
            if *byte != b'\n' {
                *byte = b' ';
            }
        }
    };
    while at < bytes.len() {
        match bytes[at] {
            quote @ (b'\'' | b'"') => {
                at += 1;
                while at < bytes.len() && bytes[at] != quote && bytes[at] != b'\n' {
                    at += if bytes[at] == b'$' { 2 } else { 1 };
                }
                at += 1;
            }
            b'(' if bytes.get(at + 1) == Some(&b'*') => {
                let end = text[at + 2..]
                    .find("*)")
                    .map_or(bytes.len(), |e| at + 2 + e + 2);
                blank(&mut out, at..end);
                at = end;
            }
            b'/' if bytes.get(at + 1) == Some(&b'/') => {
                let end = text[at..].find('\n').map_or(bytes.len(), |e| at + e);
                blank(&mut out, at..end);
                at = end;
            }
            _ => at += 1,
        }
    }
    // Only ASCII bytes inside comments were replaced by ASCII blanks, and a multi-byte
    // character's bytes are all replaced or all kept, so the text stays UTF-8.
    String::from_utf8(out).unwrap_or_else(|_| text.to_owned())
}

/// The part of a line whose parentheses belong to a call: after a label and an operator's
/// word, and after the `(` of a deferred operation (`AND(`), which a `)` line closes.
fn call_part(line: &str) -> &str {
    let mut rest = line.trim_start();
    let word = |text: &str| {
        text.find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(text.len())
    };
    let name = word(rest);
    if name > 0
        && rest[name..].trim_start().starts_with(':')
        && !rest[name..].trim_start().starts_with(":=")
    {
        rest = rest[name..].trim_start()[1..].trim_start();
    }
    let operator = word(rest);
    let upper = rest[..operator].to_ascii_uppercase();
    let after = rest[operator..].trim_start();
    let deferrable = matches!(operator_of(&upper).0, Operator::Binary(_));
    match after.strip_prefix('(') {
        Some(inside) if deferrable => inside,
        _ => after,
    }
}

/// How many parentheses `text` leaves open.
fn depth(text: &str) -> i32 {
    let mut depth = 0;
    let mut quote = None;
    for c in text.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '\'' | '"') => quote = Some(c),
            (None, '(') => depth += 1,
            (None, ')') => depth -= 1,
            _ => {}
        }
    }
    depth
}

/// The range of `range` without the blanks around it.
fn trimmed(code: &str, range: Range<usize>) -> Range<usize> {
    let text = &code[range.clone()];
    let start = range.start + (text.len() - text.trim_start().len());
    let end = range.start + text.trim_end().len();
    start..end.max(start)
}

fn parse_line(code: &str, line: Range<usize>, program: &mut IlProgram) {
    let mut rest = trimmed(code, line);
    if rest.is_empty() {
        return;
    }
    // A label: a name, then a colon that does not start `:=`.
    let text = &code[rest.clone()];
    let name_len = text
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(text.len());
    let after = text[name_len..].trim_start();
    if name_len > 0 && after.starts_with(':') && !after.starts_with(":=") {
        let name = &text[..name_len];
        if !project_model::is_valid_identifier(name) {
            program.errors.push(IlError {
                code: Code::InvalidIlInstruction,
                range: rest.start..rest.start + name_len,
                message: format!("'{name}' is not a valid label; a label is an identifier"),
            });
        } else {
            program.items.push(IlItem::Label {
                name: name.to_owned(),
                range: rest.start..rest.start + name_len,
            });
        }
        let colon = rest.start + name_len + (text[name_len..].len() - after.len());
        rest = trimmed(code, colon + 1..rest.end);
        if rest.is_empty() {
            return;
        }
    }
    match instruction(code, rest.clone()) {
        Ok(instruction) => program.items.push(IlItem::Instruction(instruction)),
        Err(error) => program.errors.push(error),
    }
}

/// Reads the instruction in `range` (trimmed, not empty).
fn instruction(code: &str, range: Range<usize>) -> Result<Instruction, IlError> {
    let text = &code[range.clone()];
    let word_len = if text.starts_with(')') {
        1
    } else if let Some(after) = text.strip_prefix('&') {
        if after.starts_with(['N', 'n']) { 2 } else { 1 }
    } else {
        text.find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(text.len())
    };
    if word_len == 0 {
        return Err(IlError {
            code: Code::InvalidIlInstruction,
            range,
            message: format!(
                "'{text}' is not an instruction; expected an operator such as LD, ST or JMP, \
                 a function's name or a label"
            ),
        });
    }
    let word = &text[..word_len];
    let upper = word.to_ascii_uppercase();
    let mut after = word_len;
    // `AND(`, `ANDN(`: the parenthesis belongs to the operator, the operand follows it.
    let mut deferred = false;
    let rest_after_word = text[after..].trim_start();
    let mut instruction = Instruction {
        operator: Operator::Load,
        negated: false,
        conditional: false,
        deferred: false,
        operand: None,
        range: range.clone(),
    };
    let (operator, negated, conditional) = operator_of(&upper);
    let takes_paren = matches!(operator, Operator::Binary(_));
    if takes_paren && rest_after_word.starts_with('(') {
        deferred = true;
        after = text.len() - rest_after_word.len() + 1;
    }
    let operand_range = trimmed(code, range.start + after..range.end);
    let operand = (!operand_range.is_empty()).then(|| {
        (
            code[operand_range.clone()].to_owned(),
            operand_range.clone(),
        )
    });
    let needs = match &operator {
        Operator::Not | Operator::Return | Operator::Close => Need::Nothing,
        Operator::Binary(_) if deferred => Need::Optional,
        Operator::Function(_) => Need::Optional,
        _ => Need::Operand,
    };
    match (needs, &operand) {
        (Need::Nothing, Some((extra, extra_range))) => {
            return Err(IlError {
                code: Code::InvalidIlInstruction,
                range: extra_range.clone(),
                message: format!("'{word}' takes no operand, but '{extra}' follows it"),
            });
        }
        (Need::Operand, None) => {
            return Err(IlError {
                code: Code::InvalidIlInstruction,
                range,
                message: format!("'{word}' needs an operand"),
            });
        }
        _ => {}
    }
    if matches!(operator, Operator::Function(_)) && !project_model::is_valid_identifier(word) {
        return Err(IlError {
            code: Code::InvalidIlInstruction,
            range,
            message: format!("'{word}' is not an instruction; expected an operator or a function"),
        });
    }
    // A function keeps the spelling its call is written with.
    instruction.operator = match operator {
        Operator::Function(_) => Operator::Function(word.to_owned()),
        other => other,
    };
    instruction.negated = negated;
    instruction.conditional = conditional;
    instruction.deferred = deferred;
    instruction.operand = operand;
    Ok(instruction)
}

/// Whether an operator takes an operand.
#[derive(Clone, Copy)]
enum Need {
    Nothing,
    Optional,
    Operand,
}

/// The operator of an upper-case word with its `N` and `C` modifiers.
fn operator_of(upper: &str) -> (Operator, bool, bool) {
    let simple = |operator| (operator, false, false);
    match upper {
        "LD" => simple(Operator::Load),
        "LDN" => (Operator::Load, true, false),
        "ST" => simple(Operator::Store),
        "STN" => (Operator::Store, true, false),
        "S" => simple(Operator::Set),
        "R" => simple(Operator::Reset),
        "NOT" => simple(Operator::Not),
        "JMP" => simple(Operator::Jump),
        "JMPC" => (Operator::Jump, false, true),
        "JMPCN" => (Operator::Jump, true, true),
        "CAL" => simple(Operator::Call),
        "CALC" => (Operator::Call, false, true),
        "CALCN" => (Operator::Call, true, true),
        "RET" => simple(Operator::Return),
        "RETC" => (Operator::Return, false, true),
        "RETCN" => (Operator::Return, true, true),
        ")" => simple(Operator::Close),
        _ => {
            if let Some(binary) = Binary::of(upper) {
                return simple(Operator::Binary(binary));
            }
            // Only the bit operators take `N`, so a function such as LEN is not `LE` negated.
            if let Some(binary) = upper.strip_suffix('N').and_then(Binary::of)
                && binary.negatable()
            {
                return (Operator::Binary(binary), true, false);
            }
            if BLOCK_INPUTS.contains(&upper) {
                return simple(Operator::BlockInput(upper.to_owned()));
            }
            simple(Operator::Function(upper.to_owned()))
        }
    }
}
