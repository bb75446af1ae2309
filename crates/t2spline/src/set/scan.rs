//! The parameter pieces the set view scans, and the basis on them.

use crate::nurbs::basis::basis_functions;
use crate::nurbs::pieces::tame_pieces;
use crate::nurbs::KnotVector;

/// A piece `[lo, hi]` of the knot span `span` of a curve (or of one direction
/// of a surface): the parameters where the same `p + 1` control points count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SpanPiece {
    pub(crate) span: usize,
    pub(crate) lo: f64,
    pub(crate) hi: f64,
}

impl SpanPiece {
    /// The first control point that counts on the piece.
    pub(crate) fn first(&self, degree: usize) -> usize {
        self.span - degree
    }

    /// `steps + 1` equally spaced parameters from `lo` to `hi`, both ends exact.
    pub(crate) fn params(&self, steps: usize) -> impl Iterator<Item = f64> + '_ {
        let step = (self.hi - self.lo) / steps as f64;
        (0..=steps).map(move |j| {
            if j == steps {
                self.hi
            } else {
                (self.lo + step * j as f64).min(self.hi)
            }
        })
    }
}

/// The knot spans of `knots`, cut where the weights vary by more than a
/// factor 4 (as for the distance and the arc length: a rational curve can
/// move within a small part of such a span).
pub(crate) fn pieces(knots: &KnotVector, weights: &[f64]) -> Vec<SpanPiece> {
    let d = knots.domain();
    tame_pieces(knots, weights, |i| vec![weights[i]], d.start, d.end)
        .into_iter()
        .filter(|p| p.lo < p.hi)
        .map(|p| SpanPiece {
            span: p.span,
            lo: p.lo,
            hi: p.hi,
        })
        .collect()
}

/// The `p + 1` rational basis functions of span `span` at `t`, written into
/// `out` (`Rⱼ = wⱼNⱼ / Σ wᵣNᵣ`).
pub(crate) fn rational_basis(
    knots: &KnotVector,
    weights: &[f64],
    span: usize,
    t: f64,
    out: &mut [f64],
) {
    let p = knots.degree();
    basis_functions(knots.as_slice(), p, span, t, out);
    let mut sum = 0.0;
    for (n, w) in out.iter_mut().zip(&weights[span - p..]) {
        *n *= w;
        sum += *n;
    }
    for n in out.iter_mut() {
        *n /= sum;
    }
}
