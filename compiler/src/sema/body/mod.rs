//! Type checking of one ST body: every name resolved, every expression typed, every statement
//! checked against the IEC rules, and every local variable's reads and writes recorded for the
//! unused and unassigned warnings.
//!
//! This file holds the checker and the statements; `expression.rs` types expressions, `call.rs`
//! checks calls, `resolution.rs` records what names refer to.

mod bcd_target;
mod call;
mod expression;
mod refused_call;
mod resolution;
mod unwritable_place;

use unwritable_place::PlaceUse;
mod sfc;

use std::collections::HashMap;
use std::ops::Range;

use project_model::{Pou, PouKind, VarSection, Variable};

use super::constant::{Const, evaluate, integer_value, parse_expression};
use super::definition::{Definition, DefinitionKind, Resolution};
use super::scope::{GlobalSymbol, LocalSymbol, Scope, inheritance_chain, is_visible_outside};
use super::signatures::{self, FunctionSig, Sig};
use super::ty::{
    DEFAULT_STRING_LENGTH, Type, bit_string_arithmetic, common_type, implicitly_converts,
    integer_real_type, lenient_integer_conversion, lenient_real_conversion,
    lenient_real_to_integer, mixed_sign_type, power_type, wrapped,
};
use super::types::Shape;
use super::{closest, stdlib};
use crate::diagnostic::{Code, Diagnostic};
use crate::elementary::Elementary;
use crate::literal;
use crate::syntax::ast::{
    AstNode, CaseLabel, CaseStmt, Expr, ForStmt, SourceFile, StatementList, Stmt,
};
use crate::syntax::ast::{CallExpr, NameExpr};
use crate::syntax::{SyntaxKind, SyntaxNode, SyntaxToken};
use project_model::Dialect;

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
    pub(crate) types: Option<super::expression_types::ExpressionTypes>,
    /// Types resolved with the POU's own constants (open array bounds), by their text, so an
    /// `ARRAY[*]` parameter is not parsed again at every use.
    local_types: std::cell::RefCell<HashMap<String, Type>>,
    /// The ranges of the expressions checked so far that name a property (`Pos`, `fb.Pos`),
    /// for `refuse_unwritable_place`; lives as long as the body's check.
    property_nodes: std::collections::HashSet<rowan::TextRange>,
    /// The ranges of the expressions checked so far that name a BOOL located at a bit address
    /// (`x AT %IX0.1`), for `refuse_unwritable_place`; lives as long as the body's check.
    bit_nodes: std::collections::HashSet<rowan::TextRange>,
    /// The ranges of the standard `*_TO_BCD` calls checked so far, whose result takes a bit
    /// string type an assignment or input gives (`bcd_target.rs`); lives as long as the
    /// body's check.
    bcd_calls: std::collections::HashSet<rowan::TextRange>,
}

fn range_of(node: &SyntaxNode) -> Range<usize> {
    let range = node.text_range();
    usize::from(range.start())..usize::from(range.end())
}

