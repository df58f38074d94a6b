//! The I/O mapping view: every channel of the controller's I/O areas and of each Modbus TCP
//! device, with the variable bound to it, so a user sees what is wired where and what is free.
//!
//! It only reads the project; a click on a bound variable is reported so the app can open its
//! declaration.

mod channels;

use compiler::ide::LocatedVariable;
use egui::{CollapsingHeader, RichText, Ui};
use egui_extras::{Column, TableBuilder};
use project_model::{IoDirection, ModbusDataType, ModbusDevice, ModbusTable, Project};

use channels::{Channel, area_channels, outside_areas};

use crate::TableTexts;
use crate::table_texts::fill;

/// What the user did in the I/O mapping view this frame.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct IoMappingOutput {
    /// A bound variable was clicked: its owner (POU or global variable list) and its name.
    pub open: Option<(String, String)>,
}

/// Shows the I/O mapping of `project`: each I/O area word by word and bit by bit, then each
/// Modbus TCP device binding, each with the variables bound to it, in the words of `texts`.
pub fn io_mapping_ui(ui: &mut Ui, project: &Project, texts: &TableTexts) -> IoMappingOutput {
    let mut output = IoMappingOutput::default();
    let located = compiler::ide::located_variables(project);
    egui::ScrollArea::vertical()
        .id_salt("io_mapping")
        .auto_shrink([false, true])
        .show(ui, |ui| {
            ui.heading(format!("{} I/O", project.controller.name));
            if project.io_areas.is_empty() {
                ui.label(&texts.no_io_areas);
            }
            for (index, area) in project.io_areas.iter().enumerate() {
                let direction = match area.direction {
                    IoDirection::Input => &texts.inputs,
                    IoDirection::Output => &texts.outputs,
                    IoDirection::Memory => &texts.markers,
                };
                let title = format!(
                    "{} ({direction}, %{}B{} to %{}B{})",
                    area.name,
                    area.direction.area_letter(),
                    area.start_byte,
                    area.direction.area_letter(),
                    (area.start_byte + area.size_bytes).saturating_sub(1),
                );
                // Marker areas are large and rarely wired, so they start closed.
                CollapsingHeader::new(title)
                    .id_salt(("io_area", index))
                    .default_open(area.direction != IoDirection::Memory)
                    .show(ui, |ui| {
                        if !area.comment.is_empty() {
                            ui.label(&area.comment);
                        }
                        let channels = area_channels(area, &located);
                        channel_table_ui(ui, index, &channels, texts, &mut output);
                    });
            }
            let outside = outside_areas(project, &located);
            if !outside.is_empty() {
                ui.separator();
                ui.label(RichText::new(&texts.outside_areas).color(ui.visuals().warn_fg_color));
                for variable in &outside {
                    ui.horizontal(|ui| {
                        ui.monospace(&variable.address);
                        variable_link_ui(ui, variable, &mut output);
                    });
                }
            }
            for (index, device) in project.modbus_devices.iter().enumerate() {
                ui.separator();
                device_ui(ui, index, device, project, texts, &mut output);
            }
        });
    output
}

/// One area's channels; only the rows in view are laid out, as marker areas have thousands.
fn channel_table_ui(
    ui: &mut Ui,
    index: usize,
    channels: &[Channel],
    texts: &TableTexts,
    output: &mut IoMappingOutput,
) {
    let row_height = ui.spacing().interact_size.y + 2.0;
    TableBuilder::new(ui)
        .id_salt(("io_channels", index))
        .striped(true)
        // A 16-bit area (a word and its bits) shows whole; longer ones scroll.
        .max_scroll_height(row_height * 18.0)
        .auto_shrink([false, true])
        .column(Column::initial(90.0))
        .column(Column::initial(60.0))
        .column(Column::initial(220.0).clip(true))
        .column(Column::initial(80.0))
        .column(Column::remainder().clip(true))
        .header(row_height, |mut header| {
            for title in [
                &texts.channel,
                &texts.data_type,
                &texts.variable,
                &texts.declared_as,
                &texts.comment,
            ] {
                header.col(|ui| {
                    ui.strong(title);
                });
            }
        })
        .body(|body| {
            body.rows(row_height, channels.len(), |mut row| {
                let channel = &channels[row.index()];
                row.col(|ui| {
                    let text = RichText::new(&channel.address).monospace();
                    // Bits are indented under their word, as the channels of a device are.
                    if channel.kind == "BOOL" {
                        ui.add_space(12.0);
                    }
                    ui.label(text);
                });
                row.col(|ui| {
                    ui.label(channel.kind);
                });
                row.col(|ui| {
                    for variable in &channel.bound {
                        variable_link_ui(ui, variable, output);
                    }
                });
                row.col(|ui| {
                    let declared: Vec<String> = channel
                        .bound
                        .iter()
                        .map(|variable| format!("{} : {}", variable.address, variable.ty))
                        .collect();
                    ui.label(declared.join(", "));
                });
                row.col(|ui| {
                    let comments: Vec<&str> = channel
                        .bound
                        .iter()
                        .map(|variable| variable.comment.as_str())
                        .filter(|comment| !comment.is_empty())
                        .collect();
                    ui.label(comments.join("; "));
                });
            });
        });
}

