//! Memory layouts: the size, alignment and image type of every type a program uses, and the
//! instance layout of every program and function block.

use std::collections::HashMap;
use std::rc::Rc;

use program_image::{
    Elementary as IE, Located, Member as ImageMember, Region, StdBlock, StructKind, SymbolFlags,
    TypeDef, TypeId, std_blocks,
};
use project_model::{DataType, Pou, PouKind, TypeDefinition, VarSection, Variable};

use super::body::Gen;
use super::error::{Within, fail};
use crate::elementary::Elementary;
use crate::sema::address::{self, Area};
use crate::sema::resolve_local_type;
use crate::sema::scope::{Globals, inheritance_chain};
use crate::sema::ty::Type;
use crate::sema::types::Shape;

/// How a value of some type is laid out.
#[derive(Clone, Debug)]
pub(crate) struct Lay {
    pub(crate) size: u32,
    pub(crate) align: u32,
    pub(crate) id: TypeId,
    pub(crate) shape: LayShape,
}

/// What a laid-out type is, as code generation needs to know.
#[derive(Clone, Debug)]
pub(crate) enum LayShape {
    /// An elementary value the instructions work on.
    Scalar(IE),
    /// An enumeration, stored as its base type.
    Enum(IE),
    /// `STRING(length)` or `WSTRING(length)`.
    Text { wide: bool, length: u32 },
    /// An array.
    Array {
        element: Box<Lay>,
        element_ty: Type,
        dims: Vec<(i64, i64)>,
    },
    /// A structure or union of the project.
    Struct(String),
    /// An instance of a program or function block of the project.
    Pou(String),
    /// An instance of a standard function block.
    Std(StdBlock, bool),
    /// A pointer or reference (8 bytes).
    Pointer,
    /// An interface value (16 bytes: a pointer to the instance and its class).
    Interface,
    /// The descriptor of a VAR_IN_OUT array with open bounds: pointer, then bounds.
    OpenArray {
        element: Box<Lay>,
        element_ty: Type,
        rank: u32,
    },
}

/// A member of a structure.
#[derive(Clone, Debug)]
pub(crate) struct Field<'p> {
    pub(crate) name: String,
    pub(crate) offset: u32,
    pub(crate) lay: Lay,
    pub(crate) initial: Option<&'p str>,
}

/// A variable stored in an instance, or located in an area.
#[derive(Clone, Debug)]
pub(crate) struct Slot<'p> {
    pub(crate) var: &'p Variable,
    /// Byte offset in the instance (meaningless for a located variable).
    pub(crate) offset: u32,
    /// The declared type (a reference stays a reference).
    pub(crate) ty: Type,
    pub(crate) lay: Lay,
    /// Where a located variable lives.
    pub(crate) located: Option<Located>,
    /// A VAR_IN_OUT: the slot holds a pointer to the caller's variable.
    pub(crate) by_ref: bool,
}

/// The layout of a program's or function block's instance.
#[derive(Debug)]
pub(crate) struct Instance<'p> {
    pub(crate) size: u32,
    pub(crate) align: u32,
    pub(crate) id: TypeId,
    pub(crate) slots: Vec<Slot<'p>>,
    /// The index in `slots` of each variable by its lower-case name (the first one declared
    /// when a name repeats), so looking a name up does not walk every slot: a lowered LD body
    /// declares thousands of hidden variables.
    by_name: HashMap<String, usize>,
    /// The state of the chart when the body is textual SFC, after the variables.
    pub(crate) sfc: Option<super::sfc::SfcLayout>,
}

impl<'p> Instance<'p> {
    /// The slot of variable `name` (any case).
    pub(crate) fn slot(&self, name: &str) -> Option<&Slot<'p>> {
        let index = self.by_name.get(&name.to_ascii_lowercase())?;
        self.slots.get(*index)
    }
}

/// The image type of a checker elementary type; the strings are not elementary in the image.
pub(crate) fn image_elementary(e: Elementary) -> Option<IE> {
    e.image()
}

