//! Tests of the editor driven through egui, as a user would: keys, text and clipboard events.
//! Each test keeps a model string the way the app would, applies the reported changes to it,
//! and checks that it ends equal to the editor's own text.

use std::ops::Range;

use egui::epaint::text::MissingGlyphPolicy;
use egui::{Event, Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;

use super::*;

/// Services with a fixed list of names, as the app's project services would give.
struct FakeServices;

impl LanguageServices for FakeServices {
    fn completions(&self, _text: &str, _offset: usize) -> Vec<CompletionItem> {
        ["counter", "count_max", "motor_on"]
            .into_iter()
            .map(|label| CompletionItem {
                label: label.to_owned(),
                kind: CompletionKind::Variable,
                detail: "INT".to_owned(),
            })
            .collect()
    }

    fn hover(&self, _text: &str, _offset: usize) -> Option<String> {
        Some("counter : INT".to_owned())
    }
}

/// What the app would keep: the editor, its own copy of the text and what came out.
struct Host {
    editor: StEditor,
    model: String,
    gestures: Vec<Gesture>,
    change_lists: Vec<Vec<TextChange>>,
    undo_left_for_app: bool,
    prepared: Option<(Range<usize>, String)>,
    breakpoint_toggles: Vec<usize>,
}

fn harness(text: &str, caret: usize) -> Harness<'static, Host> {
    let mut editor = StEditor::new(text);
    editor.reveal(caret..caret);
    editor.request_focus();
    let host = Host {
        editor,
        model: text.to_owned(),
        gestures: Vec::new(),
        change_lists: Vec::new(),
        undo_left_for_app: false,
        prepared: None,
        breakpoint_toggles: Vec::new(),
    };
    let mut harness = Harness::builder()
        .with_size(egui::vec2(800.0, 600.0))
        // Short steps, so two clicks in a row are a double-click.
        .with_step_dt(1.0 / 60.0)
        .build_ui_state(
            |ui, host: &mut Host| {
                // The editor crate bundles no CJK font (the studio installs one), so Chinese
                // text is drawn as boxes here rather than failing the test.
                ui.ctx().set_missing_glyph_policy(MissingGlyphPolicy::Tofu);
                let output = host.editor.show(ui, "Body of Main", &FakeServices);
                TextChange::apply_all(&mut host.model, &output.changes);
                if !output.changes.is_empty() {
                    host.change_lists.push(output.changes);
                }
                host.gestures.extend(output.gesture);
                host.breakpoint_toggles.extend(output.toggle_breakpoint);
                if output.prepared.is_some() {
                    host.prepared = output.prepared;
                }
                if ui.input_mut(|input| input.consume_key(Modifiers::COMMAND, Key::Z)) {
                    host.undo_left_for_app = true;
                }
            },
            host,
        );
    harness.run_steps(2);
    harness
}

fn type_text(harness: &mut Harness<'_, Host>, text: &str) {
    for c in text.chars() {
        harness.event(Event::Text(c.to_string()));
        harness.run_steps(1);
    }
}

fn press(harness: &mut Harness<'_, Host>, modifiers: Modifiers, key: Key) {
    harness.key_press_modifiers(modifiers, key);
    harness.run_steps(2);
}

#[track_caller]
fn check_model(harness: &Harness<'_, Host>) {
    assert_eq!(harness.state().model, harness.state().editor.text());
}

#[test]
fn the_editor_has_its_accessible_label() {
    let harness = harness("x := 1;", 0);
    let _node = harness.get_by_label("Body of Main");
}

#[test]
fn typed_text_is_inserted_and_reported_as_one_typing_run() {
    let mut harness = harness("x := 1;\n", 7);
    type_text(&mut harness, " // 计数");
    assert_eq!(harness.state().editor.text(), "x := 1; // 计数\n");
    check_model(&harness);
    let gestures = &harness.state().gestures;
    assert_eq!(gestures.len(), 6);
    assert!(gestures.iter().all(|gesture| *gesture == gestures[0]));
    assert!(matches!(gestures[0], Gesture::Typing { .. }));
}

