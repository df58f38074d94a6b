//! Semantic checks over a whole project: name resolution and type checking of every ST body,
//! the declarations (types, initial values, duplicates, direct addresses), the programs the
//! tasks call, and the warnings a PLC engineer expects: unused and unassigned variables,
//! inputs written inside their POU, overlapping located variables.

pub(crate) mod address;
pub(crate) mod body;
mod complete;
pub(crate) mod constant;
mod definition;
pub(crate) mod expression_types;
pub(crate) mod modbus_master;
mod reserved;
pub(crate) mod scope;
mod sfc_flags;
pub(crate) mod signatures;
mod stdlib;
pub(crate) mod ty;
pub(crate) mod types;

use std::collections::{HashMap, HashSet};
use std::path::PathBuf;

use project_model::{
    Body, DataType, Object, Pou, PouKind, Project, StBody, TextTarget, TypeDefinition, VarSection,
    Variable,
};

use crate::diagnostic::{Code, Diagnostic};
use crate::syntax::ast::{AstNode, TypeExpr};
use crate::syntax::{parse_statements, parse_type};
use body::{BodyChecker, Usage};
use scope::{Globals, Scope};

pub use complete::{Completion, completions};
pub use definition::{Definition, DefinitionKind, Resolution};
pub use stdlib::{all_names, is_built_in_type, is_function, is_function_block};

/// A finding about a project: where it is and what it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProjectDiagnostic {
    /// The file, relative to the project folder.
    pub file: PathBuf,
    /// For a finding in a declaration stored as data (a variable's type in a `.pou.toml`), the
    /// declared name; `None` when `diagnostic.range` is a range of the file's text.
    pub declaration: Option<String>,
    /// For a finding in an LD or FBD body, the network, element and pin it is about (then
    /// `file` is the POU's `.pou.toml`, `declaration` is `None`, and `diagnostic.range` is a
    /// range of the text the user typed into the element, or `0..0`).
    pub element: Option<crate::lower::ElementPlace>,
    /// The finding.
    pub diagnostic: Diagnostic,
}

/// Checks every body (LD and FBD bodies through their lowering, with findings at their
/// elements) and declaration of `project`.
pub fn check_project(project: &Project) -> Vec<ProjectDiagnostic> {
    let lowered = crate::lower::lower_project(project);
    check_lowered(project, &lowered, None)
}

/// Checks `project` whose graphical bodies were lowered into `lowered`.
///
/// With `keep`, each body's tree and expression types are kept there for the code generator.
pub(crate) fn check_lowered(
    project: &Project,
    lowered: &crate::lower::LoweredProject<'_>,
    keep: Option<&mut expression_types::CheckedBodies>,
) -> Vec<ProjectDiagnostic> {
    let mut found = lowered.findings();
    found.extend(reserved::reserved_names(project));
    found.extend(reserved::reserved_references(project));
    found.extend(lowered.locate(check_text_project(&lowered.project, keep)));
    found
}

