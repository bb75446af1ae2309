//! The rational B-spline surface: its net, weights and knots, checked, and
//! its evaluation (docs/method.md §8).

use super::net_rules::{check_params, default_knots, net_shape, net_weights};
use super::tensor_basis::TensorBasis;
use crate::error::{Error, Place};
use crate::fuzzy::Axis;
use crate::limits::{within_magnitude, MAGNITUDE_RANGE};
use crate::nurbs::basis::{basis_functions, STACK_ORDER};
use crate::nurbs::{Domain, KnotVector};
use crate::place::Direction;

/// A rational B-spline surface in `D` dimensions (docs/method.md §8), the tensor
/// product of two rational B-spline curves:
///
/// ```text
/// S(u, v) = Σᵢ Σⱼ wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v) Pᵢⱼ / Σᵢ Σⱼ wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v),   (u, v) ∈ [U[p], U[nu]] × [V[q], V[nv]]
/// ```
/// with `nu ≥ p + 1` rows and `nv ≥ q + 1` columns of control points `Pᵢⱼ`,
/// weights `wᵢⱼ > 0` and a validated [`KnotVector`] per direction. Equal
/// weights give the non-rational tensor-product B-spline.
///
/// # Examples
/// A quarter cylinder of radius 1 about the z axis: the quarter circle as a
/// rational quadratic in u (weights 1, √2/2, 1), a straight line in v.
/// ```
/// # use t2spline::NurbsSurface;
/// let w = std::f64::consts::FRAC_1_SQRT_2;
/// let net = vec![
///     vec![[1.0, 0.0, 0.0], [1.0, 0.0, 2.0]],
///     vec![[1.0, 1.0, 0.0], [1.0, 1.0, 2.0]],
///     vec![[0.0, 1.0, 0.0], [0.0, 1.0, 2.0]],
/// ];
/// let s = NurbsSurface::try_clamped([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]])?;
/// let [x, y, z] = s.eval(0.3, 0.25)?;
/// assert!((x.hypot(y) - 1.0).abs() < 1e-15 && (z - 0.5).abs() < 1e-15);
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsSurface<const D: usize> {
    /// Row-major: `points[i·nv + j]` is `Pᵢⱼ`.
    pub(super) points: Vec<[f64; D]>,
    /// Row-major, as `points`.
    pub(super) weights: Vec<f64>,
    /// `[U, V]`.
    pub(super) knots: [KnotVector; 2],
}

impl<const D: usize> NurbsSurface<D> {
    /// Makes a surface from a net of control points (`points[i][j]`, `i` along
    /// u), a net of weights of the same shape, and the knot vectors `[U, V]`,
    /// whose degrees and counts it must match.
    ///
    /// # Errors
    /// [`Error::NetShape`] if the rows of `points` or `weights` differ in
    /// length or `weights` has another shape than `points`;
    /// [`Error::InDirection`] wrapping [`Error::KnotCount`] if a knot vector
    /// was made for another number of control points in its direction;
    /// [`Error::NetWeight`] for a weight that is not finite and positive or
    /// outside [`MIN_WEIGHT`](crate::MIN_WEIGHT) … [`MAX_WEIGHT`](crate::MAX_WEIGHT);
    /// [`Error::NotFinite`] / [`Error::OutOfRange`] for a coordinate that is
    /// not finite or of magnitude above [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE)
    /// (the place is `points[i][j].x`); [`Error::Dimension`] unless
    /// `1 ≤ D ≤ 3`.
    pub fn try_new(
        points: Vec<Vec<[f64; D]>>,
        weights: Vec<Vec<f64>>,
        knots: [KnotVector; 2],
    ) -> Result<Self, Error> {
        let shape = net_shape(&points, "points")?;
        for direction in Direction::BOTH {
            let k = &knots[direction.index()];
            let n = shape[direction.index()];
            if k.count() != n {
                return Err(Error::KnotCount {
                    expected: n + k.degree() + 1,
                    found: k.as_slice().len(),
                }
                .in_direction(direction));
            }
        }
        let weights = net_weights(&weights, shape)?;
        let points: Vec<[f64; D]> = points.into_iter().flatten().collect();
        let axes = Axis::first::<D>()?;
        for (index, p) in points.iter().enumerate() {
            let place = |axis| Place::in_net(index / shape[1], index % shape[1], axis);
            for (&axis, &value) in axes.iter().zip(p) {
                if !value.is_finite() {
                    return Err(Error::NotFinite {
                        place: place(axis),
                        what: "coordinate",
                        value,
                    });
                }
                if !within_magnitude(value) {
                    return Err(Error::OutOfRange {
                        place: place(axis),
                        what: "coordinate",
                        value,
                        range: MAGNITUDE_RANGE,
                    });
                }
            }
        }
        Ok(NurbsSurface {
            points,
            weights,
            knots,
        })
    }

