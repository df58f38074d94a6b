//! Images the compiler writes, and mutations of them with a correct hash, never make decoding
//! or `runtime::engine::Engine::new` panic, and an image that loads runs a cycle without a
//! panic. The fuzz target `program_image/fuzz` does the same at length; its crash inputs and
//! hand-made hostile images are kept in `program_image/tests/fuzz_regressions/` and loaded here.

use std::path::Path;
use std::sync::OnceLock;

use program_image::ProgramImage;
use proptest::prelude::*;
use runtime::engine::Engine;
use sha2::{Digest, Sha256};

mod online_change;

/// Programs that use most instructions: calls, blocks, timers, arrays, strings, loops, CASE.
const PROGRAMS: [&str; 3] = [
    "
FUNCTION scale : REAL
VAR_INPUT x : REAL; k : REAL; END_VAR
scale := x * k + 0.5;
END_FUNCTION

FUNCTION_BLOCK counter
VAR_INPUT step : DINT; END_VAR
VAR_OUTPUT total : DINT; END_VAR
total := total + step;
END_FUNCTION_BLOCK

PROGRAM main
VAR
    i : DINT;
    a : ARRAY[1..8] OF DINT;
    r : REAL := 1.5;
    c : counter;
    t : TON;
    run : BOOL := TRUE;
    w : WORD := 16#00F0;
END_VAR
FOR i := 1 TO 8 DO
    a[i] := a[i] + i * 2;
END_FOR
r := scale(r, 0.5);
c(step := a[3]);
t(IN := run, PT := T#20MS);
IF t.Q THEN run := FALSE; END_IF
w := ROL(w, 3) XOR SHR(w, 1);
CASE i MOD 4 OF
    0: i := 1;
    1..2: i := i - 1;
ELSE
    i := 0;
END_CASE
END_PROGRAM
",
    "
PROGRAM main
VAR
    s : STRING(20) := 'abc';
    n : INT;
    x : LREAL := 2.0;
    b : BOOL;
    q : BYTE;
END_VAR
// The engine does not run the string functions yet (runtime/src/engine/strings.rs), so
// the strings here are only assigned.
s := 'abcde';
n := 5;
WHILE n > 0 DO
    n := n - 1;
    x := SQRT(x) + 1.0;
END_WHILE
b := x > 1.5 AND NOT b;
q := DINT_TO_BYTE(LREAL_TO_DINT(x * 10.0));
END_PROGRAM
",
    "
TYPE point : STRUCT x : DINT; y : DINT; END_STRUCT END_TYPE

PROGRAM main
VAR
    p : point;
    ps : ARRAY[0..3] OF point;
    ptr : POINTER TO point;
    k : INT;
    edge : R_TRIG;
    count : CTU;
END_VAR
ptr := ADR(ps[2]);
ptr^.x := ptr^.x + 1;
p := ps[2];
REPEAT
    k := k + 1;
    ps[k MOD 4].y := ps[(k + 3) MOD 4].y + k;
UNTIL k >= 3
END_REPEAT
ptr := ADR(ps[k MOD 4]);
edge(CLK := p.x MOD 2 = 1);
count(CU := edge.Q, PV := 5);
END_PROGRAM
",
];

/// The programs compiled, encoded without their trailer.
fn seeds() -> &'static [Vec<u8>] {
    static SEEDS: OnceLock<Vec<Vec<u8>>> = OnceLock::new();
    SEEDS.get_or_init(compile_seeds)
}

fn compile_seeds() -> Vec<Vec<u8>> {
    PROGRAMS
        .iter()
        .enumerate()
        .map(|(index, text)| {
            let source = compiler::SourceProject::new(text);
            let image = match compiler::compile_source(&source, "seed.st") {
                Ok(image) => image,
                Err(error) => panic!("program {index} does not compile: {error:?}"),
            };
            let mut bytes = image.encode();
            bytes.truncate(bytes.len() - 32);
            bytes
        })
        .collect()
}

/// Decodes `content` with a correct hash and, if it decodes, loads it and runs one cycle of
/// each task with a short watchdog; a panic anywhere fails the caller.
fn load_and_run(content: &[u8]) {
    let mut bytes = content.to_vec();
    bytes.extend_from_slice(&Sha256::digest(content));
    let Ok(mut image) = ProgramImage::decode(&bytes) else {
        return;
    };
    for task in &mut image.tasks {
        task.watchdog_ns = 10_000_000;
        task.watchdog_sensitivity = 1;
    }
    let Ok(mut engine) = Engine::new(image) else {
        return;
    };
    for task in 0..engine.image().tasks.len() {
        let _ = engine.run_cycle(task, 1_000_000, 0);
    }
}

#[test]
fn the_seed_programs_load_and_run() {
    for (index, seed) in seeds().iter().enumerate() {
        let mut bytes = seed.clone();
        bytes.extend_from_slice(&Sha256::digest(seed));
        let image = ProgramImage::decode(&bytes).unwrap();
        let mut engine = Engine::new(image).unwrap();
        for cycle in 0..5 {
            if let Err(fault) = engine.run_cycle(0, cycle * 10_000_000, cycle as u64) {
                panic!("program {index} faults: {fault}");
            }
        }
    }
    // `SEED_DIR=$PWD/program_image/fuzz/seeds` (absolute) refreshes the fuzz target's seeds.
    if let Some(dir) = std::env::var_os("SEED_DIR") {
        let dir = Path::new(&dir);
        std::fs::create_dir_all(dir).unwrap();
        for (index, seed) in seeds().iter().enumerate() {
            std::fs::write(dir.join(format!("program{index}.img")), seed).unwrap();
        }
    }
}

