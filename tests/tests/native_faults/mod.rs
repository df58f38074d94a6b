//! Every fault the native engine's checks raise (`docs/native-engine.md` §4.7, §11.2), each
//! instruction that raises it: compiled, run under both engines and compared
//! (`runtime::differential::run_both`), then the one fault checked for its task, kind, POU,
//! file, line and the instruction that raised it, and the other task seen to go on.

use program_image::{BinaryOp, Instr};
use runtime::engine::{FaultKind, FaultRecord};

/// A program that counts its cycles in a task of its own, beside the faulting one.
const TICK: &str = "PROGRAM tick VAR n : DINT; END_VAR n := n + 1; END_PROGRAM";

/// Cycles run: the fault comes in the first, the other task must go on after it.
const CYCLES: u64 = 3;

/// Compiles `source` (which declares a program `bad` that faults in its first cycle at the line
/// holding `marker`) with [`TICK`], each program in a task of its own (`Bad`, then `Fast`), runs
/// it under both engines and checks the fault: task `Bad`, kind `kind`, POU `pou`, file
/// `test.st` at `marker`'s line, raised by an instruction `raised_by` accepts; `tick` ran every
/// cycle.
#[track_caller]
fn faults(source: &str, marker: &str, pou: &str, raised_by: fn(&Instr) -> bool, kind: FaultKind) {
    faults_as(source, marker, pou, raised_by, |found| *found == kind);
}

/// [`faults`] with the kind checked by `is_expected`, for a kind whose value depends on the
/// layout; returns the fault.
#[track_caller]
fn faults_as(
    source: &str,
    marker: &str,
    pou: &str,
    raised_by: fn(&Instr) -> bool,
    is_expected: impl Fn(&FaultKind) -> bool,
) -> FaultRecord {
    let text = format!("{source}\n{TICK}\n");
    let mut project = compiler::SourceProject::new(&text);
    assert!(
        project.parse.errors().is_empty(),
        "syntax errors: {:?}",
        project.parse.errors()
    );
    let task = |name: &str, program: &str, priority: u8| project_model::Task {
        name: name.to_owned(),
        kind: project_model::TaskKind::Cyclic {
            interval_us: 10_000,
        },
        priority,
        watchdog: None,
        programs: vec![program.to_owned()],
    };
    project.project.tasks = vec![task("Bad", "bad", 1), task("Fast", "tick", 2)];
    let image = match compiler::compile_source(&project, "test.st") {
        Ok(image) => image,
        Err(error) => panic!("the source does not compile: {error:?}"),
    };
    let simulation = crate::simulate(image.clone(), CYCLES);
    let [fault] = simulation.faults() else {
        panic!("one fault expected: {:?}", simulation.faults())
    };
    let line = text
        .lines()
        .position(|line| line.contains(marker))
        .unwrap_or_else(|| panic!("{marker} is not in the source")) as u32
        + 1;
    assert_eq!(fault.task, "Bad", "{fault}");
    assert!(is_expected(&fault.kind), "{fault}");
    assert_eq!(fault.pou, pou, "{fault}");
    assert_eq!(fault.file.as_deref(), Some("test.st"), "{fault}");
    assert_eq!(fault.line, Some(line), "{fault}");
    assert_eq!(fault.cycle, 0, "{fault}");
    let instruction = image
        .pous
        .iter()
        .find(|found| found.name == fault.pou)
        .and_then(|found| found.code.get(fault.instruction as usize));
    assert!(
        instruction.is_some_and(raised_by),
        "{fault}: raised by {instruction:?}"
    );
    assert_eq!(crate::value(&simulation, "tick.n"), CYCLES.to_string());
    assert_eq!(simulation.cycles()[1], CYCLES);
    fault.clone()
}

