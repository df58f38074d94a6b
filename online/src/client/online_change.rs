//! The client's side of online change (`docs/protocol.md` §7): check a transferred image,
//! read what will change, apply it, or abort the transfer.

use online_protocol::{ChangeApplied, ChangeCheck, ChangeDetailEntry, Request, Response};

use super::{Client, unexpected};
use crate::error::OnlineError;

impl Client {
    /// `ONLINE_CHANGE_CHECK` of a transfer ([`Client::transfer`]): whether the target can
    /// take the image over without stopping, and the counts of what would change. The
    /// transfer stays open for [`Client::online_change_apply`], [`Client::commit`] (a full
    /// download instead) or [`Client::abort`].
    pub async fn online_change_check(&mut self, transfer: u16) -> Result<ChangeCheck, OnlineError> {
        let request = Request::OnlineChangeCheck {
            token: self.token,
            transfer,
        };
        match self.call(&request).await? {
            Response::OnlineChangeCheck(check) => Ok(check),
            other => Err(unexpected(&other)),
        }
    }

    /// `ONLINE_CHANGE_DETAILS`, asked page by page: every detail the check found, in the
    /// protocol's order (POUs changed, added, removed, then variables, pointers, forces…).
    pub async fn online_change_details(
        &mut self,
        transfer: u16,
    ) -> Result<Vec<ChangeDetailEntry>, OnlineError> {
        let mut details = Vec::new();
        loop {
            let request = Request::OnlineChangeDetails {
                token: self.token,
                transfer,
                from: u16::try_from(details.len()).unwrap_or(u16::MAX),
            };
            match self.call(&request).await? {
                Response::OnlineChangeDetails {
                    total,
                    details: page,
                } => {
                    let empty = page.is_empty();
                    details.extend(page);
                    if empty || details.len() >= usize::from(total) {
                        return Ok(details);
                    }
                }
                other => return Err(unexpected(&other)),
            }
        }
    }

    /// `ONLINE_CHANGE_APPLY`: the checked image takes over between two cycles; the
    /// transfer ends.
    pub async fn online_change_apply(
        &mut self,
        transfer: u16,
    ) -> Result<ChangeApplied, OnlineError> {
        let request = Request::OnlineChangeApply {
            token: self.token,
            transfer,
        };
        match self.call(&request).await? {
            Response::OnlineChangeApply(applied) => Ok(applied),
            other => Err(unexpected(&other)),
        }
    }

    /// `DOWNLOAD_ABORT`: drops a transfer, changing nothing on the target.
    pub async fn abort(&mut self, transfer: u16) -> Result<(), OnlineError> {
        let request = Request::DownloadAbort {
            token: self.token,
            transfer,
        };
        match self.call(&request).await? {
            Response::DownloadAbort => Ok(()),
            other => Err(unexpected(&other)),
        }
    }
}
