//! Extreme numerics: weights from 1e-12 to 1e12 (and the limits
//! 1e-150 and 1e150), coordinates from 1e-300 to the limit 1e150, interior knots of full
//! multiplicity (a curve that jumps), repeated control points, zero-width
//! spreads, h = 1, alpha exactly 0, h and 1, and parameters on every knot and at
//! both ends.
//!
//! The reference is exact rational arithmetic (`num-rational` over `num-bigint`):
//! every `f64` input is a rational number, so the Cox–de Boor definition, the
//! rational curve, the alpha-cut, type reduction and defuzzification of docs/method.md
//! §2–§6 can be computed with no rounding at all and compared with the library.
//! The reference shares no code with the library: it follows the recursive
//! definition (The NURBS Book, Eq. 2.5), not the triangular algorithm A2.2, and
//! divides exactly where the library rounds.
//!
//! Errors are measured against the scale of the inputs involved (the largest
//! magnitude of the control values), since a curve value near 0 can be the sum
//! of values near 1e150.

use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};
use proptest::prelude::*;
use t2spline::{
    strategies, Alpha, FuzzyCurve, Layer, Nt2Number, Nt2Point, NurbsCurve, Side, MAX_MAGNITUDE,
    MAX_WEIGHT, MIN_WEIGHT,
};

type Q = BigRational;

/// The exact rational value of a finite `f64`.
fn q(x: f64) -> Q {
    Q::from_float(x).unwrap_or_else(|| panic!("{x} is not finite"))
}

/// Exact evaluation, written from the definitions and independent of the library.
mod exact {
    use super::{q, Q};
    use num_traits::{One, Zero};

    /// All `count` basis functions `N_{i,p}(t)` from the recursive definition
    /// (The NURBS Book, Eq. 2.5), `0/0 := 0`, with the conventions of docs/method.md §6: a
    /// half-open span `[U[i], U[i+1])` (the value at an interior knot comes from
    /// the right), and at the right end `t = U[n]` the last non-empty span.
    pub fn basis(u: &[f64], degree: usize, count: usize, t: f64) -> Vec<Q> {
        let uq: Vec<Q> = u.iter().map(|&x| q(x)).collect();
        let tq = q(t);
        let last = (0..count).filter(|&j| u[j] < u[j + 1]).max().expect("span");
        let mut n: Vec<Q> = (0..u.len() - 1)
            .map(|i| {
                let inside = if t == u[count] {
                    i == last
                } else {
                    u[i] <= t && t < u[i + 1]
                };
                if inside {
                    Q::one()
                } else {
                    Q::zero()
                }
            })
            .collect();
        let ratio = |num: Q, den: Q| {
            if den.is_zero() {
                Q::zero()
            } else {
                num / den
            }
        };
        for p in 1..=degree {
            n = (0..u.len() - 1 - p)
                .map(|i| {
                    ratio(&tq - &uq[i], &uq[i + p] - &uq[i]) * &n[i]
                        + ratio(&uq[i + p + 1] - &tq, &uq[i + p + 1] - &uq[i + 1]) * &n[i + 1]
                })
                .collect();
        }
        n.truncate(count);
        n
    }

    /// The rational basis `Rᵢ(t) = wᵢ Nᵢ(t) / Σ wᵣ Nᵣ(t)` (docs/method.md §6).
    pub fn rational_basis(weights: &[f64], knots: &[f64], degree: usize, t: f64) -> Vec<Q> {
        let n = basis(knots, degree, weights.len(), t);
        let wn: Vec<Q> = n.iter().zip(weights).map(|(n, &w)| n * q(w)).collect();
        let denominator: Q = wn.iter().sum();
        wn.into_iter().map(|x| x / &denominator).collect()
    }

    /// `C(t) = Σ Rᵢ(t) Pᵢ` for control values given exactly.
    pub fn combine<const D: usize>(r: &[Q], points: &[[Q; D]]) -> [Q; D] {
        std::array::from_fn(|d| r.iter().zip(points).map(|(r, p)| r * &p[d]).sum())
    }

    /// `C(t)` of a curve with control values given exactly.
    pub fn curve<const D: usize>(
        points: &[[Q; D]],
        weights: &[f64],
        knots: &[f64],
        degree: usize,
        t: f64,
    ) -> [Q; D] {
        combine(&rational_basis(weights, knots, degree, t), points)
    }

    /// The seven values, the order of docs/method.md §1, and the height of a number.
    pub type Number = ([Q; 7], Q);

    /// `cut(e, s) = e + s·(crisp − e)` (docs/method.md §2) of all seven values; `None` for
    /// the lower ends when `α > h`.
    pub fn alpha_cut((v, h): &Number, alpha: &Q) -> [Option<Q>; 7] {
        let c = &v[3];
        let cut = |e: &Q, s: &Q| e + s * (c - e);
        let below = alpha <= h;
        let lower_s = if below { alpha / h } else { Q::zero() };
        std::array::from_fn(|i| match i {
            3 => Some(c.clone()),
            2 | 4 if !below => None,
            2 | 4 => Some(cut(&v[i], &lower_s)),
            _ => Some(cut(&v[i], alpha)),
        })
    }

