//! What the compiler's corpus tests share: where the third-party corpora are and how their
//! files are found.

#![allow(clippy::unwrap_used, dead_code)] // Test helpers may panic; each test uses what it needs.

use std::path::{Path, PathBuf};

/// The shared corpora folder beside the repository; a clear failure when it is missing.
pub fn corpora() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpora");
    assert!(
        dir.is_dir(),
        "{} is missing: the corpora live in the shared folder beside the repository",
        dir.display()
    );
    dir
}

/// Every file below `dir` with `extension` (any case), sorted.
pub fn files(dir: &Path, extension: &str) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut pending = vec![dir.to_owned()];
    while let Some(current) = pending.pop() {
        for entry in std::fs::read_dir(&current).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                pending.push(path);
            } else if path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case(extension))
            {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}
