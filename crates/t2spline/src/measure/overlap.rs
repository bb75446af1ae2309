//! The cut and fill between two surfaces of crisp plan whose plan maps
//! differ, over the overlap of their plans (docs/method.md §14), for one
//! net of heights of each.
//!
//! With `P₁`, `P₂` the plans, `ξ = (plan map 2)⁻¹ ∘ (plan map 1)` taking
//! the first surface's parameters to the second's over the same `(x, y)`,
//! and `D₂` the second's parameter rectangle,
//!
//! ```text
//! cut  = ∫∫_{P₁∩P₂} max(z₁ − z₂, 0) dx dy = ∫∫ max(z₁(u, v) − z₂(ξ(u, v)), 0)·[ξ ∈ D₂]·|J₁| du dv
//! fill = ∫∫_{P₁∩P₂} max(z₂ − z₁, 0) dx dy   (likewise)
//! ```
//! over the first surface's span rectangles (those whose control points'
//! box misses the second plan's box hold nothing). `ξ` is found by Newton's
//! method on the second plan map (one to one, `Plan::check_graph`), from
//! the last point found, else from the nearest of a table of its points;
//! beyond `D₂` the end spans' polynomials are extended, so that `ξ` of a
//! point just outside lands just outside `D₂`.
//!
//! For each `u` the integral over `v` is cut where `ξ` enters or leaves
//! `D₂`, where `z₁ − z₂` changes sign and where `ξ` crosses a knot line of
//! the second surface: the places where any of these changes between 9
//! equally spaced samples of the span are found by bisection to adjacent
//! floats; between them the integrand is smooth, and a 16-point Gauss rule
//! is taken with its difference from an 8-point one as the error estimate
//! (halved where they differ). Over `u`, each span is integrated by the
//! 15-point Kronrod rule with QUADPACK's error estimate, halved until it
//! meets its share of the tolerance (`10⁻¹⁰` of the span's plan area times
//! the greatest `|z₁ − z₂|`), or a budget of rules is spent; the error
//! estimates are added up and reported. Two changes between neighbouring
//! samples that undo each other (the overlap's boundary or the contour
//! `z₁ = z₂` just touching a sample interval) are not seen at that `u`:
//! they show in the error estimates over `u`, which keep halving there.

use crate::cubature::gauss_legendre;
use crate::measure::inverse::Inverse;
use crate::measure::plan::Plan;
use crate::quadrature::kronrod_vector;

/// The share of the tolerance per span rectangle of the first surface,
/// relative to its plan area times the greatest `|z₁ − z₂|`.
const SPAN_TOLERANCE: f64 = 1e-10;
/// Samples along v per span rectangle, ends included.
const SAMPLES: usize = 9;
/// Halvings at most of a span in u.
const MAX_DEPTH: u32 = 30;
/// Kronrod rules at most per span rectangle.
const BUDGET: usize = 400;
/// Changes at most found between two neighbouring samples.
const MAX_CHANGES: usize = 16;

/// The second surface's plan, inverted, against the first's.
#[derive(Clone, Debug)]
pub(crate) struct Overlap {
    one: Inverse,
    two: Inverse,
    /// Per span rectangle of the first plan: whether its control points'
    /// box meets the second plan's, and its plan area.
    spans: Vec<(bool, f64)>,
    /// The u (first plan) where the integral over v may jump or kink.
    breaks: Vec<f64>,
    gauss: [(Vec<f64>, Vec<f64>); 2],
}

/// What is known at one point of the first surface's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Sample {
    /// `[z₁ − z₂ > 0, z₁ − z₂ < 0]` where inside the second plan.
    side: [bool; 2],
    /// Inside the second plan, and the span rectangle of the second there.
    inside: Option<[usize; 2]>,
}