/// The element type and rank of an array whose bounds are all open (`ARRAY[*, *] OF T`).
pub(crate) fn open_array(ty: &Type) -> Option<(&Type, u32)> {
    match ty {
        Type::Array { element, dims } if !dims.is_empty() && dims.iter().all(Option::is_none) => {
            Some((element, dims.len() as u32))
        }
        _ => None,
    }
}

/// Whether variables of this section live in the instance.
pub(crate) fn in_instance(section: VarSection) -> bool {
    matches!(
        section,
        VarSection::VarInput
            | VarSection::VarOutput
            | VarSection::VarInOut
            | VarSection::Var
            | VarSection::VarInst
    )
}

/// The symbol flags of a variable.
pub(crate) fn flags_of(var: &Variable) -> u16 {
    let mut flags = match var.section {
        VarSection::VarInput => SymbolFlags::INPUT,
        VarSection::VarOutput => SymbolFlags::OUTPUT,
        VarSection::VarInOut => SymbolFlags::IN_OUT,
        VarSection::VarGlobal => SymbolFlags::GLOBAL,
        _ => 0,
    };
    if var.constant {
        flags |= SymbolFlags::CONSTANT;
    }
    if var.retain {
        flags |= SymbolFlags::RETAIN;
    }
    if var.persistent {
        flags |= SymbolFlags::PERSISTENT;
    }
    flags
}

/// Where a variable's `AT` address puts it, if it has one the compiler places.
pub(crate) fn located_of(var: &Variable) -> Option<Located> {
    let address = address::parse_address(var.address.as_deref()?).ok()??;
    Some(Located {
        region: match address.area {
            Area::Input => Region::Input,
            Area::Output => Region::Output,
            Area::Memory => Region::Memory,
        },
        bit_offset: address.first_bit,
        size_bits: address.size_bits,
    })
}

/// The layouts of one build.
pub(crate) struct Layouts<'g, 'p> {
    pub(crate) globals: &'g Globals<'p>,
    /// The image's type table, filled as types are laid out.
    pub(crate) types: Vec<TypeDef>,
    cache: HashMap<String, Lay>,
    instances: HashMap<String, Rc<Instance<'p>>>,
    building: Vec<String>,
}

impl<'g, 'p> Layouts<'g, 'p> {
    pub(crate) fn new(globals: &'g Globals<'p>) -> Self {
        Self {
            globals,
            types: Vec::new(),
            cache: HashMap::new(),
            instances: HashMap::new(),
            building: Vec::new(),
        }
    }

    fn add(&mut self, def: TypeDef) -> TypeId {
        if let Some(at) = self.types.iter().position(|known| *known == def) {
            return at as TypeId;
        }
        self.types.push(def);
        (self.types.len() - 1) as TypeId
    }

    /// The layout of the type written as `text`.
    pub(crate) fn of_text(&mut self, text: &str) -> Gen<Lay> {
        let ty = self.globals.resolve_type(text);
        self.of(&ty)
    }

    /// The layout of `ty`.
    pub(crate) fn of(&mut self, ty: &Type) -> Gen<Lay> {
        let key = match ty {
            Type::Named(name) => format!("named {}", name.to_lowercase()),
            other => format!("{other:?}"),
        };
        if let Some(known) = self.cache.get(&key) {
            return Ok(known.clone());
        }
        let lay = self.compute(ty)?;
        self.cache.insert(key, lay.clone());
        Ok(lay)
    }

    fn scalar(&mut self, e: IE) -> Lay {
        let size = e.size_bytes();
        Lay {
            size,
            align: size,
            id: self.add(TypeDef::Elementary(e)),
            shape: LayShape::Scalar(e),
        }
    }

