//! Every colour the studio draws with that is not one of egui's visuals, by what it means, for
//! the dark and the light theme. The editors get theirs from here too (see [`install_palettes`]),
//! so no UI code holds a colour literal.

use cam_editor::CamPalette;
use editor::{EditorPalette, SyntaxColors};
use egui::Color32;

/// The studio's own colours for one theme.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct StudioColors {
    /// The status bar's online state while the program runs.
    pub target_running: Color32,
    /// The status bar's online state while the program is stopped or starting.
    pub target_stopped: Color32,
    /// The status bar's online state when the target faulted or was lost.
    pub target_failed: Color32,
    /// The background of the `F` badge of a forced value.
    pub forced_fill: Color32,
    /// The letter of the `F` badge of a forced value.
    pub forced_text: Color32,
    /// Online messages that report no failure.
    pub quiet_message: Color32,
    /// The trigger line of a trace plot.
    pub trace_trigger: Color32,
    /// The trace plot's cursors A and B.
    pub trace_cursors: [Color32; 2],
    /// The device tree's kind tags: programs.
    pub tag_program: Color32,
    /// Function blocks.
    pub tag_function_block: Color32,
    /// Functions.
    pub tag_function: Color32,
    /// Variable lists, data types and interfaces.
    pub tag_data: Color32,
    /// Cams and axes.
    pub tag_motion: Color32,
    /// Tasks and the task configuration.
    pub tag_task: Color32,
    /// Every other tag.
    pub tag_other: Color32,
    /// A runtime Modbus device's icon and state while its last round had no failure.
    pub device_communicating: Color32,
    /// While it answers with errors, does not answer, or its serial port failed.
    pub device_failing: Color32,
    /// While nothing reaches the program: the master is off or the program is not running.
    pub device_off: Color32,
    /// Before its first round ended, or before the runtime reported it.
    pub device_waiting: Color32,
}

/// Distinct colours for trace series without a configured colour, readable on dark and light
/// themes alike.
pub(crate) const TRACE_SERIES: [Color32; 10] = [
    Color32::from_rgb(0x1f, 0x77, 0xb4),
    Color32::from_rgb(0xff, 0x7f, 0x0e),
    Color32::from_rgb(0x2c, 0xa0, 0x2c),
    Color32::from_rgb(0xd6, 0x27, 0x28),
    Color32::from_rgb(0x94, 0x67, 0xbd),
    Color32::from_rgb(0x8c, 0x56, 0x4b),
    Color32::from_rgb(0xe3, 0x77, 0xc2),
    Color32::from_rgb(0x7f, 0x7f, 0x7f),
    Color32::from_rgb(0xbc, 0xbd, 0x22),
    Color32::from_rgb(0x17, 0xbe, 0xcf),
];

/// The colours of the dark theme. The light theme uses most of them: they were chosen to read
/// on both; a colour that needs to differ changes in [`LIGHT`] only.
const DARK: StudioColors = StudioColors {
    target_running: Color32::from_rgb(60, 170, 80),
    target_stopped: Color32::from_rgb(200, 160, 40),
    target_failed: Color32::from_rgb(220, 80, 60),
    forced_fill: Color32::from_rgb(200, 40, 40),
    forced_text: Color32::WHITE,
    quiet_message: Color32::GRAY,
    trace_trigger: Color32::GRAY,
    trace_cursors: [
        Color32::from_rgb(0xe0, 0x40, 0x40),
        Color32::from_rgb(0x40, 0x90, 0xe0),
    ],
    tag_program: Color32::from_rgb(90, 160, 230),
    tag_function_block: Color32::from_rgb(120, 190, 120),
    tag_function: Color32::from_rgb(200, 160, 80),
    tag_data: Color32::from_rgb(170, 130, 210),
    tag_motion: Color32::from_rgb(230, 120, 100),
    tag_task: Color32::from_rgb(100, 180, 180),
    tag_other: Color32::GRAY,
    device_communicating: Color32::from_rgb(60, 170, 80),
    device_failing: Color32::from_rgb(220, 80, 60),
    device_off: Color32::GRAY,
    device_waiting: Color32::from_rgb(200, 160, 40),
};

