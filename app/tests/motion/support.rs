//! Helpers of the motion tests: a copy of the example project with axes, a program and cams
//! added, run by `rivet simulate`, and the values it prints.

use std::fs;
use std::process::Command;

use runtime::simulation::Simulation;
use serde_json::Value;

/// The switches of the PLCopen digest's T12 (Fig. 37–39) as Structured Text filling an
/// `MC_CAMSWITCH_REF` called `stSwitches`: track 0 on at 2000..3000 moving positive, at
/// 2500..3000 moving negative and at 4000..1000 across the wrap; track 1 for 1350 ms from 3000.
pub const T12_SWITCHES: &str = "stSwitches.NumberOfSwitches := 4;
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
";

/// A linear virtual axis in `MotionTask`, limits generous enough for the examples.
pub fn linear_axis(name: &str) -> String {
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

/// A modulo axis in `MotionTask` with period `period_units`.
pub fn modulo_axis(name: &str, period_units: f64) -> String {
    linear_axis(name).replace(
        "unit = \"mm\"\n",
        &format!("unit = \"mm\"\nmodulo_period = {period_units:?}\n"),
    )
}

/// A copy of the example whose `MotionControl` program declares `variables` (name, type) and
/// runs `body`, with `axes` (TOML) added to the device tree.
pub fn project(axes: &[String], variables: &[(&str, &str)], body: &str) -> tempfile::TempDir {
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

/// Adds the cam table `name` with the TOML `text` to the project in `dir`.
pub fn add_cam(dir: &tempfile::TempDir, name: &str, text: &str) {
    fs::write(
        dir.path().join(format!("application/{name}.cam.toml")),
        text,
    )
    .unwrap();
    let manifest = dir.path().join("rivet.toml");
    let listed = fs::read_to_string(&manifest).unwrap().replace(
        "    \"Motion/CAM_Knife.cam.toml\",\n",
        &format!("    \"Motion/CAM_Knife.cam.toml\",\n    \"{name}.cam.toml\",\n"),
    );
    fs::write(&manifest, listed).unwrap();
}

/// Runs `cycles` cycles of the fastest task through `rivet simulate` with the default engine
/// (native where there is a backend) and returns the watched values, after checking them
/// against the same project compiled in-process and run under the interpreter and the native
/// engine, compared after every cycle by memory, faults and axes
/// (`runtime::differential::run_both`, `docs/native-engine.md` §11.1): the command must print
/// what the native engine holds after the last cycle.
#[track_caller]
pub fn simulate(
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
    let both = run_both(dir, cycles);
    assert_eq!(
        stdout.trim(),
        json_of(&both, watch),
        "rivet simulate (left) and the engines run in-process (right) differ"
    );
    match serde_json::from_str(stdout.trim()).unwrap() {
        Value::Object(map) => map,
        other => panic!("not an object: {other}"),
    }
}

/// The project in `dir` compiled as `rivet simulate` compiles it and run for `cycles` cycles
/// under both engines, compared after every cycle; the native engine's simulation.
#[track_caller]
fn run_both(dir: &tempfile::TempDir, cycles: u32) -> Simulation {
    let loaded = project_model::load_project(dir.path()).unwrap();
    let image = compiler::compile_project(&loaded.project).unwrap();
    runtime::differential::run_both(image, u64::from(cycles), |_, _| {})
        .unwrap_or_else(|difference| panic!("the engines differ: {difference}"))
}

/// The watched values of `simulation` as `rivet simulate --json` prints them.
#[track_caller]
fn json_of(simulation: &Simulation, watch: &[&str]) -> String {
    let fields: Vec<String> = watch
        .iter()
        .map(|name| {
            let value = runtime::value::read(simulation.engine(), name)
                .unwrap_or_else(|error| panic!("{name}: {error}"));
            format!("{}: {}", runtime::value::json_string(name), value.to_json())
        })
        .collect();
    format!("{{{}}}", fields.join(", "))
}

#[track_caller]
pub fn number(values: &serde_json::Map<String, Value>, path: &str) -> f64 {
    values[path]
        .as_f64()
        .unwrap_or_else(|| panic!("{path} is {:?}", values[path]))
}

#[track_caller]
pub fn boolean(values: &serde_json::Map<String, Value>, path: &str) -> bool {
    match &values[path] {
        Value::Bool(value) => *value,
        Value::String(text) => text == "TRUE",
        other => panic!("{path} is {other:?}"),
    }
}

/// Asserts that `path` is within `tolerance` of `expected`.
#[track_caller]
pub fn assert_near(
    values: &serde_json::Map<String, Value>,
    path: &str,
    expected: f64,
    tolerance: f64,
) {
    let value = number(values, path);
    assert!(
        (value - expected).abs() <= tolerance,
        "{path} = {value}, expected {expected} ± {tolerance}: {values:?}"
    );
}
