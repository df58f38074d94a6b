//! One virtual axis: its configuration, its PLCopen state, the direction rules of modulo axes
//! and the profile generator that turns a command into set values.

pub mod config;
pub mod direction;
pub mod overrides;
pub mod profile;
pub mod state;

pub use config::{AxisConfig, ConfigError, SoftwareLimits};
pub use direction::Direction;
pub use overrides::Overrides;
pub use profile::{Profile, ProfileLimits, ProfileSample};
pub use state::AxisState;
