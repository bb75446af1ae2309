//! proptest generators of valid inputs, for this crate's property tests and for
//! downstream crates (feature `proptest`), and the size of long tests
//! ([`cases`], [`test_size`]: short by default, full under
//! `T2SPLINE_LONG_TESTS=1`).

use proptest::prelude::*;

use crate::{FuzzyCurve, FuzzySurface, KnotVector, Nt2Number, Nt2Point, NurbsCurve, NurbsSurface};

/// Whether the tests run at full size: `T2SPLINE_LONG_TESTS=1` (set by CI,
/// `.ci/run`). The one place the switch is read; see [`test_size`] and
/// [`cases`].
#[must_use]
pub fn long_tests() -> bool {
    std::env::var("T2SPLINE_LONG_TESTS").as_deref() == Ok("1")
}

/// The size of a long test (the number of random draws of a loop, the
/// points of a grid): `full` under `T2SPLINE_LONG_TESTS=1`, else `short`;
/// never 0.
///
/// # Examples
/// ```
/// # use t2spline::strategies::{long_tests, test_size};
/// let n = test_size(20, 1000);
/// assert_eq!(n, if long_tests() { 1000 } else { 20 });
/// ```
#[must_use]
pub fn test_size(short: usize, full: usize) -> usize {
    let n = if long_tests() { full } else { short };
    n.max(1)
}

/// The proptest configuration of a long property test: `full` cases under
/// `T2SPLINE_LONG_TESTS=1`, else `short`; proptest's own `PROPTEST_CASES`,
/// when set, overrides both. Never 0 cases; the inputs kept in a
/// `*.proptest-regressions` file are replayed first either way.
///
/// # Examples
/// ```
/// # use t2spline::strategies::cases;
/// assert!(cases(16, 300).cases >= 1);
/// ```
#[must_use]
pub fn cases(short: u32, full: u32) -> ProptestConfig {
    let n = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse::<u32>().ok())
        .unwrap_or(if long_tests() { full } else { short });
    ProptestConfig::with_cases(n.max(1))
}

/// A seeded source of numbers in `[0, 1)`, the same on every run and
/// machine, for fixtures and benchmarks that need more data than a property
/// test draws: a linear congruential generator (Knuth's MMIX constants), the
/// top 53 bits of each state.
///
/// # Examples
/// ```
/// # use t2spline::strategies::seeded_uniform;
/// let (mut a, mut b) = (seeded_uniform(7), seeded_uniform(7));
/// let x = a();
/// assert!((0.0..1.0).contains(&x) && x == b());
/// ```
pub fn seeded_uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The shipped example, `examples/paper-alg-1-1.json` (the paper's
/// Algorithm 1.1 data: four points, order 3, weights 1, 1, 3, 1, every lower
/// height 0.6), built with the core's API: the fixture of tests and
/// benchmarks that need the example without reading a file.
///
/// # Panics
/// Never: the example's numbers are valid (checked by the tests that use it).
#[must_use]
pub fn paper_example() -> FuzzyCurve<2> {
    let n = |c: f64, u: [f64; 2], p: [f64; 2], l: [f64; 2]| {
        Nt2Number::try_new(c, u, p, l, 0.6).expect("the example's numbers are valid")
    };
    let points = vec![
        Nt2Point::new([
            n(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3]),
            n(1.0, [0.2, 1.5], [0.5, 1.35], [0.75, 1.2]),
        ]),
        Nt2Point::new([
            n(2.0, [1.5, 2.8], [1.7, 2.5], [1.85, 2.25]),
            n(4.0, [3.3, 4.4], [3.5, 4.3], [3.8, 4.15]),
        ]),
        Nt2Point::new([
            n(5.0, [4.1, 5.6], [4.4, 5.45], [4.7, 5.2]),
            n(4.5, [4.0, 5.4], [4.2, 5.1], [4.35, 4.8]),
        ]),
        Nt2Point::new([
            n(6.0, [5.3, 6.9], [5.5, 6.6], [5.8, 6.3]),
            n(1.0, [0.4, 1.8], [0.6, 1.5], [0.8, 1.25]),
        ]),
    ];
    FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 3.0, 1.0], None)
        .expect("the example's curve is valid")
}

