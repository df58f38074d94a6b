//! A project built from one Structured Text source file, so a plain `.st` file (a text export,
//! a library, a test case) is checked exactly like a project folder.
//!
//! Every POU, method, property accessor and action of the file becomes an object of the project
//! model with its ST body as a slice of the file; `TYPE` blocks become data types and
//! `VAR_GLOBAL` blocks global variable lists. The project remembers where each body and each
//! declaration came from, so a finding about the project is reported at its place in the file.

use std::collections::HashMap;
use std::ops::Range;
use std::path::PathBuf;

use project_model::{
    Body, DataType, EnumValue, Method, Node, Object, Pou, PouAction, PouKind, Project, Property,
    PropertyAccessor, StructMember, TypeDefinition, VarSection, Variable,
};

use crate::declaration_parts::{access_of, block_section, declaration_parts};
use crate::sema::ProjectDiagnostic;
use crate::syntax::ast::{
    self, AstNode, ExtendsClause, GlobalVarList, InterfaceDecl, Item, MethodDecl, Name, PouMember,
    PropertyDecl, SourceFile, StatementList, TypeDecl, TypeExpr, VarBlock, VarDecl,
};
use crate::syntax::{Parse, SyntaxKind, SyntaxNode, parse};

/// A project made from one source file, with the way back from the project to the file.
#[derive(Debug)]
pub struct SourceProject {
    /// The project.
    pub project: Project,
    /// The parse of the whole file, with its syntax errors.
    pub parse: Parse,
    /// What the file holds that a project cannot: a POU or type declared twice (the second is
    /// left out of the project).
    pub diagnostics: Vec<crate::Diagnostic>,
    /// Where each body file's text starts in the source.
    body_offsets: HashMap<PathBuf, usize>,
    /// Where each declared name is in the source: (object name, declared name), lower case.
    declarations: HashMap<(String, String), Range<usize>>,
    /// The object each project file belongs to.
    file_objects: HashMap<PathBuf, String>,
}

impl SourceProject {
    /// Builds the project of `text`. It never fails: what does not parse is left out of the
    /// project and reported by [`SourceProject::parse`].
    pub fn new(text: &str) -> Self {
        let parse = parse(text);
        let mut builder = Builder::default();
        let items = SourceFile::cast(parse.syntax())
            .into_iter()
            .flat_map(|file| file.items());
        for item in items {
            match item {
                Item::Pou(pou) => builder.pou(&pou),
                Item::InterfaceDecl(interface) => builder.interface(&interface),
                Item::TypeDecl(types) => builder.types(&types),
                Item::GlobalVarList(list) => builder.globals(&list),
                _ => {}
            }
        }
        let mut project = Project {
            name: "source".to_owned(),
            ..Project::default()
        };
        project.application.children = builder.objects.into_iter().map(Node::Object).collect();
        let mut body_offsets = HashMap::new();
        for body in project_model::st_body_files(&project) {
            let key = (body.pou.name.to_lowercase(), target_key(&body.target));
            if let Some(offset) = builder.body_offsets.get(&key) {
                body_offsets.insert(body.file.clone(), *offset);
            }
        }
        let file_objects = project_model::object_files(&project)
            .into_iter()
            .map(|(file, object)| (file, object.name().to_lowercase()))
            .collect();
        Self {
            project,
            parse,
            diagnostics: builder.diagnostics,
            body_offsets,
            declarations: builder.declarations,
            file_objects,
        }
    }

    /// Where in the source a finding about the project is: the body text shifted to its place,
    /// or the declaration it names. `None` for findings about things the file does not hold.
    pub fn locate(&self, diagnostic: &ProjectDiagnostic) -> Option<Range<usize>> {
        if let Some(name) = &diagnostic.declaration {
            let object = self.file_objects.get(&diagnostic.file)?;
            let repeated = diagnostic.diagnostic.code == crate::Code::DuplicateName;
            let exact = if repeated {
                format!("last={name}")
            } else {
                format!("={name}")
            };
            return self
                .declarations
                .get(&(object.clone(), exact))
                .or_else(|| {
                    self.declarations
                        .get(&(object.clone(), name.to_lowercase()))
                })
                .cloned();
        }
        let offset = self.body_offsets.get(&diagnostic.file)?;
        let range = &diagnostic.diagnostic.range;
        Some(range.start + offset..range.end + offset)
    }

