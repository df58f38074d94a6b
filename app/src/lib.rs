//! The Rivet studio and its headless command line.
//!
//! `rivet` without a subcommand opens the studio (an eframe window) on a project folder, or on
//! the example machine project when none is given. With a subcommand it works headless:
//! `rivet check`, `rivet fmt`, `rivet build`, `rivet simulate`, `rivet import`, `rivet export`, and the online
//! commands (`rivet status`, `download`, `start`, `stop`, `reset`, `read`, `write`, `force`, `unforce`,
//! `forces`, `faults`) and the debugging ones (`break`, `step`, `continue`, `halt`, `stack`,
//! `flow`) against a runtime.
//!
//! This is the only crate that knows eframe; it owns the window, the docking layout, the device
//! tree and the menus, and it applies the edits that editors emit.

mod build_cli;
mod cam_cli;
pub mod cli;
mod debug_args;
pub mod debug_bodies;
pub mod debug_cli;
pub mod debug_places;
pub mod debug_text;
mod export_cli;
mod import_cli;
mod literal_value;
pub mod modbus_devices;
pub mod modbus_devices_cli;
pub mod online_change_cli;
pub mod online_cli;
pub mod plcopen_export;
pub mod plcopen_import;
mod simulation_writes;
pub mod studio;
pub mod value_text;
