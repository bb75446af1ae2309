//! The volume below the datum and the plan area below it on one span
//! rectangle the datum crosses (docs/method.md §14), in the span's Bernstein
//! form.
//!
//! On the span, with `(s, t) ∈ [0, 1]²` its local parameters, `W`, `W·x`,
//! `W·y` and `P = W·(z − z₀)` are tensor polynomials of degrees `(p, q)`
//! with Bernstein coefficients `Mᵤ·C·Mᵥᵀ` (`C` the local B-spline
//! coefficients, `M` the Bézier matrices). As `W > 0`, `z < z₀` where
//! `P < 0`, and
//!
//! ```text
//! V = ∫₀¹ F(s) ds,   F(s) = Σ over the t-intervals where P(s, ·) < 0 of ∫ (z₀ − z)·|J| dt
//! ```
//! (`J = x_s·y_t − x_t·y_s`, the plan area likewise with `1` for `z₀ − z`).
//! For each `s` the sign changes of `P(s, ·)` are isolated in Bernstein form
//! (`roots.rs`); between them the integrand is a polynomial of degree
//! `3q − 1` where the weights of the span are equal (a Gauss rule of
//! `⌈3q/2⌉` points is exact), else a rational function (Gauss rules of 16
//! and 8 points, halved where they differ).
//!
//! `F` is smooth but at the `s` where a root of `P(s, ·)` leaves through
//! `t = 0` or `t = 1` (roots of `P(s, 0)`, `P(s, 1)`: a kink of the plan
//! area, a jump of the volume's second derivative) and where two roots meet
//! (`P = P_t = 0`, the contour tangent to the `t` direction: `F` behaves as
//! `|s − s*|^{1/2}` for the area and `|s − s*|^{3/2}` for the volume). The
//! former are isolated in Bernstein form, the latter by subdivision of the
//! square (a box whose coefficients of `P` or of `P_t` keep one strict sign
//! holds none) and Newton's method on boxes of a quarter of the searched region. `[0, 1]`
//! is cut at all of them; an end where roots meet is taken away by
//! `s = a + (b − a)·τ²`, after which `F·ds/dτ` is smooth in `τ`, and each
//! piece is integrated by the 15-point Kronrod rule with QUADPACK's error
//! estimate, halved until it meets its share of the tolerance. A meeting
//! point missed by the search only costs more halvings.

use crate::cubature::gauss_legendre;
use crate::measure::roots::{horner, sign_changes_in_unit, sign_changes_power_into};
use crate::quadrature::kronrod_vector;

/// Halvings at most of a piece of `[0, 1]` in `s`.
const MAX_DEPTH: u32 = 40;
/// Kronrod rules at most per span rectangle (a guard: past it, the
/// pieces are taken as they are, their error estimates reported).
const BUDGET: usize = 2000;
/// Subdivisions at most of the square in the search for meeting roots.
const SEARCH_DEPTH: u32 = 4;
/// The depth from which Newton's method is tried in a box.
const NEWTON_DEPTH: u32 = 2;

/// The plan of one span rectangle in Bernstein form.
#[derive(Clone, Debug)]
pub(crate) struct Patch {
    /// `(p + 1, q + 1)`.
    orders: [usize; 2],
    /// `W`, `W·x`, `W·y`: Bernstein coefficients, `a·(q + 1) + b`.
    plan: [Vec<f64>; 3],
    /// The Bézier matrices along u and v.
    bezier: [Vec<f64>; 2],
    /// Whether the weights of the span are equal (`W` constant).
    polynomial: bool,
    /// Bernstein to power coefficients along t: `a_k = Σᵢ C(q, k)·C(k, i)·
    /// (−1)^{k−i}·bᵢ`.
    to_power: Vec<f64>,
}

/// The Gauss rules the inner integrals use.
#[derive(Clone, Debug)]
pub(crate) struct Rules {
    exact: (Vec<f64>, Vec<f64>),
    fine: (Vec<f64>, Vec<f64>),
    coarse: (Vec<f64>, Vec<f64>),
}

impl Rules {
    /// The rules for degree `q` along v.
    pub(crate) fn new(q: usize) -> Self {
        Rules {
            exact: gauss_legendre((3 * q).div_ceil(2).max(1)),
            fine: gauss_legendre(16),
            coarse: gauss_legendre(8),
        }
    }
}

