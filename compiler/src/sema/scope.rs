//! What a name can refer to: the project's globals and a body's locals.

use std::collections::HashMap;

use project_model::{Object, Pou, PouKind, Project, TextTarget, TypeDefinition};

use super::{closest, stdlib};
use crate::syntax::{SyntaxKind, SyntaxNode};

/// Names visible everywhere in a project: POUs, global variable lists and their variables,
/// data types and enumeration values, cam tables and axes. Keys are lower case, as IEC names
/// compare without case; values keep the spelling of the declaration for messages.
pub(crate) struct Globals<'p> {
    names: HashMap<String, &'p str>,
    pous: HashMap<String, &'p Pou>,
    types: HashMap<String, &'p str>,
    /// The members reachable as `Container.member`: variables of a GVL, values of an enum.
    members: HashMap<String, Vec<&'p str>>,
}

impl<'p> Globals<'p> {
    pub(crate) fn new(project: &'p Project) -> Self {
        let mut globals = Self {
            names: HashMap::new(),
            pous: HashMap::new(),
            types: HashMap::new(),
            members: HashMap::new(),
        };
        for object in project.application.objects() {
            globals.add_name(object.name());
            match object {
                Object::Pou(pou) => {
                    globals.pous.insert(pou.name.to_lowercase(), pou);
                    if matches!(pou.kind, PouKind::FunctionBlock | PouKind::Interface) {
                        globals.types.insert(pou.name.to_lowercase(), &pou.name);
                    }
                }
                Object::Gvl(gvl) => {
                    for variable in &gvl.variables {
                        globals.add_name(&variable.name);
                    }
                    let names = gvl.variables.iter().map(|v| v.name.as_str()).collect();
                    globals.members.insert(gvl.name.to_lowercase(), names);
                }
                Object::DataType(data_type) => {
                    globals
                        .types
                        .insert(data_type.name.to_lowercase(), &data_type.name);
                    if let TypeDefinition::Enum { values, .. } = &data_type.definition {
                        for value in values {
                            globals.add_name(&value.name);
                        }
                        let names = values.iter().map(|v| v.name.as_str()).collect();
                        globals.members.insert(data_type.name.to_lowercase(), names);
                    }
                }
                Object::CamTable(_) | Object::Trace(_) | Object::WatchList(_) => {}
            }
        }
        for axis in &project.axes {
            globals.add_name(&axis.name);
        }
        globals
    }

    fn add_name(&mut self, name: &'p str) {
        self.names.entry(name.to_lowercase()).or_insert(name);
    }

    /// Whether `name` is a global or a standard library function or function block.
    pub(crate) fn knows(&self, name: &str) -> bool {
        self.names.contains_key(&name.to_lowercase())
            || stdlib::is_function(name)
            || stdlib::is_function_block(name)
    }

    /// The members of a global variable list or enumeration called `container`, if it is one.
    pub(crate) fn members(&self, container: &str) -> Option<&[&'p str]> {
        self.members
            .get(&container.to_lowercase())
            .map(Vec::as_slice)
    }

    /// Whether `name` is a POU of the project.
    pub(crate) fn is_pou(&self, name: &str) -> bool {
        self.pous.contains_key(&name.to_lowercase())
    }

    /// The POU called `name`.
    pub(crate) fn pou(&self, name: &str) -> Option<&'p Pou> {
        self.pous.get(&name.to_lowercase()).copied()
    }

    /// Whether `name` names a type: built in, a data type, a function block or an interface.
    pub(crate) fn is_type(&self, name: &str) -> bool {
        stdlib::is_built_in_type(name) || self.types.contains_key(&name.to_lowercase())
    }

    /// A declared global or type close to `name`, for "did you mean".
    pub(crate) fn suggest(&self, name: &str) -> Option<String> {
        let mut candidates: Vec<&str> = self
            .names
            .values()
            .chain(self.types.values())
            .copied()
            .collect();
        for standard in stdlib::all_names() {
            candidates.push(standard);
        }
        closest(name, candidates.into_iter()).map(str::to_owned)
    }
}

/// The names visible in one body: the POU's declarations and members, inherited ones, those of
/// the method or accessor the body belongs to, and SFC steps and actions declared in the text.
pub(crate) struct Scope<'a> {
    pub(crate) globals: &'a Globals<'a>,
    locals: HashMap<String, String>,
}

/// How many `EXTENDS` levels are followed; deeper chains (or cycles) stop there.
const MAX_INHERITANCE: usize = 32;

impl<'a> Scope<'a> {
    pub(crate) fn for_body(
        globals: &'a Globals<'a>,
        pou: &Pou,
        target: &TextTarget,
        root: &SyntaxNode,
    ) -> Self {
        let mut scope = Self {
            globals,
            locals: HashMap::new(),
        };
        scope.add_pou(pou);
        let mut base = pou.extends.clone();
        for _ in 0..MAX_INHERITANCE {
            let Some(parent) = base.as_deref().and_then(|name| globals.pou(name)) else {
                break;
            };
            scope.add_pou(parent);
            base = parent.extends.clone();
        }
        match target {
            TextTarget::Method { method, .. } => {
                if let Some(method) = pou.methods.iter().find(|m| m.name == *method) {
                    scope.add(&method.name);
                    for variable in &method.variables {
                        scope.add(&variable.name);
                    }
                }
            }
            TextTarget::Property { property, get, .. } => {
                if let Some(property) = pou.properties.iter().find(|p| p.name == *property) {
                    scope.add(&property.name);
                    let accessor = if *get { &property.get } else { &property.set };
                    for variable in accessor.iter().flat_map(|a| &a.variables) {
                        scope.add(&variable.name);
                    }
                }
            }
            TextTarget::Pou(_) | TextTarget::Action { .. } => {}
        }
        // Textual SFC: steps (for `Step.X`, `Step.T`) and actions declared in the body.
        for node in root.descendants() {
            if matches!(node.kind(), SyntaxKind::STEP_DECL | SyntaxKind::ACTION_DECL)
                && let Some(name) = node
                    .children()
                    .find(|child| child.kind() == SyntaxKind::NAME)
            {
                scope.add(name.text().to_string().trim());
            }
        }
        scope
    }

    fn add_pou(&mut self, pou: &Pou) {
        self.add(&pou.name);
        for variable in &pou.variables {
            self.add(&variable.name);
        }
        for method in &pou.methods {
            self.add(&method.name);
        }
        for property in &pou.properties {
            self.add(&property.name);
        }
        for action in &pou.actions {
            self.add(&action.name);
        }
    }

    fn add(&mut self, name: &str) {
        self.locals
            .entry(name.to_lowercase())
            .or_insert_with(|| name.to_owned());
    }

    /// Whether `name` is declared in this body's POU (which hides globals of the same name).
    pub(crate) fn is_local(&self, name: &str) -> bool {
        self.locals.contains_key(&name.to_lowercase())
    }

    /// Whether `name` is declared here or globally.
    pub(crate) fn knows(&self, name: &str) -> bool {
        self.locals.contains_key(&name.to_lowercase()) || self.globals.knows(name)
    }

    /// A local or global name close to `name`.
    pub(crate) fn suggest(&self, name: &str) -> Option<String> {
        let local = closest(name, self.locals.values().map(String::as_str)).map(str::to_owned);
        local.or_else(|| self.globals.suggest(name))
    }
}
