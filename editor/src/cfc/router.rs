//! The wire router: an orthogonal route from an output pin to an input pin that goes around
//! the boxes, through the control points the user pinned.
//!
//! A pure function on grid units, so it is tested without a screen. Each leg between two
//! waypoints is an A* search over the grid points of a window around the leg; a point on or
//! inside an element's rectangle is blocked, so no segment crosses an element; a turn costs
//! more than a step, so routes have few corners. A wire leaves its output pin to the right and
//! enters its input pin from the left, as the pins' leads point.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};

use project_model::GridPoint;

/// The cost of a turn, in steps: a route takes this many extra steps to save one corner.
const TURN_COST: u32 = 3;
/// How far a leg's search window reaches beyond the leg's two ends, in grid units, first
/// and at the second try.
const WINDOW_MARGINS: [i32; 2] = [6, 24];

/// An element's rectangle on the grid: the closed range of columns and rows it covers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GridRect {
    /// The leftmost column.
    pub left: i32,
    /// The topmost row.
    pub top: i32,
    /// The rightmost column.
    pub right: i32,
    /// The bottom row.
    pub bottom: i32,
}

impl GridRect {
    /// Whether the rectangle overlaps the window `(min, max)`.
    fn meets(&self, min: GridPoint, max: GridPoint) -> bool {
        self.left <= max.x && self.right >= min.x && self.top <= max.y && self.bottom >= min.y
    }

    /// Whether the axis-parallel segment `a`–`b` runs through the inside of the rectangle
    /// (along its border does not count).
    #[cfg(test)]
    pub fn crossed_by(&self, a: GridPoint, b: GridPoint) -> bool {
        let (x0, x1) = (a.x.min(b.x), a.x.max(b.x));
        let (y0, y1) = (a.y.min(b.y), a.y.max(b.y));
        if y0 == y1 {
            self.top < y0 && y0 < self.bottom && x0 < self.right && x1 > self.left
        } else {
            self.left < x0 && x0 < self.right && y0 < self.bottom && y1 > self.top
        }
    }
}

/// The four directions a route runs in.
const DIRECTIONS: [(i32, i32); 4] = [(1, 0), (0, 1), (-1, 0), (0, -1)];

/// Routes a wire from the output pin at `from` to the input pin at `to` through `points`
/// (the control points, in order), around `obstacles`. Returns the corners of the route,
/// `from` first and `to` last.
pub fn route(
    from: GridPoint,
    to: GridPoint,
    points: &[GridPoint],
    obstacles: &[GridRect],
) -> Vec<GridPoint> {
    let lead_out = GridPoint {
        x: from.x + 1,
        y: from.y,
    };
    let lead_in = GridPoint {
        x: to.x - 1,
        y: to.y,
    };
    let mut waypoints = vec![lead_out];
    waypoints.extend_from_slice(points);
    waypoints.push(lead_in);
    let mut path = vec![from];
    // The direction the route arrives in at each waypoint, so a turn there costs as well.
    let mut heading = 0;
    for leg in waypoints.windows(2) {
        let (steps, arrived) = leg_route(leg[0], leg[1], heading, obstacles);
        heading = arrived;
        path.push(leg[0]);
        path.extend(steps);
    }
    path.push(lead_in);
    path.push(to);
    corners(path)
}

/// The grid points after `start` up to and including `goal`, found by A* in a window around
/// the two, and the direction the route arrives in. Falls back to one corner when the window
/// has no free way (the ends are walled in).
fn leg_route(
    start: GridPoint,
    goal: GridPoint,
    heading: usize,
    obstacles: &[GridRect],
) -> (Vec<GridPoint>, usize) {
    if start == goal {
        return (Vec::new(), heading);
    }
    for margin in WINDOW_MARGINS {
        if let Some(found) = search(start, goal, heading, obstacles, margin) {
            return found;
        }
    }
    let corner = GridPoint {
        x: goal.x,
        y: start.y,
    };
    (vec![corner, goal], if goal.y >= start.y { 1 } else { 3 })
}

