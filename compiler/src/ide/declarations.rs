//! Declaration text back into the model: what a user typed in the textual view of a declaration
//! part (`PROGRAM Main VAR … END_VAR`, or a list's `VAR_GLOBAL` blocks) as a header and
//! [`Variable`]s, so the table and the text edit the same data.
//!
//! The text is parsed by the compiler's parser, which is the only source of diagnostics; this
//! module only reads the tree. Types, initial values and addresses are kept as written, as the
//! model keeps them.

use std::ops::Range;

use project_model::{AccessSpecifier, PouKind, Variable};

use crate::declaration_parts::{access_of, block_section, declaration_parts};
use crate::syntax::ast::{
    AstNode, ExtendsClause, Item, Name, NameRef, PouMember, SourceFile, StatementList, TypeExpr,
    VarBlock, VarDecl,
};
use crate::syntax::{SyntaxKind, SyntaxNode, SyntaxToken, parse_declaration_part};
use crate::{Code, Diagnostic};

/// What a declaration part declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeclarationKind {
    /// A program, function block, function or interface.
    Pou(PouKind),
    /// A method of a function block.
    Method,
}

/// The header line of a POU or method declaration part.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeclarationHeader {
    /// POU or method, and which kind of POU.
    pub kind: DeclarationKind,
    /// The declared name.
    pub name: String,
    /// The return type as written (functions and methods).
    pub return_type: Option<String>,
    /// The base function block of `EXTENDS`.
    pub extends: Option<String>,
    /// The interfaces of `IMPLEMENTS`, in order.
    pub implements: Vec<String>,
    /// A method's access specifier; `PUBLIC` when none is written.
    pub access: AccessSpecifier,
    /// Whether a method is `ABSTRACT`.
    pub is_abstract: bool,
}

/// A declaration part read back into the model's terms.
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedDeclarations {
    /// The POU or method header; `None` for a global variable list.
    pub header: Option<DeclarationHeader>,
    /// The `//` comment lines before the header (or before a list's first section), joined by
    /// line breaks.
    pub comment: String,
    /// The variables in the order written, each with its section and qualifiers.
    pub variables: Vec<Variable>,
}

/// Parses a declaration part as `declaration_text()` renders it: an optional header (`PROGRAM`,
/// `FUNCTION_BLOCK`, `FUNCTION`, `INTERFACE` or `METHOD`) followed by `VAR… END_VAR` sections, or
/// only `VAR_GLOBAL` sections for a global variable list.
///
/// A variable's comment is the `//` or `(* *)` comment after its `;` on the same line, or else
/// the line comments right above it. Broken text gives the parser's diagnostics, with byte
/// ranges into `text`; so does text the model cannot hold (statements, a second POU).
pub fn parse_declarations(text: &str) -> Result<ParsedDeclarations, Vec<Diagnostic>> {
    let parse = parse_declaration_part(text);
    if !parse.errors().is_empty() {
        return Err(parse.errors().to_vec());
    }
    let root = parse.syntax();
    let tokens: Vec<SyntaxToken> = root
        .descendants_with_tokens()
        .filter_map(|element| element.into_token())
        .collect();
    let mut reader = Reader {
        tokens: &tokens,
        errors: Vec::new(),
        header: None,
        variables: Vec::new(),
    };
    for item in SourceFile::cast(root)
        .into_iter()
        .flat_map(|file| file.items())
    {
        reader.item(&item);
    }
    // Each part is refused where it is: in the order of the text.
    reader.errors.sort_by_key(|error| error.range.start);
    if !reader.errors.is_empty() {
        return Err(reader.errors);
    }
    Ok(ParsedDeclarations {
        header: reader.header,
        comment: leading_comment(text),
        variables: reader.variables,
    })
}

/// Walks the top-level items and collects what the model can hold.
struct Reader<'t> {
    tokens: &'t [SyntaxToken],
    errors: Vec<Diagnostic>,
    header: Option<DeclarationHeader>,
    variables: Vec<Variable>,
}

