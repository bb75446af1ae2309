//! Evaluation on one knot span at a time without allocation: the inner loop
//! of quadrature and search (arc length, the distance between curves).

use crate::nurbs::basis::basis_functions;
use crate::nurbs::NurbsCurve;

/// Evaluates curves of one degree and their first derivatives on a chosen
/// knot span, many times, without allocating.
///
/// The Cox–de Boor recurrence (The NURBS Book, A2.2) divides by the knot
/// differences `U[span+1+r] − U[span+1−j+r]`, which depend on the span only:
/// their reciprocals are computed once when the span is chosen, so a point
/// costs `p(p+1)` multiplications and no division. The first derivative
/// comes from the same products (A2.3 with `k = 1`):
///
/// ```text
/// N'ᵢ,ₚ = p·( Nᵢ,ₚ₋₁/(U[i+p] − U[i]) − Nᵢ₊₁,ₚ₋₁/(U[i+p+1] − U[i+1]) )
/// C = A/w,   C' = (A' − w'·C)/w,   A = Σ wᵢNᵢPᵢ,  w = Σ wᵢNᵢ
/// ```
/// A span so narrow that a reciprocal overflows (below about 1e-308) is
/// evaluated by [`basis_functions`], which divides first.
#[derive(Clone, Debug)]
pub(crate) struct SpanEvaluator {
    span: usize,
    /// `1/(U[span+1+r] − U[span+1−j+r])` at `j(j−1)/2 + r`, for `j = 1 … p`,
    /// `r < j`.
    inverse: Vec<f64>,
    /// Whether every reciprocal is finite.
    finite: bool,
    basis: Vec<f64>,
    derivative: Vec<f64>,
    left: Vec<f64>,
    right: Vec<f64>,
}

impl SpanEvaluator {
    /// An evaluator for curves of degree `degree`, on no span yet.
    pub(crate) fn new(degree: usize) -> Self {
        let order = degree + 1;
        SpanEvaluator {
            span: usize::MAX,
            inverse: vec![0.0; order * (order - 1) / 2],
            finite: true,
            basis: vec![0.0; order],
            derivative: vec![0.0; order],
            left: vec![0.0; order],
            right: vec![0.0; order],
        }
    }

    /// Chooses the non-empty knot span `span` (`U[span] < U[span+1]`, `p ≤
    /// span < n`) of `curve`, whose degree must be the evaluator's. The
    /// evaluation methods must then be given the same curve. Costs about one
    /// evaluation: callers choose a span once for many points.
    pub(crate) fn set_span<const D: usize>(&mut self, curve: &NurbsCurve<D>, span: usize) {
        debug_assert_eq!(curve.order(), self.basis.len());
        self.span = span;
        let u = curve.knots().as_slice();
        let p = curve.degree();
        self.finite = true;
        for j in 1..=p {
            for r in 0..j {
                let inverse = 1.0 / (u[span + 1 + r] - u[span + 1 + r - j]);
                self.finite &= inverse.is_finite();
                self.inverse[j * (j - 1) / 2 + r] = inverse;
            }
        }
    }

    /// The basis functions at `t` into `self.basis`, and with `derivative`
    /// their derivatives into `self.derivative`.
    fn basis_at(&mut self, u: &[f64], t: f64, derivative: bool) {
        let (p, span) = (self.basis.len() - 1, self.span);
        if !self.finite {
            basis_functions(u, p, span, t, &mut self.basis);
            if derivative {
                let d = &crate::nurbs::derivatives::basis_derivatives(u, p, span, t, 1)[1];
                self.derivative.copy_from_slice(d);
            }
            return;
        }
        let out = &mut self.basis;
        out[0] = 1.0;
        for j in 1..=p {
            self.left[j] = t - u[span + 1 - j];
            self.right[j] = u[span + j] - t;
            let inverse = &self.inverse[j * (j - 1) / 2..j * (j + 1) / 2];
            let last = derivative && j == p;
            let mut saved = 0.0;
            for r in 0..j {
                let temp = out[r] * inverse[r];
                if last {
                    // temp = Nᵣ,ₚ₋₁/(U[…] − U[…]): N'ᵣ = p·(temp_{r−1} − temp_r).
                    self.derivative[r] = if r == 0 { 0.0 } else { self.derivative[r] } - temp;
                    self.derivative[r + 1] = temp;
                }
                out[r] = saved + self.right[r + 1] * temp;
                saved = self.left[j - r] * temp;
            }
            out[j] = saved;
        }
        if derivative {
            if p == 0 {
                self.derivative[0] = 0.0;
            }
            let degree = p as f64;
            self.derivative.iter_mut().for_each(|d| *d *= degree);
        }
    }

    /// `C(t)` on the chosen span (`t` in it or at its ends), as the convex
    /// combination `Σ Rᵢ·Pᵢ` with `Rᵢ = wᵢNᵢ/w`: forming `Σ wᵢNᵢPᵢ` first
    /// would underflow for weights near 1e-150 and coordinates near 1e-300.
    pub(crate) fn point<const D: usize>(&mut self, curve: &NurbsCurve<D>, t: f64) -> [f64; D] {
        self.basis_at(curve.knots().as_slice(), t, false);
        let first = self.span - curve.degree();
        let order = self.basis.len();
        let weights = &curve.weights()[first..first + order];
        let points = &curve.control_points()[first..first + order];
        let w: f64 = self.basis.iter().zip(weights).map(|(n, wi)| n * wi).sum();
        // w is at least the least weight, 1e-150 or more: 1/w is finite.
        let inverse = 1.0 / w;
        let mut c = [0.0; D];
        for ((n, wi), pi) in self.basis.iter().zip(weights).zip(points) {
            let r = n * wi * inverse;
            for (cd, pd) in c.iter_mut().zip(pi) {
                *cd += r * pd;
            }
        }
        c
    }

