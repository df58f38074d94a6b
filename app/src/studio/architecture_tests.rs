//! Checks of the studio's architecture that the compiler does not make: no two modules of
//! `app::studio` import each other in a circle, so each can be understood (and changed) without
//! the ones that use it.
//!
//! A module is a file, or a folder's `mod.rs`. An edge is a `use` of `super::…`, `self::…`,
//! `crate::studio::…` or a child module, resolved to the deepest module it names; `use` lines
//! after `#[cfg(test)]` and files named `tests.rs` are test code and left out, since a test
//! module naturally uses the module it tests.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module of `app::studio` by its path below it (`[]` is `app::studio` itself).
type Module = Vec<String>;

/// Every `.rs` file below `dir`, sorted (the literal test reads the same files).
pub(super) fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut folders = vec![dir.to_owned()];
    while let Some(folder) = folders.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|ext| ext == "rs") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// The module a file of `root` holds.
fn module_of(root: &Path, file: &Path) -> Module {
    let relative = file.strip_prefix(root).unwrap_or(file);
    let mut parts: Vec<String> = relative
        .iter()
        .map(|part| part.to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().unwrap_or_default();
    if last != "mod.rs" {
        parts.push(last.trim_end_matches(".rs").to_owned());
    }
    parts
}

/// The `use` declarations of a source text outside its tests, each as one string without
/// `use` and `;`.
fn use_declarations(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut current: Option<String> = None;
    let lines: Vec<&str> = text
        .lines()
        .map(|line| line.split("//").next().unwrap_or_default().trim())
        .collect();
    for (index, line) in lines.iter().enumerate() {
        // An inline test module ends what counts; `mod tests;` only declares one.
        let next = lines.get(index + 1).copied().unwrap_or_default();
        if line.starts_with("#[cfg(test)]") && next.starts_with("mod ") && next.ends_with('{') {
            break;
        }
        if current.is_none() {
            let rest = ["use ", "pub use ", "pub(crate) use ", "pub(super) use "]
                .iter()
                .find_map(|prefix| line.strip_prefix(prefix));
            match rest {
                Some(rest) => current = Some(rest.to_owned()),
                None => continue,
            }
        } else if let Some(statement) = &mut current {
            statement.push_str(line);
        }
        if let Some(statement) = current.take_if(|statement| statement.ends_with(';')) {
            found.push(statement.trim_end_matches(';').to_owned());
        }
    }
    found
}

/// The paths a use tree names: `a::{b, c::{d, e as f}}` gives `a::b`, `a::c::d`, `a::c::e`.
fn expand(tree: &str) -> Vec<Vec<String>> {
    // A renaming is marked before the spaces go, so names that hold "as" stay whole.
    let tree = tree.replace(" as ", "@");
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let mut paths = Vec::new();
    expand_into(&tree, &mut Vec::new(), &mut paths);
    paths
}

fn expand_into(tree: &str, prefix: &mut Vec<String>, paths: &mut Vec<Vec<String>>) {
    match tree.find('{') {
        Some(open) => {
            let head = &tree[..open];
            let inner = &tree[open + 1..tree.len() - 1];
            let added: Vec<String> = head
                .split("::")
                .filter(|part| !part.is_empty())
                .map(str::to_owned)
                .collect();
            let kept = prefix.len();
            prefix.extend(added);
            for item in split_top_level(inner) {
                expand_into(item, prefix, paths);
            }
            prefix.truncate(kept);
        }
        None => {
            let mut path = prefix.clone();
            let tree = tree.split('@').next().unwrap_or(tree);
            path.extend(
                tree.split("::")
                    .filter(|part| !part.is_empty())
                    .map(str::to_owned),
            );
            paths.push(path);
        }
    }
}

/// The items of a brace group, split at the commas outside nested braces.
fn split_top_level(inner: &str) -> Vec<&str> {
    let mut items = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (at, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                items.push(&inner[start..at]);
                start = at + 1;
            }
            _ => {}
        }
    }
    items.push(&inner[start..]);
    items.into_iter().filter(|item| !item.is_empty()).collect()
}

/// The module of `app::studio` a path used in `from` names, if it names one.
fn resolve(from: &Module, path: &[String], modules: &BTreeSet<Module>) -> Option<Module> {
    let mut segments = path.iter().peekable();
    let mut base: Module = match segments.peek().map(|s| s.as_str()) {
        Some("crate") => {
            segments.next();
            if segments.next().map(String::as_str) != Some("studio") {
                return None;
            }
            Vec::new()
        }
        Some("super") | Some("self") => {
            // `self` is the module itself (a file's, or a folder's for its `mod.rs`); `super` is
            // the one that declares it.
            let mut base = from.clone();
            while let Some(segment) = segments.peek() {
                match segment.as_str() {
                    "super" => {
                        base.pop();
                    }
                    "self" => {}
                    _ => break,
                }
                segments.next();
            }
            base
        }
        Some(first) => {
            // A bare path names a child module of this one (declared in a `mod.rs` or in a
            // file with a folder of its own), or another crate.
            let mut child = from.clone();
            child.push(first.to_owned());
            if !modules.contains(&child) {
                return None;
            }
            from.clone()
        }
        None => return None,
    };
    for segment in segments {
        base.push(segment.clone());
        if !modules.contains(&base) {
            base.pop();
            break;
        }
    }
    (base != *from).then_some(base)
}