    /// The 1-based line of the source on which the text of the body file `file` starts.
    pub fn body_first_line(&self, file: &std::path::Path) -> Option<u32> {
        let offset = *self.body_offsets.get(file)?;
        let text = self.parse.syntax().text().to_string();
        let before = text.get(..offset)?;
        Some(before.matches('\n').count() as u32 + 1)
    }
}

fn target_key(target: &project_model::TextTarget) -> String {
    use project_model::TextTarget;
    match target {
        TextTarget::Pou(_) => String::new(),
        TextTarget::Method { method, .. } => format!("method {}", method.to_lowercase()),
        TextTarget::Property { property, get, .. } => {
            format!("property {} {get}", property.to_lowercase())
        }
        TextTarget::Action { action, .. } => format!("action {}", action.to_lowercase()),
        TextTarget::Transition { transition, .. } => {
            format!("transition {}", transition.to_lowercase())
        }
    }
}

/// Collects objects while walking the tree.
#[derive(Default)]
struct Builder {
    objects: Vec<Object>,
    /// (POU name, target key) → offset of the body text.
    body_offsets: HashMap<(String, String), usize>,
    declarations: HashMap<(String, String), Range<usize>>,
    global_lists: usize,
    /// Names of the objects so far, lower case.
    object_names: std::collections::HashSet<String>,
    diagnostics: Vec<crate::Diagnostic>,
}

impl Builder {
    /// Takes `name` for a new object; a name already taken is reported and refused.
    fn claim(&mut self, name: &str, range: Range<usize>) -> bool {
        if self.object_names.insert(name.to_lowercase()) {
            return true;
        }
        self.diagnostics.push(crate::Diagnostic::new(
            crate::Code::DuplicateName,
            range,
            format!(
                "'{name}' is declared twice in this file; the second declaration is not checked"
            ),
        ));
        false
    }

    fn declare(&mut self, object: &str, name: &str, range: Range<usize>) {
        // By exact spelling (so `XTWICE` declared after `xTwice` is found as itself) and
        // without case.
        self.declarations
            .entry((object.to_lowercase(), format!("={name}")))
            .or_insert(range.clone());
        // The last one too: a name declared twice is reported where it is repeated.
        self.declarations.insert(
            (object.to_lowercase(), format!("last={name}")),
            range.clone(),
        );
        self.declarations
            .entry((object.to_lowercase(), name.to_lowercase()))
            .or_insert(range);
    }

    fn pou(&mut self, node: &ast::Pou) {
        let kind = match node.keyword().map(|keyword| keyword.kind()) {
            Some(SyntaxKind::PROGRAM) => PouKind::Program,
            Some(SyntaxKind::FUNCTION_BLOCK) => PouKind::FunctionBlock,
            Some(SyntaxKind::FUNCTION) => PouKind::Function,
            _ => return,
        };
        let Some((name, name_range)) = name_of(node.name()) else {
            return;
        };
        if !self.claim(&name, name_range.clone()) {
            return;
        }
        self.declare(&name, &name, name_range);
        let mut pou = Pou {
            name: name.clone(),
            kind,
            return_type: node.return_type().map(|ty| trimmed(ty.syntax())),
            extends: node.extends().and_then(|clause| first_name(&clause)),
            implements: node
                .implements()
                .map(|clause| clause.names().map(|name| trimmed(name.syntax())).collect())
                .unwrap_or_default(),
            comment: String::new(),
            variables: Vec::new(),
            body: Body::st(""),
            methods: Vec::new(),
            properties: Vec::new(),
            actions: Vec::new(),
            transitions: Vec::new(),
        };
        for block in node.var_blocks() {
            pou.variables.extend(self.variables(&name, &block));
        }
        // A body split by members (textual SFC) is taken from its first part with text.
        if let Some(list) = node.bodies().find(|list| !is_blank(list.syntax())) {
            pou.body = Body::st(list.syntax().text().to_string());
            self.body_offsets
                .insert((name.to_lowercase(), String::new()), start(list.syntax()));
        }
        self.members(&mut pou, node.members());
        self.objects.push(Object::Pou(pou));
    }

    fn interface(&mut self, node: &InterfaceDecl) {
        let Some((name, name_range)) = name_of(node.name()) else {
            return;
        };
        if !self.claim(&name, name_range.clone()) {
            return;
        }
        self.declare(&name, &name, name_range);
        let mut interface = Pou {
            name,
            kind: PouKind::Interface,
            return_type: None,
            extends: node.extends().and_then(|clause| first_name(&clause)),
            implements: Vec::new(),
            comment: String::new(),
            variables: Vec::new(),
            body: Body::None,
            methods: Vec::new(),
            properties: Vec::new(),
            actions: Vec::new(),
            transitions: Vec::new(),
        };
        self.members(&mut interface, node.members());
        self.objects.push(Object::Pou(interface));
    }

