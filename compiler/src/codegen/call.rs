//! Calls: functions, methods and actions of the project, programs, and instances of function
//! blocks (the project's and the standard ones).

use program_image::{Instr, Operand, Transfer};
use project_model::{Pou, PouKind, VarSection};

use super::body::{BodyGen, Frame, FrameVar, Gen, Place, Typed};
use super::error::fail;
use super::expr::written;
use super::layout::LayShape;
use crate::sema::scope::{GlobalSymbol, LocalSymbol};
use crate::sema::ty::Type;
use crate::syntax::SyntaxKind;
use crate::syntax::ast::{ArgKind, CallExpr, Expr};

/// One argument of a call: its formal name if given, whether it is an output (`=>`), and its
/// expression.
#[derive(Clone)]
pub(crate) struct Argument {
    pub(crate) formal: Option<String>,
    pub(crate) output: bool,
    pub(crate) value: Option<Expr>,
}

/// The arguments of a call expression, in order.
pub(crate) fn arguments(node: &CallExpr) -> Vec<Argument> {
    node.args()
        .map(|argument| Argument {
            formal: argument.name().map(|name| name.text().to_owned()),
            output: argument.kind() == ArgKind::Output,
            value: argument.value(),
        })
        .collect()
}

/// The transfers of a call with a frame, and where its outputs go afterwards.
#[derive(Default)]
pub(crate) struct FrameCall {
    pub(crate) inputs: Vec<Transfer>,
    pub(crate) outputs: Vec<Transfer>,
    /// (temporary, its type, the target) for each `=>` output.
    pub(crate) stores: Vec<(Operand, Type, Typed)>,
    /// The result's temporary and type.
    pub(crate) result: Option<(Operand, Type)>,
}

/// What a call's callee is.
enum Callee<'p> {
    /// A function of the project.
    Function(&'p Pou),
    /// A method of the current POU or of an instance; the instance pointer, `None` for THIS.
    Method {
        owner: &'p Pou,
        name: String,
        instance: Option<Operand>,
    },
    /// An action of the current POU or of an instance.
    Action {
        owner: &'p Pou,
        name: String,
        instance: Place,
    },
    /// An instance of a function block or a program.
    Instance(Typed),
    /// A method called through an interface value.
    Virtual {
        interface: &'p Pou,
        name: String,
        base: Expr,
    },
    /// A standard function.
    Standard(String),
}

impl<'p> BodyGen<'_, '_, 'p> {
    /// `name;` or `fb.Action;` without parentheses.
    pub(crate) fn call_without_arguments(&mut self, node: &Expr) -> Gen<()> {
        let callee = self.callee(node)?;
        self.call_callee(callee, &[], None).map(|_| ())
    }

    /// A call; its result when it has one.
    pub(crate) fn call(
        &mut self,
        node: &CallExpr,
        want: Option<&Type>,
    ) -> Gen<Option<(Operand, Type)>> {
        let callee_node = node.callee().ok_or("a call of nothing")?;
        let all = arguments(node);
        let named = |name: &str| {
            all.iter()
                .find(|a| {
                    a.formal
                        .as_deref()
                        .is_some_and(|f| f.eq_ignore_ascii_case(name))
                })
                .and_then(|a| a.value.clone())
        };
        let callee = self.callee(&callee_node)?;
        // CODESYS's RTC declares EN as its own input: there it is an argument, not the enable.
        let en_is_input = matches!(
            &callee,
            Callee::Instance(typed)
                if matches!(typed.lay.shape, LayShape::Std(program_image::StdBlock::Rtc, _))
        );
        let enable = named("EN").filter(|_| !en_is_input);
        let enabled_out = named("ENO");
        let args: Vec<Argument> = all
            .iter()
            .filter(|a| {
                !a.formal.as_deref().is_some_and(|f| {
                    f.eq_ignore_ascii_case("EN") && !en_is_input || f.eq_ignore_ascii_case("ENO")
                })
            })
            .cloned()
            .collect();
        // EN = FALSE skips the call (a result reads as zero) and ENO tells whether it ran. Both
        // branches store into ENO's place, so it is computed (and an element's index checked)
        // here, before the skip, where both branches pass.
        let enabled_place = match &enabled_out {
            Some(target) => {
                let place = self.place(target)?;
                Some(self.settled(place)?)
            }
            None => None,
        };
        let skip = match &enable {
            Some(condition) => {
                let condition = self.expr_as(condition, &Type::BOOL)?;
                Some(self.emit(Instr::JumpIfNot {
                    cond: condition,
                    target: 0,
                }))
            }
            None => None,
        };
        let result = self.call_callee(callee, &args, Some((node, want)))?;
        if let Some(place) = &enabled_place {
            let on = self.build.constant(&[1]);
            self.store(place, on)?;
        }
        if let Some(skip) = skip {
            let done = self.emit(Instr::Jump { target: 0 });
            let skipped = self.here();
            self.patch(skip, skipped);
            if let Some(place) = &enabled_place {
                let off = self.build.constant(&[0]);
                self.store(place, off)?;
            }
            if let Some((operand, ty)) = &result {
                let size = self.lay(ty)?.size;
                let zeros = self.build.constant(&vec![0; size as usize]);
                self.emit(Instr::Copy {
                    size,
                    dst: *operand,
                    src: zeros,
                });
            }
            let end = self.here();
            self.patch(done, end);
        }
        Ok(result)
    }