/// Checks every ST body and declaration of `project`, keeping each body's tree and types in
/// `keep` when given.
fn check_text_project(
    project: &Project,
    mut keep: Option<&mut expression_types::CheckedBodies>,
) -> Vec<ProjectDiagnostic> {
    let globals = Globals::new(project);
    let mut found = Vec::new();
    // The variables runtime Modbus devices fill, which W0002 leaves alone, and the variables
    // some body writes, for W0015.
    let filled = modbus_master::runtime_filled(project, &globals);
    let mut written = HashSet::new();
    // Each POU's bodies, grouped once rather than searched for every POU.
    let mut bodies: HashMap<*const Pou, Vec<StBody<'_>>> = HashMap::new();
    for body in project_model::st_body_files(project) {
        bodies
            .entry(std::ptr::from_ref(body.pou))
            .or_default()
            .push(body);
    }
    for (file, object) in project_model::object_files(project) {
        let mut report = |name: &str, diagnostic: Diagnostic| {
            found.push(ProjectDiagnostic {
                file: file.clone(),
                declaration: Some(name.to_owned()),
                element: None,
                diagnostic,
            });
        };
        match object {
            Object::Pou(pou) => {
                check_pou_declarations(&globals, pou, &mut report);
                sfc_flags::check_sfc_flags(&globals, pou, &mut report);
                let own = bodies
                    .get(&std::ptr::from_ref(pou))
                    .map_or(&[][..], Vec::as_slice);
                let usage = UsageContext {
                    filled: &filled,
                    written: &mut written,
                };
                found.extend(check_pou_bodies(
                    &globals,
                    &file,
                    pou,
                    own,
                    keep.as_deref_mut(),
                    usage,
                ));
            }
            Object::Gvl(gvl) => {
                check_variables(&globals, None, &gvl.variables, &mut report);
                duplicates(
                    gvl.variables.iter().map(|v| v.name.as_str()),
                    "global variable list",
                    &gvl.name,
                    &mut report,
                );
            }
            Object::DataType(data_type) => check_data_type(&globals, data_type, &mut report),
            Object::CamTable(_) | Object::Trace(_) | Object::WatchList(_) => {}
        }
    }
    overlapping_addresses(project, &mut found);
    for task in &project.tasks {
        for program in &task.programs {
            let is_program = project.application.object(program).is_some_and(
                |object| matches!(object, Object::Pou(pou) if pou.kind == PouKind::Program),
            );
            if !is_program {
                let message = format!(
                    "task '{}' calls '{program}', which is not a PROGRAM of the project",
                    task.name
                );
                found.push(ProjectDiagnostic {
                    file: PathBuf::from(project_model::MANIFEST_FILE_NAME),
                    declaration: Some(task.name.clone()),
                    element: None,
                    diagnostic: Diagnostic::new(Code::UnknownProgram, 0..0, message),
                });
            }
        }
    }
    found.extend(modbus_master::check_modbus_master(
        project, &globals, &written,
    ));
    found
}

/// Checks one POU (declarations and every body) of `project`: what an editor re-checks after an
/// edit of that POU, without the rest of the project.
pub fn check_pou(project: &Project, pou_name: &str) -> Vec<ProjectDiagnostic> {
    let lowered = crate::lower::lower_project(project);
    // The POU's own files: its `.pou.toml` and the `.st` and `.il` files of its bodies, beside
    // it.
    let own = |file: &std::path::Path| {
        file.file_name()
            .and_then(|name| name.to_str())
            .and_then(|name| name.split('.').next())
            .is_some_and(|name| name.eq_ignore_ascii_case(pou_name))
    };
    let mut found: Vec<ProjectDiagnostic> = lowered
        .findings()
        .into_iter()
        .filter(|finding| match &finding.element {
            Some(place) => place.pou.eq_ignore_ascii_case(pou_name),
            None => own(&finding.file),
        })
        .collect();
    found.extend(
        reserved::reserved_names(project)
            .into_iter()
            .chain(reserved::reserved_references(project))
            .filter(|finding| own(&finding.file)),
    );
    found.extend(lowered.locate(check_text_pou(&lowered.project, pou_name)));
    found
}

fn check_text_pou(project: &Project, pou_name: &str) -> Vec<ProjectDiagnostic> {
    let globals = Globals::new(project);
    let Some(pou) = globals.pou(pou_name) else {
        return Vec::new();
    };
    let Some((file, _)) = project_model::object_files(project)
        .into_iter()
        .find(|(_, object)| std::ptr::eq(object.name(), pou.name.as_str()))
    else {
        return Vec::new();
    };
    let mut found = Vec::new();
    check_pou_declarations(&globals, pou, &mut |name, diagnostic| {
        found.push(ProjectDiagnostic {
            file: file.clone(),
            declaration: Some(name.to_owned()),
            element: None,
            diagnostic,
        });
    });
    let bodies: Vec<StBody<'_>> = project_model::st_body_files(project)
        .into_iter()
        .filter(|body| std::ptr::eq(body.pou, pou))
        .collect();
    let filled = modbus_master::runtime_filled(project, &globals);
    let usage = UsageContext {
        filled: &filled,
        written: &mut HashSet::new(),
    };
    found.extend(check_pou_bodies(&globals, &file, pou, &bodies, None, usage));
    found
}

/// What every name of one body refers to, in order.
pub fn body_resolutions(project: &Project, body: &StBody<'_>) -> Vec<Resolution> {
    let globals = Globals::new(project);
    resolutions_with(&globals, body)
}

