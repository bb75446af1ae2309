//! The rational B-spline curve of docs/method.md §6 (paper Def. 5.1).

use crate::error::{Error, Place};
use crate::fuzzy::Axis;
use crate::limits::{within_magnitude, MAGNITUDE_RANGE, MAX_WEIGHT, MIN_WEIGHT};
use crate::nurbs::basis::{basis_functions, STACK_ORDER};
use crate::nurbs::{Domain, KnotVector};

/// A rational B-spline curve in `D` dimensions (docs/method.md §6, paper Def. 5.1):
///
/// ```text
/// C(t) = Σᵢ wᵢ Nᵢ,ₚ(t) Pᵢ / Σᵣ wᵣ Nᵣ,ₚ(t),   t ∈ [U[p], U[n]]
/// ```
/// of degree `p` (order `k = p + 1`), with `n ≥ k` control points `Pᵢ`, weights
/// `wᵢ > 0` and a validated [`KnotVector`]. Equal weights give the non-rational
/// B-spline.
///
/// # Examples
/// The quarter circle as a rational quadratic (The NURBS Book, Ex. 7.1):
/// ```
/// # use t2spline::NurbsCurve;
/// let w = std::f64::consts::FRAC_1_SQRT_2;
/// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
/// let [x, y] = c.eval(0.3)?;
/// assert!((x.hypot(y) - 1.0).abs() < 1e-15);
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve<const D: usize> {
    control_points: Vec<[f64; D]>,
    weights: Vec<f64>,
    knots: KnotVector,
}

impl<const D: usize> NurbsCurve<D> {
    /// Makes a curve from control points, weights and a knot vector whose degree
    /// and count it must match.
    ///
    /// # Errors
    /// [`Error::KnotCount`] if the knot vector was made for another number of
    /// control points; [`Error::WeightCount`], [`Error::Weight`],
    /// [`Error::WeightOutOfRange`] for a wrong number of weights or a weight
    /// that is not finite and positive or outside [`MIN_WEIGHT`](crate::MIN_WEIGHT) …
    /// [`MAX_WEIGHT`](crate::MAX_WEIGHT); [`Error::NotFinite`] for a non-finite
    /// coordinate and [`Error::OutOfRange`] for one of magnitude above
    /// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE); [`Error::Dimension`] unless
    /// `1 ≤ D ≤ 3`.
    pub fn try_new(
        control_points: Vec<[f64; D]>,
        weights: Vec<f64>,
        knots: KnotVector,
    ) -> Result<Self, Error> {
        let n = control_points.len();
        if knots.count() != n {
            return Err(Error::KnotCount {
                expected: n + knots.degree() + 1,
                found: knots.as_slice().len(),
            });
        }
        check_weights(&weights, n)?;
        let axes = Axis::first::<D>()?;
        for (i, p) in control_points.iter().enumerate() {
            for (&axis, &value) in axes.iter().zip(p) {
                if !value.is_finite() {
                    return Err(Error::NotFinite {
                        place: Place::new(i, axis),
                        what: "coordinate",
                        value,
                    });
                }
                if !within_magnitude(value) {
                    return Err(Error::OutOfRange {
                        place: Place::new(i, axis),
                        what: "coordinate",
                        value,
                        range: MAGNITUDE_RANGE,
                    });
                }
            }
        }
        Ok(NurbsCurve {
            control_points,
            weights,
            knots,
        })
    }

    /// Makes a curve with the default clamped uniform knot vector (docs/method.md §6).
    ///
    /// # Errors
    /// [`Error::TooFewControlPoints`] if there are fewer than `degree + 1`
    /// control points, and the errors of [`NurbsCurve::try_new`].
    pub fn try_clamped(
        degree: usize,
        control_points: Vec<[f64; D]>,
        weights: Vec<f64>,
    ) -> Result<Self, Error> {
        let knots = KnotVector::clamped_uniform(degree, control_points.len())?;
        Self::try_new(control_points, weights, knots)
    }

    /// A curve from parts that are already known to be valid and consistent.
    pub(crate) fn from_parts_unchecked(
        control_points: Vec<[f64; D]>,
        weights: Vec<f64>,
        knots: KnotVector,
    ) -> Self {
        debug_assert_eq!(control_points.len(), knots.count());
        debug_assert_eq!(weights.len(), knots.count());
        NurbsCurve {
            control_points,
            weights,
            knots,
        }
    }

