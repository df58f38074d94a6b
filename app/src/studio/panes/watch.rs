//! The watch pane: the project's watch lists with live values while online, prepared values
//! for Ctrl+F7 (write) and F7 (force), and a field to add any variable path.

use std::collections::HashMap;

use egui::{RichText, Ui};
use project_model::{Edit, Object, WatchEntry, WatchList};

use crate::studio::command::{Command, Commands};
use crate::studio::i18n::Text;
use crate::studio::online::devices::Bound;
use crate::studio::session::Session;
use crate::studio::theme;
use crate::studio::view::StudioView;

/// What the watch pane remembers between frames.
#[derive(Default)]
pub struct WatchPaneState {
    /// The watch list shown; the first one when `None` or gone.
    pub list: Option<String>,
    /// The path typed in the "add variable" field.
    new_path: String,
    /// Prepared values being typed, by path, until Enter commits them.
    typing: HashMap<String, String>,
    /// Values the target or the type check refused, with the reason, by path.
    pub refused: Vec<(String, String)>,
}

impl WatchPaneState {
    /// Every watch list of the project and the one shown.
    fn lists<'p>(
        &self,
        session: Option<&'p Session>,
    ) -> (Vec<&'p WatchList>, Option<&'p WatchList>) {
        super::chosen_object(session, self.list.as_deref(), |object| match object {
            Object::WatchList(list) => Some(list),
            _ => None,
        })
    }

    fn current<'p>(&self, session: Option<&'p Session>) -> Option<&'p WatchList> {
        self.lists(session).1
    }

    /// The paths of the shown watch list, which the studio reads while online.
    pub fn watched_paths(&self, session: Option<&Session>) -> Vec<String> {
        self.current(session)
            .map(|list| {
                list.entries
                    .iter()
                    .map(|entry| entry.path.clone())
                    .collect()
            })
            .unwrap_or_default()
    }

    /// The prepared values of the shown watch list, as (path, text).
    pub fn prepared_values(&self, session: Option<&Session>) -> Vec<(String, String)> {
        self.current(session)
            .map(|list| {
                list.entries
                    .iter()
                    .filter_map(|entry| {
                        let value = entry.prepared_value.as_deref()?.trim();
                        (!value.is_empty()).then(|| (entry.path.clone(), value.to_owned()))
                    })
                    .collect()
            })
            .unwrap_or_default()
    }
}

/// The edit that replaces a watch list with `changed`.
fn replace(changed: WatchList) -> Vec<Edit> {
    vec![Edit::ReplaceObject(Object::WatchList(changed))]
}

/// Draws the watch pane; changes to the list become commands.
pub(crate) fn watch_ui(
    view: StudioView<'_>,
    state: &mut WatchPaneState,
    commands: &mut Commands,
    ui: &mut Ui,
) {
    let language = view.language;
    let (lists, current) = state.lists(view.session);
    let names: Vec<String> = lists.iter().map(|list| list.name.clone()).collect();
    let Some(list) = current.cloned() else {
        ui.label(RichText::new(Text::NoWatchList.get(language)).weak());
        return;
    };
    ui.horizontal(|ui| {
        let label = ui.label(Text::WatchList.get(language));
        egui::ComboBox::from_id_salt("watch_list")
            .selected_text(&list.name)
            .show_ui(ui, |ui| {
                for name in &names {
                    if ui.selectable_label(*name == list.name, name).clicked() {
                        state.list = Some(name.clone());
                    }
                }
            })
            .response
            .labelled_by(label.id);
        ui.separator();
        let label = ui.label(Text::AddVariable.get(language));
        let field = ui
            .add(
                egui::TextEdit::singleline(&mut state.new_path)
                    .hint_text("Main.fbConveyor.xMotorOn")
                    .desired_width(260.0),
            )
            .labelled_by(label.id);
        let path = state.new_path.trim().to_owned();
        if field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) && !path.is_empty() {
            let mut changed = list.clone();
            changed.entries.push(WatchEntry {
                path: path.clone(),
                ..WatchEntry::default()
            });
            let label = Text::UndoWatch.fill(language, &[("path", &path)]);
            commands.push(Command::Edit(label, replace(changed)));
            state.new_path.clear();
        }
    });
    ui.separator();
    let online = view.online.can_write();
    let mut edits: Vec<(String, Vec<Edit>)> = Vec::new();
    // A variable dragged from a declaration table anywhere onto the list joins it.
    let (_, dropped) =
        ui.dnd_drop_zone::<editor::VariableDragPayload, _>(egui::Frame::NONE, |ui| {
            entries_ui(view, state, ui, &list, online, &mut edits);
        });
    // A variable without one path (a function block's) cannot be watched by its name alone.
    let dropped = dropped.and_then(|dropped| dropped.path.clone());
    if let Some(dropped) = dropped
        && !list
            .entries
            .iter()
            .any(|e| e.path.eq_ignore_ascii_case(&dropped))
    {
        let mut changed = list.clone();
        changed.entries.push(WatchEntry {
            path: dropped.clone(),
            ..WatchEntry::default()
        });
        let label = Text::UndoWatch.fill(view.language, &[("path", &dropped)]);
        edits.push((label, replace(changed)));
    }
    for (label, edit) in edits {
        commands.push(Command::Edit(label, edit));
    }
}

