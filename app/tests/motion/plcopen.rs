//! The motion kernel driven from Structured Text through `rivet simulate`: the worked examples
//! of the PLCopen motion digest (`../shared/reference/digests/plcopen-and-softmotion-cams.md`
//! §3) on the example project's `MotionTask` (2 ms), with its axes and extra linear ones.

use std::fs;

use crate::support::{
    T12_SWITCHES, add_cam, boolean, linear_axis, modulo_axis, number, project, simulate,
};

#[test]
fn t13a_a_second_move_started_by_the_first_ones_done_ends_at_10000() {
    let dir = project(
        &[linear_axis("Feed")],
        &[
            ("fbPower", "MC_Power"),
            ("fbFirst", "MC_MoveRelative"),
            ("fbSecond", "MC_MoveRelative"),
        ],
        "fbPower(Axis := Feed, Enable := TRUE);
fbFirst(Axis := Feed, Execute := fbPower.Status, Distance := 6000.0, Velocity := 2000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);
fbSecond(Axis := Feed, Execute := fbFirst.Done, Distance := 4000.0, Velocity := 2000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);",
    );
    // 6000 at 2000/s takes 3.2 s, 4000 another 2.2 s: 3000 cycles of 2 ms are enough.
    let values = simulate(
        &dir,
        3000,
        &[
            "Feed.fActPosition",
            "MotionControl.fbSecond.Done",
            "Feed.nAxisState",
        ],
    );
    assert!(
        (number(&values, "Feed.fActPosition") - 10000.0).abs() < 1e-6,
        "{values:?}"
    );
    assert!(
        boolean(&values, "MotionControl.fbSecond.Done"),
        "{values:?}"
    );
    // SMC_AXIS_STATE.standstill.
    assert_eq!(number(&values, "Feed.nAxisState"), 3.0);
}

#[test]
fn t13b_move_relative_and_move_additive_aborting_at_3250() {
    let dir = project(
        &[linear_axis("Relative"), linear_axis("Additive")],
        &[
            ("fbPowerR", "MC_Power"),
            ("fbPowerA", "MC_Power"),
            ("fbFirstR", "MC_MoveRelative"),
            ("fbFirstA", "MC_MoveRelative"),
            ("fbSecondR", "MC_MoveRelative"),
            ("fbSecondA", "MC_MoveAdditive"),
            ("xTriggerR", "BOOL"),
            ("xTriggerA", "BOOL"),
            ("lrTriggerR", "LREAL"),
        ],
        "fbPowerR(Axis := Relative, Enable := TRUE);
fbPowerA(Axis := Additive, Enable := TRUE);
fbFirstR(Axis := Relative, Execute := fbPowerR.Status, Distance := 6000.0, Velocity := 1000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);
fbFirstA(Axis := Additive, Execute := fbPowerA.Status, Distance := 6000.0, Velocity := 1000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);
IF NOT xTriggerR AND Relative.fActPosition >= 3250.0 THEN
    xTriggerR := TRUE;
    lrTriggerR := Relative.fSetPosition;
END_IF
xTriggerA := xTriggerA OR Additive.fActPosition >= 3250.0;
fbSecondR(Axis := Relative, Execute := xTriggerR, Distance := 4000.0, Velocity := 1000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);
fbSecondA(Axis := Additive, Execute := xTriggerA, Distance := 4000.0, Velocity := 1000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);",
    );
    let values = simulate(
        &dir,
        6000,
        &[
            "Relative.fActPosition",
            "Additive.fActPosition",
            "MotionControl.lrTriggerR",
            "MotionControl.fbFirstR.CommandAborted",
            "MotionControl.fbFirstA.CommandAborted",
        ],
    );
    let trigger = number(&values, "MotionControl.lrTriggerR");
    // The trigger is the first 2 ms cycle at or past 3250 (1000 mm/s: 2 mm per cycle).
    assert!((3250.0..3252.1).contains(&trigger), "{values:?}");
    assert!((number(&values, "Relative.fActPosition") - (trigger + 4000.0)).abs() < 1e-6);
    assert!((number(&values, "Additive.fActPosition") - 10000.0).abs() < 1e-6);
}

