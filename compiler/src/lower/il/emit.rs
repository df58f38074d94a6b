//! Instruction List lowered into Structured Text, line for line: the statements of the
//! instruction on IL line N are on line N of the text, so the checker's findings, the line
//! table and breakpoints name the IL lines (`docs/instruction-list.md` §2).

use std::collections::HashMap;
use std::ops::Range;

use project_model::{VarSection, Variable};

use super::parse::{IlError, IlItem, IlProgram, Instruction, Operator};
use crate::diagnostic::Code;

/// The type of an ST expression over the POU's names and the hidden variables given, by the
/// checker's rules; `None` for an untyped literal or an error.
pub(crate) type TypeOf<'t> = &'t dyn Fn(&[Variable], &str) -> Option<String>;

/// The current result (CR) at a point of the body.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Current {
    /// Nothing loaded: at the start, after an unconditional jump or return, and after a label
    /// only jumps reach with no value.
    Undefined,
    /// A value: a hidden variable of type `ty`, or (when `ty` is `None`) an untyped literal
    /// expression, which costs nothing to evaluate again.
    Value {
        /// The ST expression reading it.
        expression: String,
        /// Its declared type, when known.
        ty: Option<String>,
    },
}

/// An operation waiting for its `)`.
#[derive(Clone, Debug)]
struct Deferred {
    /// The instruction that opened it.
    instruction: Instruction,
    /// The current result before it.
    outer: Current,
}

/// The lowering of one IL body.
pub(crate) struct IlLowering<'t> {
    /// The prefix of the hidden variables' names (`__` or `__Member__`).
    prefix: String,
    /// The types of expressions.
    type_of: TypeOf<'t>,
    /// The hidden variables holding current results, one per nesting depth and type.
    pub hidden: Vec<Variable>,
    /// Each hidden variable's name with the words a message uses for it.
    pub descriptions: Vec<(String, String)>,
    /// What cannot be compiled.
    pub findings: Vec<IlError>,
    /// The byte offset each line of the IL text starts at.
    line_starts: Vec<usize>,
    /// The type the current result has at each label (lower case), as the jumps to it and the
    /// instruction before it leave it.
    label_types: HashMap<String, String>,
    /// The labels some jump goes to, lower case.
    jumped_to: Vec<String>,
    /// The labels whose first instruction reads the current result, lower case: only these
    /// carry it across (a label followed by `LD` needs nothing from before it).
    live: Vec<String>,
    /// The hidden variable of each depth and type.
    slots: HashMap<(usize, String), String>,
    /// Whether findings and text are kept (the last pass) or only label types learnt.
    emitting: bool,
    /// The generated text.
    out: String,
    /// How many line breaks `out` has.
    out_lines: usize,
    /// The current result.
    current: Current,
    /// The open parentheses, innermost last.
    deferred: Vec<Deferred>,
    /// The operand in the next emitted text: its byte offset there, its length and its start in
    /// the IL text.
    operand: Option<(usize, usize, usize)>,
    /// Each operand copied into the generated text: its range there and its start in the IL
    /// text, so values shown at names of the generated text can be shown at the IL's.
    pub operands: Vec<(Range<usize>, usize)>,
}

impl<'t> IlLowering<'t> {
    /// A lowering naming its hidden variables with `prefix`.
    pub fn new(prefix: String, type_of: TypeOf<'t>) -> Self {
        Self {
            prefix,
            type_of,
            hidden: Vec::new(),
            descriptions: Vec::new(),
            findings: Vec::new(),
            line_starts: Vec::new(),
            label_types: HashMap::new(),
            jumped_to: Vec::new(),
            live: Vec::new(),
            slots: HashMap::new(),
            emitting: false,
            out: String::new(),
            out_lines: 0,
            current: Current::Undefined,
            deferred: Vec::new(),
            operand: None,
            operands: Vec::new(),
        }
    }

