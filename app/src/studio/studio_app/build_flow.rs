//! Building in the background and logging in with the build.

use super::state::Studio;
use crate::studio::build_job::{BuildJob, BuildOutcome};
use crate::studio::command::Command;
use crate::studio::i18n::Text;
use crate::studio::pane::Pane;
use crate::studio::status::StatusMessage;

impl Studio {
    /// Starts a build of the current revision unless one is running for it.
    pub(super) fn start_build(&mut self) {
        let Some(session) = &self.shared.session else {
            return;
        };
        let revision = session.history.revision();
        if self
            .shared
            .build
            .as_ref()
            .is_some_and(|job| job.revision() == revision)
        {
            return;
        }
        self.shared.build = Some(BuildJob::start(session.project.clone(), revision));
        let language = self.shared.settings.language;
        self.report(StatusMessage::info(Text::Building.get(language)));
    }

    /// Takes in a finished build: says how it went, shows the messages on errors, and logs in
    /// when the build was started for a login.
    pub(super) fn finish_build(&mut self, outcome: BuildOutcome, ctx: &egui::Context) {
        let language = self.shared.settings.language;
        let (errors, warnings) = outcome.counts();
        let counts = format!(
            "{errors} {}, {warnings} {}",
            Text::Errors.get(language),
            Text::Warnings.get(language)
        );
        let message = match (&outcome.image, &outcome.failure) {
            (Some(_), _) => StatusMessage::info(format!(
                "{}: {counts} ({} ms)",
                Text::BuildSucceeded.get(language),
                outcome.elapsed.as_millis()
            )),
            (None, Some(failure)) => StatusMessage::error(format!(
                "{}: {}",
                Text::BuildFailed.get(language),
                failure.text(language)
            )),
            (None, None) => {
                StatusMessage::error(format!("{}: {counts}", Text::BuildFailed.get(language)))
            }
        };
        self.report(message);
        if errors > 0 {
            self.commands.push(Command::ShowPane(Pane::Messages));
        }
        let login = std::mem::take(&mut self.login_after_build);
        let built = outcome.image.is_some();
        self.shared.last_build = Some(outcome);
        if login && built {
            self.login(ctx);
        }
    }

    /// Logs in with the current build, building first when the project changed since.
    pub(super) fn login(&mut self, ctx: &egui::Context) {
        let revision = self.shared.revision();
        let current = self
            .shared
            .last_build
            .as_ref()
            .filter(|outcome| Some(outcome.revision) == revision)
            .and_then(|outcome| outcome.image.clone());
        let Some(image) = current else {
            let failed = self
                .shared
                .last_build
                .as_ref()
                .is_some_and(|outcome| Some(outcome.revision) == revision);
            if failed {
                let language = self.shared.settings.language;
                self.report(StatusMessage::error(Text::LoginNeedsBuild.get(language)));
            } else {
                self.login_after_build = true;
                self.start_build();
            }
            return;
        };
        let address = self.shared.session.as_ref().and_then(|session| {
            use std::net::ToSocketAddrs as _;
            let controller = &session.project.controller;
            (controller.host.as_str(), controller.port)
                .to_socket_addrs()
                .ok()
                .and_then(|mut addresses| addresses.next())
        });
        let password = self.chrome.password();
        let target = self.shared.settings.target;
        let wake = ctx.clone();
        self.shared
            .online
            .login(target, address, password, image, move || {
                wake.request_repaint();
            });
        // The project's breakpoints, and flow control when it is on, go to the target once its
        // debug session is attached.
        self.sync_breakpoints();
        if self.shared.debug.flow_control {
            let bodies = self.flow_bodies();
            self.shared.online.set_flow_bodies(bodies);
        }
    }
}
