//! Checks that UI code holds neither colour literals nor user-visible English: colours come
//! from the theme module (`theme.rs`, which fills the editors' palettes) and words from the
//! translation texts (`i18n/`, and the editors' texts structs the app fills).
//!
//! The check reads the sources of `app/src`, `editor/src` and `cam_editor/src` outside their
//! tests. A user-visible string is a literal (or a `format!` pattern) with a word in it, passed
//! straight to a call that shows text: labels, buttons, headings, hover texts, `RichText`,
//! menus, hint texts, dialog titles, plot items, status messages.
//! Labels are checked too: undo labels, accessible labels and the studio's refusals, in every
//! argument at the call's own level (the keys of `Text::fill` are nested and left alone).

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

/// Places where a label the user reads starts: an undo label (`Command::Edit`, a plan's or a
/// text edit's `label:` field, the `(label, edit)` pairs pushed for later, the trace pane's
/// `replace(commands, label, …)`, `apply_edits`) or an accessible label (`WidgetInfo::labeled`).
/// Every argument at the call's own level is checked, not only the first.
/// `Err(` (a refusal the user reads) counts only in the studio: the command line's refusals
/// are English by design.
const LABEL_SITES: [&str; 7] = [
    "Err(",
    "Command::Edit(",
    "label: ",
    ".push((",
    "commands,",
    "apply_edits(",
    "WidgetInfo::labeled(",
];

/// Words that are no English to translate: the product's name and units.
const ALLOWED_WORDS: [&str; 3] = ["Rivet", "ms", "min"];

/// Colour constants that are no colour: `TRANSPARENT` lays out invisible space.
const ALLOWED_COLORS: [&str; 1] = ["TRANSPARENT"];

/// The source files below `dir` but the `tests.rs` modules, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = super::architecture_tests::rust_files(dir);
    files.retain(|path| path.file_name().is_some_and(|name| name != "tests.rs"));
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

/// The end of the string literal that starts right after an opening quote in `literal`.
fn literal_end(literal: &str) -> usize {
    literal
        .char_indices()
        .scan(false, |escaped, (index, c)| {
            let quote = c == '"' && !*escaped;
            *escaped = c == '\\' && !*escaped;
            Some((index, quote))
        })
        .find(|(_, quote)| *quote)
        .map_or(literal.len(), |(index, _)| index)
}

/// The string literals passed at the top level of the argument list that starts at `rest`
/// (a literal itself, or the pattern of a `format!`), up to the list's closing bracket or, for a
/// field (`label: …`), the end of its value. Literals nested in other calls (`fill`'s keys,
/// `vec![…]`) are not labels and are left out.
fn top_level_literals(rest: &str, field: bool) -> Vec<(usize, &str)> {
    let mut found = Vec::new();
    let mut depth = 0usize;
    let mut at = 0;
    while at < rest.len() {
        let tail = &rest[at..];
        let c = tail.chars().next().unwrap_or(' ');
        if c == '"' {
            let end = literal_end(&tail[1..]);
            if depth == 0 {
                found.push((at, &tail[1..1 + end]));
            }
            at += end + 2;
            continue;
        }
        if depth == 0 && tail.starts_with("format!(") {
            let open = tail.find('(').unwrap_or(0);
            let pattern = tail[open + 1..].trim_start();
            if let Some(literal) = pattern.strip_prefix('"') {
                found.push((at, &literal[..literal_end(literal)]));
            }
        }
        match c {
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' if depth == 0 => break,
            ')' | ']' | '}' => depth -= 1,
            ',' | ';' if field && depth == 0 => break,
            _ => {}
        }
        at += c.len_utf8();
    }
    found
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
            let literal = &literal[..literal_end(literal)];
            let words = words_to_translate(literal);
            if !words.is_empty() {
                found.push(format!(
                    "{file}:{}: user-visible text {literal:?} (words {words:?}) belongs in the translations",
                    line_of(&code, at)
                ));
            }
        }
    }
    for site in LABEL_SITES {
        if site == "Err(" && !file.starts_with("app/src/studio/") {
            continue;
        }
        for (at, _) in code.match_indices(site) {
            let rest = &code[at + site.len()..];
            for (offset, literal) in top_level_literals(rest, site == "label: ") {
                let words = words_to_translate(literal);
                if !words.is_empty() {
                    found.push(format!(
                        "{file}:{}: label {literal:?} (words {words:?}) belongs in the translations",
                        line_of(&code, at + site.len() + offset)
                    ));
                }
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

#[test]
fn english_undo_and_accessible_labels_are_found_but_template_keys_are_not() {
    let text = "commands.push(Command::Edit(format!(\"Watch {path}\"), edits));\n\
                let plan = Plan { label: format!(\"Delete {name}\"), edits };\n\
                changes.push((format!(\"Add task {name}\"), edit));\n\
                replace(commands, \"Change the sampling\", changed, true);\n\
                WidgetInfo::labeled(Role::TextInput, true, format!(\"Prepared value of {}\", p));\n\
                replace(\ncommands,\n&format!(\"Stop tracing {}\", gone.path),\nchanged,\n);\n\
                let label = Text::UndoWatch.fill(language, &[(\"path\", &path)]);\n\
                commands.push(Command::Edit(label, vec![Edit::Rename(\"name\".into())]));\n\
                Plan { label: Text::UndoDelete.fill(language, &[(\"name\", &name)]), edits };\n";
    let found = findings("x.rs", text, false);
    let mut lines: Vec<&str> = found
        .iter()
        .map(|finding| finding.split(": label").next().unwrap_or(""))
        .collect();
    lines.sort_unstable();
    let refusal = "return Err(format!(\"'{input}' is not a priority\"));\nErr(reason) => {}\n";
    assert_eq!(findings("app/src/studio/x.rs", refusal, false).len(), 1);
    assert!(findings("app/src/cli.rs", refusal, false).is_empty());
    assert_eq!(
        lines,
        ["x.rs:1", "x.rs:2", "x.rs:3", "x.rs:4", "x.rs:5", "x.rs:8"],
        "{found:?}"
    );
}
