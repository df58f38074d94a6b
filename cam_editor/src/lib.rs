//! Rivet's cam and tappet editor: segments and key points over the master range, plots of slave
//! position, velocity, acceleration and jerk, tappet lanes and CSV import and export.
//!
//! Like every editor it never changes the project while drawing: it emits edits that the app
//! applies after the frame.