fn resolutions_with(globals: &Globals<'_>, body: &StBody<'_>) -> Vec<Resolution> {
    let parse = parse_statements(body.text);
    let root = parse.syntax();
    let scope = Scope::for_body(globals, body.pou, &body.target, &root);
    let mut usage = Usage::new();
    let mut checker = BodyChecker::new(&scope, &mut usage);
    checker.resolutions = Some(Vec::new());
    checker.check(&root);
    let mut resolutions = checker.resolutions.unwrap_or_default();
    resolutions.sort_by_key(|resolution| resolution.range.start);
    resolutions
}

/// The checker's type of every expression of a body, for code generation.
pub(crate) fn expression_types(
    scope: &Scope<'_, '_>,
    root: &crate::syntax::SyntaxNode,
) -> expression_types::ExpressionTypes {
    let mut usage = Usage::new();
    let mut checker = BodyChecker::new(scope, &mut usage);
    checker.types = Some(expression_types::ExpressionTypes::default());
    checker.check(root);
    checker.types.unwrap_or_default()
}

/// The checker's type of every expression under `root` and what it finds there, for a
/// breakpoint condition compiled in a body's scope (`codegen::compile_condition`).
pub(crate) fn expression_check(
    scope: &Scope<'_, '_>,
    root: &crate::syntax::SyntaxNode,
) -> (expression_types::ExpressionTypes, Vec<Diagnostic>) {
    let mut usage = Usage::new();
    let mut checker = BodyChecker::new(scope, &mut usage);
    checker.types = Some(expression_types::ExpressionTypes::default());
    checker.check(root);
    (
        checker.types.take().unwrap_or_default(),
        checker.diagnostics,
    )
}

/// The names an expression in the body `target` of `pou` sees, for
/// [`expression_declared_type`]: made once per body, as it indexes all of the POU's names.
pub(crate) fn expression_scope<'a, 'p>(
    globals: &'a Globals<'p>,
    pou: &'p Pou,
    target: &TextTarget,
) -> Scope<'a, 'p> {
    Scope::for_body(globals, pou, target, &parse_statements("").syntax())
}

/// The declared type (`INT`, `STRING(80)`, `E_Mode`) of the value of `expression`, an ST
/// expression over the names of `scope` (from [`expression_scope`]), by the checker's rules;
/// `None` when the expression has no type a variable can be declared with (an error, an
/// untyped literal such as `1 + 2`, an array or reference).
///
/// The lowering declares a hidden variable of this type for a box's result.
pub(crate) fn expression_declared_type(scope: &Scope<'_, '_>, expression: &str) -> Option<String> {
    use crate::syntax::ast::{SourceFile, Stmt};
    let parse = parse_statements(&format!("__value := {expression};"));
    let root = parse.syntax();
    let statement = SourceFile::cast(root.clone())?
        .statement_list()?
        .statements()
        .next()?;
    let Stmt::AssignStmt(assignment) = statement else {
        return None;
    };
    let value = assignment.value()?;
    let types = expression_types(scope, &root);
    match types.get(value.syntax())? {
        ty::Type::Elementary(elementary)
        | ty::Type::Subrange {
            base: elementary, ..
        } => Some(elementary.name().to_owned()),
        ty::Type::String { wide, length } => Some(format!(
            "{}({length})",
            if *wide { "WSTRING" } else { "STRING" }
        )),
        ty::Type::Named(name) => Some(name.clone()),
        _ => None,
    }
}

/// The type written as `text` in a declaration among `locals` (the declarations of a POU,
/// its bases and the method or accessor at hand): array bounds may name their constants.
pub(crate) fn resolve_local_type(
    globals: &Globals<'_>,
    locals: &[&Variable],
    text: &str,
) -> ty::Type {
    let ty = globals.resolve_type(text);
    if !body::has_open_bounds(&ty) {
        return ty;
    }
    fn constant(
        globals: &Globals<'_>,
        locals: &[&Variable],
        name: &str,
        container: Option<&str>,
        depth: u32,
    ) -> Option<constant::Const> {
        if depth > constant::MAX_CONSTANT_DEPTH {
            return None;
        }
        if container.is_none()
            && let Some(variable) = locals.iter().find(|v| v.name.eq_ignore_ascii_case(name))
        {
            if !variable.constant {
                return None;
            }
            let expression = constant::parse_expression(variable.initial.as_deref()?)?;
            return constant::evaluate(
                &expression,
                &|n, c, d| constant(globals, locals, n, c, d),
                depth + 1,
            );
        }
        globals.constant(name, container, depth)
    }
    types::resolve_type_text_with(globals, text, &|n, c, d| constant(globals, locals, n, c, d))
}

