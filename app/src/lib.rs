//! The Rivet studio and its headless command line.
//!
//! `rivet` without a subcommand opens the studio (an eframe window) on a project folder, or on
//! the example machine project when none is given. With a subcommand it works headless:
//! `rivet check`, `rivet fmt`, `rivet build` and `rivet simulate` today; download and the
//! online commands as they arrive.
//!
//! This is the only crate that knows eframe; it owns the window, the docking layout, the device
//! tree and the menus, and it applies the edits that editors emit.

mod build_cli;
pub mod cli;
pub mod studio;