    /// Type reduction (docs/method.md §3): `(left, crisp, right)`.
    pub fn type_reduce(cut: &[Option<Q>; 7]) -> [Q; 3] {
        let get = |i: usize| cut[i].clone().expect("present");
        let three = Q::from_integer(3.into());
        let two = Q::from_integer(2.into());
        match (&cut[2], &cut[4]) {
            (Some(ll), Some(lr)) => [
                (get(0) + get(1) + ll) / &three,
                get(3),
                (lr + get(5) + get(6)) / &three,
            ],
            _ => [(get(0) + get(1)) / &two, get(3), (get(5) + get(6)) / &two],
        }
    }

    /// Defuzzification (docs/method.md §4).
    pub fn defuzzify(tfn: &[Q; 3]) -> Q {
        (&tfn[0] + &tfn[1] + &tfn[2]) / Q::from_integer(3.into())
    }
}

/// `|got − want| ≤ tol·scale`, exactly.
fn check(got: f64, want: &Q, scale: f64, tol: f64, what: &str) -> Result<(), String> {
    if !got.is_finite() {
        return Err(format!("{what}: {got} is not finite"));
    }
    let error = (q(got) - want).abs();
    if error <= q(tol) * q(scale) {
        Ok(())
    } else {
        Err(format!(
            "{what}: got {got:e}, exact {:e}, error {:e} > {tol:e}·{scale:e}",
            want.to_f64().unwrap_or(f64::NAN),
            error.to_f64().unwrap_or(f64::INFINITY)
        ))
    }
}

/// The next float below `x`.
fn next_down(x: f64) -> f64 {
    match x {
        0.0 => -f64::from_bits(1),
        x if x > 0.0 => f64::from_bits(x.to_bits() - 1),
        x => f64::from_bits(x.to_bits() + 1),
    }
}

/// A number `(c; spreads)` with left distances `l = [upper, primary, lower]`
/// and right distances `r`, all scaled by `scale`.
fn number(c: f64, l: [f64; 3], r: [f64; 3], h: f64, scale: f64) -> Nt2Number {
    let (c, l, r) = (c * scale, l.map(|x| x * scale), r.map(|x| x * scale));
    Nt2Number::try_new(
        c,
        [c - l[0], c + r[0]],
        [c - l[1], c + r[1]],
        [c - l[2], c + r[2]],
        h,
    )
    .unwrap_or_else(|e| panic!("test number ({c}; {l:?}, {r:?}): {e}"))
}

/// The parameters every check visits: both ends, every knot in the domain, the
/// float just below each of them (the left side of a jump), and a few interior
/// values.
fn parameters(curve: &FuzzyCurve<2>) -> Vec<f64> {
    let d = curve.domain();
    let mut t = vec![d.start, d.end];
    for &u in curve.knots().as_slice() {
        if d.contains(u) {
            t.push(u);
            if d.contains(next_down(u)) {
                t.push(next_down(u));
            }
        }
    }
    t.extend(d.uniform(5).unwrap());
    t
}

/// The exact seven values and height of every number of a curve's points.
fn exact_numbers(curve: &FuzzyCurve<2>) -> Vec<[exact::Number; 2]> {
    curve
        .points()
        .iter()
        .map(|p| {
            p.coords()
                .map(|x| (x.layers().as_array().map(q), q(x.height().get())))
        })
        .collect()
}