/// The Bernstein functions of degree `values.len() − 1` at `s` and their
/// slopes.
fn bernstein(s: f64, values: &mut [f64], slopes: &mut [f64]) {
    let n = values.len() - 1;
    values.fill(0.0);
    values[0] = 1.0;
    // Degree n − 1 first (for the slopes), then n.
    for d in 1..n.max(1) {
        for j in (1..=d).rev() {
            values[j] = (1.0 - s) * values[j] + s * values[j - 1];
        }
        values[0] *= 1.0 - s;
    }
    slopes.fill(0.0);
    if n == 0 {
        return;
    }
    let nf = n as f64;
    for j in 0..=n {
        let left = if j >= 1 { values[j - 1] } else { 0.0 };
        let right = if j < n { values[j] } else { 0.0 };
        slopes[j] = nf * (left - right);
    }
    if n >= 1 {
        for j in (1..=n).rev() {
            values[j] = (1.0 - s) * values[j] + s * values[j - 1];
        }
        values[0] *= 1.0 - s;
    }
}

/// `M·C·Nᵀ` for `C` of `ku × kv` (row-major).
fn tensor(m: &[f64], c: &[f64], n: &[f64], ku: usize, kv: usize) -> Vec<f64> {
    let mut mc = vec![0.0; ku * kv];
    for r in 0..ku {
        for a in 0..ku {
            let x = m[r * ku + a];
            if x != 0.0 {
                for b in 0..kv {
                    mc[r * kv + b] += x * c[a * kv + b];
                }
            }
        }
    }
    let mut out = vec![0.0; ku * kv];
    for r in 0..ku {
        for col in 0..kv {
            out[r * kv + col] = (0..kv).map(|b| mc[r * kv + b] * n[col * kv + b]).sum();
        }
    }
    out
}

/// The value and the two slopes of the tensor Bernstein polynomial `c`
/// (`ku × kv`) at `(s, t)`.
fn value_and_slopes(c: &[f64], [ku, kv]: [usize; 2], s: f64, t: f64) -> [f64; 3] {
    let (mut bu, mut du, mut bv, mut dv) =
        (vec![0.0; ku], vec![0.0; ku], vec![0.0; kv], vec![0.0; kv]);
    bernstein(s, &mut bu, &mut du);
    bernstein(t, &mut bv, &mut dv);
    let mut out = [0.0; 3];
    for a in 0..ku {
        for b in 0..kv {
            let x = c[a * kv + b];
            out[0] += bu[a] * bv[b] * x;
            out[1] += du[a] * bv[b] * x;
            out[2] += bu[a] * dv[b] * x;
        }
    }
    out
}

/// The columns of the patch contracted at one `s`: per Bernstein function
/// along t, `W`, `W·x`, `W·y`, `P` and the s-slopes of the first three.
struct Columns {
    value: [Vec<f64>; 4],
    slope: [Vec<f64>; 3],
    /// `W`, `W·x`, `W·y`, `P`, then the s-slopes of the first three, in
    /// powers of t (for Horner's rule at the inner nodes).
    power: [Vec<f64>; 7],
    /// The ends of the pieces along t (reused).
    cuts: Vec<f64>,
}

/// The working space of [`Patch::below`], reused across the span
/// rectangles of one net.
pub(crate) struct Scratch {
    columns: Columns,
    /// The Bernstein functions along s and their slopes.
    basis: (Vec<f64>, Vec<f64>),
}

impl Scratch {
    /// Room for patches of orders `[ku, kv]`.
    pub(crate) fn new([ku, kv]: [usize; 2]) -> Self {
        Scratch {
            columns: Columns {
                value: std::array::from_fn(|_| vec![0.0; kv]),
                slope: std::array::from_fn(|_| vec![0.0; kv]),
                power: std::array::from_fn(|_| vec![0.0; kv]),
                cuts: Vec::with_capacity(kv + 2),
            },
            basis: (vec![0.0; ku], vec![0.0; ku]),
        }
    }
}

