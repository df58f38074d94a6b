//! LD and FBD bodies lowered into Structured Text and SFC charts into textual SFC, so the
//! checker and the code generator run unchanged on them (ARCHITECTURE.md, "Bodies and their
//! origins").
//!
//! [`lower_project`] gives the project with every LD, FBD and SFC body (of POUs, methods,
//! property accessors, actions and transition objects) replaced by its text, the hidden
//! variables it needs declared in the POU and the transition objects turned into methods, and
//! for each such body a [`LoweredBody`]: the text, the [`OriginMap`] from its byte ranges back
//! to networks (an SFC chart is network 0), elements and pins, and the [`Probe`]s that say
//! where each element's live value is read. The semantics are in
//! `docs/graphical-semantics.md`.

mod boxes;
mod cfc;
mod fragment;
mod il;
mod locate;
mod network;
mod operator;
mod place;
mod results;
mod sfc;
#[cfg(test)]
mod tests;
mod value;

use std::borrow::Cow;
use std::collections::HashMap;
use std::path::PathBuf;

use project_model::{
    Body, ElementId, Method, Object, Pou, PouKind, Project, TextTarget, VarSection, Variable,
};

use crate::diagnostic::Code;
use fragment::Span;
use network::BodyLowering;
use operator::Operator;

pub use il::LoweredIl;
pub use locate::OriginMap;
pub use place::ElementPlace;

/// A project whose graphical bodies are Structured Text, with the way back to the networks.
#[derive(Debug)]
pub struct LoweredProject<'p> {
    /// The project: borrowed when it has no LD, FBD or SFC body and no transition object,
    /// else a copy with every such body replaced by its text, the hidden variables declared
    /// in their POUs and the transition objects turned into methods.
    pub project: Cow<'p, Project>,
    /// Every lowered body, in tree order.
    pub bodies: Vec<LoweredBody>,
    /// Every Instruction List body, lowered into Structured Text line for line, in tree order.
    pub il: Vec<LoweredIl>,
}

/// One LD or FBD body as Structured Text, or one SFC chart as textual SFC.
#[derive(Clone, Debug)]
pub struct LoweredBody {
    /// The POU's name.
    pub pou: String,
    /// Which body of the POU it is.
    pub target: TextTarget,
    /// The POU's `.pou.toml` file, relative to the project folder: where findings are shown.
    pub file: PathBuf,
    /// The `.st` file the lowered text would have as an ST body, which the checker and the
    /// code generator name; it does not exist on disk.
    pub text_file: PathBuf,
    /// The generated statements.
    pub text: String,
    /// From byte ranges of `text` back to networks, elements and pins.
    pub origins: OriginMap,
    /// Where each element's (and pin's) live value is read, in the order they were met.
    pub probes: Vec<Probe>,
    /// Each hidden name of the body with the words a message uses for it.
    descriptions: Vec<(String, String)>,
    /// What the lowering found that cannot be compiled.
    findings: Vec<Finding>,
}

/// Where the live value of an element (or of one of its pins) is read while online.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Probe {
    /// The network's index in its body, from 0.
    pub network: usize,
    /// The element.
    pub element: ElementId,
    /// The pin of a box, or `EN` for the power entering a box; `None` for the element itself.
    pub pin: Option<String>,
    /// What the value is.
    pub kind: ProbeKind,
    /// The variable holding it, relative to the POU's instance (`bStart`, `tDelay.Q`, or a
    /// hidden `__e7`): prefix the instance's path to read it.
    pub path: String,
}

/// What a [`Probe`] reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProbeKind {
    /// The power flow leaving the element (a contact, parallel group or box) or entering the
    /// pin; where an element has no power probe, the power is derived from its neighbours'.
    Power,
    /// The value of the variable the element reads or writes (a contact's or coil's variable,
    /// a box's pin).
    Value,
    /// The output of the element's (or pin's) edge detection: TRUE for the one cycle of the
    /// edge.
    Edge,
}

/// Something the lowering cannot compile, at an element.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Finding {
    /// The network's index.
    pub network: usize,
    /// The element, or `None` for the network itself.
    pub element: Option<ElementId>,
    /// The pin, if any.
    pub pin: Option<String>,
    /// The diagnostic code.
    pub code: Code,
    /// What is wrong, in the user's words.
    pub message: String,
}

