//! The damped update of the active set: the contact set changes only at the ends of its zones,
//! each end moving by at most a given number of nodes.
//!
//! With adhesion acting only in contact, the edge of a contact zone can hold a strip of nodes
//! where the sharp law has no exact solution (docs/physics/spatial-partial.md section 3): the
//! full update C <- {i in C: p_i > 0} u {i not in C: gap_i < 0} then flips many nodes at once,
//! back and forth, or in patterns that need not repeat, so neither convergence nor the cycle guard
//! ends the iteration. Moving the ends by a bounded reach walks the sets towards the solution;
//! the caller widens the reach while the residual falls and narrows it when it grows.

use std::collections::VecDeque;

use crate::physics::spatial::partial::grid::Grid;

/// The neighbours of node `i` along x and along y (periodic; none along an axis of one node).
fn neighbours(grid: Grid, i: usize) -> impl Iterator<Item = usize> {
    let (nx, ny) = (grid.nx, grid.ny);
    let (x, y) = (i % nx, i / nx);
    let along_x = (nx > 1).then(|| [y * nx + (x + 1) % nx, y * nx + (x + nx - 1) % nx]);
    let along_y = (ny > 1).then(|| [((y + 1) % ny) * nx + x, ((y + ny - 1) % ny) * nx + x]);
    along_x.into_iter().chain(along_y).flatten()
}

/// The update `next` of the contact set `set` limited to the ends of the zones. At each end (a
/// pair of neighbouring nodes, one in contact and one not) only one of the two may change: the
/// one that `next` changes with the larger `violation` (>= 0: -p/pbar in contact, -gap/(pbar max
/// A) outside). From it the change spreads to the neighbours that `next` changes the same way,
/// up to `reach` (>= 1) nodes from the end. When `next` changes no node at an end, the full update
/// is returned, so that a change is never mistaken for convergence.
pub fn limit(
    grid: Grid,
    set: &[bool],
    next: &[bool],
    violation: &[f64],
    reach: usize,
) -> Vec<bool> {
    let changes = |i: usize| next[i] != set[i];
    let mut limited = set.to_vec();
    let mut queue = VecDeque::new();
    for a in 0..set.len() {
        for b in neighbours(grid, a) {
            if b < a || set[a] == set[b] || !(changes(a) || changes(b)) {
                continue;
            }
            let chosen = if changes(a) && (!changes(b) || violation[a] >= violation[b]) {
                a
            } else {
                b
            };
            if limited[chosen] == set[chosen] {
                limited[chosen] = next[chosen];
                queue.push_back((chosen, 1));
            }
        }
    }
    while let Some((i, depth)) = queue.pop_front() {
        if depth >= reach {
            continue;
        }
        for j in neighbours(grid, i) {
            if set[j] == set[i] && changes(j) && limited[j] == set[j] {
                limited[j] = next[j];
                queue.push_back((j, depth + 1));
            }
        }
    }
    if limited == set {
        next.to_vec()
    } else {
        limited
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(n: usize) -> Grid {
        Grid {
            nx: n,
            ny: 1,
            lx: 1.0,
            ly: 1.0,
        }
    }

    fn bools(s: &str) -> Vec<bool> {
        s.chars().map(|c| c == '1').collect()
    }

    #[test]
    fn each_end_moves_by_one_node_at_most() {
        // a zone 0011111100 whose update removes two nodes at the left end, opens a hole inside
        // and adds two at the right end: only the end nodes may change, the hole does not open
        let set = bools("0011111100");
        let next = bools("0000110111");
        let violation = [0.0, 0.0, 0.5, 0.4, 0.0, 0.0, 0.3, 0.0, 0.2, 0.1];
        let limited = limit(line(10), &set, &next, &violation, 1);
        assert_eq!(limited, bools("0001111110"));
    }

    #[test]
    fn a_wider_reach_moves_an_end_further_but_opens_no_hole() {
        // the same update with reach 2: two nodes leave at the left end and two join at the right
        let set = bools("0011111100");
        let next = bools("0000110111");
        let violation = [0.0, 0.0, 0.5, 0.4, 0.0, 0.0, 0.3, 0.0, 0.2, 0.1];
        let limited = limit(line(10), &set, &next, &violation, 2);
        assert_eq!(limited, bools("0000111111"));
    }

    #[test]
    fn the_larger_violation_wins_at_an_end() {
        // at the end between nodes 3 (in) and 4 (out) both want to change: node 4 violates more
        let set = bools("01110000");
        let next = bools("01101000");
        let violation = [0.0, 0.0, 0.0, 0.1, 0.3, 0.0, 0.0, 0.0];
        assert_eq!(
            limit(line(8), &set, &next, &violation, 1),
            bools("01111000")
        );
    }

    #[test]
    fn an_update_away_from_the_ends_is_kept_whole() {
        // a new zone far from the others: no end changes, the full update is returned
        let set = bools("11000000");
        let next = bools("11000110");
        let violation = [0.0; 8];
        assert_eq!(limit(line(8), &set, &next, &violation, 3), next);
    }
}
