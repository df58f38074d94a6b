//! Places (variables, members, elements, dereferences) and expressions.

use program_image::{BinaryOp, CompareOp, Elementary as IE, Instr, Operand, UnaryOp};
use project_model::VarSection;

use super::body::{BodyGen, ElementPlace, Gen, Place, Typed};
use super::constant::{Value, evaluate_node, raw_of, text_bytes};
use super::error::fail;
use super::layout::{Lay, LayShape, located_of};
use crate::elementary::Elementary;
use crate::sema::scope::{GlobalSymbol, LocalSymbol};
use crate::sema::signatures;
use crate::sema::ty::{
    Type, bit_string_arithmetic, common_type, integer_real_type, mixed_sign_type,
};
use crate::sema::types::Shape;
use crate::syntax::SyntaxKind;
use crate::syntax::ast::{
    AstNode, BinaryExpr, CallExpr, Expr, FieldExpr, IndexExpr, NameExpr, UnaryExpr,
};

/// The text of an expression as written, for messages.
pub(crate) fn written(node: &Expr) -> String {
    node.syntax().text().to_string().trim().to_owned()
}

/// `op` moved on by `delta` bytes.
pub(crate) fn shifted(op: Operand, delta: u32) -> Operand {
    match op {
        Operand::Global(o) => Operand::Global(o + delta),
        Operand::Instance(o) => Operand::Instance(o + delta),
        Operand::Frame(o) => Operand::Frame(o + delta),
        Operand::Const(o) => Operand::Const(o + delta),
        Operand::Input(o) => Operand::Input(o + delta),
        Operand::Output(o) => Operand::Output(o + delta),
        Operand::Memory(o) => Operand::Memory(o + delta),
    }
}

/// The operand of a located variable's first byte, and its bit for a BOOL.
pub(crate) fn located_operand(located: program_image::Located) -> (Operand, Option<u8>) {
    let byte = (located.bit_offset / 8) as u32;
    let op = match located.region {
        program_image::Region::Input => Operand::Input(byte),
        program_image::Region::Output => Operand::Output(byte),
        program_image::Region::Memory => Operand::Memory(byte),
        program_image::Region::Data => Operand::Global(byte),
    };
    let bit = (located.size_bits == 1).then_some((located.bit_offset % 8) as u8);
    (op, bit)
}

/// The place of a located variable: its bytes in the area, or its bit for a BOOL.
pub(crate) fn located_place(located: program_image::Located) -> Place {
    match located_operand(located) {
        (operand, Some(bit)) => Place::Bit {
            operand,
            ty: IE::Byte,
            bit,
        },
        (operand, None) => Place::Direct(operand),
    }
}

/// A literal's type made concrete by where it goes, or by IEC's defaults (DINT, LREAL).
pub(crate) fn concrete(ty: &Type, want: Option<&Type>) -> Type {
    let wanted_number = want.filter(|w| {
        matches!(w, Type::Elementary(e) | Type::Subrange { base: e, .. } if !matches!(e, Elementary::String | Elementary::Wstring))
            || matches!(w, Type::Named(_))
    });
    match ty {
        Type::IntLiteral(value) => match wanted_number {
            Some(Type::Named(_)) | None => {
                let fits_dint = value.is_none_or(|v| i32::try_from(v).is_ok());
                Type::Elementary(if fits_dint {
                    Elementary::Dint
                } else {
                    Elementary::Lint
                })
            }
            Some(w) => w.clone(),
        },
        Type::RealLiteral => match wanted_number {
            Some(w @ Type::Elementary(Elementary::Real | Elementary::Lreal)) => w.clone(),
            _ => Type::Elementary(Elementary::Lreal),
        },
        Type::Subrange { base, .. } => Type::Elementary(*base),
        other => other.clone(),
    }
}