/// The colours of the light theme: the dark theme's, but for the Modbus device lights, which
/// are darker so that a small icon keeps its contrast on a light panel.
const LIGHT: StudioColors = StudioColors {
    device_communicating: Color32::from_rgb(25, 125, 45),
    device_failing: Color32::from_rgb(190, 40, 30),
    device_off: Color32::from_rgb(105, 105, 105),
    device_waiting: Color32::from_rgb(150, 105, 0),
    ..DARK
};

/// The studio's colours for the theme `ui` is drawn in.
pub(crate) fn colors(ui: &egui::Ui) -> &'static StudioColors {
    colors_for(ui.visuals().dark_mode)
}

/// The studio's colours for the dark (`true`) or the light theme.
pub(crate) fn colors_for(dark_mode: bool) -> &'static StudioColors {
    if dark_mode { &DARK } else { &LIGHT }
}

/// The Structured Text colours of the dark theme.
const DARK_SYNTAX: SyntaxColors = SyntaxColors {
    keyword: Color32::from_rgb(86, 156, 214),
    comment: Color32::from_rgb(106, 153, 85),
    string: Color32::from_rgb(206, 145, 120),
    number: Color32::from_rgb(181, 206, 168),
    constant: Color32::from_rgb(100, 180, 230),
    type_name: Color32::from_rgb(78, 201, 176),
    function: Color32::from_rgb(220, 220, 170),
    property: Color32::from_rgb(156, 220, 254),
    attribute: Color32::from_rgb(197, 134, 192),
    label: Color32::from_rgb(220, 180, 90),
};

/// The Structured Text colours of the light theme.
const LIGHT_SYNTAX: SyntaxColors = SyntaxColors {
    keyword: Color32::from_rgb(0, 70, 180),
    comment: Color32::from_rgb(0, 128, 0),
    string: Color32::from_rgb(163, 21, 21),
    number: Color32::from_rgb(9, 134, 88),
    constant: Color32::from_rgb(0, 110, 150),
    type_name: Color32::from_rgb(38, 127, 153),
    function: Color32::from_rgb(121, 94, 38),
    property: Color32::from_rgb(0, 16, 128),
    attribute: Color32::from_rgb(140, 40, 140),
    label: Color32::from_rgb(150, 90, 0),
};

/// The editors' colours for the dark (`true`) or the light theme.
pub(crate) fn editor_palette(dark_mode: bool) -> EditorPalette {
    EditorPalette {
        syntax: if dark_mode { DARK_SYNTAX } else { LIGHT_SYNTAX },
        find_match: if dark_mode {
            Color32::from_rgba_unmultiplied(200, 160, 40, 70)
        } else {
            Color32::from_rgba_unmultiplied(250, 200, 60, 110)
        },
        changed_value: if dark_mode {
            Color32::from_rgb(40, 90, 60)
        } else {
            Color32::from_rgb(190, 240, 200)
        },
        forced_fill: Color32::from_rgb(200, 40, 40),
        forced_text: Color32::WHITE,
        error: Color32::from_rgb(230, 60, 60),
        warning: Color32::from_rgb(220, 180, 40),
        info: Color32::from_rgb(80, 150, 230),
        table_warning: Color32::from_rgb(0xE0, 0xB0, 0x20),
        // CODESYS draws energised connections in blue.
        power_on: if dark_mode {
            Color32::from_rgb(80, 160, 255)
        } else {
            Color32::from_rgb(0, 90, 220)
        },
        diagram_selection: if dark_mode {
            Color32::from_rgba_unmultiplied(60, 110, 200, 60)
        } else {
            Color32::from_rgba_unmultiplied(120, 170, 250, 70)
        },
        insert_point: Color32::from_rgb(30, 160, 70),
        // CODESYS fills active SFC steps in blue.
        active_step: if dark_mode {
            Color32::from_rgb(40, 100, 200)
        } else {
            Color32::from_rgb(110, 170, 255)
        },
        // White on the dark theme's blue, black on the light theme's.
        active_step_text: if dark_mode {
            Color32::WHITE
        } else {
            Color32::BLACK
        },
        // CODESYS draws breakpoints red and the halted statement with a yellow arrow.
        breakpoint: Color32::from_rgb(200, 40, 40),
        breakpoint_symbol: Color32::WHITE,
        halt_marker: Color32::from_rgb(250, 210, 40),
        halt_outline: if dark_mode {
            Color32::BLACK
        } else {
            Color32::from_rgb(90, 70, 0)
        },
        halt_line: if dark_mode {
            Color32::from_rgba_unmultiplied(200, 170, 30, 70)
        } else {
            Color32::from_rgba_unmultiplied(255, 230, 80, 140)
        },
        flow_mark: Color32::from_rgb(30, 160, 70),
    }
}