impl Reader<'_> {
    fn item(&mut self, item: &Item) {
        match item {
            Item::Pou(_) | Item::InterfaceDecl(_) | Item::MethodDecl(_) => self.header(item),
            Item::GlobalVarList(list) => {
                for block in list.var_blocks() {
                    self.block(&block);
                }
            }
            Item::VarBlock(block) => self.block(block),
            _ => self.refuse(
                item.syntax(),
                "a declaration part holds one header and variable sections; types, \
                 properties and actions are objects of their own",
            ),
        }
    }

    fn header(&mut self, item: &Item) {
        if self.header.is_some() || !self.variables.is_empty() {
            self.refuse(
                item.syntax(),
                "a declaration part declares one POU or method, with its header first",
            );
            return;
        }
        let header = match item {
            Item::Pou(pou) => Header {
                kind: match pou.keyword().map(|keyword| keyword.kind()) {
                    Some(SyntaxKind::PROGRAM) => DeclarationKind::Pou(PouKind::Program),
                    Some(SyntaxKind::FUNCTION_BLOCK) => {
                        DeclarationKind::Pou(PouKind::FunctionBlock)
                    }
                    Some(SyntaxKind::FUNCTION) => DeclarationKind::Pou(PouKind::Function),
                    _ => DeclarationKind::Method,
                },
                name: pou.name(),
                return_type: pou.return_type(),
                extends: pou.extends(),
                implements: pou
                    .implements()
                    .map(|clause| clause.names().collect())
                    .unwrap_or_default(),
                modifiers: pou.modifiers().collect(),
                blocks: pou.var_blocks().collect(),
                bodies: pou.bodies().collect(),
                members: pou.members().collect(),
            },
            Item::InterfaceDecl(interface) => Header {
                kind: DeclarationKind::Pou(PouKind::Interface),
                name: interface.name(),
                return_type: None,
                extends: interface.extends(),
                implements: Vec::new(),
                modifiers: Vec::new(),
                blocks: Vec::new(),
                bodies: Vec::new(),
                members: interface.members().collect(),
            },
            Item::MethodDecl(method) => Header {
                kind: DeclarationKind::Method,
                name: method.name(),
                return_type: method.return_type(),
                extends: None,
                implements: Vec::new(),
                modifiers: method.modifiers().collect(),
                blocks: method.var_blocks().collect(),
                bodies: method.body().into_iter().collect(),
                members: Vec::new(),
            },
            _ => return,
        };
        self.header = Some(DeclarationHeader {
            kind: header.kind,
            name: header
                .name
                .map(|name| trimmed(name.syntax()))
                .unwrap_or_default(),
            return_type: header.return_type.map(|ty| trimmed(ty.syntax())),
            extends: header
                .extends
                .and_then(|clause| clause.names().next())
                .map(|name| trimmed(name.syntax())),
            implements: header
                .implements
                .iter()
                .map(|name| trimmed(name.syntax()))
                .collect(),
            access: access_of(header.modifiers.iter().copied()),
            is_abstract: header.modifiers.contains(&SyntaxKind::ABSTRACT),
        });
        for block in &header.blocks {
            self.block(block);
        }
        for body in header.bodies.iter().map(|body| body.syntax()) {
            if !trimmed(body).is_empty() {
                self.refuse(
                    body,
                    "statements belong in the implementation, not in the declaration part",
                );
            }
        }
        for member in &header.members {
            self.refuse(
                member.syntax(),
                "methods, properties and actions are objects of their own, not part \
                 of the declarations",
            );
        }
    }

    /// One `VAR… END_VAR` section.
    fn block(&mut self, block: &VarBlock) {
        let Some(section) = block_section(block) else {
            self.refuse(
                block.syntax(),
                "access paths (VAR_ACCESS) have no place in the model",
            );
            return;
        };
        let template = Variable {
            section,
            constant: block.is_constant(),
            retain: block.has_retain_keyword(),
            persistent: block.has_persistent_keyword(),
            ..Variable::default()
        };
        for declaration in block.declarations() {
            self.declaration(&declaration, &template);
        }
    }

    /// One declaration `a, b AT %IX0.0 : BOOL := TRUE; // comment`.
    fn declaration(&mut self, declaration: &VarDecl, template: &Variable) {
        let Some(parts) = declaration_parts(declaration, trimmed) else {
            self.refuse(
                declaration.syntax(),
                "a located variable needs a name: write `name AT %IX0.0 : BOOL;`",
            );
            return;
        };
        let range = super::trimmed_range(declaration.syntax());
        let comment = self
            .trailing_comment(range.end)
            .or_else(|| self.comment_above(range.start))
            .unwrap_or_default();
        for name in &parts.names {
            self.variables.push(Variable {
                name: trimmed(name.syntax()),
                ty: parts.ty.clone(),
                initial: parts.initial.clone(),
                address: parts.address.clone(),
                comment: comment.clone(),
                ..template.clone()
            });
        }
    }

    /// The comment after `end` on the same line.
    fn trailing_comment(&self, end: usize) -> Option<String> {
        let first = self
            .tokens
            .iter()
            .position(|token| offset(token).start >= end)?;
        for token in &self.tokens[first..] {
            match token.kind() {
                SyntaxKind::WHITESPACE if !token.text().contains('\n') => {}
                SyntaxKind::LINE_COMMENT | SyntaxKind::BLOCK_COMMENT => {
                    return Some(comment_text(token.text()));
                }
                _ => return None,
            }
        }
        None
    }

    /// The line comments on lines of their own right above `start`, joined by line breaks.
    fn comment_above(&self, start: usize) -> Option<String> {
        let before = self
            .tokens
            .iter()
            .position(|token| offset(token).start >= start)
            .unwrap_or(self.tokens.len());
        let mut lines = Vec::new();
        let mut index = before;
        while index > 0 {
            index -= 1;
            let token = &self.tokens[index];
            match token.kind() {
                // A blank line separates a comment from the declaration it does not describe.
                SyntaxKind::WHITESPACE if token.text().matches('\n').count() > 1 => break,
                SyntaxKind::WHITESPACE => {}
                SyntaxKind::LINE_COMMENT if self.starts_a_line(index) => {
                    lines.push(comment_text(token.text()));
                }
                _ => break,
            }
        }
        lines.reverse();
        (!lines.is_empty()).then(|| lines.join("\n"))
    }

    /// Whether only indentation comes between the previous line break and token `index`.
    fn starts_a_line(&self, index: usize) -> bool {
        match index.checked_sub(1).map(|previous| &self.tokens[previous]) {
            None => true,
            Some(previous) => {
                previous.kind() == SyntaxKind::WHITESPACE && previous.text().contains('\n')
                    || index == 1 && previous.kind() == SyntaxKind::WHITESPACE
            }
        }
    }

    /// Records that `node` holds something the model cannot.
    fn refuse(&mut self, node: &SyntaxNode, message: &str) {
        self.errors.push(Diagnostic::new(
            Code::UnexpectedToken,
            super::trimmed_range(node),
            message,
        ));
    }
}

