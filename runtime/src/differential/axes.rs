//! The motion kernel's axes of two engines compared: state, power, positions, velocities,
//! acceleration, error, reference, period, overrides, the commanded position and the command
//! in control, each bit for bit.

use motion::kernel::AxisSnapshot;
use program_image::ProgramImage;

use super::{AxisQuantity, Difference, Subject};

/// Compares two engines' axes after `cycle`; `image` names them.
pub(super) fn compare(
    cycle: u64,
    image: &ProgramImage,
    first: &[Option<AxisSnapshot>],
    second: &[Option<AxisSnapshot>],
) -> Result<(), Difference> {
    let name = |index: usize| {
        image
            .motion
            .as_ref()
            .and_then(|motion| motion.axes.get(index))
            .map_or_else(String::new, |axis| axis.name.clone())
    };
    for index in 0..first.len().max(second.len()) {
        let (Some(Some(a)), Some(Some(b))) = (first.get(index), second.get(index)) else {
            return Err(Difference {
                cycle,
                subject: Subject::Axis {
                    index,
                    name: name(index),
                    quantity: AxisQuantity::State,
                },
                first: presence(first.get(index)),
                second: presence(second.get(index)),
            });
        };
        if let Some((quantity, first, second)) = first_difference(a, b) {
            return Err(Difference {
                cycle,
                subject: Subject::Axis {
                    index,
                    name: name(index),
                    quantity,
                },
                first,
                second,
            });
        }
    }
    Ok(())
}

fn presence(axis: Option<&Option<AxisSnapshot>>) -> String {
    match axis {
        Some(Some(axis)) => format!("{:?}", axis.state),
        Some(None) => "no snapshot of the axis".to_owned(),
        None => "no such axis".to_owned(),
    }
}

