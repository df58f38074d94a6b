//! The cams a kernel owns and the selections MC_CamTableSelect made of them.

use std::fmt;
use std::sync::Arc;

use crate::curve::CamCurve;
use crate::kernel::MotionError;
use crate::sync::{CamId, CamSelection, CamTableId};
use crate::tappet::TappetTrack;

/// A registered cam: the curve, its master range and its tappet tracks.
#[derive(Clone)]
pub(crate) struct StoredCam {
    /// The curve; shared so that a kernel stays cheap to clone.
    pub(crate) curve: Arc<dyn CamCurve + Send + Sync>,
    /// The tappet tracks, copied into the tappet evaluator of each coupling or register.
    pub(crate) tracks: Vec<TappetTrack>,
}

/// Cams by [`CamId`] and cam selections by [`CamTableId`]. Both only grow while the image
/// loads and while MC_CamTableSelect makes new selections, never in `advance`.
#[derive(Clone, Default)]
pub(crate) struct CamStore {
    pub(crate) cams: Vec<StoredCam>,
    pub(crate) selections: Vec<CamSelection>,
}

impl fmt::Debug for CamStore {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("CamStore")
            .field("cams", &self.cams.len())
            .field("selections", &self.selections)
            .finish()
    }
}

impl CamStore {
    /// The cam `id`.
    pub(crate) fn cam(&self, id: CamId) -> Result<&StoredCam, MotionError> {
        self.cams.get(id.0).ok_or(MotionError::UnknownCam(id.0))
    }

    /// The selection `id`.
    pub(crate) fn selection(&self, id: CamTableId) -> Result<CamSelection, MotionError> {
        let index = (id.0 as usize).checked_sub(1);
        index
            .and_then(|index| self.selections.get(index))
            .copied()
            .ok_or(MotionError::UnknownCamTable(id.0))
    }

    /// Records a selection, in the slot of `previous` when that is one, and returns its id.
    pub(crate) fn select(
        &mut self,
        selection: CamSelection,
        previous: Option<CamTableId>,
    ) -> CamTableId {
        if let Some(previous) = previous
            && let Some(index) = (previous.0 as usize).checked_sub(1)
            && let Some(slot) = self.selections.get_mut(index)
        {
            *slot = selection;
            return previous;
        }
        self.selections.push(selection);
        CamTableId(u32::try_from(self.selections.len()).unwrap_or(u32::MAX))
    }
}