/// One A* search in the window around `start` and `goal` widened by `margin`.
fn search(
    start: GridPoint,
    goal: GridPoint,
    heading: usize,
    obstacles: &[GridRect],
    margin: i32,
) -> Option<(Vec<GridPoint>, usize)> {
    let min = GridPoint {
        x: start.x.min(goal.x) - margin,
        y: start.y.min(goal.y) - margin,
    };
    let max = GridPoint {
        x: start.x.max(goal.x) + margin,
        y: start.y.max(goal.y) + margin,
    };
    let width = (max.x - min.x + 1) as usize;
    let height = (max.y - min.y + 1) as usize;
    let index = |p: GridPoint| (p.y - min.y) as usize * width + (p.x - min.x) as usize;
    let mut blocked = vec![false; width * height];
    for rect in obstacles.iter().filter(|rect| rect.meets(min, max)) {
        for y in rect.top.max(min.y)..=rect.bottom.min(max.y) {
            for x in rect.left.max(min.x)..=rect.right.min(max.x) {
                blocked[index(GridPoint { x, y })] = true;
            }
        }
    }
    blocked[index(start)] = false;
    blocked[index(goal)] = false;
    let estimate = |p: GridPoint| (p.x - goal.x).unsigned_abs() + (p.y - goal.y).unsigned_abs();
    // Costs and predecessors by (grid point, direction of arrival).
    let state = |p: GridPoint, direction: usize| index(p) * 4 + direction;
    let mut cost: HashMap<usize, u32> = HashMap::new();
    let mut previous: HashMap<usize, usize> = HashMap::new();
    let mut open = BinaryHeap::new();
    cost.insert(state(start, heading), 0);
    open.push(Reverse((estimate(start), 0_u32, start.x, start.y, heading)));
    while let Some(Reverse((_, spent, x, y, direction))) = open.pop() {
        let here = GridPoint { x, y };
        let key = state(here, direction);
        if cost.get(&key).is_some_and(|best| *best < spent) {
            continue;
        }
        if here == goal {
            let mut steps = vec![here];
            let mut at = key;
            while let Some(before) = previous.get(&at) {
                at = *before;
                let cell = at / 4;
                steps.push(GridPoint {
                    x: min.x + (cell % width) as i32,
                    y: min.y + (cell / width) as i32,
                });
            }
            steps.pop();
            steps.reverse();
            return Some((steps, direction));
        }
        for (turn, (dx, dy)) in DIRECTIONS.iter().enumerate() {
            // Going straight back is never shorter.
            if turn == (direction + 2) % 4 {
                continue;
            }
            let next = GridPoint {
                x: x + dx,
                y: y + dy,
            };
            if next.x < min.x || next.x > max.x || next.y < min.y || next.y > max.y {
                continue;
            }
            if blocked[index(next)] {
                continue;
            }
            let step = 1 + if turn == direction { 0 } else { TURN_COST };
            let next_key = state(next, turn);
            let next_cost = spent + step;
            if cost.get(&next_key).is_none_or(|best| next_cost < *best) {
                cost.insert(next_key, next_cost);
                previous.insert(next_key, key);
                open.push(Reverse((
                    next_cost + estimate(next),
                    next_cost,
                    next.x,
                    next.y,
                    turn,
                )));
            }
        }
    }
    None
}

/// The route's corners: `path` without the points in the middle of a straight run and
/// without repeats.
fn corners(path: Vec<GridPoint>) -> Vec<GridPoint> {
    let mut result: Vec<GridPoint> = Vec::with_capacity(path.len());
    for point in path {
        if result.last() == Some(&point) {
            continue;
        }
        if let [.., a, b] = result.as_slice() {
            let straight = (a.x == b.x && b.x == point.x) || (a.y == b.y && b.y == point.y);
            if straight {
                result.pop();
            }
        }
        result.push(point);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: i32, y: i32) -> GridPoint {
        GridPoint { x, y }
    }

    fn rect(left: i32, top: i32, right: i32, bottom: i32) -> GridRect {
        GridRect {
            left,
            top,
            right,
            bottom,
        }
    }

    /// Every segment is horizontal or vertical and crosses no obstacle.
    fn assert_clear(route: &[GridPoint], obstacles: &[GridRect]) {
        for segment in route.windows(2) {
            assert!(
                segment[0].x == segment[1].x || segment[0].y == segment[1].y,
                "diagonal segment {segment:?}"
            );
            for obstacle in obstacles {
                assert!(
                    !obstacle.crossed_by(segment[0], segment[1]),
                    "segment {segment:?} crosses {obstacle:?} in {route:?}"
                );
            }
        }
    }

    #[test]
    fn a_free_straight_wire_is_one_segment() {
        assert_eq!(route(p(0, 3), p(10, 3), &[], &[]), vec![p(0, 3), p(10, 3)]);
    }

    #[test]
    fn a_wire_between_two_rows_has_two_corners() {
        let route = route(p(0, 0), p(10, 4), &[], &[]);
        assert_eq!(route.len(), 4, "{route:?}");
        assert_eq!((route[0], route[3]), (p(0, 0), p(10, 4)));
    }

    #[test]
    fn a_wire_goes_around_a_box_in_its_way() {
        let obstacles = [rect(-4, -1, 0, 1), rect(4, -3, 8, 3), rect(12, -1, 16, 1)];
        let route = route(p(0, 0), p(12, 0), &[], &obstacles);
        assert!(route.len() > 2, "{route:?}");
        assert_clear(&route, &obstacles);
    }

    #[test]
    fn a_feedback_wire_runs_back_around_its_own_box() {
        let own = rect(0, 0, 6, 6);
        let route = route(p(6, 3), p(0, 1), &[], &[own]);
        assert_clear(&route, &[own]);
        assert_eq!((route[0], *route.last().unwrap()), (p(6, 3), p(0, 1)));
    }

    #[test]
    fn control_points_are_passed_in_order() {
        let obstacles = [rect(4, 2, 8, 6)];
        let controls = [p(3, 10), p(9, 10)];
        let route = route(p(0, 0), p(14, 0), &controls, &obstacles);
        assert_clear(&route, &obstacles);
        let on_route = |point: GridPoint| {
            route.windows(2).position(|segment| {
                let (a, b) = (segment[0], segment[1]);
                (a.x == b.x && a.x == point.x && (a.y.min(b.y)..=a.y.max(b.y)).contains(&point.y))
                    || (a.y == b.y
                        && a.y == point.y
                        && (a.x.min(b.x)..=a.x.max(b.x)).contains(&point.x))
            })
        };
        let first = on_route(controls[0]).expect("the first control point is on the route");
        let second = on_route(controls[1]).expect("the second control point is on the route");
        assert!(first <= second, "{route:?}");
    }

    #[test]
    fn a_walled_in_pin_still_gets_a_route() {
        let wall = rect(2, -20, 3, 20);
        let route = route(p(0, 0), p(8, 0), &[], &[wall]);
        assert_eq!((route[0], *route.last().unwrap()), (p(0, 0), p(8, 0)));
    }
}
