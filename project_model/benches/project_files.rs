//! Load and save times of a large project: `cargo bench -p project_model`.
//!
//! Prints the median of several runs for a project of 1,000 POUs (20 variables and a 50-line
//! ST body each, 50,000 lines of ST in all) plus 100 global variable lists.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::collections::BTreeSet;
use std::time::{Duration, Instant};

use project_model::{
    Body, GlobalVarList, Node, Object, Pou, PouKind, Project, VarSection, Variable, load_project,
    save_project,
};

fn large_project() -> Project {
    let mut project = Project {
        name: "Bench".into(),
        ..Project::default()
    };
    let body: String = (0..50)
        .map(|line| {
            format!(
                "    xOut{} := xIn{} AND NOT xOut{};\n",
                line % 20,
                line % 20,
                line % 20
            )
        })
        .collect();
    for index in 0..1000 {
        let variables = (0..20)
            .map(|v| Variable {
                section: if v % 2 == 0 {
                    VarSection::VarInput
                } else {
                    VarSection::Var
                },
                comment: format!("variable {v} of POU {index}"),
                ..Variable::new(format!("xIn{v}"), "BOOL")
            })
            .collect();
        project
            .application
            .children
            .push(Node::Object(Object::Pou(Pou {
                name: format!("FB_Unit{index}"),
                kind: PouKind::FunctionBlock,
                return_type: None,
                extends: None,
                implements: Vec::new(),
                comment: String::new(),
                variables,
                body: Body::st(body.clone()),
                methods: Vec::new(),
                properties: Vec::new(),
                actions: Vec::new(),
                transitions: Vec::new(),
            })));
    }
    for index in 0..100 {
        let variables = (0..50)
            .map(|v| Variable {
                section: VarSection::VarGlobal,
                address: Some(format!("%MW{}", index * 50 + v)),
                ..Variable::new(format!("wValue{v}"), "WORD")
            })
            .collect();
        project
            .application
            .children
            .push(Node::Object(Object::Gvl(GlobalVarList {
                name: format!("GVL_{index}"),
                comment: String::new(),
                variables,
            })));
    }
    project
}

fn median(mut samples: Vec<Duration>) -> Duration {
    samples.sort();
    samples[samples.len() / 2]
}

fn measure(runs: usize, mut run: impl FnMut()) -> Duration {
    median(
        (0..runs)
            .map(|_| {
                let start = Instant::now();
                run();
                start.elapsed()
            })
            .collect(),
    )
}

fn main() {
    let project = large_project();
    let runs = 7;

    let first_save = measure(runs, || {
        let dir = tempfile::tempdir().unwrap();
        save_project(&project, dir.path(), &BTreeSet::new()).unwrap();
    });

    let dir = tempfile::tempdir().unwrap();
    let report = save_project(&project, dir.path(), &BTreeSet::new()).unwrap();
    let files = report.files.len();
    let unchanged_save = measure(runs, || {
        let report = save_project(&project, dir.path(), &report.files).unwrap();
        assert!(report.written.is_empty());
    });
    let load = measure(runs, || {
        let loaded = load_project(dir.path()).unwrap();
        assert_eq!(loaded.project.application.children.len(), 1100);
    });

    println!("project_files: 1,100 objects, {files} files, 50,000 ST lines");
    println!(
        "  first save       {:>8.1} ms",
        first_save.as_secs_f64() * 1000.0
    );
    println!(
        "  unchanged save   {:>8.1} ms (nothing written)",
        unchanged_save.as_secs_f64() * 1000.0
    );
    println!("  load             {:>8.1} ms", load.as_secs_f64() * 1000.0);
}
