//! Points of a surface result as the 3-D view reads them, and the distances
//! between two of their lists.

use t2spline::job::Points;

use super::camera::Xyz;

/// Points of a surface result (3-D) as `[x, y, z]`.
#[must_use]
pub fn xyz(points: &Points) -> Vec<Xyz> {
    let c = |k: usize| points.coord(k);
    (0..points.len())
        .map(|i| std::array::from_fn(|k| c(k).get(i).copied().unwrap_or(0.0)))
        .collect()
}

/// `‖a − b‖` at every point of two lists of points (NaN where a point is
/// missing).
#[must_use]
pub fn distances(a: &Points, b: &Points) -> Vec<f64> {
    (0..a.len())
        .map(|i| a.distance_at(b, i).unwrap_or(f64::NAN))
        .collect()
}