/// Every place in every body that refers to `definition`, with its body.
pub fn references_to(
    project: &Project,
    definition: &Definition,
) -> Vec<(PathBuf, TextTarget, std::ops::Range<usize>)> {
    let globals = Globals::new(project);
    let mut found = Vec::new();
    for body in project_model::st_body_files(project) {
        // Only bodies that mention the name can refer to it; the text search is cheap.
        if !body
            .text
            .to_lowercase()
            .contains(&definition.name.to_lowercase())
        {
            continue;
        }
        for resolution in resolutions_with(&globals, &body) {
            if resolution.definition.same_declaration(definition) {
                found.push((body.file.clone(), body.target.clone(), resolution.range));
            }
        }
    }
    found
}

/// What the usage warnings of one POU share with the rest of the project.
struct UsageContext<'u> {
    /// The declarations runtime Modbus devices fill, which W0002 does not report.
    filled: &'u HashSet<*const Variable>,
    /// The declarations written by the bodies checked so far, to which this POU's writes are
    /// added (W0015).
    written: &'u mut HashSet<*const Variable>,
}

/// The bodies of one POU (`bodies` are all its own) checked, with the usage warnings of its
/// variables.
fn check_pou_bodies(
    globals: &Globals<'_>,
    file: &std::path::Path,
    pou: &Pou,
    bodies: &[StBody<'_>],
    mut keep: Option<&mut expression_types::CheckedBodies>,
    context: UsageContext<'_>,
) -> Vec<ProjectDiagnostic> {
    let mut found = Vec::new();
    let mut usage = Usage::new();
    let mut clean = true;
    for body in bodies {
        let parse = parse_statements(body.text);
        clean &= parse.errors().is_empty();
        let mut findings: Vec<Diagnostic> = parse.errors().to_vec();
        let root = parse.syntax();
        let scope = Scope::for_body(globals, body.pou, &body.target, &root);
        let mut checker = BodyChecker::new(&scope, &mut usage);
        if keep.is_some() {
            checker.types = Some(expression_types::ExpressionTypes::default());
        }
        checker.check(&root);
        if let (Some(keep), Some(types)) = (keep.as_deref_mut(), checker.types.take()) {
            keep.keep(&body.file, root.clone(), types);
        }
        let mut checked = checker.diagnostics;
        checked.sort_by_key(|diagnostic| diagnostic.range.start);
        findings.extend(checked);
        found.extend(findings.into_iter().map(|diagnostic| ProjectDiagnostic {
            file: body.file.clone(),
            declaration: None,
            element: None,
            diagnostic,
        }));
    }
    context.written.extend(
        usage
            .iter()
            .filter(|(_, access)| access.written)
            .map(|(variable, _)| *variable),
    );
    // Usage is only complete when every body is Structured Text that parsed.
    if clean && all_bodies_are_text(pou) {
        usage_warnings(
            globals,
            pou,
            &usage,
            context.filled,
            &mut |name, diagnostic| {
                found.push(ProjectDiagnostic {
                    file: file.to_owned(),
                    declaration: Some(name.to_owned()),
                    element: None,
                    diagnostic,
                });
            },
        );
    }
    found
}

/// A POU's header and declarations: types, base types, initial values, addresses, and names
/// declared twice.
fn check_pou_declarations<'p>(
    globals: &Globals<'p>,
    pou: &'p Pou,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    check_variables(globals, Some(pou), &pou.variables, report);
    if let Some(ty) = &pou.return_type {
        check_type(globals, &pou.name, ty, report);
    }
    for base in pou.extends.iter().chain(&pou.implements) {
        if !globals.is_pou(base) {
            report(
                &pou.name,
                unknown(
                    Code::UnknownType,
                    "function block or interface",
                    base,
                    globals,
                ),
            );
        }
    }
    let members = pou
        .variables
        .iter()
        .map(|v| v.name.as_str())
        .chain(pou.methods.iter().map(|m| m.name.as_str()))
        .chain(pou.properties.iter().map(|p| p.name.as_str()))
        .chain(pou.actions.iter().map(|a| a.name.as_str()));
    duplicates(members, "POU", &pou.name, report);
    for method in &pou.methods {
        check_variables(globals, Some(pou), &method.variables, report);
        duplicates(
            method.variables.iter().map(|v| v.name.as_str()),
            "method",
            &method.name,
            report,
        );
        if let Some(ty) = &method.return_type {
            check_type(globals, &method.name, ty, report);
        }
    }
    for property in &pou.properties {
        check_type(globals, &property.name, &property.ty, report);
        for accessor in property.get.iter().chain(&property.set) {
            check_variables(globals, Some(pou), &accessor.variables, report);
        }
    }
}