/// The rows of the watch list: path, live value, prepared value, comment, remove.
fn entries_ui(
    view: StudioView<'_>,
    state: &mut WatchPaneState,
    ui: &mut Ui,
    list: &WatchList,
    online: bool,
    edits: &mut Vec<(String, Vec<Edit>)>,
) {
    let language = view.language;
    egui::ScrollArea::both()
        .id_salt("watch")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            egui::Grid::new("watch_grid")
                .num_columns(5)
                .striped(true)
                .spacing([16.0, 4.0])
                .min_col_width(60.0)
                .show(ui, |ui| {
                    for header in [
                        Text::Expression,
                        Text::Value,
                        Text::PreparedValue,
                        Text::Comment,
                    ] {
                        ui.strong(header.get(language));
                    }
                    ui.label("");
                    ui.end_row();
                    for (index, entry) in list.entries.iter().enumerate() {
                        ui.label(RichText::new(&entry.path).monospace());
                        value_cell(view, ui, &entry.path);
                        if let Some(committed) = prepared_cell(view, state, ui, entry, online) {
                            let mut changed = list.clone();
                            changed.entries[index].prepared_value =
                                (!committed.is_empty()).then_some(committed);
                            let label = Text::UndoPrepare.fill(language, &[("path", &entry.path)]);
                            edits.push((label, replace(changed)));
                        }
                        ui.label(RichText::new(&entry.comment).weak());
                        if ui
                            .small_button("×")
                            .on_hover_text(format!("{} {}", Text::Remove.get(language), entry.path))
                            .clicked()
                        {
                            let mut changed = list.clone();
                            changed.entries.remove(index);
                            let label = Text::UndoUnwatch.fill(language, &[("path", &entry.path)]);
                            edits.push((label, replace(changed)));
                        }
                        ui.end_row();
                    }
                });
        });
}

/// The live value: forced values marked, changed values highlighted, unknown paths explained.
fn value_cell(view: StudioView<'_>, ui: &mut Ui, path: &str) {
    let language = view.language;
    // Why there is no value (unknown on the target, device unreachable) comes first; values of
    // variables bound to Modbus devices show without a login.
    if let Some(problem) = view.online.problem(path) {
        ui.label(RichText::new(problem).color(ui.visuals().error_fg_color));
        return;
    }
    if matches!(view.online.bound(path), Some(Bound::RuntimeWhenLoggedIn)) {
        // A device on a serial port: only the runtime reaches it.
        ui.label(RichText::new("—").weak())
            .on_hover_text(Text::ReadThroughRuntime.get(language));
        return;
    }
    if !view.online.is_online() && !view.online.is_polled_by_studio(path) {
        ui.label(RichText::new("—").weak())
            .on_hover_text(Text::NotOnline.get(language));
        return;
    }
    match view.online.value(path) {
        Some(value) => {
            let mut text = RichText::new(&value.text).monospace();
            if value.changed {
                text = text.strong();
            }
            ui.horizontal(|ui| {
                if value.forced {
                    let colors = theme::colors(ui);
                    ui.label(
                        RichText::new(" F ")
                            .monospace()
                            .strong()
                            .color(colors.forced_text)
                            .background_color(colors.forced_fill),
                    )
                    .on_hover_text(Text::Forced.get(language));
                }
                ui.label(text);
            });
        }
        None => {
            ui.spinner();
        }
    }
}

/// The prepared value field. Returns the value to keep in the list once the user commits it
/// with Enter or by leaving the field; a value the type refuses is kept in the field with the
/// reason beside it, and not committed.
fn prepared_cell(
    view: StudioView<'_>,
    state: &mut WatchPaneState,
    ui: &mut Ui,
    entry: &WatchEntry,
    online: bool,
) -> Option<String> {
    let saved = entry.prepared_value.clone().unwrap_or_default();
    let mut text = state
        .typing
        .get(&entry.path)
        .cloned()
        .unwrap_or_else(|| saved.clone());
    let refused = state
        .refused
        .iter()
        .find(|(path, _)| *path == entry.path)
        .map(|(_, reason)| reason.clone());
    let mut committed = None;
    ui.horizontal(|ui| {
        let field = ui.add(
            egui::TextEdit::singleline(&mut text)
                .desired_width(110.0)
                .font(egui::TextStyle::Monospace),
        );
        field.widget_info(|| {
            egui::WidgetInfo::labeled(
                egui::Role::TextInput,
                true,
                Text::PreparedValueOf.fill(view.language, &[("path", &entry.path)]),
            )
        });
        if field.changed() {
            state.typing.insert(entry.path.clone(), text.clone());
            state.refused.retain(|(path, _)| *path != entry.path);
        }
        if field.lost_focus() && text.trim() != saved {
            let check = if online && !text.trim().is_empty() {
                view.online.check_value(&entry.path, &text)
            } else {
                Ok(())
            };
            match check {
                Ok(()) => {
                    state.typing.remove(&entry.path);
                    committed = Some(text.trim().to_owned());
                }
                Err(refusal) => state.refused.push((entry.path.clone(), refusal.reason)),
            }
        } else if field.lost_focus() {
            state.typing.remove(&entry.path);
        }
        if let Some(reason) = refused {
            ui.label(RichText::new(reason).color(ui.visuals().error_fg_color));
        }
    });
    committed
}
