//! Top-level items: POUs and their members, interfaces, types, global variable lists and
//! configurations.

use super::expressions::ast_enum;
use super::support::{child, children, node_after, token, tokens};
use super::*;
use crate::syntax::SyntaxToken;

ast_enum! {
    /// Anything a source file holds at its top level.
    Item {
        /// `PROGRAM`, `FUNCTION_BLOCK` or `FUNCTION`.
        Pou,
        /// `INTERFACE`.
        InterfaceDecl,
        /// `TYPE … END_TYPE`.
        TypeDecl,
        /// `VAR_GLOBAL … END_VAR`.
        GlobalVarList,
        /// `CONFIGURATION`.
        ConfigurationDecl,
        /// An `ACTION` written on its own.
        ActionDecl,
        /// A `METHOD` written on its own.
        MethodDecl,
        /// A `PROPERTY` written on its own.
        PropertyDecl,
        /// A variable section written on its own, as a declaration part holds it
        /// (`parse_declaration_part`).
        VarBlock,
    }
}

ast_enum! {
    /// A member of a POU written inside it: a method, property or action.
    PouMember {
        /// `METHOD … END_METHOD`.
        MethodDecl,
        /// `PROPERTY … END_PROPERTY`.
        PropertyDecl,
        /// `ACTION … END_ACTION`.
        ActionDecl,
    }
}

/// The modifiers a POU, method or property may carry after its keyword.
const MODIFIERS: [SyntaxKind; 6] = [
    SyntaxKind::ABSTRACT,
    SyntaxKind::FINAL,
    SyntaxKind::PUBLIC,
    SyntaxKind::PRIVATE,
    SyntaxKind::PROTECTED,
    SyntaxKind::INTERNAL,
];

/// The modifier keywords written directly in `node`, in order.
fn modifiers(node: &SyntaxNode) -> impl Iterator<Item = SyntaxKind> + use<> {
    tokens(node)
        .map(|token| token.kind())
        .filter(|kind| MODIFIERS.contains(kind))
}

impl SourceFile {
    /// The items of a source file, in order.
    pub fn items(&self) -> AstChildren<Item> {
        children(&self.0)
    }
}

impl Pou {
    /// The keyword: `PROGRAM`, `FUNCTION_BLOCK` or `FUNCTION`.
    pub fn keyword(&self) -> Option<SyntaxToken> {
        tokens(&self.0).next()
    }

    /// The POU's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// A function's return type.
    pub fn return_type(&self) -> Option<TypeExpr> {
        child::<ReturnType>(&self.0).and_then(|r| r.ty())
    }

    /// `EXTENDS Base`.
    pub fn extends(&self) -> Option<ExtendsClause> {
        child(&self.0)
    }

    /// `IMPLEMENTS I_A, I_B`.
    pub fn implements(&self) -> Option<ImplementsClause> {
        child(&self.0)
    }

    /// The variable sections, in order.
    pub fn var_blocks(&self) -> AstChildren<VarBlock> {
        children(&self.0)
    }

    /// The methods, in order.
    pub fn methods(&self) -> AstChildren<MethodDecl> {
        children(&self.0)
    }

    /// The properties, in order.
    pub fn properties(&self) -> AstChildren<PropertyDecl> {
        children(&self.0)
    }

    /// The actions, in order.
    pub fn actions(&self) -> AstChildren<ActionDecl> {
        children(&self.0)
    }

    /// The methods, properties and actions in the order written.
    pub fn members(&self) -> AstChildren<PouMember> {
        children(&self.0)
    }

    /// The modifiers after the keyword (`ABSTRACT`, `FINAL`, `PUBLIC`, `PRIVATE`, …), in order.
    pub fn modifiers(&self) -> impl Iterator<Item = SyntaxKind> + use<> {
        modifiers(&self.0)
    }

    /// The body's statement lists (a body may be split by members, as in textual SFC).
    pub fn bodies(&self) -> AstChildren<StatementList> {
        children(&self.0)
    }
}

impl ReturnType {
    /// The type after `:`.
    pub fn ty(&self) -> Option<TypeExpr> {
        child(&self.0)
    }
}

impl ExtendsClause {
    /// The names after `EXTENDS`.
    pub fn names(&self) -> AstChildren<NameRef> {
        children(&self.0)
    }
}

impl ImplementsClause {
    /// The interfaces after `IMPLEMENTS`.
    pub fn names(&self) -> AstChildren<NameRef> {
        children(&self.0)
    }
}

impl MethodDecl {
    /// The method's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The modifiers after `METHOD` (`ABSTRACT`, `PRIVATE`, …), in order.
    pub fn modifiers(&self) -> impl Iterator<Item = SyntaxKind> + use<> {
        modifiers(&self.0)
    }

    /// The return type.
    pub fn return_type(&self) -> Option<TypeExpr> {
        child::<ReturnType>(&self.0).and_then(|r| r.ty())
    }

    /// The variable sections, in order.
    pub fn var_blocks(&self) -> AstChildren<VarBlock> {
        children(&self.0)
    }

    /// The statements.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

impl PropertyDecl {
    /// The property's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The modifiers after `PROPERTY` (`PRIVATE`, `FINAL`, …), in order.
    pub fn modifiers(&self) -> impl Iterator<Item = SyntaxKind> + use<> {
        modifiers(&self.0)
    }