/// Checks every output of `curve` solved at `alpha` against exact arithmetic:
/// the seven layer curves, the cut, reduced and defuzzified control points,
/// the curves of stages 3 and 4, and the distance, at the parameters of
/// [`parameters`]. (The alpha-cut curves of stage 2 are the same evaluation
/// with other control points, which are checked one by one.)
fn check_against_exact(curve: &FuzzyCurve<2>, alpha: f64, label: &str) -> Result<(), String> {
    let tol = 1e-12;
    let (u, p, w) = (curve.knots().as_slice(), curve.degree(), curve.weights());
    let scale = curve
        .points()
        .iter()
        .flat_map(|pt| {
            pt.coords()
                .map(|x| x.upper().left().abs().max(x.upper().right().abs()))
        })
        .fold(f64::MIN_POSITIVE, f64::max);
    let numbers = exact_numbers(curve);
    let alpha_q = q(alpha);
    let solution = curve.solve(Alpha::try_new(alpha).map_err(|e| e.to_string())?);

    // Stages 2–4 on the control points.
    let mut reduced = Vec::new();
    let mut defuzzified = Vec::new();
    for (i, exact_point) in numbers.iter().enumerate() {
        let cut = exact_point
            .each_ref()
            .map(|x| exact::alpha_cut(x, &alpha_q));
        let tfn = cut.each_ref().map(exact::type_reduce);
        let dfz = tfn.each_ref().map(exact::defuzzify);
        for d in 0..2 {
            let got = solution.alpha_cut_points()[i][d];
            for layer in Layer::ALL {
                let what = format!("{label}: cut point {i}, axis {d}, {layer}");
                match (got.layer(layer), &cut[d][layer.index()]) {
                    (Some(g), Some(e)) => check(g, e, scale, tol, &what)?,
                    (None, None) => {}
                    (g, e) => return Err(format!("{what}: got {g:?}, exact {e:?}")),
                }
            }
            let t = solution.type_reduced_points()[i][d];
            let what = format!("{label}: reduced point {i}, axis {d}");
            check(t.left(), &tfn[d][0], scale, tol, &what)?;
            check(t.right(), &tfn[d][2], scale, tol, &what)?;
            let what = format!("{label}: defuzzified point {i}, axis {d}");
            check(
                solution.defuzzified_points()[i][d],
                &dfz[d],
                scale,
                tol,
                &what,
            )?;
        }
        reduced.push(tfn);
        defuzzified.push(dfz);
    }

    let layer_values = |layer: Layer| -> Vec<[Q; 2]> {
        numbers
            .iter()
            .map(|pt| pt.each_ref().map(|(v, _)| v[layer.index()].clone()))
            .collect()
    };
    let crisp_values = layer_values(Layer::Crisp);
    let dfz_values = defuzzified;
    let side_values = |k: usize| -> Vec<[Q; 2]> {
        reduced
            .iter()
            .map(|pt| pt.each_ref().map(|tfn| tfn[k].clone()))
            .collect()
    };
    let (left_values, right_values) = (side_values(0), side_values(2));
    let d = solution.distance();
    let max_q = q(d.max) + q(tol) * q(scale);
    for t in parameters(curve) {
        let r = exact::rational_basis(w, u, p, t);
        let curve_at = |values: &[[Q; 2]]| exact::combine(&r, values);
        let layers = curve.eval_layers(t).map_err(|e| e.to_string())?;
        for layer in Layer::ALL {
            let want = curve_at(&layer_values(layer));
            for k in 0..2 {
                let what = format!("{label}: layer {layer} at t = {t:e}, axis {k}");
                check(layers[layer][k], &want[k], scale, tol, &what)?;
            }
        }
        let checks: [(&str, NurbsCurve<2>, &[[Q; 2]]); 3] = [
            ("defuzzified", solution.defuzzified_curve(), &dfz_values),
            (
                "left",
                solution.type_reduced_curve(Side::Left),
                &left_values,
            ),
            (
                "right",
                solution.type_reduced_curve(Side::Right),
                &right_values,
            ),
        ];
        for (name, c, values) in checks {
            let want = curve_at(values);
            let got = c.eval(t).map_err(|e| e.to_string())?;
            for k in 0..2 {
                let what = format!("{label}: {name} curve at t = {t:e}, axis {k}");
                check(got[k], &want[k], scale, tol, &what)?;
            }
        }
        // The maximum distance is at least the exact distance at every knot
        // and end (where the library's scan looks; between them its maximum
        // is an estimate).
        if !curve.knots().as_slice().contains(&t) {
            continue;
        }
        let a = curve_at(&crisp_values);
        let b = curve_at(&dfz_values);
        let squared: Q = a.iter().zip(&b).map(|(x, y)| (x - y) * (x - y)).sum();
        if squared > &max_q * &max_q {
            return Err(format!(
                "{label}: distance at t = {t:e} is {:e} > max {:e}",
                squared.to_f64().unwrap_or(f64::INFINITY).sqrt(),
                d.max
            ));
        }
    }
    // And it is the exact distance at `max_at`; the rms lies in [0, max].
    let a = exact::curve(&crisp_values, w, u, p, d.max_at);
    let b = exact::curve(&dfz_values, w, u, p, d.max_at);
    let squared: Q = a.iter().zip(&b).map(|(x, y)| (x - y) * (x - y)).sum();
    let max = d.max / scale;
    check(
        max * max,
        &(squared / q(scale) / q(scale)),
        1.0,
        tol,
        &format!("{label}: max"),
    )?;
    if !(d.rms.is_finite() && d.rms >= 0.0 && d.rms <= d.max * (1.0 + 1e-12)) {
        return Err(format!(
            "{label}: rms {} outside [0, max = {}]",
            d.rms, d.max
        ));
    }
    Ok(())
}

/// A test curve: degree, knots (`None`: clamped uniform), weights, and per
/// point `(cx, cy)` with one shape of spreads.
struct Case {
    label: &'static str,
    degree: usize,
    knots: Option<Vec<f64>>,
    weights: Vec<f64>,
    centres: Vec<[f64; 2]>,
    /// Left and right distances `[upper, primary, lower]`, and h.
    spreads: ([f64; 3], [f64; 3], f64),
    alphas: Vec<f64>,
}

