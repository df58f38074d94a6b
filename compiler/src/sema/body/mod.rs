//! Type checking of one ST body: every name resolved, every expression typed, every statement
//! checked against the IEC rules, and every local variable's reads and writes recorded for the
//! unused and unassigned warnings.
//!
//! This file holds the checker and the statements; `expression.rs` types expressions, `call.rs`
//! checks calls, `resolution.rs` records what names refer to.

mod call;
mod expression;
mod resolution;

use std::collections::HashMap;
use std::ops::Range;

use project_model::{Pou, PouKind, VarSection, Variable};

use super::constant::{Const, evaluate, integer_value, parse_expression};
use super::definition::{Definition, DefinitionKind, Resolution};
use super::scope::{GlobalSymbol, LocalSymbol, Scope, inheritance_chain, is_visible_outside};
use super::signatures::{self, FunctionSig, Sig};
use super::ty::{DEFAULT_STRING_LENGTH, Type, common_type, implicitly_converts};
use super::types::Shape;
use super::{closest, stdlib};
use crate::diagnostic::{Code, Diagnostic};
use crate::elementary::Elementary;
use crate::literal;
use crate::syntax::{SyntaxKind, SyntaxNode, SyntaxToken};

/// How a variable was used somewhere.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Access {
    /// Its value was read.
    pub(crate) read: bool,
    /// It was written: assigned, connected to an output or passed by reference.
    pub(crate) written: bool,
}

/// Reads and writes of variables, keyed by the declaration's address.
pub(crate) type Usage = HashMap<*const Variable, Access>;

/// Whether an expression is read or written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    Read,
    Write,
}

/// Checks one body in its scope.
pub(crate) struct BodyChecker<'s, 'a, 'p> {
    scope: &'s Scope<'a, 'p>,
    /// What was found.
    pub(crate) diagnostics: Vec<Diagnostic>,
    usage: &'s mut Usage,
    /// What each name refers to, collected only when asked for (hover, references).
    pub(crate) resolutions: Option<Vec<Resolution>>,
    /// The type of every expression checked, collected only when asked for (code generation).
    pub(crate) types: Option<HashMap<SyntaxNode, Type>>,
    /// Types resolved with the POU's own constants (open array bounds), by their text, so an
    /// `ARRAY[*]` parameter is not parsed again at every use.
    local_types: std::cell::RefCell<HashMap<String, Type>>,
}

fn range_of(node: &SyntaxNode) -> Range<usize> {
    let range = node.text_range();
    usize::from(range.start())..usize::from(range.end())
}

fn token_range(token: &SyntaxToken) -> Range<usize> {
    let range = token.text_range();
    usize::from(range.start())..usize::from(range.end())
}

fn tokens(node: &SyntaxNode) -> impl Iterator<Item = SyntaxToken> {
    node.children_with_tokens()
        .filter_map(|element| element.into_token())
        .filter(|token| !token.kind().is_trivia())
}

fn text(node: &SyntaxNode) -> String {
    node.text().to_string().trim().to_owned()
}

/// A reference is used as the value it refers to.
fn dereferenced(ty: Type) -> Type {
    match ty {
        Type::Reference(target) => *target,
        other => other,
    }
}

impl<'s, 'a, 'p> BodyChecker<'s, 'a, 'p> {
    pub(crate) fn new(scope: &'s Scope<'a, 'p>, usage: &'s mut Usage) -> Self {
        Self {
            scope,
            diagnostics: Vec::new(),
            usage,
            resolutions: None,
            types: None,
            local_types: std::cell::RefCell::default(),
        }
    }

    fn error(&mut self, code: Code, range: Range<usize>, message: impl Into<String>) {
        self.diagnostics.push(Diagnostic::new(code, range, message));
    }

    /// The type written as `text`; array bounds that name the POU's own constants are
    /// resolved with them (the shared cache knows only the globals).
    fn resolve(&self, text: &str) -> Type {
        let ty = self.scope.globals.resolve_type(text);
        if !has_open_bounds(&ty) || self.scope.pou.is_none() {
            return ty;
        }
        if let Some(known) = self.local_types.borrow().get(text) {
            return known.clone();
        }
        let constants = |name: &str, container: Option<&str>, depth: u32| {
            self.named_constant(name, container, depth)
        };
        let ty = super::types::resolve_type_text_with(self.scope.globals, text, &constants);
        self.local_types
            .borrow_mut()
            .insert(text.to_owned(), ty.clone());
        ty
    }

    /// Checks an expression whose value goes where `expected` is needed, such as an initial
    /// value.
    pub(crate) fn check_value(&mut self, node: &SyntaxNode, expected: &Type, context: &str) {
        let ty = self.expression(node, Mode::Read);
        self.expect_type(&ty, expected, node, context);
    }

