//! The live check's findings and the target's faults as the diagram editor's markers.

use compiler::lower::LoweredBody;
use compiler::origin::Origin;
use compiler::sema::ProjectDiagnostic;
use editor::{ElementDiagnostic, Severity};
use online::Fault;
use project_model::TextTarget;

use crate::studio::i18n::{DiagramText, Language};

/// The findings in the body `target`, each at its network, element and pin.
pub(super) fn element_diagnostics(
    findings: &[ProjectDiagnostic],
    target: &TextTarget,
) -> Vec<ElementDiagnostic> {
    findings
        .iter()
        .filter_map(|found| {
            let place = found.element.as_ref()?;
            (place.target == *target).then(|| ElementDiagnostic {
                network: place.network,
                element: place.element,
                pin: place.pin.clone(),
                severity: match found.diagnostic.severity {
                    compiler::Severity::Error => Severity::Error,
                    compiler::Severity::Warning => Severity::Warning,
                },
                code: found.diagnostic.code.id().to_owned(),
                message: found.diagnostic.message.clone(),
            })
        })
        .collect()
}

/// The faults the target reported in the lowered body `body`, as errors on the network that
/// faulted and on the element whose statement faulted.
pub(super) fn fault_diagnostics(
    faults: &[Fault],
    body: &LoweredBody,
    language: Language,
) -> Vec<ElementDiagnostic> {
    let mut found = Vec::new();
    for fault in faults {
        if std::path::Path::new(&fault.file) != body.text_file {
            continue;
        }
        let Some(Origin::Element {
            network,
            element,
            pin,
        }) = body.origin_at_line(fault.line)
        else {
            continue;
        };
        let message = DiagramText::FaultHere.fill(language, &[("reason", &fault.kind)]);
        // The network is highlighted as a whole, and the element marked where it is known.
        found.push(ElementDiagnostic {
            network,
            element: None,
            pin: None,
            severity: Severity::Error,
            code: String::new(),
            message: message.clone(),
        });
        if element.is_some() {
            found.push(ElementDiagnostic {
                network,
                element,
                pin,
                severity: Severity::Error,
                code: String::new(),
                message,
            });
        }
    }
    found
}
