//! The surface area of a surface of crisp plan over the box of its heights
//! (docs/method.md §14).
//!
//! With x and y crisp the normal `S_u × S_v` is affine in the heights:
//!
//! ```text
//! n = ( y_u·z_v − y_v·z_u,  x_v·z_u − x_u·z_v,  J ),   z_u = Σ Rₖ,u·zₖ,  z_v = Σ Rₖ,v·zₖ
//! A(z) = ∫∫ ‖n‖ du dv ≈ Σ_q w_q ‖(a_q·z, b_q·z, J_q)‖
//! ```
//! a sum of norms of affine maps, so **A is convex on the box of heights**
//! (as the curve's length, `length.rs`), and smooth where the plan map is
//! one to one (`‖n‖ ≥ |J| > 0`). The rule is 12 × 12 Gauss nodes per span
//! rectangle, cut in four (to depth 3) where the crisp surface's area needs
//! it; the difference from 6 × 6 at the two nets found is the error
//! estimate added to each end (an estimate, not a bound: a rational basis
//! with poles near a span may need more nodes than it shows).
//!
//! - **Least**: projected gradient with Barzilai–Borwein steps (Birgin,
//!   Martínez, Raydan 2000) from the crisp net; the certificate is the dual
//!   bound `Σ_q w_q min over the box of u_q·n_q(z)` with `u_q = n_q/‖n_q‖`
//!   at the iterate (`‖n‖ ≥ u·n`), a linear function whose minimum is read
//!   off the signs of its coefficients. Solved to `10⁻⁹` of the area, or
//!   the bracket `[bound, value]` is reported with its gap.
//! - **Greatest**: at a vertex of the box (convexity); every vertex in
//!   Gray-code order while the free heights are at most 16, else branch and
//!   bound (`vertices.rs`) with the bound `Σ_q w_q ‖(max |a_q·z|, max |b_q·z|, J_q)‖`
//!   over the node's box.

use crate::cubature::gauss_legendre;
use crate::measure::bracket::Bracket;
use crate::measure::cut_box::CutBox;
use crate::measure::plan::{Basis1, Plan};
use crate::measure::vertices::{local_search, maximize, VertexProblem};

/// Free heights at most for enumerating every vertex.
pub const MAX_ENUMERATED_SURFACE_AREA_VARIABLES: usize = 16;
/// The relative accuracy the least area is solved to.
pub const SURFACE_AREA_TOLERANCE: f64 = 1e-9;
/// Projected gradient steps at most.
const STEPS: usize = 500;
/// Node evaluations at most spent by branch and bound.
const BRANCH_WORK: usize = 50_000_000;

/// The area rule: per node its weight, `a_q`, `b_q` over the local points
/// and `J_q`.
#[derive(Clone, Debug)]
pub(crate) struct AreaRule {
    width: usize,
    nv: usize,
    columns: usize,
    first: Vec<[usize; 2]>,
    weight: Vec<f64>,
    a: Vec<f64>,
    b: Vec<f64>,
    jac: Vec<f64>,
    /// The same for the coarse rule.
    coarse: Option<Box<AreaRule>>,
    /// The nodes where each point acts.
    nodes_of: Vec<Vec<usize>>,
}

impl AreaRule {
    fn with(plan: &Plan, rectangles: &[([usize; 2], [[f64; 2]; 2])], n: usize) -> Self {
        let g = gauss_legendre(n);
        let [ku, kv] = plan.orders();
        let width = ku * kv;
        let mut rule = AreaRule {
            width,
            nv: plan.nv,
            columns: kv,
            first: Vec::new(),
            weight: Vec::new(),
            a: Vec::new(),
            b: Vec::new(),
            jac: Vec::new(),
            coarse: None,
            nodes_of: vec![Vec::new(); plan.xy.len()],
        };
        for &(spans, [[u0, u1], [v0, v1]]) in rectangles {
            let (hu, hv) = (0.5 * (u1 - u0), 0.5 * (v1 - v0));
            for (s, ws) in g.0.iter().zip(&g.1) {
                let bu = Basis1::at(&plan.knots[0], spans[0], u0 + hu * (s + 1.0));
                for (t, wt) in g.0.iter().zip(&g.1) {
                    let bv = Basis1::at(&plan.knots[1], spans[1], v0 + hv * (t + 1.0));
                    let l = plan.local(&bu, &bv);
                    let [xu, xv, yu, yv] = l.plan;
                    let q = rule.weight.len();
                    rule.weight.push(ws * wt * hu * hv);
                    rule.first.push(l.first);
                    rule.jac.push(l.jacobian());
                    for k in 0..width {
                        rule.a.push(yu * l.rv[k] - yv * l.ru[k]);
                        rule.b.push(xv * l.ru[k] - xu * l.rv[k]);
                        rule.nodes_of[l.point(plan.nv, k)].push(q);
                    }
                }
            }
        }
        rule
    }

