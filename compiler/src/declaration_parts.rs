//! Reading variable declarations off the syntax tree: what `SourceProject` (a whole source
//! file as a project) and `ide::parse_declarations` (a declaration part typed in the editor)
//! both need.

use project_model::{AccessSpecifier, VarSection};

use crate::syntax::ast::{AstNode, VarDecl};
use crate::syntax::{SyntaxKind, SyntaxNode};

/// The section a `VAR… END_VAR` block declares, by its keyword; `None` for access paths
/// (`VAR_ACCESS`), which declare nothing of their own.
pub(crate) fn block_section(block: &SyntaxNode) -> Option<VarSection> {
    Some(match first_keyword(block) {
        Some(SyntaxKind::VAR_INPUT) => VarSection::VarInput,
        Some(SyntaxKind::VAR_OUTPUT) => VarSection::VarOutput,
        Some(SyntaxKind::VAR_IN_OUT) => VarSection::VarInOut,
        Some(SyntaxKind::VAR_GLOBAL) => VarSection::VarGlobal,
        Some(SyntaxKind::VAR_EXTERNAL) => VarSection::VarExternal,
        Some(SyntaxKind::VAR_TEMP) => VarSection::VarTemp,
        Some(SyntaxKind::VAR_STAT) => VarSection::VarStat,
        Some(SyntaxKind::VAR_INST) => VarSection::VarInst,
        Some(SyntaxKind::VAR_CONFIG) => VarSection::VarConfig,
        Some(SyntaxKind::VAR) => VarSection::Var,
        _ => return None,
    })
}

/// One declaration `a, b AT %IX0.0 : BOOL := TRUE;` taken apart.
pub(crate) struct DeclarationParts {
    /// The declared names' nodes, in order.
    pub names: Vec<SyntaxNode>,
    /// The type as written.
    pub ty: String,
    /// The direct address, if located.
    pub address: Option<String>,
    /// The initial value as written.
    pub initial: Option<String>,
}

/// Takes a `VAR_DECL` apart; `None` when it has no names. `trim` turns a node into its text
/// (each caller keeps its own idea of which trivia belongs to a node).
pub(crate) fn declaration_parts(
    declaration: &SyntaxNode,
    trim: impl Fn(&SyntaxNode) -> String,
) -> Option<DeclarationParts> {
    let declaration = VarDecl::cast(declaration.clone())?;
    let names: Vec<SyntaxNode> = declaration
        .name_list()?
        .names()
        .map(|name| name.syntax().clone())
        .collect();
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

/// The first keyword token directly in `node`.
pub(crate) fn first_keyword(node: &SyntaxNode) -> Option<SyntaxKind> {
    node.children_with_tokens()
        .filter_map(|element| element.into_token())
        .map(|token| token.kind())
        .find(|kind| kind.is_keyword())
}

/// Whether a token of `kind` stands directly in `node`.
pub(crate) fn has_token(node: &SyntaxNode, kind: SyntaxKind) -> bool {
    node.children_with_tokens()
        .filter_map(|element| element.into_token())
        .any(|token| token.kind() == kind)
}

/// The access specifier written on a method or property (`PUBLIC` when none is).
pub(crate) fn access_of(node: &SyntaxNode) -> AccessSpecifier {
    if has_token(node, SyntaxKind::PRIVATE) {
        AccessSpecifier::Private
    } else if has_token(node, SyntaxKind::PROTECTED) {
        AccessSpecifier::Protected
    } else if has_token(node, SyntaxKind::INTERNAL) {
        AccessSpecifier::Internal
    } else {
        AccessSpecifier::Public
    }
}
