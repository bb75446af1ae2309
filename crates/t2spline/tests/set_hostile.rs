//! The set view on hostile geometry (docs/set.md, "Certified grades"):
//! one-sided, zero-spread, repeated-point, stationary, collinear and
//! crisp-along-a-direction curves and surfaces, at the scales 1, 1e-150 and
//! 1e149, graded against a dense brute-force scan of the fuzzy point at each
//! parameter. The certified grade is never below the scan's best and never
//! above it by more than the tolerance and the scan's own gap; every point
//! computed on the crisp curve or surface grades exactly 1, 1 and h.
//!
//! The reproductions of the defects this suite guards against are its fixed
//! cases: a one-sided job's crisp curve, the cylinder (z crisp along u),
//! and a spreadless line met by `membership` and `section` alike; and
//! grades, regions and sections agree point by point.

use proptest::prelude::*;
use t2spline::set::{Grades, GRADE_TOLERANCE, MEMBERSHIPS};
use t2spline::strategies::{cases, seeded_uniform};
use t2spline::{Alpha, FuzzyCurve, FuzzySurface, Membership, Nt2Number, Nt2Point};

/// The hostile families.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Family {
    /// Spreads on both sides of every number.
    Ordinary,
    /// Spreads to the right only: `upper: [c, c + s]`.
    OneSided,
    /// One coordinate without spread.
    ZeroSpread,
    /// Neighbouring control points equal.
    Repeated,
    /// Every control point the same: the curve stands still.
    Stationary,
    /// The crisp points on one line.
    Collinear,
    /// One coordinate crisp and constant (a curve) or crisp and a function
    /// of v only (a surface: the cylinder's z).
    CrispAlong,
}

const FAMILIES: [Family; 7] = [
    Family::Ordinary,
    Family::OneSided,
    Family::ZeroSpread,
    Family::Repeated,
    Family::Stationary,
    Family::Collinear,
    Family::CrispAlong,
];

/// The scales the suite runs at: the limits of docs/jobs.md are 1e150.
const SCALES: [f64; 3] = [1.0, 1e-150, 1e149];

/// Whether every coordinate of the family has spread on both sides, so that
/// the grade is continuous in the parameter and a scan's gap is bounded by
/// the change between neighbouring scan points.
fn continuous(family: Family) -> bool {
    matches!(
        family,
        Family::Ordinary | Family::Repeated | Family::Stationary | Family::Collinear
    )
}

/// A number around `c` with the family's spreads (drawn from `random`,
/// scaled by `scale`) and height `h`; `crisp` makes it without spread.
fn number(
    c: f64,
    family: Family,
    crisp: bool,
    h: f64,
    scale: f64,
    random: &mut impl FnMut() -> f64,
) -> Nt2Number {
    let mut side = |zero: bool| {
        let mut s = [0.0; 3];
        if !zero {
            for x in &mut s {
                *x = (0.05 + 0.5 * random()) * scale;
            }
            s.sort_by(f64::total_cmp);
        }
        s
    };
    let l = side(crisp || family == Family::OneSided);
    let r = side(crisp);
    Nt2Number::try_new(
        c,
        [c - l[2], c + r[2]],
        [c - l[1], c + r[1]],
        [c - l[0], c + r[0]],
        h,
    )
    .expect("nested spreads make a valid number")
}

/// The crisp coordinates of `count` control points of the family.
fn crisp_points<const D: usize>(
    family: Family,
    count: usize,
    scale: f64,
    random: &mut impl FnMut() -> f64,
) -> Vec<[f64; D]> {
    fn draw<const D: usize>(scale: f64, random: &mut impl FnMut() -> f64) -> [f64; D] {
        std::array::from_fn(|_| (2.0 * random() - 1.0) * scale)
    }
    match family {
        Family::Stationary => vec![draw(scale, random); count],
        Family::Collinear => {
            let (a, d): ([f64; D], [f64; D]) = (draw(scale, random), draw(scale, random));
            (0..count)
                .map(|_| {
                    let s = 2.0 * random() - 1.0;
                    std::array::from_fn(|c| a[c] + s * d[c] * 0.5)
                })
                .collect()
        }
        Family::Repeated => {
            let mut out: Vec<[f64; D]> = Vec::with_capacity(count);
            for i in 0..count {
                if i > 0 && random() < 0.5 {
                    out.push(out[i - 1]);
                } else {
                    out.push(draw(scale, random));
                }
            }
            out
        }
        _ => (0..count).map(|_| draw(scale, random)).collect(),
    }
}

