//! The fields of a Modbus device that issue 19 added: its link (a TCP host and port, or one of
//! the project's serial ports), its optional poll interval, and the runtime master's settings
//! (I/O task, schedule, read gap, status variable), shown once a task is chosen as
//! `docs/modbus-master.md` §2.1 says.

use compiler::ide::{ChannelVariableError, modbus_round_requests, variable_type};
use egui::{RichText, Ui};
use project_model::{ModbusDevice, ModbusLink, ModbusSchedule, Project, same_identifier};

use super::DeviceTexts;
use super::field::parse_whole;
use super::form::Form;
use super::link_memory::{LinkMemory, switched_link};
use super::refusal::Refusal;
use super::texts::fill;

/// The link's kind, then a TCP device's host and port or an RTU device's serial port; switching
/// the kind brings back the link of that kind the device last had (`links`).
pub(crate) fn link_fields_ui(
    form: &mut Form<'_, ModbusDevice>,
    ui: &mut Ui,
    project: &Project,
    device: &ModbusDevice,
    texts: &DeviceTexts,
    links: &LinkMemory,
) {
    let kinds = [
        (texts.link_tcp.clone(), false),
        (texts.link_rtu.clone(), true),
    ];
    let rtu = matches!(device.link, ModbusLink::Rtu { .. });
    form.field("link", &texts.link, 200.0)
        .checked_combo_ui(ui, rtu, &kinds, |item, rtu| {
            item.link = switched_link(project, rtu, links)?;
            Ok(())
        });
    match &device.link {
        ModbusLink::Tcp { host, port } => {
            form.field("host", &texts.host, 160.0)
                .text_ui(ui, host, |item, host| {
                    if let ModbusLink::Tcp { host: old, .. } = &mut item.link {
                        *old = host;
                    }
                });
            form.field("port", &texts.port, 60.0).whole_ui(
                ui,
                *port,
                0..=u16::MAX,
                |item, port| {
                    if let ModbusLink::Tcp { port: old, .. } = &mut item.link {
                        *old = port;
                    }
                },
            );
        }
        ModbusLink::Rtu { serial_port } => {
            let names = port_choices(project, serial_port);
            let options: Vec<(String, usize)> = names
                .iter()
                .enumerate()
                .map(|(position, name)| (name.clone(), position))
                .collect();
            let current = names
                .iter()
                .position(|name| same_identifier(name, serial_port));
            form.field("serial port", &texts.serial_port, 160.0)
                .combo_ui(
                    ui,
                    current.unwrap_or(usize::MAX),
                    &options,
                    |item, chosen| {
                        if let Some(name) = names.get(chosen) {
                            item.link = ModbusLink::Rtu {
                                serial_port: name.clone(),
                            };
                        }
                    },
                );
        }
    }
}

/// The poll interval: empty means none, which only an RTU device polled every cycle may have
/// (the device checks refuse it elsewhere), so a device without one keeps it empty rather than
/// showing a 0 that an unrelated edit could store.
pub(crate) fn poll_interval_ui(
    form: &mut Form<'_, ModbusDevice>,
    ui: &mut Ui,
    device: &ModbusDevice,
    texts: &DeviceTexts,
) {
    let shown = device
        .poll_interval_ms
        .map(|interval| interval.to_string())
        .unwrap_or_default();
    let suffix = if device.needs_poll_interval() {
        texts.milliseconds.clone()
    } else {
        format!("{} ({})", texts.milliseconds, texts.optional)
    };
    form.field("poll", &texts.poll_interval, 60.0)
        .suffix(&suffix)
        .typed_ui(ui, &shown, |item, text| {
            if text.is_empty() {
                item.poll_interval_ms = None;
                // The undo label says the interval is gone rather than ending on a blank.
                return Ok(texts.no_poll_interval.clone());
            }
            item.poll_interval_ms = Some(parse_whole(text, 0, u32::MAX)?);
            Ok(text.to_owned())
        });
}

