//! Calls: functions, methods, actions, FB instances, programs and the standard library,
//! with their arguments matched to parameters.

use super::resolution::signature_detail;
use super::*;
use crate::syntax::ast::{Arg, ArgKind, FieldExpr};

/// A parameter of a call as the checker matches arguments to it.
pub(super) struct Param {
    pub(super) name: String,
    pub(super) ty: Type,
    pub(super) section: VarSection,
}

impl<'s, 'a, 'p> BodyChecker<'s, 'a, 'p> {
    pub(super) fn call(&mut self, call: &CallExpr) -> Type {
        let node = call.syntax();
        let Some(callee) = call.callee() else {
            return Type::Error;
        };
        let arguments: Vec<Arg> = call.args().collect();
        let callee_name_expr = match &callee {
            Expr::NameExpr(name) => Some(name.clone()),
            _ => None,
        };
        let callee_name = callee_name_expr
            .as_ref()
            .and_then(NameExpr::name)
            .map(|t| t.text().to_owned());
        let globals = self.scope.globals;
        // Functions and methods called by name.
        if let Some(name) = &callee_name
            && self.resolutions.is_some()
            && let Some(name_expr) = &callee_name_expr
            && let Some(token) = name_expr.ident()
        {
            let definition = self.definition_of_name(&token, name_expr).or_else(|| {
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
            let global_only = callee_name_expr.as_ref().is_some_and(NameExpr::is_global);
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
                // Inside a function its name is its result, but called it is the function:
                // recursion.
                Some(LocalSymbol::Result(_)) if globals.pou(name).is_some() => {
                    if let Some(pou) = globals.pou(name) {
                        return self.call_pou(name, pou, &callee, &arguments);
                    }
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
                                range_of(callee.syntax()),
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
        if let Expr::FieldExpr(field) = &callee
            && let Some(method) = self.member_method(field)
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
                self.arguments(&text(callee.syntax()), &params, &arguments, false);
                Type::Void
            }
            Type::Pointer(_) => {
                self.arguments_unchecked(&arguments);
                Type::Error
            }
            other => {
                self.error(
                    Code::InvalidCall,
                    range_of(callee.syntax()),
                    format!(
                        "'{}' is {other} and cannot be called",
                        text(callee.syntax())
                    ),
                );
                self.arguments_unchecked(&arguments);
                Type::Error
            }
        }
    }

    /// The method a `base.Method` callee names, if it names one.
    pub(super) fn member_method(
        &self,
        callee: &FieldExpr,
    ) -> Option<(String, &'p project_model::Method)> {
        let base = callee.base()?;
        let member = callee.member().filter(|t| t.kind() == SyntaxKind::IDENT)?;
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

    /// The type of an expression without reporting anything (used to look ahead).
    pub(super) fn peek_type(&self, node: &Expr) -> Option<Type> {
        let mut usage = Usage::new();
        let mut checker = BodyChecker::new(self.scope, &mut usage);
        Some(checker.expression(node, Mode::Read))
    }

    pub(super) fn call_pou(
        &mut self,
        name: &str,
        pou: &Pou,
        callee: &Expr,
        arguments: &[Arg],
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
                    range_of(callee.syntax()),
                    format!("'{name}' is a function block type; declare an instance and call that"),
                );
                self.arguments_unchecked(arguments);
                Type::Error
            }
        }
    }