/// The box `[x_min, x_max, y_min, y_max]` of points.
fn bounding(points: impl Iterator<Item = [f64; 2]>) -> [f64; 4] {
    points.fold(
        [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, [x, y]| [b[0].min(x), b[1].max(x), b[2].min(y), b[3].max(y)],
    )
}

/// The u of the first plan's parameters where the integral over v may jump
/// or kink: where the second plan's boundary, carried into the first's
/// parameters, turns back in u or runs along v (a local extreme of u along
/// it, found by golden-section search between samples), where it meets the
/// first plan's boundary (by bisection), and its corners.
fn breaks(one: &Inverse, two: &Inverse) -> Vec<f64> {
    let [[a, b], [c, d]] = two.domain;
    let edges: [([f64; 2], [f64; 2], usize); 4] = [
        ([a, c], [a, d], 1),
        ([b, c], [b, d], 1),
        ([a, c], [b, c], 0),
        ([a, d], [b, d], 0),
    ];
    let mut out = Vec::new();
    let mut start = one.first();
    for (p, q, along) in edges {
        let count = 16 * two.plan.knots[along].spans().count().max(1);
        let mut at = |t: f64| -> Option<f64> {
            let uv = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            let (xy, _, _) = two.map(uv);
            let found = one.invert(xy, start)?;
            start = found;
            one.contains(found).then_some(found[0])
        };
        let samples: Vec<(f64, Option<f64>)> = (0..=count)
            .map(|i| {
                let t = i as f64 / count as f64;
                (t, at(t))
            })
            .collect();
        for (t, u) in [samples[0], samples[count]] {
            let _ = t;
            out.extend(u);
        }
        for w in samples.windows(2) {
            // Where the edge enters or leaves the first plan.
            if w[0].1.is_some() != w[1].1.is_some() {
                let (mut lo, mut hi) = (w[0].0, w[1].0);
                let inside_lo = w[0].1.is_some();
                let mut last = w[0].1.or(w[1].1);
                for _ in 0..60 {
                    let m = 0.5 * (lo + hi);
                    if !(lo < m && m < hi) {
                        break;
                    }
                    let u = at(m);
                    if u.is_some() == inside_lo {
                        lo = m;
                    } else {
                        hi = m;
                    }
                    last = u.or(last);
                }
                out.extend(last);
            }
        }
        for w in samples.windows(3) {
            let (Some(l), Some(m), Some(r)) = (w[0].1, w[1].1, w[2].1) else {
                continue;
            };
            if (m - l) * (r - m) > 0.0 {
                continue;
            }
            // A turn (or a run along v): the extreme of u near w[1].
            let sign = if m >= l && m >= r { 1.0 } else { -1.0 };
            let (mut lo, mut hi) = (w[0].0, w[2].0);
            let g = 0.5 * (5.0_f64.sqrt() - 1.0);
            let mut best = m;
            for _ in 0..60 {
                let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
                let (Some(f1), Some(f2)) = (at(x1), at(x2)) else {
                    break;
                };
                best = if sign * f1 > sign * best { f1 } else { best };
                best = if sign * f2 > sign * best { f2 } else { best };
                if sign * f1 >= sign * f2 {
                    hi = x2;
                } else {
                    lo = x1;
                }
                if hi - lo <= 1e-15 {
                    break;
                }
            }
            out.push(best);
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup_by(|x, y| (*x - *y).abs() <= 1e-14 * x.abs().max(y.abs()).max(1.0));
    out
}

impl Overlap {
    /// The overlap of the plans `one` and `two` (each one to one).
    pub(crate) fn new(one: Plan, two: Plan) -> Self {
        let box2 = bounding(two.xy.iter().copied());
        let [ku, kv] = one.orders();
        let (nodes, weights) = gauss_legendre(8);
        let spans = one
            .spans
            .iter()
            .map(|&(s, [[u0, u1], [v0, v1]])| {
                let first = [s[0] - (ku - 1), s[1] - (kv - 1)];
                let b = bounding(
                    (0..ku * kv).map(|l| one.xy[(first[0] + l / kv) * one.nv + first[1] + l % kv]),
                );
                let meets =
                    b[0] <= box2[1] && box2[0] <= b[1] && b[2] <= box2[3] && box2[2] <= b[3];
                let mut area = 0.0;
                for (x, wx) in nodes.iter().zip(&weights) {
                    for (y, wy) in nodes.iter().zip(&weights) {
                        let u = u0 + 0.5 * (u1 - u0) * (x + 1.0);
                        let v = v0 + 0.5 * (v1 - v0) * (y + 1.0);
                        let j = one.local_at(s, u, v).jacobian().abs();
                        area += 0.25 * wx * wy * (u1 - u0) * (v1 - v0) * j;
                    }
                }
                (meets, area)
            })
            .collect();
        let (one, two) = (Inverse::new(one), Inverse::new(two));
        let breaks = breaks(&one, &two);
        Overlap {
            one,
            two,
            spans,
            breaks,
            gauss: [gauss_legendre(16), gauss_legendre(8)],
        }
    }

    /// The sample at `(u, v)` in the first plan's span rectangle `spans`,
    /// with `z₁ − z₂` and `|J₁|`; `start` is updated to `ξ`.
    fn sample(
        &self,
        spans: [usize; 2],
        [u, v]: [f64; 2],
        [z1, z2]: [&[f64]; 2],
        start: &mut [f64; 2],
    ) -> (Sample, f64, f64) {
        let local = self.one.plan.local_at(spans, u, v);
        let j = local.jacobian().abs();
        let xy = self.one.plan.xy_of(&local);
        let outside = (
            Sample {
                side: [false; 2],
                inside: None,
            },
            0.0,
            j,
        );
        let Some(uv) = self.two.invert(xy, *start) else {
            return outside;
        };
        *start = uv;
        if !self.two.contains(uv) {
            return outside;
        }
        let (_, _, spans2) = self.two.map(uv);
        let local2 = self.two.plan.local_at(spans2, uv[0], uv[1]);
        let h1: f64 = (0..local.r.len())
            .map(|l| local.r[l] * z1[local.point(self.one.plan.nv, l)])
            .sum();
        let h2: f64 = (0..local2.r.len())
            .map(|l| local2.r[l] * z2[local2.point(self.two.plan.nv, l)])
            .sum();
        let diff = h1 - h2;
        (
            Sample {
                side: [diff > 0.0, diff < 0.0],
                inside: Some(spans2),
            },
            diff,
            j,
        )
    }

    /// The plan area of the overlap, and its error estimate: the cut of
    /// the heights 1 over 0.
    pub(crate) fn area(&self) -> ([f64; 1], [f64; 1]) {
        let (v, e) = self.cut_fill(
            &vec![1.0; self.one.plan.xy.len()],
            &vec![0.0; self.two.plan.xy.len()],
        );
        ([v[0]], [e[0]])
    }

    /// `[cut, fill]` of the heights `z1` (the first surface's, one per
    /// control point) over `z2` (the second's), and their error estimates.
    pub(crate) fn cut_fill(&self, z1: &[f64], z2: &[f64]) -> ([f64; 2], [f64; 2]) {
        let range = |z: &[f64]| {
            z.iter().fold([f64::INFINITY, f64::NEG_INFINITY], |r, &x| {
                [r[0].min(x), r[1].max(x)]
            })
        };
        let ([lo1, hi1], [lo2, hi2]) = (range(z1), range(z2));
        let reach = (hi1 - lo2).abs().max((hi2 - lo1).abs());
        let (mut value, mut error) = ([0.0; 2], [0.0; 2]);
        let mut start = self.two.first();
        for (&(spans, [[u0, u1], [v0, v1]]), &(meets, area)) in
            self.one.plan.spans.iter().zip(&self.spans)
        {
            if !meets {
                continue;
            }
            let tolerance = SPAN_TOLERANCE * area * reach;
            let mut f = |u: f64| -> ([f64; 2], [f64; 2]) {
                self.across(spans, u, [v0, v1], [z1, z2], reach, &mut start)
            };
            // The span cut at the breaks inside it, each part its share.
            let mut ends = vec![u0];
            ends.extend(self.breaks.iter().copied().filter(|&x| u0 < x && x < u1));
            ends.push(u1);
            for w in ends.windows(2) {
                let share = tolerance * (w[1] - w[0]) / (u1 - u0);
                let mut budget = BUDGET;
                let (v, e) = piece(&mut f, [w[0], w[1]], [share; 2], 0, &mut budget);
                for k in 0..2 {
                    value[k] += v[k];
                    error[k] += e[k];
                }
            }
        }
        let n = self.spans.len() as f64;
        for k in 0..2 {
            error[k] += 64.0 * n * f64::EPSILON * value[k].abs();
        }
        (value, error)
    }

    /// `[∫ max(z₁ − z₂, 0)|J₁| dv, ∫ max(z₂ − z₁, 0)|J₁| dv]` over `v ∈
    /// [v0, v1]` at `u`, where `ξ` lies in the second plan, and their error
    /// estimates.
    fn across(
        &self,
        spans: [usize; 2],
        u: f64,
        [v0, v1]: [f64; 2],
        z: [&[f64]; 2],
        reach: f64,
        start: &mut [f64; 2],
    ) -> ([f64; 2], [f64; 2]) {
        let mut at = |v: f64| self.sample(spans, [u, v], z, start).0;
        // The places where the sample changes.
        let mut cuts = vec![v0];
        let step = (v1 - v0) / (SAMPLES - 1) as f64;
        let mut left = at(v0);
        for i in 1..SAMPLES {
            let b = if i == SAMPLES - 1 {
                v1
            } else {
                v0 + step * i as f64
            };
            let right = at(b);
            // Bisection between the last place and `b`: `key` at `lo`,
            // another value at `hi`.
            let (mut lo, mut key) = (*cuts.last().unwrap_or(&v0), left);
            let mut found = 0;
            while key != right && found < MAX_CHANGES {
                let mut hi = b;
                loop {
                    let m = 0.5 * (lo + hi);
                    if !(lo < m && m < hi) {
                        break;
                    }
                    if at(m) == key {
                        lo = m;
                    } else {
                        hi = m;
                    }
                }
                cuts.push(hi);
                lo = hi;
                key = at(hi);
                found += 1;
            }
            if *cuts.last().unwrap_or(&v0) < b {
                cuts.push(b);
            }
            left = right;
        }
        cuts.dedup();
        let (mut value, mut error) = ([0.0; 2], [0.0; 2]);
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b <= a {
                continue;
            }
            let (v, e) = self.inner_piece(spans, u, [a, b], z, reach, start, 0);
            for k in 0..2 {
                value[k] += v[k];
                error[k] += e[k];
            }
        }
        (value, error)
    }

    /// A piece `[a, b]` of v where the sample keeps one value: the 16-point
    /// Gauss rule against the 8-point one, halved (to depth 6) where they
    /// differ by more than `10⁻¹²` of the value or of the piece's plan area
    /// times `reach`.
    #[allow(clippy::too_many_arguments)]
    fn inner_piece(
        &self,
        spans: [usize; 2],
        u: f64,
        [a, b]: [f64; 2],
        z: [&[f64]; 2],
        reach: f64,
        start: &mut [f64; 2],
        depth: u32,
    ) -> ([f64; 2], [f64; 2]) {
        let h = 0.5 * (b - a);
        let mut rule = |(nodes, weights): &(Vec<f64>, Vec<f64>)| {
            let (mut out, mut area) = ([0.0; 2], 0.0);
            for (x, w) in nodes.iter().zip(weights) {
                let (s, diff, j) = self.sample(spans, [u, a + h * (x + 1.0)], z, start);
                let wj = w * h * j;
                if s.inside.is_some() {
                    area += wj;
                }
                out[0] += diff.max(0.0) * wj;
                out[1] += (-diff).max(0.0) * wj;
            }
            (out, area)
        };
        let (fine, area) = rule(&self.gauss[0]);
        let (coarse, _) = rule(&self.gauss[1]);
        let error = [(fine[0] - coarse[0]).abs(), (fine[1] - coarse[1]).abs()];
        let m = 0.5 * (a + b);
        let met = |k: usize| error[k] <= 1e-12 * fine[k].abs().max(area * reach);
        if (met(0) && met(1)) || depth >= 6 || !(a < m && m < b) {
            return (fine, error);
        }
        let (l, el) = self.inner_piece(spans, u, [a, m], z, reach, start, depth + 1);
        let (r, er) = self.inner_piece(spans, u, [m, b], z, reach, start, depth + 1);
        ([l[0] + r[0], l[1] + r[1]], [el[0] + er[0], el[1] + er[1]])
    }
}

/// `∫ F` over `[a, b]` in u by the Kronrod rule, halved where it misses
/// `tolerance`; the inner errors are added, times the width.
fn piece(
    f: &mut impl FnMut(f64) -> ([f64; 2], [f64; 2]),
    [a, b]: [f64; 2],
    tolerance: [f64; 2],
    depth: u32,
    budget: &mut usize,
) -> ([f64; 2], [f64; 2]) {
    *budget = budget.saturating_sub(1);
    let mut inner = [0.0_f64; 2];
    let (value, error) = kronrod_vector(
        |u| {
            let (v, e) = f(u.clamp(a, b));
            for k in 0..2 {
                inner[k] = inner[k].max(e[k]);
            }
            v
        },
        a,
        b,
    );
    let m = 0.5 * (a + b);
    if (error[0] <= tolerance[0] && error[1] <= tolerance[1])
        || depth >= MAX_DEPTH
        || *budget == 0
        || !(a < m && m < b)
    {
        return (
            value,
            [error[0] + inner[0] * (b - a), error[1] + inner[1] * (b - a)],
        );
    }
    let half = [0.5 * tolerance[0], 0.5 * tolerance[1]];
    let (l, el) = piece(f, [a, m], half, depth + 1, budget);
    let (r, er) = piece(f, [m, b], half, depth + 1, budget);
    ([l[0] + r[0], l[1] + r[1]], [el[0] + er[0], el[1] + er[1]])
}
