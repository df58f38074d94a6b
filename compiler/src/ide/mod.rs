//! The IDE facade: what editors ask the compiler, answered with plain structs (byte ranges,
//! names, kinds). Syntax trees never cross this boundary.
//!
//! From the syntax of one text: diagnostics, the document outline, semantic token classes and
//! folding ranges. From the project: hover, go to definition, find references, completion
//! candidates and the diagnostics of one POU ([`semantic`]). For the declaration table and the
//! I/O mapping: direct addresses checked against their types, overlapping located variables, and
//! declaration text read back into variables. For the Modbus device editor: a device as the build
//! defines it and the requests of its round ([`modbus_round_requests`]).

mod addresses;
mod blocks;
mod declarations;
mod folding;
mod modbus_round;
mod outline;
pub mod semantic;
mod semantic_tokens;
mod unplaceable;
pub(crate) mod variable_type;

use std::ops::Range;

pub use crate::codegen::modbus_device_def::value_type as modbus_value_type;
pub use crate::sema::address::AddressError;
pub use addresses::{
    AddressArea, AddressCheckError, AddressInfo, LocatedVariable, Overlap, address_info,
    check_address, located_overlaps, located_variables,
};
pub use blocks::{
    BlockPins, block_completions, block_pins, operand_completions, structure_members,
};
pub use declarations::{
    DeclarationHeader, DeclarationKind, ParsedDeclarations, parse_declarations,
};
pub use folding::folding_ranges;
pub use modbus_round::{modbus_device_def, modbus_round_requests};
pub use outline::{OutlineItem, OutlineKind, outline};
pub use semantic::{
    Completion, Definition, DefinitionKind, Hover, MonitoredName, Reference, completions,
    definition, hover, monitor_paths, pou_diagnostics, references,
};
pub use semantic_tokens::{SemanticClass, SemanticToken, semantic_tokens};
pub use unplaceable::Unplaceable;
pub use variable_type::{
    ChannelBindingError, ChannelMisfit, ChannelVariableError, check_channel_binding,
    check_channel_variable, variable_type, variable_values,
};

use crate::Diagnostic;

/// The diagnostics of a source text holding whole POUs, types or variable lists.
pub fn diagnostics(text: &str) -> Vec<Diagnostic> {
    crate::syntax::parse(text).errors().to_vec()
}

/// The diagnostics of a POU body stored on its own (a project's `.st` file).
pub fn body_diagnostics(text: &str) -> Vec<Diagnostic> {
    crate::syntax::parse_statements(text).errors().to_vec()
}

/// A byte range of `node` without its leading and trailing trivia.
fn trimmed_range(node: &crate::syntax::SyntaxNode) -> Range<usize> {
    let significant = |token: &crate::syntax::SyntaxToken| {
        !token.kind().is_trivia() && token.kind() != crate::syntax::SyntaxKind::PRAGMA
    };
    let tokens: Vec<_> = node
        .descendants_with_tokens()
        .filter_map(|element| element.into_token())
        .filter(significant)
        .collect();
    match (tokens.first(), tokens.last()) {
        (Some(first), Some(last)) => {
            usize::from(first.text_range().start())..usize::from(last.text_range().end())
        }
        _ => {
            let range = node.text_range();
            usize::from(range.start())..usize::from(range.end())
        }
    }
}
