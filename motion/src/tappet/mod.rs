//! Tappets of a cam, evaluated once per task cycle on the cam master coordinate as CODESYS
//! `SMC_CamRegister` and `SMC_GetTappetValue` do: each track switches one BOOL when the master
//! passes its tappets.
//!
//! The rules (digest `plcopen-and-softmotion-cams.md` §4.3):
//! - A positive pass over X happens when `prev < X ≤ cur`, a negative pass when `cur ≤ X < prev`.
//! - A wrap at the period end continues the motion in the same direction: the cycle's interval
//!   is unwrapped across the period boundary, so a forward wrap never counts as a negative pass.
//! - Dead-time compensation of `t` seconds moves the coordinate the tappets see to
//!   `master + v·t`, so a tappet at P fires when the master reaches `P − v·t`.
//! - With a hysteresis `h`, the opposite switch of a tappet that just switched at X waits until
//!   the master is more than `h` beyond X on the other side; coming back within `h` and leaving
//!   on the original side switches nothing.

mod action;
mod cycle;
mod error;
mod evaluator;
mod switch;
mod track;
mod track_state;

#[cfg(test)]
mod tests;

pub use action::{PassDirection, TappetAction};
pub use cycle::{MasterWrap, TappetCycle};
pub use error::TappetError;
pub use evaluator::TappetEvaluator;
pub use switch::{SwitchCause, TappetSwitch};
pub use track::{Tappet, TappetTrack};
