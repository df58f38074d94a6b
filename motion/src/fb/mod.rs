//! The PLCopen function blocks (single-axis, and the synchronised-motion FBs that take a master
//! and a slave) as plain structs: public input fields named after
//! the PLCopen inputs, public output fields, and a `call` that the runtime makes once per cycle
//! with the kernel and the axis the instance's `Axis` input refers to.
//!
//! Every Execute-type FB follows the rules documented in the `execute` module: a rising edge
//! samples the inputs, a re-trigger while busy is ignored (CODESYS), and a final output shows
//! for exactly one call when `Execute` is already FALSE.

pub mod cam_in;
pub mod cam_out;
pub mod cam_register;
pub mod cam_switch;
pub mod cam_table_select;
mod decouple;
pub mod digital_cam_switch;
mod execute;
pub mod gear_in;
pub mod gear_in_pos;
pub mod gear_out;
pub mod get_cam_slave_set_position;
pub mod get_tappet_value;
pub mod halt;
pub mod home;
pub mod jog;
pub mod move_absolute;
pub mod move_additive;
pub mod move_relative;
pub mod move_velocity;
pub mod phasing;
pub mod power;
pub mod read_actual_position;
pub mod read_actual_velocity;
pub mod read_axis_error;
pub mod read_status;
pub mod reset;
pub mod set_override;
pub mod set_position;
pub mod stop;
pub mod tappet_data;

pub use cam_in::CamIn;
pub use cam_out::CamOut;
pub use cam_register::CamRegister;
pub use cam_switch::{CamSwitch, CamSwitchMode, SwitchDirection, TrackOptions};
pub use cam_table_select::CamTableSelect;
pub use digital_cam_switch::{CAM_SWITCH_TRACKS, DigitalCamSwitch};
pub use gear_in::GearIn;
pub use gear_in_pos::GearInPos;
pub use gear_out::GearOut;
pub use get_cam_slave_set_position::GetCamSlaveSetPosition;
pub use get_tappet_value::GetTappetValue;
pub use halt::Halt;
pub use home::Home;
pub use jog::Jog;
pub use move_absolute::MoveAbsolute;
pub use move_additive::MoveAdditive;
pub use move_relative::MoveRelative;
pub use move_velocity::MoveVelocity;
pub use phasing::Phasing;
pub use power::Power;
pub use read_actual_position::ReadActualPosition;
pub use read_actual_velocity::ReadActualVelocity;
pub use read_axis_error::ReadAxisError;
pub use read_status::ReadStatus;
pub use reset::Reset;
pub use set_override::SetOverride;
pub use set_position::SetPosition;
pub use stop::Stop;
pub use tappet_data::TappetData;