    /// The fine rule with its coarse one, on the span rectangles cut where
    /// the crisp surface's area needs it ([`rectangles`]).
    pub(crate) fn new(plan: &Plan, crisp: &[f64]) -> Self {
        let mut rects = Vec::new();
        for &(spans, range) in &plan.spans {
            rectangles(plan, crisp, spans, range, 0, &mut rects);
        }
        let mut fine = Self::with(plan, &rects, 12);
        fine.coarse = Some(Box::new(Self::with(plan, &rects, 6)));
        fine
    }

    fn len(&self) -> usize {
        self.weight.len()
    }

    fn point(&self, q: usize, k: usize) -> usize {
        let f = self.first[q];
        (f[0] + k / self.columns) * self.nv + f[1] + k % self.columns
    }

    /// `(a_q·z, b_q·z)` at node `q`.
    fn normal(&self, q: usize, z: &[f64]) -> [f64; 2] {
        let w = self.width;
        let mut n = [0.0; 2];
        for k in 0..w {
            let zk = z[self.point(q, k)];
            n[0] += self.a[q * w + k] * zk;
            n[1] += self.b[q * w + k] * zk;
        }
        n
    }

    /// The area of the heights `z`.
    pub(crate) fn area(&self, z: &[f64]) -> f64 {
        (0..self.len())
            .map(|q| {
                let [a, b] = self.normal(q, z);
                self.weight[q] * norm3(a, b, self.jac[q])
            })
            .sum()
    }

    /// The area with the difference from the coarse rule: `[value, error]`.
    fn area_with_error(&self, z: &[f64]) -> [f64; 2] {
        let v = self.area(z);
        let c = self.coarse.as_ref().map_or(v, |c| c.area(z));
        [v, (v - c).abs() + 64.0 * f64::EPSILON * v]
    }
}

/// The area of the surface of heights `crisp` over `range` by the `n × n`
/// Gauss rule.
fn piece_area(
    plan: &Plan,
    crisp: &[f64],
    spans: [usize; 2],
    range: [[f64; 2]; 2],
    n: usize,
) -> f64 {
    let g = gauss_legendre(n);
    let [[u0, u1], [v0, v1]] = range;
    let (hu, hv) = (0.5 * (u1 - u0), 0.5 * (v1 - v0));
    let mut total = 0.0;
    for (s, ws) in g.0.iter().zip(&g.1) {
        let bu = Basis1::at(&plan.knots[0], spans[0], u0 + hu * (s + 1.0));
        for (t, wt) in g.0.iter().zip(&g.1) {
            let bv = Basis1::at(&plan.knots[1], spans[1], v0 + hv * (t + 1.0));
            let l = plan.local(&bu, &bv);
            let [xu, xv, yu, yv] = l.plan;
            let (mut zu, mut zv) = (0.0, 0.0);
            for k in 0..l.r.len() {
                let zk = crisp[l.point(plan.nv, k)];
                zu += l.ru[k] * zk;
                zv += l.rv[k] * zk;
            }
            let n = norm3(yu * zv - yv * zu, zu * xv - xu * zv, l.jacobian());
            total += ws * wt * hu * hv * n;
        }
    }
    total
}

