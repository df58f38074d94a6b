//! `rivet cam`: the project's cam tables from the command line: list them, evaluate one at
//! master positions, and export the point table a controller of another family loads
//! (`docs/cam-formats.md`).

#![allow(clippy::print_stdout)] // Printing is what a CLI is for.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context as _, anyhow, bail};
use clap::{Subcommand, ValueEnum};
use motion::curve::CamCurve;
use motion::table::{
    CodesysTable1d, CodesysTable2d, CodesysXyva, CsvColumns, DELTA_MAX_KEY_POINTS, DeltaKeyPoints,
    OmronCamData, sample_equidistant, write_points_csv,
};
use project_model::{CamCompileFormat, CamProfile, CamTable, Object, load_project};

/// What `rivet cam` does.
#[derive(Debug, Subcommand)]
pub enum CamCommand {
    /// Name every cam table of a project with its ranges, size, tappets and continuity.
    List {
        /// The project folder.
        project: PathBuf,
    },
    /// Print the slave position, velocity and acceleration (with respect to the master) of a
    /// cam at each master position.
    Eval {
        /// The project folder.
        project: PathBuf,
        /// The cam table's name.
        cam: String,
        /// Master positions, comma-separated or repeated.
        #[arg(long, value_delimiter = ',', num_args = 1.., required = true, allow_negative_numbers = true)]
        master: Vec<f64>,
    },
    /// Write the point table of a cam for a controller family.
    Export {
        /// The project folder.
        project: PathBuf,
        /// The cam table's name.
        cam: String,
        /// The target: CODESYS (GVL text of an SMC_CAMTable or of XYVA points), Omron
        /// (Phase,Distance CSV), Delta (key points CSV) or Rivet CSV.
        #[arg(long, value_enum)]
        format: ExportFormat,
        /// How many equidistant points to write (default: the cam's compile format, else 256;
        /// at most 2048 for Delta).
        #[arg(long)]
        elements: Option<usize>,
        /// Where to write it (default: standard output).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
}

/// The families `rivet cam export` writes for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ExportFormat {
    /// CODESYS SoftMotion.
    Codesys,
    /// Omron Sysmac (NJ/NX).
    Omron,
    /// Delta DVP-15MC.
    Delta,
    /// Rivet's CSV of points with velocity and acceleration.
    Csv,
}

/// The number of points a table gets when neither the cam nor the command says.
const DEFAULT_ELEMENTS: usize = 256;

/// Runs a `rivet cam` command.
pub fn run(command: CamCommand) -> anyhow::Result<()> {
    match command {
        CamCommand::List { project } => list(&project),
        CamCommand::Eval {
            project,
            cam,
            master,
        } => eval(&project, &cam, &master),
        CamCommand::Export {
            project,
            cam,
            format,
            elements,
            output,
        } => {
            let text = export(&project, &cam, format, elements)?;
            match output {
                Some(path) => std::fs::write(&path, text)
                    .with_context(|| format!("cannot write {}", path.display())),
                None => {
                    print!("{text}");
                    Ok(())
                }
            }
        }
    }
}

/// Every cam table of the project at `dir`.
fn cams(dir: &Path) -> anyhow::Result<Vec<CamTable>> {
    let loaded = load_project(dir).map_err(|error| anyhow!("{error}"))?;
    Ok(loaded
        .project
        .application
        .objects()
        .into_iter()
        .filter_map(|object| match object {
            Object::CamTable(cam) => Some(cam.clone()),
            _ => None,
        })
        .collect())
}

/// The cam table `name` of the project at `dir`.
fn cam_named(dir: &Path, name: &str) -> anyhow::Result<CamTable> {
    let cams = cams(dir)?;
    let names: Vec<&str> = cams.iter().map(|cam| cam.name.as_str()).collect();
    let wanted = cams
        .iter()
        .find(|cam| cam.name.eq_ignore_ascii_case(name))
        .cloned();
    wanted.ok_or_else(|| {
        anyhow!(
            "the project has no cam table '{name}'; its cam tables: {}",
            if names.is_empty() {
                "none".to_owned()
            } else {
                names.join(", ")
            }
        )
    })
}

