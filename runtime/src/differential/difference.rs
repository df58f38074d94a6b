//! What [`super::run_both`] reports when the two engines disagree.

use std::fmt;

use program_image::Region;

/// The first disagreement of two engines on one image: when, where, and what each had there.
/// Tests panic with it; its text is meant to be read without the test at hand.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "after cycle {cycle}, {subject} differs: the first engine has {first}, the second {second}"
)]
pub struct Difference {
    /// The period of the fastest task (from 1) after which it was found; 0 for the load and
    /// the memory right after it.
    pub cycle: u64,
    /// What differs.
    pub subject: Subject,
    /// The first engine's (the interpreter's) value, as text: for memory the value as an IEC
    /// literal with its bytes, for a fault the fault as it is reported.
    pub first: String,
    /// The second engine's value, in the same form.
    pub second: String,
}

/// The thing two engines disagree on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Subject {
    /// Loading the image: one engine loaded it and the other did not, or neither did.
    Load,
    /// A byte of a compared region.
    Memory {
        /// The region.
        region: Region,
        /// The first differing byte's offset in the region.
        offset: usize,
        /// The variable holding that byte, by symbol path down to the member or element
        /// (`Main.s[2].b`); `None` where no symbol covers the byte.
        path: Option<String>,
    },
    /// A byte of the constant pool as the engine holds it (a store through a pointer can
    /// reach it).
    Constants {
        /// The first differing byte's offset in the pool.
        offset: usize,
    },
    /// What the test's `writes` left in memory differs before the engines ran the cycle: the
    /// test wrote differently into the two, which is no difference of the engines.
    Writes {
        /// The place that differs, as [`Subject::Memory`] names it.
        place: Box<Subject>,
    },
    /// The number of tasks the two engines count cycles for.
    TaskCount,
    /// The `index`-th fault of the run (from 0): present in one engine only, or different.
    Fault {
        /// Its position among the run's faults.
        index: usize,
    },
    /// How many cycles a task has run.
    CycleCount {
        /// The task's name.
        task: String,
    },
    /// One quantity of a motion axis.
    Axis {
        /// The axis's index in the image's motion section.
        index: usize,
        /// The axis's name.
        name: String,
        /// The quantity that differs.
        quantity: AxisQuantity,
    },
}

/// The quantities of an axis that are compared (`motion::kernel::AxisSnapshot`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AxisQuantity {
    /// The PLCopen state.
    State,
    /// Whether the power stage is on.
    Powered,
    /// The set position.
    SetPosition,
    /// The actual position.
    ActualPosition,
    /// The set velocity.
    SetVelocity,
    /// The actual velocity.
    ActualVelocity,
    /// The set acceleration.
    SetAcceleration,
    /// The pending axis error id.
    ErrorId,
    /// Whether the axis has a reference.
    Homed,
    /// The last commanded target position, which MC_MoveAdditive adds to.
    CommandedPosition,
    /// The modulo period.
    ModuloPeriod,
    /// The velocity override factor.
    VelocityOverride,
    /// The acceleration override factor.
    AccelerationOverride,
    /// The jerk override factor.
    JerkOverride,
    /// Whether an axis error is pending.
    Error,
    /// The function block whose command controls the axis, and the command's id.
    ActiveCommand,
}

impl fmt::Display for Subject {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Load => write!(f, "loading the image"),
            Self::Memory {
                region,
                offset,
                path: Some(path),
            } => write!(f, "{path} ({} byte {offset})", region_name(*region)),
            Self::Memory {
                region,
                offset,
                path: None,
            } => write!(f, "{} byte {offset} (no variable)", region_name(*region)),
            Self::Constants { offset } => write!(f, "constant pool byte {offset}"),
            Self::Writes { place } => write!(
                f,
                "{place}, as the test's writes left it before the cycle (the test wrote differently into the two engines)"
            ),
            Self::TaskCount => write!(f, "the number of tasks"),
            Self::Fault { index } => write!(f, "fault {}", index + 1),
            Self::CycleCount { task } => write!(f, "the cycle count of task '{task}'"),
            Self::Axis {
                index,
                name,
                quantity,
            } => write!(f, "the {quantity} of axis {index} '{name}'"),
        }
    }
}

impl fmt::Display for AxisQuantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            Self::State => "state",
            Self::Powered => "power",
            Self::SetPosition => "set position",
            Self::ActualPosition => "actual position",
            Self::SetVelocity => "set velocity",
            Self::ActualVelocity => "actual velocity",
            Self::SetAcceleration => "set acceleration",
            Self::ErrorId => "error id",
            Self::Homed => "homed flag",
            Self::CommandedPosition => "commanded position",
            Self::ModuloPeriod => "modulo period",
            Self::VelocityOverride => "velocity override",
            Self::AccelerationOverride => "acceleration override",
            Self::JerkOverride => "jerk override",
            Self::Error => "error flag",
            Self::ActiveCommand => "command in control",
        };
        f.write_str(text)
    }
}

/// A region as the documents name it.
fn region_name(region: Region) -> &'static str {
    match region {
        Region::Data => "data",
        Region::Input => "%I",
        Region::Output => "%Q",
        Region::Memory => "%M",
    }
}
