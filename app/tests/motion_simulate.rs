//! The motion kernel driven from Structured Text through `rivet simulate`: the worked examples
//! of the PLCopen motion digest (`../shared/reference/digests/plcopen-and-softmotion-cams.md`
//! §3) on the example project's `MotionTask` (2 ms), with its axes and extra linear ones.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::fs;
use std::process::Command;

use serde_json::Value;

/// A linear virtual axis in `MotionTask`, limits generous enough for the examples.
fn linear_axis(name: &str) -> String {
    format!(
        r#"
[[axis]]
name = "{name}"
kind = "virtual"
task = "MotionTask"
unit = "mm"
software_limits = {{ enabled = false, min = 0.0, max = 0.0 }}
limits = {{ velocity = 5000.0, acceleration = 20000.0, deceleration = 20000.0, jerk = 0.0 }}
scaling = {{ numerator = 1.0, denominator = 1.0 }}
"#
    )
}

/// A copy of the example whose `MotionControl` program declares `variables` (name, type) and
/// runs `body`, with `axes` (TOML) added to the device tree.
fn project(axes: &[String], variables: &[(&str, &str)], body: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    assets::copy_example_project(dir.path()).unwrap();
    let manifest = dir.path().join("rivet.toml");
    let mut text = fs::read_to_string(&manifest).unwrap();
    for axis in axes {
        text.push_str(axis);
    }
    fs::write(&manifest, text).unwrap();
    let mut declarations = String::from("kind = \"program\"\nbody = { language = \"st\" }\n");
    for (name, ty) in variables {
        declarations.push_str(&format!(
            "\n[[variable]]\nname = \"{name}\"\nsection = \"VAR\"\ntype = \"{ty}\"\n"
        ));
    }
    let application = dir.path().join("application");
    fs::write(application.join("MotionControl.pou.toml"), declarations).unwrap();
    fs::write(application.join("MotionControl.st"), body).unwrap();
    dir
}

/// Runs `cycles` cycles of the fastest task and returns the watched values.
fn simulate(
    dir: &tempfile::TempDir,
    cycles: u32,
    watch: &[&str],
) -> serde_json::Map<String, Value> {
    let output = Command::new(env!("CARGO_BIN_EXE_rivet"))
        .args(["simulate", dir.path().to_str().unwrap()])
        .args(["--cycles", &cycles.to_string(), "--json", "--watch"])
        .arg(watch.join(","))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&output.stderr)
    );
    match serde_json::from_str(stdout.trim()).unwrap() {
        Value::Object(map) => map,
        other => panic!("not an object: {other}"),
    }
}

fn number(values: &serde_json::Map<String, Value>, path: &str) -> f64 {
    values[path]
        .as_f64()
        .unwrap_or_else(|| panic!("{path} is {:?}", values[path]))
}

fn boolean(values: &serde_json::Map<String, Value>, path: &str) -> bool {
    match &values[path] {
        Value::Bool(value) => *value,
        Value::String(text) => text == "TRUE",
        other => panic!("{path} is {other:?}"),
    }
}

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

/// A modulo axis in `MotionTask` with period `period_units`.
fn modulo_axis(name: &str, period_units: f64) -> String {
    linear_axis(name).replace(
        "unit = \"mm\"\n",
        &format!("unit = \"mm\"\nmodulo_period = {period_units:?}\n"),
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
    fs::write(dir.path().join("application/CAM_T10.cam.toml"), cam).unwrap();
    let manifest = dir.path().join("rivet.toml");
    let text = fs::read_to_string(&manifest).unwrap().replace(
        "    \"Motion/CAM_Knife.cam.toml\",\n",
        "    \"Motion/CAM_Knife.cam.toml\",\n    \"CAM_T10.cam.toml\",\n",
    );
    fs::write(&manifest, text).unwrap();
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
        "stSwitches.NumberOfSwitches := 4;
stSwitches.Switch[0].TrackNumber := 0;
stSwitches.Switch[0].FirstOnPosition := 2000.0;
stSwitches.Switch[0].LastOnPosition := 3000.0;
stSwitches.Switch[0].AxisDirection := 1;
stSwitches.Switch[1].TrackNumber := 0;
stSwitches.Switch[1].FirstOnPosition := 2500.0;
stSwitches.Switch[1].LastOnPosition := 3000.0;
stSwitches.Switch[1].AxisDirection := 2;
stSwitches.Switch[2].TrackNumber := 0;
stSwitches.Switch[2].FirstOnPosition := 4000.0;
stSwitches.Switch[2].LastOnPosition := 1000.0;
stSwitches.Switch[3].TrackNumber := 1;
stSwitches.Switch[3].FirstOnPosition := 3000.0;
stSwitches.Switch[3].CamSwitchMode := 1;
stSwitches.Switch[3].Duration := T#1350MS;
stTracks.Track[0].OnCompensation := T#-125MS;
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
xTimedSeen := xTimedSeen OR stOutputs.Output[1];",
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