impl Case {
    fn curve(&self, scale: f64) -> FuzzyCurve<2> {
        let (l, r, h) = self.spreads;
        let points = self
            .centres
            .iter()
            .enumerate()
            .map(|(i, &[x, y])| {
                // Vary the spreads from point to point (mirrored on odd points)
                // so that the defuzzified curve moves off the crisp one.
                let (l, r) = if i % 2 == 0 { (l, r) } else { (r, l) };
                Nt2Point::new([number(x, l, r, h, scale), number(y, r, l, h, scale)])
            })
            .collect();
        FuzzyCurve::try_new(
            self.degree,
            points,
            self.weights.clone(),
            self.knots.clone(),
        )
        .unwrap_or_else(|e| panic!("{}: {e}", self.label))
    }
}

fn cases() -> Vec<Case> {
    let asym = ([0.6, 0.4, 0.2], [0.9, 0.6, 0.3], 0.6);
    vec![
        Case {
            label: "paper configuration",
            degree: 2,
            knots: None,
            weights: vec![1.0, 1.0, 3.0, 1.0],
            centres: vec![[1.0, 1.0], [2.0, 4.0], [5.0, 4.5], [6.0, 1.0]],
            spreads: asym,
            alphas: vec![0.0, 0.3, 0.6, 0.8, 1.0],
        },
        Case {
            label: "weights 1e-12 to 1e12",
            degree: 3,
            knots: Some(vec![0.0, 0.0, 0.0, 0.0, 0.2, 0.45, 0.7, 1.0, 1.0, 1.0, 1.0]),
            weights: vec![1e-12, 1e12, 1.0, 1e-12, 1e12, 3.0, 1e-12],
            centres: vec![
                [0.0, 0.0],
                [1.0, 3.0],
                [2.0, -1.0],
                [3.0, 2.0],
                [4.0, 0.5],
                [5.0, 5.0],
                [6.0, 0.0],
            ],
            spreads: asym,
            alphas: vec![0.0, 0.6, 1.0],
        },
        Case {
            label: "weights at the limits 1e-150 and 1e150",
            degree: 2,
            knots: None,
            weights: vec![MIN_WEIGHT, MAX_WEIGHT, MIN_WEIGHT, 1.0, MAX_WEIGHT],
            centres: vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0], [3.0, -2.0], [4.0, 0.0]],
            spreads: asym,
            alphas: vec![0.25, 0.6],
        },
        Case {
            label: "interior knot of full multiplicity (a jump)",
            degree: 2,
            knots: Some(vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0]),
            weights: vec![1.0, 1e12, 1.0, 1e-12, 2.0, 1.0],
            centres: vec![
                [0.0, 0.0],
                [1.0, 1.0],
                [2.0, 0.0],
                [10.0, 10.0],
                [11.0, 12.0],
                [12.0, 10.0],
            ],
            spreads: asym,
            alphas: vec![0.0, 0.6, 0.9],
        },
        Case {
            label: "unclamped knots",
            degree: 3,
            knots: Some((0..9).map(f64::from).collect()),
            weights: vec![1e12, 1e-12, 1e12, 1e-12, 1.0],
            centres: vec![[0.0, 1.0], [1.0, -1.0], [2.0, 1.0], [3.0, -1.0], [4.0, 1.0]],
            spreads: asym,
            alphas: vec![0.0, 0.6, 1.0],
        },
        Case {
            label: "repeated control points",
            degree: 2,
            knots: None,
            weights: vec![1.0, 1e12, 1e-12, 1.0, 1.0],
            centres: vec![[1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [3.0, 2.0], [3.0, 2.0]],
            spreads: asym,
            alphas: vec![0.0, 0.6, 1.0],
        },
        Case {
            label: "zero-width spreads, h = 1",
            degree: 2,
            knots: None,
            weights: vec![1.0, 2.0, 1e12, 1.0],
            centres: vec![[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [3.0, 0.0]],
            spreads: ([0.0; 3], [0.0; 3], 1.0),
            alphas: vec![0.0, 0.5, 1.0],
        },
        Case {
            label: "h = 1, some sides of zero width",
            degree: 1,
            knots: Some(vec![0.0, 0.0, 0.25, 0.25, 0.75, 1.0, 1.0]),
            weights: vec![1.0, 1e-12, 1.0, 1e12, 1.0],
            centres: vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0], [4.0, 0.0]],
            spreads: ([0.5, 0.0, 0.0], [1.5, 1.0, 0.25], 1.0),
            alphas: vec![0.0, 0.5, 1.0],
        },
        Case {
            label: "degree 7 Bezier with alternating weights",
            degree: 7,
            knots: None,
            weights: vec![1.0, 1e12, 1e-12, 1e12, 1e-12, 1e12, 1e-12, 1.0],
            centres: (0..8).map(|i| [f64::from(i), f64::from(i % 3)]).collect(),
            spreads: asym,
            alphas: vec![0.0, 0.6, 1.0],
        },
    ]
}