    fn compute(&mut self, ty: &Type) -> Gen<Lay> {
        match ty {
            Type::Elementary(e) | Type::Subrange { base: e, .. } => match image_elementary(*e) {
                Some(ie) => Ok(self.scalar(ie)),
                None => self.compute(&Type::elementary(*e)),
            },
            Type::String { wide, length } => {
                let (size, align, def) = if *wide {
                    (2 * (length + 1), 2, TypeDef::WString { length: *length })
                } else {
                    (length + 1, 1, TypeDef::String { length: *length })
                };
                Ok(Lay {
                    size,
                    align,
                    id: self.add(def),
                    shape: LayShape::Text {
                        wide: *wide,
                        length: *length,
                    },
                })
            }
            Type::Array { element, dims } => {
                let element_lay = self.of(element)?;
                let mut count: u64 = 1;
                let mut bounds = Vec::new();
                for dim in dims {
                    let Some((low, high)) = dim else {
                        // The checker refuses open bounds anywhere but a VAR_IN_OUT parameter
                        // (E0133), which is laid out as a reference, never through here.
                        return Err(
                            "an array with open bounds (ARRAY[*]) has no size of its own; only a VAR_IN_OUT parameter can be one (E0133)".into()
                        );
                    };
                    let (low, high) = (
                        i64::try_from(*low).map_err(|_| "array bound out of range")?,
                        i64::try_from(*high).map_err(|_| "array bound out of range")?,
                    );
                    if high < low {
                        return Err(fail!("the array bounds {low}..{high} are empty"));
                    }
                    count = count.saturating_mul(high.abs_diff(low).saturating_add(1));
                    bounds.push((low, high));
                }
                let size = count.saturating_mul(u64::from(element_lay.size));
                let size = u32::try_from(size)
                    .ok()
                    .filter(|s| *s <= program_image::MAX_REGION_BYTES)
                    .ok_or("the array is larger than a memory region")?;
                let id = self.add(TypeDef::Array {
                    element: element_lay.id,
                    dims: bounds.clone(),
                });
                Ok(Lay {
                    size,
                    align: element_lay.align,
                    id,
                    shape: LayShape::Array {
                        element: Box::new(element_lay),
                        element_ty: (**element).clone(),
                        dims: bounds,
                    },
                })
            }
            Type::Reference(target) if open_array(target).is_some() => {
                let (element, rank) = open_array(target).ok_or("an open array")?;
                let element_lay = self.of(element)?;
                Ok(Lay {
                    size: 8 + 16 * rank,
                    align: 8,
                    id: self.add(TypeDef::OpenArray {
                        element: element_lay.id,
                        rank,
                    }),
                    shape: LayShape::OpenArray {
                        element: Box::new(element_lay),
                        element_ty: element.clone(),
                        rank,
                    },
                })
            }
            Type::Pointer(_) | Type::Reference(_) => {
                // Pointer targets are not laid out: a structure may point to itself.
                Ok(Lay {
                    size: 8,
                    align: 8,
                    id: self.add(TypeDef::Pointer {
                        target: None,
                        reference: matches!(ty, Type::Reference(_)),
                    }),
                    shape: LayShape::Pointer,
                })
            }
            Type::Named(name) => self.named(name),
            other => Err(fail!("values of type {other} cannot be stored")),
        }
    }

