//! Control points in homogeneous form: the common input of the knot algorithms.
//!
//! Knot insertion, refinement, splitting and degree elevation of a rational
//! curve are linear maps of the *homogeneous* control points `Pʷᵢ = (wᵢPᵢ, wᵢ)`
//! (The NURBS Book, §4.2). They are written once, for rows of any width: a crisp
//! curve in `D` dimensions has rows of width `D + 1`, a fuzzy curve stacks its
//! seven layers into rows of width `7D + 1`, so every layer sees the same
//! coefficients.

use crate::error::Error;
use crate::limits::{MAX_MAGNITUDE, MAX_WEIGHT, MIN_WEIGHT};
use crate::nurbs::{KnotVector, NurbsCurve};

/// One homogeneous control point `(w·x₁, …, w·x_m, w)`; the weight is last.
pub(crate) type Row = Vec<f64>;

/// `α·a + (1 − α)·b`, entry by entry.
///
/// With `α ∈ [0, 1]` each entry is monotone in `a` and in `b`, also in floating
/// point (products with a non-negative factor and sums are rounded monotonely),
/// which is what keeps the seven layers of a fuzzy curve ordered.
pub(crate) fn lerp(alpha: f64, a: &[f64], b: &[f64]) -> Row {
    blend(alpha, 1.0 - alpha, a, b)
}

/// `α·a + β·b`, entry by entry, for `α + β = 1` with both given.
///
/// Knot insertion computes `β` from the knots as `(U[i+p] − u)/(U[i+p] − U[i])`
/// rather than as `1 − α`: when `α` rounds to 1, `1 − α` is 0 while the true
/// `β` may be 1e-68, and multiplied by a weight of 1e98 that is no rounding
/// error but the whole new weight (found by fuzzing). Non-negative
/// `α` and `β` keep the monotonicity of [`lerp`].
pub(crate) fn blend(alpha: f64, beta: f64, a: &[f64], b: &[f64]) -> Row {
    a.iter().zip(b).map(|(x, y)| alpha * x + beta * y).collect()
}

/// The homogeneous rows of Cartesian points with weights.
pub(crate) fn to_rows<const D: usize>(points: &[[f64; D]], weights: &[f64]) -> Vec<Row> {
    points
        .iter()
        .zip(weights)
        .map(|(p, &w)| p.iter().map(|x| w * x).chain([w]).collect())
        .collect()
}

/// Cartesian points and weights from homogeneous rows of width `D + 1`.
pub(crate) fn from_rows<const D: usize>(rows: &[Row]) -> (Vec<[f64; D]>, Vec<f64>) {
    rows.iter()
        .map(|r| {
            let w = r[D];
            (std::array::from_fn(|d| r[d] / w), w)
        })
        .unzip()
}

impl<const D: usize> NurbsCurve<D> {
    /// The homogeneous control points.
    pub(crate) fn rows(&self) -> Vec<Row> {
        to_rows(self.control_points(), self.weights())
    }

    /// A curve from knots and homogeneous control points that `operation`
    /// derived from a valid curve.
    ///
    /// # Errors
    /// [`Error::IllConditioned`] if the rows are not a curve the library can
    /// work with (see [`check_rows`]).
    pub(crate) fn try_from_rows(
        knots: KnotVector,
        rows: &[Row],
        operation: &'static str,
    ) -> Result<Self, Error> {
        check_rows(rows, operation)?;
        let (points, weights) = from_rows(rows);
        Ok(NurbsCurve::from_parts_unchecked(points, weights, knots))
    }

    /// A curve from knots and homogeneous control points that an exact
    /// algorithm derived from a valid curve without amplifying anything
    /// (convex combinations only, as knot insertion at the ends does).
    pub(crate) fn from_rows(knots: KnotVector, rows: &[Row]) -> Self {
        let (points, weights) = from_rows(rows);
        debug_assert!(
            weights.iter().all(|w| w.is_finite() && *w > 0.0),
            "{weights:?}"
        );
        NurbsCurve::from_parts_unchecked(points, weights, knots)
    }
}

/// Checks the homogeneous rows an operation derived from a valid curve: every
/// weight within twice the input range `[MIN_WEIGHT, MAX_WEIGHT]`, every
/// Cartesian coordinate within twice `MAX_MAGNITUDE` (the slack lets rounding
/// through; the inputs' own limits leave room far beyond it), so that the
/// result is again a curve whose every evaluation and operation is finite.
/// Insertion and splitting only form convex combinations and never fail this;
/// degree elevation removes knots by dividing by knot differences and, with
/// knots closer than about 1e-10 of the domain or weights apart by many orders
/// of magnitude, can amplify rounding past it.
///
/// # Errors
/// [`Error::IllConditioned`] naming the first value outside.
pub(crate) fn check_rows(rows: &[Row], operation: &'static str) -> Result<(), Error> {
    let ill = |what, value, range| Error::IllConditioned {
        operation,
        what,
        value,
        range,
    };
    for row in rows {
        let Some((&w, coords)) = row.split_last() else {
            continue;
        };
        if !(MIN_WEIGHT / 2.0..=2.0 * MAX_WEIGHT).contains(&w) {
            return Err(ill("a weight", w, "[5e-151, 2e150]"));
        }
        for &x in coords {
            let value = x / w;
            if !(-2.0 * MAX_MAGNITUDE..=2.0 * MAX_MAGNITUDE).contains(&value) {
                return Err(ill("a coordinate", value, "[-2e150, 2e150]"));
            }
        }
    }
    Ok(())
}
