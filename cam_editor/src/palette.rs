//! The colours the cam editor draws with beyond egui's visuals. The application fills a
//! [`CamPalette`] from its theme and installs it in the egui context; without one the editor
//! falls back to colours taken from the visuals, so it never holds colour literals.

use egui::{Color32, Context, Id, Ui, Visuals};

/// The cam editor's colours for one theme. It lives in the egui context's temporary data,
/// replaced whenever the application installs another, and is never saved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CamPalette {
    /// The position curve.
    pub position: Color32,
    /// The velocity curve.
    pub velocity: Color32,
    /// The acceleration curve.
    pub acceleration: Color32,
    /// The jerk curve.
    pub jerk: Color32,
    /// Continuity warnings.
    pub warning: Color32,
    /// The live marker while logged in.
    pub live: Color32,
    /// The background of a tappet lane whose output is on.
    pub lit_lane: Color32,
    /// A tappet mark that switches on.
    pub tappet_on: Color32,
    /// A tappet mark that switches off.
    pub tappet_off: Color32,
    /// A tappet mark that inverts.
    pub tappet_invert: Color32,
}

impl CamPalette {
    /// The key the palette is kept under in the context.
    fn id() -> Id {
        Id::unique("cam_editor::CamPalette")
    }

    /// Makes `palette` the one the cam editors drawn in `ctx` use.
    pub fn install(ctx: &Context, palette: Self) {
        ctx.data_mut(|data| data.insert_temp(Self::id(), palette));
    }

    /// The installed palette, or one taken from the visuals of `ui`.
    pub fn of(ui: &Ui) -> Self {
        ui.ctx()
            .data(|data| data.get_temp::<Self>(Self::id()))
            .unwrap_or_else(|| Self::from_visuals(ui.visuals()))
    }

    /// A palette made of egui's visuals, for cam editors drawn without an application theme.
    pub fn from_visuals(visuals: &Visuals) -> Self {
        Self {
            position: visuals.hyperlink_color,
            velocity: visuals.strong_text_color(),
            acceleration: visuals.warn_fg_color,
            jerk: visuals.weak_text_color(),
            warning: visuals.error_fg_color,
            live: visuals.hyperlink_color,
            lit_lane: visuals.selection.bg_fill,
            tappet_on: visuals.strong_text_color(),
            tappet_off: visuals.error_fg_color,
            tappet_invert: visuals.warn_fg_color,
        }
    }
}