#[test]
fn t14_a_stop_locks_the_axis_until_its_execute_falls() {
    let dir = project(
        &[linear_axis("Spindle")],
        &[
            ("fbPower", "MC_Power"),
            ("fbVelocity", "MC_MoveVelocity"),
            ("fbStop", "MC_Stop"),
            ("fbAgain", "MC_MoveVelocity"),
            ("iCycle", "INT"),
        ],
        "iCycle := iCycle + 1;
fbPower(Axis := Spindle, Enable := TRUE);
fbVelocity(Axis := Spindle, Execute := fbPower.Status, Velocity := 50.0, Acceleration := 10.0,
    Deceleration := 10.0, Direction := MC_DIRECTION.positive);
fbStop(Axis := Spindle, Execute := iCycle >= 3000, Deceleration := 10.0);
fbAgain(Axis := Spindle, Execute := iCycle >= 3100, Velocity := 50.0, Acceleration := 10.0,
    Deceleration := 10.0);",
    );
    // Cycle 3000 is 6 s in: the axis runs at 50 and needs 5 s to stop at 10 mm/s².
    let values = simulate(
        &dir,
        6000,
        &[
            "Spindle.nAxisState",
            "Spindle.fActVelocity",
            "MotionControl.fbStop.Done",
            "MotionControl.fbAgain.Error",
            "MotionControl.fbAgain.ErrorID",
            "MotionControl.fbVelocity.CommandAborted",
        ],
    );
    // SMC_AXIS_STATE.stopping.
    assert_eq!(number(&values, "Spindle.nAxisState"), 2.0, "{values:?}");
    assert_eq!(number(&values, "Spindle.fActVelocity"), 0.0);
    assert!(boolean(&values, "MotionControl.fbStop.Done"));
    assert!(boolean(&values, "MotionControl.fbAgain.Error"));
    assert_eq!(number(&values, "MotionControl.fbAgain.ErrorID"), 3.0);
}

#[test]
fn a_modulo_axis_moves_the_way_the_direction_says() {
    let dir = project(
        &[],
        &[
            ("fbPower", "MC_Power"),
            ("fbTo350", "MC_MoveAbsolute"),
            ("fbPositive", "MC_MoveAbsolute"),
            ("lrHighest", "LREAL"),
        ],
        "fbPower(Axis := Master, Enable := TRUE);
fbTo350(Axis := Master, Execute := fbPower.Status, Position := 350.0, Velocity := 360.0,
    Acceleration := 3600.0, Deceleration := 3600.0, Direction := MC_DIRECTION.positive);
fbPositive(Axis := Master, Execute := fbTo350.Done, Position := 10.0, Velocity := 360.0,
    Acceleration := 3600.0, Deceleration := 3600.0, Direction := MC_DIRECTION.positive);
IF fbTo350.Done OR fbPositive.Busy THEN
    lrHighest := MAX(lrHighest, Master.fSetPosition);
END_IF",
    );
    let values = simulate(
        &dir,
        2000,
        &[
            "Master.fActPosition",
            "MotionControl.fbPositive.Done",
            "MotionControl.lrHighest",
            "Master.fPositionPeriod",
        ],
    );
    assert!(
        (number(&values, "Master.fActPosition") - 10.0).abs() < 1e-6,
        "{values:?}"
    );
    assert!(boolean(&values, "MotionControl.fbPositive.Done"));
    // Positive from 350 to 10 passes 359.x and wraps, rather than going back through 180.
    assert!(
        number(&values, "MotionControl.lrHighest") > 359.0,
        "{values:?}"
    );
    assert_eq!(number(&values, "Master.fPositionPeriod"), 360.0);
}

/// The example's own motion program with the master turning from the first cycle instead of
/// waiting for the start button.
fn example_knife_turning() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    assets::copy_example_project(dir.path()).unwrap();
    let program = dir.path().join("application/MotionControl.st");
    let text = fs::read_to_string(&program)
        .unwrap()
        .replace(
            "xRunning := GVL_Machine.eMachineState = E_MachineState.Running;",
            "xRunning := TRUE;",
        )
        .replace("Acceleration := 360.0", "Acceleration := 3600.0");
    fs::write(&program, text).unwrap();
    dir
}

#[test]
fn the_example_knife_follows_its_cam_and_the_tappets_switch_the_outputs() {
    let dir = example_knife_turning();
    let watch = [
        "Master.fActPosition",
        "Knife.fActPosition",
        "Knife.nAxisState",
        "GVL_IO.xGlueValve",
        "MotionControl.fbKnifeCam.InSync",
        "CAM_Knife.fMasterPosition",
        "CAM_Knife.fSlavePosition",
        "CAM_Knife.dwTappets",
    ];
    // 400 cycles of 2 ms at 90 deg/s: the master is near 72 deg, between the glue valve's
    // tappets at 30 (on) and 90 (off).
    let early = simulate(&dir, 400, &watch);
    let master = number(&early, "Master.fActPosition");
    assert!((60.0..80.0).contains(&master), "{early:?}");
    assert!(boolean(&early, "GVL_IO.xGlueValve"), "{early:?}");
    assert!(boolean(&early, "MotionControl.fbKnifeCam.InSync"));
    // SMC_AXIS_STATE.synchronized_motion.
    assert_eq!(number(&early, "Knife.nAxisState"), 6.0);
    // The cam shows the coupling live: its master coordinate, the knife's set position and
    // the glue valve's track (bit 0).
    assert!((number(&early, "CAM_Knife.fMasterPosition") - master).abs() < 1e-6);
    assert_eq!(
        number(&early, "CAM_Knife.fSlavePosition"),
        number(&early, "Knife.fActPosition")
    );
    assert_eq!(number(&early, "CAM_Knife.dwTappets"), 1.0, "{early:?}");
    // 1000 cycles: near 180 deg, on the cam's line from (120, 60) to (240, 180), past the
    // tappet that closes the valve.
    let later = simulate(&dir, 1000, &watch);
    let master = number(&later, "Master.fActPosition");
    assert!((150.0..200.0).contains(&master), "{later:?}");
    let knife = number(&later, "Knife.fActPosition");
    assert!((knife - (60.0 + master - 120.0)).abs() < 1e-6, "{later:?}");
    assert!(!boolean(&later, "GVL_IO.xGlueValve"), "{later:?}");
}

