//! The login dialog: the download question for a target without the project's program, the
//! progress of a download or of an online change check, and CODESYS's three choices for a
//! target that runs another version (`docs/debugging.md` §6), with what an online change will
//! do listed before anything on the target changes.

use egui::{RichText, Ui};

use super::command::{Command, Commands};
use super::i18n::{Language, LoginText, Text};
use super::online::{ChangeKind, ChangeOffer, ChangeRefusal, LoginChoice, Phase, grouped};
use super::view::StudioView;

/// The dialog's width in points: wide enough for a variable path and the choices' hints.
const DIALOG_WIDTH: f32 = 560.0;
/// The height of the list of changes before it scrolls, in points.
const CHANGES_HEIGHT: f32 = 260.0;

/// Shows the login dialog while the login waits for the user or for a transfer.
pub(crate) fn login_dialog_ui(ctx: &egui::Context, view: StudioView<'_>, commands: &mut Commands) {
    let language = view.language;
    let phase = view.online.phase();
    let progress = |sent: usize, total: usize| {
        if total == 0 {
            0.0
        } else {
            sent as f32 / total as f32
        }
    };
    let shown = matches!(
        phase,
        Phase::ConfirmDownload { .. }
            | Phase::Downloading { .. }
            | Phase::CheckingChange { .. }
            | Phase::ChooseLogin(_)
            | Phase::ApplyingChange
    );
    if !shown {
        return;
    }
    egui::Modal::new(egui::Id::unique("login_dialog")).show(ctx, |ui| {
        ui.set_width(DIALOG_WIDTH);
        ui.heading(Text::Login.get(language));
        match phase {
            Phase::ConfirmDownload { reason } => {
                ui.label(reason);
                ui.label(Text::DownloadQuestion.get(language));
                ui.horizontal(|ui| {
                    if ui.button(Text::Download.get(language)).clicked() {
                        commands.push(Command::ConfirmDownload);
                    }
                    if ui.button(Text::Cancel.get(language)).clicked() {
                        commands.push(Command::CancelDownload);
                    }
                });
            }
            Phase::Downloading { sent, total } => {
                ui.label(Text::Downloading.get(language));
                ui.add(egui::ProgressBar::new(progress(*sent, *total)).show_percentage());
            }
            Phase::CheckingChange { sent, total } => {
                ui.label(LoginText::Checking.get(language));
                ui.add(egui::ProgressBar::new(progress(*sent, *total)).show_percentage());
            }
            Phase::ApplyingChange => {
                ui.label(LoginText::Applying.get(language));
                ui.add(egui::Spinner::new());
            }
            Phase::ChooseLogin(offer) => choices_ui(ui, language, offer, commands),
            _ => {}
        }
    });
}

/// The verdict, what the change will do, and the three choices with Cancel.
fn choices_ui(ui: &mut Ui, language: Language, offer: &ChangeOffer, commands: &mut Commands) {
    ui.label(&offer.reason);
    ui.add_space(4.0);
    match ChangeRefusal::of(&offer.check) {
        Some(refusal) => refusal_ui(ui, language, refusal, &offer.check.why),
        None => changes_ui(ui, language, offer),
    }
    ui.add_space(8.0);
    for choice in LoginChoice::ALL {
        let (label, hint) = match choice {
            LoginChoice::OnlineChange => (LoginText::WithOnlineChange, LoginText::OnlineChangeHint),
            LoginChoice::Download => (LoginText::WithDownload, LoginText::DownloadHint),
            LoginChoice::WithoutChange => (LoginText::WithoutChange, LoginText::WithoutChangeHint),
        };
        let enabled = choice.is_enabled(&offer.check);
        let mut text = RichText::new(label.get(language));
        if choice == LoginChoice::preferred(&offer.check) {
            text = text.strong();
        }
        let button = ui.add_enabled(enabled, egui::Button::new(text));
        if button.clicked() {
            commands.push(Command::ChooseLogin(choice));
        }
        ui.label(RichText::new(hint.get(language)).weak());
        ui.add_space(4.0);
    }
    ui.separator();
    if ui.button(Text::Cancel.get(language)).clicked() {
        commands.push(Command::CancelDownload);
    }
}