/// A lower height: often 1 or a round value, otherwise anything in `(0, 1]`.
pub fn height() -> impl Strategy<Value = f64> + Clone {
    prop_oneof![
        Just(1.0),
        Just(0.5),
        (1u32..=1000).prop_map(|k| f64::from(k) / 1000.0),
    ]
}

/// A spread that is sometimes exactly zero.
fn spread() -> impl Strategy<Value = f64> + Clone {
    prop_oneof![1 => Just(0.0), 4 => 0.0..3.0f64]
}

/// A valid number with crisp value in `[-10, 10]` and the given height.
pub fn number_with_height(h: f64) -> impl Strategy<Value = Nt2Number> + Clone {
    (
        -10.0..10.0f64,
        [spread(), spread(), spread()],
        [spread(), spread(), spread()],
    )
        .prop_map(move |(c, mut l, mut r)| {
            l.sort_by(f64::total_cmp);
            r.sort_by(f64::total_cmp);
            // l[0] ≤ l[1] ≤ l[2]: lower, primary, upper distances from crisp.
            Nt2Number::try_new(
                c,
                [c - l[2], c + r[2]],
                [c - l[1], c + r[1]],
                [c - l[0], c + r[0]],
                h,
            )
            .expect("ordered spreads make a valid number")
        })
}

/// A valid number with any height.
pub fn number() -> impl Strategy<Value = Nt2Number> + Clone {
    height().prop_flat_map(number_with_height)
}

/// A point whose numbers have any heights.
pub fn point<const D: usize>() -> impl Strategy<Value = Nt2Point<D>> + Clone {
    proptest::array::uniform(number()).prop_map(Nt2Point::new)
}

/// Knot values for degree `p` and `n` control points: clamped or not, with
/// repeated interior knots (up to full multiplicity) drawn from a coarse grid.
pub fn knots(degree: usize, count: usize) -> impl Strategy<Value = Vec<f64>> {
    let order = degree + 1;
    let interior = count - order;
    (
        any::<bool>(),
        proptest::collection::vec(
            prop_oneof![(1u32..10).prop_map(|k| f64::from(k) / 10.0), 0.01..0.99f64],
            interior,
        ),
        proptest::collection::vec(0.0..1.0f64, order * 2),
    )
        .prop_map(move |(clamped, mut inner, ends)| {
            inner.sort_by(f64::total_cmp);
            let mut u = Vec::with_capacity(count + order);
            if clamped {
                u.extend(std::iter::repeat_n(0.0, order));
                u.extend(&inner);
                u.extend(std::iter::repeat_n(1.0, order));
            } else {
                let mut lo: Vec<f64> = ends[..order].iter().map(|e| -e).collect();
                let mut hi: Vec<f64> = ends[order..].iter().map(|e| 1.0 + e).collect();
                lo.sort_by(f64::total_cmp);
                hi.sort_by(f64::total_cmp);
                u.extend(lo);
                u.extend(&inner);
                u.extend(hi);
            }
            u
        })
        .prop_filter("valid knot vector", move |u| {
            KnotVector::problems(u, degree, count).is_empty()
        })
}

/// Degree, control point count (`n ≥ k`), weights in `[0.2, 5]` and knots.
fn shape() -> impl Strategy<Value = (usize, usize, Vec<f64>, Vec<f64>)> {
    (1usize..=5, 0usize..=6).prop_flat_map(|(degree, extra)| {
        let count = degree + 1 + extra;
        (
            Just(degree),
            Just(count),
            proptest::collection::vec(0.2..5.0f64, count),
            knots(degree, count),
        )
    })
}

/// A crisp rational B-spline curve of degree 1–5 with coordinates in `[-10, 10]`.
pub fn curve<const D: usize>() -> impl Strategy<Value = NurbsCurve<D>> {
    shape().prop_flat_map(|(degree, count, weights, knots)| {
        proptest::collection::vec(proptest::array::uniform(-10.0..10.0f64), count).prop_map(
            move |points| {
                let u = KnotVector::try_new(knots.clone(), degree, count).expect("filtered");
                NurbsCurve::try_new(points, weights.clone(), u).expect("valid parts")
            },
        )
    })
}

/// A fuzzy curve whose numbers have independent heights.
pub fn fuzzy_curve<const D: usize>() -> impl Strategy<Value = FuzzyCurve<D>> {
    fuzzy_curve_from(point::<D>())
}