impl Patch {
    /// The patch of the span rectangle `spans` of a plan with knots
    /// `knots`, weights and plan points `weights`, `xy` (`nv` columns).
    pub(crate) fn new(
        knots: &[crate::nurbs::KnotVector; 2],
        spans: [usize; 2],
        weights: &[f64],
        xy: &[[f64; 2]],
        nv: usize,
    ) -> Self {
        let [p, q] = [knots[0].degree(), knots[1].degree()];
        let (ku, kv) = (p + 1, q + 1);
        let bezier = [
            crate::set::bernstein::bezier_matrix(knots[0].as_slice(), p, spans[0]),
            crate::set::bernstein::bezier_matrix(knots[1].as_slice(), q, spans[1]),
        ];
        let first = [spans[0] - p, spans[1] - q];
        let local = |f: &dyn Fn(usize) -> f64| -> Vec<f64> {
            let c: Vec<f64> = (0..ku * kv)
                .map(|l| f((first[0] + l / kv) * nv + first[1] + l % kv))
                .collect();
            tensor(&bezier[0], &c, &bezier[1], ku, kv)
        };
        let plan = [
            local(&|k| weights[k]),
            local(&|k| weights[k] * xy[k][0]),
            local(&|k| weights[k] * xy[k][1]),
        ];
        let w0 = weights[first[0] * nv + first[1]];
        let polynomial =
            (0..ku * kv).all(|l| weights[(first[0] + l / kv) * nv + first[1] + l % kv] == w0);
        let binomial = |n: usize, k: usize| -> f64 {
            (0..k).fold(1.0, |c, j| c * (n - j) as f64 / (j + 1) as f64)
        };
        let mut to_power = vec![0.0; kv * kv];
        for k in 0..kv {
            for i in 0..=k {
                let sign = if (k - i) % 2 == 0 { 1.0 } else { -1.0 };
                to_power[k * kv + i] = binomial(q, k) * binomial(k, i) * sign;
            }
        }
        Patch {
            orders: [ku, kv],
            plan,
            bezier,
            polynomial,
            to_power,
        }
    }

    /// Whether the weights of the span are equal (the integrands are
    /// polynomials).
    pub(crate) fn polynomial(&self) -> bool {
        self.polynomial
    }

    /// The Bernstein coefficients of `P = W·(z − z₀)` from the local
    /// B-spline coefficients `w·(z − z₀)`.
    pub(crate) fn heights(&self, local: &[f64]) -> Vec<f64> {
        let [ku, kv] = self.orders;
        tensor(&self.bezier[0], local, &self.bezier[1], ku, kv)
    }

