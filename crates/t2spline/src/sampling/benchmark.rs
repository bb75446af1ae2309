//! The curve that `t2spline bench` and the criterion benchmarks time, so that
//! both measure the same thing.

use crate::fuzzy::{Alpha, Nt2Number, Nt2Point};
use crate::pipeline::{FuzzyCurve, FuzzySurface};

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
    let points = POINTS
        .iter()
        .map(|p| Nt2Point::new(p.map(benchmark_number)))
        .collect();
    // Constant input, valid (the tests build it).
    #[allow(clippy::expect_used)]
    FuzzyCurve::try_new(3, points, WEIGHTS.to_vec(), None).expect("a valid curve")
}

/// The fuzzy number of every benchmark coordinate `c`: upper feet
/// `c − 0.3, c + 0.45`, primary feet `c − 0.2, c + 0.3`, lower feet
/// `c − 0.1, c + 0.15`, lower height 0.6.
#[allow(clippy::expect_used)] // the spreads are ordered, and `c` is a constant of this file
fn benchmark_number(c: f64) -> Nt2Number {
    Nt2Number::try_new(
        c,
        [c - 0.3, c + 0.45],
        [c - 0.2, c + 0.3],
        [c - 0.1, c + 0.15],
        0.6,
    )
    .expect("the spreads are ordered and finite")
}

/// The benchmark surface: bicubic, an 8 × 8 net with clamped uniform knots in
/// both directions, control points `Pᵢⱼ = (i, j, sin(1.1·i)·cos(0.7·j) + 0.1·i·j)`,
/// weights `wᵢⱼ = 0.5 + ((3i + 5j) mod 7)/4` (0.5 to 2), and every coordinate
/// the fuzzy number of [`benchmark_curve`] (unequal spreads, lower height 0.6).
///
/// # Examples
/// ```
/// let s = t2spline::sampling::benchmark_surface();
/// assert_eq!((s.degree(), s.shape()), ([3, 3], [8, 8]));
/// assert_eq!(s.weights()[1], 1.75);
/// ```
#[must_use]
pub fn benchmark_surface() -> FuzzySurface<3> {
    let n = 8;
    let points = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let (x, y) = (f64::from(i), f64::from(j));
                    let z = (1.1 * x).sin() * (0.7 * y).cos() + 0.1 * x * y;
                    Nt2Point::new([x, y, z].map(benchmark_number))
                })
                .collect()
        })
        .collect();
    let weights = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| 0.5 + f64::from((3 * i + 5 * j) % 7) / 4.0)
                .collect()
        })
        .collect();
    // Constant input, valid (the tests build it).
    #[allow(clippy::expect_used)]
    FuzzySurface::try_new([3, 3], points, weights, [None, None]).expect("a valid surface")
}

/// The 11 levels of the benchmark sweep: 0, 0.1, …, 1.
///
/// # Examples
/// ```
/// let a = t2spline::sampling::benchmark_levels();
/// assert_eq!((a.len(), a[3].get()), (11, 0.3));
/// ```
#[must_use]
#[allow(clippy::expect_used)] // k/10 lies in [0, 1] for k in 0..=10
pub fn benchmark_levels() -> Vec<Alpha> {
    (0..=10)
        .map(|k| Alpha::try_new(f64::from(k) / 10.0).expect("k/10 lies in [0, 1]"))
        .collect()
}
