//! The structures of MC_DigitalCamSwitch: the switches (`MC_CAMSWITCH_REF`) and the per-track
//! options (`MC_TRACK_REF`).

/// `AxisDirection` of a switch: the direction of motion in which it acts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum SwitchDirection {
    /// 0: both directions.
    #[default]
    Both,
    /// 1: positive motion only.
    Positive,
    /// 2: negative motion only.
    Negative,
}

impl SwitchDirection {
    /// Whether the switch acts while the axis moves in `direction` (+1 or −1).
    pub(crate) fn admits(self, direction: f64) -> bool {
        match self {
            Self::Both => true,
            Self::Positive => direction > 0.0,
            Self::Negative => direction < 0.0,
        }
    }
}

/// `CamSwitchMode`: how a switch decides when it is on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CamSwitchMode {
    /// 0: on between `FirstOnPosition` and `LastOnPosition`.
    #[default]
    Position,
    /// 1: on for `Duration` from crossing `FirstOnPosition`.
    Time,
}

/// One switch (`MC_CAMSWITCH_REF` element): a window or a timed pulse on one track.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CamSwitch {
    /// `TrackNumber`: the output the switch drives, 0 ..= 15.
    pub track_number: u16,
    /// `FirstOnPosition`: where the window starts (positive motion enters here), or where a
    /// timed switch fires.
    pub first_on_position: f64,
    /// `LastOnPosition`: where the window ends; below `FirstOnPosition` on a modulo axis the
    /// window spans the wrap (4000 → 1000 on a 5000 period). Not used by a timed switch.
    pub last_on_position: f64,
    /// `AxisDirection`.
    pub axis_direction: SwitchDirection,
    /// `CamSwitchMode`.
    pub cam_switch_mode: CamSwitchMode,
    /// `Duration` of a timed switch in seconds, 0 or more.
    pub duration_s: f64,
}

/// The options of one track (`MC_TRACK_REF` element).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TrackOptions {
    /// `OnCompensation` in seconds, −1 ..= 1: negative switches on earlier, positive later,
    /// by this time at the current velocity (actuator lag).
    pub on_compensation_s: f64,
    /// `OffCompensation` in seconds, −1 ..= 1: negative switches off earlier, positive later.
    pub off_compensation_s: f64,
    /// `Hysteresis` in position units, 0 or more: a switch that changed at a position does not
    /// change back, nor does the direction of motion reverse, until the axis has moved more
    /// than this away, so jitter at an edge does not chatter.
    pub hysteresis: f64,
}
