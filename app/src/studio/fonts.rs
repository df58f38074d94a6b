//! Fonts: egui's defaults plus a CJK fallback so Chinese text renders everywhere.

use std::sync::Arc;

use egui::{FontData, FontDefinitions, FontFamily};

/// The name under which the CJK fallback font is registered.
const CJK_FONT: &str = "droid_sans_fallback";

/// Installs egui's default fonts with Droid Sans Fallback behind them in every family, so
/// Chinese names, comments and interface text render in proportional and monospace text alike.
pub fn install_fonts(ctx: &egui::Context) {
    let mut fonts = FontDefinitions::default();
    fonts.font_data.insert(
        CJK_FONT.to_owned(),
        Arc::new(FontData::from_static(assets::CJK_FONT_TTF)),
    );
    for family in [FontFamily::Proportional, FontFamily::Monospace] {
        fonts
            .families
            .entry(family)
            .or_default()
            .push(CJK_FONT.to_owned());
    }
    ctx.set_fonts(fonts);
}
