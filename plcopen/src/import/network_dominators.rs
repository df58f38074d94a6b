//! The deepest point every path from a rung's start to its outputs passes (`docs/plcopen-xml.md`
//! §3.4), found through the dominator tree of the rung's acyclic graph in near-linear time.

use std::collections::HashMap;

/// The point nearest to `targets` that every path from `root` to each of them passes, the
/// targets themselves included; `root` when only it does, or when no target is reached.
///
/// `order` holds the points reachable from `root` in a topological order (`root` first); the
/// predecessors of a point are what `predecessors` gives, of which those outside `order` are
/// not on any path from `root` and are passed over.
pub(super) fn deepest_common_dominator<P>(
    root: usize,
    order: &[usize],
    targets: &[usize],
    predecessors: P,
) -> usize
where
    P: Fn(usize) -> Vec<usize>,
{
    // Immediate dominators in one pass: in an acyclic graph every predecessor of a point is
    // done before it, so the intersection of Cooper, Harvey and Kennedy needs no iteration.
    let mut rank: HashMap<usize, usize> = HashMap::with_capacity(order.len());
    let mut dominator: HashMap<usize, usize> = HashMap::with_capacity(order.len());
    for &point in order {
        rank.insert(point, rank.len());
        if point == root {
            dominator.insert(root, root);
            continue;
        }
        let mut nearest: Option<usize> = None;
        for from in predecessors(point) {
            if !dominator.contains_key(&from) {
                continue;
            }
            nearest = Some(match nearest {
                None => from,
                Some(other) => intersect(other, from, &rank, &dominator),
            });
        }
        dominator.insert(point, nearest.unwrap_or(root));
    }
    targets
        .iter()
        .filter(|target| dominator.contains_key(target))
        .fold(None, |common: Option<usize>, &target| {
            Some(match common {
                None => target,
                Some(common) => intersect(common, target, &rank, &dominator),
            })
        })
        .unwrap_or(root)
}

/// The nearest common dominator of `a` and `b`: the deeper one climbs until they meet.
fn intersect(
    mut a: usize,
    mut b: usize,
    rank: &HashMap<usize, usize>,
    dominator: &HashMap<usize, usize>,
) -> usize {
    let rank_of = |point: usize| rank.get(&point).copied().unwrap_or(0);
    while a != b {
        while rank_of(a) > rank_of(b) {
            a = dominator.get(&a).copied().unwrap_or(a);
        }
        while rank_of(b) > rank_of(a) {
            b = dominator.get(&b).copied().unwrap_or(b);
        }
    }
    a
}

#[cfg(test)]
mod tests {
    use std::collections::HashSet;

    use super::*;

    /// The deepest common dominator found by removing each point in turn, as the definition
    /// says.
    fn by_removal(root: usize, edges: &[(usize, usize)], targets: &[usize]) -> usize {
        let reached_without = |removed: Option<usize>| {
            let mut seen = HashSet::new();
            let mut stack = vec![root];
            while let Some(point) = stack.pop() {
                if Some(point) == removed || !seen.insert(point) {
                    continue;
                }
                stack.extend(edges.iter().filter(|e| e.0 == point).map(|e| e.1));
            }
            seen
        };
        let order = topological(root, edges);
        let mut best = root;
        for &candidate in &order {
            if candidate != root
                && targets
                    .iter()
                    .all(|target| !reached_without(Some(candidate)).contains(target))
            {
                best = candidate;
            }
        }
        best
    }

    fn topological(root: usize, edges: &[(usize, usize)]) -> Vec<usize> {
        let mut reachable = HashSet::new();
        let mut stack = vec![root];
        while let Some(point) = stack.pop() {
            if reachable.insert(point) {
                stack.extend(edges.iter().filter(|e| e.0 == point).map(|e| e.1));
            }
        }
        let mut incoming: HashMap<usize, usize> = reachable.iter().map(|&p| (p, 0)).collect();
        for edge in edges.iter().filter(|e| reachable.contains(&e.0)) {
            *incoming.entry(edge.1).or_default() += 1;
        }
        let mut ready = vec![root];
        let mut order = Vec::new();
        while let Some(point) = ready.pop() {
            order.push(point);
            for edge in edges.iter().filter(|e| e.0 == point) {
                let count = incoming.entry(edge.1).or_default();
                *count -= 1;
                if *count == 0 {
                    ready.push(edge.1);
                }
            }
        }
        order
    }

    fn found(root: usize, edges: &[(usize, usize)], targets: &[usize]) -> usize {
        let order = topological(root, edges);
        deepest_common_dominator(root, &order, targets, |point| {
            edges.iter().filter(|e| e.1 == point).map(|e| e.0).collect()
        })
    }

    #[test]
    fn the_deepest_common_dominator_is_the_one_removing_each_point_finds() {
        type Case<'a> = (&'a [(usize, usize)], &'a [usize]);
        let graphs: [Case<'_>; 6] = [
            // A chain: the target itself.
            (&[(0, 1), (1, 2)], &[2]),
            // Two coils after a contact: the contact's output.
            (&[(0, 1), (1, 2), (1, 3)], &[2, 3]),
            // A parallel group, then a contact: the group's end, then the contact.
            (&[(0, 1), (0, 2), (1, 3), (2, 3), (3, 4)], &[4]),
            (&[(0, 1), (0, 2), (1, 3), (2, 3), (3, 4)], &[3, 4]),
            // A bridge whose outputs meet nowhere: the start.
            (&[(0, 1), (0, 2), (1, 2), (1, 3), (2, 4)], &[3, 4]),
            // Branches of branches after a shared contact, and a point no target needs.
            (
                &[
                    (0, 1),
                    (1, 2),
                    (1, 3),
                    (2, 4),
                    (3, 4),
                    (4, 5),
                    (4, 6),
                    (0, 7),
                ],
                &[5, 6],
            ),
        ];
        for (edges, targets) in graphs {
            assert_eq!(
                found(0, edges, targets),
                by_removal(0, edges, targets),
                "{edges:?} to {targets:?}"
            );
        }
        assert_eq!(
            found(
                0,
                &[(0, 1), (1, 2), (1, 3), (2, 4), (3, 4), (4, 5), (4, 6)],
                &[5, 6]
            ),
            4
        );
    }

    #[test]
    fn a_long_ladder_of_parallel_groups_ends_at_its_last_point() {
        // 2,000 groups of two contacts side by side, numbered in a topological order: every
        // group's end dominates what follows.
        let mut predecessors: HashMap<usize, Vec<usize>> = HashMap::new();
        for group in 0..2000 {
            let start = group * 3;
            predecessors.insert(start + 1, vec![start]);
            predecessors.insert(start + 2, vec![start]);
            predecessors.insert(start + 3, vec![start + 1, start + 2]);
        }
        let last = 2000 * 3;
        let order: Vec<usize> = (0..=last).collect();
        let find = |targets: &[usize]| {
            deepest_common_dominator(0, &order, targets, |point| {
                predecessors.get(&point).cloned().unwrap_or_default()
            })
        };
        assert_eq!(find(&[last]), last);
        assert_eq!(find(&[last - 1, last - 2]), last - 3);
    }
}
