//! Membership grades of a curve whose weights are fuzzy too (docs/method.md
//! §16): for each membership function `m`,
//!
//! ```text
//! mu_m(q) = sup over t of  sup { alpha : q ∈ S_m,alpha(t) }
//! ```
//! where `S_m,alpha(t)` is the set of the curve at `t` over every choice of
//! weights and points inside their `m`-cuts at `alpha`: convex, and decided
//! exactly by `IntervalTerms::contains` (docs/method.md §15). The cuts are
//! nested, so membership at `t` is monotone in `alpha` and the level is found
//! by bisection.
//!
//! The sup over `t` is certified by a branch and bound over the knot spans.
//! On a piece `[t₀, t₁]` of a span every basis function lies between the
//! least and the largest of its Bézier coefficients there, `n̲ᵢ ≤ Nᵢ(t) ≤ n̄ᵢ`,
//! so every curve point at any `t` of the piece is a weighted average with
//! weights `θᵢ ∈ [w̲ᵢn̲ᵢ, w̄ᵢn̄ᵢ]`: a set of the same kind that holds every
//! `S_m,alpha(t)` of the piece, whose level bounds the piece's grades from
//! above. The grade at the piece's middle bounds them from below. Pieces
//! are halved until the largest upper bound is within
//! [`GRADE_TOLERANCE`] of the best grade found, and that upper bound is
//! returned: never below the true grade, at most that far above it.

use std::collections::BinaryHeap;

use crate::fuzzy::Membership;
use crate::heap_key::heap_ordered_by;
use crate::set::certify::GRADE_TOLERANCE;
use crate::set::grades::Grades;
use crate::set::weighted_terms::{BasisBounds, PieceSet, Weighted};

/// Pieces examined per membership function before the largest upper bound
/// left is returned (still an upper bound, then possibly more than
/// [`GRADE_TOLERANCE`] above the grade).
const MAX_PIECES: usize = 4000;

/// Bisections of a level: `2⁻³⁰ ≈ 1e-9`, well inside [`GRADE_TOLERANCE`].
const LEVEL_BISECTIONS: usize = 30;

/// The grades of `q` in a curve with fuzzy weights, all three functions.
pub(crate) fn weighted_grades<const D: usize>(on: &Weighted<'_, D>, q: &[f64; D]) -> Grades {
    let grader = WeightedGrader { on, q: *q };
    Grades::ordered(
        [Membership::Upper, Membership::Primary, Membership::Lower].map(|m| grader.grade(m)),
    )
}

/// One point's search.
struct WeightedGrader<'a, 'c, const D: usize> {
    on: &'a Weighted<'c, D>,
    q: [f64; D],
}

/// A piece `[s₀, s₁]` (in the span's own coordinate `s ∈ [0, 1]`) of a knot
/// span, with an upper bound of its grades.
struct Piece {
    upper: f64,
    span: usize,
    s: [f64; 2],
}

heap_ordered_by!(Piece, upper);

impl<const D: usize> WeightedGrader<'_, '_, D> {
    /// The certified grade of `q` under `m` (module docs).
    fn grade(&self, m: Membership) -> f64 {
        let knots = self.on.curve.knots();
        let mut heap = BinaryHeap::new();
        let mut best = 0.0_f64;
        for (span, _) in knots.spans() {
            for s in [0.0, 1.0] {
                best = best.max(self.member_level(m, span, &self.on.at(span, s), best));
            }
        }
        for (span, _) in knots.spans() {
            let upper = self.bound(m, span, &self.on.on(span, [0.0, 1.0]), 0.0, 1.0);
            heap.push(Piece {
                upper,
                span,
                s: [0.0, 1.0],
            });
        }
        let mut pruned = 0.0_f64;
        for _ in 0..MAX_PIECES {
            let Some(piece) = heap.pop() else {
                return best.max(pruned);
            };
            if piece.upper <= best + GRADE_TOLERANCE {
                return piece.upper.max(best).max(pruned);
            }
            let [s0, s1] = piece.s;
            let mid = s0 + (s1 - s0) / 2.0;
            best = best.max(self.member_level(m, piece.span, &self.on.at(piece.span, mid), best));
            for half in [[s0, mid], [mid, s1]] {
                if half[0] >= half[1] {
                    continue;
                }
                let bounds = self.on.on(piece.span, half);
                let floor = best + GRADE_TOLERANCE;
                let upper = self.bound(m, piece.span, &bounds, floor, piece.upper);
                if upper <= floor {
                    pruned = pruned.max(upper);
                } else {
                    heap.push(Piece {
                        upper,
                        span: piece.span,
                        s: half,
                    });
                }
            }
        }
        heap.peek().map_or(best, |p| p.upper).max(best).max(pruned)
    }

