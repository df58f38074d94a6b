//! The variables the studio reads while online, assembled from everything that shows values.

use project_model::ModbusDevice;

use super::online::devices::{Bound, bound};

/// Where the watched variables come from this frame.
#[derive(Debug, Default)]
pub(crate) struct WatchSources {
    /// The paths of the watch list the watch pane shows.
    pub watch_list: Vec<String>,
    /// The variables of the trace the trace pane shows.
    pub trace: Vec<String>,
    /// The variables the open text editors show inline.
    pub inline: Vec<String>,
    /// The variables the cams drawn while logged in read for their live marker.
    pub cams: Vec<String>,
}

/// The paths to watch in the order of their sources: the watch list as it is, then, each added
/// once, the shown trace's variables on a Modbus device the studio polls (so the trace can
/// record them by polling; the target records the others itself, a runtime device's among them
/// while `logged_in`), the inline values and the cams.
pub(crate) fn watched_paths(
    sources: WatchSources,
    devices: &[ModbusDevice],
    logged_in: bool,
) -> Vec<String> {
    let WatchSources {
        watch_list,
        trace,
        inline,
        cams,
    } = sources;
    let mut watched = watch_list;
    let mut add = |path: String| {
        if !watched.contains(&path) {
            watched.push(path);
        }
    };
    trace
        .into_iter()
        .filter(|path| matches!(bound(devices, path, logged_in), Some(Bound::Polled(..))))
        .for_each(&mut add);
    inline.into_iter().for_each(&mut add);
    cams.into_iter().for_each(&mut add);
    watched
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paths(texts: &[&str]) -> Vec<String> {
        texts.iter().map(|text| (*text).to_owned()).collect()
    }

    fn device_bound_to(variable: &str) -> ModbusDevice {
        ModbusDevice {
            bindings: vec![project_model::ModbusBinding::new(
                variable,
                project_model::ModbusTable::HoldingRegister,
                0,
                project_model::ModbusDataType::Int16,
            )],
            ..ModbusDevice::tcp("Drive", "127.0.0.1", 502)
        }
    }

    #[test]
    fn every_source_is_watched_once_in_source_order() {
        let watched = watched_paths(
            WatchSources {
                watch_list: paths(&["Main.a", "Main.b"]),
                trace: Vec::new(),
                inline: paths(&["Main.b", "Main.c"]),
                cams: paths(&["Main.cam.master", "Main.a"]),
            },
            &[],
            false,
        );
        assert_eq!(
            watched,
            paths(&["Main.a", "Main.b", "Main.c", "Main.cam.master"])
        );
    }

    #[test]
    fn only_the_trace_variables_bound_to_a_device_are_polled() {
        let devices = [device_bound_to("GVL_IO.rSpeed")];
        let watched = watched_paths(
            WatchSources {
                trace: paths(&["Main.rPosition", "gvl_io.rspeed"]),
                ..WatchSources::default()
            },
            &devices,
            false,
        );
        assert_eq!(watched, paths(&["gvl_io.rspeed"]));
    }

    #[test]
    fn a_runtime_device_s_trace_variables_are_not_polled_while_logged_in() {
        let mut device = device_bound_to("GVL_IO.rSpeed");
        device.task = Some("MainTask".into());
        let sources = || WatchSources {
            trace: paths(&["GVL_IO.rSpeed"]),
            ..WatchSources::default()
        };
        let devices = [device];
        assert_eq!(
            watched_paths(sources(), &devices, false),
            paths(&["GVL_IO.rSpeed"])
        );
        assert!(watched_paths(sources(), &devices, true).is_empty());
    }
}
