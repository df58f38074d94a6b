//! The image's optional `debug` section (`docs/program-image.md` §3, section 13) for one
//! compiled POU: the variables of its frame, by name, type and offset, and the hash of its
//! source, so the debugger can show a frame and online change can tell changed POUs.

use program_image::{FrameVariable, FrameVariableKind, PouDebug, source_hash};
use project_model::{Pou, TextTarget, VarSection};

use super::body::{Frame, Gen};
use super::program::Build;
use crate::sema::body::has_open_bounds;
use crate::sema::ty::Type;

impl<'p> Build<'_, 'p> {
    /// The debug entry of a POU (or member) named `name` whose frame is `frame`, compiled from
    /// `body_text` (empty without a textual body).
    pub(crate) fn pou_debug(
        &mut self,
        pou: &'p Pou,
        target: &TextTarget,
        name: &str,
        frame: &Frame<'p>,
        body_text: &str,
    ) -> Gen<PouDebug> {
        let mut variables = Vec::with_capacity(frame.vars.len() + 1);
        for (variable, slot) in &frame.vars {
            // A VAR_IN_OUT holds a pointer; the debugger wants the type it points to, except
            // for an open array (ARRAY[*]), which has no layout of its own: its slot's type,
            // the descriptor with the bounds, is what the frame holds.
            let ty = match (&slot.ty, slot.by_ref) {
                (Type::Reference(pointee), true) if !has_open_bounds(pointee) => {
                    self.layouts.of(pointee)?.id
                }
                _ => slot.lay.id,
            };
            let kind = match variable.section {
                VarSection::VarInput => FrameVariableKind::Input,
                VarSection::VarOutput => FrameVariableKind::Output,
                VarSection::VarInOut => FrameVariableKind::InOut,
                VarSection::VarTemp => FrameVariableKind::Temp,
                _ => FrameVariableKind::Var,
            };
            variables.push(FrameVariable {
                name: variable.name.clone(),
                ty,
                offset: slot.offset,
                kind,
            });
        }
        if let Some(result) = &frame.result {
            // The result is named as the function, method or property that returns it.
            let short = name.rsplit('.').next().unwrap_or(name);
            variables.push(FrameVariable {
                name: short.to_owned(),
                ty: result.lay.id,
                offset: result.offset,
                kind: FrameVariableKind::Result,
            });
        }
        // Frame order: parameters, the result, then the other variables.
        variables.sort_by_key(|variable| variable.offset);
        let declaration = pou.declaration_text();
        let member_declaration = match target {
            TextTarget::Method { method, .. } => pou
                .methods
                .iter()
                .find(|m| &m.name == method)
                .map(|m| m.declaration_text()),
            TextTarget::Property { property, .. } => pou
                .properties
                .iter()
                .find(|p| &p.name == property)
                .map(|p| p.declaration_text()),
            _ => None,
        }
        .unwrap_or_default();
        Ok(PouDebug {
            source_hash: source_hash(&[name, &declaration, &member_declaration, body_text]),
            frame: variables,
        })
    }
}

#[cfg(test)]
#[path = "debug_info_tests.rs"]
mod tests;