    /// Whether `q` lies in the set at level `a` of the terms of `span` with
    /// basis values within `bounds`.
    fn inside(&self, m: Membership, span: usize, bounds: &BasisBounds, a: f64) -> bool {
        match self.on.set(m, span, bounds, a) {
            PieceSet::Empty => false,
            PieceSet::Unbounded => true,
            PieceSet::Terms(terms) => terms.contains(self.q).unwrap_or(false),
        }
    }

    /// An upper bound of the grades on the piece of `bounds` (a superset's
    /// level, rounded up), at most `ceiling` (a bound already known) and
    /// no more than `floor` when the piece cannot reach `floor`: one test
    /// prunes a piece that cannot beat the best grade found.
    fn bound(
        &self,
        m: Membership,
        span: usize,
        bounds: &BasisBounds,
        floor: f64,
        ceiling: f64,
    ) -> f64 {
        let top = self.on.least_top(m, span, bounds).min(ceiling);
        if floor >= top {
            return top;
        }
        if !self.inside(m, span, bounds, floor) {
            return floor;
        }
        if self.inside(m, span, bounds, top) {
            return top;
        }
        self.bisect(m, span, bounds, [floor, top])[1]
    }

    /// `[lo, hi]` narrowed from `range` (`q` inside at `lo`, not at `hi`) by
    /// [`LEVEL_BISECTIONS`] halvings, keeping that.
    fn bisect(
        &self,
        m: Membership,
        span: usize,
        bounds: &BasisBounds,
        range: [f64; 2],
    ) -> [f64; 2] {
        let [mut lo, mut hi] = range;
        for _ in 0..LEVEL_BISECTIONS {
            let mid = lo + (hi - lo) / 2.0;
            if self.inside(m, span, bounds, mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        [lo, hi]
    }

    /// A level at which `q` is a member at the one parameter of `bounds`
    /// (rounded down), searched above `floor` (a grade already found); 0
    /// where `q` is not a member at `floor`.
    fn member_level(&self, m: Membership, span: usize, bounds: &BasisBounds, floor: f64) -> f64 {
        let top = self.on.least_top(m, span, bounds);
        if floor > top || !self.inside(m, span, bounds, floor) {
            return 0.0;
        }
        if self.inside(m, span, bounds, top) {
            return top;
        }
        self.bisect(m, span, bounds, [floor, top])[0]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fuzzy::{Nt2Number, Nt2Point};
    use crate::pipeline::FuzzyCurve;
    use crate::set::membership::Grader;

    fn number(c: f64, spread: f64) -> Nt2Number {
        Nt2Number::try_new(
            c,
            [c - spread, c + 1.5 * spread],
            [c - 0.6 * spread, c + 0.8 * spread],
            [c - 0.2 * spread, c + 0.3 * spread],
            0.7,
        )
        .unwrap()
    }

    /// With every weight a crisp number the weighted search grades as the
    /// crisp-weight certificate does (two searches, each within the
    /// tolerance of the truth).
    #[test]
    fn crisp_numbers_as_weights_grade_as_crisp_weights() {
        let weights = [1.0, 2.5, 0.6, 1.2, 1.0];
        let points: Vec<Nt2Point<2>> = [[0.0, 0.0], [1.0, 2.0], [2.5, 2.5], [4.0, 1.0], [5.0, 0.0]]
            .iter()
            .map(|&[x, y]| Nt2Point::new([number(x, 0.4), number(y, 0.3)]))
            .collect();
        let curve = FuzzyCurve::try_new(3, points, weights.to_vec(), None).unwrap();
        let numbers: Vec<Nt2Number> = weights
            .iter()
            .map(|&w| Nt2Number::try_new(w, [w; 2], [w; 2], [w; 2], 1.0).unwrap())
            .collect();
        let grader = Grader::new(&curve);
        for (i, q) in (0..60)
            .map(|i| {
                let a = f64::from(i);
                [(a * 0.37) % 5.6 - 0.3, (a * 0.61) % 3.4 - 0.4]
            })
            .enumerate()
        {
            let on = Weighted::new(&curve, &numbers);
            let (a, b) = (weighted_grades(&on, &q), grader.grades(&q));
            for m in [Membership::Upper, Membership::Primary, Membership::Lower] {
                assert!(
                    (a.get(m) - b.get(m)).abs() <= 2.0 * GRADE_TOLERANCE + 1e-9,
                    "point {i} {q:?} {m:?}: {} vs {}",
                    a.get(m),
                    b.get(m)
                );
            }
        }
    }
}