/// The parts of a POU, interface or method header that a declaration part reads or refuses.
struct Header {
    kind: DeclarationKind,
    name: Option<Name>,
    return_type: Option<TypeExpr>,
    extends: Option<ExtendsClause>,
    implements: Vec<NameRef>,
    modifiers: Vec<SyntaxKind>,
    /// The variable sections, read into variables.
    blocks: Vec<VarBlock>,
    /// The statement lists: refused unless blank.
    bodies: Vec<StatementList>,
    /// Methods, properties and actions written inside: refused.
    members: Vec<PouMember>,
}

/// The `//` lines that open the text, as `declaration_text()` writes an object's comment.
fn leading_comment(text: &str) -> String {
    let mut lines = Vec::new();
    for line in text.lines() {
        let line = line.trim();
        match line.strip_prefix("//") {
            Some(comment) => lines.push(comment.strip_prefix(' ').unwrap_or(comment).to_owned()),
            None if line.is_empty() => {}
            None => break,
        }
    }
    lines.join("\n")
}

/// A comment token's text without its delimiters and the one space written beside each.
fn comment_text(token: &str) -> String {
    if let Some(line) = token.strip_prefix("//") {
        let line = line.trim_end_matches(['\r', '\n']);
        return line.strip_prefix(' ').unwrap_or(line).to_owned();
    }
    let inner = token
        .strip_prefix("(*")
        .and_then(|rest| rest.strip_suffix("*)"))
        .or_else(|| {
            token
                .strip_prefix("/*")
                .and_then(|rest| rest.strip_suffix("*/"))
        })
        .unwrap_or(token);
    let inner = inner.strip_prefix(' ').unwrap_or(inner);
    inner.strip_suffix(' ').unwrap_or(inner).to_owned()
}

/// The node's text without surrounding trivia.
fn trimmed(node: &SyntaxNode) -> String {
    let range = super::trimmed_range(node);
    let start = usize::from(node.text_range().start());
    let text = node.text().to_string();
    text.get(range.start - start..range.end - start)
        .unwrap_or_default()
        .to_owned()
}