fn all_bodies_are_text(pou: &Pou) -> bool {
    let text = |body: &Body| matches!(body, Body::St { .. } | Body::None);
    text(&pou.body)
        && pou.methods.iter().all(|m| text(&m.body))
        && pou.actions.iter().all(|a| text(&a.body))
        && pou
            .properties
            .iter()
            .flat_map(|p| p.get.iter().chain(&p.set))
            .all(|a| text(&a.body))
}

/// Reports every name of `names` declared a second time.
fn duplicates<'n>(
    names: impl Iterator<Item = &'n str>,
    what: &str,
    owner: &str,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    let mut seen = HashSet::new();
    for name in names {
        if !seen.insert(name.to_lowercase()) {
            report(
                name,
                Diagnostic::new(
                    Code::DuplicateName,
                    0..0,
                    format!(
                        "'{name}' is declared twice in the {what} '{owner}'; names compare without case"
                    ),
                ),
            );
        }
    }
}

/// Unused and unassigned local variables of a POU, its methods and accessors; a variable in
/// `filled` is written by the runtime's Modbus master, so it is never reported as unassigned.
fn usage_warnings(
    globals: &Globals<'_>,
    pou: &Pou,
    usage: &Usage,
    filled: &HashSet<*const Variable>,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    let locals = pou
        .variables
        .iter()
        .chain(pou.methods.iter().flat_map(|m| &m.variables))
        .chain(
            pou.properties
                .iter()
                .flat_map(|p| p.get.iter().chain(&p.set))
                .flat_map(|a| &a.variables),
        );
    for variable in locals {
        if !matches!(
            variable.section,
            VarSection::Var | VarSection::VarTemp | VarSection::VarStat
        ) || variable.address.is_some()
            || variable.constant && pou.kind == PouKind::Program
            || sfc_flags::is_sfc_flag_of(pou, &variable.name)
        {
            continue;
        }
        let access = usage
            .get(&std::ptr::from_ref(variable))
            .copied()
            .unwrap_or_default();
        if !access.read && !access.written {
            report(
                &variable.name,
                Diagnostic::new(
                    Code::UnusedVariable,
                    0..0,
                    format!("'{}' is declared but never used", variable.name),
                ),
            );
        } else if access.read
            && !access.written
            && !filled.contains(&std::ptr::from_ref(variable))
            && variable.initial.is_none()
            && !variable.constant
            && globals.resolve_type(&variable.ty).as_elementary().is_some()
        {
            report(
                &variable.name,
                Diagnostic::new(
                    Code::UnassignedVariable,
                    0..0,
                    format!(
                        "'{}' is read but never written, so it always holds its default value",
                        variable.name
                    ),
                ),
            );
        }
    }
}

/// Located variables of different sizes that share bits, as CODESYS warns.
fn overlapping_addresses(project: &Project, found: &mut Vec<ProjectDiagnostic>) {
    let mut located: Vec<(PathBuf, &Variable, address::Address)> = Vec::new();
    for (file, object) in project_model::object_files(project) {
        let variables: Vec<&Variable> = match object {
            Object::Pou(pou) => pou.variables.iter().collect(),
            Object::Gvl(gvl) => gvl.variables.iter().collect(),
            _ => continue,
        };
        for variable in variables {
            if let Some(Ok(Some(address))) = variable.address.as_deref().map(address::parse_address)
            {
                located.push((file.clone(), variable, address));
            }
        }
    }
    located.sort_by_key(|(_, _, address)| (address.area as u8, address.first_bit));
    let mut by_area: HashMap<u8, Vec<usize>> = HashMap::new();
    for (index, (_, _, address)) in located.iter().enumerate() {
        by_area.entry(address.area as u8).or_default().push(index);
    }
    for indices in by_area.values() {
        for (position, &i) in indices.iter().enumerate() {
            let (_, first, a) = &located[i];
            for &j in &indices[position + 1..] {
                let (file, second, b) = &located[j];
                if b.first_bit >= a.bits().end {
                    break;
                }
                if a.size_bits != b.size_bits {
                    let message = format!(
                        "'{}' at {} overlaps '{}' at {}: writing one changes the other",
                        second.name,
                        second.address.as_deref().unwrap_or_default(),
                        first.name,
                        first.address.as_deref().unwrap_or_default()
                    );
                    found.push(ProjectDiagnostic {
                        file: file.clone(),
                        declaration: Some(second.name.clone()),
                        element: None,
                        diagnostic: Diagnostic::new(Code::OverlappingAddresses, 0..0, message),
                    });
                }
            }
        }
    }
}

