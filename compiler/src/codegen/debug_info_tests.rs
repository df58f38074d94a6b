use program_image::{FrameVariableKind, ProgramImage, TypeDef};

use crate::{SourceProject, compile_source};

fn compiled(source: &str) -> ProgramImage {
    compile_source(&SourceProject::new(source), "test.st")
        .unwrap_or_else(|error| panic!("the source does not compile: {error}"))
}

const SOURCE: &str = "FUNCTION Scale : REAL
VAR_INPUT
    x : INT;
END_VAR
VAR_IN_OUT
    text : STRING(40);
END_VAR
VAR
    factor : REAL := 2.5;
END_VAR
Scale := INT_TO_REAL(x) * factor;
text := 'scaled';
END_FUNCTION

PROGRAM Main
VAR
    y : REAL;
    s : STRING(40);
END_VAR
VAR_TEMP
    scratch : INT;
END_VAR
scratch := 3;
y := Scale(scratch, s);
END_PROGRAM
";

#[test]
fn the_debug_section_names_each_frame_variable_with_its_kind_type_and_offset() {
    let image = compiled(SOURCE);
    let Some(debug) = &image.debug else {
        panic!("no debug section");
    };
    assert_eq!(debug.pous.len(), image.pous.len());
    let index = |name: &str| {
        image
            .pous
            .iter()
            .position(|pou| pou.name == name)
            .unwrap_or_else(|| panic!("no POU {name}"))
    };
    let scale = &debug.pous[index("Scale")].frame;
    let names: Vec<(&str, FrameVariableKind)> = scale
        .iter()
        .map(|variable| (variable.name.as_str(), variable.kind))
        .collect();
    assert_eq!(
        names,
        [
            ("x", FrameVariableKind::Input),
            ("text", FrameVariableKind::InOut),
            ("Scale", FrameVariableKind::Result),
            ("factor", FrameVariableKind::Var),
        ]
    );
    // An in-out's type is its pointee's: the frame holds a pointer to the caller's string.
    assert!(matches!(
        image.types[scale[1].ty as usize],
        TypeDef::String { length: 40 }
    ));
    let offsets: Vec<u32> = scale.iter().map(|variable| variable.offset).collect();
    assert_eq!(offsets, [0, 8, 16, 20]);
    let main = &debug.pous[index("Main")].frame;
    assert_eq!(main.len(), 1, "a program's frame holds its VAR_TEMP only");
    assert_eq!(main[0].name, "scratch");
    assert_eq!(main[0].kind, FrameVariableKind::Temp);
}

#[test]
fn a_source_hash_changes_with_its_own_pou_only() {
    let before = compiled(SOURCE);
    let after = compiled(&SOURCE.replace("scratch := 3;", "scratch := 4;"));
    let hashes = |image: &ProgramImage| -> Vec<[u8; 32]> {
        image
            .debug
            .iter()
            .flat_map(|debug| debug.pous.iter().map(|pou| pou.source_hash))
            .collect()
    };
    let (before, after) = (hashes(&before), hashes(&after));
    assert_eq!(before.len(), after.len());
    let changed = before.iter().zip(&after).filter(|(a, b)| a != b).count();
    assert_eq!(changed, 1, "only Main's text changed");
}