/// What a box's type name calls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Callee {
    /// A function, or an operator when it has an ST operator.
    Function {
        /// The ST operator that writes it, for operator boxes.
        operator: Option<Operator>,
    },
    /// A function block: called through its instance.
    Block,
    /// A program: called by its name.
    Program,
    /// Nothing the project or the standard library knows.
    Unknown,
}

/// Lowers every LD, FBD and SFC body of `project` and turns its transition objects into
/// methods; a project without either is borrowed unchanged.
pub fn lower_project(project: &Project) -> LoweredProject<'_> {
    let graphical = |body: &Body| {
        matches!(
            body,
            Body::Ld { .. }
                | Body::Fbd { .. }
                | Body::Sfc { .. }
                | Body::Cfc { .. }
                | Body::Il { .. }
        )
    };
    let pous: Vec<(PathBuf, &Pou)> = project_model::object_files(project)
        .into_iter()
        .filter_map(|(file, object)| match object {
            Object::Pou(pou)
                if !pou.transitions.is_empty()
                    || slots(pou).iter().any(|(_, _, body)| graphical(body)) =>
            {
                Some((file, pou))
            }
            _ => None,
        })
        .collect();
    if pous.is_empty() {
        return LoweredProject {
            project: Cow::Borrowed(project),
            bodies: Vec::new(),
            il: Vec::new(),
        };
    }
    let kinds: HashMap<String, PouKind> = project
        .application
        .objects()
        .into_iter()
        .chain(crate::library::objects())
        .filter_map(|object| match object {
            Object::Pou(pou) => Some((pou.name.to_lowercase(), pou.kind)),
            _ => None,
        })
        .collect();
    let classify = |name: &str| classify(&kinds, name);
    // The declared types of the functions' outputs other than their result, which a chart
    // stores in hidden variables.
    let function_outputs: HashMap<(String, String), String> = project
        .application
        .objects()
        .into_iter()
        .chain(crate::library::objects())
        .filter_map(|object| match object {
            Object::Pou(pou) if pou.kind == PouKind::Function => Some(pou),
            _ => None,
        })
        .flat_map(|pou| {
            pou.variables
                .iter()
                .filter(|variable| variable.section == VarSection::VarOutput)
                .map(|variable| {
                    (
                        (pou.name.to_lowercase(), variable.name.to_lowercase()),
                        variable.ty.clone(),
                    )
                })
                .collect::<Vec<_>>()
        })
        .collect();
    // The checker's view of the project types the boxes' results; built at the first box.
    let globals = std::cell::OnceCell::new();
    let mut lowered = project.clone();
    let mut bodies = Vec::new();
    let mut il_bodies = Vec::new();
    for (file, pou) in pous {
        let folder = file.parent().map(PathBuf::from).unwrap_or_default();
        let mut texts = Vec::new();
        let mut hidden = Vec::new();
        let transition_objects: Vec<String> =
            pou.transitions.iter().map(|t| t.name.clone()).collect();
        for (index, (suffix, target, body)) in slots(pou).into_iter().enumerate() {
            let prefix = match &target {
                TextTarget::Pou(_) => "__".to_owned(),
                TextTarget::Method { method: member, .. }
                | TextTarget::Action { action: member, .. }
                | TextTarget::Transition {
                    transition: member, ..
                } => format!("__{member}__"),
                TextTarget::Property { property, get, .. } => {
                    format!("__{property}_{}__", if *get { "get" } else { "set" })
                }
            };
            if let Body::Il { text } = body {
                let (il_body, mut il_hidden) = lower_il(
                    project, &globals, pou, &folder, &suffix, target, prefix, text,
                );
                texts.push((index, il_body.text.clone()));
                hidden.append(&mut il_hidden);
                il_bodies.push(il_body);
                continue;
            }
            // Each graphical body is lowered into ST text with its probes, descriptions and
            // findings; the text then takes the body's place in the copy that is checked.
            let (out, probes, descriptions, findings) = if let Body::Sfc { chart } = body {
                let mut lowering = sfc::ChartLowering::new(prefix, &transition_objects);
                lowering.chart(chart);
                hidden.append(&mut lowering.hidden);
                (
                    lowering.out,
                    lowering.probes,
                    lowering.descriptions,
                    Vec::new(),
                )
            } else {
                if !matches!(body, Body::Ld { .. } | Body::Fbd { .. } | Body::Cfc { .. }) {
                    continue;
                }
                let scope = std::cell::OnceCell::new();
                let typed_target = target.clone();
                let type_of = |expression: &str| {
                    let scope = scope.get_or_init(|| {
                        let globals =
                            globals.get_or_init(|| crate::sema::scope::Globals::new(project));
                        crate::sema::expression_scope(globals, pou, &typed_target)
                    });
                    crate::sema::expression_declared_type(scope, expression)
                };
                let mut lowering = BodyLowering::new(prefix, &classify, &type_of);
                match body {
                    Body::Cfc { chart } => {
                        // A chart's results may read hidden variables (feedback, structures), so
                        // they are typed in a scope that declares those known so far.
                        let of_expressions = |hidden: &[Variable], expressions: &[String]| {
                            let globals =
                                globals.get_or_init(|| crate::sema::scope::Globals::new(project));
                            let mut with_hidden = pou.clone();
                            with_hidden.variables.extend(hidden.iter().cloned());
                            let scope =
                                crate::sema::expression_scope(globals, &with_hidden, &target);
                            expressions
                                .iter()
                                .map(|expression| {
                                    crate::sema::expression_declared_type(&scope, expression)
                                })
                                .collect()
                        };
                        let of_function_output = |function: &str, pin: &str| {
                            function_outputs
                                .get(&(function.trim().to_lowercase(), pin.to_lowercase()))
                                .cloned()
                        };
                        let types = cfc::ChartTypes {
                            of_expressions: &of_expressions,
                            of_function_output: &of_function_output,
                        };
                        lowering.chart(chart, &types);
                    }
                    Body::Ld { networks } | Body::Fbd { networks } => lowering.body(networks),
                    _ => {}
                }
                hidden.append(&mut lowering.hidden);
                (
                    lowering.out,
                    lowering.probes,
                    lowering.descriptions,
                    lowering.findings,
                )
            };
            texts.push((index, out.text.clone()));
            bodies.push(LoweredBody {
                pou: pou.name.clone(),
                target,
                file: file.clone(),
                text_file: folder.join(format!("{}{suffix}", pou.name)),
                text: out.text,
                origins: OriginMap::new(out.spans),
                probes,
                descriptions,
                findings,
            });
        }
        if let Some(Object::Pou(copy)) = lowered.application.object_mut(&pou.name) {
            let mut slots = bodies_mut(copy);
            for (index, text) in texts {
                if let Some(body) = slots.get_mut(index) {
                    **body = Body::St { text };
                }
            }
            for variable in hidden {
                if !copy
                    .variables
                    .iter()
                    .any(|v| v.name.eq_ignore_ascii_case(&variable.name))
                {
                    copy.variables.push(variable);
                }
            }
            transitions_into_methods(copy);
        }
    }
    LoweredProject {
        project: Cow::Owned(lowered),
        bodies,
        il: il_bodies,
    }
}

