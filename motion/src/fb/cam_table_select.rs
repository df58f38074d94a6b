//! MC_CamTableSelect.

use crate::fb::execute::ExecuteCore;
use crate::kernel::{AxisId, Kernel, MotionError};
use crate::sync::{CamId, CamSelection, CamTableId};

/// MC_CamTableSelect: selects a cam for a master and a slave and outputs the `CamTableID`
/// MC_CamIn refers to. It finishes in the call of the rising edge (`Done`). Master and slave
/// must be different axes. Executing the instance again refreshes its selection (same
/// `CamTableID`) with the inputs of that edge; a running MC_CamIn keeps the selection it
/// started with until it is executed again.
#[derive(Clone, Debug, Default)]
pub struct CamTableSelect {
    /// `Execute`: a rising edge makes the selection.
    pub execute: bool,
    /// `CamTable`: the cam, as registered with [`Kernel::add_cam`].
    pub cam_table: CamId,
    /// `Periodic`: repeat the cam; otherwise it runs once.
    pub periodic: bool,
    /// `MasterAbsolute`: the cam master follows the master's absolute position; otherwise
    /// the master position at the start of MC_CamIn counts as 0.
    pub master_absolute: bool,
    /// `SlaveAbsolute`: with MC_CamIn `StartMode` absolute or a ramp, the cam's slave values
    /// are absolute; otherwise they count from the slave's position at the start.
    pub slave_absolute: bool,
    /// `Done`: the selection is made and `CamTableID` is valid.
    pub done: bool,
    /// `Busy`: never TRUE after a call, since the selection is made at once.
    pub busy: bool,
    /// `Error`: the selection was refused.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    /// `CamTableID`: the selection to give MC_CamIn; 0 before the first successful call.
    pub cam_table_id: CamTableId,
    core: ExecuteCore,
}

impl CamTableSelect {
    /// One call of the instance for `master` and `slave`.
    pub fn call(&mut self, kernel: &mut Kernel, master: AxisId, slave: AxisId) {
        let selection = CamSelection {
            cam: self.cam_table,
            master,
            slave,
            periodic: self.periodic,
            master_absolute: self.master_absolute,
            slave_absolute: self.slave_absolute,
        };
        let previous = (self.cam_table_id.0 != 0).then_some(self.cam_table_id);
        let mut selected = None;
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            selected = Some(kernel.select_cam(selection, previous)?);
            Ok(None)
        });
        if let Some(id) = selected {
            self.cam_table_id = id;
        }
        self.done = outputs.done();
        self.busy = outputs.busy;
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