fn token_range(token: &SyntaxToken) -> Range<usize> {
    let range = token.text_range();
    usize::from(range.start())..usize::from(range.end())
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

/// Appended to an error the `iec-strict` dialect gives where CODESYS would warn or accept.
pub(super) const STRICT_NOTE: &str =
    " (the project's dialect is iec-strict; CODESYS would accept this, see docs/dialect.md)";

/// The warning for a value of `value`'s type narrowed implicitly into `target`, as CODESYS
/// performs it: with the constant's stored value when the value is a constant.
fn narrowing_message(value: &Type, target: &Type, context: &str) -> String {
    match (value, target.as_elementary()) {
        (Type::IntLiteral(Some(v)), Some(to)) => format!(
            "{v} does not fit {target} in {context}; it is stored as {}, its low bits (write {target}#… or a value in range)",
            wrapped(*v, to)
        ),
        (_, Some(to)) => format!(
            "{context} converts {value} to {target} implicitly, keeping the low bits (write {}_TO_{}(…) to say so)",
            value.as_elementary().map_or("ANY", |e| e.name()),
            to.name()
        ),
        _ => format!("{context} converts {value} to {target} implicitly"),
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
            property_nodes: std::collections::HashSet::new(),
            bit_nodes: std::collections::HashSet::new(),
            bcd_calls: std::collections::HashSet::new(),
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
    pub(crate) fn check_value(&mut self, node: &Expr, expected: &Type, context: &str) {
        let ty = self.expression(node, Mode::Read);
        self.expect_type(&ty, expected, node.syntax(), context);
    }

    /// The type of an expression, read.
    pub(crate) fn type_of(&mut self, node: &Expr) -> Type {
        self.expression(node, Mode::Read)
    }

    /// Checks every statement of the body `root`.
    pub(crate) fn check(&mut self, root: &SyntaxNode) {
        let list = SourceFile::cast(root.clone()).and_then(|file| file.statement_list());
        if let Some(chart) = list.as_ref().and_then(crate::sfc_chart::Chart::of) {
            self.chart(&chart);
        }
        self.statement_list(list);
    }

    fn statement_list(&mut self, list: Option<StatementList>) {
        for statement in list.iter().flat_map(StatementList::statements) {
            self.statement(&statement);
        }
    }

    /// `target := value` and the statements written like it: the target is written, the
    /// value read; a statement with only one expression reads it.
    fn assignment(&mut self, target: Option<Expr>, value: Option<Expr>) {
        match (target, value) {
            (Some(target), Some(value)) => {
                let target_ty = self.expression(&target, Mode::Write);
                let value_ty = self.expression(&value, Mode::Read);
                // A POU or action name has no value to assign to.
                if !self.assignable_target(&target, &target_ty)
                    || self.refuse_unwritable_place(&target, PlaceUse::Assigned)
                {
                    return;
                }
                self.expect_type(&value_ty, &target_ty, value.syntax(), "the assignment");
            }
            (Some(only), None) | (None, Some(only)) => {
                self.expression(&only, Mode::Read);
            }
            (None, None) => {}
        }
    }

    fn statement(&mut self, statement: &Stmt) {
        match statement {
            Stmt::AssignStmt(assign) => self.assignment(assign.target(), assign.value()),
            Stmt::SetStmt(set) => self.set_or_reset(set.target(), set.value()),
            Stmt::ResetStmt(reset) => self.set_or_reset(reset.target(), reset.value()),
            // Both sides are places; their types are checked by the runtime's rules for
            // references and interfaces, which need the declared (not dereferenced) type.
            Stmt::RefAssignStmt(assign) => self.places(assign.target(), assign.value()),
            Stmt::AttemptAssignStmt(assign) => self.places(assign.target(), assign.value()),
            Stmt::CallStmt(call) => {
                if let Some(call) = call.call() {
                    self.expression(&Expr::CallExpr(call), Mode::Read);
                }
            }
            Stmt::IfStmt(stmt) => {
                if let Some(condition) = stmt.condition() {
                    self.condition(&condition, "IF");
                }
                self.statement_list(stmt.then_branch());
                for branch in stmt.elsif_branches() {
                    if let Some(condition) = branch.condition() {
                        self.condition(&condition, "IF");
                    }
                    self.statement_list(branch.body());
                }
                self.statement_list(stmt.else_branch().and_then(|branch| branch.body()));
            }
            Stmt::WhileStmt(stmt) => {
                if let Some(condition) = stmt.condition() {
                    self.condition(&condition, "WHILE");
                }
                self.statement_list(stmt.body());
            }
            Stmt::RepeatStmt(stmt) => {
                self.statement_list(stmt.body());
                if let Some(condition) = stmt.condition() {
                    self.condition(&condition, "UNTIL");
                }
            }
            Stmt::ForStmt(stmt) => self.for_statement(stmt),
            Stmt::CaseStmt(stmt) => self.case_statement(stmt),
            Stmt::TransitionDecl(transition) => {
                if let Some(condition) = transition.condition() {
                    self.condition(&condition, "TRANSITION");
                }
                for statement in transition.statements() {
                    self.statement(&statement);
                }
            }
            // A step's properties and associations are checked with its chart.
            Stmt::StepDecl(_) => {}
            Stmt::ExitStmt(_)
            | Stmt::ContinueStmt(_)
            | Stmt::ReturnStmt(_)
            | Stmt::JmpStmt(_)
            | Stmt::LabelStmt(_)
            | Stmt::EmptyStmt(_) => {}
        }
    }

    fn set_or_reset(&mut self, target: Option<Expr>, value: Option<Expr>) {
        let (Some(target), Some(value)) = (target, value) else {
            return;
        };
        let target_ty = self.expression(&target, Mode::Write);
        if self.assignable_target(&target, &target_ty) {
            self.expect_type(&target_ty, &Type::BOOL, target.syntax(), "S= and R=");
        }
        let value_ty = self.expression(&value, Mode::Read);
        self.expect_type(&value_ty, &Type::BOOL, value.syntax(), "S= and R=");
    }

    fn places(&mut self, target: Option<Expr>, value: Option<Expr>) {
        if let (Some(target), Some(value)) = (target, value) {
            self.expression(&target, Mode::Write);
            self.expression(&value, Mode::Read);
            // `REF=` takes the place of its value too; `?=` only writes its target.
            if !self.refuse_unwritable_place(&target, PlaceUse::Connected) {
                self.refuse_unwritable_place(&value, PlaceUse::ByReference);
            }
        }
    }

    fn condition(&mut self, node: &Expr, keyword: &str) {
        let ty = self.expression(node, Mode::Read);
        if !ty.is_bool_like() {
            self.error(
                Code::TypeMismatch,
                range_of(node.syntax()),
                format!("the {keyword} condition must be BOOL, found {ty}"),
            );
        }
    }

    fn for_statement(&mut self, stmt: &ForStmt) {
        let bounds = [stmt.from(), stmt.to(), stmt.by()];
        match stmt.variable() {
            Some(variable) => {
                let ty = self.expression(&variable, Mode::Write);
                if self.assignable_target(&variable, &ty)
                    && !self.refuse_unwritable_place(&variable, PlaceUse::Connected)
                    && !ty.is_integer_like()
                {
                    self.error(
                        Code::TypeMismatch,
                        range_of(variable.syntax()),
                        format!("the FOR variable must be an integer, found {ty}"),
                    );
                }
                for bound in bounds.iter().flatten() {
                    let bound_ty = self.expression(bound, Mode::Read);
                    if ty.is_integer_like() {
                        self.expect_type(&bound_ty, &ty, bound.syntax(), "the FOR range");
                    }
                }
            }
            None => {
                for bound in bounds.iter().flatten() {
                    self.expression(bound, Mode::Read);
                }
            }
        }
        self.statement_list(stmt.body());
    }

    fn case_statement(&mut self, stmt: &CaseStmt) {
        let Some(selector) = stmt.selector() else {
            return;
        };
        let selector_ty = match self.expression(&selector, Mode::Read) {
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
                range_of(selector.syntax()),
                format!(
                    "the CASE selector must be an integer or an enumeration, found {selector_ty}"
                ),
            );
        }
        let mut seen: Vec<(i128, i128)> = Vec::new();
        for branch in stmt.branches() {
            for label in branch.labels() {
                self.case_label(&label, &selector_ty, &mut seen);
            }
            self.statement_list(branch.body());
        }
        self.statement_list(stmt.else_branch().and_then(|branch| branch.body()));
    }

    fn case_label(&mut self, label: &CaseLabel, selector: &Type, seen: &mut Vec<(i128, i128)>) {
        let bounds: Vec<Expr> = match label {
            CaseLabel::Range(range) => range.low().into_iter().chain(range.high()).collect(),
            CaseLabel::Value(value) => vec![value.clone()],
        };
        let mut values = Vec::new();
        for bound in &bounds {
            let ty = self.expression(bound, Mode::Read);
            self.expect_type(&ty, selector, bound.syntax(), "the CASE label");
            match self.constant_value(bound) {
                Some(Const::Int(value)) => values.push(value),
                // A constant of another type is reported as a type mismatch above.
                Some(_) => return,
                None => {
                    if ty != Type::Error {
                        self.error(
                            Code::NotConstant,
                            range_of(bound.syntax()),
                            format!(
                                "a CASE label must be a constant, found '{}'",
                                text(bound.syntax())
                            ),
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
                range_of(label.syntax()),
                format!(
                    "the CASE label '{}' is already covered by an earlier branch, which wins",
                    text(label.syntax())
                ),
            );
        }
        seen.push((low, high));
    }
    /// The value of a constant expression, with the POU's own constants visible.
    fn constant_value(&self, node: &Expr) -> Option<Const> {
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
    fn assignable_target(&mut self, target: &Expr, target_ty: &Type) -> bool {
        let not_a_place = matches!(
            target,
            Expr::Literal(_)
                | Expr::TypedLiteral(_)
                | Expr::CallExpr(_)
                | Expr::BinaryExpr(_)
                | Expr::UnaryExpr(_)
        );
        if not_a_place || *target_ty == Type::Void {
            self.error(
                Code::NotAssignable,
                range_of(target.syntax()),
                format!(
                    "'{}' is not a variable and cannot be assigned",
                    text(target.syntax())
                ),
            );
            return false;
        }
        true
    }

    /// Reports `value` where `expected` is needed, unless it converts implicitly.
    fn expect_type(&mut self, value: &Type, expected: &Type, node: &SyntaxNode, context: &str) {
        self.expect_type_converted(value, expected, node, context, true);
    }

    /// Reports `value` where a place of type `expected` is passed by reference (VAR_IN_OUT):
    /// there is no copy to convert, so CODESYS's lenient conversions do not apply.
    fn expect_same_place_type(
        &mut self,
        value: &Type,
        expected: &Type,
        node: &SyntaxNode,
        context: &str,
    ) {
        self.expect_type_converted(value, expected, node, context, false);
    }

    fn expect_type_converted(
        &mut self,
        value: &Type,
        expected: &Type,
        node: &SyntaxNode,
        context: &str,
        copied: bool,
    ) {
        if copied && self.bcd_call_takes_target(node, value, expected) {
            return;
        }
        if self.converts(value, expected) {
            return;
        }
        let target = match expected {
            Type::Reference(target) => target.as_ref(),
            other => other,
        };
        let narrowing = copied && lenient_integer_conversion(value, target);
        let rounding = copied && lenient_real_conversion(value, target);
        let real_to_integer = copied && lenient_real_to_integer(value, target);
        let lenient = narrowing || rounding || real_to_integer;
        if lenient && self.scope.globals.dialect == Dialect::Codesys {
            let (code, message) = if narrowing {
                (
                    Code::ImplicitNarrowing,
                    narrowing_message(value, target, context),
                )
            } else if real_to_integer {
                let from = match value {
                    Type::RealLiteral => "LREAL",
                    other => other.as_elementary().map_or("LREAL", |e| e.name()),
                };
                (
                    Code::ImplicitRealToInteger,
                    format!(
                        "{context} converts {value} to {target} implicitly, rounding to the nearest integer (halves away from zero) as {from}_TO_{target} does; write {from}_TO_{target}(…) or TRUNC to say so"
                    ),
                )
            } else {
                (
                    Code::ImplicitRealRounding,
                    format!(
                        "{context} converts {value} to {target} implicitly, which rounds integers it cannot hold exactly (use LREAL, or write {}_TO_{target}(…) to say so)",
                        value.as_elementary().map_or("ANY", |e| e.name()),
                    ),
                )
            };
            self.diagnostics
                .push(Diagnostic::new(code, range_of(node), message));
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
        if lenient {
            message.push_str(STRICT_NOTE);
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
    fn declared_reference(&self, node: &Expr) -> bool {
        let Expr::NameExpr(name) = node else {
            return false;
        };
        let name = text(name.syntax());
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
