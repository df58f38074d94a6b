//! Name resolution tests on small projects built in code.

use project_model::{
    Body, GlobalVarList, Node, Object, Pou, PouKind, Project, Task, TaskKind, VarSection, Variable,
};

use super::*;

fn pou(name: &str, kind: PouKind, variables: Vec<Variable>, body: &str) -> Node {
    Node::Object(Object::Pou(Pou {
        name: name.into(),
        kind,
        return_type: (kind == PouKind::Function).then(|| "INT".into()),
        extends: None,
        implements: Vec::new(),
        comment: String::new(),
        variables,
        body: Body::st(body),
        methods: Vec::new(),
        properties: Vec::new(),
        actions: Vec::new(),
        transitions: Vec::new(),
    }))
}

fn project(nodes: Vec<Node>) -> Project {
    let mut project = Project::default();
    project.application.children = nodes;
    project
}

fn messages(project: &Project) -> Vec<String> {
    check_project(project)
        .into_iter()
        .filter(|found| found.diagnostic.severity == crate::Severity::Error)
        .map(|found| {
            format!(
                "{} {}: {}",
                found.file.display(),
                found.diagnostic.code.id(),
                found.diagnostic.message
            )
        })
        .collect()
}

#[test]
fn the_example_project_has_no_findings() {
    let loaded = project_model::load_project(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../assets/examples/packaging_machine"),
    )
    .expect("the example loads");
    assert_eq!(messages(&loaded.project), Vec::<String>::new());
}

#[test]
fn unknown_names_are_reported_with_a_suggestion() {
    let gvl = Node::Object(Object::Gvl(GlobalVarList {
        name: "GVL".into(),
        comment: String::new(),
        variables: vec![Variable {
            section: VarSection::VarGlobal,
            ..Variable::new("xStartButton", "BOOL")
        }],
    }));
    let main = pou(
        "Main",
        PouKind::Program,
        vec![
            Variable::new("tonDelay", "TON"),
            Variable::new("iCount", "INT"),
        ],
        "tonDelay(IN := xStartButon, PT := T#1s);\niCount := iCount + ABS(-1) + REAL_TO_INT(1.5) + F(1);\nundefined := GVL.xStartButton OR GVL.xStopButton;\n",
    );
    let function = pou(
        "F",
        PouKind::Function,
        vec![Variable {
            section: VarSection::VarInput,
            ..Variable::new("a", "INT")
        }],
        "F := a;",
    );
    assert_eq!(
        messages(&project(vec![gvl, main, function])),
        vec![
            "application/Main.st E0101: unknown name 'xStartButon'; did you mean 'xStartButton'?",
            "application/Main.st E0101: unknown name 'undefined'",
            "application/Main.st E0101: 'GVL' has no member 'xStopButton'; did you mean 'xStartButton'?",
        ]
    );
}

#[test]
fn unknown_types_and_programs_are_reported() {
    let main = pou(
        "Main",
        PouKind::Program,
        vec![
            Variable::new("fb", "FB_Conveyr"),
            Variable::new("a", "ARRAY[1..3] OF FB_Conveyor"),
            Variable::new("s", "STRING(20)"),
            Variable::new("p", "POINTER TO Missing"),
        ],
        "",
    );
    let fb = pou("FB_Conveyor", PouKind::FunctionBlock, Vec::new(), "");
    let mut project = project(vec![main, fb]);
    project.tasks.push(Task {
        name: "MainTask".into(),
        kind: TaskKind::Cyclic {
            interval_us: 10_000,
        },
        priority: 1,
        watchdog: None,
        programs: vec!["Main".into(), "FB_Conveyor".into()],
    });
    assert_eq!(
        messages(&project),
        vec![
            "application/Main.pou.toml E0102: fb: unknown type 'FB_Conveyr'; did you mean 'FB_Conveyor'?",
            "application/Main.pou.toml E0102: p: unknown type 'Missing'",
            "rivet.toml E0103: task 'MainTask' calls 'FB_Conveyor', which is not a PROGRAM of the project",
        ]
    );
}