#[test]
fn div_and_mod_by_zero_fault_in_every_integer_width() {
    for ty in [
        "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT",
    ] {
        for op in ["/", "MOD"] {
            let source = format!(
                "PROGRAM bad VAR a : {ty} := 7; b : {ty}; c : {ty}; END_VAR
                 c := a {op} b; (* faults *)
                 END_PROGRAM"
            );
            let raised_by: fn(&Instr) -> bool = if op == "/" {
                |instr| {
                    matches!(
                        instr,
                        Instr::Binary {
                            op: BinaryOp::Div,
                            ..
                        }
                    )
                }
            } else {
                |instr| {
                    matches!(
                        instr,
                        Instr::Binary {
                            op: BinaryOp::Mod,
                            ..
                        }
                    )
                }
            };
            faults(
                &source,
                "faults",
                "bad",
                raised_by,
                FaultKind::DivisionByZero,
            );
        }
    }
}

#[test]
fn an_array_index_outside_its_bounds_faults_with_the_bounds() {
    faults(
        "PROGRAM bad VAR a : ARRAY[1..10] OF INT; i : INT := 11; x : INT; END_VAR
         x := a[i]; (* read *)
         END_PROGRAM",
        "read",
        "bad",
        |instr| matches!(instr, Instr::LoadElement { .. }),
        FaultKind::IndexOutOfBounds {
            index: 11,
            low: 1,
            high: 10,
        },
    );
    faults(
        "PROGRAM bad VAR a : ARRAY[-5..5] OF LREAL; i : DINT := -6; END_VAR
         a[i] := 1.0; (* write *)
         END_PROGRAM",
        "write",
        "bad",
        |instr| matches!(instr, Instr::StoreElement { .. }),
        FaultKind::IndexOutOfBounds {
            index: -6,
            low: -5,
            high: 5,
        },
    );
}

#[test]
fn a_string_character_index_past_the_capacity_faults() {
    // A STRING(4) has characters 0 to 4: the terminator's place is addressable.
    faults(
        "PROGRAM bad VAR s : STRING(4); b : BYTE; i : INT := 5; END_VAR
         b := s[i]; (* character *)
         END_PROGRAM",
        "character",
        "bad",
        |instr| matches!(instr, Instr::LoadElement { .. }),
        FaultKind::IndexOutOfBounds {
            index: 5,
            low: 0,
            high: 4,
        },
    );
}

#[test]
fn an_open_array_index_outside_its_bounds_faults_in_the_function() {
    faults(
        "FUNCTION Get : INT VAR_IN_OUT v : ARRAY[*] OF INT; END_VAR VAR_INPUT i : DINT; END_VAR
         Get := v[i]; (* open *)
         END_FUNCTION
         PROGRAM bad VAR a : ARRAY[0..3] OF INT; x : INT; END_VAR
         x := Get(v := a, i := 4);
         END_PROGRAM",
        "open",
        "Get",
        |instr| matches!(instr, Instr::OpenElement { .. }),
        FaultKind::IndexOutOfBounds {
            index: 4,
            low: 0,
            high: 3,
        },
    );
}

#[test]
fn null_pointers_fault_when_read_written_or_moved_into() {
    faults(
        "PROGRAM bad VAR p : POINTER TO INT; x : INT; END_VAR
         x := p^; (* load *)
         END_PROGRAM",
        "load",
        "bad",
        |instr| matches!(instr, Instr::Load { .. }),
        FaultKind::NullPointer,
    );
    faults(
        "PROGRAM bad VAR p : POINTER TO INT; END_VAR
         p^ := 3; (* store *)
         END_PROGRAM",
        "store",
        "bad",
        |instr| matches!(instr, Instr::Store { .. }),
        FaultKind::NullPointer,
    );
    faults(
        "TYPE ST_Pair : STRUCT a : INT; b : INT; END_STRUCT END_TYPE
         PROGRAM bad VAR p : POINTER TO ST_Pair; x : INT; END_VAR
         x := p^.b; (* member *)
         END_PROGRAM",
        "member",
        "bad",
        |instr| matches!(instr, Instr::Offset { .. }),
        FaultKind::NullPointer,
    );
}

