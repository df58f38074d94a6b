//! The PLCopen XML benchmark of issue 18: exporting the 50,000-line project under 1 s, importing
//! a 10 MB PLCopen file under 1 s and 300 MB.
//!
//! The 50,000 lines are those `compiler/benches/check.rs` checks (the same generator), made a
//! project by `compiler::SourceProject`. The 10 MB file is the export of a larger project of the
//! same generator. Import is reading (`plcopen::read_file`) and converting (`plcopen::import`);
//! its peak memory is the process's peak resident memory (`VmHWM`) after the kernel's peak is
//! reset (`/proc/self/clear_refs`) with only the file's path left in memory, so it counts the
//! import alone.
//!
//! A third figure reads and converts a 5 MB export written on one line (every line end replaced
//! by a space), where a column counted from the start of its line made reading quadratic.
//!
//! `cargo bench -p tests --bench plcopen_report`. Not run in CI: its figures depend on the
//! machine.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

#[path = "../../compiler/benches/generate/mod.rs"]
mod generate;

/// The size the import's file is grown to, in bytes.
const IMPORT_FILE_BYTES: usize = 10 * 1024 * 1024;

/// The size of the file written on one line, in bytes.
const ONE_LINE_FILE_BYTES: usize = 5 * 1024 * 1024;

/// The export of a project of the generator grown until it has at least `size_bytes` bytes,
/// starting from `lines` lines (a guess from an export of known size).
fn export_of_at_least(
    size_bytes: usize,
    mut lines: usize,
    options: plcopen::ExportOptions,
) -> Vec<u8> {
    loop {
        let (source, _) = generate::project_source(lines);
        let project = compiler::SourceProject::new(&source).project;
        let bytes = plcopen::export_with(&project, options).unwrap();
        if bytes.len() >= size_bytes {
            return bytes;
        }
        lines += lines / 10;
    }
}

/// An export written on one line: without Rivet's TOML entries (the objects' and the
/// project's), whose line ends matter, and with every other line end a space.
fn one_line_export(size_bytes: usize, lines: usize) -> Vec<u8> {
    let options = plcopen::ExportOptions {
        object_entries: false,
    };
    let mut text = String::from_utf8(export_of_at_least(size_bytes, lines, options)).unwrap();
    let entry = format!("<data name=\"{}/project\"", plcopen::RIVET_NAMESPACE);
    if let Some(start) = text.find(&entry) {
        let end = start + text[start..].find("</data>").unwrap() + "</data>".len();
        text.replace_range(start..end, "");
    }
    text.replace('\n', " ").into_bytes()
}

fn main() {
    let (source, _) = generate::project_source(50_000);
    let project = compiler::SourceProject::new(&source).project;
    let mut exported = Vec::new();
    let export_time = generate::median(5, || exported = plcopen::export(&project).unwrap());
    println!(
        "export of the 50,000-line project ({} POUs): {:.1} ms median of 5, {:.1} MB of XML",
        project.application.objects().len(),
        export_time.as_secs_f64() * 1000.0,
        exported.len() as f64 / 1e6
    );

    // Grow the generated project until its export reaches the import's size.
    let lines_per_byte = 50_000.0 / exported.len().max(1) as f64;
    let big = export_of_at_least(
        IMPORT_FILE_BYTES,
        (IMPORT_FILE_BYTES as f64 * lines_per_byte) as usize + 1,
        plcopen::ExportOptions::default(),
    );
    let one_line = one_line_export(
        ONE_LINE_FILE_BYTES,
        (ONE_LINE_FILE_BYTES as f64 * lines_per_byte) as usize + 1,
    );
    let dir = tempfile::tempdir().unwrap();
    let one_line_file = dir.path().join("one_line.xml");
    std::fs::write(&one_line_file, &one_line).unwrap();
    let one_line_mb = one_line.len() as f64 / 1e6;
    drop(one_line);
    let one_line_time = generate::median(3, || {
        let document = plcopen::read_file(&one_line_file).unwrap();
        plcopen::import(&document).unwrap();
    });
    println!(
        "import of a {one_line_mb:.1} MB file written on one line: {:.1} ms median of 3",
        one_line_time.as_secs_f64() * 1000.0
    );

    let file = dir.path().join("big.xml");
    std::fs::write(&file, &big).unwrap();
    let size_mb = big.len() as f64 / 1e6;
    drop((big, exported, project, source));

    // Reset the peak so the figure counts the import only (Linux: `5` resets `VmHWM`).
    let reset = std::fs::write("/proc/self/clear_refs", "5").is_ok();
    let mut objects = 0;
    let import_time = generate::median(3, || {
        let document = plcopen::read_file(&file).unwrap();
        let imported = plcopen::import(&document).unwrap();
        objects = imported.project.application.objects().len();
    });
    println!(
        "import of a {size_mb:.1} MB file ({objects} objects): {:.1} ms median of 3, peak memory {}{}",
        import_time.as_secs_f64() * 1000.0,
        generate::peak_memory_mb(),
        if reset {
            ""
        } else {
            " (of the whole run: the kernel did not reset the peak)"
        }
    );
}