    fn named(&mut self, name: &str) -> Gen<Lay> {
        if let Some(data_type) = self.globals.data_type(name)
            && let TypeDefinition::Alias { ty, .. } = &data_type.definition
        {
            if self.building.iter().any(|b| b.eq_ignore_ascii_case(name)) {
                return Err(fail!("the type '{name}' is defined in terms of itself"));
            }
            self.building.push(name.to_owned());
            let lay = self.of_text(ty);
            self.building.pop();
            return lay;
        }
        match self.globals.shape(name) {
            Some(Shape::Enum(data_type)) => {
                let base = match &data_type.definition {
                    TypeDefinition::Enum {
                        base: Some(base), ..
                    } => self
                        .globals
                        .resolve_type(base)
                        .as_elementary()
                        .and_then(image_elementary),
                    _ => Some(IE::Int),
                }
                .ok_or_else(|| fail!("the enumeration '{name}' needs an integer base type"))?;
                let values = self.enum_values(data_type);
                let size = base.size_bytes();
                Ok(Lay {
                    size,
                    align: size,
                    id: self.add(TypeDef::Enum {
                        name: data_type.name.clone(),
                        base,
                        values,
                    }),
                    shape: LayShape::Enum(base),
                })
            }
            Some(Shape::Struct(data_type)) => {
                let fields = self.fields(data_type)?;
                let align = fields.iter().map(|f| f.lay.align).max().unwrap_or(1);
                let end = fields
                    .iter()
                    .map(|f| f.offset + f.lay.size)
                    .max()
                    .unwrap_or(0);
                let size = end.next_multiple_of(align);
                let members = fields
                    .iter()
                    .map(|f| ImageMember {
                        name: f.name.clone(),
                        ty: f.lay.id,
                        offset: f.offset,
                        located: None,
                        flags: 0,
                    })
                    .collect();
                Ok(Lay {
                    size,
                    align,
                    id: self.add(TypeDef::Struct {
                        name: data_type.name.clone(),
                        kind: StructKind::Struct,
                        size,
                        members,
                    }),
                    shape: LayShape::Struct(data_type.name.clone()),
                })
            }
            Some(Shape::Pou(pou)) if pou.kind == PouKind::Interface => Ok(Lay {
                size: 16,
                align: 8,
                id: self.add(TypeDef::Interface {
                    name: pou.name.clone(),
                }),
                shape: LayShape::Interface,
            }),
            Some(Shape::Pou(pou))
                if matches!(pou.kind, PouKind::FunctionBlock | PouKind::Program) =>
            {
                let instance = self.instance(pou)?;
                Ok(Lay {
                    size: instance.size,
                    align: instance.align,
                    id: instance.id,
                    shape: LayShape::Pou(pou.name.clone()),
                })
            }
            Some(Shape::StandardFb(_)) => {
                // Every standard block the checker knows has a native layout; the test
                // `tests/tests/standard_library` runs each one, so this is an internal error.
                let (block, long) = StdBlock::from_name(name).ok_or_else(|| {
                    format!(
                        "internal error: the standard function block '{name}' has no native layout"
                    )
                })?;
                let shape = std_blocks::layout(block, long);
                let mut members = Vec::new();
                for member in &shape.members {
                    let id = self.scalar(member.ty).id;
                    members.push(ImageMember {
                        name: member.name.to_owned(),
                        ty: id,
                        offset: member.offset,
                        located: None,
                        flags: if member.input {
                            SymbolFlags::INPUT
                        } else {
                            SymbolFlags::OUTPUT
                        },
                    });
                }
                let align = shape
                    .members
                    .iter()
                    .map(|m| m.ty.size_bytes())
                    .max()
                    .unwrap_or(1);
                Ok(Lay {
                    size: shape.size,
                    align,
                    id: self.add(TypeDef::Struct {
                        name: name.to_ascii_uppercase(),
                        kind: StructKind::FunctionBlock,
                        size: shape.size,
                        members,
                    }),
                    shape: LayShape::Std(block, long),
                })
            }
            _ => Err(fail!("values of type '{name}' cannot be stored")),
        }
    }

    fn enum_values(&self, data_type: &DataType) -> Vec<(String, i64)> {
        let TypeDefinition::Enum { values, .. } = &data_type.definition else {
            return Vec::new();
        };
        values
            .iter()
            .filter_map(|value| {
                let number = self
                    .globals
                    .enum_value(data_type, &value.name, 0)?
                    .as_int()?;
                Some((value.name.clone(), i64::try_from(number).ok()?))
            })
            .collect()
    }