/// A fuzzy curve of the family: degree `degree`, `count` points, one
/// common height `h`, weights in `[0.5, 3]`.
fn hostile_curve<const D: usize>(
    family: Family,
    degree: usize,
    count: usize,
    scale: f64,
    h: f64,
    seed: u64,
) -> FuzzyCurve<D> {
    let mut random = seeded_uniform(seed);
    let mut crisp = crisp_points::<D>(family, count, scale, &mut random);
    let special = D - 1;
    if family == Family::CrispAlong {
        let y = crisp[0][special];
        for p in &mut crisp {
            p[special] = y;
        }
    }
    let points = crisp
        .iter()
        .map(|c| {
            Nt2Point::new(std::array::from_fn(|k| {
                let no_spread =
                    k == special && matches!(family, Family::ZeroSpread | Family::CrispAlong);
                number(c[k], family, no_spread, h, scale, &mut random)
            }))
        })
        .collect();
    let weights = (0..count).map(|_| 0.5 + 2.5 * random()).collect();
    FuzzyCurve::try_new(degree, points, weights, None).expect("a valid curve")
}

/// A fuzzy surface of the family (3-D): degrees `degree`, a net of
/// `shape[0] × shape[1]` points, one height `h`.
fn hostile_surface(
    family: Family,
    degree: [usize; 2],
    shape: [usize; 2],
    scale: f64,
    h: f64,
    seed: u64,
) -> FuzzySurface<3> {
    let mut random = seeded_uniform(seed);
    let crisp = crisp_points::<3>(family, shape[0] * shape[1], scale, &mut random);
    let heights: Vec<f64> = (0..shape[1])
        .map(|_| (2.0 * random() - 1.0) * scale)
        .collect();
    let mut net = Vec::with_capacity(shape[0]);
    for i in 0..shape[0] {
        let mut row = Vec::with_capacity(shape[1]);
        for j in 0..shape[1] {
            let mut c = crisp[i * shape[1] + j];
            if family == Family::CrispAlong {
                // z a function of v only, crisp: the cylinder's wall.
                c[2] = heights[j];
            }
            row.push(Nt2Point::new(std::array::from_fn(|k| {
                let no_spread = k == 2 && matches!(family, Family::ZeroSpread | Family::CrispAlong);
                number(c[k], family, no_spread, h, scale, &mut random)
            })));
        }
        net.push(row);
    }
    let weights = (0..shape[0])
        .map(|_| (0..shape[1]).map(|_| 0.5 + 2.5 * random()).collect())
        .collect();
    FuzzySurface::try_new(degree, net, weights, [None, None]).expect("a valid surface")
}

/// The grades of `p` in the fuzzy point `at` (docs/method.md §1 triangles,
/// the min across coordinates).
fn point_grades<const D: usize>(at: &Nt2Point<D>, p: &[f64; D]) -> [f64; 3] {
    MEMBERSHIPS.map(|m| {
        at.coords()
            .iter()
            .zip(p)
            .map(|(x, &v)| x.membership(m, v))
            .fold(f64::INFINITY, f64::min)
    })
}

fn as_array(g: Grades) -> [f64; 3] {
    [g.upper, g.primary, g.lower]
}

