//! Rational B-spline surfaces: the tensor product of docs/method.md §6 (docs/method.md §8).
//!
//! A [`NurbsSurface`] holds a net of `nu × nv` control points `Pᵢⱼ` (row `i`
//! along u, column `j` along v), one weight per point and one [`KnotVector`]
//! per [`Direction`]. Every rule of a curve (docs/method.md §6) holds in each direction:
//! clamped uniform knots by default, the domain `[U[p], U[nu]] × [V[q], V[nv]]`,
//! interior knots of full multiplicity (the value there is taken from the
//! right, at the end of a domain from the last non-empty span).
//!
//! | operation | method | source |
//! |---|---|---|
//! | point, rational basis | [`NurbsSurface::eval`], [`NurbsSurface::rational_basis`] | docs/method.md §8 |
//! | partial derivatives of any order, normal | [`NurbsSurface::derivatives`], [`NurbsSurface::normal`] | The NURBS Book A3.6, A4.4 |
//! | Gaussian, mean and principal curvatures, principal directions | [`NurbsSurface::curvature`] | do Carmo §3-3 |
//! | isoparametric curves | [`NurbsSurface::isocurve`] | §4.5 |
//! | knot insertion, refinement | [`NurbsSurface::insert_knot`], [`NurbsSurface::refine_knots`] | A5.1, A5.4 on stacked rows (as A5.3, A5.5) |
//! | degree elevation | [`NurbsSurface::elevate_degree`] | A5.9 on stacked rows (§5.5) |
//! | splitting, sub-rectangle | [`NurbsSurface::split_at`], [`NurbsSurface::segment`] | §5.3 |
//! | closest point | [`NurbsSurface::closest_point`] | §6.1, Eqs. 6.6–6.8 |
//! | bounding box | [`NurbsSurface::bounding_box`] | — |
//!
//! The operations in one direction are the curve algorithms of
//! `nurbs/knot_insertion.rs`, `degree_elevation.rs` and `split.rs` run on
//! rows that stack a whole line of the net (`operations.rs`): no algorithm
//! is written twice.

mod bounding_box;
pub(crate) mod closest_point;
pub use closest_point::ClosestSurfacePoint;
mod curvature;
pub use curvature::SurfaceCurvature;
pub(crate) mod derivatives;
pub(crate) mod operations;
pub(crate) mod patches;

use crate::error::{Error, Place};
use crate::fuzzy::Axis;
use crate::limits::{within_magnitude, MAGNITUDE_RANGE, MAX_WEIGHT, MIN_WEIGHT};
use crate::nurbs::basis::{basis_functions, STACK_ORDER};
use crate::nurbs::{Domain, KnotVector};
pub use crate::place::Direction;

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
    points: Vec<[f64; D]>,
    /// Row-major, as `points`.
    weights: Vec<f64>,
    /// `[U, V]`.
    knots: [KnotVector; 2],
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

/// Checks that `(u, v)` lies in the domain of the knot vectors `[U, V]`.
pub(crate) fn check_params(knots: &[KnotVector; 2], u: f64, v: f64) -> Result<(), Error> {
    for (direction, t) in Direction::BOTH.into_iter().zip([u, v]) {
        knots[direction.index()]
            .domain()
            .check(t)
            .map_err(|e| e.in_direction(direction))?;
    }
    Ok(())
}

/// The clamped uniform knot vectors of degrees `[p, q]` for a net of `shape`.
pub(crate) fn default_knots(
    degree: [usize; 2],
    shape: [usize; 2],
) -> Result<[KnotVector; 2], Error> {
    let make = |d: Direction| {
        KnotVector::clamped_uniform(degree[d.index()], shape[d.index()])
            .map_err(|e| e.in_direction(d))
    };
    Ok([make(Direction::U)?, make(Direction::V)?])
}

/// Validates knot values of one direction (`None`: the clamped uniform
/// default), naming the direction in the error.
pub(crate) fn knots_in(
    direction: Direction,
    values: Option<Vec<f64>>,
    degree: usize,
    count: usize,
) -> Result<KnotVector, Error> {
    match values {
        Some(values) => KnotVector::try_new(values, degree, count),
        None => KnotVector::clamped_uniform(degree, count),
    }
    .map_err(|e| e.in_direction(direction))
}

/// The shape `[rows, columns]` of a net given as rows, which must all have
/// the length of the first.
///
/// # Errors
/// [`Error::NetShape`] naming the first row of another length.
pub(crate) fn net_shape<T>(rows: &[Vec<T>], what: &'static str) -> Result<[usize; 2], Error> {
    let columns = rows.first().map_or(0, Vec::len);
    match rows.iter().position(|r| r.len() != columns) {
        Some(row) => Err(Error::NetShape {
            what,
            row,
            reference: "points[0]",
            expected: columns,
            found: rows[row].len(),
        }),
        None => Ok([rows.len(), columns]),
    }
}

/// The weights of a net of `shape`, row by row, each finite and within
/// [[`MIN_WEIGHT`], [`MAX_WEIGHT`]].
///
/// # Errors
/// [`Error::NetShape`] for a wrong number of rows or of entries in a row;
/// [`Error::NetWeight`] for the first bad weight.
pub(crate) fn net_weights(weights: &[Vec<f64>], shape: [usize; 2]) -> Result<Vec<f64>, Error> {
    if weights.len() != shape[0] {
        return Err(Error::NetShape {
            what: "weights",
            row: weights.len().min(shape[0]),
            reference: "points",
            expected: shape[0],
            found: weights.len(),
        });
    }
    if let Some(row) = weights.iter().position(|r| r.len() != shape[1]) {
        return Err(Error::NetShape {
            what: "weights",
            row,
            reference: "points",
            expected: shape[1],
            found: weights[row].len(),
        });
    }
    let flat: Vec<f64> = weights.concat();
    net_weights_flat(&flat, shape)?;
    Ok(flat)
}

