//! Reading variable declarations off the typed syntax layer: what `SourceProject` (a whole
//! source file as a project) and `ide::parse_declarations` (a declaration part typed in the
//! editor) both need.

use project_model::{AccessSpecifier, VarSection};

use crate::syntax::SyntaxKind;
use crate::syntax::ast::{AstNode, Name, VarBlock, VarDecl};

/// The section a `VAR… END_VAR` block declares, by its keyword; `None` for access paths
/// (`VAR_ACCESS`), which declare nothing of their own.
pub(crate) fn block_section(block: &VarBlock) -> Option<VarSection> {
    Some(match block.keyword()?.kind() {
        SyntaxKind::VAR_INPUT => VarSection::VarInput,
        SyntaxKind::VAR_OUTPUT => VarSection::VarOutput,
        SyntaxKind::VAR_IN_OUT => VarSection::VarInOut,
        SyntaxKind::VAR_GLOBAL => VarSection::VarGlobal,
        SyntaxKind::VAR_EXTERNAL => VarSection::VarExternal,
        SyntaxKind::VAR_TEMP => VarSection::VarTemp,
        SyntaxKind::VAR_STAT => VarSection::VarStat,
        SyntaxKind::VAR_INST => VarSection::VarInst,
        SyntaxKind::VAR_CONFIG => VarSection::VarConfig,
        SyntaxKind::VAR => VarSection::Var,
        _ => return None,
    })
}

/// One declaration `a, b AT %IX0.0 : BOOL := TRUE;` taken apart.
pub(crate) struct DeclarationParts {
    /// The declared names, in order.
    pub names: Vec<Name>,
    /// The type as written.
    pub ty: String,
    /// The direct address, if located.
    pub address: Option<String>,
    /// The initial value as written.
    pub initial: Option<String>,
}

/// Takes a declaration apart; `None` when it has no names. `trim` turns a node into its text
/// (each caller keeps its own idea of which trivia belongs to a node).
pub(crate) fn declaration_parts(
    declaration: &VarDecl,
    trim: impl Fn(&crate::syntax::SyntaxNode) -> String,
) -> Option<DeclarationParts> {
    let names: Vec<Name> = declaration.name_list()?.names().collect();
    let ty = declaration
        .ty()
        .map(|ty| trim(ty.syntax()))
        .unwrap_or_default();
    let address = declaration
        .address()
        .and_then(|address| address.address())
        .map(|token| token.text().to_owned());
    let initial = declaration
        .initializer()
        .and_then(|initializer| initializer.value())
        .map(|value| trim(value.syntax()));
    Some(DeclarationParts {
        names,
        ty,
        address,
        initial,
    })
}

/// The access specifier among the `modifiers` written on a method or property (`PUBLIC` when
/// none is).
pub(crate) fn access_of(modifiers: impl Iterator<Item = SyntaxKind>) -> AccessSpecifier {
    let modifiers: Vec<SyntaxKind> = modifiers.collect();
    if modifiers.contains(&SyntaxKind::PRIVATE) {
        AccessSpecifier::Private
    } else if modifiers.contains(&SyntaxKind::PROTECTED) {
        AccessSpecifier::Protected
    } else if modifiers.contains(&SyntaxKind::INTERNAL) {
        AccessSpecifier::Internal
    } else {
        AccessSpecifier::Public
    }
}