/// Lowers the IL body `text` of `target` of `pou` (stored in `folder`), typing the current
/// result with the checker's view of the project with the hidden variables declared so far.
#[allow(clippy::too_many_arguments)]
fn lower_il<'p>(
    project: &'p Project,
    globals: &std::cell::OnceCell<crate::sema::scope::Globals<'p>>,
    pou: &Pou,
    folder: &std::path::Path,
    suffix: &str,
    target: TextTarget,
    prefix: String,
    text: &str,
) -> (LoweredIl, Vec<Variable>) {
    // The passes of the lowering ask the same questions again, so answers are kept by the
    // number of hidden variables declared (which only grows) and the expression.
    let answers = std::cell::RefCell::new(HashMap::<(usize, String), Option<String>>::new());
    let type_of = |hidden: &[Variable], expression: &str| {
        let key = (hidden.len(), expression.to_owned());
        if let Some(answer) = answers.borrow().get(&key) {
            return answer.clone();
        }
        let globals = globals.get_or_init(|| crate::sema::scope::Globals::new(project));
        let mut with_hidden = pou.clone();
        with_hidden.variables.extend(hidden.iter().cloned());
        let scope = crate::sema::expression_scope(globals, &with_hidden, &target);
        let answer = crate::sema::expression_declared_type(&scope, expression);
        answers.borrow_mut().insert(key, answer.clone());
        answer
    };
    let stem = suffix.strip_suffix(".st").unwrap_or(suffix);
    let transition = match &target {
        TextTarget::Transition { transition, .. } => Some(transition.clone()),
        _ => None,
    };
    LoweredIl::new(
        &pou.name,
        target.clone(),
        folder.join(format!("{}{stem}.il", pou.name)),
        folder.join(format!("{}{suffix}", pou.name)),
        text,
        prefix,
        &type_of,
        transition.as_deref(),
    )
}

