//! The architecture rules of ARCHITECTURE.md, checked against `cargo metadata`.
//!
//! Each rule names which of our crates may depend on which, and which crates may use the UI
//! frameworks and tokio. A change that breaks a rule fails here with the edge that broke it.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::collections::{BTreeMap, BTreeSet};
use std::process::Command;

use serde_json::Value;

/// Our crates and the crates of ours each may depend on (normal dependencies).
const ALLOWED_INTERNAL: &[(&str, &[&str])] = &[
    ("project_model", &[]),
    ("program_image", &[]),
    ("motion", &[]),
    // The online protocol's one definition: no crate of ours; only the two peers use it.
    ("online_protocol", &[]),
    // The PLCopen XML reader: pure, no crate of ours.
    ("plcopen", &["project_model"]),
    ("assets", &[]),
    ("compiler", &["project_model", "program_image"]),
    (
        "runtime",
        &["program_image", "motion", "online_protocol", "jit"],
    ),
    // The native engine: the translator and the only unsafe module (docs/native-engine.md §1.1).
    ("jit", &["program_image"]),
    ("online", &["program_image", "online_protocol"]),
    (
        "editor",
        &["project_model", "compiler", "tree-sitter-rivet-st"],
    ),
    ("cam_editor", &["project_model", "motion"]),
    (
        "app",
        &[
            "assets",
            "cam_editor",
            "compiler",
            "editor",
            "motion",
            "online",
            // `rivet import` and File ▸ Import PLCopen XML… (`docs/plcopen-xml.md` §6).
            "plcopen",
            "program_image",
            "project_model",
            "runtime",
        ],
    ),
    ("tests", &[]),
    // The editor's grammar: no crate of ours at run time (it uses `compiler` only in tests).
    ("tree-sitter-rivet-st", &[]),
];

/// Our crates and the crates of ours each may use in its tests (dev-dependencies), where that
/// is narrower than "any": the grammar is checked against the compiler and nothing else.
const ALLOWED_INTERNAL_DEV: &[(&str, &[&str])] = &[("tree-sitter-rivet-st", &["compiler"])];

/// Third-party crates that only some of our crates may use directly.
const RESTRICTED: &[(&str, &[&str])] = &[
    ("eframe", &["app"]),
    ("egui", &["app", "editor", "cam_editor"]),
    ("egui_tiles", &["app"]),
    ("egui_extras", &["app", "editor", "cam_editor"]),
    ("egui_plot", &["app", "editor", "cam_editor"]),
    ("tokio", &["app", "online", "runtime"]),
    ("tokio-modbus", &["app", "online", "runtime"]),
    // Serial ports belong to the soft PLC: its RTU slave and its Modbus master's serial lines.
    ("tokio-serial", &["runtime"]),
    // The code generator of the native engine stays behind `jit`'s audit boundary.
    ("cranelift-codegen", &["jit"]),
    ("cranelift-frontend", &["jit"]),
    ("cranelift-jit", &["jit"]),
    ("cranelift-module", &["jit"]),
    ("cranelift-native", &["jit"]),
    // Tree-sitter serves editor highlighting and folding only; diagnostics come from the compiler.
    ("tree-sitter", &["tree-sitter-rivet-st", "editor"]),
];

/// Each workspace crate with its normal (non-dev, non-build) dependencies by package name.
fn workspace_dependencies() -> BTreeMap<String, BTreeSet<String>> {
    workspace_dependencies_of_kind(None)
}