    /// The degree `p`.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.knots.degree()
    }

    /// The order `k = p + 1`.
    #[must_use]
    pub fn order(&self) -> usize {
        self.degree() + 1
    }

    /// The control points.
    #[must_use]
    pub fn control_points(&self) -> &[[f64; D]] {
        &self.control_points
    }

    /// The weights.
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The knot vector.
    #[must_use]
    pub fn knots(&self) -> &KnotVector {
        &self.knots
    }

    /// The parameter domain `[U[p], U[n]]`.
    #[must_use]
    pub fn domain(&self) -> Domain {
        self.knots.domain()
    }

    /// The point `C(t)`.
    ///
    /// At an interior knot of full multiplicity the value from the right is
    /// returned; at the right end of the domain the last non-empty span is used.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside [`NurbsCurve::domain`].
    pub fn eval(&self, t: f64) -> Result<[f64; D], Error> {
        self.domain().check(t)?;
        Ok(self.eval_unchecked(t))
    }

    /// `C(t)` for `t` in the domain, without allocation up to order
    /// [`STACK_ORDER`].
    pub(crate) fn eval_unchecked(&self, t: f64) -> [f64; D] {
        let order = self.order();
        let mut stack = [0.0; STACK_ORDER];
        let mut heap = Vec::new();
        let r: &mut [f64] = if order <= STACK_ORDER {
            &mut stack[..order]
        } else {
            heap.resize(order, 0.0);
            &mut heap
        };
        let first = rational_basis_into(&self.knots, &self.weights, t, r);
        let mut out = [0.0; D];
        for (ri, p) in r.iter().zip(&self.control_points[first..]) {
            for (o, x) in out.iter_mut().zip(p) {
                *o += ri * x;
            }
        }
        out
    }

    /// The index of the first non-zero rational basis function at `t` and the
    /// `p + 1` values from there on; see [`rational_basis_span`].
    pub(crate) fn rational_basis_span(&self, t: f64) -> (usize, Vec<f64>) {
        rational_basis_span(&self.knots, &self.weights, t)
    }

    /// All `n` rational basis functions `Rᵢ(t)` (docs/method.md §6), zeros outside the span.
    /// They are non-negative and sum to 1.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let c = NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], vec![1.0, 2.0, 1.0])?;
    /// let r = c.rational_basis(0.5)?;
    /// // N = (1/4, 1/2, 1/4), wN = (1/4, 1, 1/4), Σ = 3/2.
    /// let expect = [1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0];
    /// assert!(r.iter().zip(expect).all(|(a, b)| (a - b).abs() < 1e-15));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn rational_basis(&self, t: f64) -> Result<Vec<f64>, Error> {
        self.domain().check(t)?;
        let (first, r) = self.rational_basis_span(t);
        let mut all = vec![0.0; self.control_points.len()];
        all[first..first + r.len()].copy_from_slice(&r);
        Ok(all)
    }

    /// `C(t)` at every parameter of `params`.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    pub fn sample(&self, params: &[f64]) -> Result<Vec<[f64; D]>, Error> {
        params.iter().map(|&t| self.eval(t)).collect()
    }
}

/// The index of the first non-zero rational basis function at `t` (in the
/// domain) and the `p + 1` values from there on:
///
/// ```text
/// Rⱼ(t) = wⱼ Nⱼ,ₚ(t) / Σᵣ wᵣ Nᵣ,ₚ(t)
/// ```
pub(crate) fn rational_basis_span(
    knots: &KnotVector,
    weights: &[f64],
    t: f64,
) -> (usize, Vec<f64>) {
    let mut r = vec![0.0; knots.degree() + 1];
    let first = rational_basis_into(knots, weights, t, &mut r);
    (first, r)
}

/// [`rational_basis_span`] into `out` (`p + 1` values); returns the index of
/// the first non-zero function.
fn rational_basis_into(knots: &KnotVector, weights: &[f64], t: f64, out: &mut [f64]) -> usize {
    let p = knots.degree();
    let span = knots.find_span(t);
    basis_functions(knots.as_slice(), p, span, t, out);
    let first = span - p;
    let mut denominator = 0.0;
    for (nj, w) in out.iter_mut().zip(&weights[first..]) {
        *nj *= w;
        denominator += *nj;
    }
    // Σ wᵣ Nᵣ is positive and finite: the Nᵣ are non-negative and sum to 1, so
    // some Nⱼ ≥ 1/(p + 1), and every weight lies in [MIN_WEIGHT, MAX_WEIGHT] =
    // [1e-150, 1e150], so the sum lies in [1e-150/(p + 1), 1e150·(p + 1)].
    for nj in out.iter_mut() {
        *nj /= denominator;
    }
    first
}

