//! The kinds of tokens and nodes in a Structured Text syntax tree.

/// Defines `SyntaxKind` with its keyword table, so a keyword is listed once.
macro_rules! syntax_kinds {
    (
        tokens { $($token:ident),* $(,)? }
        keywords { $($keyword:ident),* $(,)? }
        nodes { $($node:ident),* $(,)? }
    ) => {
        /// Every kind of token and node. Tokens come first, then keywords, then nodes.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[repr(u16)]
        #[allow(non_camel_case_types, missing_docs)] // Kinds are named as the grammar writes them.
        pub enum SyntaxKind {
            $($token,)*
            $($keyword,)*
            $($node,)*
            /// Not a kind: the number of kinds.
            __LAST,
        }

        impl SyntaxKind {
            /// Every kind in discriminant order.
            pub const ALL: &'static [SyntaxKind] = &[
                $(Self::$token,)*
                $(Self::$keyword,)*
                $(Self::$node,)*
            ];

            /// The keyword spelled `upper` (already upper case), if it is one.
            pub fn from_keyword(upper: &str) -> Option<Self> {
                match upper {
                    $(stringify!($keyword) => Some(Self::$keyword),)*
                    _ => None,
                }
            }

            /// Whether this kind is a keyword.
            pub fn is_keyword(self) -> bool {
                matches!(self, $(Self::$keyword)|*)
            }
        }
    };
}

syntax_kinds! {
    tokens {
        WHITESPACE, LINE_COMMENT, BLOCK_COMMENT, PRAGMA,
        IDENT, INT_NUMBER, REAL_NUMBER, TIME_LITERAL, DATE_LITERAL, STRING, WSTRING, DIRECT_ADDRESS,
        ASSIGN, OUTPUT_ASSIGN, QUESTION_ASSIGN, EQ, NEQ, LT, LE, GT, GE, PLUS, MINUS, STAR, SLASH,
        POWER, AMP, CARET, DOT, DOTDOT, COMMA, SEMICOLON, COLON, HASH, L_PAREN, R_PAREN, L_BRACK,
        R_BRACK, ERROR_TOKEN, EOF,
    }
    keywords {
        PROGRAM, END_PROGRAM, FUNCTION, END_FUNCTION, FUNCTION_BLOCK, END_FUNCTION_BLOCK,
        METHOD, END_METHOD, PROPERTY, END_PROPERTY, INTERFACE, END_INTERFACE, ACTION, END_ACTION,
        EXTENDS, IMPLEMENTS, ABSTRACT, FINAL, PUBLIC, PRIVATE, PROTECTED, INTERNAL,
        TYPE, END_TYPE, STRUCT, END_STRUCT, UNION, END_UNION, ARRAY, OF, POINTER, REFERENCE, REF_TO, TO,
        VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR_GLOBAL, VAR_EXTERNAL, VAR_TEMP, VAR_STAT,
        VAR_INST, VAR_CONFIG, VAR_ACCESS, END_VAR, CONSTANT, RETAIN, NON_RETAIN, PERSISTENT, AT,
        CONFIGURATION, END_CONFIGURATION, RESOURCE, END_RESOURCE, ON, TASK, WITH,
        IF, THEN, ELSIF, ELSE, END_IF, CASE, END_CASE, FOR, BY, DO, END_FOR, WHILE, END_WHILE,
        REPEAT, UNTIL, END_REPEAT, EXIT, CONTINUE, RETURN, JMP,
        AND, AND_THEN, OR, OR_ELSE, XOR, NOT, MOD, TRUE, FALSE, SUPER, THIS,
    }
    nodes {
        SOURCE_FILE, ERROR,
        POU, POU_HEADER, EXTENDS_CLAUSE, IMPLEMENTS_CLAUSE, METHOD_DECL, PROPERTY_DECL, ACCESSOR_DECL,
        ACTION_DECL,
        INTERFACE_DECL, TYPE_DECL, TYPE_DEFINITION, STRUCT_TYPE, UNION_TYPE, ENUM_TYPE, ENUM_VALUE,
        SUBRANGE, GLOBAL_VAR_LIST, CONFIGURATION_DECL, RESOURCE_DECL, TASK_DECL, PROGRAM_CONFIG,
        VAR_BLOCK, VAR_DECL, VAR_NAME_LIST, ADDRESS, TYPE_REF, ARRAY_TYPE, ARRAY_RANGE,
        POINTER_TYPE, REFERENCE_TYPE, STRING_TYPE, NAMED_TYPE, INITIALIZER, ARRAY_INIT,
        REPEAT_INIT, STRUCT_INIT, FIELD_INIT, NAME, NAME_REF, RETURN_TYPE,
        STATEMENT_LIST, ASSIGN_STMT, SET_STMT, RESET_STMT, REF_ASSIGN_STMT, ATTEMPT_ASSIGN_STMT,
        CALL_STMT, IF_STMT, ELSIF_BRANCH, ELSE_BRANCH, CASE_STMT, CASE_BRANCH, CASE_LABELS,
        CASE_RANGE, FOR_STMT, WHILE_STMT, REPEAT_STMT, EXIT_STMT, CONTINUE_STMT, RETURN_STMT,
        JMP_STMT, LABEL_STMT, EMPTY_STMT, STEP_DECL, TRANSITION_DECL, STEP_LIST,
        LITERAL, TYPED_LITERAL, PAREN_EXPR, BINARY_EXPR, UNARY_EXPR, NAME_EXPR, FIELD_EXPR,
        INDEX_EXPR, DEREF_EXPR, CALL_EXPR, ARG_LIST, ARG, ADDRESS_EXPR,
    }
}