/// Every case at every scale from 1e-300 to about 1e149 (the largest centre,
/// 12, plus its spread times 7e148 stays within the limit 1e150) against
/// exact arithmetic.
#[test]
fn every_case_at_every_scale_matches_exact_rationals() {
    for case in cases() {
        for scale in [1.0, 7e148, 1e-150, 1e-300] {
            let curve = case.curve(scale);
            for &alpha in &case.alphas {
                let label = format!("{} at scale {scale:e}, alpha {alpha}", case.label);
                check_against_exact(&curve, alpha, &label).unwrap_or_else(|e| panic!("{e}"));
            }
        }
    }
}

/// Control values exactly at the limits ±1e150 (and weights at 1e-150 and
/// 1e150) through every stage, against exact arithmetic.
#[test]
fn values_exactly_at_the_limits_match_exact_rationals() {
    let m = MAX_MAGNITUDE;
    let n = |c: f64, lo: f64, hi: f64| {
        Nt2Number::try_new(c, [lo, hi], [(lo + c) / 2.0, (hi + c) / 2.0], [c, c], 0.5).unwrap()
    };
    let points = vec![
        Nt2Point::new([n(0.0, -m, m), n(m, m / 2.0, m)]),
        Nt2Point::new([n(m / 2.0, 0.0, m), n(-m, -m, -m / 2.0)]),
        Nt2Point::new([n(-m / 2.0, -m, 0.0), n(0.0, -m, m)]),
        Nt2Point::new([n(m, m, m), n(1e-150, -1e-150, 2e-150)]),
    ];
    let curve = FuzzyCurve::try_new(
        2,
        points,
        vec![MIN_WEIGHT, MAX_WEIGHT, 1.0, MIN_WEIGHT],
        Some(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]),
    )
    .unwrap();
    for alpha in [0.0, 0.5, 0.75, 1.0] {
        check_against_exact(&curve, alpha, &format!("limits, alpha {alpha}"))
            .unwrap_or_else(|e| panic!("{e}"));
    }
}

/// Alpha exactly at the lower height h takes the three-term rule (docs/method.md §2):
/// the lower cut is the crisp value itself.
#[test]
fn alpha_exactly_h_cuts_the_lower_triangle_at_its_apex() {
    for h in [0.6, 1e-300, 1.0] {
        let x = number(1e150, [0.6, 0.4, 0.2], [0.9, 0.6, 0.3], h, 1.0);
        let cut = x.alpha_cut(Alpha::try_new(h).unwrap());
        let lower = cut.lower().expect("alpha = h is at or below h");
        assert_eq!((lower.left(), lower.right()), (1e150, 1e150), "h = {h}");
    }
}

/// A jump at an interior knot of full multiplicity: the value at the knot is
/// the right limit (the first control point after the jump, since the right
/// piece is clamped there) and the value one float below it is, to rounding,
/// the left limit (the last control point before the jump) — with extreme
/// weights away from the jump and extreme weights next to it (then the exact
/// value one float below differs from the limit, and is checked exactly).
#[test]
fn the_jump_takes_the_value_from_the_right() {
    let knots = vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0];
    let centres = [
        [0.0, 0.0],
        [1.0, 1.0],
        [2.0, 0.0],
        [10.0, 10.0],
        [11.0, 12.0],
        [12.0, 10.0],
    ];
    for weights in [
        vec![1e12, 1.0, 1.0, 1.0, 1.0, 1e-12],
        vec![1.0, 1e12, 1.0, 1e-12, 2.0, 1.0],
    ] {
        for scale in [1.0, 7e148, 1e-150, 1e-300] {
            let points: Vec<[f64; 2]> = centres.iter().map(|p| p.map(|x| x * scale)).collect();
            let u = t2spline::KnotVector::try_new(knots.clone(), 2, 6).unwrap();
            let c = NurbsCurve::try_new(points.clone(), weights.clone(), u).unwrap();
            assert_eq!(c.eval(0.5).unwrap(), points[3], "scale {scale:e}");
            let below = next_down(0.5);
            let left = c.eval(below).unwrap();
            let exact_points: Vec<[Q; 2]> = points.iter().map(|p| p.map(q)).collect();
            let want = exact::curve(&exact_points, &weights, &knots, 2, below);
            for k in 0..2 {
                let what = format!("weights {weights:?}, scale {scale:e}, t = 0.5⁻");
                check(left[k], &want[k], 12.0 * scale, 1e-14, &what).unwrap();
                if weights[1] == 1.0 {
                    check(left[k], &q(points[2][k]), 12.0 * scale, 1e-14, &what).unwrap();
                }
            }
        }
    }
}

