//! The weighted B-spline basis in power form, one polynomial per span.
//!
//! On each non-empty span `[a, b]` the basis is written in
//! `s = (t − mid)·2/(b − a) ∈ [−1, 1]` from its derivatives at the midpoint
//! (The NURBS Book A2.3, `derivatives::basis_derivatives_in`). Centring on the
//! midpoint keeps the coefficients small; the tests hold degrees up to 12 to
//! 1e-12. The derivatives are taken in `s` itself: each knot difference that
//! divides a derivative in A2.3 is mapped to `s` units, while the basis values
//! stay ratios of differences in `t`. In `t` the `k`-th derivative grows like
//! `width⁻ᵏ` and overflowed for spans of 1e-140 (NaN samples); in `s` it stays
//! of the size of the basis, and a difference that overflows when mapped (a
//! far knot) contributes 0, as it should to within 1e-308. Mapping the knots
//! themselves and clamping the far ones was tried first and was wrong: two far
//! knots on either side of a narrow span share a ratio (found by fuzzing).
//! Spans narrower than 1e-290 are pre-scaled by 2⁶⁰⁰ so that `2/width` stays
//! finite.
//!
//! Horner's rule errs by about `order·ε·Σ|cⱼₖ|`, and the denominator is at
//! least the least weight, so a span whose condition `Σ|cⱼₖ| / min w` exceeds
//! 10³ is evaluated from the basis instead (`direct.rs`). Ordinary curves
//! measure 3 to 160; weights from 1e-12 to 1e12 measure 1e24, where the power
//! form's denominator cancelled to negative values and NaN.

use crate::nurbs::derivatives::basis_derivatives_in;
use crate::nurbs::KnotVector;

/// One non-empty knot span `[start, end]` and its local variable
///
/// ```text
/// s = ((t − mid)·pre)·inv_half ∈ [−1, 1],   mid = (start + end)/2,   inv_half = 2/((end − start)·pre)
/// ```
/// Centring on the midpoint keeps the power coefficients small (a power basis on
/// `[−1, 1]` is far better conditioned than one on `[0, 1]`). `pre` is 1, or
/// 2⁶⁰⁰ for a span narrower than 1e-290, whose `2/(end − start)` would
/// overflow (an exact power of two, so it changes no rounding). In a span one
/// subnormal unit wide `mid` rounds to `start` and `s` runs over `[0, 2]`;
/// the power form stays exact, as it is taken about `mid` whatever it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Span {
    pub(crate) start: f64,
    pub(crate) end: f64,
    pub(crate) mid: f64,
    pub(crate) pre: f64,
    pub(crate) inv_half: f64,
    /// Index of the first control point whose basis function is non-zero here.
    pub(crate) first: usize,
    /// Whether the power form is too ill-conditioned here and the span is
    /// evaluated directly from the basis (see [`MAX_CONDITION`]).
    pub(crate) direct: bool,
}

/// The largest condition number `κ = Σⱼₖ |cⱼₖ| / minⱼ wⱼ` of a span that is
/// evaluated in power form. Horner's rule on `|s| ≤ 1` errs by at most about
/// `2·order·ε·Σₖ|aₖ|` (Higham, *Accuracy and Stability of Numerical
/// Algorithms*, §5.1), while the denominator is at least `minⱼ wⱼ` (the basis
/// is non-negative and sums to 1): so a value's relative error, against the
/// size of the control values, is at most about `4·order·ε·κ`, below 1e-11
/// for κ ≤ 1e3 at order 8. Typical curves have κ of 2ᵖ times the weight
/// ratio (8 for the cubic Bézier with equal weights); weights spread over
/// 1e-12 … 1e12 give κ near 1e24, where the power form cancels to nonsense
/// (a negative denominator, NaN).
pub(crate) const MAX_CONDITION: f64 = 1e3;

/// Spans narrower than this get the pre-scaling `PRE`.
const NARROW: f64 = 1e-290;
/// 2⁶⁰⁰.
const PRE: f64 = 4.149_515_568_880_993e180;

impl Span {
    fn new(start: f64, end: f64, first: usize) -> Self {
        let width = end - start;
        let pre = if width < NARROW { PRE } else { 1.0 };
        Span {
            start,
            end,
            mid: start + width / 2.0,
            pre,
            inv_half: 2.0 / (width * pre),
            first,
            direct: false,
        }
    }

    /// A span evaluated directly from the basis, without power form.
    pub(crate) fn direct(start: f64, end: f64, first: usize) -> Self {
        Span {
            direct: true,
            ..Span::new(start, end, first)
        }
    }

    /// The local variable `s` of `t`.
    #[inline(always)]
    pub(crate) fn local(&self, t: f64) -> f64 {
        ((t - self.mid) * self.pre) * self.inv_half
    }
}

