//! Checks that UI code holds neither colour literals nor user-visible English: colours come
//! from the theme module (`theme.rs`, which fills the editors' palettes) and words from the
//! translation texts (`i18n/`, and the editors' texts structs the app fills).
//!
//! The check reads the sources of `app/src`, `editor/src` and `cam_editor/src` outside their
//! tests. A user-visible string is a literal (or a `format!` pattern) with a word in it, passed
//! straight to a call that shows text: labels, buttons, headings, hover texts, `RichText`,
//! menus, hint texts, dialog titles, plot items, status messages.

use std::path::{Path, PathBuf};

/// The only files that may hold colour literals.
const THEME_MODULES: [&str; 1] = ["app/src/studio/theme.rs"];

/// Test modules compiled only under `cfg(test)`, which quote what they look for.
const TEST_MODULES: [&str; 2] = [
    "app/src/studio/architecture_tests.rs",
    "app/src/studio/literal_tests.rs",
];

/// Calls whose first argument is shown to the user.
const SHOWING_CALLS: [&str; 28] = [
    ".label(",
    ".button(",
    ".heading(",
    ".strong(",
    ".weak(",
    ".on_hover_text(",
    "RichText::new(",
    ".selectable_label(",
    ".checkbox(",
    ".menu_button(",
    ".small_button(",
    ".hint_text(",
    ".set_title(",
    "Button::new(",
    ".colored_label(",
    ".radio(",
    ".radio_value(",
    ".selectable_value(",
    ".link(",
    "StatusMessage::info(",
    "StatusMessage::error(",
    "commands.status(",
    "commands.error(",
    "Line::new(",
    "VLine::new(",
    "Points::new(",
    ".add_filter(",
    "WidgetInfo::labeled(",
];

/// Words that are no English to translate: the product's name and units.
const ALLOWED_WORDS: [&str; 3] = ["Rivet", "ms", "min"];

/// Colour constants that are no colour: `TRANSPARENT` lays out invisible space.
const ALLOWED_COLORS: [&str; 1] = ["TRANSPARENT"];

