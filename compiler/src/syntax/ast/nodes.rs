//! One wrapper type per node kind, generated from one list so a kind is named once.

use super::AstNode;
use crate::syntax::{SyntaxKind, SyntaxNode};

/// Defines a wrapper struct per `Name = KIND` pair, with its `AstNode` impl.
macro_rules! ast_nodes {
    ($($(#[doc = $doc:literal])+ $name:ident = $kind:ident,)*) => {
        $(
            $(#[doc = $doc])+
            #[derive(Clone, Debug, PartialEq, Eq, Hash)]
            pub struct $name(pub(super) SyntaxNode);

            impl AstNode for $name {
                fn can_cast(kind: SyntaxKind) -> bool {
                    kind == SyntaxKind::$kind
                }

                fn cast(node: SyntaxNode) -> Option<Self> {
                    Self::can_cast(node.kind()).then(|| Self(node))
                }

                fn syntax(&self) -> &SyntaxNode {
                    &self.0
                }
            }
        )*

        /// Every node kind that has a wrapper, for the test that none is missing.
        #[cfg(test)]
        pub(super) const WRAPPED_KINDS: &[SyntaxKind] = &[$(SyntaxKind::$kind),*];
    };
}

ast_nodes! {
    /// A whole file or body: POUs and declarations, or one statement list.
    SourceFile = SOURCE_FILE,
    /// Input the parser could not make sense of, kept so the tree holds every byte.
    ErrorNode = ERROR,
    /// A `PROGRAM`, `FUNCTION` or `FUNCTION_BLOCK` with its declarations and body.
    Pou = POU,
    /// The header of a POU: its keyword, name, return type and clauses.
    PouHeader = POU_HEADER,
    /// `EXTENDS Base`.
    ExtendsClause = EXTENDS_CLAUSE,
    /// `IMPLEMENTS I_A, I_B`.
    ImplementsClause = IMPLEMENTS_CLAUSE,
    /// A `METHOD … END_METHOD`.
    MethodDecl = METHOD_DECL,
    /// A `PROPERTY … END_PROPERTY`.
    PropertyDecl = PROPERTY_DECL,
    /// The `GET` or `SET` accessor of a property.
    AccessorDecl = ACCESSOR_DECL,
    /// An `ACTION … END_ACTION`, or an SFC action.
    ActionDecl = ACTION_DECL,
    /// An `INTERFACE … END_INTERFACE`.
    InterfaceDecl = INTERFACE_DECL,
    /// A `TYPE … END_TYPE` block.
    TypeDecl = TYPE_DECL,
    /// One type defined in a `TYPE` block: `E_State : (Idle, Running);`.
    TypeDefinition = TYPE_DEFINITION,
    /// `STRUCT … END_STRUCT`.
    StructType = STRUCT_TYPE,
    /// `UNION … END_UNION`.
    UnionType = UNION_TYPE,
    /// An enumeration `(Idle := 0, Running)`.
    EnumType = ENUM_TYPE,
    /// One value of an enumeration, `Idle := 0`.
    EnumValue = ENUM_VALUE,
    /// The bounds of a subrange type, `(0..100)`.
    Subrange = SUBRANGE,
    /// A `VAR_GLOBAL … END_VAR` list outside POUs.
    GlobalVarList = GLOBAL_VAR_LIST,
    /// A `CONFIGURATION … END_CONFIGURATION`.
    ConfigurationDecl = CONFIGURATION_DECL,
    /// A `RESOURCE … END_RESOURCE`.
    ResourceDecl = RESOURCE_DECL,
    /// A `TASK` of a resource.
    TaskDecl = TASK_DECL,
    /// A `PROGRAM name WITH task : Type;` of a resource.
    ProgramConfig = PROGRAM_CONFIG,
    /// One `VAR… END_VAR` section.
    VarBlock = VAR_BLOCK,
    /// One declaration in a section: `a, b AT %IX0.0 : Type := init;`.
    VarDecl = VAR_DECL,
    /// The names a declaration declares.
    VarNameList = VAR_NAME_LIST,
    /// `AT %IX0.0`.
    Address = ADDRESS,
    /// A type reference (a kind the grammar keeps for a type that wraps another).
    TypeRef = TYPE_REF,
    /// `ARRAY[1..3, 0..1] OF REAL`.
    ArrayType = ARRAY_TYPE,
    /// One dimension of an array type, `1..3` or `*`.
    ArrayRange = ARRAY_RANGE,
    /// `POINTER TO T`.
    PointerType = POINTER_TYPE,
    /// `REFERENCE TO T` or `REF_TO T`.
    ReferenceType = REFERENCE_TYPE,
    /// `STRING(20)` or `WSTRING[80]`.
    StringType = STRING_TYPE,
    /// A type by name, with an optional subrange or FB initialisation arguments.
    NamedType = NAMED_TYPE,
    /// `:= value` in a declaration.
    Initializer = INITIALIZER,
    /// `[1, 2, 3(0)]`, an array value.
    ArrayInit = ARRAY_INIT,
    /// `3(0)` in an array initialiser: a value repeated.
    RepeatInit = REPEAT_INIT,
    /// `(x := 1, y := 2)`, a structure value.
    StructInit = STRUCT_INIT,
    /// `x := 1` in a structure initialiser.
    FieldInit = FIELD_INIT,
    /// A name being declared.
    Name = NAME,
    /// A reference to a named thing, possibly dotted: `FB_Conveyor`, `Lib.FB_X`.
    NameRef = NAME_REF,
    /// `: Type` after a function's or method's name.
    ReturnType = RETURN_TYPE,
    /// Statements in a row.
    StatementList = STATEMENT_LIST,
    /// `target := value;`.
    AssignStmt = ASSIGN_STMT,
    /// `target S= value;`.
    SetStmt = SET_STMT,
    /// `target R= value;`.
    ResetStmt = RESET_STMT,
    /// `target REF= value;`.
    RefAssignStmt = REF_ASSIGN_STMT,
    /// `target ?= value;`.
    AttemptAssignStmt = ATTEMPT_ASSIGN_STMT,
    /// A call used as a statement, `fbTimer(IN := x);`.
    CallStmt = CALL_STMT,
    /// `IF … ELSIF … ELSE … END_IF`.
    IfStmt = IF_STMT,
    /// `ELSIF condition THEN statements`.
    ElsifBranch = ELSIF_BRANCH,
    /// `ELSE statements` of an IF or a CASE.
    ElseBranch = ELSE_BRANCH,
    /// `CASE selector OF … END_CASE`.
    CaseStmt = CASE_STMT,
    /// `1, 3..5: statements` of a CASE.
    CaseBranch = CASE_BRANCH,
    /// The labels of a CASE branch.
    CaseLabels = CASE_LABELS,
    /// `3..5` as a CASE label.
    CaseRange = CASE_RANGE,
    /// `FOR i := from TO to BY step DO … END_FOR`.
    ForStmt = FOR_STMT,
    /// `WHILE condition DO … END_WHILE`.
    WhileStmt = WHILE_STMT,
    /// `REPEAT … UNTIL condition END_REPEAT`.
    RepeatStmt = REPEAT_STMT,
    /// `EXIT;`.
    ExitStmt = EXIT_STMT,
    /// `CONTINUE;`.
    ContinueStmt = CONTINUE_STMT,
    /// `RETURN;`.
    ReturnStmt = RETURN_STMT,
    /// `JMP label;`.
    JmpStmt = JMP_STMT,
    /// `label:`.
    LabelStmt = LABEL_STMT,
    /// A lone `;`.
    EmptyStmt = EMPTY_STMT,
    /// A textual SFC step, `STEP Name: … END_STEP`.
    StepDecl = STEP_DECL,
    /// A textual SFC transition, `TRANSITION FROM a TO b := condition; END_TRANSITION`.
    TransitionDecl = TRANSITION_DECL,
    /// The steps a transition comes from or goes to: `Step` or `(Step1, Step2)`.
    StepList = STEP_LIST,
    /// A plain literal: `42`, `1.5`, `'text'`, `T#2s`, `TRUE`.
    Literal = LITERAL,
    /// A literal with a type prefix, `INT#5` or `E_State#Idle`.
    TypedLiteral = TYPED_LITERAL,
    /// `(inner)`.
    ParenExpr = PAREN_EXPR,
    /// `lhs op rhs`.
    BinaryExpr = BINARY_EXPR,
    /// `NOT x`, `-x`, `+x`.
    UnaryExpr = UNARY_EXPR,
    /// A name in an expression: `x`, `.x` (the global), `THIS`, `SUPER`, or `MOD` called.
    NameExpr = NAME_EXPR,
    /// `base.member`.
    FieldExpr = FIELD_EXPR,
    /// `base[i, j]`.
    IndexExpr = INDEX_EXPR,
    /// `base^`.
    DerefExpr = DEREF_EXPR,
    /// `callee(args)`.
    CallExpr = CALL_EXPR,
    /// `(a := 1, b => x, 3)`.
    ArgList = ARG_LIST,
    /// One argument: `value`, `name := value` or `name => place`.
    Arg = ARG,
    /// A direct address used as a value, `%IX0.1`.
    AddressExpr = ADDRESS_EXPR,
}
