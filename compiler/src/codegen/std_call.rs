//! Calls of the standard functions: conversions, numeric and bit functions, selection, and the
//! string functions the runtime implements.

use program_image::{BinaryOp, CompareOp, Elementary as IE, Instr, Operand, StdFunction, UnaryOp};

use super::body::{BodyGen, Gen, Place};
use super::call::Argument;
use super::error::fail;
use super::expr::concrete;
use super::layout::LayShape;
use crate::elementary::Elementary;
use crate::sema::signatures::iec_input_alias;
use crate::sema::ty::Type;
use crate::syntax::ast::{CallExpr, Expr};

/// The operation of a date and time function, if `name` is one.
fn time_arithmetic(name: &str) -> Option<BinaryOp> {
    Some(match name {
        "ADD_TIME" | "ADD_LTIME" | "ADD_TOD_TIME" | "ADD_DT_TIME" | "ADD_LTOD_LTIME"
        | "ADD_LDT_LTIME" | "CONCAT_DATE_TOD" | "CONCAT_DATE_LTOD" => BinaryOp::Add,
        "SUB_TIME" | "SUB_LTIME" | "SUB_TOD_TIME" | "SUB_DT_TIME" | "SUB_DATE_DATE"
        | "SUB_TOD_TOD" | "SUB_DT_DT" | "SUB_LTOD_LTIME" | "SUB_LDT_LTIME" | "SUB_LDATE_LDATE"
        | "SUB_LTOD_LTOD" | "SUB_LDT_LDT" => BinaryOp::Sub,
        "MUL_TIME" | "MUL_LTIME" => BinaryOp::Mul,
        "DIV_TIME" | "DIV_LTIME" => BinaryOp::Div,
        _ => return None,
    })
}

/// The formal input names of the standard functions whose inputs are not `IN`/`IN1…`.
fn formal_order(name: &str) -> &'static [&'static str] {
    match name {
        "LIMIT" => &["MN", "IN", "MX"],
        "LEN" => &["STR"],
        "SEL" => &["G", "IN0", "IN1"],
        "MID" => &["STR", "LEN", "POS"],
        "LEFT" | "RIGHT" => &["STR", "SIZE"],
        "INSERT" => &["STR1", "STR2", "POS"],
        "DELETE" => &["STR", "LEN", "POS"],
        // CODESYS names REPLACE's length and position L and P, unlike MID's and DELETE's.
        "REPLACE" => &["STR1", "STR2", "L", "P"],
        "FIND" => &["STR1", "STR2"],
        _ => &[],
    }
}