/// The folder of saved fuzz inputs: crashes the fuzz target found and hand-made hostile images
/// (its README says what each file is).
fn regression_dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../program_image/tests/fuzz_regressions")
}

/// How a saved input is given to the decoder.
#[derive(Clone, Copy, Debug)]
enum Form {
    /// The file's bytes as they are: a whole image with its trailer.
    AsStored,
    /// The file's bytes with their correct SHA-256 appended, as the fuzz target does.
    WithHash,
}

/// The hand-made hostile inputs of the folder, the form they are meant to be decoded in, and
/// words of the error they must be refused with. Checking the error shows that each one still
/// reaches the check it was made for, rather than being refused earlier for another reason.
const HOSTILE_INPUTS: [(&str, Form, &str); 13] = [
    ("empty.img", Form::WithHash, "the image is truncated"),
    ("header-only.img", Form::WithHash, "the image is truncated"),
    (
        "truncated-in-a-section.img",
        Form::WithHash,
        "is truncated: it says",
    ),
    ("wrong-version.img", Form::AsStored, "format version 2"),
    (
        "unknown-header-flags.img",
        Form::AsStored,
        "unknown flags 0x8000",
    ),
    ("bad-hash.img", Form::AsStored, "SHA-256 does not match"),
    (
        "huge-section-length.img",
        Form::WithHash,
        "section 1 is truncated: it says 4294967295 bytes",
    ),
    (
        "huge-section-count.img",
        Form::WithHash,
        "the image is truncated",
    ),
    (
        "huge-vector-length.img",
        Form::WithHash,
        "section 'types' is malformed",
    ),
    (
        "huge-symbol-count.img",
        Form::WithHash,
        "section 'symbols' is malformed",
    ),
    (
        "sections-out-of-order.img",
        Form::WithHash,
        "section 1 is out of order",
    ),
    (
        "unknown-critical-section.img",
        Form::WithHash,
        "needs section 99",
    ),
    (
        "trailing-bytes.img",
        Form::WithHash,
        "3 unexpected bytes after the last section",
    ),
];

#[test]
fn the_saved_fuzz_inputs_load_without_a_panic() {
    let dir = regression_dir();
    let readme = std::fs::read_to_string(dir.join("README.md"))
        .unwrap_or_else(|error| panic!("{}: {error}", dir.join("README.md").display()));
    let mut loaded = 0;
    for entry in
        std::fs::read_dir(&dir).unwrap_or_else(|error| panic!("{}: {error}", dir.display()))
    {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "img") {
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            assert!(
                readme.contains(&format!("`{name}`")),
                "{name} is not described in the folder's README"
            );
            let content = std::fs::read(&path).unwrap();
            // The fuzz target decodes its input as it is, then with its hash appended.
            let _ = ProgramImage::decode(&content);
            load_and_run(&content);
            loaded += 1;
        }
    }
    assert!(
        loaded >= HOSTILE_INPUTS.len(),
        "only {loaded} inputs in {}",
        dir.display()
    );
}

#[test]
fn each_hostile_input_is_refused_by_the_check_it_was_made_for() {
    for (name, form, words) in HOSTILE_INPUTS {
        let path = regression_dir().join(name);
        let mut bytes =
            std::fs::read(&path).unwrap_or_else(|error| panic!("{}: {error}", path.display()));
        if let Form::WithHash = form {
            let hash = Sha256::digest(&bytes);
            bytes.extend_from_slice(&hash);
        }
        match ProgramImage::decode(&bytes) {
            Ok(_) => panic!("{name} ({form:?}) decodes"),
            Err(error) => assert!(
                error.to_string().contains(words),
                "{name} ({form:?}) is refused with \"{error}\", not with \"{words}\""
            ),
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn mutated_images_with_a_correct_hash_never_panic(
        program in 0..PROGRAMS.len(),
        edits in proptest::collection::vec(
            (any::<proptest::sample::Index>(), any::<u8>()),
            1..6,
        ),
    ) {
        let mut content = seeds()[program].clone();
        for (at, byte) in &edits {
            let at = at.index(content.len());
            content[at] = *byte;
        }
        load_and_run(&content);
    }
}

#[test]
fn an_array_element_of_extreme_bounds_does_not_panic() {
    // The verifier accepts any non-zero count and any low bound for `Element`, and any low
    // bound for the fused `LoadElement` and `StoreElement` (whose count it checks against the
    // array's region); the engine must compute the bounds and the element offset without
    // overflowing.
    let (mut pointer_elements, mut fused_elements) = (0, 0);
    for (low, count) in [
        (1, 1u64 << 63),
        (i64::MIN, 1u64 << 63),
        (i64::MIN, u64::MAX),
        (i64::MAX, 2),
    ] {
        for seed in seeds() {
            let mut bytes = seed.clone();
            bytes.extend_from_slice(&Sha256::digest(&bytes));
            let mut image = ProgramImage::decode(&bytes).unwrap();
            for pou in &mut image.pous {
                for instr in &mut pou.code {
                    match instr {
                        program_image::Instr::Element {
                            low: l, count: c, ..
                        } => {
                            (*l, *c) = (low, count);
                            pointer_elements += 1;
                        }
                        program_image::Instr::LoadElement { low: l, .. }
                        | program_image::Instr::StoreElement { low: l, .. } => {
                            *l = low;
                            fused_elements += 1;
                        }
                        _ => {}
                    }
                }
            }
            let content = image.encode();
            load_and_run(&content[..content.len() - 32]);
        }
    }
    assert!(pointer_elements > 0 && fused_elements > 0);
}
