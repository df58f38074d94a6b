//! The reverse of resolving a path: the path of the instance at an address of the data region,
//! so a debugger can name the instance a breakpoint or a stack frame runs on (`Main.fbA`,
//! `Main.aFbs[2]`).

use crate::ProgramImage;
use crate::image::Region;
use crate::types::{StructKind, TypeDef, TypeId};

/// The region number of the data region in a pointer value (`docs/program-image.md` §5.2).
const DATA_POINTER_REGION: u64 = 1;

impl ProgramImage {
    /// The path of the function block or program instance whose first byte is the pointer
    /// value `instance` (region 1, data), found through the symbols and the type table.
    ///
    /// An instance at offset 0 of another has the same address; `owner` (the name of the
    /// function block or program the code belongs to, as its `TypeDef::Struct` is named)
    /// picks the right one, and without it the outermost is named. `None` for a pointer into
    /// another region or to no instance.
    pub fn instance_path(&self, instance: u64, owner: Option<&str>) -> Option<String> {
        if instance >> 56 != DATA_POINTER_REGION {
            return None;
        }
        let offset = instance & ((1 << 56) - 1);
        let mut candidates = Vec::new();
        for symbol in &self.symbols {
            if symbol.region != Region::Data || symbol.bit.is_some() {
                continue;
            }
            let start = u64::from(symbol.offset);
            let Some(ty) = self.types.get(symbol.ty as usize) else {
                continue;
            };
            if offset < start || offset >= start + ty.size_bytes(&self.types).max(1) {
                continue;
            }
            self.instances_at(
                symbol.path.clone(),
                symbol.ty,
                start,
                offset,
                &mut candidates,
                0,
            );
            if owner.is_none() && !candidates.is_empty() {
                break;
            }
        }
        let mut candidates = candidates.into_iter();
        match owner {
            Some(owner) => candidates
                .find(|(_, name)| name == owner)
                .map(|(path, _)| path),
            None => candidates.next().map(|(path, _)| path),
        }
    }

    /// Collects, outermost first, every instance (path and type name) of type `ty` at `base`
    /// or inside it that starts at `offset`. `depth` bounds the descent, as a hostile type
    /// table could be deep.
    fn instances_at(
        &self,
        path: String,
        ty: TypeId,
        base: u64,
        offset: u64,
        found: &mut Vec<(String, String)>,
        depth: usize,
    ) {
        if depth > 64 {
            return;
        }
        match self.types.get(ty as usize) {
            Some(TypeDef::Struct {
                name,
                kind,
                members,
                ..
            }) => {
                if base == offset && *kind != StructKind::Struct {
                    found.push((path.clone(), name.clone()));
                }
                for member in members {
                    if member.located.is_some() {
                        continue;
                    }
                    let start = base + u64::from(member.offset);
                    let size = self
                        .types
                        .get(member.ty as usize)
                        .map_or(0, |ty| ty.size_bytes(&self.types));
                    if start <= offset && offset < start + size.max(1) {
                        let inner = format!("{path}.{}", member.name);
                        self.instances_at(inner, member.ty, start, offset, found, depth + 1);
                    }
                }
            }
            Some(TypeDef::Array { element, dims }) => {
                let size = self
                    .types
                    .get(*element as usize)
                    .map_or(0, |ty| ty.size_bytes(&self.types));
                if size == 0 {
                    return;
                }
                let mut index = (offset - base) / size;
                let start = base + index * size;
                // The last index varies fastest.
                let mut subscripts = Vec::with_capacity(dims.len());
                for (low, high) in dims.iter().rev() {
                    let count = u64::try_from(high.saturating_sub(*low)).unwrap_or(0) + 1;
                    subscripts.push(low.saturating_add((index % count) as i64));
                    index /= count;
                }
                if index != 0 {
                    return;
                }
                subscripts.reverse();
                let list: Vec<String> = subscripts.iter().map(i64::to_string).collect();
                let inner = format!("{path}[{}]", list.join(", "));
                self.instances_at(inner, *element, start, offset, found, depth + 1);
            }
            _ => {}
        }
    }
}

#[cfg(test)]
#[path = "instance_path_tests.rs"]
mod tests;