    /// The type of an expression, read.
    pub(crate) fn type_of(&mut self, node: &SyntaxNode) -> Type {
        self.expression(node, Mode::Read)
    }

    /// Checks every statement under `root`.
    pub(crate) fn check(&mut self, root: &SyntaxNode) {
        for child in root.children() {
            self.statement_or_list(&child);
        }
    }

    fn statement_or_list(&mut self, node: &SyntaxNode) {
        match node.kind() {
            SyntaxKind::STATEMENT_LIST | SyntaxKind::ELSE_BRANCH => {
                for child in node.children() {
                    self.statement_or_list(&child);
                }
            }
            _ => self.statement(node),
        }
    }

    fn statement(&mut self, node: &SyntaxNode) {
        let children: Vec<SyntaxNode> = node.children().collect();
        match node.kind() {
            SyntaxKind::ASSIGN_STMT => {
                if let [target, value, ..] = children.as_slice() {
                    let target_ty = self.expression(target, Mode::Write);
                    let value_ty = self.expression(value, Mode::Read);
                    // A POU or action name has no value to assign to.
                    if !self.assignable_target(target, &target_ty) {
                        return;
                    }
                    self.expect_type(&value_ty, &target_ty, value, "the assignment");
                } else if let [only] = children.as_slice() {
                    self.expression(only, Mode::Read);
                }
            }
            SyntaxKind::SET_STMT | SyntaxKind::RESET_STMT => {
                if let [target, value, ..] = children.as_slice() {
                    let target_ty = self.expression(target, Mode::Write);
                    if self.assignable_target(target, &target_ty) {
                        self.expect_type(&target_ty, &Type::BOOL, target, "S= and R=");
                    }
                    let value_ty = self.expression(value, Mode::Read);
                    self.expect_type(&value_ty, &Type::BOOL, value, "S= and R=");
                }
            }
            SyntaxKind::REF_ASSIGN_STMT | SyntaxKind::ATTEMPT_ASSIGN_STMT => {
                // Both sides are places; their types are checked by the runtime's rules for
                // references and interfaces, which need the declared (not dereferenced) type.
                if let [target, value, ..] = children.as_slice() {
                    self.expression(target, Mode::Write);
                    self.expression(value, Mode::Read);
                }
            }
            SyntaxKind::CALL_STMT => {
                for child in &children {
                    self.expression(child, Mode::Read);
                }
            }
            SyntaxKind::IF_STMT | SyntaxKind::ELSIF_BRANCH => {
                for child in &children {
                    match child.kind() {
                        SyntaxKind::STATEMENT_LIST
                        | SyntaxKind::ELSIF_BRANCH
                        | SyntaxKind::ELSE_BRANCH => self.statement_or_list(child),
                        _ => self.condition(child, "IF"),
                    }
                }
            }
            SyntaxKind::WHILE_STMT | SyntaxKind::REPEAT_STMT => {
                let keyword = if node.kind() == SyntaxKind::WHILE_STMT {
                    "WHILE"
                } else {
                    "UNTIL"
                };
                for child in &children {
                    if child.kind() == SyntaxKind::STATEMENT_LIST {
                        self.statement_or_list(child);
                    } else {
                        self.condition(child, keyword);
                    }
                }
            }
            SyntaxKind::FOR_STMT => self.for_statement(&children),
            SyntaxKind::CASE_STMT => self.case_statement(&children),
            SyntaxKind::TRANSITION_DECL => {
                for child in &children {
                    match child.kind() {
                        SyntaxKind::STEP_LIST | SyntaxKind::NAME | SyntaxKind::ARG_LIST => {}
                        SyntaxKind::STATEMENT_LIST => self.statement_or_list(child),
                        kind if is_statement(kind) => self.statement(child),
                        _ => self.condition(child, "TRANSITION"),
                    }
                }
            }
            SyntaxKind::STEP_DECL => {
                // Action associations: `Action(N);`, `Action(D, T#2s);`. Only the action's
                // name is a name; the arguments are qualifiers and times.
                for call in node
                    .descendants()
                    .filter(|n| n.kind() == SyntaxKind::CALL_EXPR)
                {
                    if let Some(callee) = call.children().next() {
                        self.expression(&callee, Mode::Read);
                    }
                }
            }
            SyntaxKind::ACTION_DECL => {
                for child in &children {
                    if child.kind() == SyntaxKind::STATEMENT_LIST {
                        self.statement_or_list(child);
                    }
                }
            }
            _ => {}
        }
    }

    fn condition(&mut self, node: &SyntaxNode, keyword: &str) {
        let ty = self.expression(node, Mode::Read);
        if !ty.is_bool_like() {
            self.error(
                Code::TypeMismatch,
                range_of(node),
                format!("the {keyword} condition must be BOOL, found {ty}"),
            );
        }
    }

