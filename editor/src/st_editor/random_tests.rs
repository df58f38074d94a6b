//! Random input against the editor: whatever the keys, texts and offsets, it never panics and
//! the changes it reports always turn the app's copy into its own text.

use std::ops::Range;

use egui::epaint::text::MissingGlyphPolicy;
use egui::{Event, Key, Modifiers};
use egui_kittest::Harness;
use proptest::prelude::*;

use super::*;

/// One thing a user or the app does.
#[derive(Clone, Debug)]
enum Action {
    Type(String),
    Press(Modifiers, Key),
    Paste(String),
    Cut,
    Reveal(Range<usize>),
    Diagnose(Range<usize>),
    ShowValue(Range<usize>),
    Fold(usize),
    SetText(String),
    ReadOnly(bool),
}

fn text() -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop::sample::select(vec![
            "a", "IF ", "THEN", "\n", "END_IF;", "(", ")", " ", "计数", "'s'", "(* c *)", "\r\n",
            "x := 1;", ".", "\t",
        ]),
        0..12,
    )
    .prop_map(|parts| parts.concat())
}

fn action() -> impl Strategy<Value = Action> {
    let keys = prop::sample::select(vec![
        Key::ArrowLeft,
        Key::ArrowRight,
        Key::ArrowUp,
        Key::ArrowDown,
        Key::Home,
        Key::End,
        Key::PageUp,
        Key::PageDown,
        Key::Enter,
        Key::Backspace,
        Key::Delete,
        Key::Tab,
        Key::Escape,
        Key::Space,
        Key::A,
        Key::F,
        Key::F3,
        Key::F12,
        Key::Z,
    ]);
    let modifiers = prop::sample::select(vec![
        Modifiers::NONE,
        Modifiers::SHIFT,
        Modifiers::COMMAND,
        Modifiers::CTRL,
        Modifiers::COMMAND | Modifiers::SHIFT,
    ]);
    let range = (0usize..200, 0usize..200).prop_map(|(a, b)| a..b);
    prop_oneof![
        4 => prop::sample::select(vec!["a", "计", ".", " ", "x"]).prop_map(|s| Action::Type(s.to_owned())),
        6 => (modifiers, keys).prop_map(|(m, k)| Action::Press(m, k)),
        1 => text().prop_map(Action::Paste),
        1 => Just(Action::Cut),
        1 => range.clone().prop_map(Action::Reveal),
        1 => range.clone().prop_map(Action::Diagnose),
        1 => range.prop_map(Action::ShowValue),
        1 => (0usize..20).prop_map(Action::Fold),
        1 => text().prop_map(Action::SetText),
        1 => any::<bool>().prop_map(Action::ReadOnly),
    ]
}

/// The editor and the app's copy of its text.
struct Host {
    editor: StEditor,
    model: String,
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_input_never_panics_and_changes_match_the_text(
        start in text(),
        actions in prop::collection::vec(action(), 1..30),
    ) {
        let mut editor = StEditor::new(&start);
        editor.request_focus();
        let host = Host { editor, model: start };
        let mut harness = Harness::builder()
            .with_size(egui::vec2(600.0, 300.0))
            .with_step_dt(1.0 / 60.0)
            .build_ui_state(
                |ui, host: &mut Host| {
                    ui.ctx().set_missing_glyph_policy(MissingGlyphPolicy::Tofu);
                    let output = host.editor.show(ui, "Body", &KeywordCompletions);
                    TextChange::apply_all(&mut host.model, &output.changes);
                },
                host,
            );
        harness.run_steps(2);
        for action in actions {
            match action {
                Action::Type(text) => harness.event(Event::Text(text)),
                Action::Press(modifiers, key) => harness.key_press_modifiers(modifiers, key),
                Action::Paste(text) => harness.event(Event::Paste(text)),
                Action::Cut => harness.event(Event::Cut),
                Action::Reveal(range) => harness.state_mut().editor.reveal(range),
                Action::Diagnose(range) => harness.state_mut().editor.set_diagnostics(vec![
                    EditorDiagnostic {
                        range,
                        severity: Severity::Error,
                        code: "E0001".to_owned(),
                        message: "m".to_owned(),
                    },
                ]),
                Action::ShowValue(range) => {
                    harness.state_mut().editor.set_inline_values(vec![InlineValue {
                        range,
                        text: "1".to_owned(),
                        changed: true,
                        forced: true,
                    }]);
                }
                Action::Fold(line) => {
                    harness.state_mut().editor.toggle_fold(line);
                }
                Action::SetText(text) => {
                    let host = harness.state_mut();
                    host.editor.set_text(&text);
                    host.model = text;
                }
                Action::ReadOnly(read_only) => harness.state_mut().editor.set_read_only(read_only),
            }
            harness.run_steps(1);
            // The focus may have gone to the find bar; the next keys go to the editor again.
            harness.state_mut().editor.request_focus();
            let host = harness.state();
            prop_assert_eq!(&host.model, host.editor.text());
            prop_assert!(host.editor.caret() <= host.editor.text().len());
            prop_assert!(host.editor.text().is_char_boundary(host.editor.caret()));
        }
    }
}