/// Turns the transition objects of `pou` (their bodies already Structured Text) into methods
/// returning BOOL named like them: a body that is a bare expression is wrapped as
/// `Ready := (expression);`, and when a chart reads the object's value for its probe, the
/// method also keeps its result in the POU's hidden variable [`sfc::transition_result`].
fn transitions_into_methods(pou: &mut Pou) {
    for transition in std::mem::take(&mut pou.transitions) {
        let name = transition.name;
        let body = match transition.body {
            Body::St { text } => {
                let mut text = match bare_expression(&text) {
                    Some(expression) => format!("{name} := ({expression});"),
                    None => text,
                };
                let result = sfc::transition_result(&name);
                if pou
                    .variables
                    .iter()
                    .any(|v| v.name.eq_ignore_ascii_case(&result))
                {
                    if !text.ends_with('\n') {
                        text.push('\n');
                    }
                    text.push_str(&format!("{result} := {name};\n"));
                }
                Body::St { text }
            }
            other => other,
        };
        pou.methods.push(Method {
            name,
            return_type: Some("BOOL".into()),
            access: project_model::AccessSpecifier::Private,
            is_abstract: false,
            comment: String::new(),
            variables: Vec::new(),
            body,
        });
    }
}

/// The expression the ST text of a transition object is when it is an expression alone
/// (`a AND b`), not statements: it does not parse as statements but does as the right side of
/// an assignment.
fn bare_expression(text: &str) -> Option<&str> {
    let trimmed = text.trim().trim_end_matches(';').trim_end();
    let alone = !trimmed.is_empty()
        && !crate::syntax::parse_statements(text).errors().is_empty()
        && crate::syntax::parse_statements(&format!("__x := ({trimmed});"))
            .errors()
            .is_empty();
    alone.then_some(trimmed)
}

/// What `name` calls, by the project's POUs, the motion library and the standard library.
fn classify(kinds: &HashMap<String, PouKind>, name: &str) -> Callee {
    let name = name.trim();
    if let Some(operator) = Operator::of(name) {
        return Callee::Function {
            operator: Some(operator),
        };
    }
    match kinds.get(&name.to_lowercase()) {
        Some(PouKind::Function) => Callee::Function { operator: None },
        Some(PouKind::FunctionBlock) => Callee::Block,
        Some(PouKind::Program) => Callee::Program,
        Some(PouKind::Interface) => Callee::Unknown,
        None if crate::sema::is_function(name) => Callee::Function { operator: None },
        None if crate::sema::is_function_block(name) => Callee::Block,
        None => Callee::Unknown,
    }
}

/// Every body of a POU with the suffix of its `.st` file and its target, in the order of
/// `project_model::st_body_files`.
fn slots(pou: &Pou) -> Vec<(String, TextTarget, &Body)> {
    let name = || pou.name.clone();
    let mut slots = vec![(".st".to_owned(), TextTarget::Pou(name()), &pou.body)];
    for method in &pou.methods {
        let target = TextTarget::Method {
            pou: name(),
            method: method.name.clone(),
        };
        slots.push((format!(".{}.st", method.name), target, &method.body));
    }
    for property in &pou.properties {
        for (accessor, get) in [(&property.get, true), (&property.set, false)] {
            if let Some(accessor) = accessor {
                let which = if get { "get" } else { "set" };
                let target = TextTarget::Property {
                    pou: name(),
                    property: property.name.clone(),
                    get,
                };
                slots.push((
                    format!(".{}.{which}.st", property.name),
                    target,
                    &accessor.body,
                ));
            }
        }
    }
    for action in &pou.actions {
        let target = TextTarget::Action {
            pou: name(),
            action: action.name.clone(),
        };
        slots.push((format!(".{}.st", action.name), target, &action.body));
    }
    for transition in &pou.transitions {
        let target = TextTarget::Transition {
            pou: name(),
            transition: transition.name.clone(),
        };
        slots.push((format!(".{}.st", transition.name), target, &transition.body));
    }
    slots
}

