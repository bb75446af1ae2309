//! Control points in homogeneous form: the common input of the knot algorithms.
//!
//! Knot insertion, refinement, splitting and degree elevation of a rational
//! curve are linear maps of the *homogeneous* control points `Pʷᵢ = (wᵢPᵢ, wᵢ)`
//! (The NURBS Book, §4.2). They are written once, for rows of any width: a crisp
//! curve in `D` dimensions has rows of width `D + 1`, a fuzzy curve stacks its
//! seven layers into rows of width `7D + 1`, so every layer sees the same
//! coefficients.

use crate::nurbs::{KnotVector, NurbsCurve};

/// One homogeneous control point `(w·x₁, …, w·x_m, w)`; the weight is last.
pub(crate) type Row = Vec<f64>;

/// `α·a + (1 − α)·b`, entry by entry.
///
/// With `α ∈ [0, 1]` each entry is monotone in `a` and in `b`, also in floating
/// point (products with a non-negative factor and sums are rounded monotonely),
/// which is what keeps the seven layers of a fuzzy curve ordered.
pub(crate) fn lerp(alpha: f64, a: &[f64], b: &[f64]) -> Row {
    let beta = 1.0 - alpha;
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

    /// A curve from knots and homogeneous control points that an exact
    /// algorithm derived from a valid curve.
    pub(crate) fn from_rows(knots: KnotVector, rows: &[Row]) -> Self {
        let (points, weights) = from_rows(rows);
        debug_assert!(
            weights.iter().all(|w| w.is_finite() && *w > 0.0),
            "{weights:?}"
        );
        NurbsCurve::from_parts_unchecked(points, weights, knots)
    }
}