/// The rectangles of the rule: a span rectangle is cut in four (to depth 3)
/// where the 12 × 12 and the 6 × 6 rule differ by more than `10⁻¹¹` of the
/// crisp surface's area there (a rational basis with poles near the span,
/// or a normal that nearly vanishes).
fn rectangles(
    plan: &Plan,
    crisp: &[f64],
    spans: [usize; 2],
    range: [[f64; 2]; 2],
    depth: u32,
    out: &mut Vec<([usize; 2], [[f64; 2]; 2])>,
) {
    let (fine, coarse) = (
        piece_area(plan, crisp, spans, range, 12),
        piece_area(plan, crisp, spans, range, 6),
    );
    if depth >= 3 || (fine - coarse).abs() <= 1e-11 * fine.abs() {
        out.push((spans, range));
        return;
    }
    let [[u0, u1], [v0, v1]] = range;
    let (um, vm) = (0.5 * (u0 + u1), 0.5 * (v0 + v1));
    for r in [
        [[u0, um], [v0, vm]],
        [[um, u1], [v0, vm]],
        [[u0, um], [vm, v1]],
        [[um, u1], [vm, v1]],
    ] {
        rectangles(plan, crisp, spans, r, depth + 1, out);
    }
}

fn norm3(a: f64, b: f64, c: f64) -> f64 {
    (a * a + b * b + c * c).sqrt()
}

/// The heights of a cut box (every third variable).
pub(crate) fn heights(cut: &CutBox) -> ([Vec<f64>; 2], Vec<f64>) {
    let pick = |v: &[f64]| v.iter().skip(2).step_by(3).copied().collect::<Vec<f64>>();
    ([pick(&cut.lo), pick(&cut.hi)], pick(&cut.crisp))
}

/// The area's gradient at `z` and the dual bound there.
fn gradient(rule: &AreaRule, z: &[f64], lo: &[f64], hi: &[f64], g: &mut [f64]) -> (f64, f64) {
    g.iter_mut().for_each(|x| *x = 0.0);
    let w = rule.width;
    let mut value = 0.0;
    let mut constant = 0.0;
    for q in 0..rule.len() {
        let [a, b] = rule.normal(q, z);
        let j = rule.jac[q];
        let n = norm3(a, b, j);
        if n == 0.0 {
            continue;
        }
        let wq = rule.weight[q];
        value += wq * n;
        constant += wq * j * j / n;
        for k in 0..w {
            let p = rule.point(q, k);
            g[p] += wq * (a * rule.a[q * w + k] + b * rule.b[q * w + k]) / n;
        }
    }
    let linear: f64 = g
        .iter()
        .zip(lo.iter().zip(hi))
        .map(|(g, (l, h))| (g * l).min(g * h))
        .sum();
    (value, constant + linear)
}

/// The least area: `[certified lower bound, value attained]`.
fn least(rule: &AreaRule, lo: &[f64], hi: &[f64], crisp: &[f64]) -> ([f64; 2], Vec<f64>) {
    let n = lo.len();
    let clamp = |x: &mut [f64]| {
        for (v, x) in x.iter_mut().enumerate() {
            *x = x.clamp(lo[v], hi[v]);
        }
    };
    let mut z = crisp.to_vec();
    clamp(&mut z);
    let mut g = vec![0.0; n];
    let (mut value, mut bound) = gradient(rule, &z, lo, hi, &mut g);
    let mut step = 1.0 / g.iter().fold(f64::MIN_POSITIVE, |m, x| m.max(x.abs()));
    let (mut trial, mut gt) = (vec![0.0; n], vec![0.0; n]);
    for _ in 0..STEPS {
        if value - bound <= 0.1 * SURFACE_AREA_TOLERANCE * value {
            break;
        }
        // Backtracking on the projected step.
        let mut moved = false;
        for _ in 0..40 {
            for v in 0..n {
                trial[v] = (z[v] - step * g[v]).clamp(lo[v], hi[v]);
            }
            let (vt, bt) = gradient(rule, &trial, lo, hi, &mut gt);
            let descent: f64 = (0..n).map(|v| g[v] * (trial[v] - z[v])).sum();
            if vt <= value + 1e-4 * descent.min(0.0) {
                // Barzilai–Borwein: ⟨s, s⟩ / ⟨s, y⟩.
                let (mut ss, mut sy) = (0.0, 0.0);
                for v in 0..n {
                    let s = trial[v] - z[v];
                    ss += s * s;
                    sy += s * (gt[v] - g[v]);
                }
                step = if sy > 0.0 { ss / sy } else { step * 2.0 };
                std::mem::swap(&mut z, &mut trial);
                std::mem::swap(&mut g, &mut gt);
                value = vt;
                bound = bound.max(bt);
                moved = true;
                break;
            }
            step *= 0.5;
        }
        if !moved {
            break;
        }
    }
    ([bound.min(value), value], z)
}

