//! Appending the protocol's fields to a frame; the counterpart of [`crate::Reader`].

use crate::framing::{MAX_COUNT, MAX_STR8_BYTES};
use crate::place::Place;

/// `text` cut at a character boundary to at most `bytes` bytes.
pub fn cut(text: &str, bytes: usize) -> &str {
    let mut end = text.len().min(bytes);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    &text[..end]
}

/// Appends `text` as an `str8`, cut at a character boundary to [`MAX_STR8_BYTES`], the most
/// its length byte can say.
pub(crate) fn put_str8(out: &mut Vec<u8>, text: &str) {
    let text = cut(text, MAX_STR8_BYTES);
    out.push(text.len() as u8);
    out.extend_from_slice(text.as_bytes());
}

/// Appends a place (8 bytes).
pub(crate) fn put_place(out: &mut Vec<u8>, place: &Place) {
    place.encode(out);
}

/// Appends `count:u8` and the first [`MAX_COUNT`] places.
pub(crate) fn put_places(out: &mut Vec<u8>, places: &[Place]) {
    let places = first(places);
    out.push(places.len() as u8);
    for place in places {
        put_place(out, place);
    }
}

/// Appends `count:u8` and the first [`MAX_COUNT`] places, each followed by its value.
pub(crate) fn put_values(out: &mut Vec<u8>, values: &[(Place, Vec<u8>)]) {
    let values = first(values);
    out.push(values.len() as u8);
    for (place, value) in values {
        put_place(out, place);
        out.extend_from_slice(value);
    }
}

/// The first [`MAX_COUNT`] items: a list's count is one byte, so a longer list is cut.
pub(crate) fn first<T>(items: &[T]) -> &[T] {
    &items[..items.len().min(MAX_COUNT)]
}