#[test]
fn text_committed_by_an_input_method_is_inserted() {
    let mut harness = harness("x := 1;", 7);
    harness.event(Event::Ime(egui::ImeEvent::Commit(" // 计数器".to_owned())));
    harness.run_steps(2);
    assert_eq!(harness.state().editor.text(), "x := 1; // 计数器");
    check_model(&harness);
}

#[test]
fn text_being_composed_is_not_in_the_text_until_committed() {
    let mut harness = harness("x := 1;", 7);
    harness.event(Event::Ime(egui::ImeEvent::Preedit {
        text: "ji".to_owned(),
        active_range_chars: None,
    }));
    harness.run_steps(2);
    assert_eq!(harness.state().editor.preedit, "ji");
    assert!(harness.state().change_lists.is_empty());
    harness.event(Event::Ime(egui::ImeEvent::Commit("计".to_owned())));
    harness.run_steps(2);
    assert_eq!(harness.state().editor.preedit, "");
    assert_eq!(harness.state().editor.text(), "x := 1;计");
    check_model(&harness);
}

#[test]
fn enter_keeps_the_indentation_and_indents_after_then() {
    let text = "IF a THEN\n    b := 1;\nEND_IF;";
    let mut harness = harness(text, 18);
    press(&mut harness, Modifiers::NONE, Key::End);
    press(&mut harness, Modifiers::NONE, Key::Enter);
    type_text(&mut harness, "c");
    assert_eq!(
        harness.state().editor.text(),
        "IF a THEN\n    b := 1;\n    c\nEND_IF;"
    );
    press(&mut harness, Modifiers::COMMAND, Key::Home);
    press(&mut harness, Modifiers::NONE, Key::End);
    press(&mut harness, Modifiers::NONE, Key::Enter);
    assert!(
        harness
            .state()
            .editor
            .text()
            .starts_with("IF a THEN\n    \n    b")
    );
    check_model(&harness);
    assert!(harness.state().gestures.contains(&Gesture::Other));
}

#[test]
fn a_block_closer_typed_on_its_own_line_moves_under_its_opener() {
    let text = "IF a THEN\n    b := 1;";
    let mut harness = harness(text, text.len());
    press(&mut harness, Modifiers::NONE, Key::Enter);
    type_text(&mut harness, "ELSE");
    assert_eq!(
        harness.state().editor.text(),
        "IF a THEN\n    b := 1;\nELSE"
    );
    press(&mut harness, Modifiers::NONE, Key::Enter);
    type_text(&mut harness, "c;");
    press(&mut harness, Modifiers::NONE, Key::Enter);
    type_text(&mut harness, "end_if");
    assert_eq!(
        harness.state().editor.text(),
        "IF a THEN\n    b := 1;\nELSE\n    c;\nend_if"
    );
    // A closer already under its opener stays where it is.
    type_text(&mut harness, ";");
    press(&mut harness, Modifiers::NONE, Key::Home);
    type_text(&mut harness, "x");
    assert!(harness.state().editor.text().ends_with("\nxend_if;"));
    check_model(&harness);
}

#[test]
fn backspace_and_delete_remove_one_char_even_a_chinese_one() {
    let mut harness = harness("// 计数器", 11);
    press(&mut harness, Modifiers::NONE, Key::Backspace);
    assert_eq!(harness.state().editor.text(), "// 计器");
    press(&mut harness, Modifiers::NONE, Key::Delete);
    assert_eq!(harness.state().editor.text(), "// 计");
    check_model(&harness);
}

#[test]
fn typing_over_a_selection_replaces_it() {
    let mut harness = harness("a := old_value;", 5);
    for _ in 0..9 {
        press(&mut harness, Modifiers::SHIFT, Key::ArrowRight);
    }
    assert_eq!(harness.state().editor.selection(), 5..14);
    type_text(&mut harness, "n");
    assert_eq!(harness.state().editor.text(), "a := n;");
    check_model(&harness);
    assert_eq!(harness.state().gestures.first(), Some(&Gesture::Other));
}

