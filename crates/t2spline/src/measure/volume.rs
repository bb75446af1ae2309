//! The volumes between a surface of crisp plan and the plane `z = z₀`, and
//! the plan area below it (docs/method.md §14), for one net of heights.
//!
//! Over the plan `P`, with the plan map `(u, v) ↦ (x, y)` one to one and
//! `J` its Jacobian,
//!
//! ```text
//! V_below = ∫∫_P max(z₀ − z, 0) dx dy = ∫∫ max(z₀ − z(u, v), 0)·|J| du dv
//! V_above = ∫∫_P max(z − z₀, 0) dx dy,   A_below = ∫∫_P [z < z₀] dx dy
//! V_above − V_below = Σₖ Mₖ·zₖ − z₀·A,   Mₖ = ∫∫ Rₖ·|J|,  A = ∫∫ |J|
//! ```
//! On a span rectangle where every height acting there is on one side of
//! `z₀`, so is the surface (`z` is a convex combination of them), and its
//! part is the moments' sum: `Mₖ` and `A` exactly by a Gauss rule of
//! `⌈3p/2⌉ × ⌈3q/2⌉` points where the span's weights are equal (then
//! `Rₖ·|J|` is a polynomial of degrees `(3p − 1, 3q − 1)`), else by a
//! 16 × 16 Gauss rule, the difference from an 8 × 8 rule the error estimate
//! (the rectangle cut in four where they differ). A span rectangle whose Bernstein coefficients of
//! `W·(z − z₀)` keep one strict sign is on one side too. On the others
//! (those the datum crosses) the part below is integrated in the span's
//! Bernstein form (`crossing.rs`), to `10⁻¹⁰` of the span's plan area times
//! its greatest depth.

use crate::cubature::gauss_legendre;
use crate::measure::crossing::{Patch, Rules, Scratch};
use crate::measure::plan::{Basis1, Plan};

/// The relative tolerance aimed at by the volumes and the plan area.
pub const VOLUME_TOLERANCE: f64 = 1e-9;
/// The error aimed at on a span rectangle the datum crosses, relative to
/// its plan area (times its greatest depth for the volume): summed, `10⁻¹⁰`
/// of the plan area times the greatest depth.
const CROSSING_TOLERANCE: f64 = 1e-10;

/// The moments of one span rectangle.
#[derive(Clone, Debug)]
struct SpanMoments {
    first: [usize; 2],
    /// `Mₖ` of its local functions by the fine and the coarse rule.
    fine: Vec<f64>,
    coarse: Vec<f64>,
    /// `A` by each rule.
    area: [f64; 2],
}

impl SpanMoments {
    /// The largest `|zₖ − z₀|` of the heights acting on the span.
    fn depth(&self, z: &[f64], datum: f64, nv: usize, kv: usize) -> f64 {
        (0..self.fine.len())
            .map(|l| (z[(self.first[0] + l / kv) * nv + self.first[1] + l % kv] - datum).abs())
            .fold(0.0, f64::max)
    }
}

/// What one net gives: `[value, error bound]` of each quantity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Volumes {
    pub(crate) below: [f64; 2],
    pub(crate) above: [f64; 2],
    pub(crate) plan_below: [f64; 2],
}

/// The moments of a plan, shared by every net and level.
#[derive(Clone, Debug)]
pub(crate) struct VolumeForm {
    pub(crate) plan: Plan,
    spans: Vec<SpanMoments>,
    /// The Bernstein form of each span rectangle.
    patches: Vec<Patch>,
    /// The plan area, with its error estimate.
    pub(crate) area: [f64; 2],
    rules: Rules,
}

