//! Properties: reading one calls its getter, assigning one calls its setter, each on the
//! instance the property belongs to (CODESYS's `PROPERTY … GET … SET`).

use program_image::{Instr, Operand, Transfer};
use project_model::{Pou, PouKind, Property};

use super::body::{BodyGen, Gen};
use super::error::fail;
use crate::sema::scope::{LocalSymbol, inheritance_chain};
use crate::sema::ty::Type;
use crate::syntax::SyntaxKind;
use crate::syntax::ast::Expr;

/// The image name of a property accessor, as `Build::pou_index` knows it.
pub(crate) fn accessor_name(property: &str, get: bool) -> String {
    format!("{property}.{}", if get { "GET" } else { "SET" })
}

impl<'p> BodyGen<'_, '_, 'p> {
    /// The property `node` names, with its owner and a pointer to the instance, if it names
    /// one: `Prop` inside the function block or `fb.Prop` outside.
    pub(crate) fn property_of(
        &mut self,
        node: &Expr,
    ) -> Gen<Option<(&'p Pou, &'p Property, Operand)>> {
        match node {
            Expr::NameExpr(name_expr) => {
                let Some(name) = name_expr.ident() else {
                    return Ok(None);
                };
                let Some(LocalSymbol::Property(property)) = self.scope.local(name.text()) else {
                    return Ok(None);
                };
                let owner = inheritance_chain(self.scope.globals, self.pou)
                    .into_iter()
                    .find(|p| p.properties.iter().any(|q| std::ptr::eq(q, property)))
                    .ok_or("a property without an owner")?;
                let this = self.temp(8);
                self.emit(Instr::Address {
                    dst: this,
                    place: Operand::Instance(0),
                });
                Ok(Some((owner, property, this)))
            }
            Expr::FieldExpr(field) => {
                let Some(base) = field.base() else {
                    return Ok(None);
                };
                let Some(member) = field.member().filter(|t| t.kind() == SyntaxKind::IDENT) else {
                    return Ok(None);
                };
                let Type::Named(type_name) = self.type_of(&base) else {
                    return Ok(None);
                };
                let Some(pou) = self
                    .scope
                    .globals
                    .pou(&type_name)
                    .filter(|p| p.kind != PouKind::Function)
                else {
                    return Ok(None);
                };
                let found = inheritance_chain(self.scope.globals, pou)
                    .into_iter()
                    .find_map(|owner| {
                        owner
                            .properties
                            .iter()
                            .find(|p| p.name.eq_ignore_ascii_case(member.text()))
                            .map(|p| (owner, p))
                    });
                let Some((owner, property)) = found else {
                    return Ok(None);
                };
                let typed = self.place(&base)?;
                let pointer = self.pointer_to(&typed)?;
                Ok(Some((owner, property, pointer)))
            }
            _ => Ok(None),
        }
    }

    /// Calls the getter: the property's value.
    pub(crate) fn property_get(
        &mut self,
        owner: &'p Pou,
        property: &'p Property,
        instance: Operand,
    ) -> Gen<(Operand, Type)> {
        let accessor = property
            .get
            .as_ref()
            .ok_or_else(|| fail!("the property '{}' has no GET", property.name))?;
        let index = self
            .build
            .pou_index(&owner.name, Some(&accessor_name(&property.name, true)))?;
        let frame = self
            .build
            .frame_of(owner, &accessor.variables, Some(&property.ty))?;
        let result = frame.result.ok_or("a property without a value")?;
        let dst = self.temp(result.lay.size);
        self.emit(Instr::CallFunction {
            pou: index,
            instance: Some(instance),
            inputs: Vec::new(),
            outputs: vec![Transfer {
                caller: dst,
                callee_offset: result.offset,
                size: result.lay.size,
            }],
        });
        Ok((dst, result.ty))
    }

    /// Calls the setter with the value of `value`.
    pub(crate) fn property_set(
        &mut self,
        owner: &'p Pou,
        property: &'p Property,
        instance: Operand,
        value: &Expr,
    ) -> Gen<()> {
        let accessor = property
            .set
            .as_ref()
            .ok_or_else(|| fail!("the property '{}' has no SET", property.name))?;
        let index = self
            .build
            .pou_index(&owner.name, Some(&accessor_name(&property.name, false)))?;
        let frame = self
            .build
            .frame_of(owner, &accessor.variables, Some(&property.ty))?;
        let slot = frame.result.ok_or("a property without a value")?;
        let operand = self.expr_as(value, &slot.ty)?;
        self.emit(Instr::CallFunction {
            pou: index,
            instance: Some(instance),
            inputs: vec![Transfer {
                caller: operand,
                callee_offset: slot.offset,
                size: slot.lay.size,
            }],
            outputs: Vec::new(),
        });
        Ok(())
    }
}