/// The brute force: the best grade over a scan (in scan order), and the
/// largest change of a grade between neighbouring scan values.
fn best_and_gap(scan: &[[f64; 3]], neighbours: &[(usize, usize)]) -> ([f64; 3], [f64; 3]) {
    let mut best = [0.0_f64; 3];
    let mut gap = [0.0_f64; 3];
    for g in scan {
        for k in 0..3 {
            best[k] = best[k].max(g[k]);
        }
    }
    for &(a, b) in neighbours {
        for k in 0..3 {
            gap[k] = gap[k].max((scan[a][k] - scan[b][k]).abs());
        }
    }
    (best, gap)
}

/// A bound on the grades between neighbouring scan points: on the step from
/// `a` to `b` a triangle's value moves by at most `top·(|Δfoot| + |Δcrisp|)/w`
/// (its derivatives in the foot and the apex are at most `1/w` in size, `w`
/// the side's width), so the sup there is at most the larger end value plus
/// `2·top·δ/w`, `δ` the largest move of a foot or apex, `w` the narrowest
/// side at either end (no bound where a side has no width).
fn lipschitz_bound<const D: usize>(
    fuzzy: &[Nt2Point<D>],
    scan: &[[f64; 3]],
    pairs: &[(usize, usize)],
) -> [f64; 3] {
    let mut bound = [0.0_f64; 3];
    for &(a, b) in pairs {
        for (k, m) in MEMBERSHIPS.iter().enumerate() {
            let mut delta = 0.0_f64;
            let mut width = f64::INFINITY;
            let mut top = 1.0_f64;
            for c in 0..D {
                let mut ends = |i: usize| {
                    let x = fuzzy[i].coords()[c];
                    let feet = match m {
                        Membership::Upper => x.upper(),
                        Membership::Primary => x.primary(),
                        Membership::Lower => x.lower(),
                    };
                    if *m == Membership::Lower {
                        top = top.min(x.height().get());
                    }
                    [feet.left(), x.crisp(), feet.right()]
                };
                let (ea, eb) = (ends(a), ends(b));
                for e in [ea, eb] {
                    width = width.min(e[1] - e[0]).min(e[2] - e[1]);
                }
                for i in 0..3 {
                    delta = delta.max((ea[i] - eb[i]).abs());
                }
            }
            let step = if width > 0.0 {
                2.0 * top * delta / width
            } else {
                f64::INFINITY
            };
            bound[k] = bound[k].max(scan[a][k].max(scan[b][k]) + step);
        }
    }
    bound
}

/// Checks the certified grades `got` of `p` against the scan; where a grade
/// is above the scan's bound, `refine(k)` zooms in on the scan's best points
/// of function `k` (a region narrower than a scan cell hides between scan
/// points) and gives the best grade found there with its own gap.
/// `lipschitz` is the bound of [`lipschitz_bound`], the last word where a
/// sliver of a region hides from the scan and the zoom alike.
fn compare(
    got: [f64; 3],
    [best, gap, lipschitz]: [[f64; 3]; 3],
    continuous: bool,
    mut refine: impl FnMut(usize) -> (f64, f64),
    what: &str,
) -> Result<(), TestCaseError> {
    for k in 0..3 {
        // The scan's values are grades reached: the sup is never below them
        // (rounding of the two evaluations aside).
        prop_assert!(
            got[k] >= best[k] - 1e-9,
            "{what}, {:?}: {got:?} below the scan's {best:?}",
            MEMBERSHIPS[k]
        );
        if continuous && got[k] > best[k] + GRADE_TOLERANCE + 2.0 * gap[k] + 1e-9 {
            // The scan misses at most the change between neighbours, unless
            // the peak is narrower than a cell: look closer.
            let (fine, fine_gap) = refine(k);
            let allowed = fine.max(best[k]) + GRADE_TOLERANCE + 2.0 * fine_gap + 1e-9;
            let bounded = lipschitz[k] + GRADE_TOLERANCE + 1e-9;
            prop_assert!(
                got[k] <= allowed.max(bounded),
                "{what}, {:?}: {got:?} above the scan's {best:?} (gap {gap:?}), zoomed {fine} (gap {fine_gap}), bound {lipschitz:?}",
                MEMBERSHIPS[k]
            );
        }
    }
    Ok(())
}

