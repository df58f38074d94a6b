//! Interfaces: an interface value is a pointer to an instance and the instance's class (the
//! POU index of its function block); a method called through it is chosen by the class from a
//! table of every function block that implements the interface.

use program_image::{Elementary as IE, Instr, Operand};
use project_model::{Pou, PouKind};

use super::body::{BodyGen, Gen};
use super::call::Argument;
use super::error::fail;
use super::expr::shifted;
use super::layout::LayShape;
use crate::sema::scope::inheritance_chain;
use crate::sema::ty::Type;
use crate::syntax::ast::Expr;

impl<'p> BodyGen<'_, '_, 'p> {
    /// The interface `ty` names, if it names one.
    pub(crate) fn interface_of(&self, ty: &Type) -> Option<&'p Pou> {
        match ty {
            Type::Named(name) => self
                .scope
                .globals
                .pou(name)
                .filter(|p| p.kind == PouKind::Interface),
            _ => None,
        }
    }

    /// Whether the function block `pou` (or a base) implements `interface` (or an interface
    /// extending it).
    fn implements(&self, pou: &'p Pou, interface: &str) -> bool {
        inheritance_chain(self.scope.globals, pou)
            .iter()
            .any(|current| {
                current
                    .implements
                    .iter()
                    .any(|name| self.extends_interface(name, interface, 0))
            })
    }

    fn extends_interface(&self, name: &str, wanted: &str, depth: usize) -> bool {
        name.eq_ignore_ascii_case(wanted)
            || depth < 32
                && self.scope.globals.pou(name).is_some_and(|itf| {
                    itf.extends
                        .iter()
                        .chain(&itf.implements)
                        .any(|base| self.extends_interface(base, wanted, depth + 1))
                })
    }

    /// An interface value for `node`: an instance of a function block that implements it, the
    /// literal 0 (no instance), or another interface value.
    pub(crate) fn interface_value(&mut self, node: &Expr, interface: &Type) -> Gen<Operand> {
        let checked = self.type_of(node);
        if let Type::IntLiteral(Some(0)) = checked {
            return Ok(self.build.constant(&[0; 16]));
        }
        if let Type::Named(name) = &checked
            && let Some(pou) = self
                .scope
                .globals
                .pou(name)
                .filter(|p| p.kind == PouKind::FunctionBlock)
        {
            let typed = self.place(node)?;
            let pointer = self.pointer_to(&typed)?;
            let class = self.build.pou_index(&pou.name, None)?;
            let value = self.temp(16);
            self.emit(Instr::Move {
                ty: IE::Lword,
                dst: value,
                src: pointer,
            });
            let class = self.build.scalar_constant(u64::from(class), IE::Udint);
            self.emit(Instr::Move {
                ty: IE::Udint,
                dst: shifted(value, 8),
                src: class,
            });
            return Ok(value);
        }
        let (value, ty) = self.expr(node, Some(interface))?;
        match self.lay(&ty)?.shape {
            LayShape::Interface => Ok(value),
            _ => Err(fail!("{ty} is not an instance that implements {interface}")),
        }
    }

    /// `itf.Method(args)`: a call chosen at run time by the instance's class.
    pub(crate) fn call_virtual(
        &mut self,
        interface: &'p Pou,
        method_name: &str,
        base: &Expr,
        args: &[Argument],
    ) -> Gen<Option<(Operand, Type)>> {
        let declared = interface
            .methods
            .iter()
            .find(|m| m.name.eq_ignore_ascii_case(method_name))
            .ok_or_else(|| {
                format!(
                    "the interface '{}' has no method '{method_name}'",
                    interface.name
                )
            })?;
        let frame = self.build.frame_of(
            interface,
            &declared.variables,
            declared.return_type.as_deref(),
        )?;
        let mut table = Vec::new();
        let classes: Vec<&'p Pou> = self
            .build
            .function_blocks()
            .into_iter()
            .filter(|pou| self.implements(pou, &interface.name))
            .collect();
        for class in classes {
            let owner = inheritance_chain(self.scope.globals, class)
                .into_iter()
                .find(|p| {
                    p.methods
                        .iter()
                        .any(|m| m.name.eq_ignore_ascii_case(method_name))
                })
                .ok_or_else(|| {
                    format!(
                        "'{}' implements '{}' but has no method '{method_name}'",
                        class.name, interface.name
                    )
                })?;
            let method = owner
                .methods
                .iter()
                .find(|m| m.name.eq_ignore_ascii_case(method_name))
                .ok_or("a method")?;
            // Every implementation must take its parameters where the interface puts them.
            let own =
                self.build
                    .frame_of(owner, &method.variables, method.return_type.as_deref())?;
            let same = frame
                .vars
                .iter()
                .all(|(var, slot)| own.var(&var.name).is_some_and(|o| o.offset == slot.offset))
                && frame.result.as_ref().map(|r| r.offset) == own.result.as_ref().map(|r| r.offset);
            if !same {
                return Err(fail!(
                    "'{}.{method_name}' does not declare the parameters of '{}.{method_name}' in the same order",
                    owner.name,
                    interface.name
                ));
            }
            table.push((
                self.build.pou_index(&class.name, None)?,
                self.build.pou_index(&owner.name, Some(&method.name))?,
            ));
        }
        let (value, _) = self.expr(base, None)?;
        let call = self.frame_arguments(&frame, args)?;
        self.emit(Instr::CallVirtual {
            table,
            interface: value,
            inputs: call.inputs,
            outputs: call.outputs,
        });
        self.store_outputs(call.stores)?;
        Ok(call.result)
    }
}