    /// `C(t)` and `C'(t)` on the chosen span (one-sided at its ends).
    ///
    /// The derivative is formed from differences of control points,
    ///
    /// ```text
    /// C' = Σᵢ<ⱼ (bᵢaⱼ − aᵢbⱼ)·(Pᵢ − Pⱼ),   aᵢ = wᵢNᵢ/w,  bᵢ = wᵢN'ᵢ/w
    /// ```
    /// (from `C' = (A' − w'·C)/w` and `C − Pᵢ = Σⱼ aⱼ(Pⱼ − Pᵢ)`), not as
    /// `(A' − w'·C)/w`: with weights far apart, `A'` and `w'·C` are huge and
    /// nearly equal where one weight dominates, and their difference was
    /// rounding noise larger than the speed itself (weights from 10⁻¹² to
    /// 10¹²: a length 1% too long). `O(p²)` operations, as the basis.
    pub(crate) fn point_and_derivative<const D: usize>(
        &mut self,
        curve: &NurbsCurve<D>,
        t: f64,
    ) -> ([f64; D], [f64; D]) {
        self.basis_at(curve.knots().as_slice(), t, true);
        let first = self.span - curve.degree();
        let order = self.basis.len();
        let weights = &curve.weights()[first..first + order];
        let points = &curve.control_points()[first..first + order];
        let w: f64 = self.basis.iter().zip(weights).map(|(n, wi)| n * wi).sum();
        // aᵢ and bᵢ in place of the basis and its derivative.
        for ((n, dn), wi) in self.basis.iter_mut().zip(&mut self.derivative).zip(weights) {
            *n *= wi / w;
            *dn *= wi / w;
        }
        let (a, b) = (&self.basis, &self.derivative);
        let mut c = [0.0; D];
        let mut dc = [0.0; D];
        for i in 0..order {
            for d in 0..D {
                c[d] += a[i] * points[i][d];
            }
            for j in i + 1..order {
                let k = b[i] * a[j] - a[i] * b[j];
                if k != 0.0 {
                    for d in 0..D {
                        dc[d] += k * (points[i][d] - points[j][d]);
                    }
                }
            }
        }
        (c, dc)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::KnotVector;

    #[test]
    fn matches_eval_and_derivatives_on_every_span() {
        let u = KnotVector::try_new(
            vec![0.0, 0.0, 0.0, 0.0, 0.2, 0.2, 0.5, 0.9, 1.0, 1.0, 1.0, 1.0],
            3,
            8,
        )
        .unwrap();
        let c = NurbsCurve::try_new(
            vec![
                [0.0, 0.0],
                [1.0, 3.0],
                [3.0, -1.0],
                [4.0, 2.0],
                [5.0, 0.0],
                [6.0, 1.5],
                [7.0, -2.0],
                [8.0, 0.5],
            ],
            vec![1.0, 4.0, 0.3, 1.0, 2.0, 0.7, 5.0, 1.0],
            u,
        )
        .unwrap();
        let mut e = SpanEvaluator::new(3);
        for (span, [a, b]) in c.knots().spans() {
            e.set_span(&c, span);
            for s in [0.0, 0.13, 0.5, 0.77, 1.0] {
                let t = a + s * (b - a);
                let (point, tangent) = e.point_and_derivative(&c, t);
                let again = e.point(&c, t);
                assert!((0..2).all(|d| (again[d] - point[d]).abs() < 1e-14));
                let want = c.derivatives_in_span(span, t, 1);
                for d in 0..2 {
                    assert!(
                        (point[d] - want[0][d]).abs() < 1e-14,
                        "{t}: {point:?} {want:?}"
                    );
                    assert!(
                        (tangent[d] - want[1][d]).abs() < 1e-12 * (1.0 + want[1][d].abs()),
                        "{t}: {tangent:?} {want:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn degree_zero_and_one() {
        let c = NurbsCurve::try_clamped(0, vec![[1.0, 2.0], [3.0, 4.0]], vec![1.0, 2.0]).unwrap();
        let mut e = SpanEvaluator::new(0);
        e.set_span(&c, 1);
        assert_eq!(e.point_and_derivative(&c, 0.7), ([3.0, 4.0], [0.0, 0.0]));
        let c = NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [3.0, 4.0]], vec![1.0, 1.0]).unwrap();
        let mut e = SpanEvaluator::new(1);
        e.set_span(&c, 1);
        assert_eq!(e.point_and_derivative(&c, 0.5), ([1.5, 2.0], [3.0, 4.0]));
    }

    #[test]
    fn a_subnormal_span_is_evaluated_by_division() {
        let end = 1.354e-321;
        let u = KnotVector::try_new(vec![0.0, 0.0, 0.0, end, end, end], 2, 3).unwrap();
        let c = NurbsCurve::try_new(
            vec![[0.0, 0.0], [1.0, 2.0], [3.0, 4.0]],
            vec![1.0, 2.0, 1.0],
            u,
        )
        .unwrap();
        let mut e = SpanEvaluator::new(2);
        e.set_span(&c, 2);
        assert!(!e.finite);
        let t = end / 2.0;
        let (got, want) = (e.point(&c, t), c.eval(t).unwrap());
        assert!(
            (0..2).all(|d| (got[d] - want[d]).abs() <= 1e-15 * want[d].abs()),
            "{got:?} {want:?}"
        );
    }
}
