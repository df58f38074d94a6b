//! The session's online change commands (`docs/protocol.md` §7): transfer and check, apply,
//! load the checked transfer as a full download, or drop it.

use tokio::sync::mpsc;

use super::Event;
use crate::client::Client;
use crate::error::OnlineError;

/// A step of an online change.
#[derive(Debug)]
pub enum ChangeCommand {
    /// Transfer an image and check whether the target can take it over without stopping,
    /// with [`Event::DownloadProgress`] on the way; answered by [`Event::ChangeChecked`]. The
    /// transfer stays open for one of the three steps below.
    Check(Vec<u8>),
    /// Apply the checked online change of this transfer; answered by [`Event::ChangeApplied`].
    Apply(u16),
    /// Load the checked transfer as a full download instead (`start` starts it; without it the
    /// target's program is stopped before the load and the new one stays stopped, as
    /// CODESYS's login with download does); answered by [`Event::Done`].
    Commit {
        /// The transfer's number.
        transfer: u16,
        /// Start the program once loaded; without it the target is stopped before the load.
        start: bool,
    },
    /// Drop a transfer, changing nothing on the target; answered by [`Event::Done`].
    Abort(u16),
}

/// Runs one online change step: `Some(event)` is its own answer; `None` means it is
/// answered as other commands are, with [`Event::Done`] and the target's state.
pub(super) async fn run(
    client: &mut Client,
    step: ChangeCommand,
    events: &mpsc::Sender<Event>,
) -> Result<Option<Event>, OnlineError> {
    match step {
        ChangeCommand::Check(image) => {
            let transfer = client
                .transfer(&image, |sent, total| {
                    let _ = events.try_send(Event::DownloadProgress(sent, total));
                })
                .await?;
            match check(client, transfer).await {
                Ok(event) => Ok(Some(event)),
                Err(error) => {
                    // The transfer is of no use without its check; dropping it is best effort,
                    // as the target forgets an idle transfer by itself.
                    if !matches!(error, OnlineError::Io(..) | OnlineError::Timeout(..)) {
                        let _ = client.abort(transfer).await;
                    }
                    Err(error)
                }
            }
        }
        ChangeCommand::Apply(transfer) => {
            let applied = client.online_change_apply(transfer).await?;
            let state = client.identify().await?.state;
            Ok(Some(Event::ChangeApplied(applied, state)))
        }
        ChangeCommand::Commit { transfer, start } => {
            commit(client, transfer, start).await?;
            Ok(None)
        }
        ChangeCommand::Abort(transfer) => {
            client.abort(transfer).await?;
            Ok(None)
        }
    }
}

/// `DOWNLOAD_COMMIT` of a transferred image as CODESYS's download does it: without `start`,
/// the running program is stopped first, so the new one is loaded stopped and waits for the
/// user's start (a runtime keeps a running target running across a commit, and the new code
/// would otherwise run at once from its initial values, unasked). With `start` it is started
/// once loaded.
pub(super) async fn commit(
    client: &mut Client,
    transfer: u16,
    start: bool,
) -> Result<(), OnlineError> {
    if !start {
        client.stop().await?;
    }
    client.commit(transfer, start).await?;
    Ok(())
}

/// The check of an open transfer with its details, which exist only when the target runs a
/// program to compare with.
async fn check(client: &mut Client, transfer: u16) -> Result<Event, OnlineError> {
    let check = client.online_change_check(transfer).await?;
    let details = if check.details > 0 {
        client.online_change_details(transfer).await?
    } else {
        Vec::new()
    };
    Ok(Event::ChangeChecked {
        transfer,
        check,
        details,
    })
}