impl SyntaxKind {
    /// Whitespace and comments, which the parser skips but the tree keeps.
    pub fn is_trivia(self) -> bool {
        matches!(
            self,
            Self::WHITESPACE | Self::LINE_COMMENT | Self::BLOCK_COMMENT
        )
    }

    /// How the kind is written in messages, such as `';'` or `END_IF` or `an identifier`.
    pub fn describe(self) -> String {
        let text = match self {
            Self::IDENT => "an identifier",
            Self::INT_NUMBER => "an integer",
            Self::REAL_NUMBER => "a number",
            Self::TIME_LITERAL => "a time literal",
            Self::DATE_LITERAL => "a date literal",
            Self::STRING => "a string",
            Self::WSTRING => "a wide string",
            Self::DIRECT_ADDRESS => "a direct address",
            Self::PRAGMA => "a pragma",
            Self::ASSIGN => "':='",
            Self::OUTPUT_ASSIGN => "'=>'",
            Self::QUESTION_ASSIGN => "'?='",
            Self::EQ => "'='",
            Self::NEQ => "'<>'",
            Self::LT => "'<'",
            Self::LE => "'<='",
            Self::GT => "'>'",
            Self::GE => "'>='",
            Self::PLUS => "'+'",
            Self::MINUS => "'-'",
            Self::STAR => "'*'",
            Self::SLASH => "'/'",
            Self::POWER => "'**'",
            Self::AMP => "'&'",
            Self::CARET => "'^'",
            Self::DOT => "'.'",
            Self::DOTDOT => "'..'",
            Self::COMMA => "','",
            Self::SEMICOLON => "';'",
            Self::COLON => "':'",
            Self::HASH => "'#'",
            Self::L_PAREN => "'('",
            Self::R_PAREN => "')'",
            Self::L_BRACK => "'['",
            Self::R_BRACK => "']'",
            Self::EOF => "the end of the file",
            Self::ERROR_TOKEN => "an invalid character",
            kind if kind.is_keyword() => return format!("{kind:?}"),
            kind => return format!("{kind:?}").to_lowercase().replace('_', " "),
        };
        text.to_owned()
    }
}

impl From<SyntaxKind> for rowan::SyntaxKind {
    fn from(kind: SyntaxKind) -> Self {
        Self(kind as u16)
    }
}

/// The rowan language of Structured Text trees.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum StLanguage {}

impl rowan::Language for StLanguage {
    type Kind = SyntaxKind;

    fn kind_from_raw(raw: rowan::SyntaxKind) -> SyntaxKind {
        // Kinds are dense from 0, so the table turns a raw kind back without `unsafe`.
        SyntaxKind::ALL
            .get(usize::from(raw.0))
            .copied()
            .unwrap_or(SyntaxKind::ERROR)
    }

    fn kind_to_raw(kind: SyntaxKind) -> rowan::SyntaxKind {
        kind.into()
    }
}

/// A node of a Structured Text syntax tree.
pub type SyntaxNode = rowan::SyntaxNode<StLanguage>;
/// A token of a Structured Text syntax tree.
pub type SyntaxToken = rowan::SyntaxToken<StLanguage>;
