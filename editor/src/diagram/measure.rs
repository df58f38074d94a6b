//! How wide texts are in the grid, so both layouts size cells and boxes from what they show.
//!
//! The layouts are pure functions without access to fonts, so the diagram draws its operands,
//! pin names and box titles in the monospace font, whose advance is the same for every
//! character: a text's width is its character count times one advance. Operands longer than
//! [`MAX_OPERAND_CHARS`] are shortened with "…" (the full text is the element's tooltip).

use super::paint::CELL_SIZE_PX;

/// The longest operand shown in full, in characters; longer ones are shortened with "…".
pub(crate) const MAX_OPERAND_CHARS: usize = 24;
/// The size of an operand's and a box title's font at zoom 1, in points.
pub(crate) const OPERAND_FONT_PX: f32 = 11.0;
/// The size of a pin name's font at zoom 1, in points.
pub(crate) const PIN_FONT_PX: f32 = 10.0;
/// The advance of a monospace character per point of font size (Hack, the egui default, and
/// the studio's monospace font are 0.6 em; a little more leaves room for rounding).
const ADVANCE_PER_FONT_PX: f32 = 0.62;
/// The space left and right of a text inside its cell, in points.
const TEXT_PADDING_PX: f32 = 4.0;
/// The room left and right of a box's frame for the pins' leads, in points.
pub(crate) const BOX_LEAD_PX: f32 = 10.0;
/// The space between an input pin's name and an output pin's name on one row of a box.
const PIN_GAP_PX: f32 = 12.0;

/// The advance of a character outside ASCII (a CJK fallback glyph, about one em wide), in
/// monospace advances.
const WIDE_CHAR_ADVANCES: f32 = 1.7;

/// The width of `text` in monospace advances: one per ASCII character, more for the wide
/// glyphs of the CJK fallback font a Chinese name is drawn with.
fn advances(text: impl Iterator<Item = char>) -> f32 {
    text.map(|c| {
        if c.is_ascii() {
            1.0
        } else {
            WIDE_CHAR_ADVANCES
        }
    })
    .sum()
}

/// The width of `text` in the operand font, in points, once shortened.
pub(crate) fn operand_width_px(text: &str) -> f32 {
    advances(text.chars().take(MAX_OPERAND_CHARS)) * OPERAND_FONT_PX * ADVANCE_PER_FONT_PX
}

/// The width in cells of an operand's cell: its text with padding, at least `min_cells`.
pub(crate) fn operand_cells(text: &str, min_cells: f32) -> f32 {
    let px = operand_width_px(text) + 2.0 * TEXT_PADDING_PX;
    (px / CELL_SIZE_PX.x).max(min_cells)
}

/// The width in cells of a box with `title` (its type), `instance` above it, and pins named
/// `inputs` on the left and `outputs` on the right, including the pins' leads; at least
/// `min_cells`.
pub(crate) fn box_cells<'a>(
    title: &str,
    instance: &str,
    inputs: impl Iterator<Item = &'a str>,
    outputs: impl Iterator<Item = &'a str>,
    min_cells: f32,
) -> f32 {
    let pin_px = |name: &str| advances(name.chars()) * PIN_FONT_PX * ADVANCE_PER_FONT_PX;
    let widest =
        |names: &mut dyn Iterator<Item = &'a str>| names.map(&pin_px).fold(0.0_f32, f32::max);
    let (mut inputs, mut outputs) = (inputs, outputs);
    let (inputs_px, outputs_px) = (widest(&mut inputs), widest(&mut outputs));
    // The title shares the first row with the first pins' names, between them.
    let title_row_px = if operand_width_px(title) > 0.0 {
        inputs_px + operand_width_px(title) + outputs_px + 2.0 * PIN_GAP_PX
    } else {
        inputs_px + PIN_GAP_PX + outputs_px
    };
    let frame_px = title_row_px.max(operand_width_px(instance)) + 2.0 * TEXT_PADDING_PX;
    ((frame_px + 2.0 * BOX_LEAD_PX) / CELL_SIZE_PX.x).max(min_cells)
}

/// `text` shortened to [`MAX_OPERAND_CHARS`] with "…", and whether it was shortened.
pub(crate) fn shortened(text: &str) -> (std::borrow::Cow<'_, str>, bool) {
    if text.chars().count() <= MAX_OPERAND_CHARS {
        (std::borrow::Cow::Borrowed(text), false)
    } else {
        let mut short: String = text.chars().take(MAX_OPERAND_CHARS - 1).collect();
        short.push('…');
        (std::borrow::Cow::Owned(short), true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_operand_cell_grows_with_its_text_up_to_the_longest_shown() {
        assert_eq!(operand_cells("a", 1.0), 1.0);
        let twenty = operand_cells(&"x".repeat(20), 1.0);
        assert!(
            twenty > 1.0,
            "20 characters need more than a cell: {twenty}"
        );
        assert!(operand_cells(&"x".repeat(21), 1.0) > twenty);
        let longest = operand_cells(&"x".repeat(MAX_OPERAND_CHARS), 1.0);
        assert_eq!(operand_cells(&"x".repeat(60), 1.0), longest);
    }

    #[test]
    fn a_chinese_name_is_measured_wider_than_as_many_latin_letters() {
        assert!(operand_width_px("电机启动") > operand_width_px("abcd"));
    }

    #[test]
    fn a_box_is_as_wide_as_its_widest_row_of_pin_names_or_its_title() {
        let narrow = box_cells("AND", "", ["", ""].into_iter(), [""].into_iter(), 0.0);
        let timer = box_cells(
            "TON",
            "",
            ["IN", "PT"].into_iter(),
            ["Q", "ET"].into_iter(),
            0.0,
        );
        assert!(narrow < timer, "{narrow} < {timer}");
        let long_pin = box_cells(
            "TON",
            "",
            ["IN", "PRESET_TIME"].into_iter(),
            ["Q", "ET"].into_iter(),
            0.0,
        );
        assert!(timer < long_pin, "{timer} < {long_pin}");
        let long_title = box_cells(
            "A_VERY_LONG_BLOCK_NAME",
            "",
            [].into_iter(),
            [].into_iter(),
            0.0,
        );
        assert!(timer < long_title, "{timer} < {long_title}");
        assert_eq!(
            box_cells("AND", "", [].into_iter(), [].into_iter(), 2.0),
            2.0
        );
    }

    #[test]
    fn only_operands_longer_than_the_limit_are_shortened() {
        let limit = "y".repeat(MAX_OPERAND_CHARS);
        assert_eq!(shortened(&limit), (limit.as_str().into(), false));
        let longer = format!("{limit}z");
        let (short, cut) = shortened(&longer);
        assert!(cut);
        assert_eq!(short.chars().count(), MAX_OPERAND_CHARS);
        assert!(short.ends_with('…'));
    }
}