    /// The members of a structure (base members first) or union (all at offset 0).
    pub(crate) fn fields(&mut self, data_type: &'p DataType) -> Gen<Vec<Field<'p>>> {
        let mut chain = vec![data_type];
        let mut current = data_type;
        while let TypeDefinition::Struct {
            extends: Some(base),
            ..
        } = &current.definition
        {
            let Some(base) = self.globals.data_type(base) else {
                break;
            };
            if chain.len() > 32 || chain.iter().any(|seen| std::ptr::eq(*seen, base)) {
                return Err(fail!("the structure '{}' extends itself", data_type.name));
            }
            chain.push(base);
            current = base;
        }
        if self
            .building
            .iter()
            .any(|b| b.eq_ignore_ascii_case(&data_type.name))
        {
            return Err(fail!("the structure '{}' contains itself", data_type.name));
        }
        self.building.push(data_type.name.clone());
        let mut fields = Vec::new();
        let mut offset = 0u32;
        let mut result = Ok(());
        for current in chain.iter().rev() {
            let (members, union) = match &current.definition {
                TypeDefinition::Struct { members, .. } => (members, false),
                TypeDefinition::Union { members } => (members, true),
                _ => continue,
            };
            for member in members {
                let ty = self.globals.resolve_type(&member.ty);
                let lay = match self.of(&ty) {
                    Ok(lay) => lay,
                    Err(error) => {
                        result = Err(error.within(Within::Declaration(format!(
                            "{}.{}",
                            current.name, member.name
                        ))));
                        break;
                    }
                };
                let at = if union {
                    0
                } else {
                    offset.next_multiple_of(lay.align)
                };
                offset = if union {
                    offset.max(lay.size)
                } else {
                    at + lay.size
                };
                fields.push(Field {
                    name: member.name.clone(),
                    offset: at,
                    lay,
                    initial: member.initial.as_deref(),
                });
            }
        }
        self.building.pop();
        result.map(|()| fields)
    }

    /// The instance layout of a program or function block (inherited variables first).
    pub(crate) fn instance(&mut self, pou: &'p Pou) -> Gen<Rc<Instance<'p>>> {
        let key = pou.name.to_lowercase();
        if let Some(known) = self.instances.get(&key) {
            return Ok(known.clone());
        }
        if self
            .building
            .iter()
            .any(|b| b.eq_ignore_ascii_case(&pou.name))
        {
            return Err(fail!("'{}' contains an instance of itself", pou.name));
        }
        self.building.push(pou.name.clone());
        let result = self.build_instance(pou);
        self.building.pop();
        let instance = Rc::new(result?);
        self.instances.insert(key, instance.clone());
        Ok(instance)
    }

    fn build_instance(&mut self, pou: &'p Pou) -> Gen<Instance<'p>> {
        let mut chain = inheritance_chain(self.globals, pou);
        chain.reverse();
        // Array bounds may name constants of the POU or its bases.
        let locals: Vec<&Variable> = chain.iter().flat_map(|p| &p.variables).collect();
        let mut slots = Vec::new();
        let mut offset = 0u32;
        let mut align = 1u32;
        for current in chain {
            for var in &current.variables {
                if !in_instance(var.section) {
                    continue;
                }
                let by_ref = var.section == VarSection::VarInOut;
                let declared = resolve_local_type(self.globals, &locals, &var.ty);
                let ty = if by_ref {
                    Type::Reference(Box::new(declared))
                } else {
                    declared
                };
                let lay = self.of(&ty).map_err(|error| {
                    error.within(Within::Declaration(format!(
                        "{}.{}",
                        current.name, var.name
                    )))
                })?;
                let located = located_of(var);
                let at = if located.is_some() {
                    0
                } else {
                    let at = offset.next_multiple_of(lay.align);
                    offset = at + lay.size;
                    align = align.max(lay.align);
                    at
                };
                slots.push(Slot {
                    var,
                    offset: at,
                    ty,
                    lay,
                    located,
                    by_ref,
                });
            }
        }
        let sfc = match pou
            .body
            .st_text()
            .and_then(|text| super::sfc::SfcLayout::of_body(text, offset))
        {
            Some((sfc, end)) => {
                offset = end;
                align = align.max(8);
                Some(sfc)
            }
            None => None,
        };
        // An empty instance still has a size, so two instances never share an address.
        let size = offset.max(1).next_multiple_of(align);
        let members = slots
            .iter()
            .map(|slot| ImageMember {
                name: slot.var.name.clone(),
                ty: slot.lay.id,
                offset: slot.offset,
                located: slot.located,
                flags: flags_of(slot.var),
            })
            .collect();
        let id = self.add(TypeDef::Struct {
            name: pou.name.clone(),
            kind: if pou.kind == PouKind::Program {
                StructKind::Program
            } else {
                StructKind::FunctionBlock
            },
            size,
            members,
        });
        let mut by_name = HashMap::with_capacity(slots.len());
        for (index, slot) in slots.iter().enumerate() {
            by_name
                .entry(slot.var.name.to_ascii_lowercase())
                .or_insert(index);
        }
        Ok(Instance {
            size,
            align,
            id,
            slots,
            by_name,
            sfc,
        })
    }
}
