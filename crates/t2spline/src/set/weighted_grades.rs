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

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::fuzzy::{Alpha, Membership, Nt2Number, Nt2Point};
use crate::interval_weights::IntervalTerms;
use crate::nurbs::basis::basis_functions;
use crate::pipeline::FuzzyCurve;
use crate::set::bernstein::{bezier_matrix, restrict};
use crate::set::certify::GRADE_TOLERANCE;
use crate::set::curve_envelope::cut;
use crate::set::membership::Grades;

/// Pieces examined per membership function before the largest upper bound
/// left is returned (still an upper bound, then possibly more than
/// [`GRADE_TOLERANCE`] above the grade).
const MAX_PIECES: usize = 4000;

/// Bisections of a level: `2⁻³⁰ ≈ 1e-9`, well inside [`GRADE_TOLERANCE`].
const LEVEL_BISECTIONS: usize = 30;

/// The relative widening of the bounds of a basis function on a piece,
/// against the rounding of its Bézier coefficients.
const BASIS_WIDENING: f64 = 1e-12;

/// The grades of `q` in a curve with fuzzy weights, all three functions.
pub(crate) fn weighted_grades<const D: usize>(
    curve: &FuzzyCurve<D>,
    weights: &[Nt2Number],
    q: &[f64; D],
) -> Grades {
    let grader = WeightedGrader {
        curve,
        weights,
        q: *q,
    };
    Grades::ordered(
        [Membership::Upper, Membership::Primary, Membership::Lower].map(|m| grader.grade(m)),
    )
}

/// One point's search.
struct WeightedGrader<'a, const D: usize> {
    curve: &'a FuzzyCurve<D>,
    weights: &'a [Nt2Number],
    q: [f64; D],
}

/// A piece `[s₀, s₁]` (in the span's own coordinate `s ∈ [0, 1]`) of a knot
/// span, with an upper bound of its grades.
struct Piece {
    upper: f64,
    span: usize,
    s: [f64; 2],
}