/// The best grade of function `k` found by zooming in on the `starts`
/// (parameter pairs; a curve's second is 0) with cells of `cell`: twelve
/// rounds of a 21 × 21 grid (21 for a curve) over ±1 cell around the best
/// so far, each round's cells a third of the last (so that the search can
/// walk along a narrow ridge); with the largest change between neighbours of
/// the last round.
fn zoom(
    grade: impl Fn([f64; 2]) -> Option<[f64; 3]>,
    k: usize,
    starts: &[[f64; 2]],
    cell: [f64; 2],
    surface: bool,
) -> (f64, f64) {
    let mut best = 0.0_f64;
    let mut last_gap = 0.0_f64;
    for &start in starts {
        let (mut at, mut h) = (start, cell);
        for _ in 0..12 {
            let steps = 20usize;
            let mut round_best = (f64::NEG_INFINITY, at);
            let mut gap = 0.0_f64;
            let mut previous_row: Vec<f64> = Vec::new();
            for i in 0..=steps {
                let mut row: Vec<f64> = Vec::new();
                for j in 0..=(if surface { steps } else { 0 }) {
                    let q = [
                        at[0] + h[0] * (2.0 * i as f64 / steps as f64 - 1.0),
                        if surface {
                            at[1] + h[1] * (2.0 * j as f64 / steps as f64 - 1.0)
                        } else {
                            0.0
                        },
                    ];
                    let g = grade(q).map_or(0.0, |g| g[k]);
                    if g > round_best.0 {
                        round_best = (g, q);
                    }
                    if let Some(&left) = row.last() {
                        gap = gap.max((g - left).abs());
                    }
                    if let Some(&below) = previous_row.get(j) {
                        gap = gap.max((g - below).abs());
                    }
                    row.push(g);
                }
                previous_row = row;
            }
            best = best.max(round_best.0);
            at = round_best.1;
            last_gap = gap;
            h = [h[0] / 3.0, h[1] / 3.0];
        }
    }
    (best, last_gap)
}

/// The `count` scan indices with the largest grade of function `k`.
fn top_of(scan: &[[f64; 3]], k: usize, count: usize) -> Vec<usize> {
    let mut order: Vec<usize> = (0..scan.len()).collect();
    order.sort_by(|&a, &b| scan[b][k].total_cmp(&scan[a][k]));
    order.truncate(count);
    order
}

/// Curves: the crisp curve grades 1, 1, h exactly; points near the curve
/// grade within the scan's bounds.
fn check_curve(
    family: Family,
    degree: usize,
    extra: usize,
    scale: f64,
    h: f64,
    seed: u64,
) -> Result<(), TestCaseError> {
    let count = degree + 1 + extra;
    let curve = hostile_curve::<2>(family, degree, count, scale, h, seed);
    let crisp = curve.crisp_curve();
    let d = curve.domain();
    for j in 0..=16 {
        let t = d.lerp(f64::from(j) / 16.0);
        let p = crisp.eval(t).expect("in the domain");
        let g = curve.membership(&p).expect("finite");
        prop_assert!(
            g.upper == 1.0 && g.primary == 1.0 && g.lower == h,
            "{family:?}: crisp point at t = {t}: {g:?}"
        );
    }
    const STEPS: usize = 3000;
    let params: Vec<f64> = (0..=STEPS)
        .map(|j| d.lerp(j as f64 / STEPS as f64))
        .collect();
    let fuzzy: Vec<Nt2Point<2>> = params
        .iter()
        .map(|&t| curve.eval(t).expect("domain").expect("one height"))
        .collect();
    let neighbours: Vec<(usize, usize)> = (0..STEPS).map(|j| (j, j + 1)).collect();
    let pairs = neighbours.clone();
    let mut random = seeded_uniform(seed ^ 0x5eed);
    for _ in 0..6 {
        let at = &fuzzy[(random() * STEPS as f64) as usize];
        let p: [f64; 2] = near(at, &mut random);
        let got = as_array(curve.membership(&p).expect("finite"));
        let scan: Vec<[f64; 3]> = fuzzy.iter().map(|at| point_grades(at, &p)).collect();
        let (best, gap) = best_and_gap(&scan, &neighbours);
        let grade = |q: [f64; 2]| {
            (d.start..=d.end)
                .contains(&q[0])
                .then(|| point_grades(&curve.eval(q[0]).expect("domain").expect("one height"), &p))
        };
        let cell = [(d.end - d.start) / STEPS as f64, 0.0];
        let refine = |k: usize| {
            let starts: Vec<[f64; 2]> = top_of(&scan, k, 8)
                .iter()
                .map(|&j| [params[j], 0.0])
                .collect();
            zoom(grade, k, &starts, cell, false)
        };
        let lipschitz = lipschitz_bound(&fuzzy, &scan, &pairs);
        compare(
            got,
            [best, gap, lipschitz],
            continuous(family),
            refine,
            &format!("{family:?} at {p:?}"),
        )?;
    }
    Ok(())
}

