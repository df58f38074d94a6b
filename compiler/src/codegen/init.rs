//! Initial values: the bytes of a variable, structure or instance after a cold start, from the
//! types' defaults and the initialisers written in declarations.

use program_image::TypeDef;

use super::body::Gen;
use super::constant::{Value, evaluate_node, raw_of, text_bytes};
use super::error::{Within, fail};
use super::layout::{Lay, LayShape, Layouts};
use crate::syntax::ast::{AstNode, Expr, InitValue, Initializer};
use crate::syntax::parse_declaration_part;

impl Layouts<'_, '_> {
    /// The bytes of a value of layout `lay` initialised with `initial` (the text after `:=`),
    /// or with the type's default.
    pub(crate) fn initial_bytes(&mut self, lay: &Lay, initial: Option<&str>) -> Gen<Vec<u8>> {
        let mut bytes = self.default_bytes(lay)?;
        if let Some(text) = initial {
            let parse = parse_declaration_part(&format!("VAR __v : INT := {text}; END_VAR"));
            let value = parse
                .syntax()
                .descendants()
                .find_map(Initializer::cast)
                .and_then(|initializer| initializer.value())
                .ok_or_else(|| fail!("the initial value '{text}' is not an expression"))?;
            self.apply(&mut bytes, lay, &value)?;
        }
        Ok(bytes)
    }

    /// The default bytes of a type: zeros, the first value of an enumeration, and the
    /// initialisers of structure members and function block variables.
    pub(crate) fn default_bytes(&mut self, lay: &Lay) -> Gen<Vec<u8>> {
        let mut bytes = vec![0u8; lay.size as usize];
        match &lay.shape {
            LayShape::Enum(base) => {
                if let Some(TypeDef::Enum { values, .. }) = self.types.get(lay.id as usize)
                    && let Some((_, first)) = values.first()
                    && let Some(raw) = raw_of(&Value::Int(i128::from(*first)), *base)
                {
                    bytes.copy_from_slice(&raw.to_le_bytes()[..lay.size as usize]);
                }
            }
            LayShape::Array { element, .. } => {
                let one = self.default_bytes(element)?;
                if one.iter().any(|b| *b != 0) {
                    for chunk in bytes.chunks_mut(one.len().max(1)) {
                        chunk.copy_from_slice(&one[..chunk.len()]);
                    }
                }
            }
            LayShape::Struct(name) => {
                let Some(data_type) = self.globals.data_type(name) else {
                    return Ok(bytes);
                };
                for field in self.fields(data_type)? {
                    let value = self.initial_bytes(&field.lay, field.initial)?;
                    put(&mut bytes, field.offset, &value);
                }
            }
            LayShape::Pou(name) => {
                let Some(pou) = self.globals.pou(name) else {
                    return Ok(bytes);
                };
                let instance = self.instance(pou)?;
                for slot in &instance.slots {
                    if slot.located.is_some() || slot.by_ref {
                        continue;
                    }
                    let value = self
                        .initial_bytes(&slot.lay, slot.var.initial.as_deref())
                        .map_err(|error| {
                            error.within(Within::Declaration(format!(
                                "{}.{}",
                                pou.name, slot.var.name
                            )))
                        })?;
                    put(&mut bytes, slot.offset, &value);
                }
            }
            _ => {}
        }
        Ok(bytes)
    }