/// The non-zero weighted basis functions `wⱼ Nⱼ,ₚ` of every non-empty span as
/// polynomials in the span's local variable `s` (see [`Span`]):
///
/// ```text
/// wⱼ Nⱼ,ₚ(t) = Σₖ cⱼₖ sᵏ,   cⱼₖ = wⱼ · (dᵏNⱼ/dsᵏ)(0) / k!  ( = wⱼ · Nⱼ⁽ᵏ⁾(mid) · halfᵏ / k! )
/// ```
/// a Taylor expansion about the midpoint, exact for polynomials of degree p,
/// with the derivatives from The NURBS Book, A2.3, taken in `s` (see
/// [`local_basis_derivatives`]).
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
            let mut span = Span::new(start, end, i - p);
            let ders = local_basis_derivatives(knots.as_slice(), p, i, &span);
            let active = &weights[span.first..span.first + order];
            let mut size = 0.0;
            for (j, w) in active.iter().enumerate() {
                let mut factorial = 1.0;
                for (k, d) in ders.iter().enumerate() {
                    if k > 0 {
                        factorial *= k as f64;
                    }
                    let c = d[j] / factorial * w;
                    size += c.abs();
                    coefficients.push(c);
                }
            }
            let least = active.iter().fold(f64::INFINITY, |m, &w| m.min(w));
            let condition = size / least;
            span.direct = condition.is_nan() || condition > MAX_CONDITION;
            spans.push(span);
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

/// The derivatives in the local variable `s` at `s = 0` (`t = mid`) of the
/// basis functions `N_{index−p}, …, N_{index}` (`ders[k][j]`, as
/// [`basis_derivatives`](crate::nurbs::derivatives::basis_derivatives)):
/// `dᵏNⱼ/dsᵏ = Nⱼ⁽ᵏ⁾(mid)·halfᵏ`, with every knot difference that divides a
/// derivative mapped to `s` units ([`basis_derivatives_in`]).
///
/// In `t` the `k`-th derivative grows like `1/(span width)ᵏ` and overflowed for
/// spans of 1e-140 (infinite and NaN samples). Mapping the knots
/// themselves to `s` and clamping the far ones was wrong: two far knots on
/// either side of a narrow span enter one ratio, which clamping changed (found
/// by fuzzing); here the basis values stay ratios in `t`.
fn local_basis_derivatives(knots: &[f64], p: usize, index: usize, span: &Span) -> Vec<Vec<f64>> {
    let local = |d: f64| (d * span.pre) * span.inv_half;
    basis_derivatives_in(knots, p, index, span.mid, p, local)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cubic(interior: &[f64], weights: &[f64]) -> PowerBasis {
        let mut u = vec![0.0; 4];
        u.extend(interior);
        u.extend([1.0; 4]);
        PowerBasis::new(&KnotVector::try_new(u, 3, weights.len()).unwrap(), weights)
    }

    #[test]
    fn bezier_coefficients_are_the_bernstein_polynomials_in_s() {
        // B₀(t) = (1 − t)³ with t = (1 + s)/2: ((1 − s)/2)³ = (1 − 3s + 3s² − s³)/8.
        let b = cubic(&[], &[1.0; 4]);
        let c = b.span_coefficients(0);
        let want = [0.125, -0.375, 0.375, -0.125];
        assert!(
            c[..4].iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-16),
            "{c:?}"
        );
        assert!(!b.spans()[0].direct);
    }

    #[test]
    fn narrow_spans_have_finite_coefficients_of_the_basis_size() {
        for width in [1e-140, 1e-300, 1e-320, 5e-324] {
            let b = cubic(&[0.5, 0.5 + width], &[1.0, 2.0, 0.5, 1.0, 3.0, 1.0]);
            for k in 0..b.spans().len() {
                let c = b.span_coefficients(k);
                assert!(
                    c.iter().all(|x| x.is_finite() && x.abs() <= 3.0 * 8.0),
                    "{width:e}: {c:?}"
                );
            }
            assert!(b.spans().iter().all(|s| !s.direct), "{width:e}");
        }
    }

    #[test]
    fn weights_over_many_orders_of_magnitude_are_evaluated_directly() {
        let b = cubic(&[0.5], &[1e12, 1e-12, 3.0, 1.0, 1.0]);
        assert!(b.spans()[0].direct);
        // The second span's weights 1e-12 … 1: κ ≈ 1e12 too.
        assert!(b.spans()[1].direct);
        let b = cubic(&[0.5], &[1.0, 0.5, 3.0, 1.0, 1.0]);
        assert!(b.spans().iter().all(|s| !s.direct));
    }

    #[test]
    fn the_benchmark_curve_and_uneven_curves_use_the_power_form() {
        let c = crate::sampling::benchmark_curve();
        let b = PowerBasis::new(c.knots(), c.weights());
        assert!(b.spans().iter().all(|s| !s.direct));
        // Degree 5, weights 0.2 … 5, uneven knots.
        let u = vec![
            0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.01, 0.3, 0.31, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
        ];
        let w = [1.0, 0.2, 5.0, 0.7, 1.0, 0.2, 5.0, 0.7, 1.0];
        let b = PowerBasis::new(&KnotVector::try_new(u, 5, 9).unwrap(), &w);
        // κ is 4 … 78 here (and at most 160 for degrees up to 12 with such
        // weights in `tests/sampling.rs`).
        assert!(b.spans().iter().all(|s| !s.direct));
    }
}
