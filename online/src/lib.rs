//! The client side of Rivet's online services: connect, identify, download with progress,
//! run control, monitoring, write and force, trace upload, and polling of generic Modbus TCP
//! devices.
//!
//! It exposes commands in and events and value snapshots out, and knows nothing of any UI.