    /// The methods, properties and actions of `pou`, in the order written (which is the
    /// order their names are declared in).
    fn members(&mut self, pou: &mut Pou, members: impl Iterator<Item = PouMember>) {
        let name = pou.name.clone();
        for member in members {
            match member {
                PouMember::MethodDecl(method) => {
                    if let Some(method) = self.method(&name, &method) {
                        pou.methods.push(method);
                    }
                }
                PouMember::PropertyDecl(property) => {
                    if let Some(property) = self.property(&name, &property) {
                        pou.properties.push(property);
                    }
                }
                PouMember::ActionDecl(action) => {
                    if let Some((action_name, range)) = name_of(action.name()) {
                        self.declare(&name, &action_name, range);
                        let (body, offset) = statements_of(action.body());
                        if let Some(offset) = offset {
                            let key = format!("action {}", action_name.to_lowercase());
                            self.body_offsets.insert((name.to_lowercase(), key), offset);
                        }
                        pou.actions.push(PouAction {
                            name: action_name,
                            body,
                        });
                    }
                }
            }
        }
    }

    fn method(&mut self, pou: &str, node: &MethodDecl) -> Option<Method> {
        let (name, range) = name_of(node.name())?;
        self.declare(pou, &name, range);
        let mut variables = Vec::new();
        for block in node.var_blocks() {
            variables.extend(self.variables(pou, &block));
        }
        let (body, offset) = statements_of(node.body());
        if let Some(offset) = offset {
            let key = format!("method {}", name.to_lowercase());
            self.body_offsets.insert((pou.to_lowercase(), key), offset);
        }
        Some(Method {
            return_type: node.return_type().map(|ty| trimmed(ty.syntax())),
            access: access_of(node.modifiers()),
            is_abstract: node.modifiers().any(|kind| kind == SyntaxKind::ABSTRACT),
            comment: String::new(),
            variables,
            body,
            name,
        })
    }

    fn property(&mut self, pou: &str, node: &PropertyDecl) -> Option<Property> {
        let (name, range) = name_of(node.name())?;
        self.declare(pou, &name, range);
        let mut property = Property {
            ty: node.ty().map(|ty| trimmed(ty.syntax())).unwrap_or_default(),
            access: access_of(node.modifiers()),
            comment: String::new(),
            get: None,
            set: None,
            name: name.clone(),
        };
        for accessor in node.accessors() {
            let get = accessor.is_get();
            let mut variables = Vec::new();
            for block in accessor.var_blocks() {
                variables.extend(self.variables(pou, &block));
            }
            let (body, offset) = statements_of(accessor.body());
            if let Some(offset) = offset {
                let key = format!("property {} {get}", name.to_lowercase());
                self.body_offsets.insert((pou.to_lowercase(), key), offset);
            }
            let slot = if get {
                &mut property.get
            } else {
                &mut property.set
            };
            *slot = Some(PropertyAccessor { variables, body });
        }
        Some(property)
    }

    fn types(&mut self, node: &TypeDecl) {
        for definition in node.definitions() {
            let Some((name, range)) = name_of(definition.name()) else {
                continue;
            };
            if !self.claim(&name, range.clone()) {
                continue;
            }
            self.declare(&name, &name, range);
            let extends = definition.extends().and_then(|clause| first_name(&clause));
            let definition_model = if let Some(structure) = definition.struct_type() {
                TypeDefinition::Struct {
                    extends,
                    members: self.struct_members(&name, structure.members()),
                }
            } else if let Some(union) = definition.union_type() {
                TypeDefinition::Union {
                    members: self.struct_members(&name, union.members()),
                }
            } else if let Some(TypeExpr::EnumType(shape)) = definition.ty() {
                let mut values = Vec::new();
                for value in shape.values() {
                    let Some((value_name, range)) = name_of(value.name()) else {
                        continue;
                    };
                    self.declare(&name, &value_name, range);
                    values.push(EnumValue {
                        name: value_name,
                        value: value.value().map(|number| trimmed(number.syntax())),
                        comment: String::new(),
                    });
                }
                let base = shape.base().map(|base| trimmed(base.syntax()));
                TypeDefinition::Enum { base, values }
            } else if let Some(ty) = definition.ty() {
                TypeDefinition::Alias {
                    ty: trimmed(ty.syntax()),
                    initial: definition
                        .initializer()
                        .and_then(|initializer| initializer.value())
                        .map(|value| trimmed(value.syntax())),
                }
            } else {
                continue;
            };
            self.objects.push(Object::DataType(DataType {
                name,
                comment: String::new(),
                definition: definition_model,
            }));
        }
    }

