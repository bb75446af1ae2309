//! Derivatives of any order of a rational curve and its tangent (The NURBS
//! Book, A2.3, A3.2 and A4.2); the curvature from them is in `curvature.rs`.

use crate::error::{Error, Place};
use crate::nurbs::NurbsCurve;
use crate::vector::norm;

/// The highest derivative order computed. Rational derivatives grow roughly
/// like `k!/hᵏ` (h a knot span), so orders far above the degree overflow
/// long before this; the bound keeps a nonsense order from asking for
/// unbounded time and memory.
pub const MAX_DERIVATIVE_ORDER: usize = 64;

/// Checks a derivative order against [`MAX_DERIVATIVE_ORDER`].
pub(crate) fn check_order(order: usize) -> Result<(), Error> {
    if order > MAX_DERIVATIVE_ORDER {
        return Err(Error::OutOfRange {
            place: Place::NONE,
            what: "derivative order",
            value: order as f64,
            range: "[0, 64]",
        });
    }
    Ok(())
}

/// The basis functions `N_{span−p,p} … N_{span,p}` and their derivatives up to
/// order `n` at `t` (The NURBS Book, A2.3): `ders[k][j]` is the `k`-th
/// derivative of `N_{span−p+j,p}`. Orders above the degree are zero.
///
/// ```text
/// N'_{i,p} = p/(U[i+p] − U[i])·N_{i,p−1} − p/(U[i+p+1] − U[i+1])·N_{i+1,p−1}
/// ```
/// `span` must be a non-empty span with `p ≤ span` and `span + p` below the
/// number of knots (a span of a validated knot vector);
/// [`try_basis_derivatives`] is the checked form.
pub(crate) fn basis_derivatives(
    knots: &[f64],
    degree: usize,
    span: usize,
    t: f64,
    n: usize,
) -> Vec<Vec<f64>> {
    basis_derivatives_in(knots, degree, span, t, n, |d| d)
}

/// The basis functions at `t` in `span` and their derivatives up to order
/// `n` (The NURBS Book, A2.3), checked: `ders[k][j]` is the `k`-th derivative
/// of `N_{span−p+j,p}`; orders above the degree are zero.
///
/// # Errors
/// [`Error::Index`] if `span` does not have `degree` knots on either side
/// (`degree ≤ span` and `span + degree < knots.len()`); [`Error::OutOfRange`]
/// if `n` is above [`MAX_DERIVATIVE_ORDER`].
///
/// # Examples
/// ```
/// # use t2spline::nurbs::derivatives::try_basis_derivatives;
/// // Bernstein polynomials of degree 2 at 1/2: B' = (−1, 0, 1), B'' = (2, −4, 2).
/// let d = try_basis_derivatives(&[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 2, 2, 0.5, 3)?;
/// assert_eq!(d[1], [-1.0, 0.0, 1.0]);
/// assert_eq!(d[2], [2.0, -4.0, 2.0]);
/// assert_eq!(d[3], [0.0, 0.0, 0.0]);
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn try_basis_derivatives(
    knots: &[f64],
    degree: usize,
    span: usize,
    t: f64,
    n: usize,
) -> Result<Vec<Vec<f64>>, Error> {
    crate::nurbs::basis::check_span(knots, degree, span)?;
    check_order(n)?;
    Ok(basis_derivatives(knots, degree, span, t, n))
}