    /// Lowers `text`, returning the Structured Text with as many lines; with `result`, the
    /// current result at the end is assigned to that name (a transition's condition).
    pub fn lower(&mut self, text: &str, result: Option<&str>) -> String {
        let program = super::parse::parse(text);
        self.line_starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(at, _)| at + 1))
            .collect();
        self.findings.extend(program.errors.iter().cloned());
        self.check_labels(&program);
        // The types at labels reached by backward jumps are known only after a pass, so the
        // passes run until they no longer change (each pass can only add types).
        for _ in 0..4 {
            let known = self.label_types.len();
            self.pass(&program);
            if self.label_types.len() == known {
                break;
            }
        }
        self.emitting = true;
        self.pass(&program);
        if let Some(result) = result {
            let end = text.trim_end().len();
            match &self.current {
                Current::Value { expression, .. } => {
                    let assignment = format!("{result} := {expression};");
                    self.emit(end, &assignment);
                }
                Current::Undefined => self.error(
                    Code::IlNoCurrentResult,
                    end..end,
                    format!(
                        "the transition '{result}' ends without a current result; its last \
                         instructions load the condition"
                    ),
                ),
            }
        }
        let lines = self.line_starts.len();
        while self.out_lines + 1 < lines {
            self.out.push('\n');
            self.out_lines += 1;
        }
        std::mem::take(&mut self.out)
    }

    /// Finds labels declared twice and jumps to labels the body does not have, and the labels
    /// the current result is live at.
    fn check_labels(&mut self, program: &IlProgram) {
        let mut waiting: Vec<String> = Vec::new();
        for item in &program.items {
            match item {
                IlItem::Label { name, .. } => waiting.push(name.to_lowercase()),
                IlItem::Instruction(instruction) => {
                    if reads_current(instruction) {
                        self.live.append(&mut waiting);
                    } else {
                        waiting.clear();
                    }
                }
            }
        }
        // A label at the end of a transition hands the current result on as its condition.
        self.live.append(&mut waiting);
        let mut labels: Vec<String> = Vec::new();
        for item in &program.items {
            if let IlItem::Label { name, range } = item {
                let key = name.to_lowercase();
                if labels.contains(&key) {
                    self.findings.push(IlError {
                        code: Code::IlLabel,
                        range: range.clone(),
                        message: format!("the label '{name}' is declared twice"),
                    });
                }
                labels.push(key);
            }
        }
        for item in &program.items {
            if let IlItem::Instruction(instruction) = item
                && instruction.operator == Operator::Jump
                && let Some((target, range)) = &instruction.operand
            {
                let key = target.to_lowercase();
                if !project_model::is_valid_identifier(target) {
                    self.findings.push(IlError {
                        code: Code::IlLabel,
                        range: range.clone(),
                        message: format!("'{target}' is not a label; JMP takes a label's name"),
                    });
                } else if !labels.contains(&key) {
                    self.findings.push(IlError {
                        code: Code::IlLabel,
                        range: range.clone(),
                        message: format!(
                            "the jump goes to '{target}', but no line of this body has that label"
                        ),
                    });
                } else {
                    self.jumped_to.push(key);
                }
            }
        }
    }

    /// One pass over the body.
    fn pass(&mut self, program: &IlProgram) {
        self.out.clear();
        self.out_lines = 0;
        self.operands.clear();
        self.current = Current::Undefined;
        self.deferred.clear();
        for item in &program.items {
            match item {
                IlItem::Label { name, range } => self.label(name, range),
                IlItem::Instruction(instruction) => self.instruction(instruction),
            }
        }
        for open in std::mem::take(&mut self.deferred) {
            self.error(
                Code::IlParenthesis,
                open.instruction.range.clone(),
                "this '(' is never closed; a line with ')' ends the operation".into(),
            );
        }
    }

    fn label(&mut self, name: &str, range: &Range<usize>) {
        if !self.deferred.is_empty() {
            self.error(
                Code::IlParenthesis,
                range.clone(),
                format!("the label '{name}' is inside parentheses; close them before it"),
            );
        }
        let key = name.to_lowercase();
        if !self.live.contains(&key) {
            // What follows loads its own current result, so nothing crosses the label.
            self.emit(range.start, &format!("{name}:"));
            if self.jumped_to.contains(&key) {
                self.current = Current::Undefined;
            }
            return;
        }
        if let Current::Value { ty: Some(ty), .. } = &self.current
            && !self.label_types.contains_key(&key)
        {
            self.label_types.insert(key.clone(), ty.clone());
        }
        let reconcile = self.reconcile(&key);
        let mut text = reconcile.unwrap_or_default();
        text.push_str(&format!("{name}:"));
        self.emit(range.start, &text);
        if let Some(ty) = self.label_types.get(&key).cloned() {
            let slot = self.slot(0, &ty);
            self.current = Current::Value {
                expression: slot,
                ty: Some(ty),
            };
        } else if self.jumped_to.contains(&key) {
            // Jumps bring no value the label can hold, so what follows must load one.
            self.current = Current::Undefined;
        }
    }

    /// The assignment that moves the current result into the variable the label `key`
    /// expects it in, when it is elsewhere.
    fn reconcile(&mut self, key: &str) -> Option<String> {
        let ty = self.label_types.get(key)?.clone();
        let slot = self.slot(0, &ty);
        match &self.current {
            Current::Value { expression, .. } if *expression != slot => {
                Some(format!("{slot} := {expression}; "))
            }
            _ => None,
        }
    }

    fn instruction(&mut self, instruction: &Instruction) {
        let at = instruction.range.start;
        let operand = instruction.operand.as_ref().map(|(text, _)| text.as_str());
        let il_operand = instruction
            .operand
            .as_ref()
            .map_or(0, |(_, range)| range.start);
        // Where `operand` is in `text` when written there as `grouped` gives it.
        let within = |text_before: usize, operand: &str| {
            let parenthesis = usize::from(grouped(operand) != operand);
            Some((text_before + parenthesis, operand.len(), il_operand))
        };
        match &instruction.operator {
            Operator::Load => {
                let Some(operand) = operand else { return };
                let value = if instruction.negated {
                    self.operand = within(4, operand);
                    format!("NOT {}", grouped(operand))
                } else {
                    self.operand = Some((0, operand.len(), il_operand));
                    operand.to_owned()
                };
                self.set_current(at, value);
            }
            Operator::Store => {
                let (Some(target), Some(value)) = (operand, self.read(instruction)) else {
                    return;
                };
                let value = if instruction.negated {
                    format!("NOT {value}")
                } else {
                    value
                };
                self.operand = Some((0, target.len(), il_operand));
                self.emit(at, &format!("{target} := {value};"));
            }
            Operator::Set | Operator::Reset => {
                let (Some(target), Some(value)) = (operand, self.read(instruction)) else {
                    return;
                };
                let bit = if instruction.operator == Operator::Set {
                    "TRUE"
                } else {
                    "FALSE"
                };
                self.operand = Some((value.len() + 9, target.len(), il_operand));
                self.emit(at, &format!("IF {value} THEN {target} := {bit}; END_IF;"));
            }
            Operator::Not => {
                if let Some(value) = self.read(instruction) {
                    self.set_current(at, format!("NOT {value}"));
                }
            }
            Operator::Binary(binary) => {
                let Some(value) = self.read(instruction) else {
                    return;
                };
                if instruction.deferred {
                    self.deferred.push(Deferred {
                        instruction: instruction.clone(),
                        outer: self.current.clone(),
                    });
                    self.current = Current::Undefined;
                    if let Some(operand) = operand {
                        self.operand = Some((0, operand.len(), il_operand));
                        self.set_current(at, operand.to_owned());
                    }
                    return;
                }
                let Some(operand) = operand else { return };
                let not = if instruction.negated { "NOT " } else { "" };
                self.operand = within(value.len() + binary.st().len() + 2 + not.len(), operand);
                self.set_current(
                    at,
                    format!("{value} {} {not}{}", binary.st(), grouped(operand)),
                );
            }
            Operator::Close => self.close(instruction),
            Operator::Jump => self.jump(instruction),
            Operator::Call => {
                let Some(operand) = operand else { return };
                let call = if operand.contains('(') {
                    format!("{operand};")
                } else {
                    format!("{operand}();")
                };
                self.operand = Some((0, operand.len(), il_operand));
                self.conditionally(instruction, call);
            }
            Operator::BlockInput(pin) => {
                let (Some(instance), Some(value)) = (operand, self.read(instruction)) else {
                    return;
                };
                self.operand = Some((0, instance.len(), il_operand));
                self.emit(at, &format!("{instance}({pin} := {value});"));
            }
            Operator::Return => {
                if !self.deferred.is_empty() {
                    self.inside_parentheses(instruction, "RET");
                    return;
                }
                self.conditionally(instruction, "RETURN;".into());
                if !instruction.conditional {
                    self.current = Current::Undefined;
                }
            }
            Operator::Function(name) => {
                let call = match operand {
                    Some(arguments) if arguments.starts_with('(') => {
                        self.operand = Some((name.len(), arguments.len(), il_operand));
                        format!("{name}{arguments}")
                    }
                    Some(arguments) => {
                        let Some(value) = self.read(instruction) else {
                            return;
                        };
                        self.operand =
                            Some((name.len() + value.len() + 3, arguments.len(), il_operand));
                        format!("{name}({value}, {arguments})")
                    }
                    None => {
                        let Some(value) = self.read(instruction) else {
                            return;
                        };
                        format!("{name}({value})")
                    }
                };
                self.set_current(at, call);
            }
        }
    }

    /// `)`: the deferred operation on the result before `(` and the one between.
    fn close(&mut self, instruction: &Instruction) {
        let Some(open) = self.deferred.pop() else {
            self.error(
                Code::IlParenthesis,
                instruction.range.clone(),
                "')' closes no parenthesis; an operator such as AND( opens one".into(),
            );
            return;
        };
        let inner = self.read(instruction);
        let outer = match &open.outer {
            Current::Value { expression, .. } => expression.clone(),
            Current::Undefined => return,
        };
        let Some(inner) = inner else { return };
        let Operator::Binary(binary) = open.instruction.operator else {
            return;
        };
        let not = if open.instruction.negated { "NOT " } else { "" };
        self.set_current(
            instruction.range.start,
            format!("{outer} {} {not}({inner})", binary.st()),
        );
    }

    fn jump(&mut self, instruction: &Instruction) {
        if !self.deferred.is_empty() {
            self.inside_parentheses(instruction, "JMP");
            return;
        }
        let Some((target, _)) = &instruction.operand else {
            return;
        };
        let key = target.to_lowercase();
        if !self.jumped_to.contains(&key) {
            return;
        }
        if let Current::Value { ty: Some(ty), .. } = &self.current
            && !self.label_types.contains_key(&key)
            && self.live.contains(&key)
        {
            self.label_types.insert(key.clone(), ty.clone());
        }
        let reconcile = self.reconcile(&key).unwrap_or_default();
        self.conditionally(instruction, format!("{reconcile}JMP {target};"));
        if !instruction.conditional {
            self.current = Current::Undefined;
        }
    }

    /// Emits `statement`, inside `IF` on the current result for the `C` modifier.
    fn conditionally(&mut self, instruction: &Instruction, statement: String) {
        let at = instruction.range.start;
        if !instruction.conditional {
            self.emit(at, &statement);
            return;
        }
        let operand = self.operand.take();
        let Some(value) = self.read(instruction) else {
            return;
        };
        let condition = if instruction.negated {
            format!("NOT {value}")
        } else {
            value
        };
        self.operand = operand.map(|(offset, len, il)| (offset + condition.len() + 9, len, il));
        self.emit(at, &format!("IF {condition} THEN {statement} END_IF;"));
    }

    fn inside_parentheses(&mut self, instruction: &Instruction, what: &str) {
        self.error(
            Code::IlParenthesis,
            instruction.range.clone(),
            format!("{what} is inside parentheses; close them with ')' first"),
        );
    }

    /// The current result as an expression, or an error at `instruction` when there is none.
    fn read(&mut self, instruction: &Instruction) -> Option<String> {
        match &self.current {
            Current::Value { expression, .. } => Some(expression.clone()),
            Current::Undefined => {
                self.error(
                    Code::IlNoCurrentResult,
                    instruction.range.clone(),
                    "there is no current result here; load one with LD first".into(),
                );
                None
            }
        }
    }

    /// Makes `value` the current result: stored in the hidden variable of its type at this
    /// depth, so it is evaluated once however often it is read; an untyped literal is kept as
    /// it is.
    fn set_current(&mut self, at: usize, value: String) {
        let ty = (self.type_of)(&self.hidden, &value);
        let operand = self.operand.take();
        self.current = match ty {
            Some(ty) => {
                let slot = self.slot(self.deferred.len(), &ty);
                self.operand = operand.map(|(offset, len, il)| (offset + slot.len() + 4, len, il));
                self.emit(at, &format!("{slot} := {value};"));
                Current::Value {
                    expression: slot,
                    ty: Some(ty),
                }
            }
            None if is_literal(&value) => Current::Value {
                expression: grouped(&value),
                ty: None,
            },
            None => {
                // An expression without a type has an error the checker must see on this
                // line, so it is stored like any other, in the type the result had before.
                let ty = match &self.current {
                    Current::Value { ty: Some(ty), .. } => ty.clone(),
                    _ => "BOOL".to_owned(),
                };
                let slot = self.slot(self.deferred.len(), &ty);
                self.operand = operand.map(|(offset, len, il)| (offset + slot.len() + 4, len, il));
                self.emit(at, &format!("{slot} := {value};"));
                Current::Value {
                    expression: slot,
                    ty: Some(ty),
                }
            }
        };
    }

    /// The hidden variable of the current result of type `ty` at nesting `depth`.
    fn slot(&mut self, depth: usize, ty: &str) -> String {
        let key = (depth, ty.to_uppercase());
        if let Some(name) = self.slots.get(&key) {
            return name.clone();
        }
        let name = format!("{}cr{}", self.prefix, self.slots.len());
        self.hidden.push(Variable {
            name: name.clone(),
            section: VarSection::Var,
            ty: ty.to_owned(),
            ..Variable::default()
        });
        let words = if depth == 0 {
            format!("the current result ({ty})")
        } else {
            format!("the current result ({ty}) inside parentheses")
        };
        self.descriptions.push((name.clone(), words));
        self.slots.insert(key, name.clone());
        name
    }

    /// Appends `statement` on the line of byte `at` of the IL text.
    fn emit(&mut self, at: usize, statement: &str) {
        let line = self.line_starts.partition_point(|start| *start <= at) - 1;
        while self.out_lines < line {
            self.out.push('\n');
            self.out_lines += 1;
        }
        if !self.out.is_empty() && !self.out.ends_with('\n') {
            self.out.push(' ');
        }
        if let Some((offset, len, il)) = self.operand.take() {
            let start = self.out.len() + offset;
            self.operands.push((start..start + len, il));
        }
        self.out.push_str(statement);
        self.out_lines += statement.matches('\n').count();
    }

    fn error(&mut self, code: Code, range: Range<usize>, message: String) {
        if self.emitting {
            self.findings.push(IlError {
                code,
                range,
                message,
            });
        }
    }
}

