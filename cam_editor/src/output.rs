//! What the cam editor gives back each frame, and the live values it is given.

use project_model::CamTable;

/// What the user did in the cam editor this frame. The editor never changes the model: the
/// app applies `edit` after the frame as one undo step and fulfils the file requests.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CamEditorOutput {
    /// The whole changed cam with a label for the undo menu; at most one per gesture (a drag
    /// gives one edit when it is released).
    pub edit: Option<(String, CamTable)>,
    /// The user asked to import points from a CSV file: the app picks the file, reads it and
    /// passes its text to [`crate::import_points`].
    pub import_csv: bool,
    /// The user asked to export the points: the app writes [`crate::export_points`] to a file
    /// the user picks.
    pub export_csv: bool,
}

/// Live values of a running cam, shown while logged in.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CamLive {
    /// The master position the cam is at.
    pub master: f64,
    /// The slave set point.
    pub slave: f64,
    /// The output of each track, in the order of the cam's tracks.
    pub tappets: Vec<bool>,
}