#[test]
fn paste_cut_and_copy_use_the_clipboard_events() {
    let mut harness = harness("a := 1;", 7);
    harness.event(Event::Paste("\r\nb := 2;".to_owned()));
    harness.run_steps(2);
    assert_eq!(harness.state().editor.text(), "a := 1;\nb := 2;");
    press(&mut harness, Modifiers::COMMAND, Key::A);
    harness.event(Event::Cut);
    harness.run_steps(2);
    assert_eq!(harness.state().editor.text(), "");
    check_model(&harness);
    assert_eq!(harness.state().change_lists.len(), 2);
}

#[test]
fn tab_indents_and_shift_tab_outdents_the_selected_lines() {
    let mut harness = harness("a;\nb;\nc;", 0);
    press(&mut harness, Modifiers::SHIFT, Key::ArrowDown);
    press(&mut harness, Modifiers::SHIFT, Key::ArrowDown);
    press(&mut harness, Modifiers::NONE, Key::Tab);
    assert_eq!(harness.state().editor.text(), "    a;\n    b;\nc;");
    press(&mut harness, Modifiers::SHIFT, Key::Tab);
    assert_eq!(harness.state().editor.text(), "a;\nb;\nc;");
    check_model(&harness);
}

#[test]
fn undo_and_redo_keys_are_left_to_the_app() {
    let mut harness = harness("a := 1;", 7);
    press(&mut harness, Modifiers::COMMAND, Key::Z);
    assert!(harness.state().undo_left_for_app);
    assert!(harness.state().change_lists.is_empty());
    assert_eq!(harness.state().editor.text(), "a := 1;");
}

#[test]
fn completion_filters_by_the_typed_prefix_and_replaces_it() {
    let mut harness = harness("x := ;", 5);
    press(&mut harness, Modifiers::CTRL, Key::Space);
    assert_eq!(
        harness.state().editor.completion_labels(),
        ["counter", "count_max", "motor_on"]
    );
    type_text(&mut harness, "coun");
    press(&mut harness, Modifiers::NONE, Key::ArrowDown);
    assert_eq!(
        harness.state().editor.completion_labels(),
        ["counter", "count_max"]
    );
    press(&mut harness, Modifiers::NONE, Key::Enter);
    assert_eq!(harness.state().editor.text(), "x := count_max;");
    assert!(harness.state().editor.completion_labels().is_empty());
    check_model(&harness);
}

#[test]
fn a_dot_after_a_name_opens_completion_and_escape_closes_it() {
    let mut harness = harness("motor", 5);
    type_text(&mut harness, ".");
    assert_eq!(harness.state().editor.completion_labels().len(), 3);
    press(&mut harness, Modifiers::NONE, Key::Escape);
    assert!(harness.state().editor.completion_labels().is_empty());
}

#[test]
fn replace_all_of_a_whole_word_is_one_change_list() {
    let text = "x := x + 1;\nmax := x1 + x;";
    let mut harness = harness(text, 0);
    let changes = {
        let editor = &mut harness.state_mut().editor;
        editor.set_find("x", "speed", true, true);
        editor.replace_all()
    };
    assert_eq!(
        harness.state().editor.text(),
        "speed := speed + 1;\nmax := x1 + speed;"
    );
    let mut model = text.to_owned();
    TextChange::apply_all(&mut model, &changes);
    assert_eq!(model, harness.state().editor.text());
    assert_eq!(changes.len(), 3);
}