/// A bound variable as a link that opens its declaration.
fn variable_link_ui(ui: &mut Ui, variable: &LocatedVariable, output: &mut IoMappingOutput) {
    let path = format!("{}.{}", variable.owner, variable.name);
    if ui.link(path).clicked() {
        output.open = Some((variable.owner.clone(), variable.name.clone()));
    }
}

/// One Modbus device and its bindings.
fn device_ui(
    ui: &mut Ui,
    index: usize,
    device: &ModbusDevice,
    project: &Project,
    texts: &TableTexts,
    output: &mut IoMappingOutput,
) {
    let protocol = match device.link {
        project_model::ModbusLink::Tcp { .. } => "TCP",
        project_model::ModbusLink::Rtu { .. } => "RTU",
    };
    let title = format!(
        "{} (Modbus {protocol} {}, unit {})",
        device.name, device.link, device.unit_id
    );
    CollapsingHeader::new(title)
        .id_salt(("modbus_device", index))
        .default_open(true)
        .show(ui, |ui| {
            if device.bindings.is_empty() {
                ui.label(&texts.no_binding);
                return;
            }
            let row_height = ui.spacing().interact_size.y + 2.0;
            TableBuilder::new(ui)
                .id_salt(("modbus_bindings", index))
                .striped(true)
                .auto_shrink([false, true])
                .column(Column::initial(120.0))
                .column(Column::initial(80.0))
                .column(Column::initial(80.0))
                .column(Column::initial(220.0).clip(true))
                .column(Column::remainder().clip(true))
                .header(row_height, |mut header| {
                    for title in [
                        &texts.modbus_table,
                        &texts.address,
                        &texts.data_type,
                        &texts.variable,
                        &texts.comment,
                    ] {
                        header.col(|ui| {
                            ui.strong(title);
                        });
                    }
                })
                .body(|mut body| {
                    for binding in &device.bindings {
                        body.row(row_height, |mut row| {
                            row.col(|ui| {
                                ui.label(table_name(binding.table, texts));
                            });
                            row.col(|ui| {
                                let width = binding.data_type.width();
                                let text = if width > 1 {
                                    format!(
                                        "{}..{}",
                                        binding.address,
                                        u32::from(binding.address) + u32::from(width) - 1
                                    )
                                } else {
                                    binding.address.to_string()
                                };
                                ui.monospace(text);
                            });
                            row.col(|ui| {
                                ui.label(data_type_name(binding.data_type));
                            });
                            row.col(|ui| {
                                binding_variable_ui(ui, &binding.variable, project, texts, output)
                            });
                            row.col(|ui| {
                                ui.label(&binding.comment);
                            });
                        });
                    }
                });
        });
}

/// A binding's variable path (`GVL_Machine.rBeltSpeedActual`) as a link when it names a declared
/// variable, in the error colour when it does not.
fn binding_variable_ui(
    ui: &mut Ui,
    path: &str,
    project: &Project,
    texts: &TableTexts,
    output: &mut IoMappingOutput,
) {
    let declared = path.split_once('.').filter(|(owner, name)| {
        project
            .application
            .object(owner)
            .is_some_and(|object| declares(object, name))
    });
    match declared {
        Some((owner, name)) => {
            if ui.link(path).clicked() {
                output.open = Some((owner.to_owned(), name.to_owned()));
            }
        }
        None => {
            ui.label(
                RichText::new(fill(&texts.not_declared, &[("path", path)]))
                    .color(ui.visuals().error_fg_color),
            );
        }
    }
}

fn declares(object: &project_model::Object, name: &str) -> bool {
    let variables = match object {
        project_model::Object::Pou(pou) => &pou.variables,
        project_model::Object::Gvl(gvl) => &gvl.variables,
        _ => return false,
    };
    variables
        .iter()
        .any(|variable| project_model::same_identifier(&variable.name, name))
}

fn table_name(table: ModbusTable, texts: &TableTexts) -> &str {
    match table {
        ModbusTable::Coil => &texts.coil,
        ModbusTable::DiscreteInput => &texts.discrete_input,
        ModbusTable::HoldingRegister => &texts.holding_register,
        ModbusTable::InputRegister => &texts.input_register,
    }
}

fn data_type_name(data_type: ModbusDataType) -> &'static str {
    match data_type {
        ModbusDataType::Bool => "BOOL",
        ModbusDataType::Int16 => "INT",
        ModbusDataType::Uint16 => "UINT",
        ModbusDataType::Int32 => "DINT",
        ModbusDataType::Uint32 => "UDINT",
        ModbusDataType::Int64 => "LINT",
        ModbusDataType::Uint64 => "ULINT",
        ModbusDataType::Real => "REAL",
        ModbusDataType::Lreal => "LREAL",
    }
}