/// Each workspace crate with its dependencies of one kind by package name: `None` for normal
/// dependencies, `Some("dev")` or `Some("build")` for the others.
fn workspace_dependencies_of_kind(kind: Option<&str>) -> BTreeMap<String, BTreeSet<String>> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let output = Command::new(cargo)
        .args([
            "metadata",
            "--format-version",
            "1",
            "--no-deps",
            "--offline",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo metadata runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let metadata: Value = serde_json::from_slice(&output.stdout).expect("cargo metadata is JSON");
    let mut crates = BTreeMap::new();
    for package in metadata["packages"].as_array().expect("packages") {
        let name = package["name"].as_str().expect("name").to_owned();
        let dependencies = package["dependencies"]
            .as_array()
            .expect("dependencies")
            .iter()
            .filter(|dependency| dependency["kind"].as_str() == kind)
            .map(|dependency| dependency["name"].as_str().expect("name").to_owned())
            .collect();
        crates.insert(name, dependencies);
    }
    crates
}

/// The crates that may not take the workspace's lints (whose `unsafe_code = "forbid"` cannot be
/// lifted for one item) and deny unsafe code in their own table instead: the native engine
/// (`jit::machine`) and the grammar's one `unsafe extern` declaration.
const UNSAFE_DENIED_NOT_FORBIDDEN: &[&str] = &["jit", "tree-sitter-rivet-st"];

/// Each workspace crate's name with the text of its `Cargo.toml`.
fn workspace_manifests() -> Vec<(String, String)> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let output = Command::new(cargo)
        .args([
            "metadata",
            "--format-version",
            "1",
            "--no-deps",
            "--offline",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo metadata runs");
    let metadata: Value = serde_json::from_slice(&output.stdout).expect("cargo metadata is JSON");
    metadata["packages"]
        .as_array()
        .expect("packages")
        .iter()
        .map(|package| {
            let path = package["manifest_path"].as_str().expect("manifest_path");
            let text = std::fs::read_to_string(path).expect("a readable Cargo.toml");
            (package["name"].as_str().expect("name").to_owned(), text)
        })
        .collect()
}

/// Whether a manifest takes the workspace's lints (`[lints]` then `workspace = true`).
fn takes_workspace_lints(manifest: &str) -> bool {
    let mut lines = manifest.lines().map(str::trim);
    while let Some(line) = lines.next() {
        if line == "[lints]" {
            return lines.next() == Some("workspace = true");
        }
    }
    false
}

/// Whether a manifest's own `[lints.rust]` table denies unsafe code.
fn denies_unsafe_code(manifest: &str) -> bool {
    let Some((_, rust)) = manifest.split_once("[lints.rust]") else {
        return false;
    };
    let table = rust.split("\n[").next().unwrap_or_default();
    table
        .lines()
        .any(|line| line.replace(' ', "") == "unsafe_code=\"deny\"")
}

#[test]
fn unsafe_code_is_forbidden_everywhere_but_in_the_two_crates_that_deny_it() {
    for (name, manifest) in workspace_manifests() {
        if UNSAFE_DENIED_NOT_FORBIDDEN.contains(&name.as_str()) {
            assert!(
                !takes_workspace_lints(&manifest) && denies_unsafe_code(&manifest),
                "{name} must deny unsafe code in its own [lints.rust] table"
            );
        } else {
            assert!(
                takes_workspace_lints(&manifest),
                "{name} must take the workspace's lints ([lints] workspace = true), which forbid unsafe code"
            );
        }
    }
    // Inside `jit`, only `machine.rs` allows it (docs/native-engine.md §1.1).
    let jit_source = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../jit/src");
    let mut allowing = Vec::new();
    let mut folders = vec![jit_source.clone()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).expect("jit/src is readable") {
            let path = entry.expect("an entry").path();
            if path.is_dir() {
                folders.push(path);
            } else if std::fs::read_to_string(&path)
                .expect("a source file")
                .contains("allow(unsafe_code)")
            {
                allowing.push(path.strip_prefix(&jit_source).expect("inside").to_owned());
            }
        }
    }
    assert_eq!(allowing, vec![std::path::PathBuf::from("machine.rs")]);
}

#[test]
fn the_lint_checks_read_manifests_as_written() {
    assert!(takes_workspace_lints(
        "[package]\nname = \"x\"\n\n[lints]\nworkspace = true\n"
    ));
    assert!(!takes_workspace_lints(
        "[lints.rust]\nunsafe_code = \"deny\"\n"
    ));
    assert!(denies_unsafe_code(
        "[lints.rust]\nmissing_docs = \"warn\"\nunsafe_code = \"deny\"\n"
    ));
    assert!(!denies_unsafe_code(
        "[lints.rust]\nunsafe_code = \"allow\"\n"
    ));
    assert!(!denies_unsafe_code("[lints]\nworkspace = true\n"));
}

#[test]
fn every_workspace_crate_has_a_rule() {
    let crates = workspace_dependencies();
    let ruled: BTreeSet<&str> = ALLOWED_INTERNAL.iter().map(|(name, _)| *name).collect();
    let found: BTreeSet<&str> = crates.keys().map(String::as_str).collect();
    assert_eq!(
        found, ruled,
        "add the new crate to ARCHITECTURE.md and to this test"
    );
}

type CrateMap = BTreeMap<String, BTreeSet<String>>;

/// The edges between our crates that no rule allows.
fn internal_violations(crates: &CrateMap) -> Vec<String> {
    let mut violations = Vec::new();
    for (name, dependencies) in crates {
        let allowed = ALLOWED_INTERNAL
            .iter()
            .find(|(ruled, _)| ruled == name)
            .map_or(&[][..], |(_, allowed)| *allowed);
        for dependency in dependencies {
            if crates.contains_key(dependency) && !allowed.contains(&dependency.as_str()) {
                violations.push(format!("{name} -> {dependency}"));
            }
        }
    }
    violations
}

/// The uses of UI frameworks and tokio outside the crates allowed them.
fn restricted_violations(crates: &CrateMap) -> Vec<String> {
    let mut violations = Vec::new();
    for (name, dependencies) in crates {
        for (restricted, allowed) in RESTRICTED {
            if dependencies.contains(*restricted) && !allowed.contains(&name.as_str()) {
                violations.push(format!("{name} -> {restricted}"));
            }
        }
    }
    violations
}

#[test]
fn crates_depend_only_on_the_crates_of_ours_they_may() {
    let violations = internal_violations(&workspace_dependencies());
    assert!(
        violations.is_empty(),
        "forbidden dependencies: {violations:?}"
    );
}

#[test]
fn crates_use_in_their_tests_only_the_crates_of_ours_they_may() {
    let dev = workspace_dependencies_of_kind(Some("dev"));
    let ours: BTreeSet<&str> = dev.keys().map(String::as_str).collect();
    let mut violations = Vec::new();
    for (name, allowed) in ALLOWED_INTERNAL_DEV {
        for dependency in dev.get(*name).into_iter().flatten() {
            if ours.contains(dependency.as_str()) && !allowed.contains(&dependency.as_str()) {
                violations.push(format!("{name} -> {dependency}"));
            }
        }
    }
    assert!(
        violations.is_empty(),
        "forbidden dev-dependencies: {violations:?}"
    );
}

#[test]
fn ui_frameworks_and_tokio_stay_in_their_crates() {
    let violations = restricted_violations(&workspace_dependencies());
    assert!(
        violations.is_empty(),
        "forbidden dependencies: {violations:?}"
    );
}

#[test]
fn the_checks_catch_forbidden_edges() {
    let mut crates = workspace_dependencies();
    crates
        .get_mut("project_model")
        .unwrap()
        .insert("egui".into());
    crates
        .get_mut("editor")
        .unwrap()
        .insert("cam_editor".into());
    crates.get_mut("compiler").unwrap().insert("tokio".into());
    assert_eq!(internal_violations(&crates), ["editor -> cam_editor"]);
    assert_eq!(
        restricted_violations(&crates),
        ["compiler -> tokio", "project_model -> egui"]
    );
}