#[test]
fn ctrl_f_opens_the_find_bar_and_f3_selects_the_next_match() {
    let mut harness = harness("a := 1;\nb := a;", 0);
    press(&mut harness, Modifiers::SHIFT, Key::ArrowRight);
    press(&mut harness, Modifiers::COMMAND, Key::F);
    assert!(harness.state().editor.is_find_open());
    harness.state_mut().editor.request_focus();
    harness.run_steps(2);
    press(&mut harness, Modifiers::NONE, Key::F3);
    assert_eq!(harness.state().editor.selection(), 13..14);
}

#[test]
fn folding_an_if_block_hides_its_lines() {
    let text = "x := 0;\nIF a THEN\n    b := 1;\n    c := 2;\nEND_IF;\ny := 1;";
    let mut harness = harness(text, 0);
    assert!(harness.state_mut().editor.toggle_fold(1));
    harness.run_steps(2);
    let editor = &harness.state().editor;
    assert!(!editor.is_line_hidden(1));
    assert!(editor.is_line_hidden(2) && editor.is_line_hidden(3) && editor.is_line_hidden(4));
    assert!(!editor.is_line_hidden(5));
    // The caret moving down from the IF line skips the hidden lines.
    harness.state_mut().editor.reveal(8..8);
    press(&mut harness, Modifiers::NONE, Key::ArrowDown);
    assert_eq!(
        harness.state().editor.caret(),
        text.find("y :=").unwrap_or_default()
    );
    assert!(!harness.state_mut().editor.toggle_fold(0));
}

#[test]
fn read_only_editors_move_but_do_not_change() {
    let mut harness = harness("a := 1;", 0);
    harness.state_mut().editor.set_read_only(true);
    type_text(&mut harness, "zz");
    press(&mut harness, Modifiers::NONE, Key::Delete);
    harness.event(Event::Paste("q".to_owned()));
    press(&mut harness, Modifiers::NONE, Key::End);
    assert_eq!(harness.state().editor.text(), "a := 1;");
    assert_eq!(harness.state().editor.caret(), 7);
    assert!(harness.state().change_lists.is_empty());
}

#[test]
fn f12_and_shift_f12_report_the_caret() {
    let mut harness = harness("a := b;", 5);
    let goto = std::rc::Rc::new(std::cell::Cell::new(None));
    let refs = std::rc::Rc::new(std::cell::Cell::new(None));
    let (goto_seen, refs_seen) = (goto.clone(), refs.clone());
    let mut editor = StEditor::new("a := b;");
    editor.reveal(5..5);
    editor.request_focus();
    let mut other = Harness::new_ui(move |ui| {
        ui.ctx().set_missing_glyph_policy(MissingGlyphPolicy::Tofu);
        let output = editor.show(ui, "Other", &KeywordCompletions);
        if output.goto_definition.is_some() {
            goto_seen.set(output.goto_definition);
        }
        if output.find_references.is_some() {
            refs_seen.set(output.find_references);
        }
    });
    other.run_steps(2);
    other.key_press(Key::F12);
    other.run_steps(2);
    other.key_press_modifiers(Modifiers::SHIFT, Key::F12);
    other.run_steps(2);
    assert_eq!(goto.get(), Some(5));
    assert_eq!(refs.get(), Some(5));
    harness.run_steps(1);
}

#[test]
fn set_text_replaces_only_a_different_text_and_clamps_the_caret() {
    let mut editor = StEditor::new("a := 1; // 计数器");
    editor.reveal(20..20);
    assert_eq!(editor.caret(), 20);
    editor.set_text("a := 1; // 计");
    assert_eq!(editor.caret(), editor.text().len());
    editor.reveal(14..14);
    editor.set_text("a := 1; // 计");
    assert_eq!(editor.caret(), 14);
    editor.set_text("a := 1; //数数");
    // 14 is inside the second Chinese char: the caret goes back to its start.
    assert_eq!(editor.caret(), 13);
}

