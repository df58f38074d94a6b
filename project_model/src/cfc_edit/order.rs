//! The execution order commands of CODESYS's explicit execution order mode: Send to Front,
//! Send to Back, Move Up, Move Down, Set Execution Order, Order by Data Flow and Order by
//! Topology. Each takes the selected elements (the non-executable ones among them are
//! refused) and renumbers the chart densely.

use std::collections::{HashMap, HashSet};

use super::{CfcEditError, element};
use crate::{CfcChart, CfcElementKind, ElementId};

/// The executable elements in their execution order.
fn sequence(chart: &CfcChart) -> Vec<ElementId> {
    let mut executable: Vec<(u32, ElementId)> = chart
        .elements
        .iter()
        .filter_map(|element| element.order.map(|order| (order, element.id)))
        .collect();
    executable.sort();
    executable.into_iter().map(|(_, id)| id).collect()
}

/// `chart` with its elements numbered in the sequence `ids`.
fn numbered(chart: &CfcChart, ids: &[ElementId]) -> CfcChart {
    let place: HashMap<ElementId, u32> = ids.iter().zip(0_u32..).map(|(id, n)| (*id, n)).collect();
    let mut chart = chart.clone();
    for element in &mut chart.elements {
        element.order = place.get(&element.id).copied();
    }
    chart
}

/// The selected executable elements in their current order; refuses an empty selection and
/// elements that are not executable.
fn selected(chart: &CfcChart, ids: &[ElementId]) -> Result<HashSet<ElementId>, CfcEditError> {
    if ids.is_empty() {
        return Err(CfcEditError::NothingSelected);
    }
    for id in ids {
        if !element(chart, *id)?.kind.is_executable() {
            return Err(CfcEditError::NotExecutable(*id));
        }
    }
    Ok(ids.iter().copied().collect())
}

/// Makes the elements `ids` run first (keeping their relative order).
pub fn send_to_front(chart: &CfcChart, ids: &[ElementId]) -> Result<CfcChart, CfcEditError> {
    let chosen = selected(chart, ids)?;
    let (mut front, rest): (Vec<_>, Vec<_>) = sequence(chart)
        .into_iter()
        .partition(|id| chosen.contains(id));
    front.extend(rest);
    Ok(numbered(chart, &front))
}

/// Makes the elements `ids` run last (keeping their relative order).
pub fn send_to_back(chart: &CfcChart, ids: &[ElementId]) -> Result<CfcChart, CfcEditError> {
    let chosen = selected(chart, ids)?;
    let (back, mut rest): (Vec<_>, Vec<_>) = sequence(chart)
        .into_iter()
        .partition(|id| chosen.contains(id));
    rest.extend(back);
    Ok(numbered(chart, &rest))
}

/// Moves each of the elements `ids` one place earlier in the order (one already first, or
/// behind another selected one at the front, stays).
pub fn move_up(chart: &CfcChart, ids: &[ElementId]) -> Result<CfcChart, CfcEditError> {
    let chosen = selected(chart, ids)?;
    let mut order = sequence(chart);
    for index in 1..order.len() {
        if chosen.contains(&order[index]) && !chosen.contains(&order[index - 1]) {
            order.swap(index, index - 1);
        }
    }
    Ok(numbered(chart, &order))
}

/// Moves each of the elements `ids` one place later in the order.
pub fn move_down(chart: &CfcChart, ids: &[ElementId]) -> Result<CfcChart, CfcEditError> {
    let chosen = selected(chart, ids)?;
    let mut order = sequence(chart);
    for index in (0..order.len().saturating_sub(1)).rev() {
        if chosen.contains(&order[index]) && !chosen.contains(&order[index + 1]) {
            order.swap(index, index + 1);
        }
    }
    Ok(numbered(chart, &order))
}

/// Gives the element `id` the execution order `order`; the others keep their sequence around
/// it.
pub fn set_execution_order(
    chart: &CfcChart,
    id: ElementId,
    order: u32,
) -> Result<CfcChart, CfcEditError> {
    selected(chart, &[id])?;
    let mut sequence = sequence(chart);
    let count = sequence.len() as u32;
    if order >= count {
        return Err(CfcEditError::OrderOutOfRange { order, count });
    }
    sequence.retain(|other| *other != id);
    sequence.insert(order as usize, id);
    Ok(numbered(chart, &sequence))
}