/// Why an online change is impossible: the reason in the interface language, then the first
/// difference the target found, in its own words.
fn refusal_ui(ui: &mut Ui, language: Language, refusal: ChangeRefusal, why: &str) {
    let reason = match refusal {
        ChangeRefusal::NoProgram => LoginText::ReasonNoProgram.get(language).to_owned(),
        ChangeRefusal::SameProgram => LoginText::ReasonSameProgram.get(language).to_owned(),
        ChangeRefusal::TaskConfiguration => {
            LoginText::ReasonTaskConfiguration.get(language).to_owned()
        }
        ChangeRefusal::LocatedAreas => LoginText::ReasonLocatedAreas.get(language).to_owned(),
        ChangeRefusal::Motion => LoginText::ReasonMotion.get(language).to_owned(),
        ChangeRefusal::TaskHalted => LoginText::ReasonTaskHalted.get(language).to_owned(),
        ChangeRefusal::Other(number) => {
            LoginText::ReasonOther.fill(language, &[("number", &number.to_string())])
        }
    };
    let error = ui.visuals().error_fg_color;
    ui.label(
        RichText::new(LoginText::Impossible.fill(language, &[("reason", &reason)])).color(error),
    );
    if !why.is_empty() {
        ui.label(LoginText::TargetSays.fill(language, &[("why", why)]));
    }
}

/// What the online change will do: the variables kept, then each kind of change with its
/// names; kinds that lose something (a value, a force, a pointer) in the warning colour.
fn changes_ui(ui: &mut Ui, language: Language, offer: &ChangeOffer) {
    ui.label(RichText::new(LoginText::WhatWillChange.get(language)).strong());
    let check = &offer.check;
    let mut counts = vec![(LoginText::CountCarried, check.carried)];
    if check.pointers_moved > 0 {
        counts.push((LoginText::CountPointersMoved, check.pointers_moved));
    }
    for (text, count) in counts {
        ui.label(format!("{} {count}", text.get(language)));
    }
    let groups = grouped(&offer.details);
    if groups.is_empty() {
        ui.label(RichText::new(LoginText::NoDetails.get(language)).weak());
        return;
    }
    let warn = ui.visuals().warn_fg_color;
    egui::ScrollArea::vertical()
        .max_height(CHANGES_HEIGHT)
        .auto_shrink([false, true])
        .show(ui, |ui| {
            for group in groups {
                let heading = format!(
                    "{} ({})",
                    heading(group.kind).get(language),
                    group.names.len()
                );
                let heading = RichText::new(heading).strong();
                ui.label(if group.kind.loses_state() {
                    heading.color(warn)
                } else {
                    heading
                });
                for name in &group.names {
                    ui.label(RichText::new(format!("    {name}")).monospace());
                }
            }
        });
}

/// The heading of a kind of change.
fn heading(kind: ChangeKind) -> LoginText {
    match kind {
        ChangeKind::PouChanged => LoginText::PousChanged,
        ChangeKind::PouAdded => LoginText::PousAdded,
        ChangeKind::PouRemoved => LoginText::PousRemoved,
        ChangeKind::VariableAdded => LoginText::VariablesAdded,
        ChangeKind::VariableRemoved => LoginText::VariablesRemoved,
        ChangeKind::VariableReinitialised => LoginText::VariablesReinitialised,
        ChangeKind::PointerCleared => LoginText::PointersCleared,
        ChangeKind::ForceReleased => LoginText::ForcesReleased,
        ChangeKind::TraceRemoved => LoginText::TracesRemoved,
        ChangeKind::MotionBlockDropped => LoginText::MotionBlocksDropped,
        ChangeKind::Other => LoginText::OtherChanges,
    }
}