#[test]
fn inline_values_and_diagnostics_draw_without_hiding_text() {
    let text = "counter := counter + 1;";
    let mut harness = harness(text, 0);
    {
        let editor = &mut harness.state_mut().editor;
        editor.set_inline_values(vec![InlineValue {
            range: 0..7,
            text: "42".to_owned(),
            changed: true,
            forced: true,
        }]);
        editor.set_diagnostics(vec![EditorDiagnostic {
            range: 11..18,
            severity: Severity::Warning,
            code: "W0001".to_owned(),
            message: "unused".to_owned(),
        }]);
    }
    harness.run_steps(2);
    // Typing after the name keeps the value on the (now longer) name's end.
    press(&mut harness, Modifiers::NONE, Key::End);
    type_text(&mut harness, " ");
    assert_eq!(harness.state().editor.inline_values[0].range, 0..7);
    assert_eq!(harness.state().editor.diagnostics[0].range, 11..18);
    check_model(&harness);
}

/// The screen position of a char column and line in the editor, from the editor's rectangle
/// and the monospace font: the gutter is 8 chars wide (the breakpoint column, 3 digits,
/// markers) plus one char gap.
fn text_pos(harness: &Harness<'_, Host>, line: usize, col: f32) -> egui::Pos2 {
    let rect = harness.get_by_label("Body of Main").rect();
    let font = egui::TextStyle::Monospace.resolve(&harness.ctx.global_style());
    let (row_height, char_width) = harness
        .ctx
        .fonts_mut(|fonts| (fonts.row_height(&font), fonts.glyph_width(&font, '0')));
    egui::pos2(
        rect.min.x + (9.0 + col) * char_width,
        rect.min.y + (line as f32 + 0.5) * row_height,
    )
}

fn click_at(harness: &mut Harness<'_, Host>, pos: egui::Pos2) {
    harness.event(Event::PointerMoved(pos));
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
        harness.run_steps(1);
    }
}

#[test]
fn a_click_places_the_caret_and_a_double_click_selects_the_word() {
    let mut harness = harness("counter := 1;\nspeed := counter;", 0);
    let pos = text_pos(&harness, 1, 2.2);
    click_at(&mut harness, pos);
    harness.run_steps(2);
    assert_eq!(harness.state().editor.caret(), 16);
    click_at(&mut harness, pos);
    assert_eq!(harness.state().editor.selection(), 14..19);
    type_text(&mut harness, "v");
    assert_eq!(
        harness.state().editor.text(),
        "counter := 1;\nv := counter;"
    );
    check_model(&harness);
}

#[test]
fn typing_elsewhere_starts_a_new_typing_run() {
    let mut harness = harness("a := 1;", 7);
    type_text(&mut harness, "x");
    press(&mut harness, Modifiers::NONE, Key::Home);
    type_text(&mut harness, "y");
    let gestures = &harness.state().gestures;
    assert_eq!(gestures.len(), 2);
    assert_ne!(gestures[0], gestures[1]);
}

#[test]
fn clicking_an_inline_value_prepares_a_value_on_enter() {
    let text = "counter := counter + 1;";
    let mut harness = harness(text, 0);
    harness
        .state_mut()
        .editor
        .set_inline_values(vec![InlineValue {
            range: 0..7,
            text: "42".to_owned(),
            changed: false,
            forced: false,
        }]);
    harness.run_steps(2);
    let pos = text_pos(&harness, 0, 8.5);
    click_at(&mut harness, pos);
    harness.run_steps(3);
    type_text(&mut harness, "7");
    press(&mut harness, Modifiers::NONE, Key::Enter);
    harness.run_steps(2);
    assert_eq!(harness.state().prepared, Some((0..7, "7".to_owned())));
    // The value went to the box, not into the code.
    assert_eq!(harness.state().editor.text(), text);
}

fn rest_pointer_at(harness: &mut Harness<'_, Host>, pos: egui::Pos2) {
    harness.event(Event::PointerMoved(pos));
    // The pointer rests for more than the hover delay.
    harness.run_steps(40);
}