/// A constant offset between crisp and defuzzified points gives the closed form
/// `max = rms = |δ|` at every scale, δ computed exactly.
#[test]
fn constant_offset_distance_is_exact_at_every_scale() {
    for scale in [1.0, 2e149, 1e-150, 1e-300] {
        let x = |c: f64| number(c, [0.6, 0.4, 0.2], [0.9, 0.6, 0.3], 0.6, scale);
        let points: Vec<Nt2Point<2>> = (0..5)
            .map(|i| Nt2Point::new([x(f64::from(i)), x(f64::from(i * i % 5))]))
            .collect();
        let curve = FuzzyCurve::try_new(3, points, vec![1.0, 1e12, 1e-12, 2.0, 1.0], None).unwrap();
        let solution = curve.solve(Alpha::try_new(0.8).unwrap());
        // δ per coordinate, exactly, from the first point.
        let first = exact_numbers(&curve)[0].each_ref().map(|n| {
            let tfn = exact::type_reduce(&exact::alpha_cut(n, &q(0.8)));
            exact::defuzzify(&tfn) - &n.0[3]
        });
        let squared: Q = first.iter().map(|d| d * d).sum();
        let d = solution.distance();
        // Rounding of the cut points differs a little from point to point.
        let what = format!("scale {scale:e}");
        let want = &squared / q(scale) / q(scale);
        let (max, rms) = (d.max / scale, d.rms / scale);
        check(max * max, &want, 1.0, 1e-9, &what).unwrap();
        check(rms * rms, &want, 1.0, 1e-9, &what).unwrap();
    }
}

/// A distance growing linearly from 0 to `δ` along a line: `max = δ` at the end
/// and `rms = δ/√3`, at every scale.
#[test]
fn linear_distance_has_the_closed_form_rms_at_every_scale() {
    for scale in [1.0, 3e149, 1e-150, 1e-300] {
        // Point 0 is crisp 0. Point 1 has crisp 0 and only an upper right
        // spread 3s: at alpha 0 (h = 1) type reduction gives right = 3s/3 = s
        // and defuzzification s/3, so the distance is (s/3)·t.
        let zero = Nt2Number::try_crisp(0.0).unwrap();
        let top = Nt2Number::try_new(0.0, [0.0, 3.0 * scale], [0.0, 0.0], [0.0, 0.0], 1.0).unwrap();
        let points = vec![Nt2Point::new([zero, zero]), Nt2Point::new([zero, top])];
        let curve = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None).unwrap();
        let d = curve.solve(Alpha::try_new(0.0).unwrap()).distance();
        let delta = scale / 3.0;
        assert!(
            ((d.max - delta) / delta).abs() < 1e-15,
            "scale {scale:e}: {d:?}"
        );
        assert_eq!(d.max_at, 1.0);
        let rms = delta / 3f64.sqrt();
        assert!(
            ((d.rms - rms) / rms).abs() < 1e-14,
            "scale {scale:e}: {d:?} vs {rms}"
        );
    }
}

/// Knot spans narrower than the smallest normal float (about 2.2e-308): the
/// basis is still a partition of unity and every value is finite.
#[test]
fn subnormal_knot_spans_give_finite_values() {
    let tiny = f64::from_bits(1); // 5e-324
    let knots = vec![0.0, 0.0, 0.0, tiny, 2.0 * tiny, 1e-310, 1.0, 1.0, 1.0];
    let weights = vec![1.0, MAX_WEIGHT, MIN_WEIGHT, 1.0, 1e12, 1.0];
    let points: Vec<[f64; 2]> = (0..6)
        .map(|i| [f64::from(i) * 1e150 / 6.0, -1e150])
        .collect();
    let u = t2spline::KnotVector::try_new(knots.clone(), 2, 6).unwrap();
    let c = NurbsCurve::try_new(points.clone(), weights.clone(), u).unwrap();
    for t in [0.0, tiny, 2.0 * tiny, 3.0 * tiny, 1e-310, 1e-309, 0.5, 1.0] {
        let r = c.rational_basis(t).unwrap();
        assert!(
            r.iter().all(|x| x.is_finite() && *x >= 0.0),
            "t = {t:e}: {r:?}"
        );
        assert!(
            (r.iter().sum::<f64>() - 1.0).abs() < 1e-12,
            "t = {t:e}: {r:?}"
        );
        let want = exact::curve(
            &points.iter().map(|p| p.map(q)).collect::<Vec<_>>(),
            &weights,
            &knots,
            2,
            t,
        );
        let got = c.eval(t).unwrap();
        for k in 0..2 {
            check(got[k], &want[k], 1e150, 1e-12, &format!("t = {t:e}")).unwrap();
        }
    }
}