/// Checks that there are `n` weights, each in [`MIN_WEIGHT`], [`MAX_WEIGHT`]];
/// returns the first of [`weight_problems`].
pub(crate) fn check_weights(weights: &[f64], n: usize) -> Result<(), Error> {
    match weight_problems(weights, n).into_iter().next() {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// Every rule that `weights` break as the weights of a curve with `count`
/// control points (docs/method.md §6): one per point ([`Error::WeightCount`]), each of
/// the first `count` finite and positive ([`Error::Weight`]) and within
/// [[`MIN_WEIGHT`], [`MAX_WEIGHT`]] ([`Error::WeightOutOfRange`]); empty if none.
///
/// # Examples
/// ```
/// # use t2spline::nurbs::weight_problems;
/// let p = weight_problems(&[1.0, 0.0, 1e-200], 4);
/// let lines: Vec<String> = p.iter().map(ToString::to_string).collect();
/// assert_eq!(lines, [
///     "weights: expected 4 (one per control point), got 3",
///     "weights[1] = 0 must be finite and greater than 0",
///     "weights[2] = 1e-200 is outside [1e-150, 1e150]",
/// ]);
/// ```
#[must_use]
pub fn weight_problems(weights: &[f64], count: usize) -> Vec<Error> {
    let mut out = Vec::new();
    if weights.len() != count {
        out.push(Error::WeightCount {
            expected: count,
            found: weights.len(),
        });
    }
    // Beyond `count` weights there are no points to weigh: the count is the
    // problem, not each extra value.
    for (index, &value) in weights.iter().enumerate().take(count) {
        if !(value.is_finite() && value > 0.0) {
            out.push(Error::Weight { index, value });
        } else if !(MIN_WEIGHT..=MAX_WEIGHT).contains(&value) {
            out.push(Error::WeightOutOfRange { index, value });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn quarter_circle() -> NurbsCurve<2> {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        NurbsCurve::try_clamped(
            2,
            vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            vec![1.0, w, 1.0],
        )
        .unwrap()
    }

    #[test]
    fn quarter_circle_has_radius_one_everywhere() {
        let c = quarter_circle();
        for t in c.domain().uniform(1001).unwrap() {
            let [x, y] = c.eval(t).unwrap();
            assert_relative_eq!(x.hypot(y), 1.0, epsilon = 1e-15);
        }
        assert_eq!(c.eval(0.0).unwrap(), [1.0, 0.0]);
        assert_eq!(c.eval(1.0).unwrap(), [0.0, 1.0]);
    }

    #[test]
    fn equal_weights_give_the_bernstein_form() {
        // Degree 3, one span: C(t) = Σ B_i,3(t) P_i.
        let p = [[0.0, 0.0], [1.0, 3.0], [3.0, -1.0], [4.0, 2.0]];
        for w in [1.0, 2.5] {
            let c = NurbsCurve::try_clamped(3, p.to_vec(), vec![w; 4]).unwrap();
            for t in [0.0, 0.1, 0.5, 0.77, 1.0] {
                let s = 1.0 - t;
                let b = [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t];
                let expect: [f64; 2] =
                    std::array::from_fn(|d| (0..4).map(|i| b[i] * p[i][d]).sum());
                let got = c.eval(t).unwrap();
                assert_relative_eq!(got[0], expect[0], epsilon = 1e-14);
                assert_relative_eq!(got[1], expect[1], epsilon = 1e-14);
            }
        }
    }

    #[test]
    fn full_multiplicity_interior_knot_jumps_and_takes_the_right_value() {
        let u = KnotVector::try_new(vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0], 1, 4).unwrap();
        let c = NurbsCurve::try_new(
            vec![[0.0, 0.0], [1.0, 0.0], [5.0, 5.0], [6.0, 5.0]],
            vec![1.0; 4],
            u,
        )
        .unwrap();
        assert_eq!(c.eval(0.5).unwrap(), [5.0, 5.0]);
        let before = c.eval(0.5 - 1e-12).unwrap();
        assert!((before[0] - 1.0).abs() < 1e-10, "{before:?}");
        assert_eq!(c.eval(1.0).unwrap(), [6.0, 5.0]);
    }

    #[test]
    fn bad_parameters_and_weights_are_errors() {
        let c = quarter_circle();
        assert!(c.eval(f64::NAN).is_err());
        assert!(c.eval(-1e-300).is_err());
        assert!(matches!(
            NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, f64::NAN]),
            Err(Error::Weight { index: 1, .. })
        ));
    }
}
