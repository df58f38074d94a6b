//! Files shipped with Rivet: fonts, icons, themes and example projects.
//!
//! Fonts are embedded in the binary so the studio renders Chinese text wherever it runs.
//! Example projects stay folders of text files in this crate's source tree; `example_project_dir`
//! finds them.

use std::path::PathBuf;

/// Droid Sans Fallback (Apache-2.0), a TrueType font covering the CJK ideographs.
///
/// The studio registers it as a fallback behind egui's default fonts.
pub const CJK_FONT_TTF: &[u8] = include_bytes!("../fonts/DroidSansFallbackFull.ttf");

/// The folder that holds the example projects.
pub fn examples_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples")
}

/// The folder of the example machine project that the studio opens when started without a
/// project: a conveyor, a counter, a state machine, two tasks, located I/O, a cam table with
/// tappets and two virtual axes.
pub fn example_project_dir() -> PathBuf {
    examples_dir().join("packaging_machine")
}

/// Copies the example project into `target` (created if missing), so it can be changed without
/// touching the shipped copy: used by tests, and by anyone who wants to start from it.
pub fn copy_example_project(target: &std::path::Path) -> std::io::Result<()> {
    copy_dir(&example_project_dir(), target)
}

fn copy_dir(from: &std::path::Path, to: &std::path::Path) -> std::io::Result<()> {
    std::fs::create_dir_all(to)?;
    for entry in std::fs::read_dir(from)? {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&entry.path(), &target)?;
        } else {
            std::fs::copy(entry.path(), target)?;
        }
    }
    Ok(())
}
