//! The execution order of a chart built from a graph (docs/plcopen-xml.md §4.6): the
//! document's `executionOrderId`s where it has them, else Beremiz's rule.

use std::cmp::Reverse;
use std::collections::{BTreeSet, BinaryHeap, HashMap, HashSet};

use project_model::{CfcElement, CfcElementKind, ElementId, Wire};

use super::cfc_chart::CfcDialect;

/// One element of a chart in the making, with the order the document gave it.
#[derive(Clone, Debug)]
pub(super) struct OrderedElement {
    /// The element.
    pub element: CfcElement,
    /// The object's `executionOrderId` (`None` and `Some(0)` both mean "none").
    pub execution_order_id: Option<u64>,
    /// For the input of an `inOutVariable`'s pair, the pair's output: the input reads what that
    /// output writes, so it counts as driven by it.
    pub reads_write_of: Option<ElementId>,
}

/// What drives each element of a chart in the making: the elements its wires come from, for a
/// connection sink the sources of its name, and (in CODESYS's order) for an in-out's input its
/// output.
struct Drivers<'e> {
    /// The elements by id.
    by_id: HashMap<ElementId, &'e CfcElement>,
    /// The elements wired into each element, in wire order, then the output of an in-out's
    /// input.
    wired: HashMap<ElementId, Vec<ElementId>>,
    /// The connection sources by lower-case name, in document order.
    sources: HashMap<String, Vec<ElementId>>,
}

impl<'e> Drivers<'e> {
    /// The drivers of `elements` through `wires`; an in-out's input is driven by its output
    /// when `in_outs_written_first`.
    fn new(elements: &'e [OrderedElement], wires: &[Wire], in_outs_written_first: bool) -> Self {
        let by_id = elements
            .iter()
            .map(|placed| (placed.element.id, &placed.element))
            .collect();
        let mut wired: HashMap<ElementId, Vec<ElementId>> = HashMap::new();
        for wire in wires {
            wired
                .entry(wire.to.element)
                .or_default()
                .push(wire.from.element);
        }
        let mut sources: HashMap<String, Vec<ElementId>> = HashMap::new();
        for placed in elements {
            if let Some(output) = placed.reads_write_of
                && in_outs_written_first
            {
                wired.entry(placed.element.id).or_default().push(output);
            }
            if let CfcElementKind::ConnectionSource { name } = &placed.element.kind {
                sources
                    .entry(name.to_lowercase())
                    .or_default()
                    .push(placed.element.id);
            }
        }
        Self {
            by_id,
            wired,
            sources,
        }
    }

    /// The kind of the element `id`.
    fn kind(&self, id: ElementId) -> Option<&'e CfcElementKind> {
        self.by_id.get(&id).map(|element| &element.kind)
    }

    /// What `id` reads directly: the elements wired into it, and for a connection sink the
    /// sources of its name.
    fn before(&self, id: ElementId) -> Vec<ElementId> {
        let mut before: Vec<ElementId> = self.wired.get(&id).cloned().unwrap_or_default();
        if let Some(CfcElementKind::ConnectionSink { name }) = self.kind(id) {
            before.extend(self.sources.get(&name.to_lowercase()).into_iter().flatten());
        }
        before
    }
}

/// The executable elements of `elements` (in document order) in the order they run.
///
/// Rivet's own export numbers every executable element: those numbers are the order, exactly
/// (the elements without one follow in document order). Beremiz's files have 0 everywhere:
/// Beremiz's generator's order ([`by_data_flow`]), unless some number is above 0, which is then
/// kept as Rivet's. CODESYS's numbers rank the elements among those whose inputs are ready
/// ([`by_rank_and_flow`]).
pub(super) fn execution_order(
    elements: &[OrderedElement],
    wires: &[Wire],
    dialect: CfcDialect,
) -> Vec<ElementId> {
    let executable: Vec<&OrderedElement> = elements
        .iter()
        .filter(|placed| placed.element.kind.is_executable())
        .collect();
    let numbered = |placed: &&OrderedElement| placed.execution_order_id.is_some_and(|id| id > 0);
    match dialect {
        CfcDialect::Codesys => return by_rank_and_flow(elements, wires),
        CfcDialect::Beremiz if !executable.iter().any(numbered) => {
            return by_data_flow(elements, wires);
        }
        CfcDialect::Beremiz | CfcDialect::Rivet => {}
    }
    let mut first: Vec<&OrderedElement> = executable.iter().copied().filter(numbered).collect();
    // A stable sort keeps the document order among equal numbers.
    first.sort_by_key(|placed| placed.execution_order_id);
    let rest = executable
        .iter()
        .copied()
        .filter(|placed| !numbered(placed));
    first
        .into_iter()
        .chain(rest)
        .map(|placed| placed.element.id)
        .collect()
}