/// The modules each module of the studio imports.
fn module_edges(root: &Path) -> BTreeMap<Module, BTreeSet<Module>> {
    let files: Vec<PathBuf> = rust_files(root)
        .into_iter()
        .filter(|file| file.file_name().is_some_and(|name| name != "tests.rs"))
        .collect();
    let modules: BTreeSet<Module> = files.iter().map(|file| module_of(root, file)).collect();
    let mut edges: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    for file in &files {
        let from = module_of(root, file);
        let text = std::fs::read_to_string(file).unwrap_or_default();
        let targets = edges.entry(from.clone()).or_default();
        for declaration in use_declarations(&text) {
            for path in expand(&declaration) {
                if let Some(to) = resolve(&from, &path, &modules) {
                    targets.insert(to);
                }
            }
        }
    }
    edges
}

/// A circle of imports, if there is one, as its modules from the first back to it.
fn find_cycle(edges: &BTreeMap<Module, BTreeSet<Module>>) -> Option<Vec<Module>> {
    #[derive(Clone, Copy, PartialEq)]
    enum Mark {
        Open,
        Done,
    }
    fn visit(
        module: &Module,
        edges: &BTreeMap<Module, BTreeSet<Module>>,
        marks: &mut BTreeMap<Module, Mark>,
        stack: &mut Vec<Module>,
    ) -> Option<Vec<Module>> {
        marks.insert(module.clone(), Mark::Open);
        stack.push(module.clone());
        for next in edges.get(module).into_iter().flatten() {
            match marks.get(next) {
                Some(Mark::Open) => {
                    let start = stack.iter().position(|m| m == next).unwrap_or(0);
                    let mut cycle = stack[start..].to_vec();
                    cycle.push(next.clone());
                    return Some(cycle);
                }
                Some(Mark::Done) => {}
                None => {
                    if let Some(cycle) = visit(next, edges, marks, stack) {
                        return Some(cycle);
                    }
                }
            }
        }
        stack.pop();
        marks.insert(module.clone(), Mark::Done);
        None
    }
    let mut marks = BTreeMap::new();
    for module in edges.keys() {
        if marks.contains_key(module) {
            continue;
        }
        if let Some(cycle) = visit(module, edges, &mut marks, &mut Vec::new()) {
            return Some(cycle);
        }
    }
    None
}

fn name(module: &Module) -> String {
    if module.is_empty() {
        "studio".to_owned()
    } else {
        format!("studio::{}", module.join("::"))
    }
}

fn studio_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src/studio")
}

#[test]
fn no_two_modules_of_the_studio_import_each_other_in_a_circle() {
    let edges = module_edges(&studio_dir());
    assert!(edges.len() > 20, "the studio's modules were not found");
    if let Some(cycle) = find_cycle(&edges) {
        let names: Vec<String> = cycle.iter().map(name).collect();
        panic!(
            "these modules import each other in a circle: {}",
            names.join(" -> ")
        );
    }
}

#[test]
fn a_circle_of_imports_is_found_and_named() {
    let module = |name: &str| vec![name.to_owned()];
    let mut edges = BTreeMap::new();
    edges.insert(module("a"), BTreeSet::from([module("b")]));
    edges.insert(module("b"), BTreeSet::from([module("c")]));
    edges.insert(module("c"), BTreeSet::from([module("a")]));
    let cycle = find_cycle(&edges).map(|cycle| cycle.iter().map(name).collect::<Vec<_>>());
    assert_eq!(
        cycle,
        Some(vec![
            "studio::a".to_owned(),
            "studio::b".to_owned(),
            "studio::c".to_owned(),
            "studio::a".to_owned()
        ])
    );
    edges.insert(module("c"), BTreeSet::new());
    assert_eq!(find_cycle(&edges), None);
}

#[test]
fn use_paths_resolve_to_the_deepest_module_they_name() {
    let modules: BTreeSet<Module> = [
        vec![],
        vec!["panes".to_owned()],
        vec!["panes".to_owned(), "watch".to_owned()],
        vec!["view".to_owned()],
    ]
    .into_iter()
    .collect();
    let watch = vec!["panes".to_owned(), "watch".to_owned()];
    let paths: Vec<Option<Module>> = expand("crate::studio::{view::StudioView, Language}")
        .into_iter()
        .chain(expand("super::super::view::{self, StudioView}"))
        .map(|path| resolve(&watch, &path, &modules))
        .collect();
    assert_eq!(
        paths,
        vec![
            Some(vec!["view".to_owned()]),
            Some(vec![]),
            Some(vec!["view".to_owned()]),
            Some(vec!["view".to_owned()]),
        ]
    );
    // A bare path from a `mod.rs` names its child; another crate's path names nothing.
    let panes = vec!["panes".to_owned()];
    assert_eq!(
        resolve(&panes, &expand("watch::WatchPaneState")[0], &modules),
        Some(watch.clone())
    );
    assert_eq!(resolve(&panes, &expand("egui::Ui")[0], &modules), None);
}