    /// `[V, A]` below the datum on the span, from `P`'s Bernstein
    /// coefficients, and their error estimates; `tolerance` is the absolute
    /// error aimed at for each.
    pub(crate) fn below(
        &self,
        p: &[f64],
        rules: &Rules,
        tolerance: [f64; 2],
        scratch: &mut Scratch,
    ) -> ([f64; 2], [f64; 2]) {
        let [ku, kv] = self.orders;
        let edge = |b: usize| -> Vec<f64> { (0..ku).map(|a| p[a * kv + b]).collect() };
        // Where the integrand is not smooth: 0 ends, 1 a meeting of roots.
        let mut cuts: Vec<(f64, bool)> = vec![(0.0, false), (1.0, false)];
        for b in [0, kv - 1] {
            cuts.extend(
                sign_changes_in_unit(&edge(b))
                    .into_iter()
                    .map(|s| (s, false)),
            );
        }
        let found = if one_sign(p) {
            Vec::new()
        } else {
            meetings(p, [ku, kv])
        };
        let inside = |m: &Meeting| (0.0..=1.0).contains(&m.s) && (0.0..=1.0).contains(&m.t);
        cuts.extend(found.iter().filter(|m| inside(m)).map(|m| (m.s, true)));
        // Meetings outside the square, near a piece: a change of variable
        // that takes them away too.
        let nearby: Vec<f64> = found.iter().filter(|m| !inside(m)).map(|m| m.s).collect();
        cuts.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut merged: Vec<(f64, bool)> = Vec::with_capacity(cuts.len());
        for c in cuts {
            match merged.last_mut() {
                Some(last) if c.0 - last.0 <= 1e-13 => last.1 |= c.1,
                _ => merged.push(c),
            }
        }
        // The span's greatest depth |z − z₀| (the tolerances' ratio).
        let reach = if tolerance[1] > 0.0 {
            tolerance[0] / tolerance[1]
        } else {
            0.0
        };
        let Scratch { columns, basis } = scratch;
        let mut f = |s: f64| -> ([f64; 2], [f64; 2]) {
            self.contract(p, s, columns, basis);
            self.across(columns, rules, reach)
        };
        let (mut value, mut error) = ([0.0; 2], [0.0; 2]);
        let mut budget = BUDGET;
        for w in merged.windows(2) {
            let ((a, sa), (b, sb)) = (w[0], w[1]);
            if b <= a {
                continue;
            }
            let margin = 0.5 * (b - a);
            let near = |x: f64, side: f64| {
                nearby
                    .iter()
                    .copied()
                    .filter(|&m| (m - x) * side >= 0.0 && (m - x).abs() <= margin)
                    .min_by(|m, n| (m - x).abs().total_cmp(&(n - x).abs()))
            };
            let left = if sa { Some(a) } else { near(a, -1.0) };
            let right = if sb { Some(b) } else { near(b, 1.0) };
            let maps: Vec<([f64; 2], Map)> = match (left, right) {
                (Some(l), Some(r)) => {
                    let m = 0.5 * (a + b);
                    vec![([a, m], Map::From(l)), ([m, b], Map::To(r))]
                }
                (Some(l), None) => vec![([a, b], Map::From(l))],
                (None, Some(r)) => vec![([a, b], Map::To(r))],
                (None, None) => vec![([a, b], Map::Linear)],
            };
            for ([a, b], map) in maps {
                let share = [tolerance[0] * (b - a), tolerance[1] * (b - a)];
                let (v, e) = piece(
                    &mut f,
                    [a, b],
                    map,
                    map.range([a, b]),
                    share,
                    0,
                    &mut budget,
                );
                for k in 0..2 {
                    value[k] += v[k];
                    error[k] += e[k];
                }
            }
        }
        (value, error)
    }

    /// Contracts the patch along s at `s` into `columns`.
    fn contract(&self, p: &[f64], s: f64, c: &mut Columns, (bu, du): &mut (Vec<f64>, Vec<f64>)) {
        let [ku, kv] = self.orders;
        bernstein(s, bu, du);
        for b in 0..kv {
            let mut v = [0.0; 4];
            let mut d = [0.0; 3];
            for a in 0..ku {
                let l = a * kv + b;
                for k in 0..3 {
                    v[k] += bu[a] * self.plan[k][l];
                    d[k] += du[a] * self.plan[k][l];
                }
                v[3] += bu[a] * p[l];
            }
            for (column, x) in c.value.iter_mut().zip(v) {
                column[b] = x;
            }
            for (column, x) in c.slope.iter_mut().zip(d) {
                column[b] = x;
            }
        }
        for (power, bernstein) in c.power.iter_mut().zip(c.value.iter().chain(&c.slope)) {
            for (k, out) in power.iter_mut().enumerate() {
                *out = (0..=k)
                    .map(|i| self.to_power[k * kv + i] * bernstein[i])
                    .sum();
            }
        }
    }

    /// `[∫ (z₀ − z)|J| dt, ∫ |J| dt]` over the t where `P < 0`, at the
    /// contracted `s`, and their error estimates.
    fn across(&self, c: &mut Columns, rules: &Rules, reach: f64) -> ([f64; 2], [f64; 2]) {
        let mut cuts = std::mem::take(&mut c.cuts);
        cuts.clear();
        cuts.push(0.0);
        sign_changes_power_into(&c.value[3], &c.power[3], &mut cuts);
        cuts.push(1.0);
        let (mut value, mut error) = ([0.0; 2], [0.0; 2]);
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b <= a || horner(&c.power[3], 0.5 * (a + b)) >= 0.0 {
                continue;
            }
            let (v, e) = if self.polynomial {
                (gauss_polynomial(c, &rules.exact, [a, b]), [0.0; 2])
            } else {
                inner_piece(c, rules, [a, b], reach, 0)
            };
            for k in 0..2 {
                value[k] += v[k];
                error[k] += e[k];
            }
        }
        c.cuts = cuts;
        (value, error)
    }
}