/// Reports `declared` (written as `text`) when it is an array with open bounds (E0133), which
/// only a VAR_IN_OUT parameter of a function, function block or method may be.
fn check_open_bounds(
    globals: &Globals<'_>,
    declared: &str,
    text: &str,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    if has_open_bounds(globals, text) {
        report(
            declared,
            Diagnostic::new(
                Code::OpenArrayOutsideInOut,
                0..0,
                format!(
                    "'{declared}' is an array with open bounds (ARRAY[*]), which only a VAR_IN_OUT of a function, function block or method can be: its bounds come from the array passed in"
                ),
            ),
        );
    }
}

/// Whether the type written `text` is an array with an open bound `*`: seen in the text of an
/// array written in place (whose other bounds may name local constants, which the resolved
/// type cannot tell from `*`), or in the resolved type of a named type (whose bounds are
/// global).
fn has_open_bounds(globals: &Globals<'_>, text: &str) -> bool {
    let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    if compact.contains('[') {
        return compact.contains("[*") || compact.contains(",*");
    }
    fn open(ty: &ty::Type) -> bool {
        match ty {
            ty::Type::Array { element, dims } => dims.iter().any(Option::is_none) || open(element),
            _ => false,
        }
    }
    open(&globals.resolve_type(text))
}

fn check_variables<'p>(
    globals: &Globals<'p>,
    pou: Option<&'p Pou>,
    variables: &[Variable],
    report: &mut impl FnMut(&str, Diagnostic),
) {
    // The scope of initial values, built once and only if some variable has one.
    let mut scope = None;
    for variable in variables {
        check_type(globals, &variable.name, &variable.ty, report);
        let declared = globals.resolve_type(&variable.ty);
        let in_out_parameter = variable.section == VarSection::VarInOut
            && pou.is_none_or(|pou| pou.kind != PouKind::Program);
        if !in_out_parameter {
            check_open_bounds(globals, &variable.name, &variable.ty, report);
        }
        if let Some(initial) = variable.initial.as_deref()
            && let Some(expression) = constant::parse_expression(initial)
        {
            let scope = scope.get_or_insert_with(|| match pou {
                Some(pou) => Scope::for_declarations(globals, pou),
                None => Scope::globals_only(globals),
            });
            let mut usage = Usage::new();
            let mut checker = BodyChecker::new(scope, &mut usage);
            checker.check_value(
                &expression,
                &declared,
                &format!("the initial value of '{}'", variable.name),
            );
            for mut diagnostic in checker.diagnostics {
                diagnostic.range = 0..0;
                report(&variable.name, diagnostic);
            }
        }
        if let Some(text) = variable.address.as_deref() {
            match address::parse_address(text) {
                Err(message) => report(
                    &variable.name,
                    Diagnostic::new(
                        Code::InvalidAddress,
                        0..0,
                        format!("{}: {message}", variable.name),
                    ),
                ),
                Ok(Some(address)) => {
                    let size = declared.as_elementary().map(|e| {
                        if e == crate::elementary::Elementary::Bool {
                            1
                        } else {
                            e.size_bits()
                        }
                    });
                    if let Some(size) = size
                        && size != address.size_bits
                    {
                        report(
                            &variable.name,
                            Diagnostic::new(
                                Code::AddressSizeMismatch,
                                0..0,
                                format!(
                                    "'{}' is {} ({size} bit(s)) but {text} addresses {} bit(s)",
                                    variable.name, declared, address.size_bits
                                ),
                            ),
                        );
                    }
                }
                Ok(None) => {}
            }
        }
    }
}