/// The area at the vertices of the free heights, updated incrementally.
struct Vertices<'a> {
    rule: &'a AreaRule,
    lo: &'a [f64],
    hi: &'a [f64],
    free: Vec<usize>,
    slot: Vec<Option<usize>>,
    z: Vec<f64>,
    normals: Vec<[f64; 2]>,
    norms: Vec<f64>,
    total: f64,
    changes: usize,
}

impl<'a> Vertices<'a> {
    fn new(rule: &'a AreaRule, lo: &'a [f64], hi: &'a [f64]) -> Self {
        let free: Vec<usize> = (0..lo.len()).filter(|&v| lo[v] < hi[v]).collect();
        let mut slot = vec![None; lo.len()];
        for (j, &v) in free.iter().enumerate() {
            slot[v] = Some(j);
        }
        let mut out = Vertices {
            rule,
            lo,
            hi,
            free,
            slot,
            z: lo.to_vec(),
            normals: Vec::new(),
            norms: Vec::new(),
            total: 0.0,
            changes: 0,
        };
        out.refresh();
        out
    }

    fn refresh(&mut self) {
        let rule = self.rule;
        self.normals = (0..rule.len()).map(|q| rule.normal(q, &self.z)).collect();
        self.norms = (0..rule.len())
            .map(|q| norm3(self.normals[q][0], self.normals[q][1], rule.jac[q]))
            .collect();
        self.total = (0..rule.len())
            .map(|q| rule.weight[q] * self.norms[q])
            .sum();
        self.changes = 0;
    }

    fn point(&self, choice: &[bool]) -> Vec<f64> {
        let mut z = self.lo.to_vec();
        for (&v, &c) in self.free.iter().zip(choice) {
            z[v] = if c { self.hi[v] } else { self.lo[v] };
        }
        z
    }

    /// The free heights by influence: cut width times `Σ w_q (|a| + |b|)`.
    fn order(&self) -> Vec<usize> {
        let rule = self.rule;
        let mut influence: Vec<(f64, usize)> = self
            .free
            .iter()
            .enumerate()
            .map(|(j, &v)| {
                let s: f64 = rule.nodes_of[v]
                    .iter()
                    .map(|&q| {
                        let k = local_index(rule, q, v);
                        rule.weight[q]
                            * (rule.a[q * rule.width + k].abs() + rule.b[q * rule.width + k].abs())
                    })
                    .sum();
                (s * (self.hi[v] - self.lo[v]), j)
            })
            .collect();
        influence.sort_by(|a, b| b.0.total_cmp(&a.0));
        influence.into_iter().map(|(_, j)| j).collect()
    }
}

/// The local index of point `v` at node `q`.
fn local_index(rule: &AreaRule, q: usize, v: usize) -> usize {
    let f = rule.first[q];
    let (i, j) = (v / rule.nv, v % rule.nv);
    (i - f[0]) * rule.columns + (j - f[1])
}