/// `∫∫ Rₖ|J|` and `∫∫ |J|` over `range` by the tensor Gauss rule `g × h`.
fn moments(
    plan: &Plan,
    spans: [usize; 2],
    [[u0, u1], [v0, v1]]: [[f64; 2]; 2],
    g: &(Vec<f64>, Vec<f64>),
    h: &(Vec<f64>, Vec<f64>),
) -> (Vec<f64>, f64) {
    let [ku, kv] = plan.orders();
    let mut m = vec![0.0; ku * kv];
    let mut area = 0.0;
    let (hu, hv) = (0.5 * (u1 - u0), 0.5 * (v1 - v0));
    let bvs: Vec<Basis1> =
        h.0.iter()
            .map(|t| Basis1::at(&plan.knots[1], spans[1], v0 + hv * (t + 1.0)))
            .collect();
    for (s, ws) in g.0.iter().zip(&g.1) {
        let bu = Basis1::at(&plan.knots[0], spans[0], u0 + hu * (s + 1.0));
        for (bv, wt) in bvs.iter().zip(&h.1) {
            let local = plan.local(&bu, bv);
            let w = ws * wt * hu * hv * local.jacobian().abs();
            area += w;
            for (mk, r) in m.iter_mut().zip(&local.r) {
                *mk += w * r;
            }
        }
    }
    (m, area)
}

/// The moments by the 16 × 16 rule and the 8 × 8 one, the rectangle cut in
/// four (to depth 4) where they differ by more than `10⁻¹³` of the area (a
/// rational basis with poles near the span); the coarse moments are the
/// fine ones plus the leaves' differences, so that their difference is the
/// error estimate.
fn adaptive_moments(
    plan: &Plan,
    spans: [usize; 2],
    range: [[f64; 2]; 2],
    gauss16: &(Vec<f64>, Vec<f64>),
    gauss8: &(Vec<f64>, Vec<f64>),
    depth: u32,
) -> (Vec<f64>, Vec<f64>, [f64; 2]) {
    let (fine, a) = moments(plan, spans, range, gauss16, gauss16);
    let (coarse, c) = moments(plan, spans, range, gauss8, gauss8);
    let agree = fine
        .iter()
        .zip(&coarse)
        .all(|(f, c)| (f - c).abs() <= 1e-13 * a.abs())
        && (a - c).abs() <= 1e-13 * a.abs();
    if agree || depth >= 4 {
        return (fine, coarse, [a, c]);
    }
    let [[u0, u1], [v0, v1]] = range;
    let (um, vm) = (0.5 * (u0 + u1), 0.5 * (v0 + v1));
    let mut out = (vec![0.0; fine.len()], vec![0.0; fine.len()], [0.0; 2]);
    for r in [
        [[u0, um], [v0, vm]],
        [[um, u1], [v0, vm]],
        [[u0, um], [vm, v1]],
        [[um, u1], [vm, v1]],
    ] {
        let (f, c, a) = adaptive_moments(plan, spans, r, gauss16, gauss8, depth + 1);
        for (o, x) in out.0.iter_mut().zip(&f) {
            *o += x;
        }
        for (o, x) in out.1.iter_mut().zip(&c) {
            *o += x;
        }
        out.2[0] += a[0];
        out.2[1] += a[1];
    }
    out
}

impl VolumeForm {
    /// The moments of every span rectangle of `plan`.
    pub(crate) fn new(plan: Plan) -> Self {
        let (gauss16, gauss8) = (gauss_legendre(16), gauss_legendre(8));
        let q = plan.knots[1].degree();
        let patches: Vec<Patch> = plan
            .spans
            .iter()
            .map(|&(spans, _)| Patch::new(&plan.knots, spans, &plan.weights, &plan.xy, plan.nv))
            .collect();
        // Equal weights on a span: `Rₖ·|J|` is a polynomial of degrees
        // `(3p − 1, 3q − 1)` (`J` keeps its sign), which Gauss rules of
        // `⌈3p/2⌉ × ⌈3q/2⌉` points integrate exactly.
        let exact = [
            gauss_legendre((3 * plan.knots[0].degree()).div_ceil(2).max(1)),
            gauss_legendre((3 * q).div_ceil(2).max(1)),
        ];
        let mut area = [0.0; 2];
        let spans = plan
            .spans
            .iter()
            .zip(&patches)
            .map(|(&(spans, range), patch)| {
                let (fine, coarse, a) = if patch.polynomial() {
                    let (m, a) = moments(&plan, spans, range, &exact[0], &exact[1]);
                    (m.clone(), m, [a, a])
                } else {
                    adaptive_moments(&plan, spans, range, &gauss16, &gauss8, 0)
                };
                area[0] += a[0];
                area[1] += (a[0] - a[1]).abs();
                SpanMoments {
                    first: [spans[0] - plan.knots[0].degree(), spans[1] - q],
                    fine,
                    coarse,
                    area: a,
                }
            })
            .collect();
        VolumeForm {
            plan,
            spans,
            patches,
            area,
            rules: Rules::new(q),
        }
    }