/// A Gauss rule over `[a, b]` in t of `[(z₀ − z)|J|, |J|]`.
fn gauss(c: &Columns, rule: &(Vec<f64>, Vec<f64>), [a, b]: [f64; 2]) -> [f64; 2] {
    let h = 0.5 * (b - a);
    let mut out = [0.0; 2];
    // Horner's rule: the value and the slope.
    let horner = |p: &[f64], t: f64| -> (f64, f64) {
        p.iter()
            .rev()
            .fold((0.0, 0.0), |(v, d), &x| (v * t + x, d * t + v))
    };
    for (x, wt) in rule.0.iter().zip(&rule.1) {
        let t = a + h * (x + 1.0);
        let (w, w_t) = horner(&c.power[0], t);
        let (wx, wx_t) = horner(&c.power[1], t);
        let (wy, wy_t) = horner(&c.power[2], t);
        let (p, _) = horner(&c.power[3], t);
        let (w_s, _) = horner(&c.power[4], t);
        let (wx_s, _) = horner(&c.power[5], t);
        let (wy_s, _) = horner(&c.power[6], t);
        let (x, y) = (wx / w, wy / w);
        let (x_s, y_s) = ((wx_s - x * w_s) / w, (wy_s - y * w_s) / w);
        let (x_t, y_t) = ((wx_t - x * w_t) / w, (wy_t - y * w_t) / w);
        let j = (x_s * y_t - x_t * y_s).abs() * wt * h;
        out[0] += (-p / w).max(0.0) * j;
        out[1] += j;
    }
    out
}

/// [`gauss`] where the span's weights are equal: `W` is the constant
/// `w`, so `x = W·x/w` and `J = ((W·x)_s·(W·y)_t − (W·x)_t·(W·y)_s)/w²`
/// (four polynomials in t instead of seven).
fn gauss_polynomial(c: &Columns, rule: &(Vec<f64>, Vec<f64>), [a, b]: [f64; 2]) -> [f64; 2] {
    let h = 0.5 * (b - a);
    let w = c.power[0].first().copied().unwrap_or(1.0);
    let scale = h / (w * w);
    let mut out = [0.0; 2];
    let horner = |p: &[f64], t: f64| -> (f64, f64) {
        p.iter()
            .rev()
            .fold((0.0, 0.0), |(v, d), &x| (v * t + x, d * t + v))
    };
    let value = |p: &[f64], t: f64| p.iter().rev().fold(0.0, |v, &x| v * t + x);
    for (x, wt) in rule.0.iter().zip(&rule.1) {
        let t = a + h * (x + 1.0);
        let (_, wx_t) = horner(&c.power[1], t);
        let (_, wy_t) = horner(&c.power[2], t);
        let p = value(&c.power[3], t);
        let wx_s = value(&c.power[5], t);
        let wy_s = value(&c.power[6], t);
        let j = (wx_s * wy_t - wx_t * wy_s).abs() * wt * scale;
        out[0] += (-p / w).max(0.0) * j;
        out[1] += j;
    }
    out
}

/// A rational inner integrand: the 16-point rule against the 8-point one,
/// halved (to depth 8) where they differ by more than `10⁻¹²` of the value
/// or of the piece's plan area (times `reach`, the span's greatest depth,
/// for the volume).
fn inner_piece(
    c: &Columns,
    rules: &Rules,
    [a, b]: [f64; 2],
    reach: f64,
    depth: u32,
) -> ([f64; 2], [f64; 2]) {
    let fine = gauss(c, &rules.fine, [a, b]);
    let coarse = gauss(c, &rules.coarse, [a, b]);
    let error = [(fine[0] - coarse[0]).abs(), (fine[1] - coarse[1]).abs()];
    let m = 0.5 * (a + b);
    // Relative to the value, or to the piece's plan area (times the
    // span's greatest depth for the volume), whichever is larger.
    let floor = [fine[1].abs() * reach, fine[1].abs()];
    let met = |k: usize| error[k] <= 1e-12 * fine[k].abs().max(floor[k]);
    if (met(0) && met(1)) || depth >= 8 || !(a < m && m < b) {
        return (fine, error);
    }
    let (l, el) = inner_piece(c, rules, [a, m], reach, depth + 1);
    let (r, er) = inner_piece(c, rules, [m, b], reach, depth + 1);
    ([l[0] + r[0], l[1] + r[1]], [el[0] + er[0], el[1] + er[1]])
}

