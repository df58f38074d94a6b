//! Whether an online change is possible at all (`docs/protocol.md` §7): what must stay the same
//! between the running image and the new one, and the first difference found when it did not.

use program_image::motion::MotionSection;
use program_image::{ProgramImage, Region, StructKind, TypeDef};

/// Why an online change is impossible, with its number on the wire (`reason` of
/// `ONLINE_CHANGE_CHECK`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChangeRefusal {
    /// No program is loaded: there is nothing to change.
    NoProgram = 1,
    /// The new image is the running one.
    SameImage = 2,
    /// A task was added, removed, renamed, or its timing, trigger or program calls changed.
    Tasks = 3,
    /// The located areas changed size, or the Modbus map changed.
    Areas = 4,
    /// An axis or a cam table was added, removed or changed.
    Motion = 5,
    /// A task is halted or stepping.
    Halted = 6,
}

impl ChangeRefusal {
    /// The reason's number on the wire.
    pub fn number(self) -> u8 {
        self as u8
    }
}

/// The first difference between `old` and `new` that rules an online change out, with its
/// description for people ("task 'Fast': interval changed from 2 ms to 1 ms").
pub(super) fn refusal(old: &ProgramImage, new: &ProgramImage) -> Option<(ChangeRefusal, String)> {
    if old.identity() == new.identity() {
        return Some((
            ChangeRefusal::SameImage,
            "the target already runs this program".to_owned(),
        ));
    }
    if let Some(why) = task_difference(old, new) {
        return Some((ChangeRefusal::Tasks, why));
    }
    if let Some(why) = area_difference(old, new) {
        return Some((ChangeRefusal::Areas, why));
    }
    if !same_motion(old.motion.as_ref(), new.motion.as_ref()) {
        return Some((
            ChangeRefusal::Motion,
            "the axes or cam tables changed: the motion kernel's state belongs to the old ones"
                .to_owned(),
        ));
    }
    None
}

fn task_difference(old: &ProgramImage, new: &ProgramImage) -> Option<String> {
    for task in &old.tasks {
        if !new
            .tasks
            .iter()
            .any(|t| t.name.eq_ignore_ascii_case(&task.name))
        {
            return Some(format!("task '{}' was removed or renamed", task.name));
        }
    }
    for (index, task) in new.tasks.iter().enumerate() {
        let Some(before) = old.tasks.get(index) else {
            return Some(format!("task '{}' was added", task.name));
        };
        if !before.name.eq_ignore_ascii_case(&task.name) {
            return Some(format!(
                "task '{}' is where task '{}' was: the task order changed",
                task.name, before.name
            ));
        }
        let name = &task.name;
        if before.kind != task.kind {
            return Some(format!(
                "task '{name}': kind changed from {:?} to {:?}",
                before.kind, task.kind
            ));
        }
        if before.interval_ns != task.interval_ns {
            return Some(format!(
                "task '{name}': interval changed from {} to {}",
                duration_text(before.interval_ns),
                duration_text(task.interval_ns)
            ));
        }
        let trigger = |image: &ProgramImage, index: Option<u32>| {
            index
                .and_then(|index| image.symbols.get(index as usize))
                .map(|symbol| symbol.path.to_ascii_lowercase())
        };
        if trigger(old, before.trigger) != trigger(new, task.trigger) {
            return Some(format!("task '{name}': its trigger changed"));
        }
        if before.priority != task.priority {
            return Some(format!(
                "task '{name}': priority changed from {} to {}",
                before.priority, task.priority
            ));
        }
        if before.watchdog_ns != task.watchdog_ns
            || before.watchdog_sensitivity != task.watchdog_sensitivity
        {
            return Some(format!("task '{name}': its watchdog changed"));
        }
        let calls = |image: &ProgramImage, task: &program_image::Task| -> Vec<(String, String)> {
            task.programs
                .iter()
                .map(|call| {
                    let pou = image
                        .pous
                        .get(call.pou as usize)
                        .map(|pou| pou.name.to_ascii_lowercase())
                        .unwrap_or_default();
                    (pou, program_instance_path(image, call.instance_offset))
                })
                .collect()
        };
        if calls(old, before) != calls(new, task) {
            return Some(format!("task '{name}': its program calls changed"));
        }
    }
    None
}

/// The path of the program instance at `offset` of the data region, lower case.
fn program_instance_path(image: &ProgramImage, offset: u32) -> String {
    image
        .symbols
        .iter()
        .find(|symbol| {
            symbol.region == Region::Data
                && symbol.offset == offset
                && matches!(
                    image.types.get(symbol.ty as usize),
                    Some(TypeDef::Struct {
                        kind: StructKind::Program,
                        ..
                    })
                )
        })
        .map(|symbol| symbol.path.to_ascii_lowercase())
        .unwrap_or_default()
}

fn area_difference(old: &ProgramImage, new: &ProgramImage) -> Option<String> {
    let (a, b) = (&old.layout, &new.layout);
    for (area, before, after) in [
        ("%I", a.input_size, b.input_size),
        ("%Q", a.output_size, b.output_size),
        ("%M", a.memory_size, b.memory_size),
    ] {
        if before != after {
            return Some(format!(
                "the {area} area changed from {before} to {after} bytes"
            ));
        }
    }
    if old.modbus_map != new.modbus_map {
        return Some("the Modbus map changed: Modbus clients would see another map".to_owned());
    }
    None
}

/// Whether two motion sections describe the same axes and cams, wherever their references
/// live in the data region (moving variables is what an online change does).
fn same_motion(old: Option<&MotionSection>, new: Option<&MotionSection>) -> bool {
    let placeless = |section: Option<&MotionSection>| {
        let mut section = section.cloned().unwrap_or_default();
        section.axes.iter_mut().for_each(|axis| axis.offset = 0);
        section.cams.iter_mut().for_each(|cam| cam.offset = 0);
        section
    };
    placeless(old) == placeless(new)
}

/// A duration for people: whole milliseconds as "2 ms", else microseconds.
fn duration_text(ns: u64) -> String {
    if ns.is_multiple_of(1_000_000) {
        format!("{} ms", ns / 1_000_000)
    } else {
        format!("{} µs", ns / 1000)
    }
}
