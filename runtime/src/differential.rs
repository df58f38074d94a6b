//! One image run under two engines and compared after every cycle (`docs/native-engine.md`
//! §11.1): the first engine is the interpreter, the reference; the second is the engine under
//! test. After loading and after every cycle, [`run_both`] compares the data, `%I`, `%Q` and
//! `%M` regions and the constant pool byte for byte, the faults (under the exceptions of §6.3)
//! and the motion kernel's axes, and stops at the first [`Difference`], which names the cycle, the place by
//! symbol path and both values.
//!
//! It lives in the runtime rather than in the `tests` crate's library because that library may
//! not depend on `runtime`, and both `tests/tests` and `app/tests` use it.

mod axes;
mod difference;
mod faults;
mod place_name;

use program_image::{ProgramImage, Region};

pub use difference::{AxisQuantity, Difference, Subject};

use crate::engine::{Engine, EngineChoice, LoadError, NativeReport};
use crate::simulation::Simulation;

use faults::FaultVerdict;

/// The regions compared after every cycle, in the order a difference is looked for.
const COMPARED_REGIONS: [Region; 4] = [Region::Data, Region::Input, Region::Output, Region::Memory];

/// Loads `image` in the interpreter and in the native engine, runs both for `cycles` periods
/// of the fastest task and compares them after the load and after every period, as
/// [`run_against`] does with the native engine as the second.
///
/// The native load must translate every POU: a POU that fell back to the interpreter, or an
/// image for which no machine code could be made on a machine that has a native code
/// generator, is a [`Difference`] of cycle 0 with [`Subject::Load`] naming the fallbacks. (A
/// test that expects a fallback calls [`run_against`] and says so.)
pub fn run_both(
    image: ProgramImage,
    cycles: u64,
    writes: impl FnMut(u64, &mut Engine),
) -> Result<Simulation, Difference> {
    let mut report = None;
    let compared = run_against(image, cycles, writes, |image| {
        let (simulation, native) = Simulation::with_choice(image, EngineChoice::Native)?;
        report = Some(native);
        Ok(simulation)
    });
    if let Some(report) = report
        && let Some(fallback) = fallback(&report)
    {
        return Err(Difference {
            cycle: 0,
            subject: Subject::Load,
            first: "runs in the interpreter".to_owned(),
            second: fallback,
        });
    }
    compared
}

/// What of the image does not run natively although it could, as one text; `None` when every
/// POU runs as machine code, or when this machine has no native code generator at all.
fn fallback(report: &NativeReport) -> Option<String> {
    if report.unavailable.is_some() && jit::native_support().is_err() {
        return None;
    }
    if report.runs_natively() && report.fallbacks.is_empty() {
        return None;
    }
    let mut lines = vec![report.summary()];
    lines.extend(report.lines());
    Some(format!("falls back: {}", lines.join("; ")))
}

/// Loads `image` in the interpreter and with `second`, runs both for `cycles` periods of the
/// fastest task (as [`Simulation::run`] counts them), and compares them after the load and
/// after every period. Before period `n` (from 1), `writes(n, engine)` is called on the first
/// engine, then on the second: it writes what the test feeds the program (inputs, commands),
/// and must write the same into both.
///
/// Returns the second engine's simulation when nothing differed, so a test goes on reading the
/// values it read before. A load that fails in either engine is a [`Difference`] of cycle 0
/// with [`Subject::Load`], even when both fail alike, since there is then no simulation to give
/// back.
///
/// A cycle that ends in a watchdog, an abandoned halt or a stack overflow makes the memory and
/// the axes depend on the engine's speed or build (§6.3): from that cycle on only the faults
/// and the cycle counts are compared.
pub fn run_against(
    image: ProgramImage,
    cycles: u64,
    mut writes: impl FnMut(u64, &mut Engine),
    second: impl FnOnce(ProgramImage) -> Result<Simulation, LoadError>,
) -> Result<Simulation, Difference> {
    let first = Simulation::with_choice(image.clone(), EngineChoice::Interpreter)
        .map(|(simulation, _)| simulation);
    let (mut first, mut second) = match (first, second(image)) {
        (Ok(first), Ok(second)) => (first, second),
        (first, second) => {
            return Err(Difference {
                cycle: 0,
                subject: Subject::Load,
                first: load_outcome(&first),
                second: load_outcome(&second),
            });
        }
    };
    compare_state(0, &first, &second)?;
    let mut faults_seen = 0;
    let mut state_compared = true;
    for cycle in 1..=cycles {
        writes(cycle, first.engine_mut());
        writes(cycle, second.engine_mut());
        if state_compared {
            // A test whose writes keep state could write differently into the two engines;
            // that is the test's difference, not the engines'.
            compare_memory(cycle, first.engine(), second.engine()).map_err(|difference| {
                Difference {
                    subject: Subject::Writes {
                        place: Box::new(difference.subject),
                    },
                    ..difference
                }
            })?;
        }
        first.run(1);
        second.run(1);
        let verdict = faults::compare(cycle, faults_seen, first.faults(), second.faults())?;
        faults_seen = first.faults().len();
        if verdict == FaultVerdict::Lenient {
            state_compared = false;
        }
        compare_cycle_counts(cycle, &first, &second)?;
        if state_compared {
            compare_state(cycle, &first, &second)?;
        }
    }
    Ok(second)
}