/// The variable `σ` a piece `[a, b]` of `[0, 1]` in s is integrated in:
/// `s = a + (b − a)·σ`, or away from a meeting of roots at `c` before the
/// piece, `s = c + σ²`, or after it, `s = c − σ²`; then the square root
/// that `F` has at `c` is a smooth function of `σ`.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Map {
    Linear,
    From(f64),
    To(f64),
}

impl Map {
    /// The range of `σ` for `[a, b]`.
    fn range(self, [a, b]: [f64; 2]) -> [f64; 2] {
        match self {
            Map::Linear => [0.0, 1.0],
            Map::From(c) => [(a - c).max(0.0).sqrt(), (b - c).max(0.0).sqrt()],
            Map::To(c) => [(c - b).max(0.0).sqrt(), (c - a).max(0.0).sqrt()],
        }
    }

    /// `s` and `|ds/dσ|` at `σ`.
    fn at(self, [a, b]: [f64; 2], sigma: f64) -> (f64, f64) {
        match self {
            Map::Linear => (a + (b - a) * sigma, b - a),
            Map::From(c) => (c + sigma * sigma, 2.0 * sigma),
            Map::To(c) => (c - sigma * sigma, 2.0 * sigma),
        }
    }
}

/// `∫ F` over `[a, b]` in s, by `σ ∈ range` of `map`, halved where the
/// Kronrod rule misses `tolerance`. Inner errors are added, times the width.
fn piece(
    f: &mut impl FnMut(f64) -> ([f64; 2], [f64; 2]),
    [a, b]: [f64; 2],
    map: Map,
    [t0, t1]: [f64; 2],
    tolerance: [f64; 2],
    depth: u32,
    budget: &mut usize,
) -> ([f64; 2], [f64; 2]) {
    *budget = budget.saturating_sub(1);
    let mut inner = [0.0_f64; 2];
    let (value, error) = kronrod_vector(
        |sigma| {
            let (s, ds) = map.at([a, b], sigma);
            let (v, e) = f(s.clamp(a, b));
            for k in 0..2 {
                inner[k] = inner[k].max(e[k] * ds);
            }
            [v[0] * ds, v[1] * ds]
        },
        t0,
        t1,
    );
    let m = 0.5 * (t0 + t1);
    // Halving helps the rule's error, not the inner integrals' (relative
    // to their values): only the former decides.
    if (error[0] <= tolerance[0] && error[1] <= tolerance[1])
        || depth >= MAX_DEPTH
        || *budget == 0
        || !(t0 < m && m < t1)
    {
        let error = [
            error[0] + inner[0] * (t1 - t0),
            error[1] + inner[1] * (t1 - t0),
        ];
        return (value, error);
    }
    let half = [0.5 * tolerance[0], 0.5 * tolerance[1]];
    let (l, el) = piece(f, [a, b], map, [t0, m], half, depth + 1, budget);
    let (r, er) = piece(f, [a, b], map, [m, t1], half, depth + 1, budget);
    ([l[0] + r[0], l[1] + r[1]], [el[0] + er[0], el[1] + er[1]])
}

/// Whether the coefficients keep one strict sign.
fn one_sign(c: &[f64]) -> bool {
    c.iter().all(|&x| x > 0.0) || c.iter().all(|&x| x < 0.0)
}

/// Where roots of `P(s, ·)` meet: `P = P_t = 0` at `(s, t)`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Meeting {
    s: f64,
    t: f64,
}

/// The region searched for meetings: beyond the square too, as one just
/// outside slows the integration of the pieces next to it.
const SEARCHED: [[f64; 2]; 2] = [[-0.125, 1.125], [-0.25, 1.25]];