/// Values past the limits are refused with their place, never clamped.
#[test]
fn values_past_the_limits_are_refused() {
    let e = Nt2Number::try_new(0.0, [-1e151, 1.0], [0.0, 0.0], [0.0, 0.0], 1.0).unwrap_err();
    assert_eq!(
        e.to_string(),
        "upper.left = -1e151 is outside [-1e150, 1e150]"
    );
    assert!(Nt2Number::try_crisp(MAX_MAGNITUDE).is_ok());
    let e =
        NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, 0.9e-150]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "weights[1] = 9e-151 is outside [1e-150, 1e150]"
    );
    let e = NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [2e150, 1.0]], vec![1.0, 1.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "points[1].x: coordinate = 2e150 is outside [-1e150, 1e150]"
    );
    let e = t2spline::KnotVector::try_new(vec![0.0, 0.0, 1.0, 1e151], 1, 2).unwrap_err();
    assert_eq!(e.to_string(), "knots[3] = 1e151 is outside [-1e150, 1e150]");
    // A degree whose order overflows is "too few points", not a panic.
    assert!(t2spline::KnotVector::clamped_uniform(usize::MAX, 3).is_err());
    assert!(t2spline::KnotVector::try_new(vec![0.0, 1.0], usize::MAX, 1).is_err());
}

// ---------------------------------------------------------------------------
// Random inputs
// ---------------------------------------------------------------------------

/// A magnitude `10^e`, e uniform in [-300, 149.9], sometimes 0.
fn magnitude() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 6 => (-300.0..149.9f64).prop_map(|e| 10f64.powf(e))]
}

/// A fuzzy number of any scale: crisp value and six spreads of independent
/// magnitudes, all within ±1e150 when added up.
fn extreme_number() -> impl Strategy<Value = Nt2Number> {
    (
        magnitude(),
        any::<bool>(),
        proptest::array::uniform6(magnitude()),
        prop_oneof![Just(1.0), Just(0.5), (1e-300..=1.0f64)],
    )
        .prop_map(|(c, negative, spreads, h)| {
            let c = if negative { -c / 4.0 } else { c / 4.0 };
            let mut s = spreads.map(|x| x / 4.0);
            s[..3].sort_by(f64::total_cmp);
            s[3..].sort_by(f64::total_cmp);
            Nt2Number::try_new(
                c,
                [c - s[2], c + s[5]],
                [c - s[1], c + s[4]],
                [c - s[0], c + s[3]],
                h,
            )
            .expect("sorted spreads about c are ordered")
        })
}

/// Knots of any scale and spacing: `c + M·gⱼ` with `M = 10^e` (e from -300
/// to 147), gⱼ sorted in [0, 1], some repeated (full multiplicity included),
/// clamped or not, and an offset `c` up to 1e14·M so that spans can be a few
/// ulps of the knots wide. An invalid draw (too many repeats, or spans that
/// rounding merged) falls back to evenly spaced knots of the same scale.
fn extreme_knots(degree: usize, count: usize) -> impl Strategy<Value = Vec<f64>> {
    let len = count + degree + 1;
    (
        -300.0..147.0f64,
        0.0..14.0f64,
        -1.0..1.0f64,
        any::<bool>(),
        proptest::collection::vec(
            (0.0..=1.0f64, prop_oneof![3 => Just(false), 1 => Just(true)]),
            len,
        ),
    )
        .prop_map(move |(e, relative, offset, clamped, draws)| {
            let m = 10f64.powf(e);
            let c = offset * m * 10f64.powf(relative.min(149.0 - e));
            let mut g: Vec<f64> = Vec::with_capacity(len);
            for (x, repeat) in draws {
                g.push(match g.last() {
                    Some(&last) if repeat => last,
                    _ => x,
                });
            }
            g.sort_by(f64::total_cmp);
            if clamped {
                for x in &mut g[..=degree] {
                    *x = 0.0;
                }
                for x in &mut g[len - degree - 1..] {
                    *x = 1.0;
                }
            }
            let u: Vec<f64> = g.iter().map(|x| c + m * x).collect();
            if t2spline::KnotVector::problems(&u, degree, count).is_empty() {
                u
            } else {
                (0..len).map(|i| m * i as f64 / len as f64).collect()
            }
        })
}

