//! The numbers the runtime shows and writes into `AXIS_REF` and FB outputs are stable.

use motion::axis::{AxisState, Direction};
use motion::kernel::{BufferMode, MotionError};

#[test]
fn axis_states_have_the_codesys_smc_axis_state_numbers() {
    let table = [
        (AxisState::PowerOff, 0),
        (AxisState::ErrorStop, 1),
        (AxisState::Stopping, 2),
        (AxisState::Standstill, 3),
        (AxisState::DiscreteMotion, 4),
        (AxisState::ContinuousMotion, 5),
        (AxisState::SynchronizedMotion, 6),
        (AxisState::Homing, 7),
    ];
    for (state, code) in table {
        assert_eq!(state.code(), code, "{state}");
    }
}

#[test]
fn directions_have_the_codesys_mc_direction_numbers_both_ways() {
    let table = [
        (Direction::Positive, 1),
        (Direction::Negative, -1),
        (Direction::Shortest, 0),
        (Direction::Current, 2),
        (Direction::Fastest, 3),
    ];
    for (direction, code) in table {
        assert_eq!(direction.code(), code);
        assert_eq!(Direction::from_code(code), Some(direction));
    }
    assert_eq!(Direction::from_code(4), None);
}

#[test]
fn start_modes_have_the_codesys_mc_start_mode_numbers() {
    use motion::sync::StartMode;
    let table = [
        (StartMode::Absolute, 0),
        (StartMode::Relative, 1),
        (StartMode::RampIn, 2),
        (StartMode::RampInPositive, 3),
        (StartMode::RampInNegative, 4),
    ];
    for (mode, code) in table {
        assert_eq!(mode.code(), code);
    }
}

#[test]
fn buffer_modes_have_the_codesys_mc_buffer_mode_numbers() {
    let table = [
        (BufferMode::Aborting, 0),
        (BufferMode::Buffered, 1),
        (BufferMode::BlendingLow, 2),
        (BufferMode::BlendingPrevious, 3),
        (BufferMode::BlendingNext, 4),
        (BufferMode::BlendingHigh, 5),
    ];
    for (mode, code) in table {
        assert_eq!(mode.code(), code);
    }
}

#[test]
fn error_ids_are_stable_and_messages_name_what_is_wrong() {
    let table = [
        (MotionError::NotPowered, 1, "MC_Power"),
        (MotionError::AxisInErrorStop, 2, "MC_Reset"),
        (MotionError::AxisStopping, 3, "MC_Stop"),
        (
            MotionError::InvalidParameter {
                input: "Deceleration",
                value: -1.0,
                reason: "it must be a number above 0",
            },
            4,
            "Deceleration = -1",
        ),
        (
            MotionError::OutsideSoftwareLimits {
                target: 150.0,
                min: -100.0,
                max: 100.0,
            },
            5,
            "150",
        ),
        (
            MotionError::IllegalState {
                command: "MC_Home",
                state: AxisState::ContinuousMotion,
            },
            6,
            "MC_Home is not allowed while the axis is in ContinuousMotion",
        ),
        (MotionError::BufferFull, 7, "buffered"),
        (MotionError::AxisError { axis_error_id: 42 }, 8, "42"),
        (MotionError::UnknownAxis(3), 9, "axis 3"),
        (
            MotionError::NotCoupled {
                command: "MC_CamOut",
            },
            10,
            "MC_CamOut",
        ),
        (MotionError::MasterIsSlave, 11, "different axes"),
        (MotionError::UnknownCamTable(4), 12, "CamTableID 4"),
        (MotionError::UnknownCam(2), 13, "cam 2"),
        (
            MotionError::MasterOutOfCamRange {
                cam_master: 400.0,
                start: 0.0,
                end: 360.0,
            },
            14,
            "400",
        ),
    ];
    for (error, id, words) in table {
        assert_eq!(error.id(), id, "{error}");
        assert!(error.to_string().contains(words), "{error}");
    }
}