    /// The volumes and the plan area below `datum` of the heights `z` (one
    /// per control point).
    pub(crate) fn eval(&self, z: &[f64], datum: f64) -> Volumes {
        let [ku, kv] = self.plan.orders();
        let nv = self.plan.nv;
        let (mut below, mut above, mut plan_below) = ([0.0; 2], [0.0; 2], [0.0; 2]);
        let mut local = vec![0.0; ku * kv];
        let mut scratch = Scratch::new([ku, kv]);
        for (s, patch) in self.spans.iter().zip(&self.patches) {
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            let (mut fine, mut coarse) = (0.0, 0.0);
            for (l, c) in local.iter_mut().enumerate() {
                let k = (s.first[0] + l / kv) * nv + s.first[1] + l % kv;
                let zk = z[k];
                lo = lo.min(zk);
                hi = hi.max(zk);
                fine += s.fine[l] * zk;
                coarse += s.coarse[l] * zk;
                *c = self.plan.weights[k] * (zk - datum);
            }
            let (value, error) = (
                fine - datum * s.area[0],
                (fine - coarse - datum * (s.area[0] - s.area[1])).abs(),
            );
            let area_error = (s.area[0] - s.area[1]).abs();
            // Above or below throughout: by the control heights, else by
            // the tighter Bernstein coefficients of W·(z − z₀).
            let side = if lo >= datum {
                Some(true)
            } else if hi < datum {
                Some(false)
            } else {
                None
            };
            let (side, bernstein) = match side {
                Some(side) => (Some(side), None),
                None => {
                    let b = patch.heights(&local);
                    if b.iter().all(|&x| x > 0.0) {
                        (Some(true), None)
                    } else if b.iter().all(|&x| x < 0.0) {
                        (Some(false), None)
                    } else {
                        (None, Some(b))
                    }
                }
            };
            match (side, bernstein) {
                (Some(true), _) => {
                    above[0] += value;
                    above[1] += error;
                }
                (Some(false), _) => {
                    below[0] -= value;
                    below[1] += error;
                    plan_below[0] += s.area[0];
                    plan_below[1] += area_error;
                }
                (None, b) => {
                    let b = b.unwrap_or_default();
                    let depth = s.depth(z, datum, nv, kv);
                    let tolerance = [
                        CROSSING_TOLERANCE * depth * s.area[0],
                        CROSSING_TOLERANCE * s.area[0],
                    ];
                    let (v, e) = patch.below(&b, &self.rules, tolerance, &mut scratch);
                    // V_above = V_below + value on this span.
                    below[0] += v[0];
                    below[1] += e[0];
                    above[0] += value + v[0];
                    above[1] += error + e[0];
                    plan_below[0] += v[1];
                    plan_below[1] += e[1];
                }
            }
        }
        let rounding = |x: [f64; 2], n: f64| [x[0], x[1] + 64.0 * n * f64::EPSILON * x[0].abs()];
        let n = self.spans.len() as f64;
        Volumes {
            below: rounding([below[0].max(0.0), below[1]], n),
            above: rounding([above[0].max(0.0), above[1]], n),
            plan_below: rounding([plan_below[0].max(0.0), plan_below[1]], n),
        }
    }
}
