//! One breakpoint as the user set it: where, whether it is on, and when it halts.

use serde::{Deserialize, Serialize};

use super::graphical_place::GraphicalPlace;

/// Where a breakpoint is: a statement of a Structured Text body (the body's file in the
/// project, as `rivet check` and the image's line table name it, `application/Main.st`, and
/// the statement's line), or a network or element of a graphical body (its `.pou.toml` file
/// and [`GraphicalPlace`], with line 0).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct BreakpointPlace {
    /// The body's file, relative to the project folder, with `/` between folders.
    pub file: String,
    /// The statement's line, counted from 1; 0 in a graphical body.
    pub line: u32,
    /// The network or element of a graphical body (LD, FBD, CFC, SFC); `None` for Structured
    /// Text. Absent from the settings of a text breakpoint, so those saved before graphical
    /// breakpoints existed still load.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub graphical: Option<GraphicalPlace>,
}

impl BreakpointPlace {
    /// The statement on `line` of the Structured Text body in `file`.
    pub fn text(file: impl Into<String>, line: u32) -> Self {
        Self {
            file: file.into(),
            line,
            graphical: None,
        }
    }

    /// The network or element `place` of the graphical body in `file` (its `.pou.toml`).
    pub fn graphical(file: impl Into<String>, place: GraphicalPlace) -> Self {
        Self {
            file: file.into(),
            line: 0,
            graphical: Some(place),
        }
    }

    /// The place as the command line writes it, `FILE:LINE` or, in a graphical body,
    /// `FILE:POU:NETWORK[:ELEMENT]`.
    pub fn label(&self) -> String {
        match &self.graphical {
            None => format!("{}:{}", self.file, self.line),
            Some(place) => format!("{}:{}", self.file, place.command_line()),
        }
    }
}

/// When a reached breakpoint (with its condition TRUE) halts, by its hit count
/// (`docs/debugging.md` §3, CODESYS's breakpoint dialog).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum HitMode {
    /// Every time.
    #[default]
    Always,
    /// When the count equals the target.
    Equal,
    /// When the count is a multiple of the target.
    MultipleOf,
    /// When the count is at least the target.
    AtLeast,
}

impl HitMode {
    /// Every mode, in the order the dialog offers them.
    pub const ALL: [HitMode; 4] = [
        HitMode::Always,
        HitMode::Equal,
        HitMode::MultipleOf,
        HitMode::AtLeast,
    ];

    /// Whether a breakpoint reached for the `count`th time (from 1) halts with this mode and
    /// `target`; a target of 0 never matches "equal" or "multiple of".
    pub fn halts(self, count: u32, target: u32) -> bool {
        match self {
            HitMode::Always => true,
            HitMode::Equal => count == target,
            HitMode::MultipleOf => target != 0 && count.is_multiple_of(target),
            HitMode::AtLeast => count >= target,
        }
    }
}

/// A breakpoint, saved with the studio's settings under its project.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct Breakpoint {
    /// Where it is.
    pub place: BreakpointPlace,
    /// Whether it is on; a breakpoint that is off stays in the list and is not sent.
    pub enabled: bool,
    /// The condition as the user typed it (a BOOL expression), empty for none.
    pub condition: String,
    /// When it halts by its hit count.
    pub hit_mode: HitMode,
    /// The hit count's target, for every mode but `Always`.
    pub hit_target: u32,
    /// The instance path it halts in (`Main.fbA`), empty for every instance.
    pub instance: String,
    /// The task it halts in, empty for every task.
    pub task: String,
}

impl Default for Breakpoint {
    fn default() -> Self {
        Self::at(BreakpointPlace::text(String::new(), 1))
    }
}

impl Breakpoint {
    /// A plain breakpoint on `place`: on, no condition, halting every time.
    pub fn at(place: BreakpointPlace) -> Self {
        Self {
            place,
            enabled: true,
            condition: String::new(),
            hit_mode: HitMode::Always,
            hit_target: 0,
            instance: String::new(),
            task: String::new(),
        }
    }

    /// How the editor draws it.
    pub fn look(&self) -> editor::BreakpointLook {
        if !self.enabled {
            editor::BreakpointLook::Disabled
        } else if self.hit_mode != HitMode::Always {
            editor::BreakpointLook::HitCount
        } else if !self.condition.trim().is_empty() {
            editor::BreakpointLook::Conditional
        } else {
            editor::BreakpointLook::Enabled
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hit_modes_halt_at_their_counts() {
        assert!(HitMode::Always.halts(1, 0));
        assert!(HitMode::Equal.halts(3, 3) && !HitMode::Equal.halts(4, 3));
        assert!(HitMode::MultipleOf.halts(6, 3) && !HitMode::MultipleOf.halts(7, 3));
        assert!(!HitMode::MultipleOf.halts(6, 0));
        assert!(HitMode::AtLeast.halts(5, 3) && !HitMode::AtLeast.halts(2, 3));
    }

    #[test]
    fn the_look_follows_enabled_then_hit_count_then_condition() {
        let mut breakpoint = Breakpoint::at(BreakpointPlace::text("application/Main.st", 3));
        assert_eq!(breakpoint.look(), editor::BreakpointLook::Enabled);
        breakpoint.condition = "iCount > 100".to_owned();
        assert_eq!(breakpoint.look(), editor::BreakpointLook::Conditional);
        breakpoint.hit_mode = HitMode::AtLeast;
        assert_eq!(breakpoint.look(), editor::BreakpointLook::HitCount);
        breakpoint.enabled = false;
        assert_eq!(breakpoint.look(), editor::BreakpointLook::Disabled);
        assert_eq!(breakpoint.place.label(), "application/Main.st:3");
    }

    #[test]
    fn text_breakpoints_saved_before_graphical_ones_existed_still_load() {
        let saved = r#"{"place":{"file":"application/Main.st","line":3},"enabled":false}"#;
        let breakpoint: Breakpoint = serde_json::from_str(saved).unwrap_or_default();
        assert_eq!(
            breakpoint.place,
            BreakpointPlace::text("application/Main.st", 3)
        );
        assert!(!breakpoint.enabled);
        // A text breakpoint is saved as before; a graphical one round-trips with its element.
        let text = serde_json::to_string(&breakpoint).unwrap_or_default();
        assert!(!text.contains("graphical"), "{text}");
        let graphical = Breakpoint::at(BreakpointPlace::graphical(
            "application/Interlock.pou.toml",
            GraphicalPlace {
                body: "Interlock".to_owned(),
                network: 1,
                element: Some(7),
            },
        ));
        let text = serde_json::to_string(&graphical).unwrap_or_default();
        assert_eq!(
            serde_json::from_str::<Breakpoint>(&text).ok(),
            Some(graphical.clone())
        );
        assert_eq!(
            graphical.place.label(),
            "application/Interlock.pou.toml:Interlock:2:7"
        );
    }
}
