//! The IEC string functions, generic over the character unit: `u8` for `STRING`, `u16` (UTF-16
//! code units) for `WSTRING`.
//!
//! Positions are 1-based and lengths count characters, as in CODESYS and the Delta manual 8.15.
//! The standard calls values outside the string an error; here every input has a defined result,
//! chosen so that no characters are made up and none of the input is lost by surprise:
//! - a negative length counts as 0, and a length beyond the available characters takes what is
//!   there (`LEFT('abc', 5)` is `'abc'`);
//! - `MID` with a position below 1 or beyond the end gives `''` (no characters are taken from
//!   before the string);
//! - `DELETE` with a position below 1 or beyond the end deletes nothing;
//! - `INSERT` with a position below 0 inserts at the front, beyond the end appends;
//! - `REPLACE` with a position below 1 replaces from the front, beyond the end appends;
//! - `FIND` of an empty string gives 0, as a string that is not found does.
//!
//! The results are unbounded by the destination; the engine truncates them with [`store`] or
//! [`store_wide`].
//! Their length is at most the sum of the inputs' lengths, which their declared lengths bound.

/// `LEN(s)`: the number of characters.
pub fn len<C>(s: &[C]) -> i64 {
    s.len() as i64
}

/// `LEFT(s, l)`: the first `l` characters.
pub fn left<C: Copy>(s: &[C], l: i64) -> Vec<C> {
    s[..clamp_count(l, s.len())].to_vec()
}

/// `RIGHT(s, l)`: the last `l` characters.
pub fn right<C: Copy>(s: &[C], l: i64) -> Vec<C> {
    s[s.len() - clamp_count(l, s.len())..].to_vec()
}

/// `MID(s, l, p)`: `l` characters from position `p` (`MID('AaBbCcDd', 2, 3)` is `'Bb'`).
pub fn mid<C: Copy>(s: &[C], l: i64, p: i64) -> Vec<C> {
    match start_index(p, s.len()) {
        Some(start) => {
            let rest = &s[start..];
            rest[..clamp_count(l, rest.len())].to_vec()
        }
        None => Vec::new(),
    }
}

/// `CONCAT(a, b)`: `a` followed by `b`.
pub fn concat<C: Copy>(a: &[C], b: &[C]) -> Vec<C> {
    let mut result = Vec::with_capacity(a.len() + b.len());
    result.extend_from_slice(a);
    result.extend_from_slice(b);
    result
}

/// `INSERT(s1, s2, p)`: `s2` inserted after the `p`-th character of `s1`; `p` = 0 inserts at the
/// front (`INSERT('AaBbCcDd', 'Ee', 2)` is `'AaEeBbCcDd'`).
pub fn insert<C: Copy>(s1: &[C], s2: &[C], p: i64) -> Vec<C> {
    let at = clamp_count(p, s1.len());
    let mut result = Vec::with_capacity(s1.len() + s2.len());
    result.extend_from_slice(&s1[..at]);
    result.extend_from_slice(s2);
    result.extend_from_slice(&s1[at..]);
    result
}

/// `DELETE(s, l, p)`: `s` without the `l` characters from position `p`
/// (`DELETE('AaBbCcDd', 2, 3)` is `'AaCcDd'`).
pub fn delete<C: Copy>(s: &[C], l: i64, p: i64) -> Vec<C> {
    match start_index(p, s.len()) {
        Some(start) => {
            let end = start + clamp_count(l, s.len() - start);
            let mut result = Vec::with_capacity(s.len() - (end - start));
            result.extend_from_slice(&s[..start]);
            result.extend_from_slice(&s[end..]);
            result
        }
        None => s.to_vec(),
    }
}

/// `REPLACE(s1, s2, l, p)`: the `l` characters of `s1` from position `p` replaced by `s2`
/// (`REPLACE('AaBbCcDd', 'DELTA', 2, 3)` is `'AaDELTACcDd'`).
pub fn replace<C: Copy>(s1: &[C], s2: &[C], l: i64, p: i64) -> Vec<C> {
    let start = clamp_count(p.saturating_sub(1), s1.len());
    let end = start + clamp_count(l, s1.len() - start);
    let mut result = Vec::with_capacity(s1.len() - (end - start) + s2.len());
    result.extend_from_slice(&s1[..start]);
    result.extend_from_slice(s2);
    result.extend_from_slice(&s1[end..]);
    result
}

/// `FIND(s1, s2)`: the position of the first occurrence of `s2` in `s1`, or 0 if there is none
/// or `s2` is empty (`FIND('AaBbCcDd', 'Cc')` is 5).
pub fn find<C: PartialEq>(s1: &[C], s2: &[C]) -> i64 {
    if s2.is_empty() || s2.len() > s1.len() {
        return 0;
    }
    s1.windows(s2.len())
        .position(|window| window == s2)
        .map_or(0, |index| index as i64 + 1)
}

/// The characters of a `STRING` in memory: up to the first zero byte or `capacity` characters,
/// whichever comes first (a string without its terminator is not read beyond its declaration).
pub fn load(memory: &[u8], capacity: usize) -> &[u8] {
    let bounded = &memory[..capacity.min(memory.len())];
    let end = bounded
        .iter()
        .position(|&c| c == 0)
        .unwrap_or(bounded.len());
    &bounded[..end]
}

