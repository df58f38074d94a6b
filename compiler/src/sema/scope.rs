//! What a name can refer to: the project's globals and a body's locals, as symbols that know
//! their declarations.

use std::borrow::Cow;
use std::cell::RefCell;

use rustc_hash::FxHashMap;

use project_model::{
    DataType, GlobalVarList, Method, Object, Pou, PouKind, Project, Property, TextTarget,
    TypeDefinition, VarSection, Variable,
};

use super::ty::Type;
use super::{closest, stdlib, types};
use crate::syntax::SyntaxNode;
use crate::syntax::ast::{ActionDecl, AstNode, StepDecl, TransitionDecl};

/// What a global name stands for.
#[derive(Clone, Copy, Debug)]
pub(crate) enum GlobalSymbol<'p> {
    /// A variable of a global variable list.
    Var(&'p Variable),
    /// A program, function block, function or interface.
    Pou(&'p Pou),
    /// A global variable list, as the container of `GVL.x`.
    Gvl(&'p GlobalVarList),
    /// A data type.
    DataType(&'p DataType),
    /// A value of the enumeration.
    EnumValue(&'p DataType),
    /// A motion axis of the device tree: a global `AXIS_REF`.
    Axis,
    /// A cam table of the application: a global `MC_CAM_REF`.
    Cam,
}

/// Names visible everywhere in a project: POUs, global variable lists and their variables,
/// data types and enumeration values, and axes. Keys are lower case, as IEC names compare
/// without case.
pub(crate) struct Globals<'p> {
    names: FxHashMap<String, GlobalSymbol<'p>>,
    pous: FxHashMap<String, &'p Pou>,
    data_types: FxHashMap<String, &'p DataType>,
    /// Resolved type texts, as the same few type texts are declared many times.
    type_cache: RefCell<FxHashMap<String, Type>>,
    /// Spellings of every global name, for suggestions.
    spellings: Vec<&'p str>,
    /// Whether CODESYS's leniencies apply (`docs/dialect.md`).
    pub(crate) dialect: project_model::Dialect,
}

impl<'p> Globals<'p> {
    pub(crate) fn new(project: &'p Project) -> Self {
        let mut globals = Self {
            names: FxHashMap::default(),
            pous: FxHashMap::default(),
            data_types: FxHashMap::default(),
            type_cache: RefCell::new(FxHashMap::default()),
            spellings: Vec::new(),
            dialect: project.dialect,
        };
        let objects = project.application.objects();
        // Variables first: a variable wins over an enumeration value of the same name, as an
        // unqualified value is the last resort in CODESYS too.
        for object in &objects {
            match object {
                Object::Gvl(gvl) => {
                    for variable in &gvl.variables {
                        globals.add(&variable.name, GlobalSymbol::Var(variable));
                    }
                }
                // A cam table is a global MC_CAM_REF, so it is a variable too.
                Object::CamTable(cam) => globals.add(&cam.name, GlobalSymbol::Cam),
                _ => {}
            }
        }
        // An axis is a global AXIS_REF.
        for axis in &project.axes {
            globals.add(&axis.name, GlobalSymbol::Axis);
        }
        for object in &objects {
            match object {
                Object::Pou(pou) => {
                    globals.pous.insert(pou.name.to_lowercase(), pou);
                    globals.add(&pou.name, GlobalSymbol::Pou(pou));
                }
                Object::Gvl(gvl) => globals.add(&gvl.name, GlobalSymbol::Gvl(gvl)),
                Object::DataType(data_type) => {
                    globals
                        .data_types
                        .insert(data_type.name.to_lowercase(), data_type);
                    globals.add(&data_type.name, GlobalSymbol::DataType(data_type));
                }
                Object::CamTable(_) | Object::Trace(_) | Object::WatchList(_) => {}
            }
        }
        // The libraries' POUs and types come after the project's own, which win a clash.
        let libraries = crate::library::objects();
        for object in &libraries {
            match object {
                Object::Pou(pou) => {
                    globals.pous.entry(pou.name.to_lowercase()).or_insert(pou);
                    globals.add(&pou.name, GlobalSymbol::Pou(pou));
                }
                Object::DataType(data_type) => {
                    globals
                        .data_types
                        .entry(data_type.name.to_lowercase())
                        .or_insert(data_type);
                    globals.add(&data_type.name, GlobalSymbol::DataType(data_type));
                }
                _ => {}
            }
        }
        for object in objects.iter().chain(&libraries) {
            if let Object::DataType(data_type) = object
                && let TypeDefinition::Enum { values, .. } = &data_type.definition
            {
                for value in values {
                    globals.add(&value.name, GlobalSymbol::EnumValue(data_type));
                }
            }
        }
        globals
    }

    fn add(&mut self, name: &'p str, symbol: GlobalSymbol<'p>) {
        self.spellings.push(name);
        self.names.entry(name.to_lowercase()).or_insert(symbol);
    }

    /// The global called `name`.
    pub(crate) fn lookup(&self, name: &str) -> Option<GlobalSymbol<'p>> {
        self.names.get(lower(name).as_ref()).copied()
    }

    /// The names of every global variable list.
    pub(crate) fn gvl_names(&self) -> Vec<&'p str> {
        self.names
            .values()
            .filter_map(|symbol| match symbol {
                GlobalSymbol::Gvl(gvl) => Some(gvl.name.as_str()),
                _ => None,
            })
            .collect()
    }

    /// Whether `name` is a POU of the project.
    pub(crate) fn is_pou(&self, name: &str) -> bool {
        self.pous.contains_key(&name.to_lowercase())
    }

    /// The POU called `name`.
    pub(crate) fn pou(&self, name: &str) -> Option<&'p Pou> {
        self.pous.get(&name.to_lowercase()).copied()
    }

    /// The data type called `name`.
    pub(crate) fn data_type(&self, name: &str) -> Option<&'p DataType> {
        self.data_types.get(&name.to_lowercase()).copied()
    }

    /// Whether `name` names a type: built in, a data type, a function block or an interface.
    pub(crate) fn is_type(&self, name: &str) -> bool {
        stdlib::is_built_in_type(name)
            || self.data_types.contains_key(&name.to_lowercase())
            || self
                .pou(name)
                .is_some_and(|pou| matches!(pou.kind, PouKind::FunctionBlock | PouKind::Interface))
    }

    /// The type written as `text`, resolved once per distinct text.
    pub(crate) fn resolve_type(&self, text: &str) -> Type {
        if let Some(ty) = self.type_cache.borrow().get(text) {
            return ty.clone();
        }
        let ty = types::resolve_type_text(self, text);
        self.type_cache
            .borrow_mut()
            .insert(text.to_owned(), ty.clone());
        ty
    }

    /// The members of a global variable list or enumeration called `container`, for messages.
    pub(crate) fn member_names(&self, container: &str) -> Vec<&'p str> {
        match self.lookup(container) {
            Some(GlobalSymbol::Gvl(gvl)) => gvl.variables.iter().map(|v| v.name.as_str()).collect(),
            Some(GlobalSymbol::DataType(data_type)) => match &data_type.definition {
                TypeDefinition::Enum { values, .. } => {
                    values.iter().map(|v| v.name.as_str()).collect()
                }
                TypeDefinition::Struct { members, .. } | TypeDefinition::Union { members } => {
                    members.iter().map(|m| m.name.as_str()).collect()
                }
                TypeDefinition::Alias { .. } => Vec::new(),
            },
            _ => Vec::new(),
        }
    }

    /// A declared global or type close to `name`, for "did you mean".
    pub(crate) fn suggest(&self, name: &str) -> Option<String> {
        let candidates = self
            .spellings
            .iter()
            .copied()
            .chain(stdlib::all_names().map(|name| -> &'p str { name }));
        closest(name, candidates).map(str::to_owned)
    }
}

/// What a name declared in or for one body stands for.
#[derive(Clone, Copy, Debug)]
pub(crate) enum LocalSymbol<'p> {
    /// A variable of the POU, of a base function block, or of the method or accessor.
    Var(&'p Variable),
    /// The function's, method's or property's own name inside its body: its result.
    Result(&'p str),
    /// A method of the POU or a base.
    Method(&'p Method),
    /// A property of the POU or a base.
    Property(&'p Property),
    /// An action of the POU.
    Action,
    /// A step of a textual SFC.
    Step,
    /// The flags `_Action.x`, `_Action._x` of an action associated in a textual SFC.
    SfcAction,
    /// The value of a textual SFC transition written with statements, which assign it.
    TransitionValue,
}

/// The names visible in one body: the POU's declarations and members, inherited ones, those of
/// the method or accessor the body belongs to, and SFC steps and actions declared in the text.
pub(crate) struct Scope<'a, 'p> {
    pub(crate) globals: &'a Globals<'p>,
    /// The POU the body belongs to; `None` for global declarations.
    pub(crate) pou: Option<&'p Pou>,
    locals: FxHashMap<String, LocalSymbol<'p>>,
    /// The type of the body's result variable (a function's, method's or property's name).
    pub(crate) result_type: Option<&'p str>,
    spellings: Vec<String>,
    /// Whether the body may hold an SFC chart: only the body of the POU itself keeps the
    /// chart's state in its instance, not a method, accessor or action.
    pub(crate) chart_allowed: bool,
}

/// How many `EXTENDS` levels are followed; deeper chains (or cycles) stop there.
pub(crate) const MAX_INHERITANCE: usize = 32;

impl<'a, 'p> Scope<'a, 'p> {
    pub(crate) fn for_body(
        globals: &'a Globals<'p>,
        pou: &'p Pou,
        target: &TextTarget,
        root: &SyntaxNode,
    ) -> Self {
        let mut scope = Self {
            globals,
            pou: Some(pou),
            locals: FxHashMap::default(),
            result_type: None,
            spellings: Vec::new(),
            chart_allowed: false,
        };
        // The innermost declarations first: a method's locals hide the POU's variables.
        match target {
            TextTarget::Method { method, .. } => {
                if let Some(method) = pou.methods.iter().find(|m| m.name == *method) {
                    if let Some(ty) = &method.return_type {
                        scope.add(&method.name, LocalSymbol::Result(ty));
                        scope.result_type = Some(ty);
                    }
                    for variable in &method.variables {
                        scope.add(&variable.name, LocalSymbol::Var(variable));
                    }
                }
            }
            TextTarget::Property { property, get, .. } => {
                if let Some(property) = pou.properties.iter().find(|p| p.name == *property) {
                    scope.add(&property.name, LocalSymbol::Result(&property.ty));
                    scope.result_type = Some(&property.ty);
                    let accessor = if *get { &property.get } else { &property.set };
                    for variable in accessor.iter().flat_map(|a| &a.variables) {
                        scope.add(&variable.name, LocalSymbol::Var(variable));
                    }
                }
            }
            TextTarget::Pou(_) => scope.chart_allowed = true,
            // A transition object's body computes a BOOL named after it (it compiles into a
            // method returning BOOL).
            TextTarget::Transition { transition, .. } => {
                if let Some(transition) = pou.transitions.iter().find(|t| t.name == *transition) {
                    scope.add(&transition.name, LocalSymbol::Result("BOOL"));
                    scope.result_type = Some("BOOL");
                }
            }
            TextTarget::Action { .. } => {}
        }
        if let Some(ty) = &pou.return_type
            && pou.kind == PouKind::Function
        {
            scope.add(&pou.name, LocalSymbol::Result(ty));
            scope.result_type = scope.result_type.or(Some(ty));
        }
        for current in inheritance_chain(globals, pou) {
            scope.add_pou(current);
        }
        // Textual SFC: steps (for `Step.X`, `Step.T`) and actions declared in the body, or
        // in the POU's body when this is one of its actions.
        let pou_body = match target {
            TextTarget::Action { .. } => pou
                .body
                .st_text()
                .filter(|text| text.to_ascii_uppercase().contains("STEP"))
                .map(|text| crate::syntax::parse_statements(text).syntax()),
            _ => None,
        };
        for node in root
            .descendants()
            .chain(pou_body.iter().flat_map(SyntaxNode::descendants))
        {
            let (name, symbol) = if let Some(step) = StepDecl::cast(node.clone()) {
                (step.name(), LocalSymbol::Step)
            } else if let Some(transition) = TransitionDecl::cast(node.clone()) {
                // `TRANSITION Name FROM a TO b : Name := …; END_TRANSITION`: the statements
                // compute the transition's value by assigning its name.
                if transition.condition().is_some() {
                    continue;
                }
                (transition.name(), LocalSymbol::TransitionValue)
            } else if let Some(action) = ActionDecl::cast(node) {
                (action.name(), LocalSymbol::Action)
            } else {
                continue;
            };
            if let Some(name) = name {
                scope.add(&name.text(), symbol);
            }
        }
        // The flags of every action the chart associates, `_Fill.x`, as CODESYS declares them.
        let associated: Vec<String> = root
            .descendants()
            .chain(pou_body.iter().flat_map(SyntaxNode::descendants))
            .filter_map(StepDecl::cast)
            .flat_map(|step| step.statements())
            .filter_map(|statement| match statement {
                crate::syntax::ast::Stmt::CallStmt(call) => call.call()?.callee(),
                _ => None,
            })
            .map(|callee| callee.syntax().text().to_string().trim().to_owned())
            .collect();
        for action in associated {
            let flags = format!("_{action}");
            if scope.local(&flags).is_none() {
                scope.add(&flags, LocalSymbol::SfcAction);
            }
        }
        scope
    }

    /// The scope of a POU's declarations (initial values may use its constants).
    pub(crate) fn for_declarations(globals: &'a Globals<'p>, pou: &'p Pou) -> Self {
        let mut scope = Self::globals_only(globals);
        scope.pou = Some(pou);
        for current in inheritance_chain(globals, pou) {
            scope.add_pou(current);
        }
        scope
    }

    /// A scope with only the globals, for declarations outside any POU.
    pub(crate) fn globals_only(globals: &'a Globals<'p>) -> Self {
        Self {
            globals,
            pou: None,
            locals: FxHashMap::default(),
            result_type: None,
            spellings: Vec::new(),
            chart_allowed: false,
        }
    }

    fn add_pou(&mut self, pou: &'p Pou) {
        for variable in &pou.variables {
            self.add(&variable.name, LocalSymbol::Var(variable));
        }
        for method in &pou.methods {
            self.add(&method.name, LocalSymbol::Method(method));
        }
        for property in &pou.properties {
            self.add(&property.name, LocalSymbol::Property(property));
        }
        for action in &pou.actions {
            self.add(&action.name, LocalSymbol::Action);
        }
    }

    fn add(&mut self, name: &str, symbol: LocalSymbol<'p>) {
        let key = name.to_lowercase();
        if !self.locals.contains_key(&key) {
            self.spellings.push(name.to_owned());
            self.locals.insert(key, symbol);
        }
    }

    /// The local called `name`.
    pub(crate) fn local(&self, name: &str) -> Option<LocalSymbol<'p>> {
        self.locals.get(lower(name).as_ref()).copied()
    }

    /// Every local name with its symbol, in the spelling of its declaration.
    pub(crate) fn local_symbols(&self) -> Vec<(String, LocalSymbol<'p>)> {
        self.spellings
            .iter()
            .filter_map(|name| self.local(name).map(|symbol| (name.clone(), symbol)))
            .collect()
    }

    /// A local or global name close to `name`.
    pub(crate) fn suggest(&self, name: &str) -> Option<String> {
        let local = closest(name, self.spellings.iter().map(String::as_str)).map(str::to_owned);
        local.or_else(|| self.globals.suggest(name))
    }
}

/// `name` in lower case, the key of the name maps; borrowed when it is lower case already,
/// as most names are, so a lookup allocates only for mixed-case names.
fn lower(name: &str) -> Cow<'_, str> {
    if name
        .bytes()
        .any(|b| !b.is_ascii() || b.is_ascii_uppercase())
    {
        Cow::Owned(name.to_lowercase())
    } else {
        Cow::Borrowed(name)
    }
}

/// `pou` and the function blocks it extends, nearest first, stopping at cycles.
pub(crate) fn inheritance_chain<'p>(globals: &Globals<'p>, pou: &'p Pou) -> Vec<&'p Pou> {
    let mut chain = vec![pou];
    let mut base = pou.extends.as_deref();
    while let Some(parent) = base.and_then(|name| globals.pou(name)) {
        if chain.len() >= MAX_INHERITANCE || chain.iter().any(|seen| std::ptr::eq(*seen, parent)) {
            break;
        }
        chain.push(parent);
        base = parent.extends.as_deref();
    }
    chain
}

/// Whether a variable of this section can be read from outside its POU (`fb.Q`, `fb.IN`).
pub(crate) fn is_visible_outside(section: VarSection) -> bool {
    matches!(
        section,
        VarSection::VarInput | VarSection::VarOutput | VarSection::VarInOut
    )
}