    /// The property's type.
    pub fn ty(&self) -> Option<TypeExpr> {
        child::<ReturnType>(&self.0).and_then(|r| r.ty())
    }

    /// The `GET` and `SET` accessors written inline, in order.
    pub fn accessors(&self) -> AstChildren<AccessorDecl> {
        children(&self.0)
    }
}

impl AccessorDecl {
    /// Whether this is the `GET` accessor (else the `SET`).
    pub fn is_get(&self) -> bool {
        tokens(&self.0)
            .next()
            .is_some_and(|t| t.text().eq_ignore_ascii_case("GET"))
    }

    /// The variable sections, in order.
    pub fn var_blocks(&self) -> AstChildren<VarBlock> {
        children(&self.0)
    }

    /// The statements.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

impl InterfaceDecl {
    /// The interface's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// `EXTENDS I_Base, …`.
    pub fn extends(&self) -> Option<ExtendsClause> {
        child(&self.0)
    }

    /// The methods, in order.
    pub fn methods(&self) -> AstChildren<MethodDecl> {
        children(&self.0)
    }

    /// The properties, in order.
    pub fn properties(&self) -> AstChildren<PropertyDecl> {
        children(&self.0)
    }

    /// The methods and properties in the order written.
    pub fn members(&self) -> AstChildren<PouMember> {
        children(&self.0)
    }
}

impl TypeDecl {
    /// The types defined, in order.
    pub fn definitions(&self) -> AstChildren<TypeDefinition> {
        children(&self.0)
    }
}

impl TypeDefinition {
    /// The type's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// `EXTENDS Base` of a structure.
    pub fn extends(&self) -> Option<ExtendsClause> {
        child(&self.0)
    }

    /// A structure's definition.
    pub fn struct_type(&self) -> Option<StructType> {
        child(&self.0)
    }

    /// A union's definition.
    pub fn union_type(&self) -> Option<UnionType> {
        child(&self.0)
    }

    /// An alias's, subrange's, array's or enumeration's type.
    pub fn ty(&self) -> Option<TypeExpr> {
        child(&self.0)
    }

    /// The default value after `:=`.
    pub fn initializer(&self) -> Option<Initializer> {
        child(&self.0)
    }
}

impl StructType {
    /// The members, in order.
    pub fn members(&self) -> AstChildren<VarDecl> {
        children(&self.0)
    }
}

impl UnionType {
    /// The members, in order.
    pub fn members(&self) -> AstChildren<VarDecl> {
        children(&self.0)
    }
}

impl GlobalVarList {
    /// The variable sections, in order.
    pub fn var_blocks(&self) -> AstChildren<VarBlock> {
        children(&self.0)
    }
}

impl VarBlock {
    /// The section keyword: `VAR`, `VAR_INPUT`, `VAR_GLOBAL`, ….
    pub fn keyword(&self) -> Option<SyntaxToken> {
        tokens(&self.0).next()
    }

    /// Whether the section is `CONSTANT`.
    pub fn is_constant(&self) -> bool {
        token(&self.0, SyntaxKind::CONSTANT).is_some()
    }

    /// Whether the section is `RETAIN` or `PERSISTENT`.
    pub fn is_retain(&self) -> bool {
        self.has_retain_keyword() || self.has_persistent_keyword()
    }

    /// Whether `RETAIN` is written on the section.
    pub fn has_retain_keyword(&self) -> bool {
        token(&self.0, SyntaxKind::RETAIN).is_some()
    }

    /// Whether `PERSISTENT` is written on the section.
    pub fn has_persistent_keyword(&self) -> bool {
        token(&self.0, SyntaxKind::PERSISTENT).is_some()
    }

    /// The declarations, in order.
    pub fn declarations(&self) -> AstChildren<VarDecl> {
        children(&self.0)
    }
}

impl ConfigurationDecl {
    /// The configuration's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The configuration's global variable sections.
    pub fn var_blocks(&self) -> AstChildren<VarBlock> {
        children(&self.0)
    }

    /// The resources, in order.
    pub fn resources(&self) -> AstChildren<ResourceDecl> {
        children(&self.0)
    }
}

impl ResourceDecl {
    /// The resource's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The processor after `ON`.
    pub fn processor(&self) -> Option<NameRef> {
        node_after(&self.0, Some(SyntaxKind::ON))
    }

    /// The tasks, in order.
    pub fn tasks(&self) -> AstChildren<TaskDecl> {
        children(&self.0)
    }

    /// The program instances, in order.
    pub fn programs(&self) -> AstChildren<ProgramConfig> {
        children(&self.0)
    }
}

impl TaskDecl {
    /// The task's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The task's settings, `(INTERVAL := T#10ms, PRIORITY := 1)`.
    pub fn arg_list(&self) -> Option<ArgList> {
        child(&self.0)
    }
}

impl ProgramConfig {
    /// The instance's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The task after `WITH`.
    pub fn task(&self) -> Option<NameRef> {
        node_after(&self.0, Some(SyntaxKind::WITH))
    }

    /// The program's type after `:`.
    pub fn program_type(&self) -> Option<NameRef> {
        node_after(&self.0, Some(SyntaxKind::COLON))
    }
}
