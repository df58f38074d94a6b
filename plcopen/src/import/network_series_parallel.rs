//! The reduction of a rung's graph of contacts and boxes into Rivet's series and parallel
//! chains (`docs/plcopen-xml.md` §3.4).

use project_model::{Branch, FlowNode, Parallel};

use super::network_error::NetworkError;

/// The most paths a rung that is not series-parallel may have when it is expanded.
pub(super) const MAX_PATHS: usize = 64;

/// One edge of a rung's graph: what lies between two points, as a chain.
#[derive(Clone, Debug)]
pub(super) struct ChainEdge {
    /// The point the power enters.
    pub from: usize,
    /// The point it leaves.
    pub to: usize,
    /// The chain between them.
    pub nodes: Vec<FlowNode>,
    /// The order of the edge among parallel ones: the top of its elements, then document order.
    pub key: (f64, usize),
    /// Whether the chain holds something other than operands (a box), which the expansion of a
    /// bridge must not duplicate.
    pub has_block: bool,
    /// When the chain is one parallel group merged from edges: each branch's key, in order;
    /// empty otherwise.
    pub branch_keys: Vec<(f64, usize)>,
}

/// The chain from `source` to `target` through `edges`, which hold only the edges between
/// points that lie on a path from `source` to `target`.
///
/// Series and parallel edges are merged until one edge is left; a graph that does not reduce
/// (a bridge) is expanded into one branch per path, which is exact when only operands are
/// repeated.
pub(super) fn reduce(
    source: usize,
    target: usize,
    mut edges: Vec<ChainEdge>,
) -> Result<Vec<FlowNode>, NetworkError> {
    if source == target {
        return Ok(Vec::new());
    }
    loop {
        let before = edges.len();
        edges = merge_parallel(edges);
        edges = merge_series(source, target, edges);
        if edges.len() == before {
            break;
        }
    }
    match edges.as_slice() {
        [] => Ok(Vec::new()),
        [only] if only.from == source && only.to == target => Ok(only.nodes.clone()),
        _ => expand(source, target, &edges),
    }
}

fn merge_parallel(edges: Vec<ChainEdge>) -> Vec<ChainEdge> {
    let mut merged: Vec<Vec<ChainEdge>> = Vec::new();
    for edge in edges {
        match merged
            .iter_mut()
            .find(|group| group[0].from == edge.from && group[0].to == edge.to)
        {
            Some(group) => group.push(edge),
            None => merged.push(vec![edge]),
        }
    }
    merged
        .into_iter()
        .map(|mut group| {
            if group.len() == 1 {
                return group.remove(0);
            }
            group.sort_by(|a, b| compare_keys(a.key, b.key));
            let key = group[0].key;
            let (from, to) = (group[0].from, group[0].to);
            let has_block = group.iter().any(|edge| edge.has_block);
            // A group merged before gives its branches with their own keys, so a branch that
            // reduces later still takes its place among them.
            let mut keyed: Vec<((f64, usize), Branch)> = Vec::new();
            for edge in group {
                let edge_key = edge.key;
                let branch_keys = edge.branch_keys;
                match <[FlowNode; 1]>::try_from(edge.nodes) {
                    Ok([FlowNode::Parallel(parallel)]) => {
                        let count = parallel.branches.len();
                        let keys = if branch_keys.len() == count {
                            branch_keys
                        } else {
                            vec![edge_key; count]
                        };
                        keyed.extend(keys.into_iter().zip(parallel.branches));
                    }
                    Ok([node]) => keyed.push((edge_key, Branch { rung: vec![node] })),
                    Err(nodes) => keyed.push((edge_key, Branch { rung: nodes })),
                }
            }
            keyed.sort_by(|a, b| compare_keys(a.0, b.0));
            let (branch_keys, branches): (Vec<_>, Vec<_>) = keyed.into_iter().unzip();
            ChainEdge {
                from,
                to,
                nodes: vec![FlowNode::Parallel(Parallel {
                    id: Default::default(),
                    branches,
                })],
                key,
                has_block,
                branch_keys,
            }
        })
        .collect()
}

fn merge_series(source: usize, target: usize, mut edges: Vec<ChainEdge>) -> Vec<ChainEdge> {
    let mut points: Vec<usize> = edges.iter().flat_map(|edge| [edge.from, edge.to]).collect();
    points.sort_unstable();
    points.dedup();
    for point in points {
        if point == source || point == target {
            continue;
        }
        let incoming: Vec<usize> = (0..edges.len()).filter(|&i| edges[i].to == point).collect();
        let outgoing: Vec<usize> = (0..edges.len())
            .filter(|&i| edges[i].from == point)
            .collect();
        if let ([first], [second]) = (incoming.as_slice(), outgoing.as_slice()) {
            let (first, second) = (*first, *second);
            let later = edges[second].clone();
            let earlier = &mut edges[first];
            earlier.to = later.to;
            // The keys of a parallel group's branches hold while a wire is all that joins it.
            earlier.branch_keys = match (earlier.nodes.is_empty(), later.nodes.is_empty()) {
                (_, true) => std::mem::take(&mut earlier.branch_keys),
                (true, false) => later.branch_keys,
                (false, false) => Vec::new(),
            };
            earlier.nodes.extend(later.nodes);
            earlier.has_block |= later.has_block;
            if compare_keys(later.key, earlier.key).is_lt() {
                earlier.key = later.key;
            }
            edges.remove(second);
        }
    }
    edges
}

/// One branch per path from `source` to `target`, when only operands lie on several paths.
fn expand(
    source: usize,
    target: usize,
    edges: &[ChainEdge],
) -> Result<Vec<FlowNode>, NetworkError> {
    let mut paths: Vec<Vec<usize>> = Vec::new();
    let mut stack: Vec<(usize, Vec<usize>)> = vec![(source, Vec::new())];
    while let Some((point, path)) = stack.pop() {
        if point == target {
            if paths.len() == MAX_PATHS {
                return Err(NetworkError::TooManyPaths { limit: MAX_PATHS });
            }
            paths.push(path);
            continue;
        }
        // Pushed in reverse so that the paths come out in the order of their edges.
        let mut next: Vec<usize> = (0..edges.len())
            .filter(|&i| edges[i].from == point)
            .collect();
        next.sort_by(|&a, &b| compare_keys(edges[a].key, edges[b].key));
        for edge in next.into_iter().rev() {
            let mut longer = path.clone();
            longer.push(edge);
            stack.push((edges[edge].to, longer));
        }
    }
    let mut uses = vec![0usize; edges.len()];
    for edge in paths.iter().flatten() {
        uses[*edge] += 1;
    }
    if (0..edges.len()).any(|edge| uses[edge] > 1 && edges[edge].has_block) {
        return Err(NetworkError::NotSeriesParallel { element: "block" });
    }
    let branches: Vec<Branch> = paths
        .iter()
        .map(|path| Branch {
            rung: path
                .iter()
                .flat_map(|&edge| edges[edge].nodes.iter().cloned())
                .collect(),
        })
        .collect();
    Ok(match <[Branch; 1]>::try_from(branches) {
        Ok([only]) => only.rung,
        Err(branches) => vec![FlowNode::Parallel(Parallel {
            id: Default::default(),
            branches,
        })],
    })
}

/// Orders keys by the top of the element, then by document order.
pub(super) fn compare_keys(a: (f64, usize), b: (f64, usize)) -> std::cmp::Ordering {
    a.0.total_cmp(&b.0).then(a.1.cmp(&b.1))
}