#[test]
fn hovering_a_name_shows_the_services_text_and_a_diagnostic_its_message() {
    let mut harness = harness("counter := speed + 1;", 0);
    harness
        .state_mut()
        .editor
        .set_diagnostics(vec![EditorDiagnostic {
            range: 11..16,
            severity: Severity::Error,
            code: "E0104".to_owned(),
            message: "unknown name `speed`".to_owned(),
        }]);
    let pos = text_pos(&harness, 0, 2.5);
    rest_pointer_at(&mut harness, pos);
    let _hover = harness.get_by_label("counter : INT");
    let pos = text_pos(&harness, 0, 13.5);
    rest_pointer_at(&mut harness, pos);
    let _diagnostic = harness.get_by_label("E0104: unknown name `speed`");
}

#[test]
fn typing_in_the_find_field_selects_the_first_match() {
    let mut harness = harness("a := 1;\nbeta := a;", 0);
    press(&mut harness, Modifiers::COMMAND, Key::F);
    harness.run_steps(2);
    harness.event(Event::Text("beta".to_owned()));
    harness.run_steps(2);
    assert_eq!(harness.state().editor.selection(), 8..12);
    // Escape in the field closes the bar and gives the keyboard back to the editor.
    press(&mut harness, Modifiers::NONE, Key::Escape);
    assert!(!harness.state().editor.is_find_open());
    type_text(&mut harness, "x");
    assert_eq!(harness.state().editor.text(), "a := 1;\nx := a;");
}