    /// Makes a surface of degrees `[p, q]` with the default clamped uniform
    /// knot vectors in both directions (docs/method.md §6, §8).
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::TooFewControlPoints`] if there
    /// are fewer than `p + 1` rows or `q + 1` columns, and the errors of
    /// [`NurbsSurface::try_new`].
    pub fn try_clamped(
        degree: [usize; 2],
        points: Vec<Vec<[f64; D]>>,
        weights: Vec<Vec<f64>>,
    ) -> Result<Self, Error> {
        let shape = net_shape(&points, "points")?;
        let knots = default_knots(degree, shape)?;
        Self::try_new(points, weights, knots)
    }

    /// A surface from parts that are already known to be valid and consistent.
    pub(crate) fn from_parts_unchecked(
        points: Vec<[f64; D]>,
        weights: Vec<f64>,
        knots: [KnotVector; 2],
    ) -> Self {
        debug_assert_eq!(points.len(), knots[0].count() * knots[1].count());
        debug_assert_eq!(weights.len(), points.len());
        NurbsSurface {
            points,
            weights,
            knots,
        }
    }

    /// The degrees `[p, q]`.
    #[must_use]
    pub fn degree(&self) -> [usize; 2] {
        self.knots.each_ref().map(KnotVector::degree)
    }

    /// The orders `[p + 1, q + 1]`.
    #[must_use]
    pub fn order(&self) -> [usize; 2] {
        self.degree().map(|p| p + 1)
    }

    /// The shape of the net `[nu, nv]`: rows along u, columns along v.
    #[must_use]
    pub fn shape(&self) -> [usize; 2] {
        self.knots.each_ref().map(KnotVector::count)
    }

    /// The control points, row by row (`control_points()[i·nv + j]` is `Pᵢⱼ`).
    #[must_use]
    pub fn control_points(&self) -> &[[f64; D]] {
        &self.points
    }

    /// The control point `Pᵢⱼ`.
    ///
    /// # Errors
    /// [`Error::Index`] naming the `row` or `column` if `i ≥ nu` or `j ≥ nv`.
    pub fn control_point(&self, i: usize, j: usize) -> Result<[f64; D], Error> {
        let [nu, nv] = self.shape();
        let (i, j) = (
            Error::check_index("row", i, nu)?,
            Error::check_index("column", j, nv)?,
        );
        // `i·nv + j < nu·nv`, the length of the validated net.
        self.points.get(i * nv + j).copied().ok_or(Error::Index {
            what: "control point",
            index: i * nv + j,
            count: self.points.len(),
        })
    }

    /// The weights, row by row as [`NurbsSurface::control_points`].
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The knot vector of one direction.
    #[must_use]
    pub fn knots(&self, direction: Direction) -> &KnotVector {
        &self.knots[direction.index()]
    }

    /// The parameter domain of one direction.
    #[must_use]
    pub fn domain(&self, direction: Direction) -> Domain {
        self.knots(direction).domain()
    }

    /// Checks that `(u, v)` lies in the domain.
    pub(crate) fn check(&self, u: f64, v: f64) -> Result<(), Error> {
        check_params(&self.knots, u, v)
    }

    /// The point `S(u, v)`.
    ///
    /// At an interior knot of full multiplicity the value from the right (in
    /// that direction) is returned; at the end of a domain the last non-empty
    /// span is used.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `u` or `v` is
    /// NaN or outside its domain.
    pub fn eval(&self, u: f64, v: f64) -> Result<[f64; D], Error> {
        self.check(u, v)?;
        Ok(self.eval_unchecked(u, v))
    }

    /// `S(u, v)` for `(u, v)` in the domain.
    pub(crate) fn eval_unchecked(&self, u: f64, v: f64) -> [f64; D] {
        self.combine(&TensorBasis::new(&self.knots, &self.weights, u, v))
    }

    /// The polynomial piece of the non-empty span rectangle `spans` at
    /// `(u, v)` in its closure: on its right or upper border this is the
    /// one-sided limit from inside, which differs from [`NurbsSurface::eval`]
    /// only at a knot of full multiplicity.
    ///
    /// Up to order [`STACK_ORDER`] in each direction it allocates nothing
    /// (the distance of docs/method.md §8 calls it thousands of times per span
    /// rectangle); it forms the same products and quotients as
    /// [`TensorBasis`], so the results are the same to the bit.
    pub(crate) fn eval_in_spans(&self, spans: [usize; 2], u: f64, v: f64) -> [f64; D] {
        let [p, q] = self.degree();
        if p >= STACK_ORDER || q >= STACK_ORDER {
            return self.combine(&TensorBasis::in_spans(
                &self.knots,
                &self.weights,
                spans,
                u,
                v,
            ));
        }
        let [su, sv] = spans;
        let mut bu = [0.0; STACK_ORDER];
        let mut bv = [0.0; STACK_ORDER];
        let (bu, bv) = (&mut bu[..=p], &mut bv[..=q]);
        basis_functions(self.knots[0].as_slice(), p, su, u, bu);
        basis_functions(self.knots[1].as_slice(), q, sv, v, bv);
        let nv = self.shape()[1];
        // The row of weights and of points each basis row acts on.
        let rows = |a: usize| (su - p + a) * nv + sv - q..(su - p + a) * nv + sv + 1;
        let mut denominator = 0.0;
        for (a, nu) in bu.iter().enumerate() {
            for (mv, w) in bv.iter().zip(&self.weights[rows(a)]) {
                denominator += nu * mv * w;
            }
        }
        let mut out = [0.0; D];
        for (a, nu) in bu.iter().enumerate() {
            let (weights, points) = (&self.weights[rows(a)], &self.points[rows(a)]);
            for ((mv, w), point) in bv.iter().zip(weights).zip(points) {
                let r = nu * mv * w / denominator;
                for (o, x) in out.iter_mut().zip(point) {
                    *o += r * x;
                }
            }
        }
        out
    }

    /// `Σ Rᵢⱼ Pᵢⱼ` for a basis of this surface.
    fn combine(&self, basis: &TensorBasis) -> [f64; D] {
        let mut out = [0.0; D];
        basis.for_each(self.shape()[1], |k, r| {
            for (o, x) in out.iter_mut().zip(&self.points[k]) {
                *o += r * x;
            }
        });
        out
    }

    /// All `nu × nv` rational basis functions `Rᵢⱼ(u, v)` (docs/method.md §8), zeros
    /// outside the spans; `out[i][j]` belongs to `Pᵢⱼ`. They are non-negative
    /// and sum to 1.
    ///
    /// ```text
    /// Rᵢⱼ(u, v) = wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v) / Σₖ Σₗ wₖₗ Nₖ,ₚ(u) Mₗ,q(v)
    /// ```
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `u` or `v` is
    /// NaN or outside its domain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsSurface;
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0, 1.0], vec![1.0, 2.0]])?;
    /// let r = s.rational_basis(0.5, 0.5)?;
    /// // wN M = (1, 1, 1, 2)/4, Σ = 5/4.
    /// assert_eq!(r, vec![vec![0.2, 0.2], vec![0.2, 0.4]]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn rational_basis(&self, u: f64, v: f64) -> Result<Vec<Vec<f64>>, Error> {
        self.check(u, v)?;
        let [nu, nv] = self.shape();
        let mut out = vec![vec![0.0; nv]; nu];
        TensorBasis::new(&self.knots, &self.weights, u, v)
            .for_each(nv, |k, r| out[k / nv][k % nv] = r);
        Ok(out)
    }
}
