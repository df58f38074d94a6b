//! Resources' tasks and program instances → Rivet's task configuration.

use std::collections::HashMap;

use project_model::{Object, PouKind, Task, TaskKind};

use super::converter::{Converter, Place};
use super::duration::parse_interval_us;
use super::error::{ImportError, ImportErrorKind};
use super::report::Outcome;
use crate::instances::PouInstance;

/// The lowest priority Rivet has (0 is the highest, as in PLCopen and CODESYS).
const LOWEST_PRIORITY: u8 = 31;

impl Converter<'_> {
    /// Converts the tasks of every resource in document order, with their program instances.
    pub fn tasks(&mut self) -> Result<(), ImportError> {
        let document = self.document;
        let mut task_names: HashMap<String, (String, u32)> = HashMap::new();
        // The programs some task calls already, lower-case: Rivet runs one instance of each.
        let mut called: HashMap<String, String> = HashMap::new();
        // Rivet's project is one controller running one application: the first resource with
        // tasks gives the task configuration, as `configuration/resource`.
        let mut chosen: Option<String> = None;
        for configuration in &document.configurations {
            let configuration_path = format!(
                "project/instances/configurations/configuration[@name='{}']",
                configuration.name
            );
            for resource in &configuration.resources {
                let resource_path =
                    format!("{configuration_path}/resource[@name='{}']", resource.name);
                for instance in &resource.pou_instances {
                    self.report.push(
                        Outcome::NotConverted,
                        format!("program instance '{}'", instance.name),
                        &format!("{resource_path}/pouInstance[@name='{}']", instance.name),
                        resource.line,
                        "it runs in no task; Rivet's programs run only when a task calls them",
                    );
                }
                let owner = format!("{}/{}", configuration.name, resource.name);
                if let Some(first) = &chosen
                    && !resource.tasks.is_empty()
                {
                    for task in &resource.tasks {
                        self.report.push(
                            Outcome::NotConverted,
                            format!("task '{}' of {owner}", task.name),
                            &format!("{resource_path}/task[@name='{}']", task.name),
                            task.line,
                            format!(
                                "a Rivet project runs one controller; its tasks are those of {first}"
                            ),
                        );
                    }
                    continue;
                }
                if !resource.tasks.is_empty() {
                    chosen = Some(owner);
                }
                for task in &resource.tasks {
                    let place = Place {
                        path: format!("{resource_path}/task[@name='{}']", task.name),
                        line: task.line,
                        column: task.column,
                    };
                    if !project_model::is_valid_identifier(&task.name) {
                        return Err(self.error(&place, ImportErrorKind::BadName(task.name.clone())));
                    }
                    let key = task.name.to_lowercase();
                    if let Some((first, first_line)) = task_names.get(&key) {
                        return Err(self.error(
                            &place,
                            ImportErrorKind::DuplicateName {
                                what: "task",
                                name: task.name.clone(),
                                first: first.clone(),
                                first_line: *first_line,
                            },
                        ));
                    }
                    task_names.insert(key, (task.name.clone(), task.line));
                    let mut notes = Vec::new();
                    let kind = match (&task.single, &task.interval) {
                        (Some(trigger), interval) => {
                            if let Some(interval) = interval {
                                notes.push(format!(
                                    "the interval {interval} is left out: a task with `single` runs on the rising edge of {trigger}"
                                ));
                            }
                            TaskKind::Event {
                                trigger: trigger.clone(),
                            }
                        }
                        (None, Some(interval)) => TaskKind::Cyclic {
                            interval_us: parse_interval_us(interval).ok_or_else(|| {
                                self.error(&place, ImportErrorKind::BadInterval(interval.clone()))
                            })?,
                        },
                        (None, None) => {
                            notes.push(
                                "no interval and no `single`: the task runs freewheeling"
                                    .to_owned(),
                            );
                            TaskKind::Freewheeling
                        }
                    };
                    let priority = match u8::try_from(task.priority) {
                        Ok(priority) if priority <= LOWEST_PRIORITY => priority,
                        _ => {
                            notes.push(format!(
                                "priority {} is beyond Rivet's lowest, {LOWEST_PRIORITY}, and becomes it",
                                task.priority
                            ));
                            LOWEST_PRIORITY
                        }
                    };
                    let mut programs = Vec::new();
                    for instance in &task.pou_instances {
                        if let Some(program) = self.program_call(instance, &place, &mut called) {
                            programs.push(program);
                        }
                    }
                    self.project.tasks.push(Task {
                        name: task.name.clone(),
                        kind,
                        priority,
                        watchdog: None,
                        programs,
                    });
                    self.report.push(
                        Outcome::Converted,
                        format!("task '{}'", task.name),
                        &place.path,
                        place.line,
                        notes.join("; "),
                    );
                    self.opaque(&task.add_data, &place.path, place.line);
                }
            }
        }
        Ok(())
    }

    /// The program a task's instance calls, or `None` (with the reason in the report) when the
    /// project has no such program or another task calls it already.
    fn program_call(
        &mut self,
        instance: &PouInstance,
        task: &Place,
        called: &mut HashMap<String, String>,
    ) -> Option<String> {
        let path = format!("{}/pouInstance[@name='{}']", task.path, instance.name);
        let what = format!("program instance '{}'", instance.name);
        self.opaque(&instance.add_data, &path, task.line);
        // CODESYS writes an empty `typeName`: its instances are named after their programs.
        let program = if instance.type_name.is_empty() {
            instance.name.clone()
        } else {
            instance.type_name.clone()
        };
        let is_program = self.project.application.object(&program).is_some_and(
            |object| matches!(object, Object::Pou(pou) if pou.kind == PouKind::Program),
        );
        if !is_program {
            let note = format!(
                "`{program}` is not a program of the imported project (not in the file, or not converted)"
            );
            self.report
                .push(Outcome::NotConverted, what, &path, task.line, note);
            return None;
        }
        if let Some(first) = called.get(&program.to_lowercase()) {
            let note = format!(
                "instance `{first}` runs `{program}` already; Rivet runs one instance of each program"
            );
            self.report
                .push(Outcome::NotConverted, what, &path, task.line, note);
            return None;
        }
        called.insert(program.to_lowercase(), instance.name.clone());
        let note = if project_model::same_identifier(&instance.name, &program) {
            String::new()
        } else {
            format!(
                "the task calls the program `{program}`; Rivet names a program's only instance after it"
            )
        };
        self.report
            .push(Outcome::Converted, what, &path, task.line, note);
        Some(program)
    }
}