    fn apply(&mut self, bytes: &mut [u8], lay: &Lay, node: &InitValue) -> Gen<()> {
        match (node, &lay.shape) {
            (InitValue::Expr(Expr::ArrayInit(array)), LayShape::Array { element, .. }) => {
                let size = element.size as usize;
                let count = bytes.len() / size.max(1);
                let mut index = 0usize;
                for child in array.elements() {
                    let (repeat, value) = match child {
                        InitValue::Repeat(repeated) => {
                            (repeated.count().unwrap_or(0), repeated.value())
                        }
                        other => (1, Some(other)),
                    };
                    for _ in 0..repeat {
                        if index >= count {
                            return Err(fail!("the initialiser has more than {count} elements"));
                        }
                        let place = &mut bytes[index * size..(index + 1) * size];
                        match &value {
                            Some(value) => self.apply(place, element, value)?,
                            None => place.copy_from_slice(&self.default_bytes(element)?),
                        }
                        index += 1;
                    }
                }
                Ok(())
            }
            (InitValue::Struct(structure), LayShape::Struct(_) | LayShape::Pou(_)) => {
                for field in structure.fields() {
                    let name = field.name().map(|name| name.text()).unwrap_or_default();
                    let Some(value) = field.value() else {
                        continue;
                    };
                    let (offset, member) = self.member_of(lay, &name)?;
                    let end = offset as usize + member.size as usize;
                    let place = bytes
                        .get_mut(offset as usize..end)
                        .ok_or("a member lies outside its structure")?;
                    self.apply(place, &member, &value)?;
                }
                Ok(())
            }
            _ => {
                let value = match node {
                    InitValue::Expr(expr) => evaluate_node(expr, self.globals),
                    InitValue::Struct(_) | InitValue::Repeat(_) => None,
                };
                let value = value.ok_or_else(|| {
                    format!(
                        "'{}' is not a constant value",
                        node.syntax().text().to_string().trim()
                    )
                })?;
                let written = match (&lay.shape, &value) {
                    (LayShape::Scalar(e) | LayShape::Enum(e), _) => raw_of(&value, *e)
                        .map(|raw| raw.to_le_bytes()[..e.size_bytes() as usize].to_vec()),
                    (LayShape::Text { wide, length }, Value::Text(chars)) => {
                        Some(text_bytes(chars, *wide, *length))
                    }
                    _ => None,
                };
                let written = written.ok_or_else(|| {
                    format!(
                        "'{}' is not a value of this type",
                        node.syntax().text().to_string().trim()
                    )
                })?;
                put(bytes, 0, &written);
                Ok(())
            }
        }
    }

    /// The offset and layout of member `name` of a structure or instance.
    pub(crate) fn member_of(&mut self, lay: &Lay, name: &str) -> Gen<(u32, Lay)> {
        match &lay.shape {
            LayShape::Struct(type_name) => {
                let data_type = self
                    .globals
                    .data_type(type_name)
                    .ok_or("unknown structure")?;
                let fields = self.fields(data_type)?;
                let field = fields
                    .into_iter()
                    .find(|f| f.name.eq_ignore_ascii_case(name))
                    .ok_or_else(|| fail!("'{type_name}' has no member '{name}'"))?;
                Ok((field.offset, field.lay))
            }
            LayShape::Pou(pou_name) => {
                let pou = self.globals.pou(pou_name).ok_or("unknown function block")?;
                let instance = self.instance(pou)?;
                let slot = instance
                    .slot(name)
                    .ok_or_else(|| fail!("'{pou_name}' has no variable '{name}'"))?;
                Ok((slot.offset, slot.lay.clone()))
            }
            LayShape::Std(block, long) => {
                let shape = program_image::std_blocks::layout(*block, *long);
                let member = shape
                    .member(name)
                    .ok_or_else(|| fail!("the standard function block has no member '{name}'"))?;
                let (offset, ty) = (member.offset, member.ty);
                let lay = self.of(&crate::sema::ty::Type::Elementary(elementary_of(ty)))?;
                Ok((offset, lay))
            }
            _ => Err(fail!("'{name}' is not a member of a structure")),
        }
    }
}

/// The checker's elementary type of an image elementary type.
pub(crate) fn elementary_of(ty: program_image::Elementary) -> crate::elementary::Elementary {
    crate::elementary::Elementary::of_image(ty)
}

fn put(bytes: &mut [u8], offset: u32, value: &[u8]) {
    let start = offset as usize;
    if let Some(place) = bytes.get_mut(start..start + value.len()) {
        place.copy_from_slice(value);
    }
}