    fn for_statement(&mut self, children: &[SyntaxNode]) {
        let expressions: Vec<&SyntaxNode> = children
            .iter()
            .filter(|child| child.kind() != SyntaxKind::STATEMENT_LIST)
            .collect();
        if let Some((variable, bounds)) = expressions.split_first() {
            let ty = self.expression(variable, Mode::Write);
            if self.assignable_target(variable, &ty) && !ty.is_integer_like() {
                self.error(
                    Code::TypeMismatch,
                    range_of(variable),
                    format!("the FOR variable must be an integer, found {ty}"),
                );
            }
            for bound in bounds {
                let bound_ty = self.expression(bound, Mode::Read);
                if ty.is_integer_like() {
                    self.expect_type(&bound_ty, &ty, bound, "the FOR range");
                }
            }
        }
        for child in children {
            if child.kind() == SyntaxKind::STATEMENT_LIST {
                self.statement_or_list(child);
            }
        }
    }

    fn case_statement(&mut self, children: &[SyntaxNode]) {
        let Some(selector) = children.first() else {
            return;
        };
        let selector_ty = match self.expression(selector, Mode::Read) {
            // A constant selector is a DINT, so its labels are checked against one.
            Type::IntLiteral(_) => Type::Elementary(Elementary::Dint),
            other => other,
        };
        let is_enum = matches!(&selector_ty, Type::Named(name)
            if matches!(self.scope.globals.shape(name), Some(Shape::Enum(_))));
        if !selector_ty.is_integer_like()
            && !is_enum
            && !matches!(selector_ty, Type::Elementary(e) if e.is_bit_string())
        {
            self.error(
                Code::TypeMismatch,
                range_of(selector),
                format!(
                    "the CASE selector must be an integer or an enumeration, found {selector_ty}"
                ),
            );
        }
        let mut seen: Vec<(i128, i128)> = Vec::new();
        for branch in children.iter().skip(1) {
            match branch.kind() {
                SyntaxKind::CASE_BRANCH => {
                    for part in branch.children() {
                        if part.kind() == SyntaxKind::CASE_LABELS {
                            for label in part.children() {
                                self.case_label(&label, &selector_ty, &mut seen);
                            }
                        } else {
                            self.statement_or_list(&part);
                        }
                    }
                }
                _ => self.statement_or_list(branch),
            }
        }
    }

    fn case_label(&mut self, label: &SyntaxNode, selector: &Type, seen: &mut Vec<(i128, i128)>) {
        let bounds: Vec<SyntaxNode> = if label.kind() == SyntaxKind::CASE_RANGE {
            label.children().collect()
        } else {
            vec![label.clone()]
        };
        let mut values = Vec::new();
        for bound in &bounds {
            let ty = self.expression(bound, Mode::Read);
            self.expect_type(&ty, selector, bound, "the CASE label");
            match self.constant_value(bound) {
                Some(Const::Int(value)) => values.push(value),
                // A constant of another type is reported as a type mismatch above.
                Some(_) => return,
                None => {
                    if ty != Type::Error {
                        self.error(
                            Code::NotConstant,
                            range_of(bound),
                            format!("a CASE label must be a constant, found '{}'", text(bound)),
                        );
                    }
                    return;
                }
            }
        }
        let (low, high) = match values.as_slice() {
            [value] => (*value, *value),
            [low, high] => (*low, *high),
            _ => return,
        };
        if seen.iter().any(|(l, h)| low <= *h && *l <= high) {
            self.error(
                Code::DuplicateCaseLabel,
                range_of(label),
                format!(
                    "the CASE label '{}' is already covered by an earlier branch, which wins",
                    text(label)
                ),
            );
        }
        seen.push((low, high));
    }

    /// The value of a constant expression, with the POU's own constants visible.
    fn constant_value(&self, node: &SyntaxNode) -> Option<Const> {
        evaluate(
            node,
            &|name, container, depth| self.named_constant(name, container, depth),
            0,
        )
    }

    fn named_constant(&self, name: &str, container: Option<&str>, depth: u32) -> Option<Const> {
        if container.is_none()
            && let Some(LocalSymbol::Var(variable)) = self.scope.local(name)
        {
            if !variable.constant {
                return None;
            }
            let expression = parse_expression(variable.initial.as_deref()?)?;
            return evaluate(
                &expression,
                &|n, c, d| self.named_constant(n, c, d),
                depth + 1,
            );
        }
        self.scope.globals.constant(name, container, depth)
    }