/// Checks the weights of a net of `shape` given row by row in one list.
///
/// # Errors
/// [`Error::Length`] for a wrong number of weights; [`Error::NetWeight`] for
/// the first weight that is not finite and positive or outside
/// [[`MIN_WEIGHT`], [`MAX_WEIGHT`]].
pub(crate) fn net_weights_flat(weights: &[f64], shape: [usize; 2]) -> Result<(), Error> {
    if weights.len() != shape[0] * shape[1] {
        return Err(Error::Length {
            what: "weights (one per control point of the net)",
            expected: shape[0] * shape[1],
            found: weights.len(),
        });
    }
    let first = weights
        .chunks(shape[1].max(1))
        .enumerate()
        .find_map(|(row, w)| net_weight_problems(row, w).into_iter().next());
    first.map_or(Ok(()), Err)
}

/// Every weight of row `row` of a net that is not finite and positive or
/// lies outside [[`MIN_WEIGHT`], [`MAX_WEIGHT`]] ([`Error::NetWeight`]);
/// empty if none. The counterpart of
/// [`weight_problems`](crate::nurbs::weight_problems) for the rows of a
/// surface, for validators that list every problem.
///
/// # Examples
/// ```
/// # use t2spline::nurbs::net_weight_problems;
/// let p = net_weight_problems(2, &[1.0, 0.0, 1e-200]);
/// let lines: Vec<String> = p.iter().map(ToString::to_string).collect();
/// assert_eq!(lines, [
///     "weights[2][1] = 0 must be finite and greater than 0",
///     "weights[2][2] = 1e-200 is outside [1e-150, 1e150]",
/// ]);
/// ```
#[must_use]
pub fn net_weight_problems(row: usize, weights: &[f64]) -> Vec<Error> {
    weights
        .iter()
        .enumerate()
        .filter_map(|(column, &value)| {
            let rule = if !(value.is_finite() && value > 0.0) {
                "must be finite and greater than 0"
            } else if !(MIN_WEIGHT..=MAX_WEIGHT).contains(&value) {
                "is outside [1e-150, 1e150]"
            } else {
                return None;
            };
            Some(Error::NetWeight {
                row,
                column,
                value,
                rule,
            })
        })
        .collect()
}

/// The non-zero rational basis functions of a surface at `(u, v)`: the
/// `(p + 1)(q + 1)` values `Rᵢⱼ` for `i = first[0] …`, `j = first[1] …`,
/// row by row. Shared by every evaluator of a net (crisp and fuzzy).
#[derive(Clone, Debug)]
pub(crate) struct TensorBasis {
    first: [usize; 2],
    columns: usize,
    values: Vec<f64>,
}

impl TensorBasis {
    /// The rational basis at `(u, v)` in the domain (spans as
    /// [`KnotVector::find_span`]: from the right at an interior knot, the last
    /// non-empty span at the end).
    pub(crate) fn new(knots: &[KnotVector; 2], weights: &[f64], u: f64, v: f64) -> Self {
        let spans = [knots[0].find_span(u), knots[1].find_span(v)];
        Self::in_spans(knots, weights, spans, u, v)
    }

    /// The rational basis of the polynomial piece on the non-empty spans
    /// `[su, sv]` at `(u, v)` in (or on the border of) that span rectangle.
    pub(crate) fn in_spans(
        knots: &[KnotVector; 2],
        weights: &[f64],
        [su, sv]: [usize; 2],
        u: f64,
        v: f64,
    ) -> Self {
        let [ku, kv] = knots;
        let (p, q) = (ku.degree(), kv.degree());
        let nv = kv.count();
        let mut bu = vec![0.0; p + 1];
        let mut bv = vec![0.0; q + 1];
        basis_functions(ku.as_slice(), p, su, u, &mut bu);
        basis_functions(kv.as_slice(), q, sv, v, &mut bv);
        let first = [su - p, sv - q];
        let mut values = Vec::with_capacity((p + 1) * (q + 1));
        let mut denominator = 0.0;
        for (a, nu) in bu.iter().enumerate() {
            let row = &weights[(first[0] + a) * nv + first[1]..][..=q];
            for (mv, w) in bv.iter().zip(row) {
                let x = nu * mv * w;
                denominator += x;
                values.push(x);
            }
        }
        // As for curves: some NᵢMⱼ ≥ 1/((p + 1)(q + 1)) and every weight is at
        // least 1e-150, so the sum is positive and finite.
        for x in &mut values {
            *x /= denominator;
        }
        TensorBasis {
            first,
            columns: q + 1,
            values,
        }
    }

    /// Calls `f(k, Rᵢⱼ)` for every non-zero basis function, with `k = i·nv + j`
    /// the index of its control point in a net of `nv` columns.
    pub(crate) fn for_each(&self, nv: usize, mut f: impl FnMut(usize, f64)) {
        for (a, row) in self.values.chunks_exact(self.columns).enumerate() {
            let base = (self.first[0] + a) * nv + self.first[1];
            for (b, &r) in row.iter().enumerate() {
                f(base + b, r);
            }
        }
    }
}

#[cfg(test)]
mod curvature_tests;
#[cfg(test)]
mod extrema_tests;
#[cfg(test)]
mod tests;
