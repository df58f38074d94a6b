//! The SFC flags a POU with a chart declares (`SFCInit`, `SFCError`, …): each must have the
//! type CODESYS gives it, BOOL or STRING (E0122).

use project_model::Pou;

use super::Globals;
use crate::diagnostic::{Code, Diagnostic};
use crate::sema::ty::Type;
use crate::sfc_chart::SFC_FLAGS;

/// Whether `name` is an SFC flag of `pou`: the chart reads and writes it, so it is used.
pub(super) fn is_sfc_flag_of(pou: &Pou, name: &str) -> bool {
    SFC_FLAGS
        .iter()
        .any(|(flag, _)| flag.eq_ignore_ascii_case(name))
        && pou
            .body
            .st_text()
            .is_some_and(crate::sfc_chart::may_hold_chart)
}

/// Reports, through `report` (by declared name), every SFC flag of `pou` declared with a type
/// other than its own. Only a POU whose body holds a chart has SFC flags.
pub(super) fn check_sfc_flags(
    globals: &Globals<'_>,
    pou: &Pou,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    let holds_chart = pou
        .body
        .st_text()
        .is_some_and(crate::sfc_chart::may_hold_chart);
    if !holds_chart {
        return;
    }
    for variable in &pou.variables {
        let Some((flag, is_string)) = SFC_FLAGS
            .iter()
            .find(|(flag, _)| flag.eq_ignore_ascii_case(&variable.name))
        else {
            continue;
        };
        let ty = globals.resolve_type(&variable.ty);
        let fits = if *is_string {
            matches!(ty, Type::String { wide: false, .. })
        } else {
            ty == Type::BOOL
        };
        if !fits {
            report(
                &variable.name,
                Diagnostic::new(
                    Code::SfcFlagType,
                    0..0,
                    format!(
                        "the SFC flag {flag} is a {}, not {}",
                        if *is_string { "STRING" } else { "BOOL" },
                        variable.ty
                    ),
                ),
            );
        }
    }
}