/// The I/O task and, once one is chosen, the schedule, the read gap, the status variable and
/// the number of requests a round sends.
pub(crate) fn master_fields_ui(
    form: &mut Form<'_, ModbusDevice>,
    ui: &mut Ui,
    project: &Project,
    device: &ModbusDevice,
    texts: &DeviceTexts,
) {
    let choices = task_choices(project, device.task.as_deref());
    let options: Vec<(String, usize)> = choices
        .iter()
        .enumerate()
        .map(|(position, task)| {
            (
                task.clone().unwrap_or_else(|| texts.no_task.clone()),
                position,
            )
        })
        .collect();
    let current = choices
        .iter()
        .position(|task| same_task(task.as_deref(), device.task.as_deref()))
        .unwrap_or_default();
    form.field("task", &texts.io_task, 200.0)
        .combo_ui(ui, current, &options, |item, chosen| {
            if let Some(task) = choices.get(chosen) {
                item.task = task.clone();
            }
        });
    if !device.is_runtime_device() {
        ui.label("");
        ui.label(RichText::new(&texts.studio_device_note).weak());
        ui.end_row();
        return;
    }
    let schedules = [
        (texts.schedule_interval.clone(), ModbusSchedule::Interval),
        (
            texts.schedule_every_cycle.clone(),
            ModbusSchedule::EveryCycle,
        ),
    ];
    form.field("schedule", &texts.schedule, 200.0).combo_ui(
        ui,
        device.schedule,
        &schedules,
        |item, schedule| item.schedule = schedule,
    );
    form.field("gap", &texts.max_read_gap, 60.0)
        .suffix(&texts.addresses)
        .whole_ui(ui, device.max_read_gap, 0..=u16::MAX, |item, gap| {
            item.max_read_gap = gap;
        });
    let status = device.status.clone().unwrap_or_default();
    form.field("status", &texts.status_variable, 200.0)
        .suffix(&texts.optional)
        .typed_ui(ui, &status, |item, text| {
            item.status = existing_variable(project, text)?;
            Ok(text.to_owned())
        });
    // Counted by the conversion and planner the build and the runtime use, so it is the count
    // the runtime sends.
    let count = modbus_round_requests(project, device);
    let template = if count == 1 {
        &texts.request_per_round
    } else {
        &texts.requests_per_round
    };
    ui.label(&texts.round);
    ui.label(RichText::new(fill(template, &[("count", &count.to_string())])).weak());
    ui.end_row();
}

/// `None` for an empty path, else the path when it names a variable of the project; whether
/// its type is `MODBUS_DEVICE_STATUS` is the build's to say (E0145).
fn existing_variable(project: &Project, text: &str) -> Result<Option<String>, Refusal> {
    if text.is_empty() {
        return Ok(None);
    }
    if variable_type(project, text).is_none() {
        return Err(ChannelVariableError::NoSuchVariable(text.to_owned()).into());
    }
    Ok(Some(text.to_owned()))
}

/// The serial ports a device may be put on: the project's, and the one it names when the
/// project has no such port, so the field shows what the file says.
fn port_choices(project: &Project, current: &str) -> Vec<String> {
    let mut names: Vec<String> = project
        .serial_ports
        .iter()
        .map(|port| port.name.clone())
        .collect();
    if !current.is_empty() && !names.iter().any(|name| same_identifier(name, current)) {
        names.push(current.to_owned());
    }
    names
}

/// The I/O tasks a device may name: none (a studio device), the project's tasks, and the one
/// it names when the project has no such task (the build reports it, E0143).
fn task_choices(project: &Project, current: Option<&str>) -> Vec<Option<String>> {
    let mut choices: Vec<Option<String>> = std::iter::once(None)
        .chain(project.tasks.iter().map(|task| Some(task.name.clone())))
        .collect();
    if let Some(current) = current
        && !choices
            .iter()
            .any(|task| same_task(task.as_deref(), Some(current)))
    {
        choices.push(Some(current.to_owned()));
    }
    choices
}

/// Whether two I/O task choices are the same: both none, or names equal as identifiers are
/// (without regard to case), as the model compares them.
fn same_task(a: Option<&str>, b: Option<&str>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => same_identifier(a, b),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> Project {
        project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project
    }

    #[test]
    fn the_task_choices_are_none_then_the_tasks_then_a_missing_one_named_by_the_device() {
        let project = example();
        let tasks = vec![
            None,
            Some("MainTask".to_owned()),
            Some("MotionTask".to_owned()),
        ];
        assert_eq!(task_choices(&project, None), tasks);
        assert_eq!(task_choices(&project, Some("MainTask")), tasks);
        // A task named in another case is the same task, not a missing one.
        assert_eq!(task_choices(&project, Some("maintask")), tasks);
        let mut with_missing = tasks.clone();
        with_missing.push(Some("Gone".into()));
        assert_eq!(task_choices(&project, Some("Gone")), with_missing);
        assert!(same_task(Some("MainTask"), Some("MAINTASK")));
        assert!(!same_task(None, Some("MainTask")));
    }

    #[test]
    fn a_port_the_project_lacks_is_offered_so_the_field_shows_it() {
        let mut project = example();
        assert_eq!(port_choices(&project, ""), Vec::<String>::new());
        assert_eq!(port_choices(&project, "RS232"), vec!["RS232".to_owned()]);
        project
            .serial_ports
            .push(project_model::SerialPort::new("RS485", "/dev/ttyS0"));
        assert_eq!(port_choices(&project, "RS485"), vec!["RS485".to_owned()]);
        // A port named in another case is the project's port, not a second one.
        assert_eq!(port_choices(&project, "rs485"), vec!["RS485".to_owned()]);
    }

    #[test]
    fn a_status_variable_must_exist_and_an_empty_one_is_none() {
        let project = example();
        assert_eq!(existing_variable(&project, ""), Ok(None));
        assert_eq!(
            existing_variable(&project, "GVL_Machine.xDriveReady"),
            Ok(Some("GVL_Machine.xDriveReady".into()))
        );
        let missing = existing_variable(&project, "GVL_Machine.stNothing").unwrap_err();
        assert!(
            missing.to_string().contains("there is no variable"),
            "{missing}"
        );
    }
}
