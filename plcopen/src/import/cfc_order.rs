//! The execution order of a chart built from a graph (docs/plcopen-xml.md §4.6): the
//! document's `executionOrderId`s where it has them, else Beremiz's rule.

use std::collections::{HashMap, HashSet};

use project_model::{CfcElement, CfcElementKind, ElementId, Wire};

/// One element of a chart in the making, with the order the document gave it.
#[derive(Clone, Debug)]
pub(super) struct OrderedElement {
    /// The element.
    pub element: CfcElement,
    /// The object's `executionOrderId` (`None` and `Some(0)` both mean "none").
    pub execution_order_id: Option<u64>,
}

/// The executable elements of `elements` (in document order) in the order they run.
///
/// When any of them has an `executionOrderId` above 0, those run first by that number (ties in
/// document order) and the others follow in document order, as CODESYS's CFC and Rivet's own
/// export number every executable element. Otherwise (Beremiz writes 0 everywhere) the order
/// is Beremiz's generator's: outputs, jumps and returns top to bottom then left to right, each
/// after the elements that drive it (depth first, back through the wires and from a sink to
/// its sources), then the executable elements nothing reached, by position likewise.
pub(super) fn execution_order(elements: &[OrderedElement], wires: &[Wire]) -> Vec<ElementId> {
    let executable: Vec<&OrderedElement> = elements
        .iter()
        .filter(|placed| placed.element.kind.is_executable())
        .collect();
    let numbered = |placed: &&OrderedElement| placed.execution_order_id.is_some_and(|id| id > 0);
    if executable.iter().any(numbered) {
        let mut first: Vec<&OrderedElement> = executable.iter().copied().filter(numbered).collect();
        // A stable sort keeps the document order among equal numbers.
        first.sort_by_key(|placed| placed.execution_order_id);
        let rest = executable
            .iter()
            .copied()
            .filter(|placed| !numbered(placed));
        return first
            .into_iter()
            .chain(rest)
            .map(|placed| placed.element.id)
            .collect();
    }
    by_data_flow(elements, wires)
}

/// Beremiz's order for a graph without execution order ids.
fn by_data_flow(elements: &[OrderedElement], wires: &[Wire]) -> Vec<ElementId> {
    let by_id: HashMap<ElementId, &CfcElement> = elements
        .iter()
        .map(|placed| (placed.element.id, &placed.element))
        .collect();
    let mut drivers: HashMap<ElementId, Vec<ElementId>> = HashMap::new();
    for wire in wires {
        drivers
            .entry(wire.to.element)
            .or_default()
            .push(wire.from.element);
    }
    let mut sources: HashMap<String, Vec<ElementId>> = HashMap::new();
    for placed in elements {
        if let CfcElementKind::ConnectionSource { name } = &placed.element.kind {
            sources
                .entry(name.to_lowercase())
                .or_default()
                .push(placed.element.id);
        }
    }
    let mut roots: Vec<(bool, i32, i32, usize, ElementId)> = elements
        .iter()
        .enumerate()
        .filter(|(_, placed)| placed.element.kind.is_executable())
        .map(|(index, placed)| {
            let writes = matches!(
                placed.element.kind,
                CfcElementKind::Output { .. }
                    | CfcElementKind::Jump { .. }
                    | CfcElementKind::Return
            );
            (
                !writes,
                placed.element.y,
                placed.element.x,
                index,
                placed.element.id,
            )
        })
        .collect();
    roots.sort();
    let mut visited: HashSet<ElementId> = HashSet::new();
    let mut order = Vec::new();
    for (_, _, _, _, root) in roots {
        // An explicit stack, so a long chain cannot overflow the thread's stack.
        let mut stack = vec![(root, false)];
        while let Some((id, expanded)) = stack.pop() {
            if expanded {
                if by_id
                    .get(&id)
                    .is_some_and(|element| element.kind.is_executable())
                {
                    order.push(id);
                }
                continue;
            }
            if !visited.insert(id) {
                continue;
            }
            stack.push((id, true));
            let mut before: Vec<ElementId> = drivers.get(&id).cloned().unwrap_or_default();
            if let Some(CfcElementKind::ConnectionSink { name }) = by_id.get(&id).map(|e| &e.kind) {
                before.extend(sources.get(&name.to_lowercase()).into_iter().flatten());
            }
            // Pushed in reverse, so the first driver is visited (and numbered) first.
            for driver in before.into_iter().rev() {
                if !visited.contains(&driver) {
                    stack.push((driver, false));
                }
            }
        }
    }
    order
}