/// Surfaces: the same on a grid of `(u, v)`.
fn check_surface(
    family: Family,
    degree: [usize; 2],
    extra: [usize; 2],
    scale: f64,
    h: f64,
    seed: u64,
) -> Result<(), TestCaseError> {
    let shape = [degree[0] + 1 + extra[0], degree[1] + 1 + extra[1]];
    let surface = hostile_surface(family, degree, shape, scale, h, seed);
    let crisp = surface.crisp_surface();
    let [du, dv] = [t2spline::Direction::U, t2spline::Direction::V].map(|dir| surface.domain(dir));
    for i in 0..=4 {
        for j in 0..=4 {
            let (u, v) = (du.lerp(f64::from(i) / 4.0), dv.lerp(f64::from(j) / 4.0));
            let p = crisp.eval(u, v).expect("in the domain");
            let g = surface.membership(&p).expect("finite");
            prop_assert!(
                g.upper == 1.0 && g.primary == 1.0 && g.lower == h,
                "{family:?}: crisp point at ({u}, {v}): {g:?}"
            );
        }
    }
    const STEPS: usize = 60;
    let mut fuzzy = Vec::with_capacity((STEPS + 1) * (STEPS + 1));
    for i in 0..=STEPS {
        for j in 0..=STEPS {
            let (u, v) = (
                du.lerp(i as f64 / STEPS as f64),
                dv.lerp(j as f64 / STEPS as f64),
            );
            fuzzy.push(surface.eval(u, v).expect("domain").expect("one height"));
        }
    }
    let mut neighbours = Vec::new();
    for i in 0..=STEPS {
        for j in 0..=STEPS {
            let a = i * (STEPS + 1) + j;
            if i < STEPS {
                neighbours.push((a, a + STEPS + 1));
            }
            if j < STEPS {
                neighbours.push((a, a + 1));
            }
        }
    }
    // The cells' diagonals too: a cell's inside is within its corners' moves.
    let mut pairs = neighbours.clone();
    for i in 0..STEPS {
        for j in 0..STEPS {
            let a = i * (STEPS + 1) + j;
            pairs.push((a, a + STEPS + 2));
            pairs.push((a + 1, a + STEPS + 1));
        }
    }
    let mut random = seeded_uniform(seed ^ 0x5eed);
    for _ in 0..3 {
        let at = &fuzzy[(random() * fuzzy.len() as f64) as usize];
        let p: [f64; 3] = near(at, &mut random);
        let got = as_array(surface.membership(&p).expect("finite"));
        let scan: Vec<[f64; 3]> = fuzzy.iter().map(|at| point_grades(at, &p)).collect();
        let (best, gap) = best_and_gap(&scan, &neighbours);
        let grade = |q: [f64; 2]| {
            ((du.start..=du.end).contains(&q[0]) && (dv.start..=dv.end).contains(&q[1])).then(
                || {
                    point_grades(
                        &surface
                            .eval(q[0], q[1])
                            .expect("domain")
                            .expect("one height"),
                        &p,
                    )
                },
            )
        };
        let cell = [
            (du.end - du.start) / STEPS as f64,
            (dv.end - dv.start) / STEPS as f64,
        ];
        let refine = |k: usize| {
            let starts: Vec<[f64; 2]> = top_of(&scan, k, 8)
                .iter()
                .map(|&a| {
                    [
                        du.lerp((a / (STEPS + 1)) as f64 / STEPS as f64),
                        dv.lerp((a % (STEPS + 1)) as f64 / STEPS as f64),
                    ]
                })
                .collect();
            zoom(grade, k, &starts, cell, true)
        };
        let lipschitz = lipschitz_bound(&fuzzy, &scan, &pairs);
        compare(
            got,
            [best, gap, lipschitz],
            continuous(family),
            refine,
            &format!("{family:?} at {p:?}"),
        )?;
    }
    Ok(())
}

