//! The curve that `t2spline bench` and the criterion benchmarks time, so that
//! both measure the same thing.

use crate::fuzzy::{Alpha, Nt2Number, Nt2Point};
use crate::pipeline::FuzzyCurve;

/// The benchmark curve: degree 3, ten control points
/// (0,0), (1,2), (2,−1), (3,3), (4,0), (5,2.5), (6,−2), (7,1), (8,3), (9,0),
/// weights 1, 0.5, 2, 1, 3, 0.7, 1, 1.5, 0.8, 1, clamped uniform knots; every
/// coordinate `c` is the fuzzy number with upper feet `c − 0.3, c + 0.45`,
/// primary feet `c − 0.2, c + 0.3`, lower feet `c − 0.1, c + 0.15` and lower
/// height 0.6 (unequal spreads, so the stages move the curve).
///
/// # Examples
/// ```
/// let c = t2spline::sampling::benchmark_curve();
/// assert_eq!((c.degree(), c.points().len()), (3, 10));
/// assert_eq!(c.points()[5].crisp(), [5.0, 2.5]);
/// ```
#[must_use]
pub fn benchmark_curve() -> FuzzyCurve<2> {
    const POINTS: [[f64; 2]; 10] = [
        [0.0, 0.0],
        [1.0, 2.0],
        [2.0, -1.0],
        [3.0, 3.0],
        [4.0, 0.0],
        [5.0, 2.5],
        [6.0, -2.0],
        [7.0, 1.0],
        [8.0, 3.0],
        [9.0, 0.0],
    ];
    const WEIGHTS: [f64; 10] = [1.0, 0.5, 2.0, 1.0, 3.0, 0.7, 1.0, 1.5, 0.8, 1.0];
    let number = |c: f64| {
        Nt2Number::try_new(
            c,
            [c - 0.3, c + 0.45],
            [c - 0.2, c + 0.3],
            [c - 0.1, c + 0.15],
            0.6,
        )
        .expect("the spreads are ordered and finite")
    };
    let points = POINTS
        .iter()
        .map(|p| Nt2Point::new(p.map(number)))
        .collect();
    FuzzyCurve::try_new(3, points, WEIGHTS.to_vec(), None).expect("a valid curve")
}

/// The 11 levels of the benchmark sweep: 0, 0.1, …, 1.
///
/// # Examples
/// ```
/// let a = t2spline::sampling::benchmark_levels();
/// assert_eq!((a.len(), a[3].get()), (11, 0.3));
/// ```
#[must_use]
pub fn benchmark_levels() -> Vec<Alpha> {
    (0..=10)
        .map(|k| Alpha::try_new(f64::from(k) / 10.0).expect("k/10 lies in [0, 1]"))
        .collect()
}