    /// Reports a place that cannot be written: a literal, a call, an expression, or a name
    /// without a value (`target_ty` is `Void`); returns whether the place can be written.
    /// (Constants, outputs and enumeration values are checked where they resolve.)
    fn assignable_target(&mut self, target: &SyntaxNode, target_ty: &Type) -> bool {
        let root = target.kind();
        let not_a_place = matches!(
            root,
            SyntaxKind::LITERAL
                | SyntaxKind::TYPED_LITERAL
                | SyntaxKind::CALL_EXPR
                | SyntaxKind::BINARY_EXPR
                | SyntaxKind::UNARY_EXPR
        );
        if not_a_place || *target_ty == Type::Void {
            self.error(
                Code::NotAssignable,
                range_of(target),
                format!(
                    "'{}' is not a variable and cannot be assigned",
                    text(target)
                ),
            );
            return false;
        }
        true
    }

    /// Reports `value` where `expected` is needed, unless it converts implicitly.
    fn expect_type(&mut self, value: &Type, expected: &Type, node: &SyntaxNode, context: &str) {
        if self.converts(value, expected) {
            return;
        }
        let mut message = format!("{context} expects {expected}, found {value}");
        if let (Some(from), Some(to)) = (value.as_elementary(), expected.as_elementary()) {
            message.push_str(&format!(
                "; IEC converts only to wider types, so write {}_TO_{}(…)",
                from.name(),
                to.name()
            ));
        } else if let Type::IntLiteral(Some(v)) = value {
            message = format!("{context} expects {expected}, but {v} does not fit it");
        }
        self.error(Code::TypeMismatch, range_of(node), message);
    }

    /// Whether a value of type `from` may go where `to` is expected: the IEC rules plus the
    /// project's interfaces and references.
    fn converts(&self, from: &Type, to: &Type) -> bool {
        let to = match to {
            Type::Reference(target) => target.as_ref(),
            other => other,
        };
        if implicitly_converts(from, to) {
            return true;
        }
        match (from, to) {
            // A function block instance goes where an interface it implements is expected.
            (Type::Named(instance), Type::Named(interface)) => self.implements(instance, interface),
            (Type::Pointer(target), Type::Pointer(_)) => **target == Type::Void,
            // Enumerations are integers underneath: CODESYS accepts them where their base type
            // goes unless the enumeration is strict.
            (Type::Named(name), target) if target.is_integer_like() => {
                matches!(self.scope.globals.shape(name), Some(Shape::Enum(_)))
            }
            _ => false,
        }
    }

    fn implements(&self, instance: &str, interface: &str) -> bool {
        let globals = self.scope.globals;
        let Some(pou) = globals.pou(instance) else {
            return false;
        };
        inheritance_chain(globals, pou).iter().any(|current| {
            current.name.eq_ignore_ascii_case(interface)
                || current
                    .implements
                    .iter()
                    .any(|name| self.interface_extends(name, interface, 0))
        })
    }

    fn interface_extends(&self, name: &str, wanted: &str, depth: usize) -> bool {
        if name.eq_ignore_ascii_case(wanted) {
            return true;
        }
        if depth > super::scope::MAX_INHERITANCE {
            return false;
        }
        self.scope.globals.pou(name).is_some_and(|interface| {
            interface
                .extends
                .iter()
                .chain(&interface.implements)
                .any(|base| self.interface_extends(base, wanted, depth + 1))
        })
    }

    fn record(&mut self, variable: &Variable, mode: Mode) {
        let access = self.usage.entry(std::ptr::from_ref(variable)).or_default();
        match mode {
            Mode::Read => access.read = true,
            Mode::Write => access.written = true,
        }
    }

    /// Whether `node` names a variable declared `REFERENCE TO`.
    fn declared_reference(&self, node: &SyntaxNode) -> bool {
        if node.kind() != SyntaxKind::NAME_EXPR {
            return false;
        }
        let name = text(node);
        let variable = match self.scope.local(&name) {
            Some(LocalSymbol::Var(variable)) => Some(variable),
            _ => match self.scope.globals.lookup(&name) {
                Some(GlobalSymbol::Var(variable)) => Some(variable),
                _ => None,
            },
        };
        variable.is_some_and(|v| matches!(self.resolve(&v.ty), Type::Reference(_)))
    }
}

/// Whether an array type (at any depth) has a bound that did not resolve.
pub(crate) fn has_open_bounds(ty: &Type) -> bool {
    match ty {
        Type::Array { element, dims } => {
            dims.iter().any(Option::is_none) || has_open_bounds(element)
        }
        Type::Pointer(target) | Type::Reference(target) => has_open_bounds(target),
        _ => false,
    }
}

fn is_statement(kind: SyntaxKind) -> bool {
    matches!(
        kind,
        SyntaxKind::ASSIGN_STMT
            | SyntaxKind::SET_STMT
            | SyntaxKind::RESET_STMT
            | SyntaxKind::CALL_STMT
            | SyntaxKind::IF_STMT
            | SyntaxKind::CASE_STMT
            | SyntaxKind::FOR_STMT
            | SyntaxKind::WHILE_STMT
            | SyntaxKind::REPEAT_STMT
    )
}
