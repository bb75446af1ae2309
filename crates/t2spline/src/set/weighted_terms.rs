//! The sets of a curve with fuzzy weights on a piece of a knot span
//! (docs/method.md §16), shared by its grades and its sections.
//!
//! At one parameter the terms are the basis values `Nᵢ(t)` with the cuts of
//! the weights and points: the exact set `S(t)` of docs/method.md §15. On a
//! piece `[t₀, t₁]` every basis function lies between the least and the
//! largest of its Bézier coefficients there, `n̲ᵢ ≤ Nᵢ(t) ≤ n̄ᵢ`, so every
//! point of the curve on the piece is a weighted average with weights
//! `θᵢ ∈ [w̲ᵢn̲ᵢ, w̄ᵢn̄ᵢ]`: terms of the same kind whose set holds every set of
//! the piece.

use crate::fuzzy::{Alpha, Membership, Nt2Number, Nt2Point};
use crate::interval_weights::IntervalTerms;
use crate::nurbs::basis::basis_functions;
use crate::pipeline::FuzzyCurve;
use crate::set::bernstein::{bezier_matrix, restrict};
use crate::set::curve_envelope::cut;

/// The relative widening of the bounds of a basis function on a piece,
/// against the rounding of its Bézier coefficients.
const BASIS_WIDENING: f64 = 1e-12;

/// Per term of a span: the least and the largest value of its basis
/// function on a piece (equal at one parameter).
pub(crate) type BasisBounds = Vec<[f64; 2]>;

/// The set of a piece at one level.
pub(crate) enum PieceSet<const D: usize> {
    /// Empty: a number that counts on the whole piece has no cut.
    Empty,
    /// Not bounded here: no term is sure to count on the piece.
    Unbounded,
    /// The set of these terms (a superset on a piece, exact at a parameter).
    Terms(IntervalTerms<D>),
}

/// The curve with its fuzzy weights, and the Bézier matrix of each of its
/// knot spans.
#[derive(Clone)]
pub(crate) struct Weighted<'a, const D: usize> {
    pub(crate) curve: &'a FuzzyCurve<D>,
    pub(crate) weights: &'a [Nt2Number],
    /// Per span index, its `bezier_matrix` (empty for an empty span).
    matrices: Vec<Vec<f64>>,
}

impl<'a, const D: usize> Weighted<'a, D> {
    /// The curve `curve` with its fuzzy weights `weights`.
    pub(crate) fn new(curve: &'a FuzzyCurve<D>, weights: &'a [Nt2Number]) -> Self {
        let (u, p) = (curve.knots().as_slice(), curve.degree());
        let mut matrices = vec![Vec::new(); u.len()];
        for (span, _) in curve.knots().spans() {
            matrices[span] = bezier_matrix(u, p, span);
        }
        Weighted {
            curve,
            weights,
            matrices,
        }
    }

    /// The parameter of `s ∈ [0, 1]` in the knot span `span`.
    pub(crate) fn param(&self, span: usize, s: f64) -> f64 {
        let u = self.curve.knots().as_slice();
        let (a, b) = (u[span], u[span + 1]);
        (a + s * (b - a)).clamp(a, b)
    }

    /// The basis values at the parameter of `s` in `span`, as bounds.
    pub(crate) fn at(&self, span: usize, s: f64) -> BasisBounds {
        let p = self.curve.degree();
        let mut basis = vec![0.0; p + 1];
        let t = self.param(span, s);
        basis_functions(self.curve.knots().as_slice(), p, span, t, &mut basis);
        basis.iter().map(|&n| [n, n]).collect()
    }

    /// Bounds of the basis functions of `span` on the piece `[s₀, s₁]`.
    pub(crate) fn on(&self, span: usize, [s0, s1]: [f64; 2]) -> BasisBounds {
        let p = self.curve.degree();
        let n = p + 1;
        let matrix = &self.matrices[span];
        (0..n)
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
            .collect()
    }

    /// The top of term `i`'s functions under `m`: 1, or for the lower
    /// function the least height of its point's numbers and its weight.
    pub(crate) fn top(&self, m: Membership, i: usize) -> f64 {
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

    /// The least top (under `m`) of the terms of `span` that count
    /// everywhere on the piece of `bounds`.
    pub(crate) fn least_top(&self, m: Membership, span: usize, bounds: &BasisBounds) -> f64 {
        let first = span - self.curve.degree();
        bounds
            .iter()
            .enumerate()
            .filter(|(_, b)| b[0] > 0.0)
            .map(|(i, _)| self.top(m, first + i))
            .fold(1.0_f64, f64::min)
    }

    /// The set at level `a` of the terms of `span` with basis values within
    /// `bounds`. A term whose number has no cut at `a` empties the set where
    /// its basis value is positive; where it may be 0 on the piece it is left
    /// out (the set there has no such term).
    pub(crate) fn set(
        &self,
        m: Membership,
        span: usize,
        bounds: &BasisBounds,
        a: f64,
    ) -> PieceSet<D> {
        let Ok(alpha) = Alpha::try_new(a) else {
            return PieceSet::Empty;
        };
        let first = span - self.curve.degree();
        let (mut lower, mut upper, mut points) = (Vec::new(), Vec::new(), Vec::new());
        for (i, &[n_lo, n_hi]) in bounds.iter().enumerate() {
            if n_hi <= 0.0 {
                continue;
            }
            let k = first + i;
            let w = cut(&self.weights[k], m, alpha);
            let mut box_ = [[0.0; 2]; D];
            let mut has_cut = w.is_some();
            for (b, x) in box_.iter_mut().zip(self.curve.points()[k].coords()) {
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
                _ if n_lo > 0.0 => return PieceSet::Empty,
                _ => {}
            }
        }
        if lower.iter().sum::<f64>() <= 0.0 {
            // At one parameter some term always counts.
            return PieceSet::Unbounded;
        }
        PieceSet::Terms(IntervalTerms::from_bounds(lower, upper, points))
    }
}
