//! The largest value of a function over the vertices of a box: every vertex
//! in Gray-code order where they are few (callers do this with incremental
//! updates), otherwise branch and bound (this file).
//!
//! A node fixes some of the binary choices (each free variable at its left
//! or its right end) and leaves the others open; `bound` is an upper bound
//! of the function over every completion of the node, `value` the function
//! at one vertex. Nodes are expanded best bound first on the open variable
//! that comes first in a given order (the most influential), and a child
//! whose bound is not above the best vertex found is dropped, so the answer
//! is the bracket `[best vertex, largest bound left]`: certified at both
//! ends, exact when the queue empties within the budget. Vertices are
//! improved by local search (flip one choice while that raises the value),
//! from the given starts and from the completion of each node expanded.

use std::collections::BinaryHeap;

use crate::heap_key::heap_ordered_by;

/// A function of binary choices and an upper bound of it over completions.
pub(crate) trait VertexProblem {
    /// The number of binary choices.
    fn vars(&self) -> usize;
    /// The function at a vertex.
    fn value(&mut self, choice: &[bool]) -> f64;
    /// An upper bound of the function over every vertex that agrees with
    /// `fixed` where it is `Some`.
    fn bound(&mut self, fixed: &[Option<bool>]) -> f64;
}

/// What branch and bound found.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Outcome {
    /// The best vertex's value (attained).
    pub(crate) best: f64,
    /// The best vertex.
    pub(crate) choice: Vec<bool>,
    /// An upper bound of the largest value (at least `best`).
    pub(crate) bound: f64,
}

struct Node {
    bound: f64,
    fixed: Vec<Option<bool>>,
}

heap_ordered_by!(Node, bound);

/// Passes of local search at most.
const PASSES: usize = 8;

/// Raises `choice` by flipping one choice at a time while that raises the
/// value; returns the value reached.
pub(crate) fn local_search(
    problem: &mut impl VertexProblem,
    choice: &mut [bool],
    mut value: f64,
) -> f64 {
    for _ in 0..PASSES {
        let mut better = false;
        for j in 0..choice.len() {
            choice[j] = !choice[j];
            let v = problem.value(choice);
            if v > value {
                value = v;
                better = true;
            } else {
                choice[j] = !choice[j];
            }
        }
        if !better {
            break;
        }
    }
    value
}

/// The bracket of the largest value: branch and bound on the choices in
/// `order` (every variable once), from the vertices `starts`, expanding at
/// most `budget` nodes; `slack` is the relative amount by which a bound may
/// exceed the best value and still be dropped (the rounding of the values).
pub(crate) fn maximize(
    problem: &mut impl VertexProblem,
    order: &[usize],
    starts: &[Vec<bool>],
    budget: usize,
    slack: f64,
) -> Outcome {
    let n = problem.vars();
    let mut choice = vec![false; n];
    let mut best = f64::NEG_INFINITY;
    for start in starts {
        let mut c = start.clone();
        let v = problem.value(&c);
        let v = local_search(problem, &mut c, v);
        if v > best {
            best = v;
            choice = c;
        }
    }
    if best == f64::NEG_INFINITY {
        best = problem.value(&choice);
    }
    let tolerance = |best: f64| slack * best.abs().max(f64::MIN_POSITIVE);
    let root = vec![None; n];
    let mut heap = BinaryHeap::new();
    heap.push(Node {
        bound: problem.bound(&root),
        fixed: root,
    });
    let mut expanded = 0usize;
    while let Some(node) = heap.peek() {
        if node.bound <= best + tolerance(best) || expanded >= budget {
            break;
        }
        let Some(node) = heap.pop() else { break };
        expanded += 1;
        // The node's completion by the best vertex, improved now and then.
        let mut c: Vec<bool> = node
            .fixed
            .iter()
            .zip(&choice)
            .map(|(f, b)| f.unwrap_or(*b))
            .collect();
        let mut v = problem.value(&c);
        if expanded % 16 == 1 {
            v = local_search(problem, &mut c, v);
        }
        if v > best {
            best = v;
            choice = c;
        }
        let Some(&var) = order.iter().find(|&&j| node.fixed[j].is_none()) else {
            continue;
        };
        for end in [false, true] {
            let mut fixed = node.fixed.clone();
            fixed[var] = Some(end);
            if fixed.iter().all(Option::is_some) {
                let c: Vec<bool> = fixed.iter().map(|f| f.unwrap_or(false)).collect();
                let v = problem.value(&c);
                if v > best {
                    best = v;
                    choice = c;
                }
                continue;
            }
            let bound = problem.bound(&fixed);
            if bound > best + tolerance(best) {
                heap.push(Node { bound, fixed });
            }
        }
    }
    let open = heap.peek().map_or(f64::NEG_INFINITY, |n| n.bound);
    Outcome {
        best,
        choice,
        bound: open.max(best),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Σ aⱼ·sⱼ` squared, `sⱼ = ±1`: a convex function of the vertex.
    struct Square(Vec<f64>);

    impl VertexProblem for Square {
        fn vars(&self) -> usize {
            self.0.len()
        }
        fn value(&mut self, choice: &[bool]) -> f64 {
            let s: f64 = self
                .0
                .iter()
                .zip(choice)
                .map(|(a, &c)| if c { *a } else { -a })
                .sum();
            s * s
        }
        fn bound(&mut self, fixed: &[Option<bool>]) -> f64 {
            let (mut lo, mut hi) = (0.0, 0.0);
            for (a, f) in self.0.iter().zip(fixed) {
                match f {
                    Some(true) => (lo, hi) = (lo + a, hi + a),
                    Some(false) => (lo, hi) = (lo - a, hi - a),
                    None => (lo, hi) = (lo - a.abs(), hi + a.abs()),
                }
            }
            f64::max(lo * lo, hi * hi)
        }
    }

    #[test]
    fn branch_and_bound_finds_the_largest_vertex() {
        let a = vec![3.0, -1.0, 2.5, 0.5, -4.0, 1.5];
        let mut p = Square(a.clone());
        let order: Vec<usize> = (0..a.len()).collect();
        let out = maximize(&mut p, &order, &[vec![false; a.len()]], 1000, 0.0);
        let total: f64 = a.iter().map(|x| x.abs()).sum();
        assert_eq!(out.best, total * total);
        assert_eq!(out.bound, out.best);
    }
}