/// A fuzzy curve whose numbers all share one lower height.
pub fn fuzzy_curve_common_height<const D: usize>() -> impl Strategy<Value = FuzzyCurve<D>> {
    height().prop_flat_map(|h| {
        fuzzy_curve_from(proptest::array::uniform(number_with_height(h)).prop_map(Nt2Point::new))
    })
}

fn fuzzy_curve_from<const D: usize>(
    point: impl Strategy<Value = Nt2Point<D>> + Clone,
) -> impl Strategy<Value = FuzzyCurve<D>> {
    shape().prop_flat_map(move |(degree, count, weights, knots)| {
        proptest::collection::vec(point.clone(), count).prop_map(move |points| {
            FuzzyCurve::try_new(degree, points, weights.clone(), Some(knots.clone()))
                .expect("valid parts")
        })
    })
}

/// Knot values for degree `p` and `n` control points, every one drawn from the
/// grid `{0, 1/8, …, 1}`: repeated knots turn up anywhere, also at the ends of
/// the domain of an unclamped vector (`U[n−1] = U[n]`, where the right end must
/// fall back to the last non-empty span) and in the interior with full
/// multiplicity. Grid values are exact binary fractions.
pub fn grid_knots(degree: usize, count: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(0u32..=8, count + degree + 1)
        .prop_map(|mut k| {
            k.sort_unstable();
            k.into_iter()
                .map(|k| f64::from(k) / 8.0)
                .collect::<Vec<f64>>()
        })
        .prop_filter("valid knot vector", move |u| {
            KnotVector::problems(u, degree, count).is_empty()
        })
}

/// A crisp rational B-spline curve like [`curve`], with [`grid_knots`].
pub fn grid_curve<const D: usize>() -> impl Strategy<Value = NurbsCurve<D>> {
    (1usize..=5, 0usize..=6)
        .prop_flat_map(|(degree, extra)| {
            let count = degree + 1 + extra;
            (
                Just(degree),
                proptest::collection::vec(0.2..5.0f64, count),
                grid_knots(degree, count),
                proptest::collection::vec(proptest::array::uniform(-10.0..10.0f64), count),
            )
        })
        .prop_map(|(degree, weights, knots, points)| {
            let u = KnotVector::try_new(knots, degree, points.len()).expect("filtered");
            NurbsCurve::try_new(points, weights, u).expect("valid parts")
        })
}

/// Data points for fitting: a random walk with steps of length `[0.1, 3]` in
/// random directions, so that consecutive points never coincide and the ratio
/// of neighbouring chords stays below 30 (the systems stay well conditioned).
pub fn data_points<const D: usize>(
    count: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = Vec<[f64; D]>> {
    (
        proptest::array::uniform::<_, D>(-10.0..10.0f64),
        proptest::collection::vec(
            (0.1..3.0f64, proptest::array::uniform::<_, D>(-1.0..1.0f64)),
            count,
        ),
    )
        .prop_map(|(start, steps)| {
            let mut at = start;
            let mut out = Vec::with_capacity(steps.len());
            for (length, direction) in steps {
                let norm = direction.iter().map(|x| x * x).sum::<f64>().sqrt();
                let unit: [f64; D] = if norm > 1e-3 {
                    direction.map(|x| x / norm)
                } else {
                    std::array::from_fn(|d| if d == 0 { 1.0 } else { 0.0 })
                };
                out.push(at);
                at = std::array::from_fn(|d| at[d] + length * unit[d]);
            }
            out
        })
}

/// Fuzzy data points: crisp values from [`data_points`], spreads drawn per
/// point and coordinate independently (so they vary wildly from point to
/// point, which is what breaks independent fits), one common lower height.
pub fn fuzzy_data<const D: usize>(
    count: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = Vec<Nt2Point<D>>> {
    (height(), data_points::<D>(count)).prop_flat_map(|(h, crisp)| {
        let n = crisp.len();
        proptest::collection::vec(
            proptest::array::uniform::<_, D>((
                [spread(), spread(), spread()],
                [spread(), spread(), spread()],
            )),
            n,
        )
        .prop_map(move |spreads| {
            crisp
                .iter()
                .zip(&spreads)
                .map(|(c, s)| {
                    Nt2Point::new(std::array::from_fn(|d| {
                        let (mut l, mut r) = s[d];
                        l.sort_by(f64::total_cmp);
                        r.sort_by(f64::total_cmp);
                        let x = c[d];
                        Nt2Number::try_new(
                            x,
                            [x - l[2], x + r[2]],
                            [x - l[1], x + r[1]],
                            [x - l[0], x + r[0]],
                            h,
                        )
                        .expect("ordered spreads make a valid number")
                    }))
                })
                .collect()
        })
    })
}

/// How far degree elevation (The NURBS Book A5.9) may move a curve through
/// rounding, for tests: A5.9 removes knots by extrapolation, which amplifies
/// the rounding of homogeneous coordinates by up to the ratio of the domain to
/// the smallest gap between distinct knots, and dividing by the weight adds the
/// ratio of the largest to the smallest weight:
///
/// ```text
/// tolerance = 64 ε · scale · (w_max / w_min) · (b − a) / min gap
/// ```
/// `scale` is the size of the coordinates (their largest absolute value).
#[must_use]
pub fn elevation_tolerance(knots: &KnotVector, weights: &[f64], scale: f64) -> f64 {
    let d = knots.domain();
    let min_gap = knots
        .as_slice()
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|&g| g > 0.0)
        .fold(f64::INFINITY, f64::min);
    let (w_min, w_max) = weights
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), &w| {
            (lo.min(w), hi.max(w))
        });
    64.0 * f64::EPSILON * scale * (w_max / w_min) * (d.end - d.start) / min_gap
}