/// Whether `instruction` reads the current result before it sets one.
fn reads_current(instruction: &Instruction) -> bool {
    match &instruction.operator {
        Operator::Load => false,
        Operator::Call | Operator::Return => instruction.conditional,
        Operator::Function(_) => !instruction
            .operand
            .as_ref()
            .is_some_and(|(arguments, _)| arguments.starts_with('(')),
        // A jump hands the current result on to its label.
        _ => true,
    }
}

/// Whether `value` is an untyped literal, or operators on literals only (`1`, `-2.5`,
/// `16#FF`, `'text'`, `(1 + 2)`): without names, so evaluating it again costs nothing.
fn is_literal(value: &str) -> bool {
    let mut words = value
        .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == '#' || c == '.'))
        .filter(|word| !word.is_empty());
    let quoted = value.starts_with('\'') || value.starts_with('"');
    quoted
        || words.all(|word| {
            word.starts_with(|c: char| c.is_ascii_digit())
                || word.eq_ignore_ascii_case("MOD")
                || word.eq_ignore_ascii_case("AND")
                || word.eq_ignore_ascii_case("OR")
                || word.eq_ignore_ascii_case("XOR")
                || word.eq_ignore_ascii_case("NOT")
        })
}

/// `operand` in parentheses unless it is one name, member, index or literal.
fn grouped(operand: &str) -> String {
    let simple = operand
        .chars()
        .all(|c| c.is_alphanumeric() || "_.#[]%'\"$:".contains(c))
        || (operand.starts_with('(') && operand.ends_with(')') && !operand[1..].contains('('));
    if simple {
        operand.to_owned()
    } else {
        format!("({operand})")
    }
}