    pub(super) fn instance_params(&self, type_name: &str) -> Vec<Param> {
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
    pub(super) fn arguments(
        &mut self,
        callee: &str,
        params: &[Param],
        arguments: &[Arg],
        function_like: bool,
    ) {
        let positional_params: Vec<&Param> = params
            .iter()
            .filter(|p| matches!(p.section, VarSection::VarInput | VarSection::VarInOut))
            .collect();
        let mut positional = 0usize;
        let mut given: Vec<String> = Vec::new();
        for argument in arguments {
            let value = argument.value();
            let formal = argument.name().map(|name| {
                let arrow = if argument.kind() == ArgKind::Output {
                    SyntaxKind::OUTPUT_ASSIGN
                } else {
                    SyntaxKind::ASSIGN
                };
                (name, arrow)
            });
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
                        value.syntax(),
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
                            range_of(argument.syntax()),
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
                        range_of(argument.syntax()),
                        format!("'{}' is {what} of '{callee}'; {arrow}", param.name),
                    );
                }
                (VarSection::VarOutput, true) => {
                    let target = self.expression(&value, Mode::Write);
                    if !self.assignable_target(&value, &target)
                        || self.refuse_unwritable_place(&value, PlaceUse::Connected)
                    {
                        continue;
                    }
                    let context = format!(
                        "the variable connected to output '{}' of '{callee}'",
                        param.name
                    );
                    if !self.converts(&param.ty, &target) {
                        self.error(
                            Code::TypeMismatch,
                            range_of(value.syntax()),
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
                            range_of(value.syntax()),
                            format!("'{}' of '{callee}' is VAR_IN_OUT and needs a variable, not a value", param.name),
                        );
                    } else if !self.refuse_unwritable_place(&value, PlaceUse::ByReference) {
                        let context = format!("VAR_IN_OUT '{}' of '{callee}'", param.name);
                        self.expect_same_place_type(&ty, &param.ty, value.syntax(), &context);
                    }
                }
                _ => {
                    let ty = self.expression(&value, Mode::Read);
                    let context = format!("input '{}' of '{callee}'", param.name);
                    self.expect_type(&ty, &param.ty, value.syntax(), &context);
                }
            }
        }
        // VAR_IN_OUT must be connected in every call of a function; an FB keeps its last one.
        if function_like {
            for param in params.iter().filter(|p| p.section == VarSection::VarInOut) {
                if !given.contains(&param.name.to_lowercase()) {
                    let range = arguments
                        .first()
                        .and_then(|a| a.syntax().parent())
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

    pub(super) fn arguments_unchecked(&mut self, arguments: &[Arg]) {
        for argument in arguments {
            let output = argument.kind() == ArgKind::Output;
            if let Some(value) = argument.value() {
                self.expression(&value, if output { Mode::Write } else { Mode::Read });
            }
        }
    }

    pub(super) fn call_standard(
        &mut self,
        name: &str,
        signature: &FunctionSig,
        arguments: &[Arg],
        node: &SyntaxNode,
    ) -> Type {
        let upper = name.to_ascii_uppercase();
        if let Some((code, message)) = self.refused_standard(&upper, arguments) {
            self.error(code, range_of(node), message);
            return Type::Error;
        }
        if upper.ends_with("_TO_BCD") {
            self.note_bcd_call(node.text_range());
        }
        // Arguments by position, or by formal name (`IN1 := …`).
        let mut typed: Vec<(Sig, Type, Expr)> = Vec::new();
        let mut given: HashMap<usize, String> = HashMap::new();
        for (index, argument) in arguments.iter().enumerate() {
            let Some(value) = argument.value() else {
                continue;
            };
            let formal = argument
                .name()
                .filter(|_| argument.kind() == ArgKind::Input);
            let writes = matches!(
                upper.as_str(),
                "ADR" | "ADRINST" | "__QUERYINTERFACE" | "__QUERYPOINTER"
            );
            let ty = self.expression(&value, if writes { Mode::Write } else { Mode::Read });
            if writes {
                self.expression(&value, Mode::Read);
                self.refuse_unwritable_place(&value, PlaceUse::ByReference);
            }
            let slot = match &formal {
                Some(formal) => standard_input_slot(&upper, signature, formal.text()),
                None => Some(index),
            };
            // An input given twice (by name and position, or by its CODESYS and IEC names)
            // would leave another input without a value.
            if let Some(slot) = slot {
                let given_as = formal.as_ref().map_or_else(
                    || format!("argument {}", index + 1),
                    |formal| formal.text().to_owned(),
                );
                if let Some(earlier) = given.insert(slot, given_as.clone()) {
                    self.error(
                        Code::InvalidCall,
                        range_of(argument.syntax()),
                        format!("'{upper}': {given_as} gives an input {earlier} already gives"),
                    );
                    continue;
                }
            }
            let sig = slot.and_then(|slot| {
                signature.inputs.get(slot).map(|(_, s)| *s).or_else(|| {
                    signature
                        .extensible
                        .then(|| signature.inputs.last().map(|(_, s)| *s))
                        .flatten()
                })
            });
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
                    self.error(Code::InvalidCall, range_of(argument.syntax()), message);
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
                            range_of(value.syntax()),
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
                                    range_of(value.syntax()),
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
                        range_of(value.syntax()),
                        format!(
                            "'{upper}' expects {} here, found {ty}",
                            Type::Generic(*generic)
                        ),
                    );
                }
                Sig::E(elementary) => {
                    let expected = Type::elementary(*elementary);
                    self.expect_type(ty, &expected, value.syntax(), &format!("'{upper}'"));
                }
                Sig::Str => match ty {
                    Type::String { wide, .. } => {
                        if string_wide.is_some_and(|w| w != *wide) {
                            self.error(
                                Code::TypeMismatch,
                                range_of(value.syntax()),
                                format!("'{upper}' cannot mix STRING and WSTRING"),
                            );
                        }
                        string_wide = Some(*wide);
                    }
                    Type::Error => {}
                    other => self.error(
                        Code::TypeMismatch,
                        range_of(value.syntax()),
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
            Sig::Power => {
                let of = |base: bool| {
                    typed
                        .iter()
                        .find(|(sig, ..)| matches!(sig, Sig::T(_)) == base)
                        .map(|(_, ty, _)| ty.clone())
                };
                match (of(true), of(false)) {
                    (Some(base), Some(exponent)) => {
                        power_type(&base, &exponent).unwrap_or(Type::Error)
                    }
                    _ => Type::Error,
                }
            }
            Sig::AnyInt => Type::IntLiteral(None),
            Sig::Pointer => Type::Pointer(Box::new(Type::Void)),
            Sig::Void => Type::Void,
            Sig::Class(_) => Type::Error,
        }
    }
}

/// The parameters of a POU or method from its variables.
pub(super) fn params_of(variables: &[Variable], resolve: impl Fn(&str) -> Type) -> Vec<Param> {
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
pub(super) fn is_place(node: &Expr) -> bool {
    match node {
        Expr::NameExpr(_) | Expr::FieldExpr(_) | Expr::IndexExpr(_) | Expr::DerefExpr(_) => true,
        Expr::ParenExpr(paren) => paren.inner().is_some_and(|inner| is_place(&inner)),
        _ => false,
    }
}

/// The position of the input the standard function `upper` (upper case) calls `formal`: by
/// its signature's name or the IEC 61131-3 name of a string function's input
/// ([`signatures::iec_input_alias`]), and for an extensible function `IN1`, `IN2`… (CONCAT's
/// `STR1`, `STR2`… too; MUX's `IN0`, `IN1`… after `K`); `None` when it has no such input.
fn standard_input_slot(upper: &str, signature: &FunctionSig, formal: &str) -> Option<usize> {
    let formal = formal.to_ascii_uppercase();
    let name = signatures::iec_input_alias(upper, &formal).unwrap_or(formal.as_str());
    if let Some(slot) = signature
        .inputs
        .iter()
        .position(|(input, _)| input.eq_ignore_ascii_case(name))
    {
        return Some(slot);
    }
    if !signature.extensible {
        return None;
    }
    let number = name
        .strip_prefix("IN")
        .or_else(|| name.strip_prefix("STR").filter(|_| upper == "CONCAT"))
        .filter(|digits| !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()))
        .and_then(|digits| digits.parse::<usize>().ok())?;
    if upper == "MUX" {
        number.checked_add(1)
    } else {
        number.checked_sub(1)
    }
}
