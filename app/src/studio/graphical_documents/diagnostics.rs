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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fault_in_a_lowered_line_marks_its_network_and_element() {
        let project = project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        let lowered = compiler::lower::lower_project(&project);
        let body = lowered
            .bodies
            .iter()
            .find(|body| body.pou == "Interlock")
            .expect("the Interlock is lowered");
        // The first line that belongs to an element of the last network.
        let (line, network, element) = (1..=body.text.lines().count() as u32)
            .find_map(|line| match body.origin_at_line(line) {
                Some(Origin::Element {
                    network: 3,
                    element: Some(element),
                    ..
                }) => Some((line, 3, element)),
                _ => None,
            })
            .expect("a line of network 4");
        let fault = |file: &str| Fault {
            task: "MainTask".to_owned(),
            kind: "division by zero".to_owned(),
            pou: "Interlock".to_owned(),
            file: file.to_owned(),
            line,
            cycle: 7,
        };
        let text_file = body.text_file.to_string_lossy().into_owned();
        let found = fault_diagnostics(&[fault(&text_file)], body, Language::English);
        assert_eq!(found.len(), 2, "{found:?}");
        assert!(found.iter().all(|marker| marker.network == network
            && marker.severity == Severity::Error
            && marker.message == "runtime fault: division by zero"));
        assert_eq!(found[0].element, None);
        assert_eq!(found[1].element, Some(element));
        // A fault in another body marks nothing here.
        assert!(
            fault_diagnostics(&[fault("application/Main.st")], body, Language::English).is_empty()
        );
    }

    #[test]
    fn a_fault_in_a_cfc_chart_marks_its_element() {
        let project = project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        let lowered = compiler::lower::lower_project(&project);
        let body = lowered
            .bodies
            .iter()
            .find(|body| body.pou == "TempControl")
            .expect("TempControl is lowered");
        // The line of the plant's MUL box (element 11).
        let line = (1..=body.text.lines().count() as u32)
            .find(|line| {
                matches!(
                    body.origin_at_line(*line),
                    Some(Origin::Element {
                        element: Some(project_model::ElementId(11)),
                        ..
                    })
                )
            })
            .expect("a line of element 11");
        let fault = Fault {
            task: "MainTask".to_owned(),
            kind: "overflow".to_owned(),
            pou: "TempControl".to_owned(),
            file: body.text_file.to_string_lossy().into_owned(),
            line,
            cycle: 3,
        };
        let found = fault_diagnostics(&[fault], body, Language::English);
        assert!(
            found.iter().any(|marker| marker.network == 0
                && marker.element == Some(project_model::ElementId(11))),
            "{found:?}"
        );
    }
}
