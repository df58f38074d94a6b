//! Typing of expressions: literals, names, members, indices, operators.

use super::resolution::variable_detail;
use super::*;
use crate::library::{AXIS_REF, CAM_REF};
use crate::syntax::ast::{
    Arg, BinaryExpr, FieldExpr, IndexExpr, InitValue, Literal, TypedLiteral, UnaryExpr,
};

impl<'s, 'a, 'p> BodyChecker<'s, 'a, 'p> {
    /// The type of an expression, reporting what is wrong inside it, and noting it when the
    /// types are collected.
    pub(super) fn expression(&mut self, node: &Expr, mode: Mode) -> Type {
        let ty = self.expression_type(node, mode);
        if let Some(types) = &mut self.types {
            types.insert(node.syntax(), ty.clone());
        }
        ty
    }

    fn expression_type(&mut self, node: &Expr, mode: Mode) -> Type {
        match node {
            Expr::Literal(literal) => literal_type(literal),
            Expr::TypedLiteral(literal) => self.typed_literal(literal),
            Expr::ParenExpr(paren) => paren
                .inner()
                .map_or(Type::Error, |inner| self.expression(&inner, mode)),
            Expr::NameExpr(name) => self.name(name, mode),
            Expr::FieldExpr(field) => self.field(field, mode),
            Expr::IndexExpr(index) => self.index(index, mode),
            Expr::DerefExpr(deref) => {
                let Some(base) = deref.base() else {
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
                            range_of(deref.syntax()),
                            format!("'^' needs a pointer, found {other}"),
                        );
                        Type::Error
                    }
                }
            }
            Expr::CallExpr(call) => self.call(call),
            Expr::UnaryExpr(unary) => self.unary(unary),
            Expr::BinaryExpr(binary) => self.binary(binary),
            Expr::AddressExpr(address) => address
                .address()
                .map_or(Type::Error, |token| address_type(token.text())),
            Expr::ArrayInit(array) => {
                // An array value: check what is inside for names. `3(0)` repeats a value:
                // only the value is an expression.
                for element in array.elements() {
                    match element {
                        InitValue::Expr(Expr::CallExpr(call))
                            if matches!(call.callee(), Some(Expr::Literal(_))) =>
                        {
                            for argument in call.syntax().descendants().filter_map(Arg::cast) {
                                if let Some(value) = argument.value() {
                                    self.expression(&value, Mode::Read);
                                }
                            }
                        }
                        InitValue::Expr(value) => {
                            self.expression(&value, Mode::Read);
                        }
                        InitValue::Struct(_) | InitValue::Repeat(_) => {}
                    }
                }
                Type::Error
            }
            Expr::ErrorNode(error) => {
                // Input past a nesting limit: check the names in what was kept.
                for inner in error.nodes().filter_map(Expr::cast) {
                    self.expression(&inner, Mode::Read);
                }
                Type::Error
            }
        }
    }

    pub(super) fn typed_literal(&mut self, literal: &TypedLiteral) -> Type {
        let node = literal.syntax();
        let Some(prefix) = &literal.type_name() else {
            return Type::Error;
        };
        // `INT#` with nothing after the '#' is a syntax error, reported already.
        let Some(value) = &literal.value() else {
            return match Elementary::from_name(prefix.text()) {
                Some(elementary) => Type::elementary(elementary),
                None => Type::Error,
            };
        };
        if let Some(elementary) = Elementary::from_name(prefix.text()) {
            let ty = Type::elementary(elementary);
            let negative = literal.is_negative();
            let fits = match value.kind() {
                SyntaxKind::INT_NUMBER => {
                    let parsed = integer_value(value.text()).map(|v| if negative { -v } else { v });
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

    pub(super) fn unknown_member(
        &mut self,
        container: &str,
        member: &SyntaxToken,
        names: Vec<&str>,
    ) {
        let name = member.text();
        let message = match closest(name, names.into_iter()) {
            Some(suggestion) => {
                format!("'{container}' has no member '{name}'; did you mean '{suggestion}'?")
            }
            None => format!("'{container}' has no member '{name}'"),
        };
        self.error(Code::UnknownName, token_range(member), message);
    }

    pub(super) fn name(&mut self, node: &NameExpr, mode: Mode) -> Type {
        let ty = self.name_type(node, mode);
        if self.resolutions.is_some()
            && let Some(token) = node.ident()
            && let Some(definition) = self.definition_of_name(&token, node)
        {
            self.note(token_range(&token), &ty, |_| definition);
        }
        ty
    }

    pub(super) fn name_type(&mut self, node: &NameExpr, mode: Mode) -> Type {
        let Some(first) = node.first_token() else {
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
            SyntaxKind::DOT => match node.ident() {
                Some(token) => (token, true),
                None => return Type::Error,
            },
            // `MOD(a, b)` and friends: operator keywords called like functions.
            _ => return Type::Error,
        };
        let name = token.text();
        if !global_only && let Some(local) = self.scope.local(name) {
            return match local {
                LocalSymbol::Var(variable) => self.variable(variable, mode, &token, true),
                LocalSymbol::Result(ty) => self.resolve(ty),
                LocalSymbol::Property(property) => {
                    self.property_nodes.insert(node.syntax().text_range());
                    self.resolve(&property.ty)
                }
                LocalSymbol::Method(_) | LocalSymbol::Action => Type::Void,
                LocalSymbol::Step => Type::Step,
                LocalSymbol::SfcAction => Type::SfcAction,
                LocalSymbol::TransitionValue => Type::BOOL,
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
            Some(GlobalSymbol::Axis) => Type::Named(AXIS_REF.to_owned()),
            Some(GlobalSymbol::Cam) => Type::Named(CAM_REF.to_owned()),
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
    pub(super) fn variable(
        &mut self,
        variable: &Variable,
        mode: Mode,
        token: &SyntaxToken,
        local: bool,
    ) -> Type {
        self.record(variable, mode);
        let at_bit = variable.address.as_deref().is_some_and(|address| {
            matches!(crate::sema::address::parse_address(address), Ok(Some(a)) if a.size_bits == 1)
        });
        if at_bit && let Some(expression) = token.parent() {
            self.bit_nodes.insert(expression.text_range());
        }
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

    pub(super) fn field(&mut self, field: &FieldExpr, mode: Mode) -> Type {
        let node = field.syntax();
        let Some(base) = field.base() else {
            return Type::Error;
        };
        let Some(member) = field.member() else {
            return Type::Error;
        };
        let from_inside = matches!(&base, Expr::DerefExpr(deref)
        if deref.base().is_some_and(|b| {
            matches!(text(b.syntax()).to_ascii_uppercase().as_str(), "THIS" | "SUPER")
        }));
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
                    if let Some(chart_member) = sfc::chart_member(globals, &type_name, name) {
                        return chart_member;
                    }
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
                            self.property_nodes.insert(node.text_range());
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
                "X" | "_X" => Type::BOOL,
                "T" => Type::Elementary(Elementary::Time),
                _ => {
                    self.unknown_member(&text(base.syntax()), &member, vec!["x", "_x", "t"]);
                    Type::Error
                }
            },
            Type::SfcAction => match name.to_ascii_uppercase().as_str() {
                "X" | "_X" => Type::BOOL,
                _ => {
                    self.unknown_member(&text(base.syntax()), &member, vec!["x", "_x"]);
                    Type::Error
                }
            },
            Type::Pointer(_) => {
                self.error(
                    Code::InvalidOperands,
                    range_of(node),
                    format!(
                        "'{}' is a pointer: dereference it first, as in '{}^.{name}'",
                        text(base.syntax()),
                        text(base.syntax())
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
                            format!("'{}' is {other}, which has no members", text(base.syntax())),
                        );
                        Type::Error
                    }
                }
            }
        }
    }

    pub(super) fn index(&mut self, index_expr: &IndexExpr, mode: Mode) -> Type {
        let node = index_expr.syntax();
        let Some(base) = index_expr.base() else {
            return Type::Error;
        };
        let indices: Vec<Expr> = index_expr.indices().collect();
        let base_ty = self.expression(&base, mode);
        let mut index_types = Vec::new();
        for index in &indices {
            let ty = self.expression(index, Mode::Read);
            if !ty.is_integer_like()
                && !matches!(&ty, Type::Named(n) if matches!(self.scope.globals.shape(n), Some(Shape::Enum(_))))
            {
                self.error(
                    Code::TypeMismatch,
                    range_of(index.syntax()),
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
                            text(base.syntax()),
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
                            range_of(index.syntax()),
                            format!(
                                "index {value} is outside the bounds {low}..{high} of '{}'",
                                text(base.syntax())
                            ),
                        );
                    }
                }
                *element
            }
            Type::String { wide, length } => {
                // The code generator indexes the characters and the terminator: 0 to the length.
                if indices.len() != 1 {
                    self.error(
                        Code::IndexOutOfRange,
                        range_of(node),
                        format!(
                            "'{}' is a string and takes one index, but {} are given",
                            text(base.syntax()),
                            indices.len()
                        ),
                    );
                } else if let Some(Const::Int(value)) = self.constant_value(&indices[0])
                    && !(0..=i128::from(length)).contains(&value)
                {
                    self.error(
                        Code::IndexOutOfRange,
                        range_of(indices[0].syntax()),
                        format!(
                            "index {value} is outside the characters 0..{length} of '{}'",
                            text(base.syntax())
                        ),
                    );
                }
                Type::Elementary(if wide {
                    Elementary::Word
                } else {
                    Elementary::Byte
                })
            }
            Type::Pointer(target) => *target,
            other => {
                self.error(
                    Code::InvalidOperands,
                    range_of(node),
                    format!(
                        "'{}' is {other}, which cannot be indexed",
                        text(base.syntax())
                    ),
                );
                Type::Error
            }
        }
    }

    pub(super) fn unary(&mut self, unary: &UnaryExpr) -> Type {
        let node = unary.syntax();
        let Some(operator) = unary.op() else {
            return Type::Error;
        };
        let Some(operand) = unary.operand() else {
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

    pub(super) fn binary(&mut self, binary: &BinaryExpr) -> Type {
        let node = binary.syntax();
        let Some(left_node) = binary.lhs() else {
            return Type::Error;
        };
        let left = self.expression(&left_node, Mode::Read);
        let Some(right_node) = binary.rhs() else {
            return Type::Error;
        };
        let right = self.expression(&right_node, Mode::Read);
        let Some(operator) = binary.op() else {
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
            self.warn_integer_rounded_into_real(&left_node, &left, &right_node, &right);
            // Fold literal arithmetic so `-128` or `2 * 64` still fit a SINT.
            if matches!(ty, Type::IntLiteral(_))
                && let Some(Const::Int(value)) =
                    self.constant_value(&Expr::BinaryExpr(binary.clone()))
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
        if self.scope.globals.dialect == Dialect::IecStrict
            && matches!(
                operator.kind(),
                SyntaxKind::PLUS
                    | SyntaxKind::MINUS
                    | SyntaxKind::STAR
                    | SyntaxKind::SLASH
                    | SyntaxKind::MOD
                    | SyntaxKind::EQ
                    | SyntaxKind::NEQ
                    | SyntaxKind::LT
                    | SyntaxKind::LE
                    | SyntaxKind::GT
                    | SyntaxKind::GE
            )
            && (bit_string_arithmetic(&left, &right).is_some()
                || mixed_sign_type(&left, &right).is_some()
                || integer_real_type(&left, &right).is_some())
        {
            message.push_str(STRICT_NOTE);
        }
        self.error(Code::InvalidOperands, range_of(node), message);
        Type::Error
    }

    /// Warns (W0013, as an assignment would) when an operation of an integer with a real
    /// converts the integer into a real type that may round it (`d * r` with `d : DINT`,
    /// `r : REAL`): only the CODESYS dialect lets such an operation through.
    fn warn_integer_rounded_into_real(
        &mut self,
        left_node: &Expr,
        left: &Type,
        right_node: &Expr,
        right: &Type,
    ) {
        let Some(real) = integer_real_type(left, right) else {
            return;
        };
        for (node, ty) in [(left_node, left), (right_node, right)] {
            if !implicitly_converts(ty, &real) && lenient_real_conversion(ty, &real) {
                self.diagnostics.push(Diagnostic::new(
                    Code::ImplicitRealRounding,
                    range_of(node.syntax()),
                    format!(
                        "this operation converts {ty} to {real} implicitly, which rounds integers it cannot hold exactly (use LREAL, or write {}_TO_{real}(…) to say so)",
                        ty.as_elementary().map_or("ANY", |e| e.name()),
                    ),
                ));
            }
        }
    }

    /// The type of an operation on a signed and an unsigned integer, or on an integer and a
    /// real, which the default dialect computes as CODESYS does (`ty::mixed_sign_type`,
    /// `ty::integer_real_type`) and `iec-strict` refuses.
    fn lenient_mixed_sign(&self, left: &Type, right: &Type) -> Option<Type> {
        (self.scope.globals.dialect == Dialect::Codesys)
            .then(|| mixed_sign_type(left, right).or_else(|| integer_real_type(left, right)))
            .flatten()
    }

    pub(super) fn binary_type(
        &self,
        operator: SyntaxKind,
        left: &Type,
        right: &Type,
    ) -> Option<Type> {
        use Elementary::*;
        use SyntaxKind::*;
        let is_enum = |ty: &Type| matches!(ty, Type::Named(n) if matches!(self.scope.globals.shape(n), Some(Shape::Enum(_))));
        match operator {
            PLUS | MINUS | STAR | SLASH => {
                if left.is_numeric() && right.is_numeric() {
                    return common_type(left, right)
                        .or_else(|| self.lenient_mixed_sign(left, right));
                }
                if self.scope.globals.dialect == Dialect::Codesys
                    && let Some(ty) = bit_string_arithmetic(left, right)
                {
                    return Some(ty);
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
                    common_type(left, right).or_else(|| self.lenient_mixed_sign(left, right))
                } else if self.scope.globals.dialect == Dialect::Codesys {
                    bit_string_arithmetic(left, right).filter(Type::is_bits)
                } else {
                    None
                }
            }
            POWER => power_type(left, right),
            EQ | NEQ | LT | LE | GT | GE => {
                let comparable = match (left, right) {
                    // Structures, unions, arrays and instances are not compared: CODESYS's EQ
                    // and NE permit "all elementary data types" (its operator pages), and
                    // interfaces, which compare the instance they hold.
                    (Type::Named(a), Type::Named(b)) => {
                        a.eq_ignore_ascii_case(b)
                            && (is_enum(left)
                                || matches!(operator, EQ | NEQ)
                                    && !matches!(
                                        self.scope.globals.shape(a),
                                        Some(Shape::Struct(_) | Shape::StandardFb(_))
                                    )
                                    && self
                                        .scope
                                        .globals
                                        .pou(a)
                                        .is_none_or(|p| p.kind == PouKind::Interface))
                    }
                    (Type::Array { .. }, _) | (_, Type::Array { .. }) => false,
                    (Type::String { wide: a, .. }, Type::String { wide: b, .. }) => a == b,
                    (Type::Pointer(_), Type::Pointer(_)) => true,
                    (Type::Pointer(_), other) | (other, Type::Pointer(_)) => {
                        other.is_integer_like()
                    }
                    (enumeration, other) | (other, enumeration) if is_enum(enumeration) => {
                        other.is_integer_like()
                    }
                    // `itf <> 0`: whether an interface holds an instance, as CODESYS allows.
                    (Type::Named(name), Type::IntLiteral(Some(0)))
                    | (Type::IntLiteral(Some(0)), Type::Named(name))
                        if matches!(operator, EQ | NEQ)
                            && self
                                .scope
                                .globals
                                .pou(name)
                                .is_some_and(|p| p.kind == PouKind::Interface) =>
                    {
                        true
                    }
                    _ => {
                        common_type(left, right).is_some()
                            || self.lenient_mixed_sign(left, right).is_some()
                            || (self.scope.globals.dialect == Dialect::Codesys
                                && bit_string_arithmetic(left, right).is_some())
                    }
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
}

/// The type of a plain literal.
pub(super) fn literal_type(literal: &Literal) -> Type {
    let Some(token) = literal.token() else {
        return Type::Error;
    };
    match token.kind() {
        SyntaxKind::INT_NUMBER => Type::IntLiteral(integer_value(token.text())),
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