fn family() -> impl Strategy<Value = Family> {
    (0..FAMILIES.len()).prop_map(|i| FAMILIES[i])
}

fn scale() -> impl Strategy<Value = f64> {
    (0..SCALES.len()).prop_map(|i| SCALES[i])
}

fn common_height() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(1.0),
        Just(0.6),
        (1u32..=100).prop_map(|k| f64::from(k) / 100.0)
    ]
}

proptest! {
    #![proptest_config(cases(24, 96))]

    #[test]
    fn hostile_curves_grade_as_the_scan(
        family in family(), degree in 0usize..=3, extra in 0usize..=3,
        scale in scale(), h in common_height(), seed in any::<u64>(),
    ) {
        check_curve(family, degree, extra, scale, h, seed)?;
    }
}

proptest! {
    #![proptest_config(cases(6, 24))]

    #[test]
    fn hostile_surfaces_grade_as_the_scan(
        family in family(), du in 0usize..=2, dv in 0usize..=2, eu in 0usize..=1, ev in 0usize..=1,
        scale in scale(), h in common_height(), seed in any::<u64>(),
    ) {
        check_surface(family, [du, dv], [eu, ev], scale, h, seed)?;
    }
}

/// Every family at every scale, once, whatever the random draws.
#[test]
fn every_family_at_every_scale() {
    for (i, &family) in FAMILIES.iter().enumerate() {
        for &scale in &SCALES {
            let seed = 1000 + i as u64;
            check_curve(family, 2, 2, scale, 0.6, seed)
                .unwrap_or_else(|e| panic!("curve {family:?} at {scale}: {e}"));
            check_surface(family, [2, 1], [0, 0], scale, 0.6, seed)
                .unwrap_or_else(|e| panic!("surface {family:?} at {scale}: {e}"));
        }
    }
}

fn n(c: f64, upper: [f64; 2], primary: [f64; 2], lower: [f64; 2], h: f64) -> Nt2Number {
    Nt2Number::try_new(c, upper, primary, lower, h).expect("a valid number")
}

/// The one-sided job (readings that can only over-read): every number
/// spreads to the right only, `upper: [c, c + 0.5]`. The search it replaced
/// graded 347 of 2 001 samples of the crisp curve below 1, 288 of them 0.
#[test]
fn a_one_sided_job_grades_its_whole_crisp_curve_one() {
    let one = |c: f64| n(c, [c, c + 0.5], [c, c + 0.3], [c, c + 0.1], 0.6);
    let crisp = [[1.0, 1.0], [2.0, 4.0], [5.0, 4.5], [6.0, 1.0]];
    let points = crisp
        .iter()
        .map(|&[x, y]| Nt2Point::new([one(x), one(y)]))
        .collect();
    let curve = FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 3.0, 1.0], None).expect("valid");
    let line = curve.crisp_curve();
    let samples: Vec<[f64; 2]> = (0..=2000)
        .map(|j| line.eval(f64::from(j) / 2000.0).expect("domain"))
        .collect();
    for (j, g) in curve
        .memberships(&samples)
        .expect("finite")
        .iter()
        .enumerate()
    {
        assert!(
            g.upper == 1.0 && g.primary == 1.0 && g.lower == 0.6,
            "sample {j}: {g:?}"
        );
    }
}

