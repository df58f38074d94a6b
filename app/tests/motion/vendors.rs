//! The worked examples with numbers of the Omron NJ/NX and Delta DVP-15MC motion digests
//! (`../shared/reference/digests/omron-njnx-motion.md`, `delta-dvp15mc.md`) and T2, T7, T11,
//! T17 and T19 of the PLCopen/SoftMotion digest, as Structured Text run by `rivet simulate` on
//! the example project's `MotionTask` (2 ms). Rivet follows CODESYS: where a vendor's semantics
//! differ, the test keeps only the numbers that still apply (see each test's comment).

use serde_json::Value;

use crate::support::{
    T12_SWITCHES, add_cam, assert_near, boolean, linear_axis, modulo_axis, number, project,
    simulate,
};

/// A cam of segments from (0, 0) with slope `start_slope`: each segment is (law, master end,
/// slave end, slope dY/dX at the end), with `tracks` (TOML of `[[track]]` tables) added.
fn cam(start_slope: f64, segments: &[(&str, f64, f64, f64)], tracks: &str) -> String {
    let master_end = segments.last().unwrap().1;
    let slaves = segments.iter().map(|segment| segment.2);
    let slave_min = slaves.clone().fold(0.0_f64, f64::min);
    let slave_max = slaves.fold(1.0_f64, f64::max);
    let mut text = format!(
        "master = {{ start = 0.0, end = {master_end:?}, unit = \"mm\" }}
slave = {{ start = {slave_min:?}, end = {slave_max:?}, unit = \"mm\" }}

[profile]
kind = \"segments\"
start = {{ master = 0.0, slave = 0.0, velocity = {start_slope:?}, acceleration = 0.0, jerk = 0.0 }}
"
    );
    for (law, master, slave, slope) in segments {
        text.push_str(&format!(
            "
[[profile.segment]]
law = \"{law}\"
end = {{ master = {master:?}, slave = {slave:?}, velocity = {slope:?}, acceleration = 0.0, jerk = 0.0 }}
"
        ));
    }
    text.push_str(tracks);
    text
}

/// A cam whose slave stays at 0 over the master range 0..`period`: only its master coordinate
/// (`CAM.fMasterPosition`) matters.
fn dwell_cam(period: f64) -> String {
    cam(0.0, &[("line", period, 0.0, 0.0)], "")
}

/// The CODESYS default cam: Poly5 through (0,0,0,0), (120,120,1,0), (240,240,1,0) and
/// (360,360,0,0) as X, Y, dY/dX, d²Y/dX².
fn codesys_default_cam() -> String {
    cam(
        0.0,
        &[
            ("poly5", 120.0, 120.0, 1.0),
            ("poly5", 240.0, 240.0, 1.0),
            ("poly5", 360.0, 360.0, 0.0),
        ],
        "",
    )
}

/// Delta 5.6 ActivationMode 2/3: two masters stand at 1000, each with a slave coupled with
/// `MasterAbsolute` through a dwell cam of master range `period`; one master then moves to
/// `forward`, the other to `backward`.
fn delta_activation(period: f64, forward: f64, backward: f64) -> serde_json::Map<String, Value> {
    let dir = project(
        &[
            linear_axis("Fwd"),
            linear_axis("Back"),
            linear_axis("SlaveF"),
            linear_axis("SlaveB"),
        ],
        &[
            ("fbPowerF", "MC_Power"),
            ("fbPowerB", "MC_Power"),
            ("fbPowerSF", "MC_Power"),
            ("fbPowerSB", "MC_Power"),
            ("fbAtF", "MC_SetPosition"),
            ("fbAtB", "MC_SetPosition"),
            ("fbSelectF", "MC_CamTableSelect"),
            ("fbSelectB", "MC_CamTableSelect"),
            ("fbCamF", "MC_CamIn"),
            ("fbCamB", "MC_CamIn"),
            ("fbMoveF", "MC_MoveAbsolute"),
            ("fbMoveB", "MC_MoveAbsolute"),
            ("iCountF", "INT"),
            ("iCountB", "INT"),
            ("lrStartF", "LREAL"),
            ("lrStartB", "LREAL"),
            ("iWrapsF", "INT"),
            ("iWrapsB", "INT"),
        ],
        &format!(
            "fbPowerF(Axis := Fwd, Enable := TRUE);
fbPowerB(Axis := Back, Enable := TRUE);
fbPowerSF(Axis := SlaveF, Enable := TRUE);
fbPowerSB(Axis := SlaveB, Enable := TRUE);
fbAtF(Axis := Fwd, Execute := fbPowerF.Status, Position := 1000.0);
fbAtB(Axis := Back, Execute := fbPowerB.Status, Position := 1000.0);
fbSelectF(Master := Fwd, Slave := SlaveF, CamTable := CAM_F,
    Execute := fbAtF.Done AND fbPowerSF.Status, Periodic := TRUE, MasterAbsolute := TRUE,
    SlaveAbsolute := TRUE);
fbSelectB(Master := Back, Slave := SlaveB, CamTable := CAM_B,
    Execute := fbAtB.Done AND fbPowerSB.Status, Periodic := TRUE, MasterAbsolute := TRUE,
    SlaveAbsolute := TRUE);
fbCamF(Master := Fwd, Slave := SlaveF, Execute := fbSelectF.Done,
    CamTableID := fbSelectF.CamTableID);
fbCamB(Master := Back, Slave := SlaveB, Execute := fbSelectB.Done,
    CamTableID := fbSelectB.CamTableID);
IF fbCamF.Busy THEN
    iCountF := iCountF + 1;
END_IF
IF fbCamB.Busy THEN
    iCountB := iCountB + 1;
END_IF
(* The cam master coordinate after the coupling's first cycle, the master at rest at 1000. *)
IF iCountF = 2 THEN
    lrStartF := CAM_F.fMasterPosition;
END_IF
IF iCountB = 2 THEN
    lrStartB := CAM_B.fMasterPosition;
END_IF
IF fbCamF.EndOfProfile THEN
    iWrapsF := iWrapsF + 1;
END_IF
IF fbCamB.EndOfProfile THEN
    iWrapsB := iWrapsB + 1;
END_IF
fbMoveF(Axis := Fwd, Execute := iCountF >= 3, Position := {forward:?}, Velocity := 1000.0,
    Acceleration := 20000.0, Deceleration := 20000.0);
fbMoveB(Axis := Back, Execute := iCountB >= 3, Position := {backward:?}, Velocity := 1000.0,
    Acceleration := 20000.0, Deceleration := 20000.0);"
        ),
    );
    add_cam(&dir, "CAM_F", &dwell_cam(period));
    add_cam(&dir, "CAM_B", &dwell_cam(period));
    simulate(
        &dir,
        500,
        &[
            "Fwd.fActPosition",
            "Back.fActPosition",
            "CAM_F.fMasterPosition",
            "CAM_B.fMasterPosition",
            "MotionControl.lrStartF",
            "MotionControl.lrStartB",
            "MotionControl.iWrapsF",
            "MotionControl.iWrapsB",
        ],
    )
}

/// Delta's ActivationMode 2 (axis phase, modulo 400): from 1000 (phase 200) the phase 100
/// comes at 1300 forward or 900 backward. Rivet has no ActivationPosition (CODESYS couples at
/// the Execute edge); the numbers that still apply are those of the phase of an absolute master
/// on a cam of range 400: 200 at 1000, 100 at 1300 (after one wrap) and at 900.
#[test]
fn delta_cam_axis_phase_from_1000_reaches_100_at_1300_or_900() {
    let values = delta_activation(400.0, 1300.0, 900.0);
    // The masters are at rest at each read: the positions are exact.
    assert_near(&values, "MotionControl.lrStartF", 200.0, 1e-9);
    assert_near(&values, "MotionControl.lrStartB", 200.0, 1e-9);
    assert_near(&values, "Fwd.fActPosition", 1300.0, 1e-9);
    assert_near(&values, "Back.fActPosition", 900.0, 1e-9);
    assert_near(&values, "CAM_F.fMasterPosition", 100.0, 1e-9);
    assert_near(&values, "CAM_B.fMasterPosition", 100.0, 1e-9);
    assert_eq!(number(&values, "MotionControl.iWrapsF"), 1.0, "{values:?}");
    assert_eq!(number(&values, "MotionControl.iWrapsB"), 0.0, "{values:?}");
}

/// Delta's ActivationMode 3 (cam phase, range 360): from 1000 (phase 280) the phase 100 comes
/// at 1180 forward or 820 backward; as above, the phase of an absolute master.
#[test]
fn delta_cam_cam_phase_from_1000_reaches_100_at_1180_or_820() {
    let values = delta_activation(360.0, 1180.0, 820.0);
    assert_near(&values, "MotionControl.lrStartF", 280.0, 1e-9);
    assert_near(&values, "MotionControl.lrStartB", 280.0, 1e-9);
    assert_near(&values, "CAM_F.fMasterPosition", 100.0, 1e-9);
    assert_near(&values, "CAM_B.fMasterPosition", 100.0, 1e-9);
    assert_eq!(number(&values, "MotionControl.iWrapsF"), 1.0, "{values:?}");
    assert_eq!(number(&values, "MotionControl.iWrapsB"), 0.0, "{values:?}");
}

/// Delta 5.6: a relative master coupled at 180 is at phase 20 at 200; an absolute master at
/// 500 is at phase 140 (range 360); SlaveOffset +60 maps 180 to 240; MasterOffset +90 makes
/// master 90 command the planned value at 180; SlaveScaling 2 doubles the slave. The cam is the
/// line Y = X over 0..360, so a slave position is the value the cam plans.
#[test]
fn delta_cam_phases_offsets_and_scaling_200_is_20_500_is_140_180_is_240() {
    let dir = project(
        &[
            linear_axis("MRel"),
            linear_axis("M500"),
            linear_axis("M180"),
            linear_axis("M90"),
            linear_axis("SRel"),
            linear_axis("SAbs"),
            linear_axis("SOffset"),
            linear_axis("SScaled"),
            linear_axis("SMaster"),
        ],
        &[
            ("fbP1", "MC_Power"),
            ("fbP2", "MC_Power"),
            ("fbP3", "MC_Power"),
            ("fbP4", "MC_Power"),
            ("fbP5", "MC_Power"),
            ("fbP6", "MC_Power"),
            ("fbP7", "MC_Power"),
            ("fbP8", "MC_Power"),
            ("fbP9", "MC_Power"),
            ("fbAtRel", "MC_SetPosition"),
            ("fbAt500", "MC_SetPosition"),
            ("fbAt180", "MC_SetPosition"),
            ("fbAt90", "MC_SetPosition"),
            ("fbSelRel", "MC_CamTableSelect"),
            ("fbSelAbs", "MC_CamTableSelect"),
            ("fbSelOffset", "MC_CamTableSelect"),
            ("fbSelScaled", "MC_CamTableSelect"),
            ("fbSelMaster", "MC_CamTableSelect"),
            ("fbCamRel", "MC_CamIn"),
            ("fbCamAbs", "MC_CamIn"),
            ("fbCamOffset", "MC_CamIn"),
            ("fbCamScaled", "MC_CamIn"),
            ("fbCamMaster", "MC_CamIn"),
            ("fbMove", "MC_MoveAbsolute"),
        ],
        "fbP1(Axis := MRel, Enable := TRUE);
fbP2(Axis := M500, Enable := TRUE);
fbP3(Axis := M180, Enable := TRUE);
fbP4(Axis := M90, Enable := TRUE);
fbP5(Axis := SRel, Enable := TRUE);
fbP6(Axis := SAbs, Enable := TRUE);
fbP7(Axis := SOffset, Enable := TRUE);
fbP8(Axis := SScaled, Enable := TRUE);
fbP9(Axis := SMaster, Enable := TRUE);
fbAtRel(Axis := MRel, Execute := fbP1.Status, Position := 180.0);
fbAt500(Axis := M500, Execute := fbP2.Status, Position := 500.0);
fbAt180(Axis := M180, Execute := fbP3.Status, Position := 180.0);
fbAt90(Axis := M90, Execute := fbP4.Status, Position := 90.0);
fbSelRel(Master := MRel, Slave := SRel, CamTable := CAM_Line, Execute := fbAtRel.Done AND fbP5.Status,
    Periodic := TRUE, MasterAbsolute := FALSE, SlaveAbsolute := TRUE);
fbSelAbs(Master := M500, Slave := SAbs, CamTable := CAM_Line, Execute := fbAt500.Done AND fbP6.Status,
    Periodic := TRUE, MasterAbsolute := TRUE, SlaveAbsolute := TRUE);
fbSelOffset(Master := M180, Slave := SOffset, CamTable := CAM_Line,
    Execute := fbAt180.Done AND fbP7.Status, Periodic := TRUE, MasterAbsolute := TRUE,
    SlaveAbsolute := TRUE);
fbSelScaled(Master := M180, Slave := SScaled, CamTable := CAM_Line,
    Execute := fbAt180.Done AND fbP8.Status, Periodic := TRUE, MasterAbsolute := TRUE,
    SlaveAbsolute := TRUE);
fbSelMaster(Master := M90, Slave := SMaster, CamTable := CAM_Line,
    Execute := fbAt90.Done AND fbP9.Status, Periodic := TRUE, MasterAbsolute := TRUE,
    SlaveAbsolute := TRUE);
fbCamRel(Master := MRel, Slave := SRel, Execute := fbSelRel.Done, CamTableID := fbSelRel.CamTableID);
fbCamAbs(Master := M500, Slave := SAbs, Execute := fbSelAbs.Done, CamTableID := fbSelAbs.CamTableID);
fbCamOffset(Master := M180, Slave := SOffset, Execute := fbSelOffset.Done,
    CamTableID := fbSelOffset.CamTableID, SlaveOffset := 60.0);
fbCamScaled(Master := M180, Slave := SScaled, Execute := fbSelScaled.Done,
    CamTableID := fbSelScaled.CamTableID, SlaveScaling := 2.0);
fbCamMaster(Master := M90, Slave := SMaster, Execute := fbSelMaster.Done,
    CamTableID := fbSelMaster.CamTableID, MasterOffset := 90.0);
(* From the cycle after the coupling: the coupling cycle's master position is phase 0. *)
fbMove(Axis := MRel, Execute := fbCamRel.InSync, Position := 200.0, Velocity := 100.0,
    Acceleration := 20000.0, Deceleration := 20000.0);",
    );
    add_cam(
        &dir,
        "CAM_Line",
        &cam(1.0, &[("line", 360.0, 360.0, 1.0)], ""),
    );
    let values = simulate(
        &dir,
        300,
        &[
            "MRel.fActPosition",
            "SRel.fActPosition",
            "SAbs.fActPosition",
            "SOffset.fActPosition",
            "SScaled.fActPosition",
            "SMaster.fActPosition",
        ],
    );
    // Every master is at rest at the read: the cam is evaluated exactly.
    assert_near(&values, "MRel.fActPosition", 200.0, 1e-9);
    assert_near(&values, "SRel.fActPosition", 20.0, 1e-9);
    assert_near(&values, "SAbs.fActPosition", 140.0, 1e-9);
    assert_near(&values, "SOffset.fActPosition", 240.0, 1e-9);
    assert_near(&values, "SScaled.fActPosition", 360.0, 1e-9);
    assert_near(&values, "SMaster.fActPosition", 180.0, 1e-9);
}

/// Delta 5.6 StartMode: the master at phase 80 needs the slave at 40; the slave stands at 180
/// (modulo 360) → shortest ends at 40 going back 140, positive at 400 (40 after the wrap, +220),
/// negative at 40 (−140). Rivet's ramp_in, ramp_in_pos and ramp_in_neg on a modulo slave.
#[test]
fn delta_cam_start_mode_slave_at_180_to_40_shortest_400_positive_40_negative() {
    let slaves = ["Shortest", "Positive", "Negative"];
    let modes = ["ramp_in", "ramp_in_pos", "ramp_in_neg"];
    let mut axes = vec![modulo_axis("Drum", 360.0)];
    let mut variables = vec![
        ("fbPowerDrum".to_string(), "MC_Power"),
        ("fbAtDrum".to_string(), "MC_SetPosition"),
    ];
    let mut body = String::from(
        "fbPowerDrum(Axis := Drum, Enable := TRUE);
fbAtDrum(Axis := Drum, Execute := fbPowerDrum.Status, Position := 80.0);
",
    );
    for (slave, mode) in slaves.iter().zip(modes) {
        axes.push(modulo_axis(slave, 360.0));
        for (prefix, ty) in [
            ("fbPower", "MC_Power"),
            ("fbAt", "MC_SetPosition"),
            ("fbSelect", "MC_CamTableSelect"),
            ("fbCam", "MC_CamIn"),
            ("xTrack", "BOOL"),
            ("lrLast", "LREAL"),
            ("lrStep", "LREAL"),
            ("lrTravel", "LREAL"),
        ] {
            variables.push((format!("{prefix}{slave}"), ty));
        }
        body.push_str(&format!(
            "fbPower{slave}(Axis := {slave}, Enable := TRUE);
fbAt{slave}(Axis := {slave}, Execute := fbPower{slave}.Status, Position := 180.0);
fbSelect{slave}(Master := Drum, Slave := {slave}, CamTable := CAM_Half,
    Execute := fbAt{slave}.Done AND fbAtDrum.Done, Periodic := TRUE, MasterAbsolute := TRUE,
    SlaveAbsolute := TRUE);
fbCam{slave}(Master := Drum, Slave := {slave}, Execute := fbSelect{slave}.Done,
    CamTableID := fbSelect{slave}.CamTableID, StartMode := MC_StartMode.{mode},
    VelocityDiff := 500.0, Acceleration := 5000.0, Deceleration := 5000.0);
(* The travel from the 180 the slave was set to (MC_SetPosition is done at its call, the
   position shows after the cycle). *)
IF xTrack{slave} THEN
    lrStep{slave} := {slave}.fSetPosition - lrLast{slave};
    IF lrStep{slave} > 180.0 THEN
        lrStep{slave} := lrStep{slave} - 360.0;
    ELSIF lrStep{slave} < -180.0 THEN
        lrStep{slave} := lrStep{slave} + 360.0;
    END_IF
    lrTravel{slave} := lrTravel{slave} + lrStep{slave};
    lrLast{slave} := {slave}.fSetPosition;
ELSIF fbAt{slave}.Done THEN
    lrLast{slave} := 180.0;
    xTrack{slave} := TRUE;
END_IF
"
        ));
    }
    let variables: Vec<(&str, &str)> = variables
        .iter()
        .map(|(name, ty)| (name.as_str(), *ty))
        .collect();
    let dir = project(&axes, &variables, &body);
    // Y = X / 2 over 0..360: phase 80 plans 40.
    add_cam(
        &dir,
        "CAM_Half",
        &cam(0.5, &[("line", 360.0, 180.0, 0.5)], ""),
    );
    let mut watch = Vec::new();
    for slave in slaves {
        watch.push(format!("{slave}.fActPosition"));
        watch.push(format!("MotionControl.lrTravel{slave}"));
        watch.push(format!("MotionControl.fbCam{slave}.InSync"));
    }
    let watch: Vec<&str> = watch.iter().map(String::as_str).collect();
    // 1 s: 220 at 500/s with 5000/s² ramps takes under 0.6 s.
    let values = simulate(&dir, 500, &watch);
    // Delta's end positions unwrapped from 180: 40 (−140), 400 (+220), 40 (−140).
    for (slave, end) in slaves.iter().zip([40.0, 400.0, 40.0]) {
        assert!(
            boolean(&values, &format!("MotionControl.fbCam{slave}.InSync")),
            "{values:?}"
        );
        // The master stands still: the ramp ends exactly on the cam.
        assert_near(&values, &format!("{slave}.fActPosition"), 40.0, 1e-6);
        assert_near(
            &values,
            &format!("MotionControl.lrTravel{slave}"),
            end - 180.0,
            1e-6,
        );
    }
}

/// Delta 5.6 MC_CamIn/MC_CamOut worked example: cam (0,0), (90,100), (180,300), (360,0) with
/// zero velocity at each point (Poly5 here: Delta does not name its curve), period 360, master
/// and slave relative, periodic, coupled when the master is at 100 (Delta: ActivationPosition
/// 100 with ActivationMode 0 from 0; here the program couples once a move to 100 is done), the
/// master then turning at 180 u/s. EndOfProfile pulses at the end of each period (master 460,
/// 820); the slave reaches 100 and 300 above its start; MC_CamOut leaves it at its velocity.
#[test]
fn delta_cam_in_and_cam_out_example_coupled_at_master_100() {
    let dir = project(
        &[linear_axis("Roller"), linear_axis("Pusher")],
        &[
            ("fbPowerRoller", "MC_Power"),
            ("fbPowerPusher", "MC_Power"),
            ("fbTo100", "MC_MoveAbsolute"),
            ("fbSelect", "MC_CamTableSelect"),
            ("fbCam", "MC_CamIn"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbOut", "MC_CamOut"),
            ("iEnds", "INT"),
            ("lrFirstEnd", "LREAL"),
            ("lrSecondEnd", "LREAL"),
            ("lrPeak", "LREAL"),
            ("lrAt190", "LREAL"),
            ("lrOutVelocity", "LREAL"),
            ("iEndsAtOut", "INT"),
        ],
        "fbPowerRoller(Axis := Roller, Enable := TRUE);
fbPowerPusher(Axis := Pusher, Enable := TRUE);
fbTo100(Axis := Roller, Execute := fbPowerRoller.Status, Position := 100.0, Velocity := 1000.0,
    Acceleration := 20000.0, Deceleration := 20000.0);
fbSelect(Master := Roller, Slave := Pusher, CamTable := CAM_Delta,
    Execute := fbTo100.Done AND fbPowerPusher.Status, Periodic := TRUE, MasterAbsolute := FALSE,
    SlaveAbsolute := FALSE);
fbCam(Master := Roller, Slave := Pusher, Execute := fbSelect.Done,
    CamTableID := fbSelect.CamTableID);
fbTurn(Axis := Roller, Execute := fbCam.Busy, Velocity := 180.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
IF fbCam.EndOfProfile THEN
    iEnds := iEnds + 1;
    IF iEnds = 1 THEN
        lrFirstEnd := Roller.fSetPosition;
    ELSIF iEnds = 2 THEN
        lrSecondEnd := Roller.fSetPosition;
    END_IF
END_IF
IF iEnds = 0 THEN
    lrPeak := MAX(lrPeak, Pusher.fSetPosition);
    IF lrAt190 = 0.0 AND Roller.fSetPosition >= 190.0 THEN
        lrAt190 := Pusher.fSetPosition;
    END_IF
END_IF
(* Phase 45 of the third period: the slave moves at its fastest there. *)
IF NOT fbOut.Execute AND Roller.fSetPosition >= 865.0 THEN
    lrOutVelocity := Pusher.fSetVelocity;
    iEndsAtOut := iEnds;
END_IF
fbOut(Slave := Pusher, Execute := Roller.fSetPosition >= 865.0);",
    );
    add_cam(
        &dir,
        "CAM_Delta",
        &cam(
            0.0,
            &[
                ("poly5", 90.0, 100.0, 0.0),
                ("poly5", 180.0, 300.0, 0.0),
                ("poly5", 360.0, 0.0, 0.0),
            ],
            "",
        ),
    );
    // 5.6 s: 0.2 s to reach 100, 4.25 s from 100 to 865 at 180 u/s, then 1 s decoupled.
    let values = simulate(
        &dir,
        2800,
        &[
            "MotionControl.iEnds",
            "MotionControl.lrFirstEnd",
            "MotionControl.lrSecondEnd",
            "MotionControl.lrPeak",
            "MotionControl.lrAt190",
            "MotionControl.lrOutVelocity",
            "MotionControl.iEndsAtOut",
            "MotionControl.fbOut.Done",
            "Pusher.fSetVelocity",
            "Pusher.nAxisState",
        ],
    );
    // The pulse is read at the call after the wrap: the master is at most one cycle
    // (180 u/s · 2 ms = 0.36) past the period end.
    let first = number(&values, "MotionControl.lrFirstEnd");
    assert!((460.0..460.37).contains(&first), "{values:?}");
    let second = number(&values, "MotionControl.lrSecondEnd");
    assert!((820.0..820.37).contains(&second), "{values:?}");
    assert_eq!(
        number(&values, "MotionControl.iEndsAtOut"),
        2.0,
        "{values:?}"
    );
    // Poly5 has zero slope and curvature at its key points: a sample up to 0.18 off 180 is
    // within (0.18/90)³·(a few hundred) of the peak, about 1e-5.
    assert_near(&values, "MotionControl.lrPeak", 300.0, 1e-4);
    // Master 190 (phase 90) is read within 0.36 past it, on the flat top of the first rise.
    assert_near(&values, "MotionControl.lrAt190", 100.0, 1e-3);
    assert!(boolean(&values, "MotionControl.fbOut.Done"), "{values:?}");
    // Decoupled at phase 45: the rise 0..100 over 90 at its steepest, 1.875·100/90·180 u/s;
    // the slave keeps it (within the change of one cycle, where the acceleration is ~0).
    let out = number(&values, "MotionControl.lrOutVelocity");
    assert!((out - 375.0).abs() < 1.0, "{values:?}");
    assert_near(&values, "Pusher.fSetVelocity", out, 1.0);
    // SMC_AXIS_STATE.continuous_motion.
    assert_eq!(number(&values, "Pusher.nAxisState"), 5.0, "{values:?}");
}

/// Delta 5.7 tappet example: tappets (50, set), (100, disable), (180, reset), (300, invert),
/// each its own status (a track each in Rivet); master forward: status 1 TRUE at 50, 2 and 3
/// stay FALSE, 4 TRUE at 300. Delta also clears every status at the cam end: Rivet (CODESYS)
/// does not, so the test stops before the end.
#[test]
fn delta_tappets_set_at_50_and_invert_at_300_disable_and_reset_stay_false() {
    let dir = project(
        &[modulo_axis("Drum", 360.0)],
        &[
            ("fbPower", "MC_Power"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbRegister", "SMC_CamRegister"),
            ("aTappets", "ARRAY[1..512] OF BOOL"),
            ("lrOn1", "LREAL"),
            ("lrOn4", "LREAL"),
            ("xSeen2", "BOOL"),
            ("xSeen3", "BOOL"),
        ],
        "fbPower(Axis := Drum, Enable := TRUE);
fbTurn(Axis := Drum, Execute := fbPower.Status, Velocity := 100.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
fbRegister(Master := Drum, CamTable := CAM_Tappets, bTappet := aTappets, Enable := TRUE);
IF aTappets[1] AND lrOn1 = 0.0 THEN
    lrOn1 := Drum.fSetPosition;
END_IF
IF aTappets[4] AND lrOn4 = 0.0 THEN
    lrOn4 := Drum.fSetPosition;
END_IF
xSeen2 := xSeen2 OR aTappets[2];
xSeen3 := xSeen3 OR aTappets[3];",
    );
    let tappet = |id: u32, position: f64, action: &str| {
        format!(
            "
[[track]]
id = {id}

[[track.tappet]]
position = {position:?}
on_positive = \"{action}\"
on_negative = \"none\"
"
        )
    };
    let tracks = [
        tappet(1, 50.0, "on"),
        tappet(2, 100.0, "none"),
        tappet(3, 180.0, "off"),
        tappet(4, 300.0, "invert"),
    ]
    .concat();
    add_cam(
        &dir,
        "CAM_Tappets",
        &cam(1.0, &[("line", 360.0, 360.0, 1.0)], &tracks),
    );
    // 3.4 s at 100 u/s: the drum ends near 340, before the cam end.
    let values = simulate(
        &dir,
        1700,
        &[
            "Drum.fActPosition",
            "MotionControl.lrOn1",
            "MotionControl.lrOn4",
            "MotionControl.xSeen2",
            "MotionControl.xSeen3",
            "MotionControl.aTappets[1]",
            "MotionControl.aTappets[4]",
        ],
    );
    assert!(number(&values, "Drum.fActPosition") > 300.5, "{values:?}");
    assert!(number(&values, "Drum.fActPosition") < 360.0, "{values:?}");
    // Read at the call after the switching cycle: at most one cycle (0.2) past the tappet.
    let on1 = number(&values, "MotionControl.lrOn1");
    assert!((50.0..50.25).contains(&on1), "{values:?}");
    let on4 = number(&values, "MotionControl.lrOn4");
    assert!((300.0..300.25).contains(&on4), "{values:?}");
    assert!(!boolean(&values, "MotionControl.xSeen2"), "{values:?}");
    assert!(!boolean(&values, "MotionControl.xSeen3"), "{values:?}");
    assert!(boolean(&values, "MotionControl.aTappets[1]"), "{values:?}");
    assert!(boolean(&values, "MotionControl.aTappets[4]"), "{values:?}");
}

/// Delta 5.4 MC_MoveRelative: 2000 + 5000 → 7000; the same move aborted at 4500 by +9000 →
/// 13500 (the second distance counts from the position at the abort).
#[test]
fn delta_move_relative_2000_plus_5000_is_7000_and_aborted_at_4500_by_9000_is_13500() {
    let dir = project(
        &[linear_axis("Plain"), linear_axis("Aborted")],
        &[
            ("fbPowerP", "MC_Power"),
            ("fbPowerA", "MC_Power"),
            ("fbAtP", "MC_SetPosition"),
            ("fbAtA", "MC_SetPosition"),
            ("fbMoveP", "MC_MoveRelative"),
            ("fbMoveA", "MC_MoveRelative"),
            ("fbAgainA", "MC_MoveRelative"),
            ("xTrigger", "BOOL"),
            ("lrTrigger", "LREAL"),
        ],
        "fbPowerP(Axis := Plain, Enable := TRUE);
fbPowerA(Axis := Aborted, Enable := TRUE);
fbAtP(Axis := Plain, Execute := fbPowerP.Status, Position := 2000.0);
fbAtA(Axis := Aborted, Execute := fbPowerA.Status, Position := 2000.0);
fbMoveP(Axis := Plain, Execute := fbAtP.Done, Distance := 5000.0, Velocity := 1000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);
fbMoveA(Axis := Aborted, Execute := fbAtA.Done, Distance := 5000.0, Velocity := 1000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);
IF NOT xTrigger AND Aborted.fSetPosition >= 4500.0 THEN
    xTrigger := TRUE;
    lrTrigger := Aborted.fSetPosition;
END_IF
fbAgainA(Axis := Aborted, Execute := xTrigger, Distance := 9000.0, Velocity := 1000.0,
    Acceleration := 10000.0, Deceleration := 10000.0);",
    );
    // 11500 units at 1000 u/s: 11.6 s; 13 s of cycles.
    let values = simulate(
        &dir,
        6500,
        &[
            "Plain.fActPosition",
            "Aborted.fActPosition",
            "MotionControl.lrTrigger",
            "MotionControl.fbMoveA.CommandAborted",
            "MotionControl.fbAgainA.Done",
        ],
    );
    assert_near(&values, "Plain.fActPosition", 7000.0, 1e-6);
    // The abort is the first 2 ms cycle at or past 4500 (1000 u/s: 2 units a cycle).
    let trigger = number(&values, "MotionControl.lrTrigger");
    assert!((4500.0..4502.1).contains(&trigger), "{values:?}");
    assert_near(&values, "Aborted.fActPosition", trigger + 9000.0, 1e-6);
    assert!(boolean(&values, "MotionControl.fbMoveA.CommandAborted"));
    assert!(boolean(&values, "MotionControl.fbAgainA.Done"));
}

/// Delta 5.4 MC_MoveAbsolute on a modulo 360 axis from 315 to 90: positive 135, negative 225,
/// shortest 135; 315 → 270 shortest 45 (back).
#[test]
fn delta_move_absolute_modulo_315_to_90_positive_135_negative_225_shortest_135() {
    let cases = [
        ("Positive", 90.0, "positive", 135.0),
        ("Negative", 90.0, "negative", -225.0),
        ("Shortest", 90.0, "shortest", 135.0),
        ("Back", 270.0, "shortest", -45.0),
    ];
    let mut axes = Vec::new();
    let mut variables = Vec::new();
    let mut body = String::new();
    for (axis, target, direction, _) in cases {
        axes.push(modulo_axis(axis, 360.0));
        for (prefix, ty) in [
            ("fbPower", "MC_Power"),
            ("fbAt", "MC_SetPosition"),
            ("fbMove", "MC_MoveAbsolute"),
            ("xTrack", "BOOL"),
            ("lrLast", "LREAL"),
            ("lrStep", "LREAL"),
            ("lrTravel", "LREAL"),
        ] {
            variables.push((format!("{prefix}{axis}"), ty));
        }
        body.push_str(&format!(
            "fbPower{axis}(Axis := {axis}, Enable := TRUE);
fbAt{axis}(Axis := {axis}, Execute := fbPower{axis}.Status, Position := 315.0);
fbMove{axis}(Axis := {axis}, Execute := fbAt{axis}.Done, Position := {target:?}, Velocity := 360.0,
    Acceleration := 3600.0, Deceleration := 3600.0, Direction := MC_DIRECTION.{direction});
(* The travel from the 315 the axis was set to (MC_SetPosition is done at its call, the
   position shows after the cycle). *)
IF xTrack{axis} THEN
    lrStep{axis} := {axis}.fSetPosition - lrLast{axis};
    IF lrStep{axis} > 180.0 THEN
        lrStep{axis} := lrStep{axis} - 360.0;
    ELSIF lrStep{axis} < -180.0 THEN
        lrStep{axis} := lrStep{axis} + 360.0;
    END_IF
    lrTravel{axis} := lrTravel{axis} + lrStep{axis};
    lrLast{axis} := {axis}.fSetPosition;
ELSIF fbAt{axis}.Done THEN
    lrLast{axis} := 315.0;
    xTrack{axis} := TRUE;
END_IF
"
        ));
    }
    let variables: Vec<(&str, &str)> = variables
        .iter()
        .map(|(name, ty)| (name.as_str(), *ty))
        .collect();
    let dir = project(&axes, &variables, &body);
    let mut watch = Vec::new();
    for (axis, ..) in cases {
        watch.push(format!("{axis}.fActPosition"));
        watch.push(format!("MotionControl.lrTravel{axis}"));
    }
    let watch: Vec<&str> = watch.iter().map(String::as_str).collect();
    // 225 at 360 u/s with 3600 u/s² ramps: 0.73 s; 1.2 s of cycles.
    let values = simulate(&dir, 600, &watch);
    for (axis, target, _, travel) in cases {
        assert_near(&values, &format!("{axis}.fActPosition"), target, 1e-6);
        assert_near(
            &values,
            &format!("MotionControl.lrTravel{axis}"),
            travel,
            1e-6,
        );
    }
}

/// Delta 5.1 S-curve: MC_MoveRelative 1,300,000 at V 100,000, A = D 20,000, J 10,000 →
/// jerk up 0–2 s, constant acceleration 2–5 s, jerk down 5–7 s (100,000 reached, 350,000
/// covered), cruise 7–13 s, mirrored deceleration to 20 s.
#[test]
fn delta_s_curve_move_relative_1300000_takes_20_s() {
    let axis = linear_axis("Gantry").replace(
        "velocity = 5000.0, acceleration = 20000.0, deceleration = 20000.0",
        "velocity = 200000.0, acceleration = 100000.0, deceleration = 100000.0",
    );
    let dir = project(
        &[axis],
        &[
            ("fbPower", "MC_Power"),
            ("fbMove", "MC_MoveRelative"),
            ("iCycle", "DINT"),
            ("iStart", "DINT"),
            ("iDone", "DINT"),
            ("lrV2", "LREAL"),
            ("lrV7", "LREAL"),
            ("lrP7", "LREAL"),
            ("lrP13", "LREAL"),
        ],
        "iCycle := iCycle + 1;
fbPower(Axis := Gantry, Enable := TRUE);
fbMove(Axis := Gantry, Execute := fbPower.Status, Distance := 1300000.0, Velocity := 100000.0,
    Acceleration := 20000.0, Deceleration := 20000.0, Jerk := 10000.0);
IF fbMove.Busy AND iStart = 0 THEN
    iStart := iCycle;
END_IF
(* A read n cycles after the start sees n advances of 2 ms. *)
IF iStart > 0 THEN
    IF iCycle - iStart = 1000 THEN
        lrV2 := Gantry.fSetVelocity;
    ELSIF iCycle - iStart = 3500 THEN
        lrV7 := Gantry.fSetVelocity;
        lrP7 := Gantry.fSetPosition;
    ELSIF iCycle - iStart = 6500 THEN
        lrP13 := Gantry.fSetPosition;
    END_IF
END_IF
IF fbMove.Done AND iDone = 0 THEN
    iDone := iCycle;
END_IF",
    );
    let values = simulate(
        &dir,
        10_100,
        &[
            "Gantry.fActPosition",
            "MotionControl.iStart",
            "MotionControl.iDone",
            "MotionControl.lrV2",
            "MotionControl.lrV7",
            "MotionControl.lrP7",
            "MotionControl.lrP13",
        ],
    );
    // The phase ends fall on whole 2 ms cycles: the samples are the profile's own values.
    assert_near(&values, "MotionControl.lrV2", 20000.0, 1e-3);
    assert_near(&values, "MotionControl.lrV7", 100000.0, 1e-3);
    assert_near(&values, "MotionControl.lrP7", 350000.0, 1e-3);
    assert_near(&values, "MotionControl.lrP13", 950000.0, 1e-3);
    assert_near(&values, "Gantry.fActPosition", 1300000.0, 1e-6);
    // 20 s are 10000 advances; Done shows at the call after the last one.
    let duration = number(&values, "MotionControl.iDone") - number(&values, "MotionControl.iStart");
    assert!((10000.0..=10001.0).contains(&duration), "{values:?}");
}

/// Delta 5.2 blending: a MoveRelative at 300 u/s followed by one at 500 u/s passes the first
/// target at 300 (BlendingLow, BlendingPrevious) or 500 (BlendingNext, BlendingHigh).
#[test]
fn delta_blending_300_then_500_passes_at_300_low_previous_and_500_next_high() {
    let cases = [
        ("Low", "BlendingLow", 300.0),
        ("Previous", "BlendingPrevious", 300.0),
        ("Next", "BlendingNext", 500.0),
        ("High", "BlendingHigh", 500.0),
    ];
    let mut axes = Vec::new();
    let mut variables = Vec::new();
    let mut body = String::new();
    for (axis, mode, _) in cases {
        axes.push(linear_axis(axis));
        for (prefix, ty) in [
            ("fbPower", "MC_Power"),
            ("fbFirst", "MC_MoveRelative"),
            ("fbSecond", "MC_MoveRelative"),
            ("lrBefore", "LREAL"),
            ("lrMin", "LREAL"),
        ] {
            variables.push((format!("{prefix}{axis}"), ty));
        }
        body.push_str(&format!(
            "fbPower{axis}(Axis := {axis}, Enable := TRUE);
fbFirst{axis}(Axis := {axis}, Execute := fbPower{axis}.Status, Distance := 1000.0, Velocity := 300.0,
    Acceleration := 10000.0, Deceleration := 10000.0);
fbSecond{axis}(Axis := {axis}, Execute := fbFirst{axis}.Busy, Distance := 1000.0, Velocity := 500.0,
    Acceleration := 10000.0, Deceleration := 10000.0, BufferMode := MC_BUFFER_MODE.{mode});
(* The velocity of the last cycle before the first target, and the lowest after the start. *)
IF {axis}.fSetPosition < 1000.0 THEN
    lrBefore{axis} := {axis}.fSetVelocity;
END_IF
IF {axis}.fSetPosition > 100.0 AND {axis}.fSetPosition < 1900.0 THEN
    IF lrMin{axis} = 0.0 OR {axis}.fSetVelocity < lrMin{axis} THEN
        lrMin{axis} := {axis}.fSetVelocity;
    END_IF
END_IF
"
        ));
    }
    let variables: Vec<(&str, &str)> = variables
        .iter()
        .map(|(name, ty)| (name.as_str(), *ty))
        .collect();
    let dir = project(&axes, &variables, &body);
    let mut watch = Vec::new();
    for (axis, ..) in cases {
        watch.push(format!("{axis}.fActPosition"));
        watch.push(format!("MotionControl.lrBefore{axis}"));
        watch.push(format!("MotionControl.lrMin{axis}"));
    }
    let watch: Vec<&str> = watch.iter().map(String::as_str).collect();
    // 2000 units at 300..500 u/s: at most 6.7 s; 8 s of cycles.
    let values = simulate(&dir, 4000, &watch);
    for (axis, _, transit) in cases {
        assert_near(&values, &format!("{axis}.fActPosition"), 2000.0, 1e-6);
        // Within one cycle of 10000 u/s² (20 u/s) of the transit velocity at the first target.
        assert_near(
            &values,
            &format!("MotionControl.lrBefore{axis}"),
            transit,
            20.5,
        );
        // No stop at the boundary.
        assert!(
            number(&values, &format!("MotionControl.lrMin{axis}")) >= 299.0,
            "{axis}: {values:?}"
        );
    }
}

/// Omron 7A.3: with StartPosition 60 on a rotary 0..360 master, the cam phases 0/60/180/300
/// are at master 60/120/240/0. In Rivet (CODESYS) StartPosition is `MasterOffset` −60 on an
/// absolute master (X = M − 60).
#[test]
fn omron_cam_start_position_60_puts_phase_0_at_master_60() {
    let dir = project(
        &[modulo_axis("Wheel", 360.0), linear_axis("Arm")],
        &[
            ("fbPowerWheel", "MC_Power"),
            ("fbPowerArm", "MC_Power"),
            ("fbSelect", "MC_CamTableSelect"),
            ("fbCam", "MC_CamIn"),
            ("fbTo60", "MC_MoveAbsolute"),
            ("fbTo120", "MC_MoveAbsolute"),
            ("fbTo240", "MC_MoveAbsolute"),
            ("iCoupled", "INT"),
            ("lrAt0", "LREAL"),
            ("lrAt60", "LREAL"),
            ("lrAt120", "LREAL"),
        ],
        "fbPowerWheel(Axis := Wheel, Enable := TRUE);
fbPowerArm(Axis := Arm, Enable := TRUE);
fbSelect(Master := Wheel, Slave := Arm, CamTable := CAM_Dwell,
    Execute := fbPowerWheel.Status AND fbPowerArm.Status, Periodic := TRUE,
    MasterAbsolute := TRUE, SlaveAbsolute := TRUE);
fbCam(Master := Wheel, Slave := Arm, Execute := fbSelect.Done, CamTableID := fbSelect.CamTableID,
    MasterOffset := -60.0);
IF fbCam.Busy THEN
    iCoupled := iCoupled + 1;
END_IF
IF iCoupled = 2 THEN
    lrAt0 := CAM_Dwell.fMasterPosition;
END_IF
fbTo60(Axis := Wheel, Execute := iCoupled >= 3, Position := 60.0, Velocity := 360.0,
    Acceleration := 20000.0, Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
(* Each read is at the first call that sees the move done, before the next move starts. *)
IF fbTo60.Done AND NOT fbTo120.Busy AND NOT fbTo120.Done THEN
    lrAt60 := CAM_Dwell.fMasterPosition;
END_IF
fbTo120(Axis := Wheel, Execute := fbTo60.Done, Position := 120.0, Velocity := 360.0,
    Acceleration := 20000.0, Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
IF fbTo120.Done AND NOT fbTo240.Busy AND NOT fbTo240.Done THEN
    lrAt120 := CAM_Dwell.fMasterPosition;
END_IF
fbTo240(Axis := Wheel, Execute := fbTo120.Done, Position := 240.0, Velocity := 360.0,
    Acceleration := 20000.0, Deceleration := 20000.0, Direction := MC_DIRECTION.positive);",
    );
    add_cam(&dir, "CAM_Dwell", &dwell_cam(360.0));
    let values = simulate(
        &dir,
        600,
        &[
            "Wheel.fActPosition",
            "CAM_Dwell.fMasterPosition",
            "MotionControl.lrAt0",
            "MotionControl.lrAt60",
            "MotionControl.lrAt120",
        ],
    );
    // The wheel is at rest at each read: exact, but phase 0 may read as 0 or as 360 − ε.
    assert_near(&values, "MotionControl.lrAt0", 300.0, 1e-9);
    let at60 = number(&values, "MotionControl.lrAt60");
    assert!(
        at60.abs() < 1e-9 || (at60 - 360.0).abs() < 1e-9,
        "{values:?}"
    );
    assert_near(&values, "MotionControl.lrAt120", 60.0, 1e-9);
    assert_near(&values, "Wheel.fActPosition", 240.0, 1e-9);
    assert_near(&values, "CAM_Dwell.fMasterPosition", 180.0, 1e-9);
}

/// PLCopen digest T2: a non-periodic cam (the CODESYS default cam, Y(360) = 360): once the
/// master passed 360 `EndOfProfile` stays TRUE and the slave holds Y(360); `Execute` FALSE
/// resets `EndOfProfile`.
#[test]
fn plcopen_t2_non_periodic_cam_end_of_profile_stays_true_and_the_slave_holds_360() {
    let dir = project(
        &[linear_axis("Feed"), linear_axis("Lift")],
        &[
            ("fbPowerFeed", "MC_Power"),
            ("fbPowerLift", "MC_Power"),
            ("fbSelect", "MC_CamTableSelect"),
            ("fbCam", "MC_CamIn"),
            ("fbTurn", "MC_MoveVelocity"),
            ("iCycle", "INT"),
            ("iEndCycles", "INT"),
            ("lrFirstEnd", "LREAL"),
            ("xEndBeforeRelease", "BOOL"),
            ("lrHeld", "LREAL"),
        ],
        "iCycle := iCycle + 1;
fbPowerFeed(Axis := Feed, Enable := TRUE);
fbPowerLift(Axis := Lift, Enable := TRUE);
fbSelect(Master := Feed, Slave := Lift, CamTable := CAM_Default,
    Execute := fbPowerFeed.Status AND fbPowerLift.Status, Periodic := FALSE,
    MasterAbsolute := TRUE, SlaveAbsolute := TRUE);
fbCam(Master := Feed, Slave := Lift, Execute := fbSelect.Done AND iCycle < 1500,
    CamTableID := fbSelect.CamTableID);
fbTurn(Axis := Feed, Execute := fbCam.Busy, Velocity := 360.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
IF fbCam.EndOfProfile THEN
    iEndCycles := iEndCycles + 1;
    IF iEndCycles = 1 THEN
        lrFirstEnd := Feed.fSetPosition;
    END_IF
END_IF
IF iCycle = 1499 THEN
    xEndBeforeRelease := fbCam.EndOfProfile;
    lrHeld := Lift.fSetPosition;
END_IF",
    );
    add_cam(&dir, "CAM_Default", &codesys_default_cam());
    // 3.2 s; the master passes 360 at about 1 s, Execute falls at cycle 1500 (3 s).
    let values = simulate(
        &dir,
        1600,
        &[
            "Feed.fActPosition",
            "Lift.fActPosition",
            "Lift.fSetVelocity",
            "MotionControl.iEndCycles",
            "MotionControl.lrFirstEnd",
            "MotionControl.xEndBeforeRelease",
            "MotionControl.lrHeld",
            "MotionControl.fbCam.EndOfProfile",
        ],
    );
    // Read at the call after the cycle that passed 360: at most 0.72 (360 u/s · 2 ms) past.
    let first = number(&values, "MotionControl.lrFirstEnd");
    assert!((360.0..360.73).contains(&first), "{values:?}");
    // TRUE at every call from then on until Execute fell: about 2 s of cycles, not a pulse.
    let ends = number(&values, "MotionControl.iEndCycles");
    assert!((950.0..1000.0).contains(&ends), "{values:?}");
    assert!(
        boolean(&values, "MotionControl.xEndBeforeRelease"),
        "{values:?}"
    );
    assert!(
        !boolean(&values, "MotionControl.fbCam.EndOfProfile"),
        "{values:?}"
    );
    assert!(number(&values, "Feed.fActPosition") > 1000.0, "{values:?}");
    assert_near(&values, "MotionControl.lrHeld", 360.0, 1e-9);
    assert_near(&values, "Lift.fActPosition", 360.0, 1e-9);
    assert_near(&values, "Lift.fSetVelocity", 0.0, 1e-9);
}

/// PLCopen digest T7: SMC_GetCamSlaveSetPosition on the CODESYS default cam with
/// MasterOffset 100: fStartPosition = CAM(100) = 98.3796296…, fStartVelocity =
/// 1.2152778·master velocity; MC_CamIn's first command in absolute mode at master 0 with
/// MasterOffset 100 is the same position.
#[test]
fn plcopen_t7_get_cam_slave_set_position_with_master_offset_100_is_98_3796() {
    let dir = project(
        &[
            linear_axis("Feed"),
            linear_axis("Lift"),
            linear_axis("Probe"),
        ],
        &[
            ("fbPowerFeed", "MC_Power"),
            ("fbPowerLift", "MC_Power"),
            ("fbPowerProbe", "MC_Power"),
            ("fbSelectAbs", "MC_CamTableSelect"),
            ("fbSelectRel", "MC_CamTableSelect"),
            ("fbAtRest", "SMC_GetCamSlaveSetPosition"),
            ("fbMoving", "SMC_GetCamSlaveSetPosition"),
            ("fbCam", "MC_CamIn"),
            ("fbTurn", "MC_MoveVelocity"),
            ("iCoupled", "INT"),
            ("lrRestPosition", "LREAL"),
            ("lrRestVelocity", "LREAL"),
            ("lrFirstCommand", "LREAL"),
        ],
        "fbPowerFeed(Axis := Feed, Enable := TRUE);
fbPowerLift(Axis := Lift, Enable := TRUE);
fbPowerProbe(Axis := Probe, Enable := TRUE);
fbSelectAbs(Master := Feed, Slave := Lift, CamTable := CAM_Default,
    Execute := fbPowerFeed.Status AND fbPowerLift.Status, Periodic := TRUE,
    MasterAbsolute := TRUE, SlaveAbsolute := TRUE);
(* MasterAbsolute FALSE: X = 0 + MasterOffset wherever the master is, at its velocity. *)
fbSelectRel(Master := Feed, Slave := Probe, CamTable := CAM_Default,
    Execute := fbPowerFeed.Status AND fbPowerProbe.Status, Periodic := TRUE,
    MasterAbsolute := FALSE, SlaveAbsolute := TRUE);
fbAtRest(Master := Feed, Slave := Lift, Enable := fbSelectAbs.Done, MasterOffset := 100.0,
    CamTableID := fbSelectAbs.CamTableID);
fbMoving(Master := Feed, Slave := Probe, Enable := fbSelectRel.Done, MasterOffset := 100.0,
    CamTableID := fbSelectRel.CamTableID);
fbCam(Master := Feed, Slave := Lift, Execute := fbSelectAbs.Done,
    CamTableID := fbSelectAbs.CamTableID, MasterOffset := 100.0);
IF fbCam.Busy THEN
    iCoupled := iCoupled + 1;
END_IF
(* After the coupling's first cycle, with the master still at rest at 0. *)
IF iCoupled = 2 THEN
    lrRestPosition := fbAtRest.fStartPosition;
    lrRestVelocity := fbAtRest.fStartVelocity;
    lrFirstCommand := Lift.fSetPosition;
END_IF
fbTurn(Axis := Feed, Execute := iCoupled >= 3, Velocity := 50.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);",
    );
    add_cam(&dir, "CAM_Default", &codesys_default_cam());
    let values = simulate(
        &dir,
        300,
        &[
            "Feed.fSetVelocity",
            "MotionControl.lrRestPosition",
            "MotionControl.lrRestVelocity",
            "MotionControl.lrFirstCommand",
            "MotionControl.fbMoving.fStartPosition",
            "MotionControl.fbMoving.fStartVelocity",
            "MotionControl.fbMoving.Error",
        ],
    );
    // A closed-form cam evaluation, independent of the cycle: the digest's 7 digits.
    assert_near(&values, "MotionControl.lrRestPosition", 98.379_629_6, 1e-6);
    assert_near(&values, "MotionControl.lrRestVelocity", 0.0, 1e-9);
    assert_near(&values, "MotionControl.lrFirstCommand", 98.379_629_6, 1e-6);
    assert!(
        !boolean(&values, "MotionControl.fbMoving.Error"),
        "{values:?}"
    );
    // The master has long reached 50 u/s: the velocity is exact up to the digest's rounding.
    assert_near(&values, "Feed.fSetVelocity", 50.0, 1e-9);
    assert_near(
        &values,
        "MotionControl.fbMoving.fStartPosition",
        98.379_629_6,
        1e-6,
    );
    assert_near(
        &values,
        "MotionControl.fbMoving.fStartVelocity",
        1.215_277_8 * 50.0,
        1e-5,
    );
}

/// PLCopen digest T11: SMC_GetTappetValue on track 2 with bInitValue FALSE: FALSE at the first
/// call, TRUE after the tappet; a restart of MC_CamIn (after MC_CamOut) sets it back to FALSE
/// with bSetInitValueAtReset TRUE and keeps TRUE with bSetInitValueAtReset FALSE.
#[test]
fn plcopen_t11_get_tappet_value_init_value_returns_at_a_cam_in_restart_only_when_asked() {
    // One coupling per SMC_GetTappetValue: bSetInitValueAtReset is told to the track of the
    // coupling's tappets, so two instances on one track would overwrite each other's choice.
    let mut variables = vec![
        ("fbPowerDrum".to_string(), "MC_Power"),
        ("fbTurn".to_string(), "MC_MoveVelocity"),
        ("iCycle".to_string(), "INT"),
        ("lrDrumAfter".to_string(), "LREAL"),
    ];
    let mut body = String::from(
        "iCycle := iCycle + 1;
fbPowerDrum(Axis := Drum, Enable := TRUE);
fbTurn(Axis := Drum, Execute := fbPowerDrum.Status, Velocity := 360.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
IF iCycle = 215 THEN
    lrDrumAfter := Drum.fSetPosition;
END_IF
",
    );
    let mut axes = vec![modulo_axis("Drum", 360.0)];
    for (slave, reset) in [("Reset", "TRUE"), ("Keep", "FALSE")] {
        axes.push(linear_axis(slave));
        for (prefix, ty) in [
            ("fbPower", "MC_Power"),
            ("fbSelect", "MC_CamTableSelect"),
            ("fbCam", "MC_CamIn"),
            ("fbOut", "MC_CamOut"),
            ("fbTappet", "SMC_GetTappetValue"),
            ("xFirst", "BOOL"),
            ("xBefore", "BOOL"),
            ("xAfter", "BOOL"),
        ] {
            variables.push((format!("{prefix}{slave}"), ty));
        }
        body.push_str(&format!(
            "fbPower{slave}(Axis := {slave}, Enable := TRUE);
fbSelect{slave}(Master := Drum, Slave := {slave}, CamTable := CAM_T11,
    Execute := fbPower{slave}.Status, Periodic := TRUE, MasterAbsolute := TRUE,
    SlaveAbsolute := TRUE);
(* Coupled from the start, decoupled at cycle 200, coupled again from cycle 210. *)
fbOut{slave}(Slave := {slave}, Execute := iCycle >= 200 AND iCycle < 210);
fbCam{slave}(Master := Drum, Slave := {slave},
    Execute := fbSelect{slave}.Done AND (iCycle < 200 OR iCycle >= 210),
    CamTableID := fbSelect{slave}.CamTableID);
fbTappet{slave}(Tappets := fbCam{slave}.Tappets, iID := 2, bInitValue := FALSE,
    bSetInitValueAtReset := {reset});
IF iCycle = 10 THEN
    xFirst{slave} := fbTappet{slave}.bTappet;
ELSIF iCycle = 199 THEN
    xBefore{slave} := fbTappet{slave}.bTappet;
ELSIF iCycle = 215 THEN
    xAfter{slave} := fbTappet{slave}.bTappet;
END_IF
"
        ));
    }
    let variables: Vec<(&str, &str)> = variables
        .iter()
        .map(|(name, ty)| (name.as_str(), *ty))
        .collect();
    let dir = project(&axes, &variables, &body);
    add_cam(
        &dir,
        "CAM_T11",
        &cam(
            1.0,
            &[("line", 360.0, 360.0, 1.0)],
            "
[[track]]
id = 2

[[track.tappet]]
position = 100.0
on_positive = \"on\"
on_negative = \"none\"
",
        ),
    );
    let values = simulate(
        &dir,
        220,
        &[
            "MotionControl.xFirstReset",
            "MotionControl.xFirstKeep",
            "MotionControl.xBeforeReset",
            "MotionControl.xBeforeKeep",
            "MotionControl.xAfterReset",
            "MotionControl.xAfterKeep",
            "MotionControl.lrDrumAfter",
            "MotionControl.fbCamReset.Busy",
            "MotionControl.fbCamKeep.Busy",
        ],
    );
    // 360 u/s, 0.72 a cycle: cycle 10 is near 6, cycle 199 near 142 (past the tappet at 100),
    // cycle 215 near 154, still past it, so only the restart can make the output FALSE.
    let drum = number(&values, "MotionControl.lrDrumAfter");
    assert!((120.0..200.0).contains(&drum), "{values:?}");
    assert!(
        boolean(&values, "MotionControl.fbCamReset.Busy"),
        "{values:?}"
    );
    assert!(
        boolean(&values, "MotionControl.fbCamKeep.Busy"),
        "{values:?}"
    );
    assert!(!boolean(&values, "MotionControl.xFirstReset"), "{values:?}");
    assert!(!boolean(&values, "MotionControl.xFirstKeep"), "{values:?}");
    assert!(boolean(&values, "MotionControl.xBeforeReset"), "{values:?}");
    assert!(boolean(&values, "MotionControl.xBeforeKeep"), "{values:?}");
    assert!(!boolean(&values, "MotionControl.xAfterReset"), "{values:?}");
    assert!(boolean(&values, "MotionControl.xAfterKeep"), "{values:?}");
}

/// PLCopen digest T17: MC_GearIn 2/1 on a master at a constant 50 u/s: InGear when the slave
/// reaches 100 u/s, then Δslave = 2·Δmaster (the distance lost while ramping is not made up).
#[test]
fn plcopen_t17_gear_in_2_to_1_in_gear_at_100_then_the_slave_moves_twice_the_master() {
    let dir = project(
        &[linear_axis("Drive"), linear_axis("Follower")],
        &[
            ("fbPowerDrive", "MC_Power"),
            ("fbPowerFollower", "MC_Power"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbGear", "MC_GearIn"),
            ("lrGearMaster", "LREAL"),
            ("lrGearSlave", "LREAL"),
            ("lrGearVelocity", "LREAL"),
            ("lrStartMaster", "LREAL"),
        ],
        "fbPowerDrive(Axis := Drive, Enable := TRUE);
fbPowerFollower(Axis := Follower, Enable := TRUE);
fbTurn(Axis := Drive, Execute := fbPowerDrive.Status, Velocity := 50.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
fbGear(Master := Drive, Slave := Follower, Execute := fbTurn.InVelocity AND fbPowerFollower.Status,
    RatioNumerator := 2, RatioDenominator := 1, Acceleration := 100.0, Deceleration := 100.0);
IF fbGear.Busy AND lrStartMaster = 0.0 THEN
    lrStartMaster := Drive.fSetPosition;
END_IF
IF fbGear.InGear AND lrGearMaster = 0.0 THEN
    lrGearMaster := Drive.fSetPosition;
    lrGearSlave := Follower.fSetPosition;
    lrGearVelocity := Follower.fSetVelocity;
END_IF",
    );
    // 3 s: the slave needs 1 s at 100 u/s² to reach 100 u/s.
    let values = simulate(
        &dir,
        1500,
        &[
            "Drive.fSetPosition",
            "Follower.fSetPosition",
            "Follower.fSetVelocity",
            "MotionControl.lrGearMaster",
            "MotionControl.lrGearSlave",
            "MotionControl.lrGearVelocity",
            "MotionControl.lrStartMaster",
        ],
    );
    assert_near(&values, "MotionControl.lrGearVelocity", 100.0, 1e-9);
    assert_near(&values, "Follower.fSetVelocity", 100.0, 1e-9);
    // The ramp of 1 s (± one 2 ms cycle of reading) at 50 u/s: the master moved 50 ± 0.1.
    let ramp = number(&values, "MotionControl.lrGearMaster")
        - number(&values, "MotionControl.lrStartMaster");
    assert!((ramp - 50.0).abs() <= 0.11, "{values:?}");
    let master =
        number(&values, "Drive.fSetPosition") - number(&values, "MotionControl.lrGearMaster");
    let slave =
        number(&values, "Follower.fSetPosition") - number(&values, "MotionControl.lrGearSlave");
    assert!(master > 50.0, "{values:?}");
    assert!((slave - 2.0 * master).abs() < 1e-6, "{values:?}");
    // Not made up: the slave ramped over 50 at half the velocity on average, 100 short of 2×.
    let total = number(&values, "Follower.fSetPosition");
    let master_total =
        number(&values, "Drive.fSetPosition") - number(&values, "MotionControl.lrStartMaster");
    assert!(
        (2.0 * master_total - total - 50.0).abs() <= 0.3,
        "{values:?}"
    );
}

/// PLCopen digest T19: MC_Phasing PhaseShift 30 on a 1:1 gear (modulo 360): after Done the
/// slave set position trails the master's by 30; the master's velocity is unchanged.
#[test]
fn plcopen_t19_phasing_30_on_a_1_to_1_gear_makes_the_slave_trail_by_30() {
    let dir = project(
        &[modulo_axis("Drive", 360.0), modulo_axis("Follower", 360.0)],
        &[
            ("fbPowerDrive", "MC_Power"),
            ("fbPowerFollower", "MC_Power"),
            ("fbGear", "MC_GearIn"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbPhase", "MC_Phasing"),
            ("lrLag", "LREAL"),
            ("lrLagBefore", "LREAL"),
            ("lrMasterVelocityMin", "LREAL"),
        ],
        "fbPowerDrive(Axis := Drive, Enable := TRUE);
fbPowerFollower(Axis := Follower, Enable := TRUE);
(* Geared with both at rest at 0, so the slave follows the master exactly from the start. *)
fbGear(Master := Drive, Slave := Follower, Execute := fbPowerDrive.Status AND fbPowerFollower.Status,
    RatioNumerator := 1, RatioDenominator := 1, Acceleration := 20000.0, Deceleration := 20000.0);
fbTurn(Axis := Drive, Execute := fbGear.InGear, Velocity := 90.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.positive);
fbPhase(Master := Drive, Slave := Follower, Execute := fbTurn.InVelocity, PhaseShift := 30.0,
    Velocity := 60.0, Acceleration := 600.0, Deceleration := 600.0);
lrLag := Drive.fSetPosition - Follower.fSetPosition;
IF lrLag < -180.0 THEN
    lrLag := lrLag + 360.0;
ELSIF lrLag > 180.0 THEN
    lrLag := lrLag - 360.0;
END_IF
IF NOT fbPhase.Busy AND NOT fbPhase.Done THEN
    lrLagBefore := lrLag;
END_IF
IF fbTurn.InVelocity THEN
    IF lrMasterVelocityMin = 0.0 OR Drive.fSetVelocity < lrMasterVelocityMin THEN
        lrMasterVelocityMin := Drive.fSetVelocity;
    END_IF
END_IF",
    );
    // 3 s: 30 at 60 u/s with 600 u/s² ramps takes 0.6 s.
    let values = simulate(
        &dir,
        1500,
        &[
            "MotionControl.lrLag",
            "MotionControl.lrLagBefore",
            "MotionControl.lrMasterVelocityMin",
            "MotionControl.fbPhase.Done",
            "MotionControl.fbGear.InGear",
            "Drive.fSetVelocity",
            "Follower.fSetVelocity",
        ],
    );
    assert!(boolean(&values, "MotionControl.fbPhase.Done"), "{values:?}");
    assert_near(&values, "MotionControl.lrLagBefore", 0.0, 1e-9);
    assert_near(&values, "MotionControl.lrLag", 30.0, 1e-9);
    // The master is not touched by the phasing; the slave runs at its velocity again.
    assert_near(&values, "MotionControl.lrMasterVelocityMin", 90.0, 1e-9);
    assert_near(&values, "Follower.fSetVelocity", 90.0, 1e-9);
}

/// Omron 7A.2 MC_GenerateCamTable example: nodes (180, 180) and (360, 0), both StraightLine,
/// from the start node (0, 0): point 1800 is (180, 180), point 3600 is (360, 0); in between the
/// slave is interpolated linearly (90 → 90, 270 → 90). Read through SMC_GetCamSlaveSetPosition
/// with MasterOffset on a master at rest at 0 (MasterAbsolute FALSE: X = MasterOffset).
#[test]
fn omron_generated_straight_cam_180_180_then_360_0() {
    let offsets = [90.0, 180.0, 270.0, 360.0];
    let mut variables = vec![
        ("fbPowerWheel".to_string(), "MC_Power"),
        ("fbPowerArm".to_string(), "MC_Power"),
        ("fbSelect".to_string(), "MC_CamTableSelect"),
    ];
    let mut body = String::from(
        "fbPowerWheel(Axis := Wheel, Enable := TRUE);
fbPowerArm(Axis := Arm, Enable := TRUE);
fbSelect(Master := Wheel, Slave := Arm, CamTable := CAM_Straight,
    Execute := fbPowerWheel.Status AND fbPowerArm.Status, Periodic := FALSE,
    MasterAbsolute := FALSE, SlaveAbsolute := TRUE);
",
    );
    for (index, offset) in offsets.iter().enumerate() {
        variables.push((format!("fbAt{index}"), "SMC_GetCamSlaveSetPosition"));
        body.push_str(&format!(
            "fbAt{index}(Master := Wheel, Slave := Arm, Enable := fbSelect.Done,
    MasterOffset := {offset:?}, CamTableID := fbSelect.CamTableID);
"
        ));
    }
    let variables: Vec<(&str, &str)> = variables
        .iter()
        .map(|(name, ty)| (name.as_str(), *ty))
        .collect();
    let dir = project(
        &[linear_axis("Wheel"), linear_axis("Arm")],
        &variables,
        &body,
    );
    add_cam(
        &dir,
        "CAM_Straight",
        &cam(
            1.0,
            &[("line", 180.0, 180.0, 1.0), ("line", 360.0, 0.0, -1.0)],
            "",
        ),
    );
    let watch: Vec<String> = (0..offsets.len())
        .flat_map(|index| {
            [
                format!("MotionControl.fbAt{index}.fStartPosition"),
                format!("MotionControl.fbAt{index}.Error"),
            ]
        })
        .collect();
    let watch: Vec<&str> = watch.iter().map(String::as_str).collect();
    let values = simulate(&dir, 20, &watch);
    // Evaluations of straight lines at rest: exact.
    for (index, expected) in [90.0, 180.0, 90.0, 0.0].into_iter().enumerate() {
        assert!(
            !boolean(&values, &format!("MotionControl.fbAt{index}.Error")),
            "{values:?}"
        );
        assert_near(
            &values,
            &format!("MotionControl.fbAt{index}.fStartPosition"),
            expected,
            1e-9,
        );
    }
}

/// Omron 7B MC_DigitalCamSwitch example table (modulo 0..5000: SW0 track 0 2000..3000
/// positive, SW1 track 0 2500..3000 negative, SW2 track 0 4000..1000 both, SW3 track 1 from
/// 3000 for 1350 ms both) with the axis moving negative at 1000 u/s from 0: track 0 is off at
/// 4000, on at 3000 (SW1), off at 2500 (SW0 is positive only), on again at 1000; track 1 is on
/// from 3000 for 1350 ms, off at 1650. (The positive direction is `plcopen`'s T12.)
/// Rivet numbers the modes and directions as PLCopen: CamSwitchMode 0 position, 1 time;
/// AxisDirection 1 positive, 2 negative, 0 both.
#[test]
fn omron_digital_cam_switch_table_moving_negative_4000_3000_2500_1000_and_1350_ms() {
    let dir = project(
        &[modulo_axis("Table", 5000.0)],
        &[
            ("fbPower", "MC_Power"),
            ("fbTurn", "MC_MoveVelocity"),
            ("fbSwitch", "MC_DigitalCamSwitch"),
            ("stSwitches", "MC_CAMSWITCH_REF"),
            ("stTracks", "MC_TRACK_REF"),
            ("stOutputs", "MC_OUTPUT_REF"),
            ("xLast0", "BOOL"),
            ("xLast1", "BOOL"),
            ("iEdge0", "INT"),
            ("iEdge1", "INT"),
            ("aEdges0", "ARRAY[1..8] OF LREAL"),
            ("aEdges1", "ARRAY[1..8] OF LREAL"),
        ],
        &format!(
            "{T12_SWITCHES}fbPower(Axis := Table, Enable := TRUE);
fbTurn(Axis := Table, Execute := fbPower.Status, Velocity := 1000.0, Acceleration := 20000.0,
    Deceleration := 20000.0, Direction := MC_DIRECTION.negative);
fbSwitch(Axis := Table, Switches := stSwitches, Outputs := stOutputs, TrackOptions := stTracks,
    Enable := TRUE);
IF stOutputs.Output[0] <> xLast0 AND iEdge0 < 8 THEN
    iEdge0 := iEdge0 + 1;
    aEdges0[iEdge0] := Table.fSetPosition;
END_IF
xLast0 := stOutputs.Output[0];
IF stOutputs.Output[1] <> xLast1 AND iEdge1 < 8 THEN
    iEdge1 := iEdge1 + 1;
    aEdges1[iEdge1] := Table.fSetPosition;
END_IF
xLast1 := stOutputs.Output[1];"
        ),
    );
    // 4.5 s at 1000 u/s from 0 backwards: the table ends near 500.
    let mut watch = vec![
        "Table.fActPosition".to_string(),
        "MotionControl.iEdge0".to_string(),
        "MotionControl.iEdge1".to_string(),
        "MotionControl.fbSwitch.Error".to_string(),
        "MotionControl.stOutputs.Output[0]".to_string(),
    ];
    for index in 1..=6 {
        watch.push(format!("MotionControl.aEdges0[{index}]"));
        watch.push(format!("MotionControl.aEdges1[{index}]"));
    }
    let watch: Vec<&str> = watch.iter().map(String::as_str).collect();
    let values = simulate(&dir, 2250, &watch);
    assert!(
        !boolean(&values, "MotionControl.fbSwitch.Error"),
        "{values:?}"
    );
    let edges = |track: u32| -> Vec<f64> {
        let count = number(&values, &format!("MotionControl.iEdge{track}")) as usize;
        (1..=count.min(6))
            .map(|index| number(&values, &format!("MotionControl.aEdges{track}[{index}]")))
            .collect()
    };
    // Each edge is read at the call after the cycle that switched: within one cycle (2 units
    // at 1000 u/s) and half a unit of rounding past the switching point.
    let near = |value: f64, expected: f64| (value - expected).abs() <= 2.5;
    let track0 = edges(0);
    assert!(
        track0.windows(4).any(|four| near(four[0], 4000.0)
            && near(four[1], 3000.0)
            && near(four[2], 2500.0)
            && near(four[3], 1000.0)),
        "{track0:?} {values:?}"
    );
    assert!(
        boolean(&values, "MotionControl.stOutputs.Output[0]"),
        "{values:?}"
    );
    // The timed switch counts its 1350 ms (675 cycles) from the call that saw the crossing;
    // the sum of 2 ms steps may fall a hair short of 1.35 s, one cycle more: 4.5 units.
    let track1 = edges(1);
    assert!(
        track1
            .windows(2)
            .any(|pair| near(pair[0], 3000.0) && (pair[1] - 1650.0).abs() <= 4.5),
        "{track1:?} {values:?}"
    );
}
