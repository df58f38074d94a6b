//! What names an element of a graphical body for the user: the variable a contact reads or a
//! coil writes, a box's instance or type, a jump's label. The debugger's panes show it beside
//! the network, so "network 1, xRunRequest" tells which coil a breakpoint is on without the
//! element's internal id.

use crate::{Body, CfcElementKind, ElementId, ElementRef, NetworkOutput, Pou};

impl Pou {
    /// The body named `member` after the POU's name, as `rivet check` names bodies: `""` for
    /// the POU's own body, `Reset` for a method, action or transition, `Speed.get` or
    /// `Speed.set` for a property's accessor.
    pub fn body_named(&self, member: &str) -> Option<&Body> {
        if member.is_empty() {
            return Some(&self.body);
        }
        if let Some((property, accessor)) = member.split_once('.') {
            let property = self
                .properties
                .iter()
                .find(|found| found.name == property)?;
            let accessor = match accessor {
                "get" => property.get.as_ref(),
                "set" => property.set.as_ref(),
                _ => None,
            };
            return accessor.map(|accessor| &accessor.body);
        }
        self.methods
            .iter()
            .find(|method| method.name == member)
            .map(|method| &method.body)
            .or_else(|| {
                self.actions
                    .iter()
                    .chain(&self.transitions)
                    .find(|action| action.name == member)
                    .map(|action| &action.body)
            })
    }
}

impl Body {
    /// The caption of element `id` of network `network` (0 in CFC): the operand of a contact
    /// or input, the variable of a coil or output, a box's instance (or its type when it has
    /// none), a jump's label, `RETURN`. `None` for elements that name nothing (a parallel
    /// group, an output branch, a comment) and for an element the body does not hold.
    pub fn element_caption(&self, network: usize, id: ElementId) -> Option<String> {
        match self {
            Self::Ld { networks } | Self::Fbd { networks } => {
                match networks.get(network)?.element(id)? {
                    ElementRef::Operand(operand) => Some(operand.text.clone()),
                    ElementRef::Block(block) => {
                        Some(box_caption(&block.instance, &block.type_name))
                    }
                    ElementRef::Output(NetworkOutput::Coil(coil)) => Some(coil.variable.clone()),
                    ElementRef::Output(NetworkOutput::Jump { label, .. }) => {
                        Some(format!("JMP {label}"))
                    }
                    ElementRef::Output(NetworkOutput::Return { .. }) => Some("RETURN".to_owned()),
                    ElementRef::Parallel(_) | ElementRef::Output(NetworkOutput::Branch { .. }) => {
                        None
                    }
                }
            }
            Self::Cfc { chart } => {
                let element = chart.elements.iter().find(|element| element.id == id)?;
                match &element.kind {
                    CfcElementKind::Input { expression }
                    | CfcElementKind::Output { expression, .. } => Some(expression.clone()),
                    CfcElementKind::Box(cfc_box) => {
                        Some(box_caption(&cfc_box.instance, &cfc_box.type_name))
                    }
                    CfcElementKind::Jump { label } => Some(format!("JMP {label}")),
                    CfcElementKind::Return => Some("RETURN".to_owned()),
                    _ => None,
                }
            }
            _ => None,
        }
    }
}

/// A box named by its instance (`tonStartWarning: TON`), or by its type alone (`ADD`).
fn box_caption(instance: &str, type_name: &str) -> String {
    if instance.is_empty() {
        type_name.to_owned()
    } else {
        format!("{instance}: {type_name}")
    }
}

#[cfg(test)]
#[path = "element_caption_tests.rs"]
mod tests;