    fn struct_members(
        &mut self,
        type_name: &str,
        declarations: impl Iterator<Item = VarDecl>,
    ) -> Vec<StructMember> {
        let mut members = Vec::new();
        for declaration in declarations {
            for variable in self.declared(type_name, &declaration, VarSection::Var) {
                members.push(StructMember {
                    name: variable.name,
                    ty: variable.ty,
                    initial: variable.initial,
                    comment: String::new(),
                });
            }
        }
        members
    }

    fn globals(&mut self, node: &GlobalVarList) {
        self.global_lists += 1;
        let mut name = if self.global_lists == 1 {
            "GVL".to_owned()
        } else {
            format!("GVL_{}", self.global_lists)
        };
        // A POU or type of the file may already be called so.
        while !self.object_names.insert(name.to_lowercase()) {
            name.push('_');
        }
        let mut variables = Vec::new();
        for block in node.var_blocks() {
            variables.extend(self.variables(&name, &block));
        }
        self.objects.push(Object::Gvl(project_model::GlobalVarList {
            name,
            comment: String::new(),
            variables,
        }));
    }

    /// The variables of one `VAR… END_VAR` section.
    fn variables(&mut self, object: &str, block: &VarBlock) -> Vec<Variable> {
        let section = match block_section(block) {
            // Configuration and access paths name other variables; they declare none.
            None | Some(VarSection::VarConfig) => return Vec::new(),
            Some(section) => section,
        };
        let constant = block.is_constant();
        let retain = block.has_retain_keyword();
        let persistent = block.has_persistent_keyword();
        let mut variables = Vec::new();
        for declaration in block.declarations() {
            for mut variable in self.declared(object, &declaration, section) {
                variable.constant = constant;
                variable.retain = retain;
                variable.persistent = persistent;
                variables.push(variable);
            }
        }
        variables
    }

    /// The variables of one declaration `a, b AT %IX0.0 : BOOL := TRUE;`.
    fn declared(
        &mut self,
        object: &str,
        declaration: &VarDecl,
        section: VarSection,
    ) -> Vec<Variable> {
        let mut variables = Vec::new();
        let Some(parts) = declaration_parts(declaration, trimmed) else {
            return variables;
        };
        for name in &parts.names {
            let text = trimmed(name.syntax());
            self.declare(object, &text, range(name.syntax()));
            variables.push(Variable {
                name: text,
                section,
                ty: parts.ty.clone(),
                initial: parts.initial.clone(),
                address: parts.address.clone(),
                ..Variable::default()
            });
        }
        variables
    }
}

/// The statements of a method, accessor or action with the offset where they start.
fn statements_of(list: Option<StatementList>) -> (Body, Option<usize>) {
    match list {
        Some(list) => (
            Body::st(list.syntax().text().to_string()),
            Some(start(list.syntax())),
        ),
        None => (Body::st(""), None),
    }
}

/// A declared name's text and range, unless it is missing or blank.
fn name_of(name: Option<Name>) -> Option<(String, Range<usize>)> {
    let name = name?;
    let text = trimmed(name.syntax());
    (!text.is_empty()).then(|| (text, range(name.syntax())))
}

/// The first name of an `EXTENDS` clause: a POU or structure has one base.
fn first_name(clause: &ExtendsClause) -> Option<String> {
    clause.names().next().map(|name| trimmed(name.syntax()))
}

fn is_blank(node: &SyntaxNode) -> bool {
    node.text().to_string().trim().is_empty()
}

fn trimmed(node: &SyntaxNode) -> String {
    node.text().to_string().trim().to_owned()
}

fn start(node: &SyntaxNode) -> usize {
    usize::from(node.text_range().start())
}

