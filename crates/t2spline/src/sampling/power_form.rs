//! The weighted B-spline basis in power form, one polynomial per span.

use crate::nurbs::derivatives::basis_derivatives;
use crate::nurbs::KnotVector;

/// One non-empty knot span `[start, end]` and its local variable
///
/// ```text
/// s = (t − mid)·inv_half ∈ [−1, 1],   mid = (start + end)/2,   inv_half = 2/(end − start)
/// ```
/// Centring on the midpoint keeps the power coefficients small (a power basis on
/// `[−1, 1]` is far better conditioned than one on `[0, 1]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Span {
    pub(crate) start: f64,
    pub(crate) end: f64,
    pub(crate) mid: f64,
    pub(crate) inv_half: f64,
    /// Index of the first control point whose basis function is non-zero here.
    pub(crate) first: usize,
}

/// The non-zero weighted basis functions `wⱼ Nⱼ,ₚ` of every non-empty span as
/// polynomials in the span's local variable `s` (see [`Span`]):
///
/// ```text
/// wⱼ Nⱼ,ₚ(t) = Σₖ cⱼₖ sᵏ,   cⱼₖ = wⱼ · Nⱼ⁽ᵏ⁾(mid) · halfᵏ / k!
/// ```
/// with the derivatives from The NURBS Book, A2.3 (Taylor expansion about the
/// midpoint, exact for polynomials of degree p).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PowerBasis {
    order: usize,
    spans: Vec<Span>,
    /// Per span, `order` rows (one per basis function) of `order` coefficients.
    coefficients: Vec<f64>,
}

impl PowerBasis {
    pub(crate) fn new(knots: &KnotVector, weights: &[f64]) -> Self {
        let p = knots.degree();
        let order = p + 1;
        let mut spans = Vec::new();
        let mut coefficients = Vec::new();
        for (i, [start, end]) in knots.spans() {
            let half = (end - start) / 2.0;
            let mid = start + half;
            let first = i - p;
            let ders = basis_derivatives(knots.as_slice(), p, i, mid, p);
            for (j, w) in weights[first..first + order].iter().enumerate() {
                let mut scale = *w;
                for (k, d) in ders.iter().enumerate() {
                    coefficients.push(d[j] * scale);
                    scale *= half / (k + 1) as f64;
                }
            }
            spans.push(Span {
                start,
                end,
                mid,
                inv_half: 1.0 / half,
                first,
            });
        }
        PowerBasis {
            order,
            spans,
            coefficients,
        }
    }

    pub(crate) fn order(&self) -> usize {
        self.order
    }

    pub(crate) fn spans(&self) -> &[Span] {
        &self.spans
    }

    /// The coefficients of one span: `order` rows of `order`.
    pub(crate) fn span_coefficients(&self, span: usize) -> &[f64] {
        let size = self.order * self.order;
        &self.coefficients[span * size..(span + 1) * size]
    }
}