/// The topology key of an element: top to bottom, then left to right.
fn topology_key(chart: &CfcChart) -> HashMap<ElementId, (i32, i32, u32)> {
    chart
        .elements
        .iter()
        .map(|element| (element.id, (element.y, element.x, element.id.0)))
        .collect()
}

/// Numbers the executable elements by their place: top to bottom, then left to right.
pub fn order_by_topology(chart: &CfcChart) -> CfcChart {
    let key = topology_key(chart);
    let mut ids = sequence(chart);
    ids.sort_by_key(|id| key[id]);
    numbered(chart, &ids)
}

/// The executable elements each executable element reads from, looking through inputs and
/// connection marks (a sink reads what drives its source of the same name).
fn dependencies(chart: &CfcChart) -> HashMap<ElementId, HashSet<ElementId>> {
    let kinds: HashMap<ElementId, &CfcElementKind> = chart
        .elements
        .iter()
        .map(|element| (element.id, &element.kind))
        .collect();
    let drivers: HashMap<ElementId, Vec<ElementId>> =
        chart.wires.iter().fold(HashMap::new(), |mut map, wire| {
            map.entry(wire.to.element)
                .or_default()
                .push(wire.from.element);
            map
        });
    let sources: HashMap<String, Vec<ElementId>> =
        chart
            .elements
            .iter()
            .fold(HashMap::new(), |mut map, element| {
                if let CfcElementKind::ConnectionSource { name } = &element.kind {
                    map.entry(name.to_lowercase()).or_default().push(element.id);
                }
                map
            });
    // The executable elements whose values reach `id` through non-executable elements.
    let resolve = |start: ElementId| -> HashSet<ElementId> {
        let mut found = HashSet::new();
        let mut seen = HashSet::new();
        let mut pending = vec![start];
        while let Some(id) = pending.pop() {
            if !seen.insert(id) {
                continue;
            }
            match kinds.get(&id) {
                Some(kind) if kind.is_executable() => {
                    found.insert(id);
                }
                Some(CfcElementKind::ConnectionSink { name }) => {
                    for source in sources.get(&name.to_lowercase()).into_iter().flatten() {
                        pending.extend(drivers.get(source).into_iter().flatten().copied());
                    }
                }
                Some(CfcElementKind::ConnectionSource { .. }) => {
                    pending.extend(drivers.get(&id).into_iter().flatten().copied());
                }
                _ => {}
            }
        }
        found
    };
    chart
        .elements
        .iter()
        .filter(|element| element.kind.is_executable())
        .map(|element| {
            let reads = drivers
                .get(&element.id)
                .into_iter()
                .flatten()
                .flat_map(|driver| resolve(*driver))
                .collect();
            (element.id, reads)
        })
        .collect()
}

/// Numbers the executable elements by data flow: an element runs once everything it reads
/// has run; among the elements that are ready, the topmost (then leftmost) runs first. When
/// only loops are left, the topmost element of them runs next and its unmet inputs become
/// feedback wires, which read the previous cycle's value (CoDeSys: "feedback paths are
/// inserted last").
pub fn order_by_data_flow(chart: &CfcChart) -> CfcChart {
    let key = topology_key(chart);
    let mut waiting = dependencies(chart);
    let mut done: HashSet<ElementId> = HashSet::new();
    let mut order = Vec::new();
    while !waiting.is_empty() {
        let ready = waiting
            .iter()
            .filter(|(id, reads)| reads.iter().all(|read| done.contains(read) || read == *id))
            .map(|(id, _)| *id)
            .min_by_key(|id| key[id]);
        // When only loops are left, the topmost element of them runs next.
        let Some(next) = ready.or_else(|| waiting.keys().copied().min_by_key(|id| key[id])) else {
            break;
        };
        waiting.remove(&next);
        done.insert(next);
        order.push(next);
    }
    numbered(chart, &order)
}

/// The ids in execution order, for the tests of the commands.
#[cfg(test)]
pub(super) fn tests_sequence(chart: &CfcChart) -> Vec<u32> {
    sequence(chart).into_iter().map(|id| id.0).collect()
}