/// Gives the editors drawn in `ctx` the colours of its current theme (called every frame, so a
/// switch of theme shows at once).
pub(crate) fn install_palettes(ctx: &egui::Context) {
    let dark_mode = ctx.global_style().visuals.dark_mode;
    EditorPalette::install(ctx, editor_palette(dark_mode));
    CamPalette::install(ctx, cam_palette(dark_mode));
}

/// The cam editor's colours for the dark (`true`) or the light theme; the same for both today.
pub(crate) fn cam_palette(_dark_mode: bool) -> CamPalette {
    CamPalette {
        position: Color32::from_rgb(0x3a, 0x80, 0xe0),
        velocity: Color32::from_rgb(0x30, 0xa0, 0x50),
        acceleration: Color32::from_rgb(0xe0, 0x80, 0x20),
        jerk: Color32::from_rgb(0xa0, 0x50, 0xc0),
        warning: Color32::from_rgb(0xe0, 0x30, 0x30),
        live: Color32::from_rgb(0x20, 0xb0, 0x90),
        lit_lane: Color32::from_rgba_unmultiplied(0x30, 0xc0, 0x60, 0x60),
        tappet_on: Color32::from_rgb(0x30, 0xb0, 0x50),
        tappet_off: Color32::from_rgb(0xd0, 0x40, 0x40),
        tappet_invert: Color32::from_rgb(0xe0, 0xb0, 0x20),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The relative luminance of a colour (WCAG 2).
    fn luminance(color: Color32) -> f64 {
        let channel = |value: u8| {
            let value = f64::from(value) / 255.0;
            if value <= 0.040_45 {
                value / 12.92
            } else {
                ((value + 0.055) / 1.055).powf(2.4)
            }
        };
        0.2126 * channel(color.r()) + 0.7152 * channel(color.g()) + 0.0722 * channel(color.b())
    }

    /// The contrast ratio of two colours, 1 to 21.
    fn contrast(a: Color32, b: Color32) -> f64 {
        let (a, b) = (luminance(a), luminance(b));
        (a.max(b) + 0.05) / (a.min(b) + 0.05)
    }

    #[test]
    fn the_device_lights_stand_out_from_the_panel_in_both_themes() {
        for (colors, visuals) in [
            (&DARK, egui::Visuals::dark()),
            (&LIGHT, egui::Visuals::light()),
        ] {
            let lights = [
                colors.device_communicating,
                colors.device_failing,
                colors.device_off,
                colors.device_waiting,
            ];
            for light in lights {
                // 3:1 is what WCAG asks of graphics that carry meaning.
                let ratio = contrast(light, visuals.panel_fill);
                assert!(
                    ratio >= 3.0,
                    "{light:?} on {:?}: {ratio:.2}",
                    visuals.panel_fill
                );
            }
        }
    }
}
