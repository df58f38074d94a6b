//! The ids of cams registered in a kernel and of cam selections made by MC_CamTableSelect.

/// A cam registered with [`crate::kernel::Kernel::add_cam`]; the index into the kernel's cams.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CamId(pub usize);

/// `MC_CAM_ID`: the result of MC_CamTableSelect that MC_CamIn refers to. 0 is never a valid
/// selection, so a `CamIn` whose `cam_table_id` was never set from a selection reports an error.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CamTableId(pub u32);

/// A cam selected for one master and one slave, with the options of MC_CamTableSelect.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CamSelection {
    /// The cam.
    pub cam: CamId,
    /// The master axis the selection was made for.
    pub master: crate::kernel::AxisId,
    /// The slave axis the selection was made for.
    pub slave: crate::kernel::AxisId,
    /// `Periodic`: repeat the cam; otherwise it runs once and the slave holds its end value.
    pub periodic: bool,
    /// `MasterAbsolute`: the cam master coordinate follows the master's absolute position;
    /// otherwise the master position at the start of MC_CamIn counts as 0.
    pub master_absolute: bool,
    /// `SlaveAbsolute`: with `StartMode` absolute or a ramp, the cam gives absolute slave
    /// positions; otherwise they count from the slave's position at the start.
    pub slave_absolute: bool,
}