/// The points of [`SEARCHED`] where `P = P_t = 0` (module docs); `p` is
/// `P`'s Bernstein coefficients, `ku × kv`.
fn meetings(p: &[f64], [ku, kv]: [usize; 2]) -> Vec<Meeting> {
    if kv < 2 {
        return Vec::new();
    }
    let q = (kv - 1) as f64;
    let pt: Vec<f64> = (0..ku)
        .flat_map(|a| (0..kv - 1).map(move |b| (a, b)))
        .map(|(a, b)| q * (p[a * kv + b + 1] - p[a * kv + b]))
        .collect();
    let mut out = Vec::new();
    search(p, &pt, [ku, kv], SEARCHED, 0, &mut out);
    out
}

/// `c` (`ku × kv`, Bernstein on the unit square) on the box `[s, t]`, which
/// may reach beyond the square (de Casteljau's steps extrapolate).
fn on_box(c: &[f64], [ku, kv]: [usize; 2], [s, t]: [[f64; 2]; 2]) -> Vec<f64> {
    let mut c = c.to_vec();
    for b in 0..kv {
        reparametrise(&mut c[b..], kv, ku, s);
    }
    for a in 0..ku {
        reparametrise(&mut c[a * kv..], 1, kv, t);
    }
    c
}

/// The Bernstein coefficients (`count`, every `stride`-th) of a polynomial
/// on `[0, 1]` rewritten for `[s0, s1]`: de Casteljau at `s0` keeping the
/// right part, then at the matching point of that part keeping the left.
fn reparametrise(c: &mut [f64], stride: usize, count: usize, [s0, s1]: [f64; 2]) {
    if s0 != 0.0 {
        for r in 1..count {
            for j in 0..count - r {
                c[j * stride] = (1.0 - s0) * c[j * stride] + s0 * c[(j + 1) * stride];
            }
        }
    }
    let s = (s1 - s0) / (1.0 - s0);
    if s != 1.0 {
        for r in 1..count {
            for j in (r..count).rev() {
                c[j * stride] = (1.0 - s) * c[(j - 1) * stride] + s * c[j * stride];
            }
        }
    }
}

fn search(
    p: &[f64],
    pt: &[f64],
    [ku, kv]: [usize; 2],
    range: [[f64; 2]; 2],
    depth: u32,
    out: &mut Vec<Meeting>,
) {
    if one_sign(&on_box(p, [ku, kv], range)) || one_sign(&on_box(pt, [ku, kv - 1], range)) {
        return;
    }
    let [[s0, s1], [t0, t1]] = range;
    if depth >= NEWTON_DEPTH {
        if let Some(m) = newton(p, pt, [ku, kv], [0.5 * (s0 + s1), 0.5 * (t0 + t1)]) {
            if !out
                .iter()
                .any(|o: &Meeting| (o.s - m.s).abs() + (o.t - m.t).abs() <= 1e-12)
            {
                out.push(m);
            }
            return;
        }
        if depth >= SEARCH_DEPTH {
            return;
        }
    }
    let (sm, tm) = (0.5 * (s0 + s1), 0.5 * (t0 + t1));
    for s in [[s0, sm], [sm, s1]] {
        for t in [[t0, tm], [tm, t1]] {
            search(p, pt, [ku, kv], [s, t], depth + 1, out);
        }
    }
}

/// Newton's method on `P = P_t = 0` from `start`: the point of
/// [`SEARCHED`] where it converges.
fn newton(p: &[f64], pt: &[f64], [ku, kv]: [usize; 2], start: [f64; 2]) -> Option<Meeting> {
    let [mut s, mut t] = start;
    let [[sa, sb], [ta, tb]] = SEARCHED;
    for _ in 0..30 {
        let [f, f_s, f_t] = value_and_slopes(p, [ku, kv], s, t);
        let [g, g_s, g_t] = value_and_slopes(pt, [ku, kv - 1], s, t);
        let det = f_s * g_t - f_t * g_s;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let ds = (f * g_t - f_t * g) / det;
        let dt = (f_s * g - f * g_s) / det;
        s -= ds;
        t -= dt;
        if !(sa..=sb).contains(&s) || !(ta..=tb).contains(&t) {
            return None;
        }
        if ds.abs() <= 1e-15 && dt.abs() <= 1e-15 {
            return Some(Meeting { s, t });
        }
    }
    None
}