#[test]
fn calls_through_null_instances_fault_at_the_call() {
    faults(
        "FUNCTION_BLOCK FB_Count VAR n : INT; END_VAR n := n + 1; END_FUNCTION_BLOCK
         PROGRAM bad VAR p : POINTER TO FB_Count; END_VAR
         p^(); (* indirect *)
         END_PROGRAM",
        "indirect",
        "bad",
        |instr| matches!(instr, Instr::CallBlock { indirect: true, .. }),
        FaultKind::NullPointer,
    );
    faults(
        "FUNCTION_BLOCK FB_Count VAR n : INT; END_VAR
         METHOD Bump : INT Bump := 1; END_METHOD
         END_FUNCTION_BLOCK
         PROGRAM bad VAR r : REFERENCE TO FB_Count; x : INT; END_VAR
         x := r.Bump(); (* method *)
         END_PROGRAM",
        "method",
        "bad",
        |instr| {
            matches!(
                instr,
                Instr::CallFunction {
                    instance: Some(_),
                    ..
                }
            )
        },
        FaultKind::NullPointer,
    );
    faults(
        "INTERFACE I_Run METHOD Go : BOOL END_METHOD END_INTERFACE
         PROGRAM bad VAR none : I_Run; ok : BOOL; END_VAR
         ok := none.Go(); (* virtual *)
         END_PROGRAM",
        "virtual",
        "bad",
        |instr| matches!(instr, Instr::CallVirtual { .. }),
        FaultKind::NullPointer,
    );
}

#[test]
fn a_pointer_of_an_unknown_region_is_a_bad_pointer() {
    // A pointer of tag 7, which no region has, written through a word located at its place.
    faults(
        "PROGRAM bad VAR w AT %ML0 : LWORD; p AT %ML0 : POINTER TO INT; y : INT; END_VAR
         w := 16#0700000000000004;
         y := p^; (* bad *)
         END_PROGRAM",
        "bad *",
        "bad",
        |instr| matches!(instr, Instr::Load { .. }),
        FaultKind::BadPointer(0x0700_0000_0000_0004),
    );
}

#[test]
fn endless_recursion_overflows_the_stack() {
    faults(
        "FUNCTION Deep : DINT VAR_INPUT n : DINT; END_VAR
         Deep := Deep(n := n + 1); (* recursion *)
         END_FUNCTION
         PROGRAM bad VAR x : DINT; END_VAR
         x := Deep(n := 0);
         END_PROGRAM",
        "recursion",
        "Deep",
        |instr| matches!(instr, Instr::CallFunction { .. }),
        FaultKind::StackOverflow,
    );
}

#[test]
fn an_element_reached_through_the_pointer_path_faults_with_its_bounds() {
    // Two variable indices keep the pointer path (`Address`, then an `Element` per index):
    // the second index is outside.
    faults(
        "PROGRAM bad VAR a : ARRAY[1..2, 1..3] OF INT; i : INT := 1; j : INT := 4; x : INT; END_VAR
         x := a[i, j]; (* element *)
         END_PROGRAM",
        "element",
        "bad",
        |instr| matches!(instr, Instr::Element { .. }),
        FaultKind::IndexOutOfBounds {
            index: 4,
            low: 1,
            high: 3,
        },
    );
    // An array reached through a pointer, one index.
    faults(
        "PROGRAM bad VAR a : ARRAY[0..3] OF DINT; p : POINTER TO ARRAY[0..3] OF DINT; i : DINT := -1; x : DINT; END_VAR
         p := ADR(a);
         x := p^[i]; (* through *)
         END_PROGRAM",
        "through",
        "bad",
        |instr| matches!(instr, Instr::Element { .. }),
        FaultKind::IndexOutOfBounds {
            index: -1,
            low: 0,
            high: 3,
        },
    );
}