    fn call_callee(
        &mut self,
        callee: Callee<'p>,
        args: &[Argument],
        node: Option<(&CallExpr, Option<&Type>)>,
    ) -> Gen<Option<(Operand, Type)>> {
        match callee {
            Callee::Function(pou) => {
                let index = self.build.pou_index(&pou.name, None)?;
                self.call_frame(
                    index,
                    pou,
                    &pou.variables,
                    pou.return_type.as_deref(),
                    None,
                    args,
                )
            }
            Callee::Method {
                owner,
                name,
                instance,
            } => {
                let method = owner
                    .methods
                    .iter()
                    .find(|m| m.name.eq_ignore_ascii_case(&name))
                    .ok_or_else(|| fail!("'{}' has no method '{name}'", owner.name))?;
                let index = self.build.pou_index(&owner.name, Some(&method.name))?;
                let instance = match instance {
                    Some(pointer) => pointer,
                    None => {
                        let dst = self.temp(8);
                        self.emit(Instr::Address {
                            dst,
                            place: Operand::Instance(0),
                        });
                        dst
                    }
                };
                self.call_frame(
                    index,
                    owner,
                    &method.variables,
                    method.return_type.as_deref(),
                    Some(instance),
                    args,
                )
            }
            Callee::Action {
                owner,
                name,
                instance,
            } => {
                let index = self.build.pou_index(&owner.name, Some(&name))?;
                let (instance, indirect) = match instance {
                    Place::Direct(op) => (op, false),
                    Place::Indirect(pointer) => (pointer, true),
                    Place::Element(element) => (self.element_pointer(element)?, true),
                    Place::Bit { .. } | Place::PointedBit { .. } => {
                        return Err("an action of a bit".into());
                    }
                };
                self.emit(Instr::CallBlock {
                    pou: index,
                    instance,
                    indirect,
                });
                Ok(None)
            }
            Callee::Instance(typed) => {
                self.call_instance(typed, args)?;
                Ok(None)
            }
            Callee::Virtual {
                interface,
                name,
                base,
            } => self.call_virtual(interface, &name, &base, args),
            Callee::Standard(name) => {
                let (node, want) = node.ok_or_else(|| fail!("'{name}' needs arguments"))?;
                self.call_standard(&name, node, args, want)
            }
        }
    }