fn offset(token: &SyntaxToken) -> Range<usize> {
    let range = token.text_range();
    usize::from(range.start())..usize::from(range.end())
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::VarSection;

    #[test]
    fn a_pou_header_and_its_sections_become_variables() {
        let text = "// Runs the belt.\n\
            FUNCTION_BLOCK FB_Conveyor EXTENDS FB_Base IMPLEMENTS I_Drive, I_Reset\n\
            VAR_INPUT\n    xStart, xJog : BOOL; // start request\nEND_VAR\n\
            VAR CONSTANT RETAIN PERSISTENT\n    tDelay : TIME := T#2s;\nEND_VAR\n\
            VAR\n    xMotor AT %QX0.0 : BOOL; (* line one\nline two *)\n\
            // speed in mm/s\n    aSpeeds : ARRAY[1..3] OF REAL := [1.0, 2.0, 3.0];\nEND_VAR\n";
        let parsed = parse_declarations(text).unwrap();
        let header = parsed.header.unwrap();
        assert_eq!(header.kind, DeclarationKind::Pou(PouKind::FunctionBlock));
        assert_eq!(header.name, "FB_Conveyor");
        assert_eq!(header.extends.as_deref(), Some("FB_Base"));
        assert_eq!(header.implements, ["I_Drive", "I_Reset"]);
        assert_eq!(parsed.comment, "Runs the belt.");
        let names: Vec<&str> = parsed.variables.iter().map(|v| v.name.as_str()).collect();
        assert_eq!(names, ["xStart", "xJog", "tDelay", "xMotor", "aSpeeds"]);
        let [start, jog, delay, motor, speeds] = parsed.variables.as_slice() else {
            panic!("five variables");
        };
        assert_eq!(
            (start.section, start.comment.as_str()),
            (VarSection::VarInput, "start request")
        );
        assert_eq!(jog.comment, "start request");
        assert!(delay.constant && delay.retain && delay.persistent);
        assert_eq!(delay.initial.as_deref(), Some("T#2s"));
        assert_eq!(motor.address.as_deref(), Some("%QX0.0"));
        assert_eq!(motor.comment, "line one\nline two");
        assert_eq!(speeds.ty, "ARRAY[1..3] OF REAL");
        assert_eq!(speeds.initial.as_deref(), Some("[1.0, 2.0, 3.0]"));
        assert_eq!(speeds.comment, "speed in mm/s");
    }

    #[test]
    fn a_method_header_keeps_its_access_and_return_type() {
        let parsed = parse_declarations(
            "METHOD PROTECTED ABSTRACT Scale : LREAL\nVAR_INPUT\n    k : INT;\nEND_VAR\n",
        )
        .unwrap();
        let header = parsed.header.unwrap();
        assert_eq!(header.kind, DeclarationKind::Method);
        assert_eq!(header.access, AccessSpecifier::Protected);
        assert!(header.is_abstract);
        assert_eq!(header.return_type.as_deref(), Some("LREAL"));
        assert_eq!(parsed.variables[0].section, VarSection::VarInput);
    }

    #[test]
    fn a_global_list_has_no_header() {
        let parsed =
            parse_declarations("VAR_GLOBAL\n    xStart AT %IX0.0 : BOOL;\nEND_VAR\n").unwrap();
        assert_eq!(parsed.header, None);
        assert_eq!(parsed.variables[0].section, VarSection::VarGlobal);
    }

    #[test]
    fn configuration_entries_keep_their_instance_paths() {
        let parsed =
            parse_declarations("VAR_CONFIG\n    Main.fbAxis.xLimit AT %IX1.0 : BOOL;\nEND_VAR\n")
                .unwrap();
        let entry = &parsed.variables[0];
        assert_eq!(entry.section, VarSection::VarConfig);
        assert_eq!(entry.name, "Main.fbAxis.xLimit");
        assert_eq!(entry.address.as_deref(), Some("%IX1.0"));
    }

    #[test]
    fn broken_text_gives_diagnostics_with_ranges() {
        let text = "PROGRAM Main\nVAR\n    x : INT := ;\nEND_VAR\n";
        let errors = parse_declarations(text).unwrap_err();
        assert!(!errors.is_empty());
        let at = text.find(":= ;").unwrap();
        assert!(
            errors[0].range.start >= at && errors[0].range.start <= at + 4,
            "{errors:?}"
        );
        assert!(!errors[0].message.is_empty());
        let missing = parse_declarations("VAR\n    x INT;\nEND_VAR\n").unwrap_err();
        assert!(missing[0].message.contains("':'"), "{missing:?}");
    }

    #[test]
    fn statements_and_second_headers_are_refused_where_they_are() {
        let text = "PROGRAM Main\nVAR\n    x : INT;\nEND_VAR\nx := 1;\n";
        let errors = parse_declarations(text).unwrap_err();
        assert_eq!(&text[errors[0].range.clone()], "x := 1;");
        assert!(errors[0].message.contains("implementation"));
        let twice = "PROGRAM A\nVAR\n    x : INT;\nEND_VAR\nEND_PROGRAM\nPROGRAM B\n";
        assert!(parse_declarations(twice).is_err());
    }
}
