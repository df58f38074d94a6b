//! The 50,000-line project of `compiler/benches/generate/` with a program `Main` that counts
//! its cycles and calls an instance of every function block from a 10 ms task: the project the
//! online change benchmark (`online_change_report`) changes and the native engine's
//! translation time (`docs/native-engine.md` §9.3, `scan_report`) is measured on.

// Each bench binary that includes this module uses part of it.
#![allow(dead_code)]

#[path = "../../../compiler/benches/generate/mod.rs"]
mod generate;

/// The interval of the task that runs the project.
pub const INTERVAL_US: u32 = 10_000;
/// The function block whose expression the online change benchmark changes and which gets a
/// variable.
pub const EDITED: &str = "FB_Station500";

/// The generated 50,000 lines with a program `Main` calling an instance of every function
/// block; `edited` applies the change to [`EDITED`].
pub fn source(edited: bool) -> (String, usize) {
    let (mut source, pairs) = generate::project_source(50_000);
    let mut main = String::from("PROGRAM Main\nVAR\n    n : UDINT;\n");
    for index in 0..pairs {
        main.push_str(&format!("    fb{index} : FB_Station{index};\n"));
    }
    main.push_str("END_VAR\nn := n + 1;\n");
    // The blocks run with their timers off: the generated code is written to be checked, and
    // after its timer's 500 ms its loops index past their arrays, which would fault the task.
    for index in 0..pairs {
        main.push_str(&format!(
            "fb{index}(xEnable := FALSE, iMode := {});\n",
            index % 7
        ));
    }
    main.push_str("END_PROGRAM\n");
    if edited {
        let start = source
            .find(&format!("FUNCTION_BLOCK {EDITED}\n"))
            .expect("the generated project has the edited function block");
        let end = start
            + source[start..]
                .find("END_FUNCTION_BLOCK")
                .expect("the function block ends");
        let block = source[start..end]
            .replace(
                "    iState : INT;\n",
                "    iState : INT;\n    rLast : REAL;\n",
            )
            .replace(
                "rSum := rSum + aValues[i]",
                "rLast := rSum;\n        rSum := rSum - aValues[i]",
            );
        assert_ne!(block, source[start..end], "the edit changes the block");
        source.replace_range(start..end, &block);
    }
    source.push_str(&main);
    (source, pairs)
}

/// The project compiled, with `Main` in a cyclic task of [`INTERVAL_US`].
pub fn compiled(source: &str) -> program_image::ProgramImage {
    let built = compiler::SourceProject::new(source);
    let mut project = built.project.clone();
    project.tasks = vec![project_model::Task {
        name: "Main10ms".to_owned(),
        kind: project_model::TaskKind::Cyclic {
            interval_us: INTERVAL_US,
        },
        priority: 0,
        watchdog: None,
        programs: vec!["Main".to_owned()],
    }];
    compiler::compile_project(&project).unwrap()
}

/// The project's image as a download sends it.
pub fn image(source: &str) -> Vec<u8> {
    compiled(source).encode()
}
