//! Which POUs each task may run: the closure of its programs over the image's calls. The
//! debugger uses it to leave a task's cycle in the plain form when no breakpoint it may reach
//! (or that a task interrupting it may reach) can halt it (`docs/debugging.md` §3, "Cost").

use program_image::{Instr, ProgramImage};

/// Per POU, the POUs its code calls: blocks, functions, methods and every method a virtual
/// call may choose.
fn callees(image: &ProgramImage) -> Vec<Vec<usize>> {
    image
        .pous
        .iter()
        .map(|pou| {
            let mut called = Vec::new();
            for instr in &pou.code {
                match instr {
                    Instr::CallBlock { pou, .. } | Instr::CallFunction { pou, .. } => {
                        called.push(*pou as usize);
                    }
                    Instr::CallVirtual { table, .. } => {
                        called.extend(table.iter().map(|&(_, method)| method as usize));
                    }
                    _ => {}
                }
            }
            called.sort_unstable();
            called.dedup();
            called
        })
        .collect()
}

/// Per task, per POU, whether a cycle of the task may run the POU (its programs and every
/// POU they may call, directly or not).
pub(super) fn pous_run_by_tasks(image: &ProgramImage) -> Vec<Vec<bool>> {
    let callees = callees(image);
    image
        .tasks
        .iter()
        .map(|task| {
            let mut runs = vec![false; image.pous.len()];
            let mut to_visit: Vec<usize> = task.programs.iter().map(|p| p.pou as usize).collect();
            while let Some(pou) = to_visit.pop() {
                let Some(seen) = runs.get_mut(pou) else {
                    continue;
                };
                if *seen {
                    continue;
                }
                *seen = true;
                if let Some(called) = callees.get(pou) {
                    to_visit.extend(called.iter().copied());
                }
            }
            runs
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use program_image::Operand;

    use super::*;
    use crate::test_images::{TestTask, image};

    #[test]
    fn a_task_runs_what_its_programs_call_directly_or_not_and_nothing_else() {
        let mut image = image(
            &[
                TestTask::cyclic(1_000_000, 1),
                TestTask::cyclic(1_000_000, 2),
            ],
            &[],
        );
        // Three more POUs: 2 calls 3 through a virtual call; 4 is called by nobody.
        let mut extra = image.pous[0].clone();
        extra.code = vec![Instr::CallVirtual {
            table: vec![(0, 3)],
            interface: Operand::Global(0),
            inputs: Vec::new(),
            outputs: Vec::new(),
        }];
        image.pous.push(extra);
        let mut leaf = image.pous[0].clone();
        leaf.code = Vec::new();
        image.pous.push(leaf.clone());
        image.pous.push(leaf);
        // Task 0's program calls POU 2 as a block; task 1's calls nothing.
        image.pous[0].code.push(Instr::CallBlock {
            pou: 2,
            instance: Operand::Global(0),
            indirect: false,
        });
        let runs = pous_run_by_tasks(&image);
        let run_by = |task: usize| -> Vec<usize> {
            (0..image.pous.len()).filter(|&p| runs[task][p]).collect()
        };
        assert_eq!(run_by(0), vec![0, 2, 3]);
        assert_eq!(run_by(1), vec![1]);
    }
}
