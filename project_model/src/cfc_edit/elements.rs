//! Adding, moving, deleting, copying and pasting elements.

use std::collections::{HashMap, HashSet};

use super::{CfcEditError, element, renumber};
use crate::{CfcChart, CfcElement, CfcElementKind, ElementId, GridPoint};

/// The id a new element gets: one more than the largest in the chart.
fn next_id(chart: &CfcChart) -> ElementId {
    ElementId(
        chart
            .elements
            .iter()
            .map(|element| element.id.0 + 1)
            .max()
            .unwrap_or(0),
    )
}

/// Adds an element of `kind` with its top-left corner at `at`; an executable one runs last.
/// Returns the new chart and the new element's id.
pub fn add_element(chart: &CfcChart, kind: CfcElementKind, at: GridPoint) -> (CfcChart, ElementId) {
    let mut chart = chart.clone();
    let id = next_id(&chart);
    let order = kind.is_executable().then(|| {
        chart
            .elements
            .iter()
            .filter(|element| element.order.is_some())
            .count() as u32
    });
    chart.elements.push(CfcElement {
        id,
        x: at.x,
        y: at.y,
        order,
        kind,
    });
    (chart, id)
}

/// Moves the elements `ids` by `delta` grid units. The control points of a wire between two
/// moved elements move with them; the others stay where the user pinned them.
pub fn move_elements(
    chart: &CfcChart,
    ids: &[ElementId],
    delta: GridPoint,
) -> Result<CfcChart, CfcEditError> {
    if ids.is_empty() {
        return Err(CfcEditError::NothingSelected);
    }
    for id in ids {
        element(chart, *id)?;
    }
    let moved: HashSet<ElementId> = ids.iter().copied().collect();
    let mut chart = chart.clone();
    for element in &mut chart.elements {
        if moved.contains(&element.id) {
            element.x += delta.x;
            element.y += delta.y;
        }
    }
    for wire in &mut chart.wires {
        if moved.contains(&wire.from.element) && moved.contains(&wire.to.element) {
            for point in &mut wire.points {
                point.x += delta.x;
                point.y += delta.y;
            }
        }
    }
    Ok(chart)
}

/// Deletes the elements `ids` and every wire to or from them; the execution order closes up.
pub fn delete_elements(chart: &CfcChart, ids: &[ElementId]) -> Result<CfcChart, CfcEditError> {
    if ids.is_empty() {
        return Err(CfcEditError::NothingSelected);
    }
    for id in ids {
        element(chart, *id)?;
    }
    let gone: HashSet<ElementId> = ids.iter().copied().collect();
    let mut chart = chart.clone();
    chart.elements.retain(|element| !gone.contains(&element.id));
    chart
        .wires
        .retain(|wire| !gone.contains(&wire.from.element) && !gone.contains(&wire.to.element));
    renumber(&mut chart);
    Ok(chart)
}

/// The elements `ids` and the wires between them, as a chart of their own (for the
/// clipboard); their execution order keeps its relative sequence.
pub fn copy_elements(chart: &CfcChart, ids: &[ElementId]) -> Result<CfcChart, CfcEditError> {
    if ids.is_empty() {
        return Err(CfcEditError::NothingSelected);
    }
    for id in ids {
        element(chart, *id)?;
    }
    let chosen: HashSet<ElementId> = ids.iter().copied().collect();
    let mut fragment = CfcChart {
        elements: chart
            .elements
            .iter()
            .filter(|element| chosen.contains(&element.id))
            .cloned()
            .collect(),
        wires: chart
            .wires
            .iter()
            .filter(|wire| chosen.contains(&wire.from.element) && chosen.contains(&wire.to.element))
            .cloned()
            .collect(),
    };
    renumber(&mut fragment);
    Ok(fragment)
}

/// Pastes `fragment` into `chart`, moved by `offset`: every element gets a fresh id and its
/// executable elements run after the chart's, in the fragment's order. Returns the new chart
/// and the pasted elements' ids.
pub fn paste_elements(
    chart: &CfcChart,
    fragment: &CfcChart,
    offset: GridPoint,
) -> (CfcChart, Vec<ElementId>) {
    let mut chart = chart.clone();
    let first = next_id(&chart).0;
    let first_order = chart
        .elements
        .iter()
        .filter(|element| element.order.is_some())
        .count() as u32;
    let mut fresh: HashMap<ElementId, ElementId> = HashMap::new();
    let mut pasted = Vec::new();
    let mut sorted = fragment.clone();
    renumber(&mut sorted);
    for (element, id) in sorted.elements.iter().zip(first..) {
        fresh.insert(element.id, ElementId(id));
        pasted.push(ElementId(id));
        chart.elements.push(CfcElement {
            id: ElementId(id),
            x: element.x + offset.x,
            y: element.y + offset.y,
            order: element.order.map(|order| first_order + order),
            kind: element.kind.clone(),
        });
    }
    for wire in &sorted.wires {
        let (Some(from), Some(to)) = (fresh.get(&wire.from.element), fresh.get(&wire.to.element))
        else {
            continue;
        };
        let mut wire = wire.clone();
        wire.from.element = *from;
        wire.to.element = *to;
        for point in &mut wire.points {
            point.x += offset.x;
            point.y += offset.y;
        }
        chart.wires.push(wire);
    }
    renumber(&mut chart);
    (chart, pasted)
}