/// Every body of a POU, mutably, in the order of [`slots`].
fn bodies_mut(pou: &mut Pou) -> Vec<&mut Body> {
    let mut bodies = vec![&mut pou.body];
    bodies.extend(pou.methods.iter_mut().map(|method| &mut method.body));
    for property in &mut pou.properties {
        if let Some(get) = &mut property.get {
            bodies.push(&mut get.body);
        }
        if let Some(set) = &mut property.set {
            bodies.push(&mut set.body);
        }
    }
    bodies.extend(pou.actions.iter_mut().map(|action| &mut action.body));
    bodies.extend(pou.transitions.iter_mut().map(|t| &mut t.body));
    bodies
}

impl LoweredProject<'_> {
    /// The lowered body `target` of POU `pou`, if it is graphical.
    pub fn body(&self, pou: &str, target: &TextTarget) -> Option<&LoweredBody> {
        self.bodies
            .iter()
            .find(|body| body.pou.eq_ignore_ascii_case(pou) && &body.target == target)
    }

    /// The IL file of the lowered IL body the checker or code generator names `file`.
    pub fn il_file_of(&self, file: &std::path::Path) -> Option<&std::path::Path> {
        self.il
            .iter()
            .find(|body| body.has_text_file(file))
            .map(|body| body.file.as_path())
    }

    /// The lowered body the checker or code generator names by its text file.
    fn body_of_text_file(&self, file: &std::path::Path) -> Option<&LoweredBody> {
        self.bodies.iter().find(|body| body.text_file == file)
    }
}

impl LoweredBody {
    /// Where the 1-based `line` of the lowered text comes from: what a fault or a line-table
    /// entry of the image (which count lines of this text) points back to. Every statement
    /// is on a line of its own, so the line's statement names the element.
    pub fn origin_at_line(&self, line: u32) -> Option<crate::origin::Origin> {
        let index = usize::try_from(line).ok()?.checked_sub(1)?;
        let mut start = 0;
        for (at, text) in self.text.split_inclusive('\n').enumerate() {
            if at == index {
                let content = text.trim();
                let offset = start + (text.len() - text.trim_start().len());
                return self.origins.origin(offset..offset + content.len());
            }
            start += text.len();
        }
        None
    }

    /// The probe of the value at `pin` of `element` (`None` for the element itself or its
    /// only pin; a pin's name without case), of kind [`ProbeKind::Value`]: in a CFC chart,
    /// what a wire from that output pin carries (inverted when the pin is negated) or what
    /// an input pin receives (`docs/graphical-semantics.md` §8.12).
    pub fn value_probe(&self, element: ElementId, pin: Option<&str>) -> Option<&Probe> {
        self.probes.iter().find(|probe| {
            probe.element == element
                && probe.kind == ProbeKind::Value
                && match (&probe.pin, pin) {
                    (Some(probed), Some(pin)) => probed.eq_ignore_ascii_case(pin.trim()),
                    (None, None) => true,
                    _ => false,
                }
        })
    }

    /// The hidden variables' names, lower case, with their descriptions.
    fn describe(&self, message: &str) -> String {
        locate::describe_hidden(message, &self.descriptions)
    }

    /// Whether `name` is a hidden variable of this body.
    fn is_hidden(&self, name: &str) -> bool {
        self.descriptions
            .iter()
            .any(|(hidden, _)| hidden.eq_ignore_ascii_case(name))
    }

    /// The span lookup of [`OriginMap`], as an element place of this body.
    fn place_of(&self, span: &Span) -> ElementPlace {
        ElementPlace {
            pou: self.pou.clone(),
            target: self.target.clone(),
            network: span.network,
            element: span.element,
            pin: span.pin.clone(),
        }
    }
}
