//! What the online session reports while debugging, in the studio's terms: halted tasks with
//! frames named by POU, instance path, file and line, and the lines flow control saw run,
//! through the image the studio logged in with.

use online::session::HaltedTask as ReportedTask;
use online::{FlowBitmap, FlowEntry, TaskDebugState};
use program_image::ProgramImage;

use super::halt::{Beneath, HaltedTask, StackFrame};
use crate::debug_places::{instance_owner, statement_of};

/// The halted and waiting tasks as the studio shows them. A waiting task is shown beneath
/// the halted task by name only when one task is halted: the target does not say in which
/// order several halted cycles nest, so beneath one of several no name is given.
pub fn halted_tasks(image: &ProgramImage, reported: &[ReportedTask]) -> Vec<HaltedTask> {
    let name = |task: u8| {
        image
            .tasks
            .get(usize::from(task))
            .map_or_else(|| format!("#{task}"), |task| task.name.clone())
    };
    let mut halted = reported
        .iter()
        .filter(|task| task.halt.state == TaskDebugState::Halted);
    let beneath = match (halted.next(), halted.next()) {
        (Some(only), None) => Beneath::Task(name(only.halt.task)),
        _ => Beneath::AHaltedTask,
    };
    reported
        .iter()
        .map(|task| HaltedTask {
            task: name(task.halt.task),
            beneath: (task.halt.state != TaskDebugState::Halted).then(|| beneath.clone()),
            frames: task
                .frames
                .iter()
                .map(|frame| stack_frame(image, frame))
                .collect(),
        })
        .collect()
}

/// One frame: the POU, the instance by path (none for a function) and the statement's line.
fn stack_frame(image: &ProgramImage, frame: &online::StackFrame) -> StackFrame {
    let pou = image
        .pous
        .get(frame.pou as usize)
        .map_or_else(|| format!("#{}", frame.pou), |pou| pou.name.clone());
    let instance = instance_owner(image, frame.pou)
        .and_then(|owner| image.instance_path(frame.instance, Some(owner)));
    let (file, line) = statement_of(image, frame.pou, frame.instruction)
        .map_or((String::new(), 0), |statement| {
            (statement.file, statement.line)
        });
    StackFrame {
        pou,
        instance,
        file,
        line,
    }
}

/// The lines whose statements ran, per body file, from the flow bitmaps of the configured
/// POUs (bit `i` of a POU's bitmap is its line-table entry `i`); a POU recorded in several
/// tasks has a line that ran in any of them.
pub fn flow_lines<'a>(
    image: &ProgramImage,
    bitmaps: impl IntoIterator<Item = (&'a FlowEntry, &'a FlowBitmap)>,
) -> Vec<(String, Vec<u32>)> {
    let mut files: Vec<(String, Vec<u32>)> = Vec::new();
    for (entry, bitmap) in bitmaps {
        let Some(pou) = image.pous.get(entry.pou as usize) else {
            continue;
        };
        for (index, line) in pou.lines.iter().enumerate() {
            if !bitmap.ran(index) {
                continue;
            }
            let Some(file) = image.sources.get(line.file as usize) else {
                continue;
            };
            match files.iter_mut().find(|(known, _)| known == file) {
                Some((_, lines)) => lines.push(line.line),
                None => files.push((file.clone(), vec![line.line])),
            }
        }
    }
    for (_, lines) in &mut files {
        lines.sort_unstable();
        lines.dedup();
    }
    files
}

#[cfg(test)]
#[path = "reported_tests.rs"]
mod tests;