impl PartialEq for Piece {
    fn eq(&self, other: &Self) -> bool {
        self.upper.total_cmp(&other.upper) == Ordering::Equal
    }
}
impl Eq for Piece {}
impl PartialOrd for Piece {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Piece {
    fn cmp(&self, other: &Self) -> Ordering {
        self.upper.total_cmp(&other.upper)
    }
}

/// Per term of a span: the least and the largest value of its basis
/// function on a piece.
type BasisBounds = Vec<[f64; 2]>;

impl<const D: usize> WeightedGrader<'_, D> {
    /// The certified grade of `q` under `m` (module docs).
    fn grade(&self, m: Membership) -> f64 {
        let knots = self.curve.knots();
        let mut heap = BinaryHeap::new();
        for (span, _) in knots.spans() {
            let upper = self.piece_bound(m, span, [0.0, 1.0]);
            heap.push(Piece {
                upper,
                span,
                s: [0.0, 1.0],
            });
        }
        let (mut best, mut pruned) = (0.0_f64, 0.0_f64);
        for _ in 0..MAX_PIECES {
            let Some(piece) = heap.pop() else {
                return best.max(pruned);
            };
            if piece.upper <= best + GRADE_TOLERANCE {
                return piece.upper.max(best).max(pruned);
            }
            let [s0, s1] = piece.s;
            let mid = s0 + (s1 - s0) / 2.0;
            for s in [s0, mid, s1] {
                best = best.max(self.grade_at(m, piece.span, s));
            }
            for half in [[s0, mid], [mid, s1]] {
                if half[0] >= half[1] {
                    continue;
                }
                let upper = self.piece_bound(m, piece.span, half).min(piece.upper);
                if upper <= best + GRADE_TOLERANCE {
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

    /// The parameter of `s` in the knot span `span`.
    fn param(&self, span: usize, s: f64) -> f64 {
        let u = self.curve.knots().as_slice();
        let (a, b) = (u[span], u[span + 1]);
        (a + s * (b - a)).clamp(a, b)
    }

    /// The grade at the parameter of `s` in `span`: the largest level at
    /// which `q` is in the set there (a lower bound of the grade).
    fn grade_at(&self, m: Membership, span: usize, s: f64) -> f64 {
        let p = self.curve.degree();
        let mut basis = vec![0.0; p + 1];
        basis_functions(
            self.curve.knots().as_slice(),
            p,
            span,
            self.param(span, s),
            &mut basis,
        );
        let bounds: BasisBounds = basis.iter().map(|&n| [n, n]).collect();
        self.level(m, span, &bounds, false)
    }

    /// An upper bound of the grades on the piece `[s₀, s₁]` of `span`.
    fn piece_bound(&self, m: Membership, span: usize, [s0, s1]: [f64; 2]) -> f64 {
        let p = self.curve.degree();
        let n = p + 1;
        let matrix = bezier_matrix(self.curve.knots().as_slice(), p, span);
        let bounds: BasisBounds = (0..n)
            .map(|i| {
                let mut column: Vec<f64> = (0..n).map(|k| matrix[k * n + i]).collect();
                restrict(&mut column, 1, n, [s0, s1]);
                let lo = column.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = column.iter().copied().fold(0.0, f64::max);
                [
                    (lo * (1.0 - BASIS_WIDENING)).max(0.0),
                    hi * (1.0 + BASIS_WIDENING),
                ]
            })
            .collect();
        self.level(m, span, &bounds, true)
    }

    /// The largest level in `[0, top]` at which `q` lies in the set of the
    /// terms of `span` with basis values within `bounds`; `top` is the least
    /// top of the functions of the terms that count everywhere there. With
    /// `upper`, the level found is rounded up (an upper bound of the grade),
    /// else down (a level at which `q` is a member).
    fn level(&self, m: Membership, span: usize, bounds: &BasisBounds, upper: bool) -> f64 {
        let first = span - self.curve.degree();
        let top = bounds
            .iter()
            .enumerate()
            .filter(|(_, b)| b[0] > 0.0)
            .map(|(i, _)| self.top(m, first + i))
            .fold(1.0_f64, f64::min);
        let inside = |a: f64| self.contains(m, first, bounds, a);
        if !inside(0.0) {
            return 0.0;
        }
        if inside(top) {
            return top;
        }
        let (mut lo, mut hi) = (0.0, top);
        for _ in 0..LEVEL_BISECTIONS {
            let mid = lo + (hi - lo) / 2.0;
            if inside(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        if upper {
            hi
        } else {
            lo
        }
    }

    /// The top of term `i`'s functions under `m`: 1, or for the lower
    /// function the least height of its point's numbers and its weight.
    fn top(&self, m: Membership, i: usize) -> f64 {
        match m {
            Membership::Lower => {
                let point: &Nt2Point<D> = &self.curve.points()[i];
                point
                    .coords()
                    .iter()
                    .chain(std::iter::once(&self.weights[i]))
                    .map(|x| x.height().get())
                    .fold(1.0, f64::min)
            }
            _ => 1.0,
        }
    }

    /// Whether `q` lies in the set at level `a` of the terms from `first`
    /// with basis values within `bounds`. A term whose number has no cut at
    /// `a` empties the set where its basis value is positive; where it may
    /// be 0 on the piece it is left out (the set there has no such term).
    fn contains(&self, m: Membership, first: usize, bounds: &BasisBounds, a: f64) -> bool {
        let Ok(alpha) = Alpha::try_new(a) else {
            return false;
        };
        let (mut lower, mut upper, mut points) = (Vec::new(), Vec::new(), Vec::new());
        for (i, &[n_lo, n_hi]) in bounds.iter().enumerate() {
            if n_hi <= 0.0 {
                continue;
            }
            let (k, point) = (first + i, &self.curve.points()[first + i]);
            let w = cut(&self.weights[k], m, alpha);
            let mut box_ = [[0.0; 2]; D];
            let mut has_cut = w.is_some();
            for (b, x) in box_.iter_mut().zip(point.coords()) {
                match cut(x, m, alpha) {
                    Some(c) => *b = c,
                    None => has_cut = false,
                }
            }
            match (has_cut, w) {
                (true, Some([w_lo, w_hi])) => {
                    lower.push(w_lo * n_lo);
                    upper.push(w_hi * n_hi);
                    points.push(box_);
                }
                _ if n_lo > 0.0 => return false,
                _ => {}
            }
        }
        if lower.iter().sum::<f64>() <= 0.0 {
            // No term is sure to count on the piece: nothing is excluded
            // (at one parameter some term always counts).
            return true;
        }
        IntervalTerms::from_bounds(lower, upper, points)
            .contains(self.q)
            .unwrap_or(false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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
            let (a, b) = (weighted_grades(&curve, &numbers, &q), grader.grades(&q));
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
