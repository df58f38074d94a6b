//! The plot as a PNG file, cut out of a screenshot of the whole window.

use egui::{ColorImage, Rect};

/// Why a PNG could not be made from a screenshot.
#[derive(Debug, thiserror::Error)]
pub enum PngExportError {
    /// The plot's rectangle lies outside the screenshot or has no area.
    #[error("the plot is not inside the screenshot ({width}×{height} pixels)")]
    EmptyRegion {
        /// The screenshot's width in pixels.
        width: usize,
        /// The screenshot's height in pixels.
        height: usize,
    },
    /// The PNG encoder refused the image.
    #[error("the PNG could not be encoded: {0}")]
    Encoding(#[from] ::png::EncodingError),
}

/// Cuts `rect` (in points, as [`super::TracePlotOutput::export_png`] gives it) out of a
/// screenshot taken at `pixels_per_point` and encodes it as an RGBA PNG.
///
/// The rectangle is widened to whole pixels and clipped to the screenshot, so a plot partly
/// scrolled out of the window exports its visible part.
pub fn crop_to_png(
    screenshot: &ColorImage,
    rect: Rect,
    pixels_per_point: f32,
) -> Result<Vec<u8>, PngExportError> {
    let cropped = crop(screenshot, rect, pixels_per_point).ok_or(PngExportError::EmptyRegion {
        width: screenshot.size[0],
        height: screenshot.size[1],
    })?;
    encode_png(&cropped)
}

/// The pixels of `image` inside `rect` (in points), or `None` when no pixel is inside.
pub fn crop(image: &ColorImage, rect: Rect, pixels_per_point: f32) -> Option<ColorImage> {
    let [width, height] = image.size;
    let to_pixel = |value: f32, round: fn(f32) -> f32, limit: usize| -> usize {
        let pixel = round(value * pixels_per_point);
        // A float cast saturates (a negative or NaN value becomes 0), and the limit keeps the
        // cut inside the image.
        (pixel as usize).min(limit)
    };
    let x0 = to_pixel(rect.min.x, f32::floor, width);
    let x1 = to_pixel(rect.max.x, f32::ceil, width);
    let y0 = to_pixel(rect.min.y, f32::floor, height);
    let y1 = to_pixel(rect.max.y, f32::ceil, height);
    if x1 <= x0 || y1 <= y0 {
        return None;
    }
    let pixels = (y0..y1)
        .flat_map(|y| image.pixels[y * width + x0..y * width + x1].iter().copied())
        .collect();
    Some(ColorImage::new([x1 - x0, y1 - y0], pixels))
}

/// `image` as PNG bytes (8-bit RGBA, colours unmultiplied as PNG stores them).
pub fn encode_png(image: &ColorImage) -> Result<Vec<u8>, PngExportError> {
    let [width, height] = image.size;
    let too_large = || PngExportError::Encoding(::png::EncodingError::LimitsExceeded);
    let width = u32::try_from(width).map_err(|_| too_large())?;
    let height = u32::try_from(height).map_err(|_| too_large())?;
    let rgba: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|pixel| pixel.to_srgba_unmultiplied())
        .collect();
    let mut bytes = Vec::new();
    let mut encoder = ::png::Encoder::new(&mut bytes, width, height);
    encoder.set_color(::png::ColorType::Rgba);
    encoder.set_depth(::png::BitDepth::Eight);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(&rgba)?;
    writer.finish()?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use egui::{Color32, pos2};

    use super::*;

    /// A 6×4 image whose every pixel has a colour of its own, so a shifted cut shows.
    fn numbered_image() -> ColorImage {
        let pixels = (0..4u8)
            .flat_map(|y| (0..6u8).map(move |x| Color32::from_rgb(x * 40, y * 60, 200)))
            .collect();
        ColorImage::new([6, 4], pixels)
    }

    fn decode(bytes: &[u8]) -> ([usize; 2], Vec<u8>) {
        let decoder = ::png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = decoder.read_info().unwrap();
        let mut buffer = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buffer).unwrap();
        assert_eq!(info.color_type, ::png::ColorType::Rgba);
        buffer.truncate(info.buffer_size());
        ([info.width as usize, info.height as usize], buffer)
    }

    #[test]
    fn the_cut_decodes_to_the_pixels_under_the_rect() {
        // At 2 pixels per point, points (1, 0.5)–(2, 1.5) are pixels x 2..4, y 1..3.
        let rect = Rect::from_min_max(pos2(1.0, 0.5), pos2(2.0, 1.5));
        let bytes = crop_to_png(&numbered_image(), rect, 2.0).unwrap();
        let (size, rgba) = decode(&bytes);
        assert_eq!(size, [2, 2]);
        let expected: Vec<u8> = [(2, 1), (3, 1), (2, 2), (3, 2)]
            .into_iter()
            .flat_map(|(x, y)| [x * 40, y * 60, 200, 255])
            .collect();
        assert_eq!(rgba, expected);
    }

    #[test]
    fn a_rect_beyond_the_screenshot_is_clipped() {
        let rect = Rect::from_min_max(pos2(-3.0, 2.0), pos2(100.0, 100.0));
        let cut = crop(&numbered_image(), rect, 1.0).unwrap();
        assert_eq!(cut.size, [6, 2]);
        assert_eq!(cut.pixels[0], Color32::from_rgb(0, 120, 200));
    }

    #[test]
    fn a_rect_outside_the_screenshot_is_an_error() {
        let rect = Rect::from_min_max(pos2(10.0, 10.0), pos2(20.0, 20.0));
        let error = crop_to_png(&numbered_image(), rect, 1.0).unwrap_err();
        assert!(matches!(
            error,
            PngExportError::EmptyRegion {
                width: 6,
                height: 4
            }
        ));
    }
}