impl BodyGen<'_, '_, '_> {
    /// Bit `bit` of the value of type `ty` at `place`, directly or through a pointer (an
    /// element's bit through the element's pointer, as the image has no fused bit access).
    fn bit_place(&mut self, place: Place, ty: IE, bit: u8) -> Gen<Place> {
        match place {
            Place::Direct(operand) => Ok(Place::Bit { operand, ty, bit }),
            Place::Indirect(pointer) => Ok(Place::PointedBit { pointer, ty, bit }),
            Place::Element(element) => Ok(Place::PointedBit {
                pointer: self.element_pointer(element)?,
                ty,
                bit,
            }),
            Place::Bit { .. } | Place::PointedBit { .. } => Err("a bit has no bits".into()),
        }
    }

    /// A pointer to an element place, made as before the fused instructions existed:
    /// `Address` of the array, `Element` for the index, then `Offset` for a member. Where a
    /// place's address is needed (`ADR`, a `VAR_IN_OUT` argument, a bit, a copy of a
    /// structure element, an instance called) the element is reached this way.
    pub(crate) fn element_pointer(&mut self, element: ElementPlace) -> Gen<Operand> {
        let array = self.temp(8);
        self.emit(Instr::Address {
            dst: array,
            place: element.array,
        });
        let dst = self.temp(8);
        self.emit(Instr::Element {
            dst,
            base: array,
            index: element.index,
            index_ty: element.index_ty,
            low: element.low,
            count: element.count,
            stride: element.stride,
        });
        match self.member_place(Place::Indirect(dst), element.offset)? {
            Place::Indirect(pointer) => Ok(pointer),
            _ => Err("an element's member is reached through its pointer".into()),
        }
    }

    /// `typed` with an element place turned into the pointer to it, computed now: for a place
    /// that is written after code that could change its index runs (a call's output, the
    /// target of an assignment whose value calls, a FOR counter, an instance called), so the
    /// element is the one the index named when the place was written down, and an index out
    /// of bounds faults before that code runs, as it always did.
    pub(crate) fn settled(&mut self, typed: Typed) -> Gen<Typed> {
        match typed.place {
            Place::Element(element) => Ok(Typed {
                place: Place::Indirect(self.element_pointer(element)?),
                ..typed
            }),
            _ => Ok(typed),
        }
    }

    /// Whether evaluating `node` may run code of the program: a call of anything but a
    /// standard function (`INT_TO_REAL`, `SQRT`, `LEN`, which change nothing but their
    /// result), or a property read through its getter (a property of this POU by name, or a
    /// member of an instance, which may be one).
    ///
    /// Standard functions count as free of effects even though `__QUERYINTERFACE`,
    /// `__QUERYPOINTER` and `__DELETE` write an argument: what they write is an interface, a
    /// pointer or a pointer variable set to null, never an integer, so they cannot change the
    /// index of an element place settled before them.
    pub(crate) fn may_run_code(&self, node: &Expr) -> bool {
        node.syntax().descendants().any(|inner| match inner.kind() {
            SyntaxKind::CALL_EXPR => !CallExpr::cast(inner)
                .and_then(|call| call.callee())
                .is_some_and(|callee| match callee {
                    Expr::NameExpr(name) => name.ident().is_some_and(|name| {
                        let name = name.text();
                        self.scope.local(name).is_none()
                            && self.scope.globals.pou(name).is_none()
                            && signatures::function(name).is_some()
                    }),
                    _ => false,
                }),
            SyntaxKind::NAME_EXPR => NameExpr::cast(inner)
                .and_then(|name| name.ident())
                .is_some_and(|name| {
                    matches!(
                        self.scope.local(name.text()),
                        Some(LocalSymbol::Property(_))
                    )
                }),
            SyntaxKind::FIELD_EXPR => FieldExpr::cast(inner)
                .and_then(|field| field.base())
                .is_some_and(|base| match self.type_of(&base) {
                    Type::Named(name) => !matches!(
                        self.scope.globals.shape(&name),
                        Some(Shape::Struct(_) | Shape::Enum(_))
                    ),
                    _ => false,
                }),
            _ => false,
        })
    }

    /// Reads a place into an operand.
    pub(crate) fn load(&mut self, typed: &Typed) -> Gen<Operand> {
        Ok(match typed.place {
            Place::Direct(op) => op,
            Place::Element(element) => match typed.lay.shape {
                LayShape::Scalar(ty) | LayShape::Enum(ty) => {
                    let dst = self.temp(ty.size_bytes());
                    self.emit(Instr::LoadElement {
                        ty,
                        dst,
                        array: element.array,
                        index: element.index,
                        index_ty: element.index_ty,
                        low: element.low,
                        count: element.count,
                        stride: element.stride,
                        offset: element.offset,
                    });
                    dst
                }
                _ => {
                    let pointer = self.element_pointer(element)?;
                    let dst = self.temp(typed.lay.size);
                    self.emit(Instr::Load {
                        size: typed.lay.size,
                        dst,
                        ptr: pointer,
                    });
                    dst
                }
            },
            Place::Indirect(pointer) => {
                let dst = self.temp(typed.lay.size);
                self.emit(Instr::Load {
                    size: typed.lay.size,
                    dst,
                    ptr: pointer,
                });
                dst
            }
            Place::Bit { operand, ty, bit } => {
                let dst = self.temp(1);
                self.emit(Instr::GetBit {
                    ty,
                    dst,
                    src: operand,
                    bit,
                });
                dst
            }
            Place::PointedBit { pointer, ty, bit } => {
                let value = self.temp(ty.size_bytes());
                self.emit(Instr::Load {
                    size: ty.size_bytes(),
                    dst: value,
                    ptr: pointer,
                });
                let dst = self.temp(1);
                self.emit(Instr::GetBit {
                    ty,
                    dst,
                    src: value,
                    bit,
                });
                dst
            }
        })
    }

    /// Writes an operand of the place's type into the place.
    pub(crate) fn store(&mut self, typed: &Typed, src: Operand) -> Gen<()> {
        match typed.place {
            Place::Direct(dst) => {
                if dst == src {
                    return Ok(());
                }
                match typed.lay.shape {
                    LayShape::Scalar(ty) | LayShape::Enum(ty) => {
                        if self.retarget_last(dst, src, ty) {
                            return Ok(());
                        }
                        self.emit(Instr::Move { ty, dst, src })
                    }
                    _ => self.emit(Instr::Copy {
                        size: typed.lay.size,
                        dst,
                        src,
                    }),
                };
            }
            Place::Indirect(pointer) => {
                self.emit(Instr::Store {
                    size: typed.lay.size,
                    ptr: pointer,
                    src,
                });
            }
            Place::Element(element) => match typed.lay.shape {
                LayShape::Scalar(ty) | LayShape::Enum(ty) => {
                    self.emit(Instr::StoreElement {
                        ty,
                        array: element.array,
                        index: element.index,
                        index_ty: element.index_ty,
                        low: element.low,
                        count: element.count,
                        stride: element.stride,
                        offset: element.offset,
                        src,
                    });
                }
                _ => {
                    let pointer = self.element_pointer(element)?;
                    self.emit(Instr::Store {
                        size: typed.lay.size,
                        ptr: pointer,
                        src,
                    });
                }
            },
            Place::Bit { operand, ty, bit } => {
                self.emit(Instr::SetBit {
                    ty,
                    dst: operand,
                    bit,
                    src,
                });
            }
            Place::PointedBit { pointer, ty, bit } => {
                // The pointed value is read, changed in one bit and written back whole, as
                // the image has no instruction that sets a bit through a pointer.
                let size = ty.size_bytes();
                let value = self.temp(size);
                self.emit(Instr::Load {
                    size,
                    dst: value,
                    ptr: pointer,
                });
                self.emit(Instr::SetBit {
                    ty,
                    dst: value,
                    bit,
                    src,
                });
                self.emit(Instr::Store {
                    size,
                    ptr: pointer,
                    src: value,
                });
            }
        }
        Ok(())
    }

    /// A pointer to a place, in an operand.
    pub(crate) fn pointer_to(&mut self, typed: &Typed) -> Gen<Operand> {
        match typed.place {
            Place::Direct(op) => {
                let dst = self.temp(8);
                self.emit(Instr::Address { dst, place: op });
                Ok(dst)
            }
            Place::Indirect(pointer) => Ok(pointer),
            Place::Element(element) => self.element_pointer(element),
            // The checker refuses a bit passed by reference (E0135).
            Place::Bit { .. } | Place::PointedBit { .. } => {
                Err("the address of a single bit cannot be taken (E0135)".into())
            }
        }
    }

    /// `ADR(x)` and the argument of a VAR_IN_OUT: a pointer to the place `node` names.
    pub(crate) fn address_of(&mut self, node: &Expr) -> Gen<Operand> {
        let typed = self.place(node)?;
        self.pointer_to(&typed)
    }

    /// A typed place for an operand of layout `lay`.
    fn typed(&mut self, place: Place, ty: Type) -> Gen<Typed> {
        let lay = self.build.layouts.of(&ty)?;
        Ok(Typed { place, ty, lay })
    }

    /// A stored variable: follows VAR_IN_OUT and reference slots to their target.
    fn slot_place(&mut self, place: Place, declared: Type, by_ref: bool) -> Gen<Typed> {
        let follow = (by_ref || matches!(declared, Type::Reference(_))) && !self.raw_references;
        if by_ref && let Some(lay) = self.open_array_lay(&declared)? {
            // An open array is reached through its descriptor, which stays where it is.
            let ty = match declared {
                Type::Reference(target) => *target,
                other => other,
            };
            return Ok(Typed { place, ty, lay });
        }
        if follow {
            let target = match declared {
                Type::Reference(target) => *target,
                other => other,
            };
            let op = self.reference_value(place)?;
            return self.typed(Place::Indirect(op), target);
        }
        self.typed(place, declared)
    }

    /// The operand holding the address a reference or VAR_IN_OUT slot at `place` holds: the
    /// slot itself when it is reached directly, its value loaded when the slot is reached
    /// through a pointer (`p^.r` with `r : REFERENCE TO INT` a member of the pointed structure).
    pub(crate) fn reference_value(&mut self, place: Place) -> Gen<Operand> {
        match place {
            Place::Direct(op) => Ok(op),
            Place::Element(element) => {
                let pointer = self.element_pointer(element)?;
                self.reference_value(Place::Indirect(pointer))
            }
            Place::Indirect(pointer) => {
                let dst = self.temp(8);
                self.emit(Instr::Load {
                    size: 8,
                    dst,
                    ptr: pointer,
                });
                Ok(dst)
            }
            Place::Bit { .. } | Place::PointedBit { .. } => Err("a reference in a bit".into()),
        }
    }

    /// The operand of the descriptor of the open array `typed`: where it is, or a copy of it
    /// when it is reached through a pointer (`THIS^.values` in a function block); the copy
    /// points to the same elements.
    fn descriptor_operand(&mut self, typed: &Typed) -> Gen<Operand> {
        match typed.place {
            Place::Direct(descriptor) => Ok(descriptor),
            Place::Element(element) => {
                let pointer = self.element_pointer(element)?;
                self.descriptor_operand(&Typed {
                    place: Place::Indirect(pointer),
                    ty: typed.ty.clone(),
                    lay: typed.lay.clone(),
                })
            }
            Place::Indirect(pointer) => {
                let dst = self.temp(typed.lay.size);
                self.emit(Instr::Load {
                    size: typed.lay.size,
                    dst,
                    ptr: pointer,
                });
                Ok(dst)
            }
            Place::Bit { .. } | Place::PointedBit { .. } => Err("an open array in a bit".into()),
        }
    }

    /// The place an expression names.
    pub(crate) fn place(&mut self, node: &Expr) -> Gen<Typed> {
        if matches!(node, Expr::NameExpr(_) | Expr::FieldExpr(_))
            && let Some((owner, property, instance)) = self.property_of(node)?
        {
            // A property read as the base of a member, bit or element (`fb.Pos.x`,
            // `Flags.3`): its getter's value, in a temporary. The checker refuses writing
            // such a part or passing a property by reference (E0134), which would be lost.
            let (value, ty) = self.property_get(owner, property, instance)?;
            return self.typed(Place::Direct(value), ty);
        }
        match node {
            Expr::ParenExpr(paren) => {
                let inner = paren.inner().ok_or("empty parentheses")?;
                self.place(&inner)
            }
            Expr::NameExpr(name) => self.name_place(name),
            Expr::FieldExpr(field) => self.field_place(field),
            Expr::IndexExpr(index) => self.index_place(index),
            Expr::DerefExpr(deref) => {
                let base = deref.base().ok_or("nothing to dereference")?;
                let (pointer, ty) = self.expr(&base, None)?;
                let target = match ty {
                    Type::Pointer(target) | Type::Reference(target) => *target,
                    other => other,
                };
                self.typed(Place::Indirect(pointer), target)
            }
            Expr::AddressExpr(address) => {
                let text = address
                    .address()
                    .map(|t| t.text().to_owned())
                    .unwrap_or_default();
                let variable = project_model::Variable {
                    address: Some(text.clone()),
                    ..Default::default()
                };
                let located = located_of(&variable)
                    .ok_or_else(|| fail!("'{text}' is not a direct address"))?;
                let ty = self.type_of(node);
                let place = located_place(located);
                self.typed(place, ty)
            }
            _ => Err(fail!("'{}' is not a variable", written(node))),
        }
    }

    /// The variable called `name` in this body's scope (an SFC flag).
    pub(crate) fn variable_place_named(&mut self, name: &str) -> Gen<Typed> {
        let node = crate::sema::constant::parse_expression(name)
            .and_then(|n| NameExpr::cast(n.syntax().clone()))
            .ok_or_else(|| fail!("'{name}' is no variable"))?;
        self.name_place(&node)
    }

    /// The BOOL variable called `name` in this body's scope (an SFC boolean action).
    pub(crate) fn variable_named(&mut self, name: &str) -> Gen<Typed> {
        let typed = self.variable_place_named(name)?;
        if typed.ty != Type::BOOL {
            return Err(fail!(
                "'{name}' is named as a step's action but is a {}, not an action or a BOOL",
                typed.ty
            ));
        }
        Ok(typed)
    }

    fn name_place(&mut self, node: &NameExpr) -> Gen<Typed> {
        let first = node.first_token().ok_or("an empty name")?;
        let (token, global_only) = match first.kind() {
            SyntaxKind::IDENT => (first, false),
            SyntaxKind::DOT => (node.ident().ok_or("a name after '.'")?, true),
            SyntaxKind::THIS => {
                // The checker refuses THIS where a variable is needed (E0134).
                return Err("THIS is a pointer to the instance, not a variable".into());
            }
            _ => return Err(fail!("'{}' is not a variable", first.text())),
        };
        let name = token.text().to_owned();
        if !global_only && let Some(local) = self.scope.local(&name) {
            match local {
                LocalSymbol::Var(variable) => {
                    if variable.section == VarSection::VarExternal {
                        return self.global_place(&name);
                    }
                    if variable.section == VarSection::VarStat {
                        // Static variables are shared by every instance and call.
                        return self
                            .build
                            .global(variable)
                            .ok_or_else(|| fail!("the static variable '{name}' has no storage"));
                    }
                    if let Some(frame_var) = self.frame.var(&name).cloned() {
                        return self.slot_place(
                            Place::Direct(Operand::Frame(frame_var.offset)),
                            frame_var.ty,
                            frame_var.by_ref,
                        );
                    }
                    let slot = self
                        .instance
                        .as_ref()
                        .and_then(|instance| instance.slot(&name).cloned())
                        .ok_or_else(|| fail!("'{name}' has no storage"))?;
                    if let Some(located) = slot.located {
                        let place = located_place(located);
                        return self.typed(place, slot.ty);
                    }
                    return self.slot_place(
                        Place::Direct(Operand::Instance(slot.offset)),
                        slot.ty,
                        slot.by_ref,
                    );
                }
                LocalSymbol::Result(_) => {
                    let result = self
                        .frame
                        .result
                        .clone()
                        .ok_or_else(|| fail!("'{name}' has no result here"))?;
                    return self.slot_place(
                        Place::Direct(Operand::Frame(result.offset)),
                        result.ty,
                        false,
                    );
                }
                LocalSymbol::Property(_) => {
                    // `place` reads a property through its getter; only an SFC flag or action
                    // named after a property arrives here.
                    return Err(fail!("'{name}' is a property, not a variable"));
                }
                LocalSymbol::TransitionValue => {
                    let value = self
                        .instance
                        .as_ref()
                        .and_then(|i| i.sfc.as_ref())
                        .and_then(|sfc| sfc.transition_value(&name))
                        .ok_or_else(|| fail!("'{name}' is a transition of no chart here"))?;
                    return self.typed(Place::Direct(Operand::Instance(value)), Type::BOOL);
                }
                _ => return Err(fail!("'{name}' is not a variable")),
            }
        }
        self.global_place(&name)
    }

    fn global_place(&mut self, name: &str) -> Gen<Typed> {
        match self.scope.globals.lookup(name) {
            Some(GlobalSymbol::Var(variable)) => {
                let slot = self
                    .build
                    .global(variable)
                    .ok_or_else(|| fail!("the global variable '{name}' has no storage"))?;
                Ok(slot)
            }
            Some(GlobalSymbol::Pou(pou)) if pou.kind == project_model::PouKind::Program => {
                let offset = self
                    .build
                    .program_offset(&pou.name)
                    .ok_or_else(|| fail!("the program '{name}' has no instance"))?;
                self.typed(
                    Place::Direct(Operand::Global(offset)),
                    Type::Named(pou.name.clone()),
                )
            }
            Some(GlobalSymbol::Axis | GlobalSymbol::Cam) => self
                .build
                .device(name)
                .ok_or_else(|| fail!("the axis or cam '{name}' has no storage")),
            _ => Err(fail!("'{name}' is not a variable")),
        }
    }

    /// The chart a step or action flags expression `base` belongs to, the place of the
    /// instance holding it (`None`: this body's own instance) and the step's or flags' name.
    fn chart_of(&mut self, base: &Expr) -> Gen<(super::sfc::SfcLayout, Option<Place>, String)> {
        if let Expr::FieldExpr(field) = base {
            let owner = field.base().ok_or("a member of nothing")?;
            let name = field
                .member()
                .ok_or("a member without a name")?
                .text()
                .to_owned();
            let owner = self.place(&owner)?;
            let LayShape::Pou(pou_name) = &owner.lay.shape else {
                return Err(fail!("'{name}' is a step of no program or function block"));
            };
            let pou = self
                .scope
                .globals
                .pou(pou_name)
                .ok_or_else(|| fail!("no POU '{pou_name}'"))?;
            let sfc = self
                .build
                .layouts
                .instance(pou)?
                .sfc
                .clone()
                .ok_or_else(|| fail!("'{pou_name}' holds no chart"))?;
            return Ok((sfc, Some(owner.place), name));
        }
        let sfc = self
            .instance
            .as_ref()
            .and_then(|i| i.sfc.clone())
            .ok_or("SFC steps outside a chart")?;
        Ok((sfc, None, written(base)))
    }

    /// The place `offset` bytes into the instance `owner` (`None`: this body's instance).
    fn chart_place(&mut self, owner: Option<Place>, offset: u32) -> Gen<Place> {
        match owner {
            Some(owner) => self.member_place(owner, offset),
            None => Ok(Place::Direct(Operand::Instance(offset))),
        }
    }

    fn field_place(&mut self, node: &FieldExpr) -> Gen<Typed> {
        let base = node.base().ok_or("a member of nothing")?;
        let member = node.member().ok_or("a member without a name")?;
        let member_name = member.text().to_owned();
        match self.type_of(&base) {
            Type::Namespace(_) => {
                let gvl = base.syntax().text().to_string();
                let variable = self
                    .build
                    .gvl_variable(gvl.trim(), &member_name)
                    .ok_or_else(|| fail!("'{}' has no variable '{member_name}'", gvl.trim()))?;
                return self
                    .build
                    .global(variable)
                    .ok_or_else(|| fail!("'{member_name}' has no storage"));
            }
            Type::EnumNamespace(_) => {
                return Err(fail!("'{member_name}' is a value, not a variable"));
            }
            Type::Step => {
                // `Step.x`, `Step._x` and `Step.t` of a textual SFC step, of this body's chart
                // or of another instance's (`Main.Fill.x`).
                let (sfc, owner, step_name) = self.chart_of(&base)?;
                let step = sfc
                    .step(&step_name)
                    .ok_or_else(|| fail!("no step '{step_name}'"))?
                    .clone();
                let (offset, ty) = match member_name.to_ascii_uppercase().as_str() {
                    "X" => (step.x(), Type::BOOL),
                    "_X" => (step.next(), Type::BOOL),
                    "T" => (step.t(), Type::Elementary(Elementary::Time)),
                    _ => return Err(fail!("a step has x, _x and t, not '{member_name}'")),
                };
                let place = self.chart_place(owner, offset)?;
                return self.typed(place, ty);
            }
            Type::SfcAction => {
                // `_Action.x` (runs this cycle) and `_Action._x` (active) of an IEC action.
                let (sfc, owner, flags_name) = self.chart_of(&base)?;
                let action = sfc
                    .action(flags_name.trim_start_matches('_'))
                    .ok_or_else(|| fail!("no associated action '{flags_name}'"))?
                    .clone();
                let offset = match member_name.to_ascii_uppercase().as_str() {
                    "X" => action.x(),
                    "_X" => action.active(),
                    _ => return Err(fail!("an action's flags are x and _x, not '{member_name}'")),
                };
                let place = self.chart_place(owner, offset)?;
                return self.typed(place, Type::BOOL);
            }
            _ => {}
        }
        let base = self.place(&base)?;
        if member.kind() == SyntaxKind::DIRECT_ADDRESS {
            return self.partial_access(base, &member_name);
        }
        if member.kind() == SyntaxKind::INT_NUMBER {
            // `x.3`: one bit of an integer or bit string.
            let ty = match base.lay.shape {
                LayShape::Scalar(e) => e,
                _ => return Err("only integers and bit strings have bits".into()),
            };
            let bit: u8 = member_name.parse().map_err(|_| "a bit number")?;
            if u32::from(bit) >= ty.size_bytes() * 8 {
                return Err(fail!("{} has no bit {bit}", ty.name()));
            }
            let place = self.bit_place(base.place, ty, bit)?;
            return self.typed(place, Type::BOOL);
        }
        if let LayShape::Pou(pou_name) = &base.lay.shape
            && let Some(pou) = self.scope.globals.pou(pou_name)
        {
            let instance = self.build.layouts.instance(pou)?;
            let slot = instance
                .slot(&member_name)
                .cloned()
                .ok_or_else(|| fail!("'{pou_name}' has no variable '{member_name}'"))?;
            if let Some(located) = slot.located {
                let place = located_place(located);
                return self.typed(place, slot.ty);
            }
            let place = self.member_place(base.place, slot.offset)?;
            return self.slot_place(place, slot.ty, slot.by_ref);
        }
        let (offset, lay) = self.build.layouts.member_of(&base.lay, &member_name)?;
        let ty = self.member_type(&base, &member_name)?;
        let place = self.member_place(base.place, offset)?;
        match ty {
            Type::Reference(_) => self.slot_place(place, ty, false),
            ty => Ok(Typed { place, ty, lay }),
        }
    }

    /// `w.%X3`, `d.%B1`, `l.%W2`, `l.%D1`: a bit, byte, word or double word inside a bit
    /// string, counted from the least significant end.
    fn partial_access(&mut self, base: Typed, text: &str) -> Gen<Typed> {
        let upper = text.to_ascii_uppercase();
        let rest = upper
            .strip_prefix('%')
            .ok_or("a partial access starts with %")?;
        let (size, number) = rest.split_at(1);
        let index: u32 = number
            .parse()
            .map_err(|_| format!("'{text}' is no partial access"))?;
        let LayShape::Scalar(ty) = base.lay.shape else {
            return Err(fail!("'{text}' needs a bit string"));
        };
        let width = ty.size_bytes() * 8;
        let (part, bits) = match size {
            "X" => (None, 1),
            "B" => (Some(Elementary::Byte), 8),
            "W" => (Some(Elementary::Word), 16),
            "D" => (Some(Elementary::Dword), 32),
            _ => return Err(fail!("'{text}' is no partial access")),
        };
        if (index + 1) * bits > width {
            return Err(fail!("{} has no {text}", ty.name()));
        }
        match part {
            None => {
                let place = self.bit_place(base.place, ty, index as u8)?;
                self.typed(place, Type::BOOL)
            }
            Some(part) => {
                // Parts are counted from the least significant end, which is the first byte
                // in the image's little-endian layout.
                let place = self.member_place(base.place, index * bits / 8)?;
                self.typed(place, Type::Elementary(part))
            }
        }
    }

    fn member_type(&mut self, base: &Typed, member: &str) -> Gen<Type> {
        let name = match &base.ty {
            Type::Named(name) => name.clone(),
            other => return Err(fail!("{other} has no members")),
        };
        self.scope
            .globals
            .member(&name, member)
            .map(|m| m.ty)
            .ok_or_else(|| fail!("'{name}' has no member '{member}'"))
    }

    /// A member `offset` bytes into `base`: a shifted operand, or a pointer moved on.
    pub(crate) fn member_place(&mut self, base: Place, offset: u32) -> Gen<Place> {
        Ok(match base {
            Place::Direct(op) => Place::Direct(shifted(op, offset)),
            Place::Element(element) => Place::Element(ElementPlace {
                offset: element
                    .offset
                    .checked_add(offset)
                    .ok_or("a member more than 4 GiB into its element")?,
                ..element
            }),
            Place::Indirect(pointer) => {
                if offset == 0 {
                    Place::Indirect(pointer)
                } else {
                    let dst = self.temp(8);
                    self.emit(Instr::Offset {
                        dst,
                        base: pointer,
                        offset,
                    });
                    Place::Indirect(dst)
                }
            }
            Place::Bit { .. } | Place::PointedBit { .. } => {
                return Err("a bit has no members".into());
            }
        })
    }

    fn index_place(&mut self, node: &IndexExpr) -> Gen<Typed> {
        let base_node = node.base().ok_or("an index of nothing")?;
        let indices: Vec<Expr> = node.indices().collect();
        let base = self.place(&base_node)?;
        if let LayShape::OpenArray {
            element,
            element_ty,
            rank,
        } = base.lay.shape.clone()
        {
            if indices.len() != rank as usize {
                return Err(fail!("{} index(es) for {rank} dimension(s)", indices.len()));
            }
            let descriptor = self.descriptor_operand(&base)?;
            let mut operands = Vec::new();
            for index in &indices {
                let (value, ty) = self.expr(index, None)?;
                let scalar = self
                    .scalar_of(&ty)
                    .ok_or("an array index must be an integer")?;
                operands.push((value, scalar));
            }
            let dst = self.temp(8);
            self.emit(Instr::OpenElement {
                dst,
                descriptor,
                indices: operands,
                stride: element.size,
            });
            return Ok(Typed {
                place: Place::Indirect(dst),
                ty: element_ty,
                lay: *element,
            });
        }
        let (element, element_ty, dims) = match base.lay.shape.clone() {
            LayShape::Array {
                element,
                element_ty,
                dims,
            } => (element, element_ty, dims),
            // CODESYS indexes a STRING's bytes (a WSTRING's words) from 0, as the checker types
            // them; the terminator's place, at the length, is the last one inside.
            LayShape::Text { wide, length } => {
                let element_ty = Type::Elementary(if wide {
                    Elementary::Word
                } else {
                    Elementary::Byte
                });
                let element = self.lay(&element_ty)?;
                (Box::new(element), element_ty, vec![(0, i64::from(length))])
            }
            _ => return Err(fail!("'{}' is not an array", written(&base_node))),
        };
        if dims.len() != indices.len() {
            return Err(fail!(
                "{} index(es) for {} dimension(s)",
                indices.len(),
                dims.len()
            ));
        }
        // Strides of each dimension: the size of what one step of its index skips.
        let mut strides = vec![0u32; dims.len()];
        let mut stride = element.size;
        for (i, (low, high)) in dims.iter().enumerate().rev() {
            strides[i] = stride;
            stride = stride.saturating_mul(
                u32::try_from(high.abs_diff(*low).saturating_add(1)).unwrap_or(u32::MAX),
            );
        }
        let constants: Vec<Option<Value>> = indices
            .iter()
            .map(|index| match evaluate_node(index, self.scope.globals) {
                Some(value @ Value::Int(_)) => Some(value),
                _ => None,
            })
            .collect();
        // An array at a direct place with one index known only when the code runs is reached
        // without a pointer (`docs/native-engine.md` §10); with several such indices each
        // moves a pointer, as before.
        let fused = matches!(base.place, Place::Direct(_))
            && constants.iter().filter(|value| value.is_none()).count() == 1;
        let mut place = base.place;
        let mut constant_offset = 0u32;
        for (((index, (low, high)), stride), constant) in
            indices.iter().zip(&dims).zip(&strides).zip(constants)
        {
            if let Some(Value::Int(value)) = constant {
                let value = i64::try_from(value).map_err(|_| "index out of range")?;
                if value < *low || value > *high {
                    return Err(fail!("the index {value} is outside {low}..{high}"));
                }
                constant_offset += (value - low) as u32 * stride;
                continue;
            }
            if constant_offset > 0 {
                place = self.member_place(place, constant_offset)?;
                constant_offset = 0;
            }
            let count = high.abs_diff(*low).saturating_add(1);
            let array = match place {
                Place::Direct(array) if fused => Some(array),
                _ => None,
            };
            // The pointer path takes the array's address before the index, as it always did.
            let base_pointer = match array {
                Some(_) => None,
                None => Some(self.pointer_to(&Typed {
                    place,
                    ty: base.ty.clone(),
                    lay: base.lay.clone(),
                })?),
            };
            let (index_value, index_ty) = self.expr(index, None)?;
            let index_scalar = self
                .scalar_of(&index_ty)
                .ok_or("an array index must be an integer")?;
            let base_pointer = match (array, base_pointer) {
                (Some(array), _) if index_scalar.is_integer() => {
                    place = Place::Element(ElementPlace {
                        array,
                        index: index_value,
                        index_ty: index_scalar,
                        low: *low,
                        count,
                        stride: *stride,
                        offset: 0,
                    });
                    continue;
                }
                (_, Some(pointer)) => pointer,
                (_, None) => self.pointer_to(&Typed {
                    place,
                    ty: base.ty.clone(),
                    lay: base.lay.clone(),
                })?,
            };
            let dst = self.temp(8);
            self.emit(Instr::Element {
                dst,
                base: base_pointer,
                index: index_value,
                index_ty: index_scalar,
                low: *low,
                count,
                stride: *stride,
            });
            place = Place::Indirect(dst);
        }
        if constant_offset > 0 {
            place = self.member_place(place, constant_offset)?;
        }
        Ok(Typed {
            place,
            ty: element_ty,
            lay: *element,
        })
    }

    /// Evaluates `node` into an operand of exactly type `target`.
    pub(crate) fn expr_as(&mut self, node: &Expr, target: &Type) -> Gen<Operand> {
        if self.interface_of(target).is_some() {
            return self.interface_value(node, target);
        }
        let (operand, ty) = self.expr(node, Some(target))?;
        self.convert(operand, &ty, target)
    }

    /// Converts an operand between types (implicit conversions the checker allowed).
    pub(crate) fn convert(&mut self, operand: Operand, from: &Type, to: &Type) -> Gen<Operand> {
        let from_lay = self.build.layouts.of(from)?;
        let to_lay = self.build.layouts.of(to)?;
        if from_lay.id == to_lay.id {
            return Ok(operand);
        }
        match (&from_lay.shape, &to_lay.shape) {
            (LayShape::Scalar(a) | LayShape::Enum(a), LayShape::Scalar(b) | LayShape::Enum(b)) => {
                if a == b {
                    return Ok(operand);
                }
                let dst = self.temp(b.size_bytes());
                self.emit(Instr::Convert {
                    from: *a,
                    to: *b,
                    dst,
                    src: operand,
                });
                Ok(dst)
            }
            (LayShape::Text { wide: a, .. }, LayShape::Text { wide: b, length }) if a == b => {
                let dst = self.temp(to_lay.size);
                let size = from_lay.size.min(to_lay.size);
                self.emit(Instr::Copy {
                    size,
                    dst,
                    src: operand,
                });
                // The copy may have cut the terminating zero.
                let unit = if *b { 2 } else { 1 };
                let zero = self.build.constant(&[0, 0]);
                let terminator = shifted(dst, length * unit);
                self.emit(Instr::Move {
                    ty: if *b { IE::Word } else { IE::Byte },
                    dst: terminator,
                    src: zero,
                });
                Ok(dst)
            }
            (
                LayShape::Text {
                    wide: from_wide,
                    length: from_length,
                },
                LayShape::Text { length, .. },
            ) => {
                // STRING to WSTRING or back: the runtime recodes each character.
                let dst = self.temp(to_lay.size);
                self.emit(Instr::CallStdFunction {
                    function: program_image::StdFunction::Recode,
                    wide: *from_wide,
                    dst: (dst, *length),
                    args: vec![(operand, *from_length)],
                });
                Ok(dst)
            }
            (LayShape::Pointer, LayShape::Pointer) => Ok(operand),
            _ if from_lay.size == to_lay.size => Ok(operand),
            _ => Err(fail!("cannot convert {from} to {to}")),
        }
    }

    /// Evaluates an expression; the type returned is concrete (never a literal's).
    pub(crate) fn expr(&mut self, node: &Expr, want: Option<&Type>) -> Gen<(Operand, Type)> {
        let checked = self.type_of(node);
        match node {
            Expr::ParenExpr(paren) => {
                let inner = paren.inner().ok_or("empty parentheses")?;
                self.expr(&inner, want)
            }
            Expr::Literal(_) | Expr::TypedLiteral(_) => self.literal(node, &checked, want),
            Expr::NameExpr(_) | Expr::FieldExpr(_) => {
                if let Expr::NameExpr(name) = node
                    && let Some(first) = name.first_token()
                    && matches!(first.kind(), SyntaxKind::THIS | SyntaxKind::SUPER)
                {
                    // THIS and SUPER are pointers to the running instance.
                    let dst = self.temp(8);
                    self.emit(Instr::Address {
                        dst,
                        place: Operand::Instance(0),
                    });
                    return Ok((dst, checked));
                }
                if let Some((owner, property, instance)) = self.property_of(node)? {
                    return self.property_get(owner, property, instance);
                }
                if let Type::Named(name) = &checked
                    && matches!(self.scope.globals.shape(name), Some(Shape::Enum(_)))
                    && self.is_enum_value(node)
                {
                    return self.literal(node, &checked, want);
                }
                let typed = self.place(node)?;
                let operand = self.load(&typed)?;
                Ok((operand, typed.ty))
            }
            Expr::IndexExpr(_) | Expr::DerefExpr(_) | Expr::AddressExpr(_) => {
                let typed = self.place(node)?;
                let operand = self.load(&typed)?;
                Ok((operand, typed.ty))
            }
            Expr::UnaryExpr(unary) => self.unary(unary, &checked, want),
            Expr::BinaryExpr(binary) => self.binary(binary, &checked, want),
            Expr::CallExpr(call) => self
                .call(call, want)?
                .ok_or_else(|| fail!("'{}' gives no value", written(node))),
            Expr::ArrayInit(_) | Expr::ErrorNode(_) => {
                Err(fail!("cannot compile the expression '{}'", written(node)))
            }
        }
    }

    /// Whether a name or member expression names an enumeration value rather than a variable.
    fn is_enum_value(&self, node: &Expr) -> bool {
        match node {
            Expr::FieldExpr(field) => {
                field
                    .member()
                    .is_some_and(|t| t.kind() == SyntaxKind::IDENT)
                    && field
                        .base()
                        .is_some_and(|base| matches!(self.type_of(&base), Type::EnumNamespace(_)))
            }
            Expr::NameExpr(name_expr) => {
                let Some(name) = name_expr.ident() else {
                    return false;
                };
                self.scope.local(name.text()).is_none()
                    && matches!(
                        self.scope.globals.lookup(name.text()),
                        Some(GlobalSymbol::EnumValue(_))
                    )
            }
            _ => false,
        }
    }

    fn literal(
        &mut self,
        node: &Expr,
        checked: &Type,
        want: Option<&Type>,
    ) -> Gen<(Operand, Type)> {
        let value = evaluate_node(node, self.scope.globals)
            .ok_or_else(|| fail!("'{}' is not a constant", written(node)))?;
        let ty = match (checked, want) {
            (Type::String { wide, .. }, Some(Type::String { wide: w, length })) if wide == w => {
                Type::String {
                    wide: *w,
                    length: *length,
                }
            }
            (Type::String { wide, .. }, _) => {
                let length = match &value {
                    Value::Text(chars) => chars.len().max(1) as u32,
                    _ => 1,
                };
                Type::String {
                    wide: *wide,
                    length,
                }
            }
            _ => concrete(checked, want),
        };
        let lay = self.build.layouts.of(&ty)?;
        let bytes = match (&lay.shape, &value) {
            (LayShape::Scalar(e) | LayShape::Enum(e), _) => {
                let raw =
                    raw_of(&value, *e).ok_or_else(|| fail!("'{}' is not a {ty}", written(node)))?;
                raw.to_le_bytes()[..e.size_bytes() as usize].to_vec()
            }
            (LayShape::Text { wide, length }, Value::Text(chars)) => {
                text_bytes(chars, *wide, *length)
            }
            _ => {
                return Err(fail!("'{}' is not a {ty}", written(node)));
            }
        };
        Ok((self.build.constant(&bytes), ty))
    }

    fn unary(
        &mut self,
        unary: &UnaryExpr,
        checked: &Type,
        want: Option<&Type>,
    ) -> Gen<(Operand, Type)> {
        let node = &Expr::UnaryExpr(unary.clone());
        let operator = unary.op().ok_or("an operator")?.kind();
        let operand_node = unary.operand().ok_or("an operand")?;
        if matches!(checked, Type::IntLiteral(_) | Type::RealLiteral)
            && operator == SyntaxKind::MINUS
        {
            // A negative literal is a constant of the type it goes to.
            if let Some(value) = evaluate_node(node, self.scope.globals) {
                let ty = concrete(checked, want);
                let scalar = self.scalar_of(&ty).ok_or("a number")?;
                let raw = raw_of(&value, scalar).ok_or("a number")?;
                return Ok((self.build.scalar_constant(raw, scalar), ty));
            }
        }
        let ty = concrete(checked, want);
        let value = self.expr_as(&operand_node, &ty)?;
        let scalar = self
            .scalar_of(&ty)
            .ok_or_else(|| fail!("an operator on {ty}"))?;
        let op = match operator {
            SyntaxKind::NOT => UnaryOp::Not,
            SyntaxKind::MINUS => UnaryOp::Neg,
            SyntaxKind::PLUS => return Ok((value, ty)),
            other => return Err(fail!("the operator {other:?}")),
        };
        let dst = self.temp(scalar.size_bytes());
        self.emit(Instr::Unary {
            op,
            ty: scalar,
            dst,
            src: value,
        });
        Ok((dst, ty))
    }

    fn binary(
        &mut self,
        binary: &BinaryExpr,
        checked: &Type,
        want: Option<&Type>,
    ) -> Gen<(Operand, Type)> {
        let node = &Expr::BinaryExpr(binary.clone());
        let (Some(left), Some(right)) = (binary.lhs(), binary.rhs()) else {
            return Err("an operator needs two operands".into());
        };
        let operator = binary.op().ok_or("an operator")?.kind();
        use SyntaxKind as K;
        let compare = match operator {
            K::EQ => Some(CompareOp::Eq),
            K::NEQ => Some(CompareOp::Ne),
            K::LT => Some(CompareOp::Lt),
            K::LE => Some(CompareOp::Le),
            K::GT => Some(CompareOp::Gt),
            K::GE => Some(CompareOp::Ge),
            _ => None,
        };
        if let Some(op) = compare {
            return self.compare(op, &left, &right);
        }
        if matches!(operator, K::AND_THEN | K::OR_ELSE) {
            let dst = self.temp(1);
            let a = self.expr_as(&left, &Type::BOOL)?;
            self.emit(Instr::Move {
                ty: IE::Bool,
                dst,
                src: a,
            });
            let skip = if operator == K::AND_THEN {
                self.emit(Instr::JumpIfNot {
                    cond: dst,
                    target: 0,
                })
            } else {
                self.emit(Instr::JumpIf {
                    cond: dst,
                    target: 0,
                })
            };
            let b = self.expr_as(&right, &Type::BOOL)?;
            self.emit(Instr::Move {
                ty: IE::Bool,
                dst,
                src: b,
            });
            let end = self.here();
            self.patch(skip, end);
            return Ok((dst, Type::BOOL));
        }
        let op = match operator {
            K::PLUS => BinaryOp::Add,
            K::MINUS => BinaryOp::Sub,
            K::STAR => BinaryOp::Mul,
            K::SLASH => BinaryOp::Div,
            K::MOD => BinaryOp::Mod,
            K::POWER => BinaryOp::Expt,
            K::AND | K::AMP => BinaryOp::And,
            K::OR => BinaryOp::Or,
            K::XOR => BinaryOp::Xor,
            other => return Err(fail!("the operator {other:?}")),
        };
        let ty = concrete(checked, want);
        // Constant arithmetic is folded by the checker's rules, so `2 * 64` is one constant.
        if matches!(checked, Type::IntLiteral(_) | Type::RealLiteral)
            && let Some(value) = evaluate_node(node, self.scope.globals)
            && let Some(scalar) = self.scalar_of(&ty)
            && let Some(raw) = raw_of(&value, scalar)
        {
            return Ok((self.build.scalar_constant(raw, scalar), ty));
        }
        let scalar = self
            .scalar_of(&ty)
            .ok_or_else(|| fail!("'{}' on {ty}", written(node)))?;
        let a = self.expr_as(&left, &ty)?;
        let b = self.expr_as(&right, &ty)?;
        let dst = self.temp(scalar.size_bytes());
        self.emit(Instr::Binary {
            op,
            ty: scalar,
            dst,
            a,
            b,
        });
        Ok((dst, ty))
    }

    /// `left op right` for a comparison operator or function: pointers and interfaces compare
    /// as addresses, strings by their characters, other values in their common type.
    pub(crate) fn compare(
        &mut self,
        op: CompareOp,
        left: &Expr,
        right: &Expr,
    ) -> Gen<(Operand, Type)> {
        let (lt, rt) = (self.type_of(left), self.type_of(right));
        // A bit string compared with a number (which only the CODESYS dialect lets through
        // the checker) is compared in the type their arithmetic has.
        let common = common_type(&lt, &rt)
            .or_else(|| bit_string_arithmetic(&lt, &rt))
            .or_else(|| mixed_sign_type(&lt, &rt))
            .or_else(|| integer_real_type(&lt, &rt))
            .unwrap_or(lt);
        let ty = concrete(&common, None);
        let sides = [self.type_of(left), self.type_of(right)];
        if sides.iter().any(|t| matches!(t, Type::Pointer(_))) {
            // Pointers compare as addresses; a literal on the other side is an address too.
            let mut operands = Vec::new();
            for node in [&left, &right] {
                let operand = match evaluate_node(node, self.scope.globals) {
                    Some(Value::Int(v)) => self.build.scalar_constant(v as u64, IE::Lword),
                    _ => self.expr(node, None)?.0,
                };
                operands.push(operand);
            }
            let dst = self.temp(1);
            self.emit(Instr::Compare {
                op,
                ty: IE::Lword,
                dst,
                a: operands[0],
                b: operands[1],
            });
            return Ok((dst, Type::BOOL));
        }
        if let Some(interface) = sides.into_iter().find(|t| self.interface_of(t).is_some()) {
            // Interfaces compare by the instance they point to (`itf <> 0`).
            let a = self.interface_value(left, &interface)?;
            let b = self.interface_value(right, &interface)?;
            let dst = self.temp(1);
            self.emit(Instr::Compare {
                op,
                ty: IE::Lword,
                dst,
                a,
                b,
            });
            return Ok((dst, Type::BOOL));
        }
        if let Type::String { wide, .. } = ty {
            return self.compare_strings(op, left, right, wide);
        }
        let scalar = self
            .scalar_of(&ty)
            .ok_or_else(|| fail!("internal error: comparing values of type {ty} reached the code generator, which the checker refuses (E0105)"))?;
        let a = self.expr_as(left, &ty)?;
        let b = self.expr_as(right, &ty)?;
        let dst = self.temp(1);
        self.emit(Instr::Compare {
            op,
            ty: scalar,
            dst,
            a,
            b,
        });
        Ok((dst, Type::BOOL))
    }

    /// `a op b` on strings: the runtime compares them, the result is compared with 0.
    fn compare_strings(
        &mut self,
        op: CompareOp,
        left: &Expr,
        right: &Expr,
        wide: bool,
    ) -> Gen<(Operand, Type)> {
        let mut args = Vec::new();
        for node in [left, right] {
            let (operand, ty) = self.expr(node, None)?;
            let Type::String { length, .. } = ty else {
                return Err(fail!("comparing a string with {ty}"));
            };
            args.push((operand, length));
        }
        let order = self.temp(4);
        self.emit(Instr::CallStdFunction {
            function: program_image::StdFunction::Compare,
            wide,
            dst: (order, 0),
            args,
        });
        let zero = self.build.scalar_constant(0, IE::Dint);
        let dst = self.temp(1);
        self.emit(Instr::Compare {
            op,
            ty: IE::Dint,
            dst,
            a: order,
            b: zero,
        });
        Ok((dst, Type::BOOL))
    }

    /// The descriptor layout of a VAR_IN_OUT whose type (`declared`, as a reference) is an
    /// array with open bounds.
    pub(crate) fn open_array_lay(&mut self, declared: &Type) -> Gen<Option<Lay>> {
        let target = match declared {
            Type::Reference(target) => &**target,
            other => other,
        };
        if super::layout::open_array(target).is_none() {
            return Ok(None);
        }
        let reference = Type::Reference(Box::new(target.clone()));
        Ok(Some(self.build.layouts.of(&reference)?))
    }

    /// The descriptor of the array `node` names, for a VAR_IN_OUT with open bounds: a pointer
    /// to it and its bounds (an open array passed on gives its own descriptor).
    pub(crate) fn open_array_descriptor(&mut self, node: &Expr, lay: &Lay) -> Gen<Operand> {
        let typed = self.place(node)?;
        if let LayShape::OpenArray { .. } = typed.lay.shape {
            return self.descriptor_operand(&typed);
        }
        let LayShape::Array { dims, .. } = typed.lay.shape.clone() else {
            return Err(fail!("{} is not an array", typed.ty));
        };
        let LayShape::OpenArray { rank, .. } = lay.shape else {
            return Err("not an open array".into());
        };
        if dims.len() != rank as usize {
            return Err(fail!("an array of {} dimension(s) for {rank}", dims.len()));
        }
        let pointer = self.pointer_to(&typed)?;
        let descriptor = self.temp(lay.size);
        self.emit(Instr::Move {
            ty: IE::Lword,
            dst: descriptor,
            src: pointer,
        });
        for (dim, (low, high)) in dims.iter().enumerate() {
            for (k, bound) in [low, high].into_iter().enumerate() {
                let value = self.build.scalar_constant(*bound as u64, IE::Lint);
                let at = shifted(descriptor, 8 + 16 * dim as u32 + 8 * k as u32);
                self.emit(Instr::Move {
                    ty: IE::Lint,
                    dst: at,
                    src: value,
                });
            }
        }
        Ok(descriptor)
    }

    /// The layout of a type.
    pub(crate) fn lay(&mut self, ty: &Type) -> Gen<Lay> {
        self.build.layouts.of(ty)
    }
}
