//! Type checking of one ST body: every name resolved, every expression typed, every statement
//! checked against the IEC rules, and every local variable's reads and writes recorded for the
//! unused and unassigned warnings.

use std::collections::HashMap;
use std::ops::Range;

use project_model::{Pou, PouKind, VarSection, Variable};

use super::constant::{Const, evaluate, parse_expression};
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

/// A parameter of a call as the checker matches arguments to it.
struct Param {
    name: String,
    ty: Type,
    section: VarSection,
}

/// Checks one body in its scope.
pub(crate) struct BodyChecker<'s, 'a, 'p> {
    scope: &'s Scope<'a, 'p>,
    /// What was found.
    pub(crate) diagnostics: Vec<Diagnostic>,
    usage: &'s mut Usage,
    /// What each name refers to, collected only when asked for (hover, references).
    pub(crate) resolutions: Option<Vec<Resolution>>,
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
        }
    }

    /// Records what the name at `range` refers to, when resolutions are collected.
    fn note(
        &mut self,
        range: Range<usize>,
        ty: &Type,
        definition: impl FnOnce(&Self) -> Definition,
    ) {
        if self.resolutions.is_none() {
            return;
        }
        let definition = definition(self);
        if let Some(resolutions) = &mut self.resolutions {
            resolutions.push(Resolution {
                range,
                definition,
                ty: ty.to_string(),
            });
        }
    }

    /// The definition of a variable, with the object (and method or property) declaring it.
    fn variable_definition(&self, variable: &Variable) -> Definition {
        let detail = variable_detail(variable);
        let make = |object: &str, container: Option<&str>| Definition {
            kind: DefinitionKind::Variable,
            object: Some(object.to_owned()),
            container: container.map(str::to_owned),
            name: variable.name.clone(),
            detail: detail.clone(),
        };
        let is = |candidate: &Variable| std::ptr::eq(candidate, variable);
        if let Some(pou) = self.scope.pou {
            for current in inheritance_chain(self.scope.globals, pou) {
                if current.variables.iter().any(is) {
                    return make(&current.name, None);
                }
                for method in &current.methods {
                    if method.variables.iter().any(is) {
                        return make(&current.name, Some(&method.name));
                    }
                }
                for property in &current.properties {
                    if property
                        .get
                        .iter()
                        .chain(&property.set)
                        .any(|a| a.variables.iter().any(is))
                    {
                        return make(&current.name, Some(&property.name));
                    }
                }
            }
        }
        for gvl_name in self.scope.globals.gvl_names() {
            if let Some(GlobalSymbol::Gvl(gvl)) = self.scope.globals.lookup(gvl_name)
                && gvl.variables.iter().any(is)
            {
                return make(&gvl.name, None);
            }
        }
        make("", None)
    }

    fn error(&mut self, code: Code, range: Range<usize>, message: impl Into<String>) {
        self.diagnostics.push(Diagnostic::new(code, range, message));
    }

    /// The type written as `text`; array bounds that name the POU's own constants are
    /// resolved with them (the shared cache knows only the globals).
    fn resolve(&self, text: &str) -> Type {
        let ty = self.scope.globals.resolve_type(text);
        if has_open_bounds(&ty) && self.scope.pou.is_some() {
            let constants = |name: &str, container: Option<&str>, depth: u32| {
                self.named_constant(name, container, depth)
            };
            return super::types::resolve_type_text_with(self.scope.globals, text, &constants);
        }
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
        let selector_ty = self.expression(selector, Mode::Read);
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

    /// The type of an expression, reporting what is wrong inside it.
    fn expression(&mut self, node: &SyntaxNode, mode: Mode) -> Type {
        match node.kind() {
            SyntaxKind::LITERAL => literal_type(node),
            SyntaxKind::TYPED_LITERAL => self.typed_literal(node),
            SyntaxKind::PAREN_EXPR => node
                .children()
                .next()
                .map_or(Type::Error, |inner| self.expression(&inner, mode)),
            SyntaxKind::NAME_EXPR => self.name(node, mode),
            SyntaxKind::FIELD_EXPR => self.field(node, mode),
            SyntaxKind::INDEX_EXPR => self.index(node, mode),
            SyntaxKind::DEREF_EXPR => {
                let Some(base) = node.children().next() else {
                    return Type::Error;
                };
                match self.expression(&base, Mode::Read) {
                    Type::Pointer(target) | Type::Reference(target) => *target,
                    Type::Error => Type::Error,
                    // A CODESYS reference is used as its target, but `r^` is accepted too.
                    other if self.declared_reference(&base) => other,
                    other => {
                        self.error(
                            Code::InvalidOperands,
                            range_of(node),
                            format!("'^' needs a pointer, found {other}"),
                        );
                        Type::Error
                    }
                }
            }
            SyntaxKind::CALL_EXPR => self.call(node),
            SyntaxKind::UNARY_EXPR => self.unary(node),
            SyntaxKind::BINARY_EXPR => self.binary(node),
            SyntaxKind::ADDRESS_EXPR => tokens(node)
                .next()
                .map_or(Type::Error, |token| address_type(token.text())),
            _ => {
                // Array initialisers and error nodes: check what is inside for names. In an
                // initialiser `3(0)` repeats a value: only the value is an expression.
                for child in node.children() {
                    let repeated = child.kind() == SyntaxKind::CALL_EXPR
                        && child
                            .children()
                            .next()
                            .is_some_and(|callee| callee.kind() == SyntaxKind::LITERAL);
                    if repeated {
                        for value in child.descendants().filter(|d| d.kind() == SyntaxKind::ARG) {
                            if let Some(value) = value.children().next() {
                                self.expression(&value, Mode::Read);
                            }
                        }
                    } else {
                        self.expression(&child, Mode::Read);
                    }
                }
                Type::Error
            }
        }
    }

    fn typed_literal(&mut self, node: &SyntaxNode) -> Type {
        let parts: Vec<SyntaxToken> = tokens(node).collect();
        let Some(prefix) = parts.first() else {
            return Type::Error;
        };
        let Some(value) = parts.last() else {
            return Type::Error;
        };
        if let Some(elementary) = Elementary::from_name(prefix.text()) {
            let ty = Type::elementary(elementary);
            let negative = parts.iter().any(|t| t.kind() == SyntaxKind::MINUS);
            let fits = match value.kind() {
                SyntaxKind::INT_NUMBER => {
                    let parsed = literal::parse_integer(value.text())
                        .ok()
                        .and_then(|v| i128::try_from(v).ok())
                        .map(|v| if negative { -v } else { v });
                    implicitly_converts(&Type::IntLiteral(parsed), &ty) || elementary.is_real()
                }
                SyntaxKind::REAL_NUMBER => elementary.is_real(),
                SyntaxKind::TRUE | SyntaxKind::FALSE => elementary == Elementary::Bool,
                _ => true,
            };
            if !fits {
                self.error(
                    Code::TypeMismatch,
                    range_of(node),
                    format!("'{}' is not a value of {ty}", text(node)),
                );
            }
            return ty;
        }
        // `E_State#Idle`.
        let globals = self.scope.globals;
        match globals.data_type(prefix.text()) {
            Some(data_type) => {
                if globals.enum_value(data_type, value.text(), 0).is_none() {
                    self.unknown_member(
                        &data_type.name,
                        value,
                        globals.member_names(&data_type.name),
                    );
                }
                Type::Named(data_type.name.clone())
            }
            None => {
                let mut diagnostic = Diagnostic::new(
                    Code::UnknownType,
                    token_range(prefix),
                    format!("unknown type '{}'", prefix.text()),
                );
                if let Some(suggestion) = globals.suggest(prefix.text()) {
                    diagnostic
                        .message
                        .push_str(&format!("; did you mean '{suggestion}'?"));
                }
                self.diagnostics.push(diagnostic);
                Type::Error
            }
        }
    }

    fn unknown_member(&mut self, container: &str, member: &SyntaxToken, names: Vec<&str>) {
        let name = member.text();
        let message = match closest(name, names.into_iter()) {
            Some(suggestion) => {
                format!("'{container}' has no member '{name}'; did you mean '{suggestion}'?")
            }
            None => format!("'{container}' has no member '{name}'"),
        };
        self.error(Code::UnknownName, token_range(member), message);
    }

    fn name(&mut self, node: &SyntaxNode, mode: Mode) -> Type {
        let ty = self.name_type(node, mode);
        if self.resolutions.is_some()
            && let Some(token) = tokens(node).find(|t| t.kind() == SyntaxKind::IDENT)
            && let Some(definition) = self.definition_of_name(&token, node)
        {
            self.note(token_range(&token), &ty, |_| definition);
        }
        ty
    }

    /// What the name `token` (in the name expression `node`) refers to.
    fn definition_of_name(&self, token: &SyntaxToken, node: &SyntaxNode) -> Option<Definition> {
        let name = token.text();
        let global_only = tokens(node)
            .next()
            .is_some_and(|t| t.kind() == SyntaxKind::DOT);
        let pou_name = self.scope.pou.map(|pou| pou.name.clone());
        let simple = |kind,
                      object: Option<String>,
                      container: Option<String>,
                      name: &str,
                      detail: String| Definition {
            kind,
            object,
            container,
            name: name.to_owned(),
            detail,
        };
        if !global_only && let Some(local) = self.scope.local(name) {
            return Some(match local {
                LocalSymbol::Var(variable) => self.variable_definition(variable),
                LocalSymbol::Result(ty) => simple(
                    DefinitionKind::Result,
                    pou_name,
                    None,
                    name,
                    format!("{name} : {ty} (the result)"),
                ),
                LocalSymbol::Method(method) => simple(
                    DefinitionKind::Method,
                    self.owner_of_member(name),
                    None,
                    &method.name,
                    format!(
                        "METHOD {}{}",
                        method.name,
                        method
                            .return_type
                            .as_deref()
                            .map(|t| format!(" : {t}"))
                            .unwrap_or_default()
                    ),
                ),
                LocalSymbol::Property(property) => simple(
                    DefinitionKind::Property,
                    self.owner_of_member(name),
                    None,
                    &property.name,
                    format!("PROPERTY {} : {}", property.name, property.ty),
                ),
                LocalSymbol::Action => simple(
                    DefinitionKind::Action,
                    pou_name,
                    None,
                    name,
                    format!("ACTION {name}"),
                ),
                LocalSymbol::Step => simple(
                    DefinitionKind::Step,
                    pou_name,
                    None,
                    name,
                    format!("STEP {name}"),
                ),
            });
        }
        let globals = self.scope.globals;
        Some(match globals.lookup(name)? {
            GlobalSymbol::Var(variable) => self.variable_definition(variable),
            GlobalSymbol::Pou(pou) => simple(
                DefinitionKind::Pou,
                Some(pou.name.clone()),
                None,
                &pou.name,
                pou_detail(pou),
            ),
            GlobalSymbol::Gvl(gvl) => simple(
                DefinitionKind::GlobalVarList,
                Some(gvl.name.clone()),
                None,
                &gvl.name,
                format!("global variable list {}", gvl.name),
            ),
            GlobalSymbol::DataType(data_type) => simple(
                DefinitionKind::DataType,
                Some(data_type.name.clone()),
                None,
                &data_type.name,
                format!("TYPE {}", data_type.name),
            ),
            GlobalSymbol::EnumValue(data_type) => {
                let value = globals
                    .enum_value(data_type, name, 0)
                    .and_then(Const::as_int);
                let detail = match value {
                    Some(value) => format!("{}.{name} = {value}", data_type.name),
                    None => format!("{}.{name}", data_type.name),
                };
                simple(
                    DefinitionKind::EnumValue,
                    Some(data_type.name.clone()),
                    None,
                    name,
                    detail,
                )
            }
            GlobalSymbol::Axis => simple(
                DefinitionKind::Axis,
                None,
                None,
                name,
                format!("axis {name}"),
            ),
        })
    }

    /// The POU (this one or a base) that declares the method or property `name`.
    fn owner_of_member(&self, name: &str) -> Option<String> {
        let pou = self.scope.pou?;
        inheritance_chain(self.scope.globals, pou)
            .into_iter()
            .find(|current| {
                current
                    .methods
                    .iter()
                    .any(|m| m.name.eq_ignore_ascii_case(name))
                    || current
                        .properties
                        .iter()
                        .any(|p| p.name.eq_ignore_ascii_case(name))
            })
            .map(|current| current.name.clone())
    }

    fn name_type(&mut self, node: &SyntaxNode, mode: Mode) -> Type {
        let mut parts = tokens(node);
        let Some(first) = parts.next() else {
            return Type::Error;
        };
        let (token, global_only) = match first.kind() {
            SyntaxKind::IDENT => (first, false),
            SyntaxKind::THIS => {
                return match self.scope.pou {
                    Some(pou) => Type::Pointer(Box::new(Type::Named(pou.name.clone()))),
                    None => Type::Error,
                };
            }
            SyntaxKind::SUPER => {
                return match self.scope.pou.and_then(|pou| pou.extends.as_ref()) {
                    Some(base) => Type::Pointer(Box::new(Type::Named(base.clone()))),
                    None => Type::Error,
                };
            }
            // `.name` is a global even where a local hides it.
            SyntaxKind::DOT => match parts.next() {
                Some(token) if token.kind() == SyntaxKind::IDENT => (token, true),
                _ => return Type::Error,
            },
            // `MOD(a, b)` and friends: operator keywords called like functions.
            _ => return Type::Error,
        };
        let name = token.text();
        if !global_only && let Some(local) = self.scope.local(name) {
            return match local {
                LocalSymbol::Var(variable) => self.variable(variable, mode, &token, true),
                LocalSymbol::Result(ty) => self.resolve(ty),
                LocalSymbol::Property(property) => self.resolve(&property.ty),
                LocalSymbol::Method(_) | LocalSymbol::Action => Type::Void,
                LocalSymbol::Step => Type::Step,
            };
        }
        let globals = self.scope.globals;
        match globals.lookup(name) {
            Some(GlobalSymbol::Var(variable)) => self.variable(variable, mode, &token, false),
            Some(GlobalSymbol::Pou(pou)) => match pou.kind {
                PouKind::Program => Type::Named(pou.name.clone()),
                _ => Type::Void,
            },
            Some(GlobalSymbol::Gvl(gvl)) => Type::Namespace(gvl.name.clone()),
            Some(GlobalSymbol::DataType(data_type)) => Type::EnumNamespace(data_type.name.clone()),
            Some(GlobalSymbol::EnumValue(data_type)) => Type::Named(data_type.name.clone()),
            Some(GlobalSymbol::Axis) => Type::Error,
            None if stdlib::is_function(name) || stdlib::is_function_block(name) => Type::Void,
            None => {
                let mut diagnostic = Diagnostic::new(
                    Code::UnknownName,
                    token_range(&token),
                    format!("unknown name '{name}'"),
                );
                if let Some(suggestion) = self.scope.suggest(name) {
                    diagnostic.message =
                        format!("unknown name '{name}'; did you mean '{suggestion}'?");
                }
                self.diagnostics.push(diagnostic);
                Type::Error
            }
        }
    }

    /// A variable used by name: records the use and reports writes to constants and inputs.
    fn variable(
        &mut self,
        variable: &Variable,
        mode: Mode,
        token: &SyntaxToken,
        local: bool,
    ) -> Type {
        self.record(variable, mode);
        if mode == Mode::Write {
            if variable.constant {
                self.error(
                    Code::NotAssignable,
                    token_range(token),
                    format!("'{}' is a CONSTANT and cannot be assigned", variable.name),
                );
            } else if local && variable.section == VarSection::VarInput {
                self.error(
                    Code::AssignmentToInput,
                    token_range(token),
                    format!(
                        "'{}' is an input: IEC 61131-3 forbids assigning it inside the POU, and the caller's value is lost",
                        variable.name
                    ),
                );
            }
        }
        dereferenced(self.resolve(&variable.ty))
    }

    fn field(&mut self, node: &SyntaxNode, mode: Mode) -> Type {
        let Some(base) = node.children().next() else {
            return Type::Error;
        };
        let Some(member) = tokens(node)
            .filter(|t| {
                matches!(
                    t.kind(),
                    SyntaxKind::IDENT | SyntaxKind::INT_NUMBER | SyntaxKind::DIRECT_ADDRESS
                )
            })
            .last()
        else {
            return Type::Error;
        };
        let from_inside = base.kind() == SyntaxKind::DEREF_EXPR
            && base.children().next().is_some_and(|b| {
                matches!(text(&b).to_ascii_uppercase().as_str(), "THIS" | "SUPER")
            });
        let base_ty = self.expression(&base, mode);
        let globals = self.scope.globals;
        let name = member.text();
        match base_ty {
            Type::Error | Type::Void => Type::Error,
            Type::Namespace(gvl_name) => {
                let Some(GlobalSymbol::Gvl(gvl)) = globals.lookup(&gvl_name) else {
                    return Type::Error;
                };
                match gvl
                    .variables
                    .iter()
                    .find(|v| v.name.eq_ignore_ascii_case(name))
                {
                    Some(variable) => {
                        let ty = self.variable(variable, mode, &member, false);
                        self.note(token_range(&member), &ty, |checker| {
                            checker.variable_definition(variable)
                        });
                        ty
                    }
                    None => {
                        self.unknown_member(&gvl_name, &member, globals.member_names(&gvl_name));
                        Type::Error
                    }
                }
            }
            Type::EnumNamespace(enum_name) => {
                let value = globals
                    .data_type(&enum_name)
                    .and_then(|data_type| globals.enum_value(data_type, name, 0));
                if value.is_none() {
                    self.unknown_member(&enum_name, &member, globals.member_names(&enum_name));
                    return Type::Error;
                }
                if mode == Mode::Write {
                    self.error(
                        Code::NotAssignable,
                        range_of(node),
                        format!(
                            "'{}' is an enumeration value and cannot be assigned",
                            text(node)
                        ),
                    );
                }
                Type::Named(enum_name)
            }
            Type::Named(type_name) => {
                let Some(found) = globals.member(&type_name, name) else {
                    if globals.shape(&type_name).is_some() {
                        let names = globals.member_names_of(&type_name);
                        let names: Vec<&str> = names.iter().map(String::as_str).collect();
                        self.unknown_member(&type_name, &member, names);
                    }
                    return Type::Error;
                };
                let is_fb = matches!(globals.shape(&type_name), Some(Shape::Pou(pou)) if pou.kind == PouKind::FunctionBlock)
                    || matches!(globals.shape(&type_name), Some(Shape::StandardFb(_)));
                if is_fb && !from_inside && !found.is_method && !is_visible_outside(found.section) {
                    self.error(
                        Code::Inaccessible,
                        token_range(&member),
                        format!(
                            "'{name}' is internal to {type_name}; from outside only its inputs, outputs, methods and properties are visible"
                        ),
                    );
                } else if mode == Mode::Write
                    && is_fb
                    && !from_inside
                    && found.section == VarSection::VarOutput
                    && !found.is_method
                {
                    self.error(
                        Code::NotAssignable,
                        range_of(node),
                        format!(
                            "'{}' is an output of {type_name} and is written only by it",
                            text(node)
                        ),
                    );
                } else if mode == Mode::Write && found.constant {
                    self.error(
                        Code::NotAssignable,
                        range_of(node),
                        format!("'{}' is a CONSTANT and cannot be assigned", text(node)),
                    );
                }
                let ty = if found.is_method {
                    Type::Void
                } else {
                    dereferenced(found.ty)
                };
                let owner = match globals.shape(&type_name) {
                    Some(Shape::Pou(pou)) => inheritance_chain(globals, pou)
                        .into_iter()
                        .find(|p| {
                            p.variables
                                .iter()
                                .any(|v| v.name.eq_ignore_ascii_case(name))
                                || p.methods.iter().any(|m| m.name.eq_ignore_ascii_case(name))
                                || p.properties
                                    .iter()
                                    .any(|m| m.name.eq_ignore_ascii_case(name))
                        })
                        .map(|p| p.name.clone()),
                    Some(Shape::Struct(data_type)) => Some(data_type.name.clone()),
                    _ => None,
                };
                let declared = owner.as_deref().and_then(|o| globals.pou(o)).and_then(|p| {
                    p.variables
                        .iter()
                        .find(|v| v.name.eq_ignore_ascii_case(name))
                });
                let detail = match declared {
                    Some(variable) => variable_detail(variable),
                    None => format!("{type_name}.{name} : {ty}"),
                };
                // A function block's variables, methods and properties are the same
                // declarations whether reached from inside or through an instance.
                let kind = match (&owner, globals.shape(&type_name)) {
                    (None, _) => DefinitionKind::Standard,
                    (Some(_), Some(Shape::Pou(_))) if found.is_method => DefinitionKind::Method,
                    (Some(owner_name), Some(Shape::Pou(_))) => {
                        let is_property = globals.pou(owner_name).is_some_and(|p| {
                            p.properties
                                .iter()
                                .any(|q| q.name.eq_ignore_ascii_case(name))
                        });
                        if is_property {
                            DefinitionKind::Property
                        } else {
                            DefinitionKind::Variable
                        }
                    }
                    (Some(_), _) => DefinitionKind::Member,
                };
                self.note(token_range(&member), &ty, |_| Definition {
                    kind,
                    object: owner,
                    container: None,
                    name: name.to_owned(),
                    detail,
                });
                ty
            }
            Type::Step => match name.to_ascii_uppercase().as_str() {
                "X" => Type::BOOL,
                "T" => Type::Elementary(Elementary::Time),
                _ => {
                    self.unknown_member(&text(&base), &member, vec!["X", "T"]);
                    Type::Error
                }
            },
            Type::Pointer(_) => {
                self.error(
                    Code::InvalidOperands,
                    range_of(node),
                    format!(
                        "'{}' is a pointer: dereference it first, as in '{}^.{name}'",
                        text(&base),
                        text(&base)
                    ),
                );
                Type::Error
            }
            other => {
                // `x.3`, `x.%X3`: one bit of an integer or bit string; `x.%B1`, `x.%W0`,
                // `x.%D0`: one byte, word or double word of it.
                let bits = other
                    .as_elementary()
                    .filter(|e| e.is_integer() || (e.is_bit_string() && *e != Elementary::Bool))
                    .map(Elementary::size_bits);
                let (part, index) = if member.kind() == SyntaxKind::INT_NUMBER {
                    (Elementary::Bool, literal::parse_integer(name).ok())
                } else {
                    let upper = name.to_ascii_uppercase();
                    let rest = upper.trim_start_matches('%');
                    let part = match rest.chars().next() {
                        Some('B') => Elementary::Byte,
                        Some('W') => Elementary::Word,
                        Some('D') => Elementary::Dword,
                        _ => Elementary::Bool,
                    };
                    let digits = rest.trim_start_matches(['X', 'B', 'W', 'D']);
                    (part, digits.parse::<u128>().ok())
                };
                let part_bits = if part == Elementary::Bool {
                    1
                } else {
                    part.size_bits()
                };
                match (bits, index) {
                    (Some(bits), Some(index))
                        if (index + 1) * u128::from(part_bits) <= u128::from(bits) =>
                    {
                        Type::Elementary(part)
                    }
                    (Some(bits), Some(_)) => {
                        let count = bits / part_bits;
                        let unit = if part_bits == 1 { "bit" } else { part.name() };
                        self.error(
                            Code::IndexOutOfRange,
                            token_range(&member),
                            format!(
                                "{unit} {name} does not exist in {other}, which has {count} of them numbered from 0"
                            ),
                        );
                        Type::Error
                    }
                    _ => {
                        self.error(
                            Code::InvalidOperands,
                            token_range(&member),
                            format!("'{}' is {other}, which has no members", text(&base)),
                        );
                        Type::Error
                    }
                }
            }
        }
    }

    fn index(&mut self, node: &SyntaxNode, mode: Mode) -> Type {
        let mut children = node.children();
        let Some(base) = children.next() else {
            return Type::Error;
        };
        let indices: Vec<SyntaxNode> = children.collect();
        let base_ty = self.expression(&base, mode);
        let mut index_types = Vec::new();
        for index in &indices {
            let ty = self.expression(index, Mode::Read);
            if !ty.is_integer_like()
                && !matches!(&ty, Type::Named(n) if matches!(self.scope.globals.shape(n), Some(Shape::Enum(_))))
            {
                self.error(
                    Code::TypeMismatch,
                    range_of(index),
                    format!("an array index must be an integer, found {ty}"),
                );
            }
            index_types.push(ty);
        }
        match base_ty {
            Type::Error => Type::Error,
            Type::Array { element, dims } => {
                if dims.len() != indices.len() {
                    self.error(
                        Code::IndexOutOfRange,
                        range_of(node),
                        format!(
                            "'{}' has {} dimension(s) but {} index(es) are given",
                            text(&base),
                            dims.len(),
                            indices.len()
                        ),
                    );
                    return *element;
                }
                for (index, dim) in indices.iter().zip(&dims) {
                    if let (Some((low, high)), Some(Const::Int(value))) =
                        (dim, self.constant_value(index))
                        && !(*low..=*high).contains(&value)
                    {
                        self.error(
                            Code::IndexOutOfRange,
                            range_of(index),
                            format!(
                                "index {value} is outside the bounds {low}..{high} of '{}'",
                                text(&base)
                            ),
                        );
                    }
                }
                *element
            }
            Type::String { wide, .. } => Type::Elementary(if wide {
                Elementary::Word
            } else {
                Elementary::Byte
            }),
            Type::Pointer(target) => *target,
            other => {
                self.error(
                    Code::InvalidOperands,
                    range_of(node),
                    format!("'{}' is {other}, which cannot be indexed", text(&base)),
                );
                Type::Error
            }
        }
    }

    fn unary(&mut self, node: &SyntaxNode) -> Type {
        let Some(operator) = tokens(node).next() else {
            return Type::Error;
        };
        let Some(operand) = node.children().next() else {
            return Type::Error;
        };
        let ty = self.expression(&operand, Mode::Read);
        let ok = match operator.kind() {
            SyntaxKind::NOT => ty.is_bits() || ty.is_bool_like(),
            SyntaxKind::MINUS | SyntaxKind::PLUS => {
                ty.is_numeric()
                    || matches!(ty, Type::Elementary(Elementary::Time | Elementary::Ltime))
            }
            _ => true,
        };
        if !ok {
            self.error(
                Code::InvalidOperands,
                range_of(node),
                format!("'{}' is not defined for {ty}", operator.text()),
            );
            return Type::Error;
        }
        match (operator.kind(), ty) {
            (SyntaxKind::MINUS, Type::IntLiteral(Some(value))) => {
                Type::IntLiteral(value.checked_neg())
            }
            (_, ty) => ty,
        }
    }

    fn binary(&mut self, node: &SyntaxNode) -> Type {
        let mut operands = node.children();
        let (Some(left_node), right_node) = (operands.next(), operands.next()) else {
            return Type::Error;
        };
        let left = self.expression(&left_node, Mode::Read);
        let Some(right_node) = right_node else {
            return Type::Error;
        };
        let right = self.expression(&right_node, Mode::Read);
        let Some(operator) = tokens(node).next() else {
            return Type::Error;
        };
        if left == Type::Error || right == Type::Error {
            return match operator.kind() {
                SyntaxKind::EQ
                | SyntaxKind::NEQ
                | SyntaxKind::LT
                | SyntaxKind::LE
                | SyntaxKind::GT
                | SyntaxKind::GE => Type::BOOL,
                _ => Type::Error,
            };
        }
        let result = self.binary_type(operator.kind(), &left, &right);
        if let Some(ty) = result {
            // Fold literal arithmetic so `-128` or `2 * 64` still fit a SINT.
            if matches!(ty, Type::IntLiteral(_))
                && let Some(Const::Int(value)) = self.constant_value(node)
            {
                return Type::IntLiteral(Some(value));
            }
            return ty;
        }
        let mut message = format!(
            "'{}' is not defined for {left} and {right}",
            operator.text()
        );
        if let (Some(a), Some(b)) = (left.as_elementary(), right.as_elementary())
            && (a.is_integer() || a.is_real())
            && (b.is_integer() || b.is_real())
        {
            message.push_str(&format!(
                "; neither converts implicitly to the other, so convert one (for example {}_TO_{})",
                a.name(),
                b.name()
            ));
        }
        self.error(Code::InvalidOperands, range_of(node), message);
        Type::Error
    }

    fn binary_type(&self, operator: SyntaxKind, left: &Type, right: &Type) -> Option<Type> {
        use Elementary::*;
        use SyntaxKind::*;
        let is_enum = |ty: &Type| matches!(ty, Type::Named(n) if matches!(self.scope.globals.shape(n), Some(Shape::Enum(_))));
        match operator {
            PLUS | MINUS | STAR | SLASH => {
                if left.is_numeric() && right.is_numeric() {
                    return common_type(left, right);
                }
                let (l, r) = (left.as_elementary(), right.as_elementary());
                let numeric = |ty: &Type| ty.is_numeric();
                match (operator, l, r) {
                    (PLUS | MINUS, Some(Time), Some(Time)) => Some(Type::Elementary(Time)),
                    (PLUS | MINUS, Some(Ltime), Some(Time | Ltime))
                    | (PLUS | MINUS, Some(Time), Some(Ltime)) => Some(Type::Elementary(Ltime)),
                    (PLUS | MINUS, Some(TimeOfDay), Some(Time)) => {
                        Some(Type::Elementary(TimeOfDay))
                    }
                    (PLUS | MINUS, Some(DateAndTime), Some(Time)) => {
                        Some(Type::Elementary(DateAndTime))
                    }
                    (PLUS, Some(Time), Some(TimeOfDay)) => Some(Type::Elementary(TimeOfDay)),
                    (PLUS, Some(Time), Some(DateAndTime)) => Some(Type::Elementary(DateAndTime)),
                    (MINUS, Some(TimeOfDay), Some(TimeOfDay))
                    | (MINUS, Some(DateAndTime), Some(DateAndTime))
                    | (MINUS, Some(Date), Some(Date)) => Some(Type::Elementary(Time)),
                    (STAR | SLASH, Some(t @ (Time | Ltime)), _) if numeric(right) => {
                        Some(Type::Elementary(t))
                    }
                    (STAR, _, Some(t @ (Time | Ltime))) if numeric(left) => {
                        Some(Type::Elementary(t))
                    }
                    _ => match (left, right) {
                        // Pointer arithmetic, as CODESYS allows.
                        (Type::Pointer(_), other) | (other, Type::Pointer(_))
                            if matches!(operator, PLUS | MINUS) && other.is_integer_like() =>
                        {
                            Some(if matches!(left, Type::Pointer(_)) {
                                left.clone()
                            } else {
                                right.clone()
                            })
                        }
                        _ => None,
                    },
                }
            }
            MOD => {
                if left.is_integer_like() && right.is_integer_like() {
                    common_type(left, right)
                } else {
                    None
                }
            }
            POWER => {
                if !(left.is_numeric() && right.is_numeric()) {
                    return None;
                }
                Some(match (left, right) {
                    (
                        Type::IntLiteral(_) | Type::RealLiteral,
                        Type::IntLiteral(_) | Type::RealLiteral,
                    ) => Type::RealLiteral,
                    _ if left.as_elementary() == Some(Lreal)
                        || right.as_elementary() == Some(Lreal) =>
                    {
                        Type::Elementary(Lreal)
                    }
                    _ => Type::Elementary(Real),
                })
            }
            EQ | NEQ | LT | LE | GT | GE => {
                let comparable = match (left, right) {
                    (Type::Named(a), Type::Named(b)) => {
                        a.eq_ignore_ascii_case(b) && (is_enum(left) || matches!(operator, EQ | NEQ))
                    }
                    (Type::String { wide: a, .. }, Type::String { wide: b, .. }) => a == b,
                    (Type::Pointer(_), Type::Pointer(_)) => true,
                    (Type::Pointer(_), other) | (other, Type::Pointer(_)) => {
                        other.is_integer_like()
                    }
                    (enumeration, other) | (other, enumeration) if is_enum(enumeration) => {
                        other.is_integer_like()
                    }
                    _ => common_type(left, right).is_some(),
                };
                comparable.then_some(Type::BOOL)
            }
            AND | OR | XOR | AMP => {
                if left.is_bool_like() && right.is_bool_like() {
                    return Some(Type::BOOL);
                }
                if left.is_bits() && right.is_bits() {
                    return common_type(left, right);
                }
                None
            }
            AND_THEN | OR_ELSE => {
                (left.is_bool_like() && right.is_bool_like()).then_some(Type::BOOL)
            }
            _ => None,
        }
    }

    fn call(&mut self, node: &SyntaxNode) -> Type {
        let Some(callee) = node.children().next() else {
            return Type::Error;
        };
        let arguments: Vec<SyntaxNode> = node
            .children()
            .find(|child| child.kind() == SyntaxKind::ARG_LIST)
            .map(|list| {
                list.children()
                    .filter(|c| c.kind() == SyntaxKind::ARG)
                    .collect()
            })
            .unwrap_or_default();
        let callee_name = match callee.kind() {
            SyntaxKind::NAME_EXPR => tokens(&callee)
                .find(|t| {
                    matches!(
                        t.kind(),
                        SyntaxKind::IDENT
                            | SyntaxKind::MOD
                            | SyntaxKind::AND
                            | SyntaxKind::OR
                            | SyntaxKind::XOR
                    )
                })
                .map(|t| t.text().to_owned()),
            _ => None,
        };
        let globals = self.scope.globals;
        // Functions and methods called by name.
        if let Some(name) = &callee_name
            && self.resolutions.is_some()
            && let Some(token) = tokens(&callee).find(|t| t.kind() == SyntaxKind::IDENT)
        {
            let definition = self.definition_of_name(&token, &callee).or_else(|| {
                let signature = signatures::function(name).map(|sig| signature_detail(name, &sig));
                let block = signatures::function_block(name)
                    .map(|_| format!("FUNCTION_BLOCK {}", name.to_ascii_uppercase()));
                signature.or(block).map(|detail| Definition {
                    kind: DefinitionKind::Standard,
                    object: None,
                    container: None,
                    name: name.to_ascii_uppercase(),
                    detail,
                })
            });
            if let Some(definition) = definition {
                self.note(token_range(&token), &Type::Void, |_| definition);
            }
        }
        if let Some(name) = &callee_name {
            let global_only = tokens(&callee)
                .next()
                .is_some_and(|t| t.kind() == SyntaxKind::DOT);
            let local = if global_only {
                None
            } else {
                self.scope.local(name)
            };
            match local {
                Some(LocalSymbol::Method(method)) => {
                    let params = params_of(&method.variables, |t| self.resolve(t));
                    self.arguments(name, &params, &arguments, true);
                    return method
                        .return_type
                        .as_deref()
                        .map_or(Type::Void, |t| dereferenced(self.resolve(t)));
                }
                Some(LocalSymbol::Action) => {
                    self.arguments(name, &[], &arguments, true);
                    return Type::Void;
                }
                Some(_) => {}
                None => match globals.lookup(name) {
                    Some(GlobalSymbol::Pou(pou)) => {
                        return self.call_pou(name, pou, &callee, &arguments);
                    }
                    Some(_) => {}
                    None => {
                        if let Some(signature) = signatures::function(name) {
                            return self.call_standard(name, &signature, &arguments, node);
                        }
                        if stdlib::is_function_block(name) {
                            self.error(
                                Code::InvalidCall,
                                range_of(&callee),
                                format!("'{name}' is a function block type; declare an instance and call that"),
                            );
                            self.arguments_unchecked(&arguments);
                            return Type::Error;
                        }
                    }
                },
            }
        }
        // Everything else is an instance or a member: `fbTimer(…)`, `fb.Method(…)`.
        let callee_ty = self.expression(&callee, Mode::Read);
        if callee.kind() == SyntaxKind::FIELD_EXPR
            && let Some(method) = self.member_method(&callee)
        {
            let (method_name, method) = method;
            let params = params_of(&method.variables, |t| self.resolve(t));
            self.arguments(&method_name, &params, &arguments, true);
            return method
                .return_type
                .as_deref()
                .map_or(Type::Void, |t| dereferenced(self.resolve(t)));
        }
        match callee_ty {
            Type::Error => {
                self.arguments_unchecked(&arguments);
                Type::Error
            }
            // An action of an instance, `fb.Act()`, or something already reported.
            Type::Void => {
                self.arguments_unchecked(&arguments);
                Type::Void
            }
            Type::Named(type_name) if globals.is_instance_type(&type_name) => {
                let params = self.instance_params(&type_name);
                self.arguments(&text(&callee), &params, &arguments, false);
                Type::Void
            }
            Type::Pointer(_) => {
                self.arguments_unchecked(&arguments);
                Type::Error
            }
            other => {
                self.error(
                    Code::InvalidCall,
                    range_of(&callee),
                    format!("'{}' is {other} and cannot be called", text(&callee)),
                );
                self.arguments_unchecked(&arguments);
                Type::Error
            }
        }
    }

    /// The method a `base.Method` callee names, if it names one.
    fn member_method(&self, callee: &SyntaxNode) -> Option<(String, &'p project_model::Method)> {
        let base = callee.children().next()?;
        let member = tokens(callee)
            .filter(|t| t.kind() == SyntaxKind::IDENT)
            .last()?;
        let globals = self.scope.globals;
        let type_name = match self.peek_type(&base)? {
            Type::Named(name) => name,
            _ => return None,
        };
        let Some(Shape::Pou(pou)) = globals.shape(&type_name) else {
            return None;
        };
        inheritance_chain(globals, pou)
            .into_iter()
            .find_map(|current| {
                current
                    .methods
                    .iter()
                    .find(|m| m.name.eq_ignore_ascii_case(member.text()))
                    .map(|m| (m.name.clone(), m))
            })
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

    /// The type of an expression without reporting anything (used to look ahead).
    fn peek_type(&self, node: &SyntaxNode) -> Option<Type> {
        let mut usage = Usage::new();
        let mut checker = BodyChecker::new(self.scope, &mut usage);
        Some(checker.expression(node, Mode::Read))
    }

    fn call_pou(
        &mut self,
        name: &str,
        pou: &Pou,
        callee: &SyntaxNode,
        arguments: &[SyntaxNode],
    ) -> Type {
        match pou.kind {
            PouKind::Function => {
                let params = params_of(&pou.variables, |t| self.resolve(t));
                self.arguments(name, &params, arguments, true);
                pou.return_type
                    .as_deref()
                    .map_or(Type::Void, |t| dereferenced(self.resolve(t)))
            }
            PouKind::Program => {
                let params = params_of(&pou.variables, |t| self.resolve(t));
                self.arguments(name, &params, arguments, false);
                Type::Void
            }
            PouKind::FunctionBlock | PouKind::Interface => {
                self.error(
                    Code::InvalidCall,
                    range_of(callee),
                    format!("'{name}' is a function block type; declare an instance and call that"),
                );
                self.arguments_unchecked(arguments);
                Type::Error
            }
        }
    }

    fn instance_params(&self, type_name: &str) -> Vec<Param> {
        let globals = self.scope.globals;
        match globals.shape(type_name) {
            Some(Shape::Pou(pou)) => inheritance_chain(globals, pou)
                .into_iter()
                .rev()
                .flat_map(|current| params_of(&current.variables, |t| self.resolve(t)))
                .collect(),
            Some(Shape::StandardFb(fb)) => fb
                .inputs
                .iter()
                .map(|(name, ty)| Param {
                    name: (*name).to_owned(),
                    ty: Type::elementary(*ty),
                    section: VarSection::VarInput,
                })
                .chain(fb.aliases.iter().filter_map(|(alias, input)| {
                    fb.member(input).map(|(ty, _)| Param {
                        name: (*alias).to_owned(),
                        ty,
                        section: VarSection::VarInput,
                    })
                }))
                .chain(fb.outputs.iter().map(|(name, ty)| Param {
                    name: (*name).to_owned(),
                    ty: Type::elementary(*ty),
                    section: VarSection::VarOutput,
                }))
                .collect(),
            _ => Vec::new(),
        }
    }

    /// Checks the arguments of a call against the parameters. Positional arguments fill the
    /// inputs (and in-outs) in order, as IEC allows for functions and methods.
    fn arguments(
        &mut self,
        callee: &str,
        params: &[Param],
        arguments: &[SyntaxNode],
        function_like: bool,
    ) {
        let positional_params: Vec<&Param> = params
            .iter()
            .filter(|p| matches!(p.section, VarSection::VarInput | VarSection::VarInOut))
            .collect();
        let mut positional = 0usize;
        let mut given: Vec<String> = Vec::new();
        for argument in arguments {
            let parts: Vec<SyntaxToken> = tokens(argument).collect();
            let value = argument.children().next();
            let formal = parts
                .iter()
                .position(|t| matches!(t.kind(), SyntaxKind::ASSIGN | SyntaxKind::OUTPUT_ASSIGN))
                .and_then(|at| Some((parts.get(at.checked_sub(1)?)?.clone(), parts[at].kind())));
            // EN and ENO belong to every call in IEC 61131-3.
            if let Some((name, arrow)) = &formal
                && (name.text().eq_ignore_ascii_case("EN") && *arrow == SyntaxKind::ASSIGN
                    || name.text().eq_ignore_ascii_case("ENO")
                        && *arrow == SyntaxKind::OUTPUT_ASSIGN)
            {
                if let Some(value) = &value {
                    let mode = if *arrow == SyntaxKind::ASSIGN {
                        Mode::Read
                    } else {
                        Mode::Write
                    };
                    let ty = self.expression(value, mode);
                    self.expect_type(
                        &ty,
                        &Type::BOOL,
                        value,
                        &format!("{} of '{callee}'", name.text()),
                    );
                }
                continue;
            }
            let (param, output) = match &formal {
                Some((name, arrow)) => {
                    let output = *arrow == SyntaxKind::OUTPUT_ASSIGN;
                    given.push(name.text().to_lowercase());
                    match params
                        .iter()
                        .find(|p| p.name.eq_ignore_ascii_case(name.text()))
                    {
                        Some(param) => (Some(param), output),
                        None => {
                            let names = params.iter().map(|p| p.name.as_str());
                            let message = match closest(name.text(), names) {
                                Some(s) => format!(
                                    "'{callee}' has no parameter '{}'; did you mean '{s}'?",
                                    name.text()
                                ),
                                None => format!("'{callee}' has no parameter '{}'", name.text()),
                            };
                            self.error(Code::InvalidCall, token_range(name), message);
                            (None, output)
                        }
                    }
                }
                None => {
                    let param = positional_params.get(positional).copied();
                    positional += 1;
                    if param.is_none() {
                        self.error(
                            Code::InvalidCall,
                            range_of(argument),
                            format!(
                                "'{callee}' takes {} input(s), but more are given",
                                positional_params.len()
                            ),
                        );
                    }
                    if let Some(param) = param {
                        given.push(param.name.to_lowercase());
                    }
                    (param, false)
                }
            };
            let Some(value) = value else { continue };
            let Some(param) = param else {
                self.expression(&value, if output { Mode::Write } else { Mode::Read });
                continue;
            };
            match (param.section, output) {
                // The wrong arrow: ':=' to an output or '=>' from an input.
                (VarSection::VarOutput, false) | (_, true)
                    if (param.section == VarSection::VarOutput) != output =>
                {
                    self.expression(&value, if output { Mode::Write } else { Mode::Read });
                    let (what, arrow) = if output {
                        ("an input", "pass it with ':='")
                    } else {
                        ("an output", "connect it with '=>'")
                    };
                    self.error(
                        Code::InvalidCall,
                        range_of(argument),
                        format!("'{}' is {what} of '{callee}'; {arrow}", param.name),
                    );
                }
                (VarSection::VarOutput, true) => {
                    let target = self.expression(&value, Mode::Write);
                    if !self.assignable_target(&value, &target) {
                        continue;
                    }
                    let context = format!(
                        "the variable connected to output '{}' of '{callee}'",
                        param.name
                    );
                    if !self.converts(&param.ty, &target) {
                        self.error(
                            Code::TypeMismatch,
                            range_of(&value),
                            format!("{context} must hold {}, but it is {target}", param.ty),
                        );
                    }
                }
                (VarSection::VarInOut, false) => {
                    let ty = self.expression(&value, Mode::Write);
                    self.expression(&value, Mode::Read);
                    if !is_place(&value) {
                        self.error(
                            Code::NotAssignable,
                            range_of(&value),
                            format!("'{}' of '{callee}' is VAR_IN_OUT and needs a variable, not a value", param.name),
                        );
                    } else {
                        let context = format!("VAR_IN_OUT '{}' of '{callee}'", param.name);
                        self.expect_type(&ty, &param.ty, &value, &context);
                    }
                }
                _ => {
                    let ty = self.expression(&value, Mode::Read);
                    let context = format!("input '{}' of '{callee}'", param.name);
                    self.expect_type(&ty, &param.ty, &value, &context);
                }
            }
        }
        // VAR_IN_OUT must be connected in every call of a function; an FB keeps its last one.
        if function_like {
            for param in params.iter().filter(|p| p.section == VarSection::VarInOut) {
                if !given.contains(&param.name.to_lowercase()) {
                    let range = arguments
                        .first()
                        .and_then(|a| a.parent())
                        .map_or(0..0, |list| range_of(&list));
                    self.error(
                        Code::InvalidCall,
                        range,
                        format!(
                            "the call of '{callee}' must connect VAR_IN_OUT '{}'",
                            param.name
                        ),
                    );
                }
            }
        }
    }

    fn arguments_unchecked(&mut self, arguments: &[SyntaxNode]) {
        for argument in arguments {
            let output = tokens(argument).any(|t| t.kind() == SyntaxKind::OUTPUT_ASSIGN);
            if let Some(value) = argument.children().next() {
                self.expression(&value, if output { Mode::Write } else { Mode::Read });
            }
        }
    }

    fn call_standard(
        &mut self,
        name: &str,
        signature: &FunctionSig,
        arguments: &[SyntaxNode],
        node: &SyntaxNode,
    ) -> Type {
        let upper = name.to_ascii_uppercase();
        // Arguments by position, or by formal name (`IN1 := …`).
        let mut typed: Vec<(Sig, Type, SyntaxNode)> = Vec::new();
        for (index, argument) in arguments.iter().enumerate() {
            let parts: Vec<SyntaxToken> = tokens(argument).collect();
            let Some(value) = argument.children().next() else {
                continue;
            };
            let formal = parts
                .iter()
                .position(|t| t.kind() == SyntaxKind::ASSIGN)
                .and_then(|at| parts.get(at.checked_sub(1)?));
            let writes = matches!(
                upper.as_str(),
                "ADR" | "ADRINST" | "__QUERYINTERFACE" | "__QUERYPOINTER"
            );
            let ty = self.expression(&value, if writes { Mode::Write } else { Mode::Read });
            if writes {
                self.expression(&value, Mode::Read);
            }
            let sig = match formal {
                Some(formal) => signature
                    .inputs
                    .iter()
                    .find(|(n, _)| n.eq_ignore_ascii_case(formal.text()))
                    .map(|(_, s)| *s)
                    .or_else(|| {
                        signature
                            .extensible
                            .then(|| signature.inputs.last().map(|(_, s)| *s))
                            .flatten()
                    }),
                None => signature.inputs.get(index).map(|(_, s)| *s).or_else(|| {
                    signature
                        .extensible
                        .then(|| signature.inputs.last().map(|(_, s)| *s))
                        .flatten()
                }),
            };
            match sig {
                Some(sig) => typed.push((sig, ty, value)),
                None => {
                    let message = match formal {
                        Some(formal) => format!("'{upper}' has no parameter '{}'", formal.text()),
                        None => format!(
                            "'{upper}' takes {} input(s), but {} are given",
                            signature.inputs.len(),
                            arguments.len()
                        ),
                    };
                    self.error(Code::InvalidCall, range_of(argument), message);
                }
            }
        }
        if arguments.len() < signature.inputs.len() {
            self.error(
                Code::InvalidCall,
                range_of(node),
                format!(
                    "'{upper}' takes {} input(s), but {} are given",
                    signature.inputs.len(),
                    arguments.len()
                ),
            );
        }
        // The type variable: every `T` argument converges to one type of its class.
        let mut common: Option<Type> = None;
        let mut string_wide = None;
        for (sig, ty, value) in &typed {
            match sig {
                Sig::T(generic) => {
                    if !generic.admits(ty) {
                        self.error(
                            Code::TypeMismatch,
                            range_of(value),
                            format!(
                                "'{upper}' expects {} here, found {ty}",
                                Type::Generic(*generic)
                            ),
                        );
                        continue;
                    }
                    common = match common.take() {
                        None => Some(ty.clone()),
                        Some(previous) => match common_type(&previous, ty) {
                            Some(joined) => Some(joined),
                            None => {
                                self.error(
                                    Code::TypeMismatch,
                                    range_of(value),
                                    format!("the inputs of '{upper}' must have one type, found {previous} and {ty}"),
                                );
                                Some(Type::Error)
                            }
                        },
                    };
                }
                Sig::Class(generic) if !generic.admits(ty) => {
                    self.error(
                        Code::TypeMismatch,
                        range_of(value),
                        format!(
                            "'{upper}' expects {} here, found {ty}",
                            Type::Generic(*generic)
                        ),
                    );
                }
                Sig::E(elementary) => {
                    let expected = Type::elementary(*elementary);
                    self.expect_type(ty, &expected, value, &format!("'{upper}'"));
                }
                Sig::Str => match ty {
                    Type::String { wide, .. } => {
                        if string_wide.is_some_and(|w| w != *wide) {
                            self.error(
                                Code::TypeMismatch,
                                range_of(value),
                                format!("'{upper}' cannot mix STRING and WSTRING"),
                            );
                        }
                        string_wide = Some(*wide);
                    }
                    Type::Error => {}
                    other => self.error(
                        Code::TypeMismatch,
                        range_of(value),
                        format!("'{upper}' expects a STRING or WSTRING here, found {other}"),
                    ),
                },
                _ => {}
            }
        }
        match signature.result {
            Sig::E(elementary) => Type::elementary(elementary),
            Sig::Str => Type::String {
                wide: string_wide.unwrap_or(false),
                length: DEFAULT_STRING_LENGTH,
            },
            Sig::T(_) => common.unwrap_or(Type::Error),
            Sig::RealOfT => match common {
                Some(Type::Elementary(e)) if e.is_real() => Type::Elementary(e),
                Some(Type::IntLiteral(_) | Type::RealLiteral) => Type::RealLiteral,
                Some(Type::Error) | None => Type::Error,
                Some(_) => Type::Elementary(Elementary::Lreal),
            },
            Sig::AnyInt => Type::IntLiteral(None),
            Sig::Pointer => Type::Pointer(Box::new(Type::Void)),
            Sig::Void => Type::Void,
            Sig::Class(_) => Type::Error,
        }
    }
}

/// `name : TYPE := initial` for hover.
fn variable_detail(variable: &Variable) -> String {
    let mut detail = format!("{} : {}", variable.name, variable.ty);
    if let Some(initial) = &variable.initial {
        detail.push_str(&format!(" := {initial}"));
    }
    if let Some(address) = &variable.address {
        detail = format!("{} AT {address} : {}", variable.name, variable.ty);
    }
    if !variable.comment.is_empty() {
        detail.push_str(&format!(" // {}", variable.comment));
    }
    detail
}

/// `LIMIT(MN, IN, MX) : ANY_ELEMENTARY` for hover.
fn signature_detail(name: &str, signature: &FunctionSig) -> String {
    let show = |sig: &Sig| match sig {
        Sig::E(e) => e.name().to_owned(),
        Sig::Str => "STRING".to_owned(),
        Sig::Class(g) | Sig::T(g) => Type::Generic(*g).to_string(),
        Sig::RealOfT => "ANY_REAL".to_owned(),
        Sig::AnyInt => "ANY_INT".to_owned(),
        Sig::Pointer => "POINTER".to_owned(),
        Sig::Void => String::new(),
    };
    let mut inputs: Vec<String> = signature
        .inputs
        .iter()
        .map(|(input, sig)| format!("{input} : {}", show(sig)))
        .collect();
    if signature.extensible {
        inputs.push("…".to_owned());
    }
    let result = show(&signature.result);
    if result.is_empty() {
        format!(
            "FUNCTION {}({})",
            name.to_ascii_uppercase(),
            inputs.join(", ")
        )
    } else {
        format!(
            "FUNCTION {}({}) : {result}",
            name.to_ascii_uppercase(),
            inputs.join(", ")
        )
    }
}

/// `FUNCTION F_Scale : REAL` for hover.
fn pou_detail(pou: &Pou) -> String {
    let mut detail = format!("{} {}", pou.kind.keyword(), pou.name);
    if let Some(ty) = &pou.return_type {
        detail.push_str(&format!(" : {ty}"));
    }
    detail
}

/// Whether an array type (at any depth) has a bound that did not resolve.
fn has_open_bounds(ty: &Type) -> bool {
    match ty {
        Type::Array { element, dims } => {
            dims.iter().any(Option::is_none) || has_open_bounds(element)
        }
        Type::Pointer(target) | Type::Reference(target) => has_open_bounds(target),
        _ => false,
    }
}

/// The parameters of a POU or method from its variables.
fn params_of(variables: &[Variable], resolve: impl Fn(&str) -> Type) -> Vec<Param> {
    variables
        .iter()
        .filter(|v| {
            matches!(
                v.section,
                VarSection::VarInput | VarSection::VarOutput | VarSection::VarInOut
            )
        })
        .map(|v| Param {
            name: v.name.clone(),
            ty: dereferenced(resolve(&v.ty)),
            section: v.section,
        })
        .collect()
}

/// Whether the expression names a place (a variable, member, element or dereference).
fn is_place(node: &SyntaxNode) -> bool {
    match node.kind() {
        SyntaxKind::NAME_EXPR
        | SyntaxKind::FIELD_EXPR
        | SyntaxKind::INDEX_EXPR
        | SyntaxKind::DEREF_EXPR => true,
        SyntaxKind::PAREN_EXPR => node.children().next().is_some_and(|inner| is_place(&inner)),
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

/// The type of a plain literal.
fn literal_type(node: &SyntaxNode) -> Type {
    let Some(token) = tokens(node).next() else {
        return Type::Error;
    };
    match token.kind() {
        SyntaxKind::INT_NUMBER => Type::IntLiteral(
            literal::parse_integer(token.text())
                .ok()
                .and_then(|v| i128::try_from(v).ok()),
        ),
        SyntaxKind::REAL_NUMBER => Type::RealLiteral,
        SyntaxKind::TRUE | SyntaxKind::FALSE => Type::BOOL,
        SyntaxKind::STRING => Type::String {
            wide: false,
            length: DEFAULT_STRING_LENGTH,
        },
        SyntaxKind::WSTRING => Type::String {
            wide: true,
            length: DEFAULT_STRING_LENGTH,
        },
        SyntaxKind::TIME_LITERAL => {
            let prefix = token
                .text()
                .split('#')
                .next()
                .unwrap_or_default()
                .to_ascii_uppercase();
            if prefix.starts_with('L') {
                Type::Elementary(Elementary::Ltime)
            } else {
                Type::Elementary(Elementary::Time)
            }
        }
        SyntaxKind::DATE_LITERAL => {
            let prefix = token
                .text()
                .split('#')
                .next()
                .unwrap_or_default()
                .to_ascii_uppercase();
            Type::Elementary(match prefix.as_str() {
                "D" | "DATE" => Elementary::Date,
                "LD" | "LDATE" => Elementary::Ldate,
                "TOD" | "TIME_OF_DAY" => Elementary::TimeOfDay,
                "LTOD" | "LTIME_OF_DAY" => Elementary::LtimeOfDay,
                "LDT" | "LDATE_AND_TIME" => Elementary::LdateAndTime,
                _ => Elementary::DateAndTime,
            })
        }
        _ => Type::Error,
    }
}

/// The type of a direct address `%IX0.0`, `%QW3`, `%MD10`, by its size letter.
pub(crate) fn address_type(address: &str) -> Type {
    let size = address.chars().nth(2).map(|c| c.to_ascii_uppercase());
    Type::Elementary(match size {
        Some('B') => Elementary::Byte,
        Some('W') => Elementary::Word,
        Some('D') => Elementary::Dword,
        Some('L') => Elementary::Lword,
        _ => Elementary::Bool,
    })
}
