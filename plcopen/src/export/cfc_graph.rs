//! CFC charts as PLCopen FBD bodies (`docs/plcopen-xml.md` §5.2): every element at its grid
//! position × 10, wires as connections (with their control points) at the pin they end at,
//! `executionOrderId` Rivet's order + 1 on executable elements (0 for none).

use project_model::{CfcChart, CfcElement, CfcElementKind, CfcPin, CoilKind, Edge, GridPoint};

use super::error::ExportError;
use super::xml_writer::XmlWriter;

/// Writes the objects of `chart` (inside the `FBD` element).
pub(super) fn write_cfc(xml: &mut XmlWriter, chart: &CfcChart) -> Result<(), ExportError> {
    for element in &chart.elements {
        CfcObject {
            xml,
            chart,
            element,
        }
        .write()?;
    }
    Ok(())
}

/// One element being written.
struct CfcObject<'a, 'x> {
    xml: &'x mut XmlWriter,
    chart: &'a CfcChart,
    element: &'a CfcElement,
}

impl CfcObject<'_, '_> {
    fn write(mut self) -> Result<(), ExportError> {
        let element = self.element;
        let id = element.id.0.to_string();
        let order = element
            .order
            .map_or(0, |order| u64::from(order) + 1)
            .to_string();
        let mut attributes = vec![("localId", id.as_str())];
        if element.kind.is_executable() {
            attributes.push(("executionOrderId", &order));
        }
        match &element.kind {
            CfcElementKind::Input { expression } => {
                self.xml.start("inVariable", &attributes)?;
                self.position()?;
                self.xml.empty("connectionPointOut", &[])?;
                self.xml.text_element("expression", &[], expression)?;
                self.xml.end("inVariable")
            }
            CfcElementKind::Output { expression, coil } => {
                match coil {
                    CoilKind::Normal => {}
                    CoilKind::Negated => attributes.push(("negated", "true")),
                    CoilKind::Set => attributes.push(("storage", "set")),
                    CoilKind::Reset => attributes.push(("storage", "reset")),
                    CoilKind::Rising => attributes.push(("edge", "rising")),
                    CoilKind::Falling => attributes.push(("edge", "falling")),
                }
                self.xml.start("outVariable", &attributes)?;
                self.position()?;
                self.input("")?;
                self.xml.text_element("expression", &[], expression)?;
                self.xml.end("outVariable")
            }
            CfcElementKind::Box(block) => {
                attributes.push(("typeName", &block.type_name));
                if !block.instance.is_empty() {
                    attributes.push(("instanceName", &block.instance));
                }
                self.block(&attributes, &block.inputs, &block.outputs)
            }
            CfcElementKind::Composer { type_name, inputs } => {
                attributes.push(("typeName", type_name));
                self.block(&attributes, inputs, &[CfcPin::named("")])
            }
            CfcElementKind::Selector { type_name, outputs } => {
                attributes.push(("typeName", type_name));
                self.block(&attributes, &[CfcPin::named("")], outputs)
            }
            CfcElementKind::Jump { label } => {
                attributes.push(("label", label));
                self.xml.start("jump", &attributes)?;
                self.position()?;
                self.input("")?;
                self.xml.end("jump")
            }
            CfcElementKind::Label { name } => {
                attributes.push(("label", name));
                self.xml.start("label", &attributes)?;
                self.position()?;
                self.xml.end("label")
            }
            CfcElementKind::Return => {
                self.xml.start("return", &attributes)?;
                self.position()?;
                self.input("")?;
                self.xml.end("return")
            }
            CfcElementKind::Comment {
                text,
                width,
                height,
            } => {
                let (width, height) = ((width * 10).to_string(), (height * 10).to_string());
                attributes.push(("height", &height));
                attributes.push(("width", &width));
                self.xml.start("comment", &attributes)?;
                self.position()?;
                self.xml.start("content", &[])?;
                self.xml.start("xhtml:p", &[])?;
                self.xml.cdata(text)?;
                self.xml.end("xhtml:p")?;
                self.xml.end("content")?;
                self.xml.end("comment")
            }
            CfcElementKind::ConnectionSource { name } => {
                attributes.push(("name", name));
                self.xml.start("connector", &attributes)?;
                self.position()?;
                self.input("")?;
                self.xml.end("connector")
            }
            CfcElementKind::ConnectionSink { name } => {
                attributes.push(("name", name));
                self.xml.start("continuation", &attributes)?;
                self.position()?;
                self.xml.empty("connectionPointOut", &[])?;
                self.xml.end("continuation")
            }
        }
    }

    fn block(
        &mut self,
        attributes: &[(&str, &str)],
        inputs: &[CfcPin],
        outputs: &[CfcPin],
    ) -> Result<(), ExportError> {
        self.xml.start("block", attributes)?;
        self.position()?;
        self.xml.start("inputVariables", &[])?;
        for pin in inputs {
            self.xml.start("variable", &pin_attributes(pin))?;
            self.input(&pin.name)?;
            self.xml.end("variable")?;
        }
        self.xml.end("inputVariables")?;
        self.xml.empty("inOutVariables", &[])?;
        self.xml.start("outputVariables", &[])?;
        for pin in outputs {
            self.xml.start("variable", &pin_attributes(pin))?;
            self.xml.empty("connectionPointOut", &[])?;
            self.xml.end("variable")?;
        }
        self.xml.end("outputVariables")?;
        self.xml.end("block")
    }

    /// The `connectionPointIn` of the pin `pin` (`""` for an element's only input): one
    /// connection per wire ending there, in the chart's order, with its control points.
    fn input(&mut self, pin: &str) -> Result<(), ExportError> {
        self.xml.start("connectionPointIn", &[])?;
        let element = self.element.id;
        for wire in &self.chart.wires {
            // A wire from an element the chart does not hold would name no object of the body.
            let known = |id| self.chart.elements.iter().any(|e| e.id == id);
            if wire.to.element != element
                || !wire.to.pin.eq_ignore_ascii_case(pin)
                || !known(wire.from.element)
            {
                continue;
            }
            let from = wire.from.element.0.to_string();
            let mut attributes = vec![("refLocalId", from.as_str())];
            if !wire.from.pin.is_empty() {
                attributes.push(("formalParameter", &wire.from.pin));
            }
            if wire.points.is_empty() {
                self.xml.empty("connection", &attributes)?;
                continue;
            }
            self.xml.start("connection", &attributes)?;
            for point in &wire.points {
                write_point(self.xml, *point)?;
            }
            self.xml.end("connection")?;
        }
        self.xml.end("connectionPointIn")
    }

    fn position(&mut self) -> Result<(), ExportError> {
        write_point(
            self.xml,
            GridPoint {
                x: self.element.x,
                y: self.element.y,
            },
        )
    }
}

/// A grid point as a `position`, grid units × 10.
fn write_point(xml: &mut XmlWriter, point: GridPoint) -> Result<(), ExportError> {
    let x = (i64::from(point.x) * 10).to_string();
    let y = (i64::from(point.y) * 10).to_string();
    xml.empty("position", &[("x", &x), ("y", &y)])
}

fn pin_attributes(pin: &CfcPin) -> Vec<(&str, &str)> {
    let mut attributes = vec![("formalParameter", pin.name.as_str())];
    if pin.negated {
        attributes.push(("negated", "true"));
    }
    match pin.edge {
        Edge::None => {}
        Edge::Rising => attributes.push(("edge", "rising")),
        Edge::Falling => attributes.push(("edge", "falling")),
    }
    attributes
}