/// The first quantity that differs, with both values as text. Reals are compared by their
/// bits, so that two NaNs with different payloads differ and the text shows the bits.
fn first_difference(a: &AxisSnapshot, b: &AxisSnapshot) -> Option<(AxisQuantity, String, String)> {
    let real = |x: f64| format!("{x} (16#{:016X})", x.to_bits());
    let reals = [
        (AxisQuantity::SetPosition, a.set_position, b.set_position),
        (
            AxisQuantity::ActualPosition,
            a.actual_position,
            b.actual_position,
        ),
        (AxisQuantity::SetVelocity, a.set_velocity, b.set_velocity),
        (
            AxisQuantity::ActualVelocity,
            a.actual_velocity,
            b.actual_velocity,
        ),
        (
            AxisQuantity::SetAcceleration,
            a.set_acceleration,
            b.set_acceleration,
        ),
        (
            AxisQuantity::CommandedPosition,
            a.commanded_position,
            b.commanded_position,
        ),
        (AxisQuantity::ModuloPeriod, a.modulo_period, b.modulo_period),
        (
            AxisQuantity::VelocityOverride,
            a.overrides.velocity,
            b.overrides.velocity,
        ),
        (
            AxisQuantity::AccelerationOverride,
            a.overrides.acceleration,
            b.overrides.acceleration,
        ),
        (
            AxisQuantity::JerkOverride,
            a.overrides.jerk,
            b.overrides.jerk,
        ),
    ];
    if a.state != b.state {
        return Some((
            AxisQuantity::State,
            format!("{:?}", a.state),
            format!("{:?}", b.state),
        ));
    }
    if a.powered != b.powered {
        return Some((
            AxisQuantity::Powered,
            a.powered.to_string(),
            b.powered.to_string(),
        ));
    }
    if let Some((quantity, x, y)) = reals
        .into_iter()
        .find(|(_, x, y)| x.to_bits() != y.to_bits())
    {
        return Some((quantity, real(x), real(y)));
    }
    if a.axis_error_id != b.axis_error_id {
        return Some((
            AxisQuantity::ErrorId,
            a.axis_error_id.to_string(),
            b.axis_error_id.to_string(),
        ));
    }
    if a.is_homed != b.is_homed {
        return Some((
            AxisQuantity::Homed,
            a.is_homed.to_string(),
            b.is_homed.to_string(),
        ));
    }
    if a.error != b.error {
        return Some((
            AxisQuantity::Error,
            a.error.to_string(),
            b.error.to_string(),
        ));
    }
    if (a.active_command, a.active_command_id) != (b.active_command, b.active_command_id) {
        let command = |axis: &AxisSnapshot| {
            format!(
                "{:?} (id {:?})",
                axis.active_command, axis.active_command_id
            )
        };
        return Some((AxisQuantity::ActiveCommand, command(a), command(b)));
    }
    None
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // A panic is a failed test.

    use motion::axis::{AxisConfig, AxisState};
    use motion::kernel::Kernel;

    use super::*;

    fn snapshot() -> AxisSnapshot {
        let mut kernel = Kernel::new();
        let config = AxisConfig {
            modulo_period: None,
            software_limits: None,
            max_velocity: 100.0,
            max_acceleration: 1000.0,
            max_deceleration: 1000.0,
            max_jerk: 0.0,
        };
        let axis = kernel.add_axis(config).unwrap();
        kernel.snapshot(axis).unwrap()
    }

    #[test]
    fn equal_axes_agree() {
        assert_eq!(
            compare(
                1,
                &ProgramImage::default(),
                &[Some(snapshot())],
                &[Some(snapshot())]
            ),
            Ok(())
        );
    }

    #[test]
    fn a_differing_position_velocity_or_state_is_named_with_both_values() {
        let a = snapshot();
        let mut b = a;
        b.set_velocity = 12.5;
        let difference = compare(7, &ProgramImage::default(), &[Some(a)], &[Some(b)]).unwrap_err();
        assert_eq!(difference.cycle, 7);
        assert_eq!(
            difference.subject,
            Subject::Axis {
                index: 0,
                name: String::new(),
                quantity: AxisQuantity::SetVelocity
            }
        );
        assert!(difference.second.starts_with("12.5 (16#"), "{difference}");
        let mut moved = a;
        moved.actual_position = -0.0;
        let difference =
            compare(1, &ProgramImage::default(), &[Some(a)], &[Some(moved)]).unwrap_err();
        assert!(
            matches!(
                difference.subject,
                Subject::Axis {
                    quantity: AxisQuantity::ActualPosition,
                    ..
                }
            ),
            "+0 and -0 differ in their bits: {difference}"
        );
        let mut stopped = a;
        stopped.state = AxisState::ErrorStop;
        let difference =
            compare(1, &ProgramImage::default(), &[Some(a)], &[Some(stopped)]).unwrap_err();
        assert!(difference.second.contains("ErrorStop"), "{difference}");
    }

    #[test]
    fn an_axis_missing_in_one_engine_is_a_difference() {
        let difference =
            compare(0, &ProgramImage::default(), &[Some(snapshot())], &[]).unwrap_err();
        assert_eq!(difference.second, "no such axis");
        let difference =
            compare(0, &ProgramImage::default(), &[Some(snapshot())], &[None]).unwrap_err();
        assert_eq!(difference.second, "no snapshot of the axis");
    }

    #[test]
    fn the_commanded_position_overrides_and_command_in_control_are_compared() {
        let a = snapshot();
        let mut based = a;
        based.commanded_position = 90.0;
        let difference =
            compare(2, &ProgramImage::default(), &[Some(a)], &[Some(based)]).unwrap_err();
        assert!(
            matches!(
                difference.subject,
                Subject::Axis {
                    quantity: AxisQuantity::CommandedPosition,
                    ..
                }
            ),
            "{difference}"
        );
        let mut slowed = a;
        slowed.overrides.velocity = 0.5;
        let difference =
            compare(2, &ProgramImage::default(), &[Some(a)], &[Some(slowed)]).unwrap_err();
        assert!(
            matches!(
                difference.subject,
                Subject::Axis {
                    quantity: AxisQuantity::VelocityOverride,
                    ..
                }
            ),
            "{difference}"
        );
        let mut commanded = a;
        commanded.active_command = Some("MC_MoveAbsolute");
        let difference =
            compare(2, &ProgramImage::default(), &[Some(a)], &[Some(commanded)]).unwrap_err();
        assert!(
            difference.second.contains("MC_MoveAbsolute"),
            "{difference}"
        );
    }
}