#[test]
fn inherited_members_method_locals_and_sfc_steps_resolve() {
    let mut base = pou(
        "FB_Base",
        PouKind::FunctionBlock,
        vec![Variable::new("xBusy", "BOOL")],
        "",
    );
    let mut derived = pou(
        "FB_Derived",
        PouKind::FunctionBlock,
        Vec::new(),
        "xBusy := TRUE;\nINITIAL_STEP Idle: Reset(N); END_STEP\nx := Idle.X;",
    );
    if let Node::Object(Object::Pou(pou)) = &mut derived {
        pou.extends = Some("FB_Base".into());
        pou.variables.push(Variable::new("x", "BOOL"));
        pou.actions.push(project_model::PouAction {
            name: "Reset".into(),
            body: Body::st("xBusy := FALSE;"),
        });
        pou.methods.push(project_model::Method {
            name: "Start".into(),
            return_type: Some("BOOL".into()),
            access: project_model::AccessSpecifier::Public,
            is_abstract: false,
            comment: String::new(),
            variables: vec![Variable::new("iTry", "INT")],
            body: Body::st("iTry := iTry + 1; Start := xBusy;"),
        });
    }
    if let Node::Object(Object::Pou(pou)) = &mut base {
        pou.body = Body::st("xBusy := NOT xBusy;");
    }
    assert_eq!(
        messages(&project(vec![base, derived])),
        Vec::<String>::new()
    );
}

#[test]
fn swapped_letters_count_as_one_edit() {
    assert_eq!(edit_distance("TP", "PT"), 1);
    assert_eq!(edit_distance("xStartButon", "xStartButton"), 1);
    assert_eq!(edit_distance("abc", "abc"), 0);
    assert_eq!(edit_distance("", "abc"), 3);
    assert_eq!(
        closest("TP", ["IN", "PT", "Q", "ET"].into_iter()),
        Some("PT")
    );
}

#[test]
fn an_array_with_open_bounds_is_refused_outside_a_var_in_out_parameter() {
    use project_model::{DataType, StructMember, VarSection};
    let open = |name: &str, section: VarSection| Variable {
        section,
        ..Variable::new(name, "ARRAY[*] OF INT")
    };
    let function = pou(
        "F_Sum",
        PouKind::Function,
        vec![open("values", VarSection::VarInOut)],
        "F_Sum := values[LOWER_BOUND(values, 1)];",
    );
    let program = pou(
        "Main",
        PouKind::Program,
        vec![
            open("local", VarSection::Var),
            open("passed", VarSection::VarInOut),
        ],
        "local[0] := 1; passed[0] := 1;",
    );
    let structure = Node::Object(Object::DataType(DataType {
        name: "ST_Open".into(),
        comment: String::new(),
        definition: TypeDefinition::Struct {
            extends: None,
            members: vec![StructMember {
                name: "member".into(),
                ty: "ARRAY[*, 0..1] OF INT".into(),
                ..StructMember::default()
            }],
        },
    }));
    let found = messages(&project(vec![function, program, structure]));
    let refused: Vec<&String> = found.iter().filter(|m| m.contains("E0133")).collect();
    assert_eq!(refused.len(), 3, "{found:?}");
    for name in ["'local'", "'passed'", "'member'"] {
        assert!(
            refused.iter().any(|m| m.contains(name)),
            "{name} in {found:?}"
        );
    }
    assert!(!refused.iter().any(|m| m.contains("'values'")), "{found:?}");
}

#[test]
fn the_clock_operators_give_time_and_ltime_and_take_no_argument() {
    let main = pou(
        "Main",
        PouKind::Program,
        vec![
            Variable::new("t", "TIME"),
            Variable::new("l", "LTIME"),
            Variable::new("b", "BOOL"),
        ],
        "t := TIME() - t;\nl := LTIME() - l;\nb := TIME() - t;\nb := LTIME();\nt := TIME(t);\nl := LTIME(IN := l);\n",
    );
    // The first two lines check; the BOOL assignments name the types the calls have.
    assert_eq!(
        messages(&project(vec![main])),
        vec![
            "application/Main.st E0104: the assignment expects BOOL, found TIME; IEC converts only to wider types, so write TIME_TO_BOOL(…)",
            "application/Main.st E0104: the assignment expects BOOL, found LTIME; IEC converts only to wider types, so write LTIME_TO_BOOL(…)",
            "application/Main.st E0106: 'TIME' takes 0 input(s), but 1 are given",
            "application/Main.st E0106: 'LTIME' has no parameter 'IN'",
        ]
    );
}

#[test]
fn a_constant_index_past_a_strings_terminator_is_refused_by_the_checker() {
    let main = pou(
        "Main",
        PouKind::Program,
        vec![Variable::new("s", "STRING(4)"), Variable::new("b", "BYTE")],
        "b := s[4];\nb := s[5];\nb := s[-1];\nb := s[1, 2];\n",
    );
    assert_eq!(
        messages(&project(vec![main])),
        vec![
            "application/Main.st E0111: index 5 is outside the characters 0..4 of 's'",
            "application/Main.st E0111: index -1 is outside the characters 0..4 of 's'",
            "application/Main.st E0111: 's' is a string and takes one index, but 2 are given",
        ]
    );
}