#[test]
fn dragging_selects_from_where_the_button_went_down() {
    let mut harness = harness("counter := 1;\nspeed := counter;", 0);
    let down = text_pos(&harness, 0, 2.2);
    let up = text_pos(&harness, 1, 4.2);
    harness.event(Event::PointerMoved(down));
    harness.event(Event::PointerButton {
        pos: down,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    harness.run_steps(1);
    for step in 1..=5 {
        let t = step as f32 / 5.0;
        harness.event(Event::PointerMoved(down + (up - down) * t));
        harness.run_steps(1);
    }
    harness.event(Event::PointerButton {
        pos: up,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    harness.run_steps(2);
    assert_eq!(harness.state().editor.selection(), 2..18);
}

#[test]
fn keys_move_by_words_lines_pages_and_to_the_ends() {
    let text: String = (0..100)
        .map(|line| format!("    value_{line} := {line};\n"))
        .collect();
    let mut harness = harness(&text, 0);
    // Home goes to the first non-blank, then to the line start.
    press(&mut harness, Modifiers::NONE, Key::Home);
    assert_eq!(harness.state().editor.caret(), 4);
    press(&mut harness, Modifiers::NONE, Key::Home);
    assert_eq!(harness.state().editor.caret(), 0);
    press(&mut harness, Modifiers::NONE, Key::End);
    assert_eq!(harness.state().editor.caret(), 17);
    for expected in [16, 15, 12, 4] {
        press(&mut harness, Modifiers::COMMAND, Key::ArrowLeft);
        assert_eq!(harness.state().editor.caret(), expected);
    }
    // Ctrl+Right goes to the start of the next word.
    press(&mut harness, Modifiers::COMMAND, Key::ArrowRight);
    assert_eq!(harness.state().editor.caret(), 12);
    // Page Down moves by the rows the view shows, keeping the column.
    press(&mut harness, Modifiers::NONE, Key::PageDown);
    let (line, col) = harness
        .state()
        .editor
        .buffer
        .line_col(harness.state().editor.caret());
    assert!(line > 10, "line {line}");
    assert_eq!(col, 12);
    press(&mut harness, Modifiers::NONE, Key::PageUp);
    assert_eq!(harness.state().editor.caret(), 12);
    press(
        &mut harness,
        Modifiers::COMMAND | Modifiers::SHIFT,
        Key::End,
    );
    assert_eq!(harness.state().editor.selection(), 12..text.len());
    press(&mut harness, Modifiers::COMMAND, Key::Home);
    assert_eq!(harness.state().editor.selection(), 0..0);
}

#[test]
fn reveal_selects_and_scrolls_a_far_line_into_view() {
    let text: String = (0..2000)
        .map(|line| format!("x_{line} := {line};\n"))
        .collect();
    let mut harness = harness(&text, 0);
    assert_eq!(harness.state().editor.visible_lines().start, 0);
    let target = text.find("x_1500 ").unwrap_or_default();
    harness.state_mut().editor.reveal(target..target + 6);
    harness.run_steps(3);
    let visible = harness.state().editor.visible_lines();
    assert!(visible.contains(&1500), "{visible:?}");
    assert_eq!(harness.state().editor.selection(), target..target + 6);
}

#[test]
fn clicking_the_fold_marker_in_the_gutter_folds_and_unfolds() {
    let text = "x := 0;\nIF a THEN\n    b := 1;\nEND_IF;\ny := 1;";
    let mut harness = harness(text, 0);
    // The marker sits in the gutter, left of the text, on the IF line.
    let marker = text_pos(&harness, 1, -2.5);
    click_at(&mut harness, marker);
    harness.run_steps(2);
    assert!(harness.state().editor.is_line_hidden(2));
    assert!(harness.state().editor.is_line_hidden(3));
    click_at(&mut harness, marker);
    harness.run_steps(2);
    assert!(!harness.state().editor.is_line_hidden(2));
}

#[test]
fn f9_reports_the_caret_line_even_in_a_read_only_editor() {
    let mut harness = harness("x := 0;\ny := 1;\nz := 2;", 9);
    harness.state_mut().editor.set_read_only(true);
    press(&mut harness, Modifiers::NONE, Key::F9);
    assert_eq!(harness.state().breakpoint_toggles, vec![1]);
    assert_eq!(harness.state().editor.caret_line(), 1);
    // Shift+F9 is not the toggle.
    press(&mut harness, Modifiers::SHIFT, Key::F9);
    assert_eq!(harness.state().breakpoint_toggles, vec![1]);
    check_model(&harness);
}

#[test]
fn clicking_the_breakpoint_column_reports_its_line_and_does_not_fold() {
    let text = "x := 0;\nIF a THEN\n    b := 1;\nEND_IF;\ny := 1;";
    let mut harness = harness(text, 0);
    // The breakpoint column is the gutter's first two chars.
    let column = text_pos(&harness, 1, -8.5);
    click_at(&mut harness, column);
    harness.run_steps(2);
    assert_eq!(harness.state().breakpoint_toggles, vec![1]);
    assert!(!harness.state().editor.is_line_hidden(2));
    let column = text_pos(&harness, 4, -8.5);
    click_at(&mut harness, column);
    assert_eq!(harness.state().breakpoint_toggles, vec![1, 4]);
}

#[test]
fn debug_marks_are_kept_until_replaced_and_draw_beside_the_text() {
    let text = "x := 0;\ny := 1;\nz := 2;";
    let mut harness = harness(text, 0);
    let marks = StDebugMarks {
        breakpoints: vec![
            BreakpointMark {
                line: 0,
                look: BreakpointLook::Enabled,
            },
            BreakpointMark {
                line: 2,
                look: BreakpointLook::Conditional,
            },
        ],
        halt_line: Some(1),
        halt_is_caller: false,
        flow_lines: vec![0, 1],
    };
    harness.state_mut().editor.set_debug_marks(marks.clone());
    harness.run_steps(2);
    assert_eq!(harness.state().editor.debug_marks(), &marks);
    assert_eq!(
        harness.state().editor.debug_marks().breakpoint_at(2),
        Some(BreakpointLook::Conditional)
    );
    assert_eq!(harness.state().editor.debug_marks().breakpoint_at(1), None);
    // Typing leaves the marks to the app, which gives new ones from its model.
    type_text(&mut harness, "a");
    assert_eq!(harness.state().editor.debug_marks(), &marks);
    check_model(&harness);
}