/// The source files below `dir`, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut folders = vec![dir.to_owned()];
    while let Some(folder) = folders.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|ext| ext == "rs")
                && path.file_name().is_some_and(|name| name != "tests.rs")
            {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// The text of a source file without its inline test module and its comment lines, with the
/// line breaks kept so offsets still tell the line.
fn code_of(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut kept = Vec::new();
    for (index, line) in lines.iter().enumerate() {
        let next = lines.get(index + 1).map_or("", |next| next.trim());
        if line.trim().starts_with("#[cfg(test)]")
            && next.starts_with("mod ")
            && next.ends_with('{')
        {
            break;
        }
        kept.push(if line.trim().starts_with("//") {
            ""
        } else {
            line
        });
    }
    kept.join("\n")
}

/// The words of a string literal a user would read: escapes and `{…}` placeholders removed,
/// IEC names in capitals (`GVL`, `VAR_GLOBAL`) and the allowed words left out.
fn words_to_translate(literal: &str) -> Vec<String> {
    // A shortcut (`Alt+F7`) or an example variable path (`Main.fbConveyor.xMotorOn`) is a name,
    // not a sentence.
    let is_shortcut = ["Ctrl+", "Alt+", "Shift+"]
        .iter()
        .any(|prefix| literal.starts_with(prefix))
        && !literal.contains(' ');
    let is_path = literal.contains('.') && !literal.contains(' ') && !literal.contains('{');
    if is_shortcut || is_path {
        return Vec::new();
    }
    let mut text = literal.replace("\\n", " ").replace("\\t", " ");
    while let (Some(open), Some(close)) = (text.find('{'), text.find('}')) {
        if close < open {
            break;
        }
        text.replace_range(open..=close, " ");
    }
    text.split(|c: char| !c.is_ascii_alphabetic())
        .filter(|word| word.len() >= 2)
        .filter(|word| !word.chars().all(|c| c.is_ascii_uppercase()))
        .filter(|word| !ALLOWED_WORDS.contains(word))
        .map(str::to_owned)
        .collect()
}

/// The 1-based line of a byte offset.
fn line_of(code: &str, offset: usize) -> usize {
    code[..offset].matches('\n').count() + 1
}

/// What a source file breaks: `file:line: …` for every colour literal (unless `theme` allows
/// them) and every user-visible English literal.
fn findings(file: &str, text: &str, theme: bool) -> Vec<String> {
    let code = code_of(text);
    let mut found = Vec::new();
    if !theme {
        for (at, _) in code.match_indices("Color32::") {
            let rest = &code[at + "Color32::".len()..];
            let name: String = rest
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            let constant = name.chars().all(|c| c.is_ascii_uppercase() || c == '_')
                && !name.is_empty()
                && !ALLOWED_COLORS.contains(&name.as_str());
            let literal_arguments = name.starts_with("from_")
                && rest[name.len()..]
                    .trim_start_matches(['(', ' ', '\n'])
                    .starts_with(|c: char| c.is_ascii_digit());
            if constant || literal_arguments {
                found.push(format!(
                    "{file}:{}: colour literal Color32::{name}",
                    line_of(&code, at)
                ));
            }
        }
    }
    for call in SHOWING_CALLS {
        for (at, _) in code.match_indices(call) {
            let mut rest = code[at + call.len()..].trim_start();
            if let Some(pattern) = rest.strip_prefix("format!(") {
                rest = pattern.trim_start();
            }
            let Some(literal) = rest.strip_prefix('"') else {
                continue;
            };
            let end = literal
                .char_indices()
                .scan(false, |escaped, (index, c)| {
                    let quote = c == '"' && !*escaped;
                    *escaped = c == '\\' && !*escaped;
                    Some((index, quote))
                })
                .find(|(_, quote)| *quote)
                .map_or(literal.len(), |(index, _)| index);
            let literal = &literal[..end];
            let words = words_to_translate(literal);
            if !words.is_empty() {
                found.push(format!(
                    "{file}:{}: user-visible text {literal:?} (words {words:?}) belongs in the translations",
                    line_of(&code, at)
                ));
            }
        }
    }
    found
}

#[test]
fn ui_code_holds_no_colour_literals_and_no_untranslated_words() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map(Path::to_owned)
        .unwrap_or_default();
    let mut found = Vec::new();
    let mut files = 0;
    for root in ["app/src", "editor/src", "cam_editor/src"] {
        for path in rust_files(&workspace.join(root)) {
            let relative = path
                .strip_prefix(&workspace)
                .unwrap_or(&path)
                .to_string_lossy()
                .replace('\\', "/");
            if TEST_MODULES.contains(&relative.as_str()) {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            let theme = THEME_MODULES.contains(&relative.as_str());
            found.extend(findings(&relative, &text, theme));
            files += 1;
        }
    }
    assert!(files > 100, "the sources were not found ({files} files)");
    assert!(found.is_empty(), "{}", found.join("\n"));
}

#[test]
fn a_colour_literal_outside_the_theme_is_found_with_its_line() {
    let text = "fn a() {}\nlet c = Color32::from_rgb(200, 40, 40);\nlet d = Color32::RED;\n";
    assert_eq!(
        findings("x.rs", text, false),
        vec![
            "x.rs:2: colour literal Color32::from_rgb".to_owned(),
            "x.rs:3: colour literal Color32::RED".to_owned()
        ]
    );
    assert!(findings("theme.rs", text, true).is_empty());
    // A colour computed from values is no literal, and transparent space is no colour.
    let computed = "Color32::from_rgb(r, g, b); Color32::TRANSPARENT";
    assert!(findings("x.rs", computed, false).is_empty());
}

#[test]
fn english_passed_to_a_label_is_found_but_names_and_units_are_not() {
    let text = "ui.label(\"Kind\");\nui.on_hover_text(\"Alt+F7\");\n\
                ui.label(format!(\"{} ms\", n));\nui.label(Text::Kind.get(l));\n\
                ui.heading(\n    \"Not translated\",\n);\nui.label(\"VAR_GLOBAL\");\n";
    let found = findings("x.rs", text, false);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found[0].starts_with("x.rs:1: user-visible text \"Kind\""));
    assert!(found[1].starts_with("x.rs:5: user-visible text \"Not translated\""));
}