/// A cam over master 0..360: Poly5 from (0, 0) up to (180, 180) and back down to (360, 0),
/// with `tappets` (TOML of `[[track]]` tables) added.
fn rise_and_return_cam(tappets: &str) -> String {
    format!(
        "master = {{ start = 0.0, end = 360.0, unit = \"deg\" }}
slave = {{ start = 0.0, end = 180.0, unit = \"mm\" }}

[profile]
kind = \"segments\"
start = {{ master = 0.0, slave = 0.0, velocity = 0.0, acceleration = 0.0, jerk = 0.0 }}

[[profile.segment]]
law = \"poly5\"
end = {{ master = 180.0, slave = 180.0, velocity = 0.0, acceleration = 0.0, jerk = 0.0 }}

[[profile.segment]]
law = \"poly5\"
end = {{ master = 360.0, slave = 0.0, velocity = 0.0, acceleration = 0.0, jerk = 0.0 }}
{tappets}"
    )
}

#[test]
fn t10_and_t1_an_invert_tappet_toggles_once_per_period_and_end_of_profile_pulses() {
    let dir = project(
        &[modulo_axis("Drum", 10.0), modulo_axis("Follower", 10.0)],
        &[
            ("fbPowerDrum", "MC_Power"),
            ("fbPowerFollower", "MC_Power"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbSelect", "MC_CamTableSelect"),
            ("fbCam", "MC_CamIn"),
            ("fbTappet", "SMC_GetTappetValue"),
            ("xLast", "BOOL"),
            ("iToggles", "INT"),
            ("iEndCycles", "INT"),
        ],
        "fbPowerDrum(Axis := Drum, Enable := TRUE);
fbPowerFollower(Axis := Follower, Enable := TRUE);
fbTurn(Axis := Drum, Execute := fbPowerDrum.Status, Velocity := 2.0, Acceleration := 10.0,
    Deceleration := 10.0, Direction := MC_DIRECTION.positive);
fbSelect(Master := Drum, Slave := Follower, CamTable := CAM_T10, Execute := fbPowerFollower.Status,
    Periodic := TRUE, MasterAbsolute := TRUE, SlaveAbsolute := TRUE);
fbCam(Master := Drum, Slave := Follower, Execute := fbSelect.Done,
    CamTableID := fbSelect.CamTableID);
fbTappet(Tappets := fbCam.Tappets, iID := 1);
IF fbTappet.bTappet <> xLast THEN
    iToggles := iToggles + 1;
END_IF
xLast := fbTappet.bTappet;
IF fbCam.EndOfProfile THEN
    iEndCycles := iEndCycles + 1;
END_IF",
    );
    let cam = "master = { start = 0.0, end = 10.0, unit = \"mm\" }
slave = { start = 0.0, end = 10.0, unit = \"mm\" }

[profile]
kind = \"segments\"
start = { master = 0.0, slave = 0.0, velocity = 1.0, acceleration = 0.0, jerk = 0.0 }

[[profile.segment]]
law = \"line\"
end = { master = 10.0, slave = 10.0, velocity = 1.0, acceleration = 0.0, jerk = 0.0 }

[[track]]
id = 1

[[track.tappet]]
position = 8.0
on_positive = \"invert\"
on_negative = \"invert\"
";
    add_cam(&dir, "CAM_T10", cam);
    // 20 s of 2 ms cycles: the drum (2 mm/s after a 0.2 s ramp) passes 8 at about 4.1 s and
    // then every 5 s (9.1, 14.1, 19.1), and wraps at 10 at about 5.1, 10.1 and 15.1 s.
    let values = simulate(
        &dir,
        10_000,
        &[
            "MotionControl.iToggles",
            "MotionControl.iEndCycles",
            "Follower.fActPosition",
            "Drum.fActPosition",
        ],
    );
    assert_eq!(number(&values, "MotionControl.iToggles"), 4.0, "{values:?}");
    // EndOfProfile is one cycle per period, never longer.
    assert_eq!(
        number(&values, "MotionControl.iEndCycles"),
        3.0,
        "{values:?}"
    );
    let (drum, follower) = (
        number(&values, "Drum.fActPosition"),
        number(&values, "Follower.fActPosition"),
    );
    assert!((drum - follower).abs() < 1e-6, "{values:?}");
}

#[test]
fn t12_a_digital_cam_switch_with_compensation_switches_early_and_late() {
    let dir = project(
        &[modulo_axis("Table", 5000.0)],
        &[
            ("fbPower", "MC_Power"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbSwitch", "MC_DigitalCamSwitch"),
            ("stSwitches", "MC_CAMSWITCH_REF"),
            ("stTracks", "MC_TRACK_REF"),
            ("stOutputs", "MC_OUTPUT_REF"),
            ("xLast", "BOOL"),
            ("iEdge", "INT"),
            ("aEdges", "ARRAY[1..8] OF LREAL"),
            ("xTimedSeen", "BOOL"),
        ],
        &format!(
            "{T12_SWITCHES}stTracks.Track[0].OnCompensation := T#-125MS;
stTracks.Track[0].OffCompensation := T#250MS;
fbPower(Axis := Table, Enable := TRUE);
fbTurn(Axis := Table, Execute := fbPower.Status, Velocity := 1000.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
fbSwitch(Axis := Table, Switches := stSwitches, Outputs := stOutputs, TrackOptions := stTracks,
    Enable := TRUE);
IF stOutputs.Output[0] <> xLast AND iEdge < 8 THEN
    iEdge := iEdge + 1;
    aEdges[iEdge] := Table.fSetPosition;
END_IF
xLast := stOutputs.Output[0];
xTimedSeen := xTimedSeen OR stOutputs.Output[1];"
        ),
    );
    // 5 s at 1000 units/s: almost one revolution of 5000.
    let values = simulate(
        &dir,
        2500,
        &[
            "MotionControl.iEdge",
            "MotionControl.aEdges[1]",
            "MotionControl.aEdges[2]",
            "MotionControl.aEdges[3]",
            "MotionControl.aEdges[4]",
            "MotionControl.fbSwitch.Error",
            "MotionControl.xTimedSeen",
        ],
    );
    assert!(
        !boolean(&values, "MotionControl.fbSwitch.Error"),
        "{values:?}"
    );
    let edges: Vec<f64> = (1..=4)
        .map(|index| number(&values, &format!("MotionControl.aEdges[{index}]")))
        .collect();
    // With OnCompensation -125 ms and OffCompensation +250 ms at 1000 units/s, Switch01's
    // window 2000..3000 becomes 1875..3250 (one 2 ms cycle of tolerance).
    let near = |value: f64, expected: f64| (value - expected).abs() <= 2.5;
    assert!(
        edges
            .windows(2)
            .any(|pair| near(pair[0], 1875.0) && near(pair[1], 3250.0)),
        "{values:?}"
    );
    assert!(boolean(&values, "MotionControl.xTimedSeen"), "{values:?}");
    // Switch03 (4000..1000 across the wrap) holds the track on from the start until its
    // compensated end at 1250.
    assert!(near(edges[0], 0.0) && near(edges[1], 1250.0), "{values:?}");
}

#[test]
fn t3_an_absolute_slave_jumps_to_the_cam_and_a_relative_one_adds_its_start() {
    let dir = project(
        &[
            modulo_axis("Drive", 360.0),
            linear_axis("Absolute"),
            linear_axis("Relative"),
        ],
        &[
            ("fbPowerDrive", "MC_Power"),
            ("fbPowerA", "MC_Power"),
            ("fbPowerR", "MC_Power"),
            ("fbAtA", "MC_SetPosition"),
            ("fbAtR", "MC_SetPosition"),
            ("fbSelectA", "MC_CamTableSelect"),
            ("fbSelectR", "MC_CamTableSelect"),
            ("fbCamA", "MC_CamIn"),
            ("fbCamR", "MC_CamIn"),
            ("fbTurn", "MC_MoveVelocity"),
            ("iCoupled", "INT"),
            ("lrFirstA", "LREAL"),
            ("lrFirstR", "LREAL"),
            ("lrPeakA", "LREAL"),
            ("lrPeakR", "LREAL"),
        ],
        "fbPowerDrive(Axis := Drive, Enable := TRUE);
fbPowerA(Axis := Absolute, Enable := TRUE);
fbPowerR(Axis := Relative, Enable := TRUE);
(* Both slaves stand at 20 when they couple. *)
fbAtA(Axis := Absolute, Execute := fbPowerA.Status, Position := 20.0);
fbAtR(Axis := Relative, Execute := fbPowerR.Status, Position := 20.0);
fbSelectA(Master := Drive, Slave := Absolute, CamTable := CAM_T3, Execute := fbAtA.Done,
    Periodic := TRUE, MasterAbsolute := TRUE, SlaveAbsolute := TRUE);
fbSelectR(Master := Drive, Slave := Relative, CamTable := CAM_T3, Execute := fbAtR.Done,
    Periodic := TRUE, MasterAbsolute := TRUE, SlaveAbsolute := FALSE);
fbCamA(Master := Drive, Slave := Absolute, Execute := fbSelectA.Done,
    CamTableID := fbSelectA.CamTableID, StartMode := MC_StartMode.absolute);
fbCamR(Master := Drive, Slave := Relative, Execute := fbSelectR.Done,
    CamTableID := fbSelectR.CamTableID, StartMode := MC_StartMode.absolute);
IF fbCamA.Busy AND fbCamR.Busy THEN
    iCoupled := iCoupled + 1;
END_IF
(* The set positions after the first cycle of the couplings, with the master at rest at 0. *)
IF iCoupled = 2 THEN
    lrFirstA := Absolute.fSetPosition;
    lrFirstR := Relative.fSetPosition;
END_IF
fbTurn(Axis := Drive, Execute := iCoupled >= 3, Velocity := 360.0, Acceleration := 3600.0,
    Deceleration := 3600.0, Direction := MC_DIRECTION.positive);
IF iCoupled >= 2 THEN
    lrPeakA := MAX(lrPeakA, Absolute.fSetPosition);
    lrPeakR := MAX(lrPeakR, Relative.fSetPosition);
END_IF",
    );
    add_cam(&dir, "CAM_T3", &rise_and_return_cam(""));
    let values = simulate(
        &dir,
        600,
        &[
            "MotionControl.lrFirstA",
            "MotionControl.lrFirstR",
            "MotionControl.lrPeakA",
            "MotionControl.lrPeakR",
        ],
    );
    assert_eq!(number(&values, "MotionControl.lrFirstA"), 0.0, "{values:?}");
    assert_eq!(
        number(&values, "MotionControl.lrFirstR"),
        20.0,
        "{values:?}"
    );
    // The peak of the cam at master 180 is reached within a cycle of 0.72 deg.
    assert!(
        (number(&values, "MotionControl.lrPeakA") - 180.0).abs() < 1e-3,
        "{values:?}"
    );
    assert!(
        (number(&values, "MotionControl.lrPeakR") - 200.0).abs() < 1e-3,
        "{values:?}"
    );
}

#[test]
fn t4_master_scaling_and_offsets_move_the_period_and_the_stroke() {
    let dir = project(
        &[
            linear_axis("Feed"),
            modulo_axis("Fast", 1000.0),
            modulo_axis("Shifted", 1000.0),
        ],
        &[
            ("fbPowerFeed", "MC_Power"),
            ("fbPowerFast", "MC_Power"),
            ("fbPowerShifted", "MC_Power"),
            ("fbSelectFast", "MC_CamTableSelect"),
            ("fbSelectShifted", "MC_CamTableSelect"),
            ("fbFast", "MC_CamIn"),
            ("fbShifted", "MC_CamIn"),
            ("fbMove", "MC_MoveAbsolute"),
            ("iFastEnds", "INT"),
            ("lrShiftedEnd", "LREAL"),
            ("lrShiftedMin", "LREAL"),
            ("lrShiftedMax", "LREAL"),
        ],
        "fbPowerFeed(Axis := Feed, Enable := TRUE);
fbPowerFast(Axis := Fast, Enable := TRUE);
fbPowerShifted(Axis := Shifted, Enable := TRUE);
fbSelectFast(Master := Feed, Slave := Fast, CamTable := CAM_T4, Execute := fbPowerFast.Status,
    Periodic := TRUE, MasterAbsolute := TRUE, SlaveAbsolute := TRUE);
fbSelectShifted(Master := Feed, Slave := Shifted, CamTable := CAM_T4,
    Execute := fbPowerShifted.Status, Periodic := TRUE, MasterAbsolute := TRUE,
    SlaveAbsolute := TRUE);
fbFast(Master := Feed, Slave := Fast, Execute := fbSelectFast.Done,
    CamTableID := fbSelectFast.CamTableID, MasterScaling := 2.0);
fbShifted(Master := Feed, Slave := Shifted, Execute := fbSelectShifted.Done,
    CamTableID := fbSelectShifted.CamTableID, MasterOffset := 20.0, SlaveOffset := 30.0);
fbMove(Axis := Feed, Execute := fbFast.Busy AND fbShifted.Busy, Position := 400.0,
    Velocity := 100.0, Acceleration := 20000.0, Deceleration := 20000.0);
IF fbFast.EndOfProfile THEN
    iFastEnds := iFastEnds + 1;
END_IF
IF fbShifted.EndOfProfile AND lrShiftedEnd = 0.0 THEN
    lrShiftedEnd := Feed.fSetPosition;
END_IF
IF fbShifted.InSync THEN
    IF lrShiftedMin = 0.0 OR Shifted.fSetPosition < lrShiftedMin THEN
        lrShiftedMin := Shifted.fSetPosition;
    END_IF
    lrShiftedMax := MAX(lrShiftedMax, Shifted.fSetPosition);
END_IF",
    );
    add_cam(&dir, "CAM_T4", &rise_and_return_cam(""));
    // 4.5 s: the feed moves 0 to 400 at 100 mm/s.
    let values = simulate(
        &dir,
        2250,
        &[
            "Feed.fActPosition",
            "MotionControl.iFastEnds",
            "MotionControl.lrShiftedEnd",
            "MotionControl.lrShiftedMin",
            "MotionControl.lrShiftedMax",
        ],
    );
    assert!(
        (number(&values, "Feed.fActPosition") - 400.0).abs() < 1e-6,
        "{values:?}"
    );
    // MasterScaling 2: a period every 180 master units, so ends at 180 and 360.
    assert_eq!(
        number(&values, "MotionControl.iFastEnds"),
        2.0,
        "{values:?}"
    );
    // MasterOffset 20: the first period ends at master 340 (the cam sees 360).
    let end = number(&values, "MotionControl.lrShiftedEnd");
    assert!((340.0..340.3).contains(&end), "{values:?}");
    // SlaveOffset 30: the slave runs 30 .. 210.
    assert!(
        (number(&values, "MotionControl.lrShiftedMin") - 30.0).abs() < 0.01,
        "{values:?}"
    );
    assert!(
        (number(&values, "MotionControl.lrShiftedMax") - 210.0).abs() < 0.01,
        "{values:?}"
    );
}

#[test]
fn t18a_gear_in_pos_starts_at_230_and_is_in_sync_at_280_with_the_slave_at_60() {
    let dir = project(
        &[modulo_axis("Drum", 360.0), modulo_axis("Roll", 360.0)],
        &[
            ("fbPowerDrum", "MC_Power"),
            ("fbPowerRoll", "MC_Power"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbGear", "MC_GearInPos"),
            ("lrStartSync", "LREAL"),
            ("lrInSyncMaster", "LREAL"),
            ("lrInSyncSlave", "LREAL"),
        ],
        "fbPowerDrum(Axis := Drum, Enable := TRUE);
fbPowerRoll(Axis := Roll, Enable := TRUE);
fbTurn(Axis := Drum, Execute := fbPowerDrum.Status, Velocity := 50.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
fbGear(Master := Drum, Slave := Roll, Execute := fbPowerRoll.Status AND fbTurn.InVelocity,
    RatioNumerator := 1, RatioDenominator := 1, MasterSyncPosition := 280.0,
    SlaveSyncPosition := 60.0, MasterStartDistance := 50.0);
IF fbGear.StartSync AND lrStartSync = 0.0 THEN
    lrStartSync := Drum.fSetPosition;
END_IF
IF fbGear.InSync AND lrInSyncMaster = 0.0 THEN
    lrInSyncMaster := Drum.fSetPosition;
    lrInSyncSlave := Roll.fSetPosition;
END_IF",
    );
    // 6 s at 50 deg/s: the drum reaches 300.
    let values = simulate(
        &dir,
        3000,
        &[
            "MotionControl.lrStartSync",
            "MotionControl.lrInSyncMaster",
            "MotionControl.lrInSyncSlave",
        ],
    );
    // Flags show at the call after the cycle that set them: within two cycles (0.2 deg).
    let near = |path: &str, expected: f64| (number(&values, path) - expected).abs() <= 0.25;
    assert!(near("MotionControl.lrStartSync", 230.0), "{values:?}");
    assert!(near("MotionControl.lrInSyncMaster", 280.0), "{values:?}");
    assert!(near("MotionControl.lrInSyncSlave", 60.0), "{values:?}");
}

#[test]
fn t8_dead_time_compensation_switches_a_tappet_early_by_the_distance_of_its_time() {
    let dir = project(
        &[modulo_axis("Drum", 360.0)],
        &[
            ("fbPower", "MC_Power"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbNow", "SMC_CamRegister"),
            ("fbEarly", "SMC_CamRegister"),
            ("aNow", "ARRAY[1..512] OF BOOL"),
            ("aEarly", "ARRAY[1..512] OF BOOL"),
            ("lrNow", "LREAL"),
            ("lrEarly", "LREAL"),
        ],
        "fbPower(Axis := Drum, Enable := TRUE);
fbTurn(Axis := Drum, Execute := fbPower.Status, Velocity := 100.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
fbNow(Master := Drum, CamTable := CAM_T8, bTappet := aNow, Enable := TRUE);
fbEarly(Master := Drum, CamTable := CAM_T8, bTappet := aEarly, Enable := TRUE,
    DeadTimeCompensation := 0.02);
IF aNow[1] AND lrNow = 0.0 THEN
    lrNow := Drum.fSetPosition;
END_IF
IF aEarly[1] AND lrEarly = 0.0 THEN
    lrEarly := Drum.fSetPosition;
END_IF",
    );
    add_cam(
        &dir,
        "CAM_T8",
        &rise_and_return_cam(
            "
[[track]]
id = 1

[[track.tappet]]
position = 100.0
on_positive = \"on\"
on_negative = \"none\"
",
        ),
    );
    // 1.5 s at 100 deg/s: past 100.
    let values = simulate(&dir, 750, &["MotionControl.lrNow", "MotionControl.lrEarly"]);
    // Each read is the set position at the call after the switching cycle (0.2 deg a cycle).
    let now = number(&values, "MotionControl.lrNow");
    let early = number(&values, "MotionControl.lrEarly");
    assert!((100.0..100.5).contains(&now), "{values:?}");
    // +0.02 s at 100 deg/s: 2 deg earlier.
    assert!((now - early - 2.0).abs() <= 0.25, "{values:?}");
}

#[test]
fn t16_buffered_stops_at_the_first_target_aborting_takes_over_and_blending_high_passes_fast() {
    let dir = project(
        &[
            linear_axis("Buffered"),
            linear_axis("Aborting"),
            linear_axis("Blending"),
        ],
        &[
            ("fbPowerB", "MC_Power"),
            ("fbPowerA", "MC_Power"),
            ("fbPowerL", "MC_Power"),
            ("fbFirstB", "MC_MoveAbsolute"),
            ("fbFirstA", "MC_MoveAbsolute"),
            ("fbFirstL", "MC_MoveAbsolute"),
            ("fbSecondB", "MC_MoveAbsolute"),
            ("fbSecondA", "MC_MoveAbsolute"),
            ("fbSecondL", "MC_MoveAbsolute"),
            ("xFirstDoneB", "BOOL"),
            ("xFirstDoneA", "BOOL"),
            ("xRestAtTargetB", "BOOL"),
            ("lrPassL", "LREAL"),
        ],
        "fbPowerB(Axis := Buffered, Enable := TRUE);
fbPowerA(Axis := Aborting, Enable := TRUE);
fbPowerL(Axis := Blending, Enable := TRUE);
fbFirstB(Axis := Buffered, Execute := fbPowerB.Status, Position := 1000.0, Velocity := 100.0,
    Acceleration := 1000.0, Deceleration := 1000.0);
fbFirstA(Axis := Aborting, Execute := fbPowerA.Status, Position := 1000.0, Velocity := 100.0,
    Acceleration := 1000.0, Deceleration := 1000.0);
fbFirstL(Axis := Blending, Execute := fbPowerL.Status, Position := 1000.0, Velocity := 100.0,
    Acceleration := 1000.0, Deceleration := 1000.0);
(* The second moves are given while the first ones run. *)
fbSecondB(Axis := Buffered, Execute := fbFirstB.Busy, Position := 2000.0, Velocity := 200.0,
    Acceleration := 1000.0, Deceleration := 1000.0, BufferMode := MC_BUFFER_MODE.Buffered);
fbSecondA(Axis := Aborting, Execute := fbFirstA.Busy, Position := 2000.0, Velocity := 200.0,
    Acceleration := 1000.0, Deceleration := 1000.0, BufferMode := MC_BUFFER_MODE.Aborting);
fbSecondL(Axis := Blending, Execute := fbFirstL.Busy, Position := 2000.0, Velocity := 200.0,
    Acceleration := 1000.0, Deceleration := 1000.0, BufferMode := MC_BUFFER_MODE.BlendingHigh);
xFirstDoneB := xFirstDoneB OR fbFirstB.Done;
xFirstDoneA := xFirstDoneA OR fbFirstA.Done;
xRestAtTargetB := xRestAtTargetB
    OR (ABS(Buffered.fSetPosition - 1000.0) < 1.0E-9 AND Buffered.fSetVelocity = 0.0);
IF lrPassL = 0.0 AND Blending.fSetPosition >= 1000.0 THEN
    lrPassL := Blending.fSetVelocity;
END_IF",
    );
    // 1000 at 100 then 1000 at 200: about 15.5 s.
    let values = simulate(
        &dir,
        8000,
        &[
            "Buffered.fActPosition",
            "Aborting.fActPosition",
            "Blending.fActPosition",
            "MotionControl.xFirstDoneB",
            "MotionControl.xFirstDoneA",
            "MotionControl.fbFirstA.CommandAborted",
            "MotionControl.xRestAtTargetB",
            "MotionControl.lrPassL",
        ],
    );
    for axis in ["Buffered", "Aborting", "Blending"] {
        let position = number(&values, &format!("{axis}.fActPosition"));
        assert!((position - 2000.0).abs() < 1e-6, "{axis}: {values:?}");
    }
    // Buffered: the first move finishes, at rest at its target, before the second starts.
    assert!(boolean(&values, "MotionControl.xFirstDoneB"), "{values:?}");
    assert!(
        boolean(&values, "MotionControl.xRestAtTargetB"),
        "{values:?}"
    );
    // Aborting: the first move never finishes.
    assert!(!boolean(&values, "MotionControl.xFirstDoneA"), "{values:?}");
    assert!(
        boolean(&values, "MotionControl.fbFirstA.CommandAborted"),
        "{values:?}"
    );
    // BlendingHigh passes the first target at the higher velocity, 200 (a cycle at 1000 /s²).
    let pass = number(&values, "MotionControl.lrPassL");
    assert!((pass - 200.0).abs() <= 2.5, "{values:?}");
}

#[test]
fn t15_a_velocity_override_of_half_halves_the_speed() {
    let dir = project(
        &[linear_axis("Belt")],
        &[
            ("fbPower", "MC_Power"),
            ("fbRun", "MC_MoveVelocity"),
            ("fbOverride", "MC_SetOverride"),
            ("iCycle", "INT"),
            ("lrFull", "LREAL"),
        ],
        "iCycle := iCycle + 1;
fbPower(Axis := Belt, Enable := TRUE);
fbRun(Axis := Belt, Execute := fbPower.Status, Velocity := 100.0, Acceleration := 1000.0,
    Deceleration := 1000.0);
IF iCycle = 500 THEN
    lrFull := Belt.fSetVelocity;
END_IF
fbOverride(Axis := Belt, Enable := iCycle > 500, VelFactor := 0.5);",
    );
    let values = simulate(
        &dir,
        1000,
        &[
            "MotionControl.lrFull",
            "Belt.fSetVelocity",
            "Belt.nAxisState",
            "MotionControl.fbOverride.Enabled",
        ],
    );
    assert_eq!(number(&values, "MotionControl.lrFull"), 100.0, "{values:?}");
    assert!(
        (number(&values, "Belt.fSetVelocity") - 50.0).abs() < 1e-9,
        "{values:?}"
    );
    assert!(boolean(&values, "MotionControl.fbOverride.Enabled"));
    // SMC_AXIS_STATE.continuous_motion: an override does not change the state.
    assert_eq!(number(&values, "Belt.nAxisState"), 5.0);
}

#[test]
fn t25_states_follow_the_plcopen_diagram_through_an_axis_error_and_a_reset() {
    let limited = linear_axis("Slide").replace(
        "software_limits = { enabled = false, min = 0.0, max = 0.0 }",
        "software_limits = { enabled = true, min = 0.0, max = 500.0 }",
    );
    let dir = project(
        &[limited],
        &[
            ("fbPower", "MC_Power"),
            ("fbRun", "MC_MoveVelocity"),
            ("fbMove", "MC_MoveAbsolute"),
            ("fbReset", "MC_Reset"),
            ("iCycle", "INT"),
            ("aStates", "ARRAY[1..6] OF INT"),
            ("wMoveInErrorStop", "WORD"),
        ],
        "iCycle := iCycle + 1;
fbPower(Axis := Slide, Enable := iCycle < 4000);
fbRun(Axis := Slide, Execute := iCycle >= 10, Velocity := 100.0, Acceleration := 1000.0,
    Deceleration := 1000.0);
fbMove(Axis := Slide, Execute := iCycle >= 3200 AND iCycle < 3300, Position := 100.0,
    Velocity := 100.0, Acceleration := 1000.0, Deceleration := 1000.0);
IF iCycle = 3250 THEN
    wMoveInErrorStop := fbMove.ErrorID;
END_IF
fbReset(Axis := Slide, Execute := iCycle >= 3500);
CASE iCycle OF
    5: aStates[1] := Slide.nAxisState;
    100: aStates[2] := Slide.nAxisState;
    3100: aStates[3] := Slide.nAxisState;
    3600: aStates[4] := Slide.nAxisState;
    4100: aStates[5] := Slide.nAxisState;
END_CASE",
    );
    let values = simulate(
        &dir,
        4200,
        &[
            "MotionControl.aStates[1]",
            "MotionControl.aStates[2]",
            "MotionControl.aStates[3]",
            "MotionControl.aStates[4]",
            "MotionControl.aStates[5]",
            "MotionControl.wMoveInErrorStop",
            "Slide.nErrorID",
        ],
    );
    let states: Vec<f64> = (1..=5)
        .map(|index| number(&values, &format!("MotionControl.aStates[{index}]")))
        .collect();
    // Standstill after MC_Power, continuous motion, ErrorStop past the software limit at 500
    // (reached at about 5 s), Standstill after MC_Reset, Disabled after MC_Power goes off.
    assert_eq!(states, [3.0, 5.0, 1.0, 3.0, 0.0], "{values:?}");
    // A move in ErrorStop is refused: ErrorID 2, the axis is in ErrorStop.
    assert_eq!(
        number(&values, "MotionControl.wMoveInErrorStop"),
        2.0,
        "{values:?}"
    );
}