/// The shipped cylinder (`examples/fuzzy-cylinder.json`): x and y spread
/// radially, z crisp and a function of v only. The search it replaced gave
/// points of the crisp surface grade 0 and sections of fragments or nothing
/// where the answer is [0, 3].
fn cylinder() -> FuzzySurface<3> {
    let r = |c: f64| {
        n(
            c,
            [0.94 * c, 1.09 * c],
            [0.96 * c, 1.06 * c],
            [0.98 * c, 1.03 * c],
            0.6,
        )
    };
    let z = |c: f64| n(c, [c, c], [c, c], [c, c], 0.6);
    let row = |x: f64, y: f64| {
        vec![
            Nt2Point::new([r(x), r(y), z(0.0)]),
            Nt2Point::new([r(x), r(y), z(3.0)]),
        ]
    };
    let w = std::f64::consts::FRAC_1_SQRT_2;
    FuzzySurface::try_new(
        [2, 1],
        vec![row(2.5, 0.0), row(2.5, 2.5), row(0.0, 2.5)],
        vec![vec![1.0, 1.0], vec![w, w], vec![1.0, 1.0]],
        [None, None],
    )
    .expect("the cylinder is valid")
}

#[test]
fn the_cylinder_grades_its_crisp_surface_one_and_its_sections_are_whole() {
    let s = cylinder();
    let crisp = s.crisp_surface();
    let mut points = Vec::new();
    for i in 0..=20 {
        for j in 0..=20 {
            points.push(
                crisp
                    .eval(f64::from(i) / 20.0, f64::from(j) / 20.0)
                    .expect("domain"),
            );
        }
    }
    for (p, g) in points.iter().zip(s.memberships(&points).expect("finite")) {
        assert!(
            g.upper == 1.0 && g.primary == 1.0 && g.lower == 0.6,
            "{p:?}: {g:?}"
        );
    }
    let levels: Vec<Alpha> = [0.0, 0.5, 1.0]
        .iter()
        .map(|&a| Alpha::try_new(a).expect("level"))
        .collect();
    let slack = s.set_slack();
    let diagonal = 2.5 * std::f64::consts::FRAC_1_SQRT_2;
    for at in [[2.5, 0.0], [0.0, 2.5], [diagonal, diagonal]] {
        let started = std::time::Instant::now();
        let sections = s.sections(at, &levels).expect("finite");
        let took = started.elapsed();
        for level in &sections {
            for m in [Membership::Upper, Membership::Primary] {
                let got = level.get(m).expect("a cut at every level");
                assert_eq!(got.len(), 1, "{at:?} at {}: {got:?}", level.alpha);
                let [lo, hi] = got[0];
                assert!(
                    lo.abs() <= 2.0 * slack && (hi - 3.0).abs() <= 2.0 * slack,
                    "{at:?} at {}: {got:?}",
                    level.alpha
                );
            }
        }
        // Seconds, not the half minute of the search it replaced (debug build).
        assert!(took.as_secs_f64() < 20.0, "{at:?}: {took:?}");
    }
}

