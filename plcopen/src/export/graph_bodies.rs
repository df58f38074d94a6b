//! Graphical bodies as PLCopen graphs: LD and FBD networks (`network_graph.rs`) with the body's
//! `…/networks` entry.

use project_model::Body;

use super::cfc_graph::write_cfc;
use super::error::ExportError;
use super::network_graph::NetworkGraph;
use super::project_writer::ProjectWriter;
use super::sfc_graph::SfcGraph;
use crate::rivet_data::{LANGUAGE_ENTRY, NETWORKS_ENTRY, RIVET_NAMESPACE};

impl ProjectWriter<'_> {
    /// Writes a graphical body; `place` names its vendor data (§5.5). LD and FBD bodies are
    /// written as graphs, CFC charts as FBD bodies marked `…/language` CFC, SFC charts in
    /// Beremiz's form.
    pub(super) fn graphical_body(
        &mut self,
        body: &Body,
        required: bool,
        place: Option<&str>,
    ) -> Result<(), ExportError> {
        let (language, networks) = match body {
            Body::Ld { networks } => ("LD", networks),
            Body::Fbd { networks } => ("FBD", networks),
            Body::Cfc { chart } => {
                self.xml.start("body", &[])?;
                self.xml.start("FBD", &[])?;
                write_cfc(&mut self.xml, chart)?;
                self.xml.end("FBD")?;
                self.xml.start("addData", &[])?;
                if let Some(place) = place {
                    self.vendor_entries(place)?;
                }
                self.xml.start(
                    "data",
                    &[("name", LANGUAGE_ENTRY), ("handleUnknown", "preserve")],
                )?;
                self.xml
                    .empty("language", &[("xmlns", RIVET_NAMESPACE), ("name", "CFC")])?;
                self.xml.end("data")?;
                self.xml.end("addData")?;
                return self.xml.end("body");
            }
            Body::Sfc { chart } => {
                self.xml.start("body", &[])?;
                self.xml.start("SFC", &[])?;
                let transitions = std::mem::take(&mut self.transition_names);
                let written = SfcGraph::new(&mut self.xml, chart, &transitions).write(chart);
                self.transition_names = transitions;
                written?;
                self.xml.end("SFC")?;
                if let Some(place) = place {
                    self.vendor_add_data(place)?;
                }
                return self.xml.end("body");
            }
            // Textual bodies are written by `body`; a caller that passes one here gets it too.
            Body::St { text } => return self.text_body("ST", text, place),
            Body::Il { text } => return self.text_body("IL", text, place),
            Body::None => {
                if required {
                    self.xml.start("body", &[])?;
                    self.xml.start("ST", &[])?;
                    self.formatted_text("")?;
                    self.xml.end("ST")?;
                    self.xml.end("body")?;
                }
                return Ok(());
            }
        };
        self.xml.start("body", &[])?;
        self.xml.start(language, &[])?;
        let element_data = place
            .map(|place| self.element_entries(place, networks))
            .unwrap_or_default();
        let mut graph = NetworkGraph::new(&mut self.xml, language == "LD", networks)
            .with_element_data(element_data);
        let starts = graph.write(networks)?;
        let data_written = graph.data_written().to_vec();
        if let Some(place) = place {
            self.mark_element_entries_written(place, networks, &data_written);
        }
        self.xml.end(language)?;
        self.xml.start("addData", &[])?;
        if let Some(place) = place {
            self.vendor_entries(place)?;
        }
        self.xml.start(
            "data",
            &[("name", NETWORKS_ENTRY), ("handleUnknown", "preserve")],
        )?;
        self.xml.start("networks", &[("xmlns", RIVET_NAMESPACE)])?;
        for start in starts {
            let first = start.first.to_string();
            let mut attributes = vec![("first", first.as_str())];
            let network = start.network;
            for (name, value) in [
                ("title", &network.title),
                ("comment", &network.comment),
                ("label", &network.label),
            ] {
                if !value.is_empty() {
                    attributes.push((name, value));
                }
            }
            self.xml.empty("network", &attributes)?;
        }
        self.xml.end("networks")?;
        self.xml.end("data")?;
        self.xml.end("addData")?;
        self.xml.end("body")
    }
}
