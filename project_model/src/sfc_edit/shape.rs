//! The structural rules of `sfc.rs`, checked on the result of every edit so that no edit can
//! produce a chart the editor cannot draw or the model cannot save.

use super::error::SfcEditError;
use crate::sfc::SfcChart;
use crate::sfc_check::first_edit_problem;

/// Checks every structural rule of `chart` with the check loading uses (`sfc_check.rs`):
/// alternation, branch shapes, jumps last and to existing steps, macro bodies, step names that
/// are identifiers without `__` and unique, unique ids and action associations. The first
/// broken rule of the chart's shape is returned with the element it breaks at (then a name,
/// a jump target, an association).
pub fn check_structure(chart: &SfcChart) -> Result<(), SfcEditError> {
    match first_edit_problem(chart) {
        Some(problem) => Err(problem.to_edit_error()),
        None => Ok(()),
    }
}
