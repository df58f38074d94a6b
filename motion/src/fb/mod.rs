//! The PLCopen single-axis function blocks as plain structs: public input fields named after
//! the PLCopen inputs, public output fields, and a `call` that the runtime makes once per cycle
//! with the kernel and the axis the instance's `Axis` input refers to.
//!
//! Every Execute-type FB follows the rules documented in the `execute` module: a rising edge
//! samples the inputs, a re-trigger while busy is ignored (CODESYS), and a final output shows
//! for exactly one call when `Execute` is already FALSE.

mod execute;
pub mod halt;
pub mod home;
pub mod jog;
pub mod move_absolute;
pub mod move_additive;
pub mod move_relative;
pub mod move_velocity;
pub mod power;
pub mod read_actual_position;
pub mod read_actual_velocity;
pub mod read_axis_error;
pub mod read_status;
pub mod reset;
pub mod set_override;
pub mod set_position;
pub mod stop;

pub use halt::Halt;
pub use home::Home;
pub use jog::Jog;
pub use move_absolute::MoveAbsolute;
pub use move_additive::MoveAdditive;
pub use move_relative::MoveRelative;
pub use move_velocity::MoveVelocity;
pub use power::Power;
pub use read_actual_position::ReadActualPosition;
pub use read_actual_velocity::ReadActualVelocity;
pub use read_axis_error::ReadAxisError;
pub use read_status::ReadStatus;
pub use reset::Reset;
pub use set_override::SetOverride;
pub use set_position::SetPosition;
pub use stop::Stop;