/// [`basis_derivatives`] with respect to a local variable `s` with
/// `ds/dt = local(1)`: every knot difference that divides a derivative is
/// mapped by `local` (`local(d) = d·ds/dt`), while the basis values, which
/// are ratios of knot differences, are computed in `t`.
///
/// Taken in `s`, the derivatives on a span stay of the size of the basis
/// however narrow it is; in `t` they grow like `width⁻ᵏ` and overflow for
/// spans below about 1e-100. A difference that overflows when mapped (a knot
/// far from a narrow span) becomes infinite and its terms 0, which they are to
/// within 1e-308 of the result.
pub(crate) fn basis_derivatives_in(
    knots: &[f64],
    degree: usize,
    span: usize,
    t: f64,
    n: usize,
    local: impl Fn(f64) -> f64,
) -> Vec<Vec<f64>> {
    let p = degree;
    // ndu[j][r]: basis functions (upper triangle) and knot differences (lower).
    let mut ndu = vec![vec![0.0; p + 1]; p + 1];
    let mut left = vec![0.0; p + 1];
    let mut right = vec![0.0; p + 1];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    let mut ders = vec![vec![0.0; p + 1]; n + 1];
    for (j, d) in ders[0].iter_mut().enumerate() {
        *d = ndu[j][p];
    }
    let top = n.min(p);
    let mut a = [vec![0.0; p + 1], vec![0.0; p + 1]];
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0][0] = 1.0;
        for k in 1..=top {
            let mut d = 0.0;
            let rk = r as isize - k as isize;
            let pk = p - k;
            if r >= k {
                let rk = rk as usize;
                a[s2][0] = a[s1][0] / local(ndu[pk + 1][rk]);
                d = a[s2][0] * ndu[rk][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r <= pk { k - 1 } else { p - r };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / local(ndu[pk + 1][idx]);
                d += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][k] = -a[s1][k - 1] / local(ndu[pk + 1][r]);
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut factor = p as f64;
    for (k, row) in ders.iter_mut().enumerate().take(top + 1).skip(1) {
        for d in row {
            *d *= factor;
        }
        factor *= (p - k) as f64;
    }
    ders
}

/// Binomial coefficient `C(n, k)` as a float (exact while below 2⁵³).
pub(crate) fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

impl<const D: usize> NurbsCurve<D> {
    /// `C(t)` and its derivatives `C⁽¹⁾(t) … C⁽ⁿ⁾(t)` (index 0 is the point).
    ///
    /// The homogeneous curve `Cʷ = (A, w)`, `A = Σ wᵢNᵢPᵢ`, `w = Σ wᵢNᵢ`, is
    /// differentiated with the basis derivatives (The NURBS Book, A3.2 with A2.3);
    /// the rational derivatives follow from Leibniz's rule (A4.2):
    ///
    /// ```text
    /// C⁽ᵏ⁾ = ( A⁽ᵏ⁾ − Σᵢ₌₁ᵏ C(k, i)·w⁽ⁱ⁾·C⁽ᵏ⁻ⁱ⁾ ) / w
    /// ```
    /// Any order is allowed: above the degree `A⁽ᵏ⁾` and `w⁽ᵏ⁾` vanish, but the
    /// derivatives of a rational curve in general do not.
    ///
    /// The derivatives are those of the polynomial piece on the span that
    /// [`NurbsCurve::eval`] uses: at an interior knot the piece to its right, at
    /// the right end of the domain the last non-empty span (one-sided
    /// derivatives where the curve is not smooth).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain;
    /// [`Error::OutOfRange`] if `order` exceeds [`MAX_DERIVATIVE_ORDER`].
    ///
    /// # Examples
    /// At the start of a clamped curve `C'(a) = p/(U[p+1] − a)·(w₁/w₀)·(P₁ − P₀)`
    /// (The NURBS Book, Eq. 4.9): for the quarter circle, `(0, √2)`.
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
    /// let d = c.derivatives(0.0, 3)?;
    /// assert_eq!(d[0], [1.0, 0.0]);
    /// assert!(d[1][0].abs() < 1e-15 && (d[1][1] - 2f64.sqrt()).abs() < 1e-15);
    /// assert!(d[3][0] != 0.0); // the third derivative of a rational quadratic
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn derivatives(&self, t: f64, order: usize) -> Result<Vec<[f64; D]>, Error> {
        self.domain().check(t)?;
        check_order(order)?;
        Ok(self.derivatives_unchecked(t, order))
    }

    /// [`NurbsCurve::derivatives`] for `t` in the domain.
    pub(crate) fn derivatives_unchecked(&self, t: f64, order: usize) -> Vec<[f64; D]> {
        self.derivatives_in_span(self.knots().find_span(t), t, order)
    }

    /// The derivatives of the polynomial piece of the non-empty span `span` at
    /// `t` (for `t` at either end of the span, its one-sided limits).
    pub(crate) fn derivatives_in_span(&self, span: usize, t: f64, order: usize) -> Vec<[f64; D]> {
        let knots = self.knots();
        let p = knots.degree();
        let top = order.min(p);
        let ders = basis_derivatives(knots.as_slice(), p, span, t, top);
        let first = span - p;
        // Homogeneous derivatives A⁽ᵏ⁾ and w⁽ᵏ⁾ (A3.2); zero above the degree.
        let mut a = vec![[0.0; D]; order + 1];
        let mut w = vec![0.0; order + 1];
        for (k, row) in ders.iter().enumerate() {
            for (j, n) in row.iter().enumerate() {
                let (pj, wj) = (self.control_points()[first + j], self.weights()[first + j]);
                w[k] += n * wj;
                for d in 0..D {
                    a[k][d] += n * wj * pj[d];
                }
            }
        }
        // Rational derivatives (A4.2).
        let mut c: Vec<[f64; D]> = Vec::with_capacity(order + 1);
        for k in 0..=order {
            let mut v = a[k];
            for i in 1..=k.min(p) {
                let b = binomial(k, i) * w[i];
                for d in 0..D {
                    v[d] -= b * c[k - i][d];
                }
            }
            c.push(v.map(|x| x / w[0]));
        }
        c
    }

    /// The unit tangent at `t`: `C'(t)/‖C'(t)‖`, or, where the first derivative
    /// vanishes, the direction of the first derivative that does not (up to the
    /// degree; beyond it the curve would be constant near `t`). One-sided at
    /// knots as in [`NurbsCurve::derivatives`].
    ///
    /// A derivative counts as vanishing when `‖C⁽ʲ⁾‖·hʲ ≤ 10⁻¹⁴·s`, with `h` the
    /// length of the knot span and `s` the size of the control polygon.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is outside the domain; [`Error::Singular`]
    /// if the curve is constant around `t`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let c = NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [3.0, 4.0]], vec![1.0, 1.0])?;
    /// assert_eq!(c.tangent(0.5)?, [0.6, 0.8]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn tangent(&self, t: f64) -> Result<[f64; D], Error> {
        self.domain().check(t)?;
        let p = self.degree();
        let ders = self.derivatives_unchecked(t, p);
        let (h, s) = self.scales(t);
        for (j, d) in ders.iter().enumerate().skip(1) {
            let norm = norm(d);
            if norm * h.powi(j as i32) > 1e-14 * s {
                return Ok(d.map(|x| x / norm));
            }
        }
        Err(Error::Singular { what: "tangent", t })
    }

    /// The length of the knot span at `t` and the size of the control polygon
    /// (the diagonal of its bounding box, at least the smallest normal float).
    pub(super) fn scales(&self, t: f64) -> (f64, f64) {
        let u = self.knots().as_slice();
        let span = self.knots().find_span(t);
        let mut lo = [f64::INFINITY; D];
        let mut hi = [f64::NEG_INFINITY; D];
        for p in self.control_points() {
            for d in 0..D {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        let size = norm(&std::array::from_fn::<f64, D, _>(|d| hi[d] - lo[d]));
        (u[span + 1] - u[span], size.max(f64::MIN_POSITIVE))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::basis::basis_functions;
    use crate::nurbs::fixtures::five_point_cubic;
    use crate::nurbs::KnotVector;

    #[test]
    fn basis_derivatives_of_order_zero_are_the_basis_functions() {
        let u = [0.0, 0.0, 0.0, 0.3, 0.3, 0.7, 1.0, 1.0, 1.0];
        for t in [0.0, 0.1, 0.3, 0.5, 0.99] {
            let span = KnotVector::try_new(u.to_vec(), 2, 6).unwrap().find_span(t);
            let mut n = [0.0; 3];
            basis_functions(&u, 2, span, t, &mut n);
            let d = basis_derivatives(&u, 2, span, t, 2);
            assert_eq!(d[0], n, "t = {t}");
            // Derivatives of a partition of unity sum to 0.
            assert!(
                d[1].iter().sum::<f64>().abs() < 1e-12 && d[2].iter().sum::<f64>().abs() < 1e-11
            );
        }
    }

    #[test]
    fn derivatives_match_central_differences() {
        let c = five_point_cubic();
        let h = 1e-5;
        for t in [0.1, 0.25, 0.6, 0.9] {
            let d = c.derivatives(t, 2).unwrap();
            let (a, b) = (c.eval(t - h).unwrap(), c.eval(t + h).unwrap());
            for k in 0..2 {
                let fd1 = (b[k] - a[k]) / (2.0 * h);
                let fd2 = (b[k] - 2.0 * d[0][k] + a[k]) / (h * h);
                assert!(
                    (d[1][k] - fd1).abs() < 1e-6 * (1.0 + fd1.abs()),
                    "{t}: {d:?} {fd1}"
                );
                assert!(
                    (d[2][k] - fd2).abs() < 1e-3 * (1.0 + fd2.abs()),
                    "{t}: {d:?} {fd2}"
                );
            }
        }
    }

    #[test]
    fn rational_derivatives_above_the_degree_do_not_vanish() {
        // The quarter circle: C(t) = ((1 − t²)·…); compare with the closed form
        // in the angle: C(θ(t)) with x = cos θ, so the derivatives of order 3 are
        // non-zero although the degree is 2. Check against finite differences of
        // the second derivative.
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let c = NurbsCurve::try_clamped(
            2,
            vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            vec![1.0, w, 1.0],
        )
        .unwrap();
        let h = 1e-5;
        let t = 0.4;
        let d3 = c.derivatives(t, 3).unwrap()[3];
        let (a, b) = (
            c.derivatives(t - h, 2).unwrap()[2],
            c.derivatives(t + h, 2).unwrap()[2],
        );
        for k in 0..2 {
            let fd = (b[k] - a[k]) / (2.0 * h);
            assert!(
                d3[k].abs() > 0.1 && (d3[k] - fd).abs() < 1e-5 * (1.0 + fd.abs()),
                "{d3:?} {fd}"
            );
        }
    }

    #[test]
    fn polynomial_derivatives_above_the_degree_vanish() {
        let c = NurbsCurve::try_clamped(
            2,
            vec![[0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 4.0]],
            vec![1.5; 4],
        )
        .unwrap();
        let d = c.derivatives(0.3, 5).unwrap();
        assert!(d[3..].iter().flatten().all(|x| x.abs() < 1e-12), "{d:?}");
        assert_eq!(c.derivatives(0.3, MAX_DERIVATIVE_ORDER).unwrap().len(), 65);
        assert!(matches!(
            c.derivatives(0.3, usize::MAX),
            Err(Error::OutOfRange {
                what: "derivative order",
                ..
            })
        ));
    }

    #[test]
    fn tangent_uses_the_first_non_vanishing_derivative() {
        // Two equal control points at the start: C'(0) = 0, C''(0) ≠ 0.
        let c = NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [0.0, 0.0], [2.0, 0.0]], vec![1.0; 3])
            .unwrap();
        assert_eq!(c.derivatives(0.0, 1).unwrap()[1], [0.0, 0.0]);
        assert_eq!(c.tangent(0.0).unwrap(), [1.0, 0.0]);
        assert!(matches!(c.curvature(0.0), Err(Error::Singular { .. })));
    }
}