/// What a load gave, as a [`Difference`] shows it.
fn load_outcome(load: &Result<Simulation, LoadError>) -> String {
    match load {
        Ok(_) => "loads".to_owned(),
        Err(error) => format!("does not load: {error}"),
    }
}

/// Compares the memory, the constant pool, then the axes, of the two simulations after
/// `cycle`.
fn compare_state(cycle: u64, first: &Simulation, second: &Simulation) -> Result<(), Difference> {
    compare_memory(cycle, first.engine(), second.engine())?;
    compare_constants(cycle, first.engine(), second.engine())?;
    axes::compare(
        cycle,
        first.engine().image(),
        &first.engine().axis_snapshots(),
        &second.engine().axis_snapshots(),
    )
}

/// Finds the first byte that differs in [`COMPARED_REGIONS`] and names it.
fn compare_memory(cycle: u64, first: &Engine, second: &Engine) -> Result<(), Difference> {
    for region in COMPARED_REGIONS {
        let (a, b) = (first.region(region), second.region(region));
        let differing = a
            .iter()
            .zip(b)
            .position(|(x, y)| x != y)
            .or_else(|| (a.len() != b.len()).then_some(a.len().min(b.len())));
        if let Some(offset) = differing {
            let named = place_name::name(first.image(), region, offset, a, b);
            return Err(Difference {
                cycle,
                subject: Subject::Memory {
                    region,
                    offset,
                    path: named.path,
                },
                first: named.first,
                second: named.second,
            });
        }
    }
    Ok(())
}

/// Finds the first byte of the constant pool that differs: the pool is read-only for the
/// program's own code, but a store through a pointer reaches it (`docs/native-engine.md` §5.2).
fn compare_constants(cycle: u64, first: &Engine, second: &Engine) -> Result<(), Difference> {
    let (a, b) = (first.constants(), second.constants());
    let differing = a
        .iter()
        .zip(b)
        .position(|(x, y)| x != y)
        .or_else(|| (a.len() != b.len()).then_some(a.len().min(b.len())));
    match differing {
        Some(offset) => {
            let byte = |pool: &[u8]| {
                pool.get(offset).map_or_else(
                    || "no such byte".to_owned(),
                    |byte| format!("16#{byte:02X}"),
                )
            };
            Err(Difference {
                cycle,
                subject: Subject::Constants { offset },
                first: byte(a),
                second: byte(b),
            })
        }
        None => Ok(()),
    }
}

/// The cycles each task has run: a task that stopped in one engine only shows here too.
fn compare_cycle_counts(
    cycle: u64,
    first: &Simulation,
    second: &Simulation,
) -> Result<(), Difference> {
    let tasks = &first.engine().image().tasks;
    if first.cycles().len() != second.cycles().len() {
        return Err(Difference {
            cycle,
            subject: Subject::TaskCount,
            first: first.cycles().len().to_string(),
            second: second.cycles().len().to_string(),
        });
    }
    for (index, (a, b)) in first.cycles().iter().zip(second.cycles()).enumerate() {
        if a != b {
            let task = tasks
                .get(index)
                .map_or_else(|| format!("#{index}"), |task| task.name.clone());
            return Err(Difference {
                cycle,
                subject: Subject::CycleCount { task },
                first: a.to_string(),
                second: b.to_string(),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
