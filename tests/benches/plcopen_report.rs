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
//! `cargo bench -p tests --bench plcopen_report`. Not run in CI: its figures depend on the
//! machine.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

#[path = "../../compiler/benches/generate/mod.rs"]
mod generate;

/// The size the import's file is grown to, in bytes.
const IMPORT_FILE_BYTES: usize = 10 * 1024 * 1024;

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
    let mut lines = 50_000 * IMPORT_FILE_BYTES / exported.len().max(1) + 1;
    let big = loop {
        let (source, _) = generate::project_source(lines);
        let bytes = plcopen::export(&compiler::SourceProject::new(&source).project).unwrap();
        if bytes.len() >= IMPORT_FILE_BYTES {
            break bytes;
        }
        lines += lines / 10;
    };
    let dir = tempfile::tempdir().unwrap();
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