/// The executable elements whose values each executable element reads directly: back through
/// its wires, past the values that are not run (from a sink to the sources of its name, past a
/// source to what drives it, from an in-out's input to its output).
fn executable_drivers(
    elements: &[OrderedElement],
    wires: &[Wire],
) -> HashMap<ElementId, BTreeSet<ElementId>> {
    let links = Drivers::new(elements, wires, true);
    let mut drivers = HashMap::new();
    for placed in elements {
        if !placed.element.kind.is_executable() {
            continue;
        }
        let mut found = BTreeSet::new();
        let mut seen = HashSet::new();
        let mut stack: Vec<ElementId> = links.before(placed.element.id);
        while let Some(id) = stack.pop() {
            if !seen.insert(id) {
                continue;
            }
            match links.kind(id) {
                Some(kind) if kind.is_executable() => {
                    found.insert(id);
                }
                // Past a value that is not run (a sink, a source, an in-out's input) to what
                // it reads.
                Some(_) => stack.extend(links.before(id)),
                None => {}
            }
        }
        found.remove(&placed.element.id);
        drivers.insert(placed.element.id, found);
    }
    drivers
}

/// Data flow first, the document's numbers among the elements it leaves free: an element runs
/// once every executable element it reads has run, and of those ready the one with the lowest
/// number (then the first in the document) runs next. In a feedback loop nothing is ready: the
/// lowest-ranked element left runs and reads the others' values of the previous cycle.
fn by_rank_and_flow(elements: &[OrderedElement], wires: &[Wire]) -> Vec<ElementId> {
    let drivers = executable_drivers(elements, wires);
    let rank: HashMap<ElementId, (u64, usize)> = elements
        .iter()
        .enumerate()
        .filter(|(_, placed)| placed.element.kind.is_executable())
        .map(|(index, placed)| {
            let number = placed
                .execution_order_id
                .filter(|id| *id > 0)
                .unwrap_or(u64::MAX);
            (placed.element.id, (number, index))
        })
        .collect();
    let mut waiting: HashMap<ElementId, usize> = HashMap::new();
    let mut readers: HashMap<ElementId, Vec<ElementId>> = HashMap::new();
    for (id, from) in &drivers {
        waiting.insert(*id, from.len());
        for driver in from {
            readers.entry(*driver).or_default().push(*id);
        }
    }
    let mut ready: BinaryHeap<Reverse<((u64, usize), ElementId)>> = waiting
        .iter()
        .filter(|(_, count)| **count == 0)
        .map(|(id, _)| Reverse((rank[id], *id)))
        .collect();
    let mut order = Vec::new();
    let mut done: HashSet<ElementId> = HashSet::new();
    while done.len() < rank.len() {
        let next = match ready.pop() {
            Some(Reverse((_, id))) if done.contains(&id) => continue,
            Some(Reverse((_, id))) => id,
            // A loop: the lowest-ranked element left breaks it.
            None => match rank
                .iter()
                .filter(|(id, _)| !done.contains(id))
                .min_by_key(|(_, key)| **key)
            {
                Some((id, _)) => *id,
                None => break,
            },
        };
        done.insert(next);
        order.push(next);
        for reader in readers.get(&next).into_iter().flatten() {
            if let Some(count) = waiting.get_mut(reader) {
                *count = count.saturating_sub(1);
                if *count == 0 && !done.contains(reader) {
                    ready.push(Reverse((rank[reader], *reader)));
                }
            }
        }
    }
    order
}

/// Beremiz's order for a graph without execution order ids. Beremiz's generator reads an
/// in-out as its variable's name and runs the writes in place order, so a reader drawn above
/// an in-out runs before its write and reads the previous cycle's value: an in-out's input is
/// not driven by its output here.
fn by_data_flow(elements: &[OrderedElement], wires: &[Wire]) -> Vec<ElementId> {
    let links = Drivers::new(elements, wires, false);
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
                if links.kind(id).is_some_and(CfcElementKind::is_executable) {
                    order.push(id);
                }
                continue;
            }
            if !visited.insert(id) {
                continue;
            }
            stack.push((id, true));
            // Pushed in reverse, so the first driver is visited (and numbered) first.
            for driver in links.before(id).into_iter().rev() {
                if !visited.contains(&driver) {
                    stack.push((driver, false));
                }
            }
        }
    }
    order
}
