//! Bytes to text: UTF-8 (with or without a byte order mark) and UTF-16 (with a byte order mark,
//! or without one when the text starts with `<`).

use std::borrow::Cow;

use super::MAX_FILE_BYTES;
use crate::error::{ReadError, ReadErrorKind};

/// The error for a file over the size limit; `size_bytes` is `None` when the file's size is not
/// known (the reader stopped reading past the limit).
pub(super) fn too_large(file_name: &str, size_bytes: Option<usize>) -> ReadError {
    ReadError {
        file: file_name.to_owned(),
        line: 1,
        column: 1,
        path: String::new(),
        kind: ReadErrorKind::TooLarge {
            size_bytes,
            limit_bytes: MAX_FILE_BYTES,
        },
    }
}

/// The text of a file's bytes, without a byte order mark.
pub(super) fn decode<'b>(bytes: &'b [u8], file_name: &str) -> Result<Cow<'b, str>, ReadError> {
    if bytes.len() > MAX_FILE_BYTES {
        return Err(too_large(file_name, Some(bytes.len())));
    }
    if let Some(rest) = bytes.strip_prefix(&[0xFF, 0xFE]) {
        return decode_utf16(rest, file_name, u16::from_le_bytes).map(Cow::Owned);
    }
    if let Some(rest) = bytes.strip_prefix(&[0xFE, 0xFF]) {
        return decode_utf16(rest, file_name, u16::from_be_bytes).map(Cow::Owned);
    }
    // UTF-16 without a byte order mark still starts with `<`, which tells the byte order.
    if bytes.starts_with(&[b'<', 0]) {
        return decode_utf16(bytes, file_name, u16::from_le_bytes).map(Cow::Owned);
    }
    if bytes.starts_with(&[0, b'<']) {
        return decode_utf16(bytes, file_name, u16::from_be_bytes).map(Cow::Owned);
    }
    let bytes = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]).unwrap_or(bytes);
    std::str::from_utf8(bytes)
        .map(Cow::Borrowed)
        .map_err(|error| {
            let (line, column) = line_and_column(&bytes[..error.valid_up_to()]);
            ReadError {
                file: file_name.to_owned(),
                line,
                column,
                path: String::new(),
                kind: ReadErrorKind::NotUtf8,
            }
        })
}

/// UTF-16 code units in the given byte order to text.
fn decode_utf16(
    bytes: &[u8],
    file_name: &str,
    unit: fn([u8; 2]) -> u16,
) -> Result<String, ReadError> {
    let units = bytes.chunks(2).map(|pair| match pair {
        [first, second] => unit([*first, *second]),
        // An odd byte at the end cannot be a code unit; an unpaired surrogate makes it an error.
        _ => 0xD800,
    });
    let mut text = String::with_capacity(bytes.len() / 2);
    for decoded in char::decode_utf16(units) {
        match decoded {
            Ok(character) => text.push(character),
            Err(_) => {
                let (line, column) = line_and_column(text.as_bytes());
                return Err(ReadError {
                    file: file_name.to_owned(),
                    line,
                    column,
                    path: String::new(),
                    kind: ReadErrorKind::NotUtf16,
                });
            }
        }
    }
    Ok(text)
}

/// The line and column (1-based) just after valid UTF-8 `text`.
pub(super) fn line_and_column(text: &[u8]) -> (u32, u32) {
    let before = String::from_utf8_lossy(text);
    let line = before.matches('\n').count() + 1;
    let column = before
        .rsplit('\n')
        .next()
        .map_or(0, |last| last.chars().count())
        + 1;
    (
        u32::try_from(line).unwrap_or(u32::MAX),
        u32::try_from(column).unwrap_or(u32::MAX),
    )
}