    fn callee(&mut self, node: &Expr) -> Gen<Callee<'p>> {
        if let Expr::NameExpr(name_expr) = node {
            let global_only = name_expr.is_global();
            let name = name_expr
                .name()
                .map(|t| t.text().to_owned())
                .ok_or("a call without a name")?;
            let local = if global_only {
                None
            } else {
                self.scope.local(&name)
            };
            match local {
                Some(LocalSymbol::Method(method)) => {
                    let owner = self.owner_of_method(&method.name)?;
                    return Ok(Callee::Method {
                        owner,
                        name: method.name.clone(),
                        instance: None,
                    });
                }
                Some(LocalSymbol::Action) => {
                    return Ok(Callee::Action {
                        owner: self.action_owner(self.pou, &name)?,
                        name,
                        instance: Place::Direct(Operand::Instance(0)),
                    });
                }
                Some(LocalSymbol::Result(_))
                    if self
                        .scope
                        .globals
                        .pou(&name)
                        .is_some_and(|p| p.kind == PouKind::Function) =>
                {
                    if let Some(pou) = self.scope.globals.pou(&name) {
                        return Ok(Callee::Function(pou));
                    }
                }
                Some(_) => {}
                None => match self.scope.globals.lookup(&name) {
                    Some(GlobalSymbol::Pou(pou)) if pou.kind == PouKind::Function => {
                        return Ok(Callee::Function(pou));
                    }
                    Some(GlobalSymbol::Pou(pou)) if pou.kind == PouKind::Program => {}
                    Some(GlobalSymbol::Pou(pou)) => {
                        return Err(fail!("'{}' is a type; call an instance of it", pou.name));
                    }
                    Some(_) => {}
                    None => return Ok(Callee::Standard(name)),
                },
            }
        }
        let field = match node {
            Expr::FieldExpr(field) => Some(field),
            _ => None,
        };
        let base_and_member = field.and_then(|field| {
            let member = field.member().filter(|t| t.kind() == SyntaxKind::IDENT)?;
            Some((field.base()?, member))
        });
        if let Some((base, member)) = base_and_member.clone()
            && let Some(interface) = self.interface_of(&self.type_of(&base))
        {
            return Ok(Callee::Virtual {
                interface,
                name: member.text().to_owned(),
                base,
            });
        }
        if let Some((base, member)) = base_and_member
            && let Type::Named(type_name) = self.type_of(&base)
            && let Some(pou) = self.scope.globals.pou(&type_name)
            && pou.kind != PouKind::Function
        {
            let member = member.text().to_owned();
            let chain = crate::sema::scope::inheritance_chain(self.scope.globals, pou);
            if let Some(owner) = chain.iter().find(|p| {
                p.methods
                    .iter()
                    .any(|m| m.name.eq_ignore_ascii_case(&member))
            }) {
                let typed = self.place(&base)?;
                let pointer = self.pointer_to(&typed)?;
                return Ok(Callee::Method {
                    owner,
                    name: member,
                    instance: Some(pointer),
                });
            }
            if pou
                .actions
                .iter()
                .any(|a| a.name.eq_ignore_ascii_case(&member))
            {
                let typed = self.place(&base)?;
                let typed = self.settled(typed)?;
                return Ok(Callee::Action {
                    owner: pou,
                    name: member,
                    instance: typed.place,
                });
            }
        }
        let typed = self.place(node)?;
        let typed = self.settled(typed)?;
        match typed.lay.shape {
            LayShape::Pou(_) | LayShape::Std(..) => Ok(Callee::Instance(typed)),
            _ => Err(fail!("'{}' cannot be called", written(node))),
        }
    }

    /// The POU declaring method `name` seen from the current POU (itself or a base).
    fn owner_of_method(&self, name: &str) -> Gen<&'p Pou> {
        crate::sema::scope::inheritance_chain(self.scope.globals, self.pou)
            .into_iter()
            .find(|p| p.methods.iter().any(|m| m.name.eq_ignore_ascii_case(name)))
            .ok_or_else(|| fail!("no method '{name}'"))
    }

    fn action_owner(&self, pou: &'p Pou, name: &str) -> Gen<&'p Pou> {
        if pou
            .actions
            .iter()
            .any(|a| a.name.eq_ignore_ascii_case(name))
        {
            Ok(pou)
        } else {
            Err(fail!("no action '{name}'"))
        }
    }

    /// A call of a function or method: a new frame with the inputs copied in, the outputs and
    /// the result copied out.
    fn call_frame(
        &mut self,
        index: u32,
        owner: &'p Pou,
        variables: &'p [project_model::Variable],
        return_type: Option<&str>,
        instance: Option<Operand>,
        args: &[Argument],
    ) -> Gen<Option<(Operand, Type)>> {
        let frame = self.build.frame_of(owner, variables, return_type)?;
        let call = self.frame_arguments(&frame, args)?;
        self.emit(Instr::CallFunction {
            pou: index,
            instance,
            inputs: call.inputs,
            outputs: call.outputs,
        });
        self.store_outputs(call.stores)?;
        Ok(call.result)
    }

    /// The transfers of a call of a function or method with frame `frame`: each argument
    /// copied into its parameter (an address for a VAR_IN_OUT), each `=>` output and the
    /// result copied out into temporaries.
    pub(crate) fn frame_arguments(
        &mut self,
        frame: &Frame<'p>,
        args: &[Argument],
    ) -> Gen<FrameCall> {
        let is_parameter = |v: &project_model::Variable| {
            matches!(
                v.section,
                VarSection::VarInput | VarSection::VarInOut | VarSection::VarOutput
            )
        };
        let params: Vec<&(&project_model::Variable, FrameVar)> =
            frame.vars.iter().filter(|(v, _)| is_parameter(v)).collect();
        // Frames keep declaration order within the parameters, so positions count inputs and
        // in-outs as declared.
        let positional: Vec<&&(&project_model::Variable, FrameVar)> = params
            .iter()
            .filter(|(v, _)| matches!(v.section, VarSection::VarInput | VarSection::VarInOut))
            .collect();
        let mut call = FrameCall::default();
        for (position, arg) in args.iter().enumerate() {
            let Some(value) = &arg.value else { continue };
            let (_, slot) = match &arg.formal {
                Some(formal) => params
                    .iter()
                    .find(|(v, _)| v.name.eq_ignore_ascii_case(formal))
                    .copied(),
                None => positional.get(position).map(|p| **p),
            }
            .ok_or_else(|| fail!("no parameter for argument {}", position + 1))?;
            let transfer = |caller| Transfer {
                caller,
                callee_offset: slot.offset,
                size: slot.lay.size,
            };
            if arg.output {
                let target = self.place(value)?;
                let target = self.settled(target)?;
                let temp = self.temp(slot.lay.size);
                call.outputs.push(transfer(temp));
                call.stores.push((temp, slot.ty.clone(), target));
                continue;
            }
            let caller = if let LayShape::OpenArray { .. } = slot.lay.shape {
                self.open_array_descriptor(value, &slot.lay)?
            } else if slot.by_ref {
                self.address_of(value)?
            } else {
                self.expr_as(value, &slot.ty)?
            };
            call.inputs.push(transfer(caller));
        }
        if let Some(result) = &frame.result {
            let temp = self.temp(result.lay.size);
            call.outputs.push(Transfer {
                caller: temp,
                callee_offset: result.offset,
                size: result.lay.size,
            });
            call.result = Some((temp, result.ty.clone()));
        }
        Ok(call)
    }

    /// Stores the outputs a call copied into temporaries into their targets.
    pub(crate) fn store_outputs(&mut self, stores: Vec<(Operand, Type, Typed)>) -> Gen<()> {
        for (temp, ty, target) in stores {
            let value = self.convert(temp, &ty, &target.ty)?;
            self.store(&target, value)?;
        }
        Ok(())
    }

    /// A call of an instance: inputs written into it, its body run, outputs read out.
    fn call_instance(&mut self, typed: Typed, args: &[Argument]) -> Gen<()> {
        let input_names: Vec<String> = match &typed.lay.shape {
            LayShape::Pou(name) => {
                let pou = self
                    .scope
                    .globals
                    .pou(name)
                    .ok_or("unknown function block")?;
                let instance = self.build.layouts.instance(pou)?;
                instance
                    .slots
                    .iter()
                    .filter(|s| {
                        matches!(s.var.section, VarSection::VarInput | VarSection::VarInOut)
                    })
                    .map(|s| s.var.name.clone())
                    .collect()
            }
            LayShape::Std(block, long) => program_image::std_blocks::layout(*block, *long)
                .members
                .iter()
                .filter(|m| m.input)
                .map(|m| m.name.to_owned())
                .collect(),
            _ => return Err("not an instance".into()),
        };
        let aliases = [
            ("RESET", "R"),
            ("LOAD", "LD"),
            ("SET1", "S1"),
            ("SET", "S"),
            ("RESET1", "R1"),
        ];
        let mut outputs = Vec::new();
        for (position, arg) in args.iter().enumerate() {
            let Some(value) = &arg.value else { continue };
            let name = match &arg.formal {
                Some(formal) => {
                    let std = matches!(typed.lay.shape, LayShape::Std(..));
                    aliases
                        .iter()
                        .find(|(alias, _)| std && alias.eq_ignore_ascii_case(formal))
                        .map_or(formal.clone(), |(_, name)| (*name).to_owned())
                }
                None => input_names
                    .get(position)
                    .cloned()
                    .ok_or_else(|| fail!("no input for argument {}", position + 1))?,
            };
            if arg.output {
                outputs.push((name, value.clone()));
                continue;
            }
            let member = self.instance_member(&typed, &name, true)?;
            if member.1 {
                let pointer = if let LayShape::OpenArray { .. } = member.0.lay.shape {
                    self.open_array_descriptor(value, &member.0.lay)?
                } else {
                    self.address_of(value)?
                };
                self.store(&member.0, pointer)?;
            } else {
                let operand = self.expr_as(value, &member.0.ty)?;
                self.store(&member.0, operand)?;
            }
        }
        let (instance, indirect) = match typed.place {
            Place::Direct(op) => (op, false),
            Place::Indirect(pointer) => (pointer, true),
            Place::Element(element) => (self.element_pointer(element)?, true),
            Place::Bit { .. } | Place::PointedBit { .. } => {
                return Err("a bit is no instance".into());
            }
        };
        match &typed.lay.shape {
            LayShape::Pou(name) => {
                let index = self.build.pou_index(name, None)?;
                self.emit(Instr::CallBlock {
                    pou: index,
                    instance,
                    indirect,
                });
            }
            LayShape::Std(block, long) => {
                self.emit(Instr::CallStdBlock {
                    block: *block,
                    long: *long,
                    instance,
                    indirect,
                });
            }
            _ => {}
        }
        for (name, target) in outputs {
            let (member, _) = self.instance_member(&typed, &name, false)?;
            let value = self.load(&member)?;
            let target = self.place(&target)?;
            let value = self.convert(value, &member.ty, &target.ty)?;
            self.store(&target, value)?;
        }
        Ok(())
    }

    /// A member of an instance as a place; `true` when it is a VAR_IN_OUT slot (to be given
    /// an address), in which case the place is the slot itself.
    fn instance_member(
        &mut self,
        typed: &Typed,
        name: &str,
        for_input: bool,
    ) -> Gen<(Typed, bool)> {
        if let LayShape::Pou(pou_name) = &typed.lay.shape
            && let Some(pou) = self.scope.globals.pou(pou_name)
        {
            let instance = self.build.layouts.instance(pou)?;
            let slot = instance
                .slot(name)
                .cloned()
                .ok_or_else(|| fail!("'{pou_name}' has no variable '{name}'"))?;
            if slot.by_ref && for_input {
                let place = self.member_place(typed.place, slot.offset)?;
                let lay = slot.lay.clone();
                return Ok((
                    Typed {
                        place,
                        ty: slot.ty,
                        lay,
                    },
                    true,
                ));
            }
        }
        let (offset, lay) = self.build.layouts.member_of(&typed.lay, name)?;
        let place = self.member_place(typed.place, offset)?;
        let ty = match &typed.lay.shape {
            LayShape::Std(..) => Type::Elementary(super::init::elementary_of(match lay.shape {
                LayShape::Scalar(e) => e,
                _ => program_image::Elementary::Bool,
            })),
            _ => match &typed.ty {
                Type::Named(type_name) => self
                    .scope
                    .globals
                    .member(type_name, name)
                    .map(|m| m.ty)
                    .ok_or_else(|| fail!("'{type_name}' has no member '{name}'"))?,
                other => return Err(fail!("{other} has no members")),
            },
        };
        if let Type::Reference(target) = ty {
            let op = self.reference_value(place)?;
            let lay = self.lay(&target)?;
            return Ok((
                Typed {
                    place: Place::Indirect(op),
                    ty: *target,
                    lay,
                },
                false,
            ));
        }
        Ok((Typed { place, ty, lay }, false))
    }
}