fn check_data_type(
    globals: &Globals<'_>,
    data_type: &DataType,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    match &data_type.definition {
        TypeDefinition::Struct { extends, members } => {
            if let Some(base) = extends
                && !globals.is_type(base)
            {
                report(
                    &data_type.name,
                    unknown(Code::UnknownType, "type", base, globals),
                );
            }
            for member in members {
                check_type(globals, &member.name, &member.ty, report);
                check_open_bounds(globals, &member.name, &member.ty, report);
            }
            duplicates(
                members.iter().map(|m| m.name.as_str()),
                "structure",
                &data_type.name,
                report,
            );
        }
        TypeDefinition::Union { members } => {
            for member in members {
                check_type(globals, &member.name, &member.ty, report);
                check_open_bounds(globals, &member.name, &member.ty, report);
            }
            duplicates(
                members.iter().map(|m| m.name.as_str()),
                "union",
                &data_type.name,
                report,
            );
        }
        TypeDefinition::Enum { base, values } => {
            if let Some(base) = base {
                check_type(globals, &data_type.name, base, report);
            }
            duplicates(
                values.iter().map(|v| v.name.as_str()),
                "enumeration",
                &data_type.name,
                report,
            );
        }
        TypeDefinition::Alias { ty, .. } => check_type(globals, &data_type.name, ty, report),
    }
}

/// Parses a type written as text and reports syntax errors and unknown type names.
fn check_type(
    globals: &Globals<'_>,
    declared: &str,
    text: &str,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    let parse = parse_type(text);
    if let Some(error) = parse.errors().first() {
        let message = format!(
            "{declared}: the type '{text}' is not valid: {}",
            error.message
        );
        report(
            declared,
            Diagnostic::new(error.code, error.range.clone(), message),
        );
        return;
    }
    for node in parse.syntax().descendants().filter_map(TypeExpr::cast) {
        let name_ref = match node {
            TypeExpr::NamedType(named) => named.name(),
            TypeExpr::StringType(string) => string.name(),
            _ => continue,
        };
        let Some(name_ref) = name_ref else {
            continue;
        };
        let name = name_ref.text();
        if !globals.is_type(&name) {
            let mut diagnostic = unknown(Code::UnknownType, "type", &name, globals);
            diagnostic.message = format!("{declared}: {}", diagnostic.message);
            report(declared, diagnostic);
        }
    }
}

/// "unknown type 'X'" with a suggestion from the project's names when one is close.
fn unknown(code: Code, what: &str, name: &str, globals: &Globals<'_>) -> Diagnostic {
    let message = match globals.suggest(name) {
        Some(suggestion) => format!("unknown {what} '{name}'; did you mean '{suggestion}'?"),
        None => format!("unknown {what} '{name}'"),
    };
    Diagnostic::new(code, 0..0, message)
}

/// The edit distance of two names compared without case, counting a swap of two neighbouring
/// letters (`TP` for `PT`) as one edit, as typing mistakes often are.
fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().flat_map(char::to_lowercase).collect();
    let b: Vec<char> = b.chars().flat_map(char::to_lowercase).collect();
    // Rows i-2, i-1 and i of the optimal string alignment table.
    let mut before: Vec<usize> = Vec::new();
    let mut previous: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut current = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let substitution = previous[j] + usize::from(ca != cb);
            let mut best = substitution.min(previous[j + 1] + 1).min(current[j] + 1);
            if i > 0 && j > 0 && *ca == b[j - 1] && a[i - 1] == *cb {
                best = best.min(before[j - 1] + 1);
            }
            current.push(best);
        }
        before = std::mem::replace(&mut previous, current);
    }
    previous[b.len()]
}

/// The closest of `candidates` to `name`, if close enough to be a likely typo; never a name
/// with `__`, which is generated (a hidden variable of an LD or FBD body) and not the user's.
fn closest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let limit = (name.chars().count() / 3).clamp(1, 3);
    let mut seen = HashSet::new();
    candidates
        .filter(|candidate| !candidate.contains("__"))
        .filter(|candidate| seen.insert(candidate.to_lowercase()))
        .map(|candidate| (edit_distance(name, candidate), candidate))
        .filter(|(distance, _)| *distance <= limit)
        .min_by_key(|(distance, candidate)| (*distance, candidate.len()))
        .map(|(_, candidate)| candidate)
}

#[cfg(test)]
mod tests;
