//! The studio's workflow tests, driven through its accessibility tree without a window (and,
//! for the image snapshots, rendered with the software rasterizer).
//!
//! They are modules of one test binary rather than one binary each: every binary links the whole
//! studio with wgpu, and nine copies of that
//! (700 MB each with full debug information) were the likely cause of a CI run failing to link.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

mod basics;
mod cam_editor;
mod charts;
mod debug_graphical;
mod debugging;
mod device_editors;
mod devices;
mod diagram;
mod editor;
mod export;
mod import;
mod instruction_list;
mod logout;
mod modbus_online;
mod online;
mod online_change;
mod recovery;
mod snapshots;
mod support;
mod target_lost;
mod trace_config;
mod tree;
mod tree_languages;