/// The shape of one direction of a surface: degree 1–4, `degree + 1` to
/// `degree + 4` control points, and knots as [`knots`] (clamped or not,
/// repeated up to full multiplicity).
fn direction_shape() -> impl Strategy<Value = (usize, usize, Vec<f64>)> {
    (1usize..=4, 0usize..=3).prop_flat_map(|(degree, extra)| {
        let count = degree + 1 + extra;
        (Just(degree), Just(count), knots(degree, count))
    })
}

/// Degrees, shape, weights in `[0.2, 5]` (row by row) and knots of a surface.
#[allow(clippy::type_complexity)]
fn surface_shape() -> impl Strategy<Value = ([usize; 2], [usize; 2], Vec<Vec<f64>>, [Vec<f64>; 2])>
{
    (direction_shape(), direction_shape()).prop_flat_map(|((p, nu, ku), (q, nv, kv))| {
        (
            Just([p, q]),
            Just([nu, nv]),
            proptest::collection::vec(proptest::collection::vec(0.2..5.0f64, nv), nu),
            Just([ku, kv]),
        )
    })
}

/// A crisp rational B-spline surface of degrees 1–4 in each direction with
/// coordinates in `[-10, 10]`.
pub fn surface<const D: usize>() -> impl Strategy<Value = NurbsSurface<D>> {
    surface_shape().prop_flat_map(|(degree, [nu, nv], weights, [ku, kv])| {
        proptest::collection::vec(
            proptest::collection::vec(proptest::array::uniform(-10.0..10.0f64), nv),
            nu,
        )
        .prop_map(move |points| {
            let knots = [
                KnotVector::try_new(ku.clone(), degree[0], nu).expect("filtered"),
                KnotVector::try_new(kv.clone(), degree[1], nv).expect("filtered"),
            ];
            NurbsSurface::try_new(points, weights.clone(), knots).expect("valid parts")
        })
    })
}

/// A fuzzy surface whose numbers have independent heights.
pub fn fuzzy_surface<const D: usize>() -> impl Strategy<Value = FuzzySurface<D>> {
    fuzzy_surface_from(point::<D>())
}

/// A fuzzy surface whose numbers all share one lower height.
pub fn fuzzy_surface_common_height<const D: usize>() -> impl Strategy<Value = FuzzySurface<D>> {
    height().prop_flat_map(|h| {
        fuzzy_surface_from(proptest::array::uniform(number_with_height(h)).prop_map(Nt2Point::new))
    })
}

fn fuzzy_surface_from<const D: usize>(
    point: impl Strategy<Value = Nt2Point<D>> + Clone,
) -> impl Strategy<Value = FuzzySurface<D>> {
    surface_shape().prop_flat_map(move |(degree, [nu, nv], weights, [ku, kv])| {
        proptest::collection::vec(proptest::collection::vec(point.clone(), nv), nu).prop_map(
            move |points| {
                FuzzySurface::try_new(
                    degree,
                    points,
                    weights.clone(),
                    [Some(ku.clone()), Some(kv.clone())],
                )
                .expect("valid parts")
            },
        )
    })
}
