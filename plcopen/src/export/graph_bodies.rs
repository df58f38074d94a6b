//! Graphical bodies (LD, FBD, CFC, SFC) as PLCopen graphs.

use project_model::Body;

use super::error::ExportError;
use super::project_writer::ProjectWriter;

impl ProjectWriter<'_> {
    /// Writes a graphical body. Its structure is kept whole in the POU's Rivet entry, which the
    /// import restores it from; where the schema requires a body, an empty ST body stands in.
    pub(super) fn graphical_body(
        &mut self,
        _body: &Body,
        required: bool,
    ) -> Result<(), ExportError> {
        if required {
            self.xml.start("body", &[])?;
            self.xml.start("ST", &[])?;
            self.formatted_text("")?;
            self.xml.end("ST")?;
            self.xml.end("body")?;
        }
        Ok(())
    }
}