fn list(dir: &Path) -> anyhow::Result<()> {
    let cams = cams(dir)?;
    if cams.is_empty() {
        println!("the project has no cam tables");
    }
    for cam in &cams {
        let shape = match &cam.profile {
            CamProfile::Segments { segments, .. } => format!("{} segments", segments.len()),
            CamProfile::Points { points, .. } => format!("{} points", points.len()),
        };
        let tappets: usize = cam.tracks.iter().map(|track| track.tappets.len()).sum();
        let continuity = match cam_editor::continuity_warnings(cam) {
            Ok(warnings) if warnings.is_empty() => "continuous".to_owned(),
            Ok(warnings) => format!("{} continuity warning(s)", warnings.len()),
            Err(error) => format!("invalid: {error}"),
        };
        println!(
            "{}: master {}..{} {}, slave {}..{} {}, {shape}, {} track(s) with {tappets} tappet(s), {continuity}",
            cam.name,
            cam.master.start,
            cam.master.end,
            cam.master.unit,
            cam.slave.start,
            cam.slave.end,
            cam.slave.unit,
            cam.tracks.len(),
        );
    }
    Ok(())
}

fn eval(dir: &Path, name: &str, masters: &[f64]) -> anyhow::Result<()> {
    let cam = cam_named(dir, name)?;
    let curve = cam_editor::curve_of(&cam)?;
    let (start, end) = curve.master_range();
    let mut text = String::from("master\tslave\tvelocity\tacceleration\n");
    for &master in masters {
        if !(start..=end).contains(&master) {
            bail!(
                "master {master} is outside the cam's master range {start}..{end} ({})",
                cam.master.unit
            );
        }
        let sample = curve.sample(master);
        let _ = writeln!(
            text,
            "{master}\t{}\t{}\t{}",
            decimal(sample.position),
            decimal(sample.velocity),
            decimal(sample.acceleration)
        );
    }
    print!("{text}");
    Ok(())
}

/// `value` rounded to nine decimals, so the last bits of floating-point arithmetic do not show
/// (288.75, not 288.74999999999994).
fn decimal(value: f64) -> String {
    let rounded = (value * 1e9).round() / 1e9;
    // Negative zero prints as "-0".
    let rounded = if rounded == 0.0 { 0.0 } else { rounded };
    format!("{rounded}")
}

fn export(
    dir: &Path,
    name: &str,
    format: ExportFormat,
    elements: Option<usize>,
) -> anyhow::Result<String> {
    let cam = cam_named(dir, name)?;
    let curve = cam_editor::curve_of(&cam)?;
    let from_format = match cam.compile_format {
        CamCompileFormat::Table1d { elements } | CamCompileFormat::Table2d { elements } => {
            Some(elements as usize)
        }
        CamCompileFormat::Segments | CamCompileFormat::Xyva => None,
    };
    let count = elements.or(from_format).unwrap_or(DEFAULT_ELEMENTS);
    let variable = cam.name.as_str();
    Ok(match format {
        ExportFormat::Codesys => match (&curve, cam.compile_format) {
            (cam_editor::Curve::Segmented(segmented), CamCompileFormat::Xyva)
                if elements.is_none() =>
            {
                CodesysXyva::from_points(&segmented.xyva_points()?)?.gvl(variable)?
            }
            (_, CamCompileFormat::Table1d { .. }) => {
                CodesysTable1d::from_curve(&curve, count)?.gvl(variable)?
            }
            _ => CodesysTable2d::from_curve(&curve, count)?.gvl(variable)?,
        },
        ExportFormat::Omron => OmronCamData::from_curve(&curve, count)?.csv(),
        ExportFormat::Delta => {
            let count = elements.unwrap_or(count.min(DELTA_MAX_KEY_POINTS));
            DeltaKeyPoints::from_curve(&curve, count)?.csv()
        }
        ExportFormat::Csv => {
            let points = sample_equidistant(&curve, count)?;
            write_points_csv(&points, CsvColumns::PositionsAndDerivatives)
        }
    })
}