/// Writes `chars` as a `STRING(max_len)` into `dst`: at most `max_len` characters (fewer if
/// `dst` is shorter than `max_len + 1` bytes, or if `chars` holds a zero byte, which would end
/// the string anyway), then a terminating zero.
/// Returns the number of characters written; an empty `dst` is left alone.
pub fn store(dst: &mut [u8], chars: &[u8], max_len: usize) -> usize {
    store_units(dst, chars, max_len)
}

/// The UTF-16 code units of a `WSTRING` in memory (two bytes each, little-endian): up to the
/// first zero unit or `capacity` units.
pub fn load_wide(memory: &[u8], capacity: usize) -> Vec<u16> {
    memory
        .chunks_exact(2)
        .take(capacity)
        .map(|pair| u16::from_le_bytes([pair[0], pair[1]]))
        .take_while(|&unit| unit != 0)
        .collect()
}

/// Writes `units` as a `WSTRING(max_len)` into `dst` (little-endian code units): at most
/// `max_len` units and as many as fit before a terminating zero unit.
/// Returns the number of units written; a `dst` shorter than one unit is left alone.
pub fn store_wide(dst: &mut [u8], units: &[u16], max_len: usize) -> usize {
    let slots = dst.len() / 2;
    if slots == 0 {
        return 0;
    }
    let count = units
        .iter()
        .take(max_len.min(slots - 1))
        .take_while(|&&unit| unit != 0)
        .count();
    for (index, unit) in units[..count].iter().chain(std::iter::once(&0)).enumerate() {
        dst[2 * index..2 * index + 2].copy_from_slice(&unit.to_le_bytes());
    }
    count
}

fn store_units(dst: &mut [u8], chars: &[u8], max_len: usize) -> usize {
    if dst.is_empty() {
        return 0;
    }
    let count = chars
        .iter()
        .take(max_len.min(dst.len() - 1))
        .take_while(|&&c| c != 0)
        .count();
    dst[..count].copy_from_slice(&chars[..count]);
    dst[count] = 0;
    count
}

/// A count clamped to `0..=available`.
fn clamp_count(count: i64, available: usize) -> usize {
    usize::try_from(count.max(0)).map_or(available, |count| count.min(available))
}

/// The index of the 1-based position `p`, if it names a character of a string of `len`.
fn start_index(p: i64, len: usize) -> Option<usize> {
    let index = usize::try_from(p.checked_sub(1)?).ok()?;
    (index < len).then_some(index)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_beyond_the_string_take_what_is_there() {
        assert_eq!(left(b"abc", 5), b"abc");
        assert_eq!(right(b"abc", 5), b"abc");
        assert_eq!(left(b"abc", -1), b"");
        assert_eq!(mid(b"abc", 9, 2), b"bc");
        assert_eq!(delete(b"abc", 9, 2), b"a");
    }

    #[test]
    fn positions_outside_the_string_have_defined_results() {
        assert_eq!(mid(b"abc", 2, 0), b"");
        assert_eq!(mid(b"abc", 2, 4), b"");
        assert_eq!(delete(b"abc", 1, 0), b"abc");
        assert_eq!(delete(b"abc", 1, 4), b"abc");
        assert_eq!(insert(b"abc", b"X", 0), b"Xabc");
        assert_eq!(insert(b"abc", b"X", -3), b"Xabc");
        assert_eq!(insert(b"abc", b"X", 9), b"abcX");
        assert_eq!(replace(b"abc", b"X", 1, 0), b"Xbc");
        assert_eq!(replace(b"abc", b"X", 1, 9), b"abcX");
        assert_eq!(replace(b"abc", b"X", -1, 2), b"aXbc");
    }

    #[test]
    fn find_gives_the_first_position_or_zero() {
        assert_eq!(find(b"abcabc", b"c"), 3);
        assert_eq!(find(b"abc", b""), 0);
        assert_eq!(find(b"ab", b"abc"), 0);
        assert_eq!(find(&[1u16, 2, 3], &[2u16, 3]), 2);
    }

    #[test]
    fn store_truncates_and_terminates() {
        let mut memory = [0xAAu8; 4];
        assert_eq!(store(&mut memory, b"hello", 3), 3);
        assert_eq!(memory, *b"hel\0");
        assert_eq!(load(&memory, 3), b"hel");
        assert_eq!(store(&mut memory, b"hello", 10), 3);
        assert_eq!(store(&mut [], b"hello", 10), 0);
        assert_eq!(load(b"abcdef", 2), b"ab");
    }

    #[test]
    fn wide_strings_are_little_endian_units() {
        let mut memory = [0xAAu8; 6];
        assert_eq!(store_wide(&mut memory, &[0x4E2D, 0x41, 0x42], 5), 2);
        assert_eq!(memory, [0x2D, 0x4E, 0x41, 0, 0, 0]);
        assert_eq!(load_wide(&memory, 2), vec![0x4E2D, 0x41]);
        assert_eq!(store_wide(&mut [0u8; 1], &[1], 1), 0);
    }
}
