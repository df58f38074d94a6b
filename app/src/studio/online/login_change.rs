//! Logging in to a target that runs another program (`docs/debugging.md` §6): the project's
//! program is sent and checked, the user chooses from the verdict, and an online change
//! applied keeps the session logged in with the new program.

use online::session::{ChangeCommand, Command};
use online::{ChangeApplied, ChangeCheck, ChangeDetailEntry, TargetState};

use super::login_choice::ChangeOffer;
use super::{Online, Phase};
use crate::studio::i18n::{LoginText, Text};

impl Online {
    /// Sends the project's program and asks the target whether it can take it over online;
    /// the dialog keeps the download question when the program cannot be sent.
    pub(super) fn check_online_change(&mut self) {
        let Some(image) = &self.image else { return };
        let bytes = image.bytes.as_ref().clone();
        let total = bytes.len();
        if self.command(Command::OnlineChange(ChangeCommand::Check(bytes))) {
            self.phase = Phase::CheckingChange { sent: 0, total };
        }
    }

    /// The check's answer: the user chooses how to log in. A check that comes too late (the
    /// user logged out or the target reconnected meanwhile) only drops its transfer.
    pub(super) fn change_checked(
        &mut self,
        transfer: u16,
        check: ChangeCheck,
        details: Vec<ChangeDetailEntry>,
    ) {
        if !matches!(self.phase, Phase::CheckingChange { .. }) {
            self.command(Command::OnlineChange(ChangeCommand::Abort(transfer)));
            return;
        }
        let project = self
            .target_identity
            .as_ref()
            .map(|identity| identity.project.clone())
            .unwrap_or_default();
        self.phase = Phase::ChooseLogin(ChangeOffer {
            transfer,
            reason: self
                .text(Text::TargetOtherProgram)
                .replace("{project}", &project),
            check,
            details,
        });
    }

    /// The switch happened: the target runs the project's program, with the values carried
    /// over; the places of the watched variables moved, so they are resolved again.
    pub(super) fn change_applied(&mut self, applied: ChangeApplied, state: TargetState) {
        self.target_state = Some(state);
        if let (Some(identity), Some(image)) = (&mut self.target_identity, &self.image) {
            identity.image_hash = Some(image.hash);
        }
        self.resolved.clear();
        self.resolving.clear();
        self.watched.clear();
        self.values.clear();
        self.phase = Phase::Online;
        let text = LoginText::Applied.fill(
            self.language,
            &[
                ("cycle", &applied.cycles.to_string()),
                ("carried", &applied.carried.to_string()),
            ],
        );
        self.info(text);
        self.refresh_watch();
    }

    /// Whether the target runs the project's program, so values can be shown by its types.
    pub(super) fn runs_project(&self) -> bool {
        let ours = self.image.as_ref().map(|image| image.hash);
        ours.is_some()
            && self
                .target_identity
                .as_ref()
                .and_then(|identity| identity.image_hash)
                == ours
    }
}
