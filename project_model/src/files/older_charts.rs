//! CFC and SFC charts of format versions 1 and 2 (graphs of placed elements and connections)
//! turned into the current [`CfcChart`] and [`SfcChart`].
//!
//! A CFC graph maps element for element: its elements keep their ids and positions, its
//! connections become wires, and the executable elements are numbered in the order the old
//! `execution_order` gave them (elements without one last, top to bottom and left to right).
//! The chart's label and comment, which a CFC chart no longer has, become a label element run
//! first and a comment element, so nothing written is lost.

use thiserror::Error;

use super::graph_chart::{Chart, ChartElement, ChartElementKind};
use crate::{
    CfcBox, CfcChart, CfcElement, CfcElementKind, CfcPin, CoilKind, EN_PIN, ENO_PIN, ElementId,
    SfcChart, Wire,
};

/// Converts the graph of a CFC body, or says which element has no CFC equivalent.
pub(crate) fn cfc_from_graph(graph: &Chart) -> Result<CfcChart, Vec<String>> {
    let mut problems = Vec::new();
    let mut elements = Vec::new();
    let mut next_id = graph
        .elements
        .iter()
        .map(|element| element.id.0)
        .max()
        .unwrap_or(0)
        + 1;
    let top = graph.elements.iter().map(|e| e.y).min().unwrap_or(0);
    if !graph.label.is_empty() {
        elements.push((
            Some(0),
            CfcElement {
                id: ElementId(next_id),
                x: 0,
                y: top - 2,
                order: None,
                kind: CfcElementKind::Label {
                    name: graph.label.clone(),
                },
            },
        ));
        next_id += 1;
    }
    if !graph.comment.is_empty() {
        elements.push((
            None,
            CfcElement {
                id: ElementId(next_id),
                x: 0,
                y: top - 4,
                order: None,
                kind: CfcElementKind::Comment {
                    text: graph.comment.clone(),
                    width: 20,
                    height: 2,
                },
            },
        ));
    }
    for element in &graph.elements {
        match cfc_kind(element) {
            Ok(kind) => elements.push((
                element.execution_order.map(|order| order.saturating_add(1)),
                CfcElement {
                    id: element.id,
                    x: element.x,
                    y: element.y,
                    order: None,
                    kind,
                },
            )),
            Err(problem) => problems.push(problem.to_string()),
        }
    }
    if !problems.is_empty() {
        return Err(problems);
    }
    // Old orders first (shifted by one so the chart's label runs before them), then the
    // elements without one by position.
    let mut runnable: Vec<(u32, i32, i32, ElementId)> = elements
        .iter()
        .filter(|(_, element)| element.kind.is_executable())
        .map(|(order, element)| (order.unwrap_or(u32::MAX), element.y, element.x, element.id))
        .collect();
    runnable.sort();
    let mut chart = CfcChart {
        elements: elements.into_iter().map(|(_, element)| element).collect(),
        wires: graph
            .connections
            .iter()
            .map(|connection| Wire::routed(connection.from.clone(), connection.to.clone()))
            .collect(),
    };
    for (position, (.., id)) in runnable.into_iter().enumerate() {
        if let Some(element) = chart.elements.iter_mut().find(|e| e.id == id) {
            element.order = u32::try_from(position).ok();
        }
    }
    Ok(chart)
}

/// Why an element of an old CFC graph has no CFC kind.
#[derive(Debug, Error)]
enum NotCfc {
    /// A rail, contact or coil: an element of a ladder diagram.
    #[error("element {element}: an LD element cannot be part of a CFC chart")]
    LdElement {
        /// The element's id.
        element: u32,
    },
    /// A step, transition, branch or step jump: an element of a sequential function chart.
    #[error("element {element}: an SFC element cannot be part of a CFC chart")]
    SfcElement {
        /// The element's id.
        element: u32,
    },
}

/// The CFC kind of one old element, or why it has none.
fn cfc_kind(element: &ChartElement) -> Result<CfcElementKind, NotCfc> {
    let pin = |name: &String| CfcPin::named(name.clone());
    Ok(match &element.kind {
        ChartElementKind::Input { expression } => CfcElementKind::Input {
            expression: expression.clone(),
        },
        ChartElementKind::Output { expression } => CfcElementKind::Output {
            expression: expression.clone(),
            coil: CoilKind::Normal,
        },
        ChartElementKind::Block {
            type_name,
            instance,
            inputs,
            outputs,
            en_eno,
        } => {
            let mut box_inputs: Vec<CfcPin> = inputs.iter().map(pin).collect();
            let mut box_outputs: Vec<CfcPin> = outputs.iter().map(pin).collect();
            let has = |pins: &[CfcPin], name: &str| {
                pins.iter().any(|p| p.name.eq_ignore_ascii_case(name))
            };
            if *en_eno && !has(&box_inputs, EN_PIN) {
                box_inputs.insert(0, pin(&EN_PIN.to_owned()));
            }
            if *en_eno && !has(&box_outputs, ENO_PIN) {
                box_outputs.insert(0, pin(&ENO_PIN.to_owned()));
            }
            CfcElementKind::Box(CfcBox {
                type_name: type_name.clone(),
                instance: instance.clone(),
                inputs: box_inputs,
                outputs: box_outputs,
            })
        }
        ChartElementKind::Jump { label } => CfcElementKind::Jump {
            label: label.clone(),
        },
        ChartElementKind::Return => CfcElementKind::Return,
        ChartElementKind::Comment {
            text,
            width,
            height,
        } => CfcElementKind::Comment {
            text: text.clone(),
            width: *width,
            height: *height,
        },
        ChartElementKind::Connector { name } => {
            CfcElementKind::ConnectionSource { name: name.clone() }
        }
        ChartElementKind::Continuation { name } => {
            CfcElementKind::ConnectionSink { name: name.clone() }
        }
        ChartElementKind::LeftRail { .. }
        | ChartElementKind::RightRail { .. }
        | ChartElementKind::Contact { .. }
        | ChartElementKind::Coil { .. } => {
            return Err(NotCfc::LdElement {
                element: element.id.0,
            });
        }
        ChartElementKind::Step { .. }
        | ChartElementKind::Transition { .. }
        | ChartElementKind::Divergence { .. }
        | ChartElementKind::Convergence { .. }
        | ChartElementKind::StepJump { .. } => {
            return Err(NotCfc::SfcElement {
                element: element.id.0,
            });
        }
    })
}

/// Converts the graph of an SFC body into the structured chart, or says where its graph has
/// no structured equivalent (`older_sfc.rs`).
pub(crate) fn sfc_from_graph(graph: &Chart) -> Result<SfcChart, Vec<String>> {
    super::older_sfc::sfc_from_graph(graph)
}

#[cfg(test)]
mod tests {
    use super::NotCfc;

    #[test]
    fn an_element_without_a_cfc_kind_is_named_with_its_language() {
        assert_eq!(
            NotCfc::LdElement { element: 4 }.to_string(),
            "element 4: an LD element cannot be part of a CFC chart"
        );
        assert_eq!(
            NotCfc::SfcElement { element: 7 }.to_string(),
            "element 7: an SFC element cannot be part of a CFC chart"
        );
    }
}
