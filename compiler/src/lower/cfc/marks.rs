//! Connection marks resolved to the pin that drives their source, before anything is written.

use std::collections::{HashMap, HashSet};

use project_model::{CfcChart, CfcElementKind, ElementId};

use super::{Chart, key};
use crate::diagnostic::Code;
use crate::lower::network::BodyLowering;

impl BodyLowering<'_> {
    /// Resolves every connection sink to the output pin wired into its source (through other
    /// marks), reporting a sink without a source, a name given to two sources, a source
    /// without an input and marks that only feed each other.
    pub(super) fn resolve_marks(&mut self, chart: &mut Chart<'_>, cfc: &CfcChart) {
        let mut sources: HashMap<String, Vec<ElementId>> = HashMap::new();
        for element in &cfc.elements {
            if let CfcElementKind::ConnectionSource { name } = &element.kind {
                let named = sources.entry(name.trim().to_lowercase()).or_default();
                if let Some(first) = named.first() {
                    self.find(
                        element.id,
                        None,
                        Code::DuplicateConnectionSource,
                        format!(
                            "the connection mark '{}' is also the source of element {}; sinks would not know which to read",
                            name.trim(),
                            first.0
                        ),
                    );
                }
                named.push(element.id);
            }
        }
        let mut unwired: HashSet<ElementId> = HashSet::new();
        for sink in &cfc.elements {
            let CfcElementKind::ConnectionSink { .. } = &sink.kind else {
                continue;
            };
            let mut at = sink.id;
            let mut seen = HashSet::from([sink.id]);
            while let Some(CfcElementKind::ConnectionSink { name }) =
                chart.elements.get(&at).map(|element| &element.kind)
            {
                let Some(source) = sources
                    .get(&name.trim().to_lowercase())
                    .and_then(|named| named.first().copied())
                else {
                    self.find(
                        sink.id,
                        None,
                        Code::ConnectionWithoutSource,
                        format!(
                            "no connection mark source of this chart is named '{}'",
                            name.trim()
                        ),
                    );
                    break;
                };
                let Some(wire) = chart.into.get(&key(source, "")) else {
                    if unwired.insert(source) {
                        self.find(
                            source,
                            None,
                            Code::InvalidCfcElement,
                            format!(
                                "the connection mark '{}' is read by its sinks, but nothing is wired into it",
                                name.trim()
                            ),
                        );
                    }
                    break;
                };
                let driver = wire.from.clone();
                let is_sink = matches!(
                    chart
                        .elements
                        .get(&driver.element)
                        .map(|element| &element.kind),
                    Some(CfcElementKind::ConnectionSink { .. })
                );
                if !is_sink {
                    chart.sinks.insert(sink.id, driver);
                    break;
                }
                if !seen.insert(driver.element) {
                    self.find(
                        sink.id,
                        None,
                        Code::ConnectionLoop,
                        format!(
                            "the connection mark '{}' is fed only by connection marks that it feeds, so no value reaches it",
                            name.trim()
                        ),
                    );
                    break;
                }
                at = driver.element;
            }
        }
    }
}