/// A fuzzy curve of degree 1–4 with extreme numbers, weights and knots.
fn extreme_curve() -> impl Strategy<Value = FuzzyCurve<2>> {
    (1usize..=4, 0usize..=4).prop_flat_map(|(degree, extra)| {
        let count = degree + 1 + extra;
        (
            proptest::collection::vec(
                proptest::array::uniform2(extreme_number()).prop_map(Nt2Point::new),
                count,
            ),
            proptest::collection::vec(
                prop_oneof![
                    Just(MIN_WEIGHT),
                    Just(MAX_WEIGHT),
                    (-150.0..150.0f64).prop_map(|e| 10f64.powf(e))
                ],
                count,
            ),
            extreme_knots(degree, count),
        )
            .prop_map(move |(points, weights, knots)| {
                FuzzyCurve::try_new(degree, points, weights, Some(knots)).expect("valid parts")
            })
    })
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(32, 96))]

    /// Inputs of any scale within the limits: every output of every stage is
    /// finite, the seven layers stay ordered, and the distance is finite with
    /// rms ≤ max.
    #[test]
    fn extreme_inputs_give_finite_ordered_outputs(
        curve in extreme_curve(), alpha in prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0f64], s in 0.0..=1.0f64,
    ) {
        let solution = curve.solve(Alpha::try_new(alpha).expect("alpha in [0, 1]"));
        let d = solution.distance();
        prop_assert!(d.max.is_finite() && d.rms.is_finite() && d.max_at.is_finite(), "{:?}", d);
        prop_assert!(d.rms <= d.max * (1.0 + 1e-12), "{:?}", d);
        let domain = curve.domain();
        let mut ts = vec![domain.lerp(s), domain.start, domain.end];
        ts.extend(curve.knots().as_slice().iter().filter(|&&u| domain.contains(u)));
        for t in ts {
            let layers = curve.eval_layers(t).expect("t in the domain");
            for k in 0..2 {
                let v = layers.as_array().map(|p| p[k]);
                prop_assert!(v.iter().all(|x| x.is_finite()), "t = {t:e}: {v:?}");
                prop_assert!(v.windows(2).all(|w| w[0] <= w[1]), "t = {t:e}: {v:?}");
            }
            let curves = [
                solution.defuzzified_curve(),
                solution.type_reduced_curve(Side::Left),
                solution.type_reduced_curve(Side::Right),
            ];
            for c in curves {
                let p = c.eval(t).expect("t in the domain");
                prop_assert!(p.iter().all(|x| x.is_finite()), "t = {t:e}: {p:?}");
            }
        }
    }

    /// Scaling every coordinate by a power of two (exact in floating point)
    /// scales every curve point by the same power, bit for bit, from 2^-490 ≈
    /// 3e-148 to 2^480 ≈ 3e144: no step depends on the absolute size of the
    /// numbers. The distance is the same to 1e-14 (its norm squares components
    /// directly between 1e-150 and 1e150 and scales them first beyond, which
    /// rounds differently).
    #[test]
    fn scaling_by_powers_of_two_is_exact(
        curve in strategies::fuzzy_curve::<2>(),
        k in prop_oneof![Just(-490i32), Just(480)],
        alpha in 0.0..=1.0f64,
        s in 0.0..=1.0f64,
    ) {
        let f = 2f64.powi(k);
        let scaled_points = curve
            .points()
            .iter()
            .map(|p| Nt2Point::new(p.coords().map(|x| {
                let v = x.layers().as_array().map(|v| v * f);
                Nt2Number::try_new(v[3], [v[0], v[6]], [v[1], v[5]], [v[2], v[4]], x.height().get())
                    .expect("scaled number")
            })))
            .collect();
        let scaled = FuzzyCurve::try_new(
            curve.degree(), scaled_points, curve.weights().to_vec(), Some(curve.knots().as_slice().to_vec()),
        ).expect("scaled curve");
        let a = Alpha::try_new(alpha).expect("alpha");
        let (s1, s2) = (curve.solve(a), scaled.solve(a));
        let (d1, d2) = (s1.distance(), s2.distance());
        let near = |a: f64, b: f64| (a - b).abs() <= 1e-14 * a.abs().max(b.abs());
        prop_assert!(near(d2.max, d1.max * f), "{:?} vs {:?}", d2, d1);
        prop_assert!(near(d2.rms, d1.rms * f), "{:?} vs {:?}", d2, d1);
        let t = curve.domain().lerp(s);
        let (p1, p2) = (s1.defuzzified_curve().eval(t).expect("t"), s2.defuzzified_curve().eval(t).expect("t"));
        prop_assert_eq!(p2, p1.map(|x| x * f));
        let (l1, l2) = (curve.eval_layers(t).expect("t"), scaled.eval_layers(t).expect("t"));
        for layer in Layer::ALL {
            prop_assert_eq!(l2[layer], l1[layer].map(|x| x * f));
        }
    }
}

#[test]
fn zero_is_a_valid_scale_for_everything() {
    // Every value 0: the crisp curve is 0 and so is the distance.
    let zero = Nt2Number::try_crisp(0.0).unwrap();
    let c = FuzzyCurve::try_new(
        2,
        vec![Nt2Point::new([zero, zero]); 3],
        vec![MIN_WEIGHT, MAX_WEIGHT, 1.0],
        None,
    )
    .unwrap();
    let d = c.solve(Alpha::try_new(0.5).unwrap()).distance();
    assert_eq!((d.max, d.rms), (0.0, 0.0));
}

proptest! {
    #![proptest_config(t2spline::strategies::cases(8, 16))]

    /// The inputs of `extreme_inputs_give_finite_ordered_outputs` against exact
    /// rational arithmetic (fewer cases: the reference is slow).
    #[test]
    fn extreme_inputs_match_exact_rationals(
        curve in extreme_curve(), alpha in prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0f64],
    ) {
        prop_assume!(curve.points().len() <= 6);
        check_against_exact(&curve, alpha, "random").map_err(TestCaseError::fail)?;
    }
}