impl VertexProblem for Vertices<'_> {
    fn vars(&self) -> usize {
        self.free.len()
    }

    fn value(&mut self, choice: &[bool]) -> f64 {
        let rule = self.rule;
        for (&v, &c) in self.free.iter().zip(choice) {
            let to = if c { self.hi[v] } else { self.lo[v] };
            let delta = to - self.z[v];
            if delta == 0.0 {
                continue;
            }
            self.z[v] = to;
            self.changes += 1;
            for &q in &rule.nodes_of[v] {
                let k = local_index(rule, q, v);
                let n = &mut self.normals[q];
                n[0] += rule.a[q * rule.width + k] * delta;
                n[1] += rule.b[q * rule.width + k] * delta;
                let new = norm3(n[0], n[1], rule.jac[q]);
                self.total += rule.weight[q] * (new - self.norms[q]);
                self.norms[q] = new;
            }
        }
        if self.changes > 4096 {
            self.refresh();
        }
        self.total
    }

    fn bound(&mut self, fixed: &[Option<bool>]) -> f64 {
        let rule = self.rule;
        let w = rule.width;
        let mut total = 0.0;
        for q in 0..rule.len() {
            let (mut a, mut b) = ([0.0; 2], [0.0; 2]);
            for k in 0..w {
                let v = rule.point(q, k);
                let (l, h) = match self.slot[v].map(|s| fixed[s]) {
                    Some(Some(true)) => (self.hi[v], self.hi[v]),
                    Some(Some(false)) => (self.lo[v], self.lo[v]),
                    Some(None) | None => (self.lo[v], self.hi[v]),
                };
                for (range, c) in [(&mut a, rule.a[q * w + k]), (&mut b, rule.b[q * w + k])] {
                    let (p, r) = (c * l, c * h);
                    range[0] += p.min(r);
                    range[1] += p.max(r);
                }
            }
            let big = |r: [f64; 2]| r[0].abs().max(r[1].abs());
            total += rule.weight[q] * norm3(big(a), big(b), rule.jac[q]);
        }
        total
    }
}

/// The greatest area: `[value attained, certified upper bound]`, whether
/// every vertex was searched, and the maximiser.
fn greatest(rule: &AreaRule, lo: &[f64], hi: &[f64]) -> ([f64; 2], bool, Vec<f64>) {
    let mut problem = Vertices::new(rule, lo, hi);
    let n = problem.free.len();
    if n <= MAX_ENUMERATED_SURFACE_AREA_VARIABLES {
        let mut choice = vec![false; n];
        let mut best = problem.value(&choice);
        let mut best_at = choice.clone();
        for k in 1u64..(1u64 << n) {
            let j = k.trailing_zeros() as usize;
            choice[j] = !choice[j];
            let v = problem.value(&choice);
            if v > best {
                best = v;
                best_at.clone_from(&choice);
            }
        }
        let z = problem.point(&best_at);
        let v = rule.area(&z);
        let slack = (1u64 << n) as f64 * 4.0 * f64::EPSILON * v;
        return ([v, v + slack], true, z);
    }
    let order = problem.order();
    // Every height at its right end, improved by flips; and all at the left.
    let mut start = vec![true; n];
    let v = problem.value(&start);
    local_search(&mut problem, &mut start, v);
    let budget = (BRANCH_WORK / rule.len().max(1)).clamp(16, 1000);
    let slack = 1e-12;
    let out = maximize(
        &mut problem,
        &order,
        &[start, vec![false; n]],
        budget,
        slack,
    );
    let z = problem.point(&out.choice);
    let v = rule.area(&z);
    let exact = out.bound <= out.best * (1.0 + slack);
    ([v, out.bound.max(v) * (1.0 + slack)], exact, z)
}

/// The bracket of the surface area over the box of heights of `cut`.
pub(crate) fn surface_area_bracket(rule: &AreaRule, cut: &CutBox) -> Bracket {
    let ([lo, hi], crisp) = heights(cut);
    let (least, z_min) = least(rule, &lo, &hi, &crisp);
    let (largest, enumerated, z_max) = greatest(rule, &lo, &hi);
    let [_, e_min] = rule.area_with_error(&z_min);
    let [_, e_max] = rule.area_with_error(&z_max);
    let least = [least[0] - e_min, least[1]];
    let largest = [largest[0], largest[1] + e_max];
    let tolerance = SURFACE_AREA_TOLERANCE * largest[1].abs().max(f64::MIN_POSITIVE);
    let exact =
        enumerated && least[1] - least[0] <= tolerance && largest[1] - largest[0] <= tolerance;
    Bracket::from_ends(least, largest, exact)
}