/// A line without spread in x (x = 0): `membership` and `section` meet it
/// within the one slack of the set view, and agree on every point.
#[test]
fn a_spreadless_line_is_met_alike_by_membership_and_section() {
    let x = |c: f64| n(c, [c, c], [c, c], [c, c], 0.5);
    let y = |c: f64| {
        n(
            c,
            [c - 1.0, c + 1.0],
            [c - 0.5, c + 0.5],
            [c - 0.25, c + 0.25],
            0.5,
        )
    };
    let points = vec![
        Nt2Point::new([x(0.0), y(0.0)]),
        Nt2Point::new([x(0.0), y(4.0)]),
    ];
    let line = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None).expect("valid");
    let slack = line.set_slack();
    assert!(slack > 0.0 && slack < 1e-10, "{slack}");
    for x0 in [
        0.0,
        0.5 * slack,
        -0.9 * slack,
        1.5 * slack,
        -3.0 * slack,
        1e-9,
    ] {
        let g = line.membership(&[x0, 2.0]).expect("finite");
        let section = line
            .section(x0, Membership::Upper, Alpha::ZERO, None)
            .expect("finite")
            .expect("a cut");
        let on = x0.abs() <= slack;
        assert_eq!(g.upper == 1.0, on, "x0 = {x0}: {g:?}");
        assert_eq!(!section.is_empty(), on, "x0 = {x0}: {section:?}");
        if on {
            // From −1 to 5, the line's reach at level 0.
            assert!(
                (section[0][0] + 1.0).abs() < 1e-5 && (section[0][1] - 5.0).abs() < 1e-5,
                "{section:?}"
            );
        }
    }
}

/// Grades, regions and sections share one definition of "on the set": on
/// the shipped example and on the one-sided job, a point whose grade
/// reaches a level is in that level's region and in the section through it,
/// and a point well inside a section's interval has a grade of that level.
#[test]
fn grades_regions_and_sections_agree() {
    let one = |c: f64| n(c, [c, c + 0.5], [c, c + 0.3], [c, c + 0.1], 0.6);
    let crisp = [[1.0, 1.0], [2.0, 4.0], [5.0, 4.5], [6.0, 1.0]];
    let points = crisp
        .iter()
        .map(|&[x, y]| Nt2Point::new([one(x), one(y)]))
        .collect();
    let one_sided = FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 3.0, 1.0], None).expect("valid");
    for curve in [t2spline::strategies::paper_example(), one_sided] {
        let tolerance = curve.default_tolerance();
        let mut random = seeded_uniform(11);
        let crisp_line = curve.crisp_curve();
        for level in [0.0, 0.3, 0.7] {
            let alpha = Alpha::try_new(level).expect("level");
            let region = curve
                .region(Membership::Upper, alpha, None)
                .expect("valid")
                .expect("a cut");
            for _ in 0..60 {
                // Near the crisp curve, where the levels change.
                let at = crisp_line.eval(random()).expect("domain");
                let p = [
                    at[0] + 0.8 * (random() - 0.5),
                    at[1] + 0.8 * (random() - 0.5),
                ];
                let g = curve.membership(&p).expect("finite").upper;
                let section = curve
                    .section(p[0], Membership::Upper, alpha, None)
                    .expect("finite")
                    .expect("a cut");
                let inside = |margin: f64| {
                    section
                        .iter()
                        .any(|iv| iv[0] + margin <= p[1] && p[1] <= iv[1] - margin)
                };
                if g >= level + GRADE_TOLERANCE && (level > 0.0 || g > 0.0) {
                    assert!(
                        region.contains(p),
                        "{p:?} at {level}: grade {g} but not in the region"
                    );
                    assert!(
                        inside(-tolerance),
                        "{p:?} at {level}: grade {g} but not in the section {section:?}"
                    );
                }
                if inside(tolerance) {
                    assert!(
                        g >= level - GRADE_TOLERANCE,
                        "{p:?} in the section {section:?} at {level}, grade {g}"
                    );
                }
            }
        }
    }
}

/// A point drawn around the fuzzy point `at`, up to 1.2 of its upper spread
/// away from the crisp value in each coordinate, on either side.
fn near<const D: usize>(at: &Nt2Point<D>, random: &mut impl FnMut() -> f64) -> [f64; D] {
    std::array::from_fn(|c| {
        let x = at.coords()[c];
        let f = 2.4 * random() - 1.2;
        let reach = if f < 0.0 {
            x.crisp() - x.upper().left()
        } else {
            x.upper().right() - x.crisp()
        };
        x.crisp() + f * reach
    })
}
