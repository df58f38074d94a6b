//! Damaged corpus files through the whole import: truncated at many offsets, with bytes flipped,
//! deleted, replaced by XML's own punctuation and lines repeated, at positions a seeded generator
//! picks. Nothing may panic, and every error must name a line and column inside the damaged text
//! (`docs/plcopen-xml.md` §1.9). The fuzz target `import` (`plcopen/fuzz`) does the same with
//! coverage guidance; this test runs on the stable toolchain in every CI run.

use std::panic::{AssertUnwindSafe, catch_unwind};

use super::import;
use crate::read_bytes;
use crate::reader::corpus_tests::corpora;

/// The files damaged: Beremiz's (every body language), matiec's LD and SFC tests (v1.0).
const FILES: [&str; 3] = [
    "plcopen/beremiz/exemples/first_steps/plc.xml",
    "matiec/tests/LD_TEST.xml",
    "matiec/tests/SFC_TEST.xml",
];

/// Damaged copies made of each file, per kind of damage.
const CASES_PER_KIND: usize = 40;

/// A small seeded generator (SplitMix64), so every run damages the same places.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number below `bound` (which must not be 0).
    fn below(&mut self, bound: usize) -> usize {
        (self.next() % bound as u64) as usize
    }
}

/// A way to damage a file: the damaged copy of the original, made with the generator.
type Damage = fn(&[u8], &mut SplitMix) -> Vec<u8>;

/// The ways a file is damaged, by name.
const DAMAGES: [(&str, Damage); 5] = [
    ("truncated", |bytes, random| {
        bytes[..random.below(bytes.len())].to_vec()
    }),
    ("byte flipped", |bytes, random| {
        let mut damaged = bytes.to_vec();
        let at = random.below(bytes.len());
        damaged[at] ^= 1 << random.below(8);
        damaged
    }),
    ("byte deleted", |bytes, random| {
        let mut damaged = bytes.to_vec();
        damaged.remove(random.below(bytes.len()));
        damaged
    }),
    ("byte replaced by punctuation", |bytes, random| {
        let mut damaged = bytes.to_vec();
        let punctuation = b"<>/=\"'&;!?- 0x\n";
        damaged[random.below(bytes.len())] = punctuation[random.below(punctuation.len())];
        damaged
    }),
    // A repeated line repeats objects, local ids, names and connections.
    ("line repeated", |bytes, random| {
        let starts: Vec<usize> = std::iter::once(0)
            .chain(
                bytes
                    .iter()
                    .enumerate()
                    .filter(|(_, byte)| **byte == b'\n')
                    .map(|(at, _)| at + 1),
            )
            .collect();
        let line = random.below(starts.len());
        let start = starts[line];
        let end = starts.get(line + 1).copied().unwrap_or(bytes.len());
        let mut damaged = bytes[..end].to_vec();
        damaged.extend_from_slice(&bytes[start..]);
        damaged
    }),
];

/// Reads and converts `bytes`; an error must lie inside the text. Returns the error's text.
fn check(bytes: &[u8], what: &str) -> Option<String> {
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        match read_bytes(bytes, "damaged.xml") {
            Err(error) => Some((error.line, error.column, error.to_string())),
            Ok(document) => import(&document)
                .err()
                .map(|error| (error.line, error.column, error.to_string())),
        }
    }));
    let Ok(error) = outcome else {
        panic!("{what}: the import panicked");
    };
    let (line, column, message) = error?;
    let text = String::from_utf8_lossy(bytes);
    let lines: Vec<&str> = text.split('\n').collect();
    assert!(
        line >= 1 && (line as usize) <= lines.len(),
        "{what}: line {line} of {}: {message}",
        lines.len()
    );
    let characters = lines[line as usize - 1].chars().count();
    assert!(
        column >= 1 && (column as usize) <= characters + 1,
        "{what}: column {column} of {characters} characters: {message}"
    );
    Some(message)
}

#[test]
fn damaged_corpus_files_never_panic_and_their_errors_lie_inside_the_text() {
    let mut random = SplitMix(18);
    for file in FILES {
        let path = corpora().join(file);
        let bytes = std::fs::read(&path).unwrap_or_else(|error| panic!("{file}: {error}"));
        assert!(check(&bytes, file).is_none(), "{file} imports undamaged");
        for (kind, damage) in DAMAGES {
            let mut refused = 0;
            for case in 0..CASES_PER_KIND {
                let damaged = damage(&bytes, &mut random);
                let what = format!("{file}, {kind}, case {case}");
                refused += usize::from(check(&damaged, &what).is_some());
            }
            // The test must damage, not only copy: most truncations are refused.
            if kind == "truncated" {
                assert!(
                    refused > CASES_PER_KIND * 9 / 10,
                    "{file}: {refused} refused"
                );
            }
        }
    }
}