fn range(node: &SyntaxNode) -> Range<usize> {
    let range = node.text_range();
    usize::from(range.start())..usize::from(range.end())
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::AccessSpecifier;

    const SOURCE: &str = "TYPE
    E_State : (Idle := 0, Run, Fault) DINT;
    ST_Point : STRUCT x : REAL; y : REAL := 1.5; END_STRUCT;
END_TYPE
VAR_GLOBAL CONSTANT
    N : INT := 10;
END_VAR
FUNCTION_BLOCK FB_A EXTENDS FB_B
VAR_INPUT
    a, b AT %IX0.0 : BOOL := TRUE;
END_VAR
a := b;
METHOD PRIVATE M : INT
VAR_INPUT k : INT; END_VAR
M := k;
END_METHOD
PROPERTY P : INT
GET
P := 1;
END_GET
END_PROPERTY
ACTION Act:
a := FALSE;
END_ACTION
END_FUNCTION_BLOCK
";

    #[test]
    fn every_kind_of_declaration_becomes_an_object() {
        let source = SourceProject::new(SOURCE);
        assert!(
            source.parse.errors().is_empty(),
            "{:?}",
            source.parse.errors()
        );
        let app = &source.project.application;
        let Some(Object::DataType(state)) = app.object("E_State") else {
            panic!("no enum");
        };
        assert!(matches!(
            &state.definition,
            TypeDefinition::Enum { base: Some(base), values } if base == "DINT" && values.len() == 3
        ));
        let Some(Object::Gvl(gvl)) = app.object("GVL") else {
            panic!("no GVL");
        };
        assert!(gvl.variables[0].constant);
        assert_eq!(gvl.variables[0].initial.as_deref(), Some("10"));
        let Some(Object::Pou(fb)) = app.object("FB_A") else {
            panic!("no FB");
        };
        assert_eq!(fb.extends.as_deref(), Some("FB_B"));
        assert_eq!(fb.variables.len(), 2);
        assert_eq!(fb.variables[1].address.as_deref(), Some("%IX0.0"));
        assert_eq!(fb.body.st_text(), Some("a := b;"));
        assert_eq!(fb.methods[0].access, AccessSpecifier::Private);
        assert_eq!(fb.methods[0].return_type.as_deref(), Some("INT"));
        assert!(fb.properties[0].get.is_some() && fb.properties[0].set.is_none());
        assert_eq!(fb.actions[0].body.st_text(), Some("a := FALSE;"));
    }

    #[test]
    fn findings_in_bodies_and_declarations_map_back_to_the_file() {
        let source = SourceProject::new(SOURCE);
        for body in project_model::st_body_files(&source.project) {
            let finding = ProjectDiagnostic {
                file: body.file.clone(),
                declaration: None,
                element: None,
                diagnostic: crate::Diagnostic::new(crate::Code::UnknownName, 0..1, "x"),
            };
            let at = source.locate(&finding).expect("every body maps back");
            assert!(SOURCE[at.start..].starts_with(body.text));
        }
        let (file, _) = project_model::object_files(&source.project)
            .into_iter()
            .find(|(_, object)| object.name() == "FB_A")
            .expect("FB_A has a file");
        let finding = ProjectDiagnostic {
            file,
            declaration: Some("b".to_owned()),
            element: None,
            diagnostic: crate::Diagnostic::new(crate::Code::UnknownType, 0..0, "x"),
        };
        let at = source.locate(&finding).expect("declarations map back");
        assert_eq!(&SOURCE[at], "b");
    }

    #[test]
    fn a_structure_extending_another_is_a_structure_with_its_base() {
        let source = SourceProject::new(
            "TYPE
    ST_A : STRUCT a : INT; END_STRUCT;
    \
             ST_B EXTENDS ST_A : STRUCT b : INT; END_STRUCT;
END_TYPE
\
             PROGRAM Main
VAR s : ST_B; END_VAR
s.b := s.a;
END_PROGRAM
",
        );
        let Some(Object::DataType(extended)) = source.project.application.object("ST_B") else {
            panic!("no ST_B");
        };
        let TypeDefinition::Struct { extends, members } = &extended.definition else {
            panic!("ST_B is no structure: {:?}", extended.definition);
        };
        assert_eq!(extends.as_deref(), Some("ST_A"));
        let names: Vec<&str> = members.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["b"]);
        let errors: Vec<String> = crate::sema::check_project(&source.project)
            .into_iter()
            .filter(|found| found.diagnostic.severity == crate::Severity::Error)
            .map(|found| found.diagnostic.message)
            .collect();
        assert_eq!(errors, Vec::<String>::new());
    }
}
