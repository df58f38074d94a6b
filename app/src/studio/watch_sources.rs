//! The variables the studio reads while online, assembled from everything that shows values.

use project_model::ModbusDevice;

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
/// once, the shown trace's variables that are bound to a Modbus device (so the trace can record
/// them by polling; the target records the others itself), the inline values and the cams.
pub(crate) fn watched_paths(sources: WatchSources, devices: &[ModbusDevice]) -> Vec<String> {
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
        .filter(|path| is_device_bound(devices, path))
        .for_each(&mut add);
    inline.into_iter().for_each(&mut add);
    cams.into_iter().for_each(&mut add);
    watched
}

/// Whether a channel of one of `devices` is bound to the variable `path`.
fn is_device_bound(devices: &[ModbusDevice], path: &str) -> bool {
    devices.iter().any(|device| {
        device
            .bindings
            .iter()
            .any(|binding| binding.variable.eq_ignore_ascii_case(path))
    })
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
        );
        assert_eq!(watched, paths(&["gvl_io.rspeed"]));
    }
}
