//! What flow control asks the target to record (`docs/debugging.md` §5): each open body's POU
//! in every task that runs it, through the image the studio logged in with.

use online::FlowEntry;
use program_image::ProgramImage;

/// The flow entries of every task of `program`, in task order (empty for a task that runs
/// none of `bodies`), each list at most [`online::MAX_FLOW_ENTRIES`] long.
///
/// `bodies` are POU names with the instance path their editor shows. An instance path starts
/// with the program it lives in, so it is recorded in the tasks that call that program; a
/// function's body, or a function block's shown for every instance, is recorded in every
/// task, since the image has no call graph to say which tasks reach it (a task that never runs
/// it records nothing). A body the image does not know is left out.
pub fn flow_entries(
    program: &ProgramImage,
    bodies: &[(String, Option<String>)],
) -> Vec<(u8, Vec<FlowEntry>)> {
    let mut tasks: Vec<(u8, Vec<FlowEntry>)> = (0..program.tasks.len())
        .filter_map(|task| Some((u8::try_from(task).ok()?, Vec::new())))
        .collect();
    for (pou_name, instance) in bodies {
        let Some(pou) = program
            .pous
            .iter()
            .position(|pou| pou.name.eq_ignore_ascii_case(pou_name))
            .and_then(|pou| u32::try_from(pou).ok())
        else {
            continue;
        };
        let root = instance
            .as_deref()
            .unwrap_or(pou_name)
            .split('.')
            .next()
            .unwrap_or_default();
        let calls_root = |task: &program_image::Task| {
            task.programs.iter().any(|call| {
                program
                    .pous
                    .get(call.pou as usize)
                    .is_some_and(|called| called.name.eq_ignore_ascii_case(root))
            })
        };
        let any_calls_root = program.tasks.iter().any(calls_root);
        let pointer = instance
            .as_deref()
            .and_then(|path| runtime::value::resolve(program, path).ok())
            .filter(|place| place.region == program_image::Region::Data)
            .map_or(0, |place| (1 << 56) | place.offset);
        for ((_, entries), task) in tasks.iter_mut().zip(&program.tasks) {
            if (!any_calls_root || calls_root(task)) && entries.len() < online::MAX_FLOW_ENTRIES {
                entries.push(FlowEntry {
                    pou,
                    instance: pointer,
                });
            }
        }
    }
    tasks
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // A panic is a failed test.

    use super::*;

    fn image() -> ProgramImage {
        let project = project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        compiler::compile_project(&project).unwrap()
    }

    fn pou(image: &ProgramImage, name: &str) -> u32 {
        image.pous.iter().position(|p| p.name == name).unwrap() as u32
    }

    #[test]
    fn each_body_is_recorded_in_the_tasks_that_run_it() {
        let image = image();
        let task = |name: &str| image.tasks.iter().position(|t| t.name == name).unwrap() as u8;
        let (main_task, motion_task) = (task("MainTask"), task("MotionTask"));
        let bodies = vec![
            ("Main".to_owned(), Some("Main".to_owned())),
            ("MotionControl".to_owned(), Some("MotionControl".to_owned())),
            ("FB_Conveyor".to_owned(), Some("Main.fbConveyor".to_owned())),
            // Every instance, which any task may run.
            ("FB_Conveyor".to_owned(), None),
            ("NoSuchPou".to_owned(), None),
        ];
        let entries = flow_entries(&image, &bodies);
        let pous = |task: u8| -> Vec<u32> {
            let (_, entries) = entries.iter().find(|(t, _)| *t == task).unwrap();
            entries.iter().map(|entry| entry.pou).collect()
        };
        let conveyor = pou(&image, "FB_Conveyor");
        assert_eq!(
            pous(main_task),
            vec![pou(&image, "Main"), conveyor, conveyor]
        );
        assert_eq!(
            pous(motion_task),
            vec![pou(&image, "MotionControl"), conveyor]
        );
        // The instance shown is recorded by its pointer, every instance by 0.
        let (_, main_entries) = &entries[usize::from(main_task)];
        assert_ne!(main_entries[1].instance, 0);
        assert_eq!(main_entries[2].instance, 0);
    }

    #[test]
    fn a_task_records_at_most_as_many_bodies_as_the_target_takes() {
        let image = image();
        let bodies = vec![("FB_Conveyor".to_owned(), None); online::MAX_FLOW_ENTRIES + 3];
        for (_, entries) in flow_entries(&image, &bodies) {
            assert_eq!(entries.len(), online::MAX_FLOW_ENTRIES);
        }
    }
}