impl BodyGen<'_, '_, '_> {
    /// The argument expressions in positional order (formal arguments put in their place).
    fn ordered(&self, name: &str, args: &[Argument]) -> Gen<Vec<Expr>> {
        let order = formal_order(name);
        let mut placed: Vec<(usize, Expr)> = Vec::new();
        for (position, arg) in args.iter().enumerate() {
            let Some(value) = arg.value.clone() else {
                continue;
            };
            let at = match &arg.formal {
                None => position,
                Some(formal) => {
                    let upper = formal.to_ascii_uppercase();
                    let upper = iec_input_alias(name, &upper).map_or(upper, str::to_owned);
                    if let Some(at) = order.iter().position(|f| *f == upper) {
                        at
                    } else if upper == "IN" {
                        0
                    } else if let Some(n) = upper
                        .strip_prefix("IN")
                        .or_else(|| upper.strip_prefix("STR").filter(|_| name == "CONCAT"))
                        .and_then(|n| n.parse::<usize>().ok())
                    {
                        // IN1, IN2… (CONCAT's STR1, STR2… too), and MUX's IN0, IN1… after K.
                        if name == "MUX" {
                            n + 1
                        } else {
                            n.saturating_sub(1)
                        }
                    } else if upper == "K" || upper == "G" {
                        0
                    } else {
                        return Err(fail!("'{name}' has no input '{formal}'"));
                    }
                }
            };
            placed.push((at, value));
        }
        placed.sort_by_key(|(at, _)| *at);
        Ok(placed.into_iter().map(|(_, v)| v).collect())
    }

    /// A call of the standard function `name`.
    pub(crate) fn call_standard(
        &mut self,
        name: &str,
        node: &CallExpr,
        args: &[Argument],
        want: Option<&Type>,
    ) -> Gen<Option<(Operand, Type)>> {
        let upper = name.to_ascii_uppercase();
        let values = self.ordered(&upper, args)?;
        let result_ty = match self.type_of(&Expr::CallExpr(node.clone())) {
            // No standard function has a generic result any more (a `*_TO_BCD` result is the
            // bit string of its argument's width, or the bit string type the checker recorded
            // for where it goes: `sema/body/bcd_target.rs`); one left untyped takes the type of
            // where it goes.
            Type::Generic(_) | Type::Error => {
                want.cloned().unwrap_or(Type::Elementary(Elementary::Word))
            }
            other => concrete(&other, want),
        };
        let first = || {
            values
                .first()
                .cloned()
                .ok_or_else(|| fail!("'{name}' needs an argument"))
        };
        // Conversions: `INT_TO_REAL`, `TO_INT`, `TRUNC_INT`, `INT_TO_BCD`, `BCD_TO_INT`…
        let conversion = upper.strip_prefix("TO_").map(|_| "").or_else(|| {
            upper
                .split_once("_TO_")
                .map(|(from, _)| from)
                .filter(|from| !from.is_empty())
        });
        if let Some(from) = conversion {
            let arg = first()?;
            let from_bcd = from == "BCD" || from.ends_with("_BCD");
            let from_ty =
                Elementary::from_name(from.trim_end_matches("_BCD")).map(Type::elementary);
            let natural = concrete(&from_ty.unwrap_or_else(|| self.type_of(&arg)), None);
            let mut value = self.expr_as(&arg, &natural)?;
            if from_bcd {
                let scalar = self.scalar_of(&natural).ok_or("BCD of a bit string")?;
                let dst = self.temp(8);
                self.emit(Instr::Unary {
                    op: UnaryOp::FromBcd,
                    ty: scalar,
                    dst,
                    src: value,
                });
                value = dst;
            }
            let trunc = upper.starts_with("TRUNC");
            let (value, ty) = self.conversion(value, &natural, &result_ty, trunc)?;
            if upper.ends_with("_TO_BCD") || upper.contains("_TO_BCD_") {
                let scalar = self.scalar_of(&ty).ok_or("BCD into a bit string")?;
                let dst = self.temp(8);
                self.emit(Instr::Unary {
                    op: UnaryOp::ToBcd,
                    ty: scalar,
                    dst,
                    src: value,
                });
                return Ok(Some((dst, ty)));
            }
            return Ok(Some((value, ty)));
        }
        if upper == "TRUNC" || upper.starts_with("TRUNC_") {
            let arg = first()?;
            let natural = concrete(&self.type_of(&arg), None);
            let value = self.expr_as(&arg, &natural)?;
            return self.conversion(value, &natural, &result_ty, true).map(Some);
        }
        let unary = match upper.as_str() {
            "ABS" => Some(UnaryOp::Abs),
            "SQRT" => Some(UnaryOp::Sqrt),
            "LN" => Some(UnaryOp::Ln),
            "LOG" => Some(UnaryOp::Log),
            "EXP" => Some(UnaryOp::Exp),
            "SIN" => Some(UnaryOp::Sin),
            "COS" => Some(UnaryOp::Cos),
            "TAN" => Some(UnaryOp::Tan),
            "ASIN" => Some(UnaryOp::Asin),
            "ACOS" => Some(UnaryOp::Acos),
            "ATAN" => Some(UnaryOp::Atan),
            "ROUND" => Some(UnaryOp::Round),
            "NOT" => Some(UnaryOp::Not),
            "NEG" => Some(UnaryOp::Neg),
            _ => None,
        };
        if let Some(op) = unary {
            let value = self.expr_as(&first()?, &result_ty)?;
            let scalar = self
                .scalar_of(&result_ty)
                .ok_or_else(|| fail!("'{name}' on {result_ty}"))?;
            let dst = self.temp(scalar.size_bytes());
            self.emit(Instr::Unary {
                op,
                ty: scalar,
                dst,
                src: value,
            });
            return Ok(Some((dst, result_ty)));
        }
        let binary = match upper.as_str() {
            "ADD" => Some(BinaryOp::Add),
            "SUB" => Some(BinaryOp::Sub),
            "MUL" => Some(BinaryOp::Mul),
            "DIV" => Some(BinaryOp::Div),
            "MOD" => Some(BinaryOp::Mod),
            "EXPT" => Some(BinaryOp::Expt),
            "AND" => Some(BinaryOp::And),
            "OR" => Some(BinaryOp::Or),
            "XOR" => Some(BinaryOp::Xor),
            "MIN" => Some(BinaryOp::Min),
            "MAX" => Some(BinaryOp::Max),
            "SHL" => Some(BinaryOp::Shl),
            "SHR" => Some(BinaryOp::Shr),
            "ROL" => Some(BinaryOp::Rol),
            "ROR" => Some(BinaryOp::Ror),
            "ATAN2" => Some(BinaryOp::Atan2),
            _ => None,
        };
        // MAX, MIN and LIMIT of strings and BOOLs compare and keep, as the runtime's MIN and
        // MAX instructions take numbers only.
        let by_comparison = !matches!(self.scalar_of(&result_ty), Some(s) if s != IE::Bool);
        if by_comparison && matches!(upper.as_str(), "MAX" | "MIN" | "LIMIT") {
            let mut operands = Vec::new();
            for value in &values {
                operands.push(self.expr_as(value, &result_ty)?);
            }
            let dst = match (upper.as_str(), operands.as_slice()) {
                ("MAX", _) => self.extreme(CompareOp::Gt, &operands, &result_ty)?,
                ("MIN", _) => self.extreme(CompareOp::Lt, &operands, &result_ty)?,
                (_, [mn, input, mx]) => {
                    let low = self.extreme(CompareOp::Gt, &[*input, *mn], &result_ty)?;
                    self.extreme(CompareOp::Lt, &[low, *mx], &result_ty)?
                }
                _ => return Err("LIMIT needs MN, IN and MX".into()),
            };
            return Ok(Some((dst, result_ty)));
        }
        if let Some(op) = binary {
            let scalar = self
                .scalar_of(&result_ty)
                .ok_or_else(|| fail!("'{name}' on {result_ty}"))?;
            let mut operands = values.iter();
            let first_node = operands
                .next()
                .ok_or_else(|| fail!("'{name}' needs arguments"))?;
            let mut acc = self.expr_as(first_node, &result_ty)?;
            for next in operands {
                let value = self.expr_as(next, &result_ty)?;
                let dst = self.temp(scalar.size_bytes());
                self.emit(Instr::Binary {
                    op,
                    ty: scalar,
                    dst,
                    a: acc,
                    b: value,
                });
                acc = dst;
            }
            return Ok(Some((acc, result_ty)));
        }
        let comparison = match upper.as_str() {
            "GT" => Some(CompareOp::Gt),
            "GE" => Some(CompareOp::Ge),
            "EQ" => Some(CompareOp::Eq),
            "LE" => Some(CompareOp::Le),
            "LT" => Some(CompareOp::Lt),
            "NE" => Some(CompareOp::Ne),
            _ => None,
        };
        if let Some(op) = comparison {
            return self.compare_chain(op, &values).map(Some);
        }
        if let Some(op) = time_arithmetic(&upper) {
            return self.time_arithmetic(op, &values, &result_ty).map(Some);
        }
        match upper.as_str() {
            "TIME" | "LTIME" => {
                let long = upper == "LTIME";
                let dst = self.temp(if long { 8 } else { 4 });
                self.emit(Instr::Clock { long, dst });
                Ok(Some((dst, result_ty)))
            }
            "MOVE" => {
                let value = self.expr_as(&first()?, &result_ty)?;
                Ok(Some((value, result_ty)))
            }
            "LIMIT" => {
                let [mn, input, mx] = values.as_slice() else {
                    return Err("LIMIT needs MN, IN and MX".into());
                };
                let scalar = self.scalar_of(&result_ty).ok_or("LIMIT on a number")?;
                let (mn, input, mx) = (
                    self.expr_as(mn, &result_ty)?,
                    self.expr_as(input, &result_ty)?,
                    self.expr_as(mx, &result_ty)?,
                );
                let low = self.temp(8);
                self.emit(Instr::Binary {
                    op: BinaryOp::Max,
                    ty: scalar,
                    dst: low,
                    a: input,
                    b: mn,
                });
                let dst = self.temp(8);
                self.emit(Instr::Binary {
                    op: BinaryOp::Min,
                    ty: scalar,
                    dst,
                    a: low,
                    b: mx,
                });
                Ok(Some((dst, result_ty)))
            }
            "SEL" => {
                let [g, in0, in1] = values.as_slice() else {
                    return Err("SEL needs G, IN0 and IN1".into());
                };
                let lay = self.lay(&result_ty)?;
                let dst = self.temp(lay.size);
                let condition = self.expr_as(g, &Type::BOOL)?;
                let to_second = self.emit(Instr::JumpIf {
                    cond: condition,
                    target: 0,
                });
                let value = self.expr_as(in0, &result_ty)?;
                self.copy_value(&lay.shape, lay.size, dst, value);
                let end_jump = self.emit(Instr::Jump { target: 0 });
                let second = self.here();
                self.patch(to_second, second);
                let value = self.expr_as(in1, &result_ty)?;
                self.copy_value(&lay.shape, lay.size, dst, value);
                let end = self.here();
                self.patch(end_jump, end);
                Ok(Some((dst, result_ty)))
            }
            "MUX" => {
                let Some((k, inputs)) = values.split_first() else {
                    return Err("MUX needs K and inputs".into());
                };
                let lay = self.lay(&result_ty)?;
                let dst = self.temp(lay.size);
                let k_ty = concrete(&self.type_of(k), None);
                let k_scalar = self.scalar_of(&k_ty).ok_or("MUX's K must be an integer")?;
                let k_value = self.expr_as(k, &k_ty)?;
                let mut ends = Vec::new();
                // K below 0 selects the first input and K past the end the last.
                let zero = self.build.scalar_constant(0, k_scalar);
                let below = self.temp(1);
                self.emit(Instr::Compare {
                    op: CompareOp::Lt,
                    ty: k_scalar,
                    dst: below,
                    a: k_value,
                    b: zero,
                });
                let to_first = self.emit(Instr::JumpIf {
                    cond: below,
                    target: 0,
                });
                let mut first_at = None;
                for (index, input) in inputs.iter().enumerate() {
                    let skip = if index + 1 < inputs.len() {
                        let constant = self.build.scalar_constant(index as u64, k_scalar);
                        let hit = self.temp(1);
                        self.emit(Instr::Compare {
                            op: CompareOp::Ne,
                            ty: k_scalar,
                            dst: hit,
                            a: k_value,
                            b: constant,
                        });
                        Some(self.emit(Instr::JumpIf {
                            cond: hit,
                            target: 0,
                        }))
                    } else {
                        None
                    };
                    if index == 0 {
                        first_at = Some(self.here());
                    }
                    let value = self.expr_as(input, &result_ty)?;
                    self.copy_value(&lay.shape, lay.size, dst, value);
                    ends.push(self.emit(Instr::Jump { target: 0 }));
                    if let Some(skip) = skip {
                        let next = self.here();
                        self.patch(skip, next);
                    }
                }
                let end = self.here();
                for at in ends {
                    self.patch(at, end);
                }
                if let Some(first) = first_at {
                    self.patch(to_first, first);
                }
                Ok(Some((dst, result_ty)))
            }
            "LOWER_BOUND" | "UPPER_BOUND" => {
                let [array, dim] = values.as_slice() else {
                    return Err(fail!("{name} needs an array and a dimension"));
                };
                let dim = match super::constant::evaluate_node(dim, self.scope.globals) {
                    Some(super::constant::Value::Int(d)) if d >= 1 => d as u32,
                    _ => return Err(fail!("{name}'s dimension must be a constant from 1")),
                };
                let upper = upper == "UPPER_BOUND";
                // The bounds are the type's, but an element such as `arrs[i]` is still settled
                // so its index is checked: a bad `i` faults as any other use of the element.
                let typed = self.place(array)?;
                let typed = self.settled(typed)?;
                let scalar = self.scalar_of(&result_ty).unwrap_or(IE::Dint);
                let bound = match (&typed.lay.shape, typed.place) {
                    (LayShape::OpenArray { rank, .. }, Place::Direct(descriptor))
                        if dim <= *rank =>
                    {
                        super::expr::shifted(
                            descriptor,
                            8 + 16 * (dim - 1) + if upper { 8 } else { 0 },
                        )
                    }
                    (LayShape::Array { dims, .. }, _) if dim as usize <= dims.len() => {
                        let (low, high) = dims[dim as usize - 1];
                        self.build
                            .scalar_constant((if upper { high } else { low }) as u64, IE::Lint)
                    }
                    _ => return Err(fail!("{name}: the array has no dimension {dim}")),
                };
                let dst = self.temp(8);
                self.emit(Instr::Convert {
                    from: IE::Lint,
                    to: scalar,
                    dst,
                    src: bound,
                });
                Ok(Some((dst, result_ty)))
            }
            "ADR" | "ADRINST" => {
                let pointer = match values.first() {
                    Some(value) => self.address_of(value)?,
                    // `ADRINST()` in a function block's body or method: its own instance.
                    None => {
                        let dst = self.temp(8);
                        self.emit(Instr::Address {
                            dst,
                            place: Operand::Instance(0),
                        });
                        dst
                    }
                };
                Ok(Some((pointer, result_ty)))
            }
            "BITADR" => {
                // The bit offset in the variable's %I, %Q or %M area, as CODESYS gives it
                // with byte addressing (`%IX2.3` is 19); the checker lets only those through.
                let typed = self.place(&first()?)?;
                let bit_offset = match typed.place {
                    Place::Direct(
                        Operand::Input(byte) | Operand::Output(byte) | Operand::Memory(byte),
                    ) => u64::from(byte) * 8,
                    Place::Bit {
                        operand:
                            Operand::Input(byte) | Operand::Output(byte) | Operand::Memory(byte),
                        bit,
                        ..
                    } => u64::from(byte) * 8 + u64::from(bit),
                    _ => return Err(fail!("'BITADR' of something without a direct address")),
                };
                let scalar = self.scalar_of(&result_ty).unwrap_or(IE::Dword);
                Ok(Some((
                    self.build.scalar_constant(bit_offset, scalar),
                    result_ty,
                )))
            }
            "ISVALIDREF" | "__ISVALIDREF" => {
                // A reference is valid when it points somewhere: its address is not 0. A
                // reference variable or member comes back followed to its target, whose
                // address is the reference's value; an element of an array of references
                // comes back as the slot itself, which holds that value.
                let typed = self.place(&first()?)?;
                let pointer = match typed.ty {
                    Type::Reference(_) => self.reference_value(typed.place)?,
                    _ => self.pointer_to(&typed)?,
                };
                let null = self.build.scalar_constant(0, IE::Lword);
                let dst = self.temp(1);
                self.emit(Instr::Compare {
                    op: CompareOp::Ne,
                    ty: IE::Lword,
                    dst,
                    a: pointer,
                    b: null,
                });
                Ok(Some((dst, result_ty)))
            }
            "SIZEOF" | "XSIZEOF" => {
                let arg = first()?;
                let ty = self.type_of(&arg);
                let size = self.lay(&ty)?.size;
                let scalar = self.scalar_of(&result_ty).unwrap_or(IE::Udint);
                Ok(Some((
                    self.build.scalar_constant(u64::from(size), scalar),
                    result_ty,
                )))
            }
            "LEN" | "LEFT" | "RIGHT" | "MID" | "CONCAT" | "INSERT" | "DELETE" | "REPLACE"
            | "FIND" => self.string_function(&upper, &values, &result_ty).map(Some),
            _ => Err(fail!(
                "the standard function '{name}' is not supported by the code generator yet"
            )),
        }
    }

    /// The first of `operands` (values of `ty`) that no later one beats by `op` (`Gt` for MAX,
    /// `Lt` for MIN), in a new temporary.
    fn extreme(&mut self, op: CompareOp, operands: &[Operand], ty: &Type) -> Gen<Operand> {
        let lay = self.lay(ty)?;
        let dst = self.temp(lay.size);
        let Some((first, rest)) = operands.split_first() else {
            return Err(fail!("'{op:?}' of nothing"));
        };
        self.copy_value(&lay.shape, lay.size, dst, *first);
        for next in rest {
            let beats = self.compare_operands(op, *next, dst, ty)?;
            let skip = self.emit(Instr::JumpIfNot {
                cond: beats,
                target: 0,
            });
            self.copy_value(&lay.shape, lay.size, dst, *next);
            let end = self.here();
            self.patch(skip, end);
        }
        Ok(dst)
    }

    /// `a op b` of two values of `ty` already evaluated: strings by their characters, other
    /// values by the comparison instruction.
    fn compare_operands(
        &mut self,
        op: CompareOp,
        a: Operand,
        b: Operand,
        ty: &Type,
    ) -> Gen<Operand> {
        let dst = self.temp(1);
        if let Type::String { wide, length } = ty {
            let order = self.temp(4);
            self.emit(Instr::CallStdFunction {
                function: StdFunction::Compare,
                wide: *wide,
                dst: (order, 0),
                args: vec![(a, *length), (b, *length)],
            });
            let zero = self.build.scalar_constant(0, IE::Dint);
            self.emit(Instr::Compare {
                op,
                ty: IE::Dint,
                dst,
                a: order,
                b: zero,
            });
            return Ok(dst);
        }
        let scalar = self
            .scalar_of(ty)
            .ok_or_else(|| fail!("comparing values of {ty}"))?;
        self.emit(Instr::Compare {
            op,
            ty: scalar,
            dst,
            a,
            b,
        });
        Ok(dst)
    }

    /// `GT(a, b, c)` and the other comparison functions: IEC 61131-3 compares each input with
    /// the next and ANDs the results (`a > b AND b > c`).
    fn compare_chain(&mut self, op: CompareOp, values: &[Expr]) -> Gen<(Operand, Type)> {
        if let [a, b] = values {
            return self.compare(op, a, b);
        }
        // More than two: each input is evaluated once, in the type they all take.
        let mut common: Option<Type> = None;
        for value in values {
            let ty = self.type_of(value);
            common = Some(match common {
                None => ty,
                Some(before) => crate::sema::ty::common_type(&before, &ty).unwrap_or(before),
            });
        }
        let common = concrete(&common.ok_or("a comparison needs inputs")?, None);
        let mut operands = Vec::new();
        for value in values {
            operands.push(self.expr_as(value, &common)?);
        }
        let mut result: Option<Operand> = None;
        for pair in operands.windows(2) {
            let value = self.compare_operands(op, pair[0], pair[1], &common)?;
            result = Some(match result {
                None => value,
                Some(before) => {
                    let dst = self.temp(1);
                    self.emit(Instr::Binary {
                        op: BinaryOp::And,
                        ty: IE::Bool,
                        dst,
                        a: before,
                        b: value,
                    });
                    dst
                }
            });
        }
        let result = result.ok_or("a comparison needs two inputs")?;
        Ok((result, Type::BOOL))
    }

    /// `ADD_DT_TIME`, `SUB_DT_DT`, `CONCAT_DATE_TOD`…: every operand is taken to nanoseconds
    /// (LTIME), combined, and the result converted to the function's type, so units never
    /// mix.
    fn time_arithmetic(
        &mut self,
        op: BinaryOp,
        values: &[Expr],
        result_ty: &Type,
    ) -> Gen<(Operand, Type)> {
        let [a, b] = values else {
            return Err("a time function takes two arguments".into());
        };
        let result = self.scalar_of(result_ty).ok_or("a time result")?;
        let nanos = Type::Elementary(Elementary::Ltime);
        if matches!(op, BinaryOp::Mul | BinaryOp::Div) {
            // MUL_TIME and DIV_TIME scale a duration by a number; by a real, the duration
            // is scaled as an LREAL of milliseconds and rounded back, as REAL_TO_TIME does.
            let factor_ty = concrete(&self.type_of(b), None);
            if self.scalar_of(&factor_ty).is_some_and(IE::is_real) {
                let lreal = Type::Elementary(Elementary::Lreal);
                let time = self.expr_as(a, result_ty)?;
                let time = self.convert_explicit(time, result_ty, &lreal)?;
                let factor = self.expr_as(b, &lreal)?;
                let scaled = self.temp(8);
                self.emit(Instr::Binary {
                    op,
                    ty: IE::Lreal,
                    dst: scaled,
                    a: time,
                    b: factor,
                });
                let dst = self.convert_explicit(scaled, &lreal, result_ty)?;
                return Ok((dst, result_ty.clone()));
            }
            let time = self.expr_as(a, result_ty)?;
            let factor = self.expr_as(b, result_ty)?;
            let dst = self.temp(8);
            self.emit(Instr::Binary {
                op,
                ty: result,
                dst,
                a: time,
                b: factor,
            });
            return Ok((dst, result_ty.clone()));
        }
        let mut operands = Vec::new();
        for value in [a, b] {
            let (operand, ty) = self.expr(value, None)?;
            let ty = concrete(&ty, Some(&nanos));
            operands.push(self.convert_explicit(operand, &ty, &nanos)?);
        }
        let sum = self.temp(8);
        self.emit(Instr::Binary {
            op,
            ty: IE::Ltime,
            dst: sum,
            a: operands[0],
            b: operands[1],
        });
        let dst = self.temp(8);
        self.emit(Instr::Convert {
            from: IE::Ltime,
            to: result,
            dst,
            src: sum,
        });
        Ok((dst, result_ty.clone()))
    }

    fn convert_explicit(&mut self, value: Operand, from: &Type, to: &Type) -> Gen<Operand> {
        let (Some(a), Some(b)) = (self.scalar_of(from), self.scalar_of(to)) else {
            return Err(fail!("converting {from} to {to}"));
        };
        if a == b {
            return Ok(value);
        }
        let dst = self.temp(8);
        self.emit(Instr::Convert {
            from: a,
            to: b,
            dst,
            src: value,
        });
        Ok(dst)
    }

    fn copy_value(&mut self, shape: &LayShape, size: u32, dst: Operand, src: Operand) {
        match shape {
            LayShape::Scalar(ty) | LayShape::Enum(ty) => {
                self.emit(Instr::Move { ty: *ty, dst, src })
            }
            _ => self.emit(Instr::Copy { size, dst, src }),
        };
    }

    fn conversion(
        &mut self,
        value: Operand,
        from: &Type,
        to: &Type,
        trunc: bool,
    ) -> Gen<(Operand, Type)> {
        // To and from text: the runtime prints and parses values as CODESYS does.
        match (from, to) {
            (Type::String { .. }, Type::String { .. }) => {
                return Ok((self.convert(value, from, to)?, to.clone()));
            }
            (_, Type::String { wide, length }) => {
                let scalar = self
                    .scalar_of(from)
                    .ok_or_else(|| fail!("converting {from} to text"))?;
                let lay = self.lay(to)?;
                let dst = self.temp(lay.size);
                self.emit(Instr::ToText {
                    from: scalar,
                    wide: *wide,
                    dst,
                    capacity: *length,
                    src: value,
                });
                return Ok((dst, to.clone()));
            }
            (Type::String { wide, length }, _) => {
                let scalar = self
                    .scalar_of(to)
                    .ok_or_else(|| fail!("converting text to {to}"))?;
                let dst = self.temp(8);
                self.emit(Instr::FromText {
                    to: scalar,
                    wide: *wide,
                    dst,
                    src: value,
                    capacity: *length,
                });
                return Ok((dst, to.clone()));
            }
            _ => {}
        }
        // Every conversion the checker accepts is between scalars or handled above; the test
        // `tests/tests/standard_library` compiles each of them, so this is an internal error.
        let (Some(a), Some(b)) = (self.scalar_of(from), self.scalar_of(to)) else {
            return Err(fail!(
                "internal error: no conversion from {from} to {to}, which the checker accepted"
            ));
        };
        if a == b && !trunc {
            return Ok((value, to.clone()));
        }
        let dst = self.temp(b.size_bytes());
        if trunc {
            self.emit(Instr::Trunc {
                from: a,
                to: b,
                dst,
                src: value,
            });
        } else {
            self.emit(Instr::Convert {
                from: a,
                to: b,
                dst,
                src: value,
            });
        }
        Ok((dst, to.clone()))
    }

    fn string_function(
        &mut self,
        name: &str,
        values: &[Expr],
        result_ty: &Type,
    ) -> Gen<(Operand, Type)> {
        let function = match name {
            "LEN" => StdFunction::Len,
            "LEFT" => StdFunction::Left,
            "RIGHT" => StdFunction::Right,
            "MID" => StdFunction::Mid,
            "CONCAT" => StdFunction::Concat,
            "INSERT" => StdFunction::Insert,
            "DELETE" => StdFunction::Delete,
            "REPLACE" => StdFunction::Replace,
            _ => StdFunction::Find,
        };
        let mut wide = false;
        let mut args = Vec::new();
        for value in values {
            let ty = self.type_of(value);
            match ty {
                Type::String { wide: w, .. } => {
                    wide = w;
                    let (operand, actual) = self.expr(value, None)?;
                    let Type::String { length, .. } = actual else {
                        return Err("a string argument".into());
                    };
                    args.push((operand, length));
                }
                _ => {
                    let dint = Type::Elementary(Elementary::Dint);
                    let operand = self.expr_as(value, &dint)?;
                    args.push((operand, 0));
                }
            }
        }
        let (dst, result_ty) = match result_ty {
            Type::String { length, .. } => {
                let lay = self.lay(result_ty)?;
                ((self.temp(lay.size), *length), result_ty.clone())
            }
            _ => ((self.temp(4), 0), Type::Elementary(Elementary::Dint)),
        };
        if function == StdFunction::Concat && args.len() > 2 {
            // The runtime joins two strings; more inputs join one after another, each
            // partial result cut to the result's length as the whole would be.
            let mut joined = args[0];
            for (index, next) in args.iter().enumerate().skip(1) {
                let into = if index + 1 == args.len() {
                    dst
                } else {
                    let lay = self.lay(&result_ty)?;
                    (self.temp(lay.size), dst.1)
                };
                self.emit(Instr::CallStdFunction {
                    function,
                    wide,
                    dst: into,
                    args: vec![joined, *next],
                });
                joined = into;
            }
            return Ok((dst.0, result_ty));
        }
        self.emit(Instr::CallStdFunction {
            function,
            wide,
            dst,
            args,
        });
        Ok((dst.0, result_ty))
    }
}
