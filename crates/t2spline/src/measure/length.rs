//! Arc length over the box of cut control points (docs/method.md §11).
//!
//! `L(P) = ∫ ‖Σᵢ Rᵢ'(t)·Pᵢ‖ dt`. With weights and knots crisp, `Rᵢ'` does
//! not depend on the control points, so at each `t` the derivative is a
//! linear map of all the control points, its norm is convex, and an
//! integral (a sum with positive weights) of convex functions is convex:
//! **L is convex on the box**. That is all the minimum and the maximum rest
//! on. The integral is the fixed rule of [`super::rule`],
//! `L_Q(P) = Σ_q w_q ‖d_q(P)‖`; the difference between the fine and the
//! coarse rule at the extreme curves is the quadrature's error estimate,
//! added to each bracket; the two extreme curves' lengths are then taken
//! from the adaptive arc length (which bisects where the speed has a corner,
//! as at a cusp of a vertex curve).
//!
//! - The **minimum** of a convex function over a box: projected Newton
//!   (Bertsekas 1982) on `Σ w_q √(‖d_q‖² + ε²)` with ε shrinking to `10⁻¹²`
//!   of the crisp speed, on the banded Hessian. The certificate is a dual
//!   bound: for any unit vectors `u_q`, `‖d_q‖ ≥ u_q·d_q`, so
//!   `min L_Q ≥ min over the box of Σ_q w_q u_q·d_q(P)`, a linear function
//!   whose minimum is read off the signs of its coefficients
//!   `gᵢ = Σ_q w_q R'ᵢ(t_q) u_q`. With `u_q = d_q/‖d_q‖` at the minimiser the
//!   two are equal (minimax for a convex–concave saddle on compact sets), so
//!   the bound closes on the minimum as the iterate does; it is solved to
//!   `10⁻¹⁰` of the length.
//! - The **maximum** of a convex function over a box is at a vertex: every
//!   vertex in Gray-code order (one variable changes, and only the nodes
//!   where its control point counts are updated) while the free variables
//!   are at most 16; beyond, branch and bound with the bound
//!   `∫ max over D(t) of ‖d‖ dt`, `D(t)` the derivative box of the node at
//!   `t` (its farthest corner from the origin).

use crate::measure::bracket::Bracket;
use crate::measure::cut_box::CutBox;
use crate::measure::rule::{Rule, Rules};
use crate::measure::vertices::{maximize, VertexProblem};

/// Free variables at most for enumerating every vertex.
pub const MAX_ENUMERATED_LENGTH_VARIABLES: usize = 16;
/// The relative accuracy the minimum is solved to (its certified gap).
pub const LENGTH_MIN_TOLERANCE: f64 = 1e-9;
/// Nodes expanded at most by branch and bound.
const BRANCH_BUDGET: usize = 1000;
/// Newton iterations at most per smoothing level.
const NEWTON_STEPS: usize = 60;

/// The derivative at every node of `rule` for control points `x`:
/// `d[q·D + c]`.
fn derivatives(rule: &Rule, dim: usize, x: &[f64], d: &mut Vec<f64>) {
    let w = rule.width;
    d.clear();
    d.resize(rule.len() * dim, 0.0);
    for q in 0..rule.len() {
        let first = rule.first[q];
        let r1 = &rule.r1[q * w..(q + 1) * w];
        for c in 0..dim {
            let mut s = 0.0;
            for (j, a) in r1.iter().enumerate() {
                s += a * x[(first + j) * dim + c];
            }
            d[q * dim + c] = s;
        }
    }
}

/// `L_Q(x)`.
pub(crate) fn length(rule: &Rule, dim: usize, x: &[f64]) -> f64 {
    let mut d = Vec::new();
    derivatives(rule, dim, x, &mut d);
    (0..rule.len())
        .map(|q| rule.weight[q] * norm(&d[q * dim..(q + 1) * dim]))
        .sum()
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The dual bound `min over the box of Σ_q w_q u_q·d_q(P)`, `u_q = d_q/‖d_q‖`
/// (0 where `d_q = 0`), from the derivatives `d` at some control points.
fn dual_bound(rule: &Rule, cut: &CutBox, d: &[f64]) -> f64 {
    let (dim, w) = (cut.dim, rule.width);
    let mut g = vec![0.0; cut.lo.len()];
    for q in 0..rule.len() {
        let dq = &d[q * dim..(q + 1) * dim];
        let n = norm(dq);
        if n == 0.0 {
            continue;
        }
        let first = rule.first[q];
        for (j, a) in rule.r1[q * w..(q + 1) * w].iter().enumerate() {
            let f = rule.weight[q] * a / n;
            for c in 0..dim {
                g[(first + j) * dim + c] += f * dq[c];
            }
        }
    }
    g.iter()
        .zip(cut.lo.iter().zip(&cut.hi))
        .map(|(g, (l, h))| (g * l).min(g * h))
        .sum()
}

/// The smoothed length, its gradient and its banded Hessian (upper band of
/// width `band + 1`, row-major).
fn smoothed(
    rule: &Rule,
    dim: usize,
    x: &[f64],
    eps: f64,
    grad: &mut [f64],
    hess: &mut [f64],
    band: usize,
) -> f64 {
    let w = rule.width;
    grad.iter_mut().for_each(|g| *g = 0.0);
    hess.iter_mut().for_each(|h| *h = 0.0);
    let mut f = 0.0;
    let mut d = [0.0; 3];
    for q in 0..rule.len() {
        let first = rule.first[q];
        let r1 = &rule.r1[q * w..(q + 1) * w];
        for (c, dc) in d.iter_mut().enumerate().take(dim) {
            *dc = r1
                .iter()
                .enumerate()
                .map(|(j, a)| a * x[(first + j) * dim + c])
                .sum();
        }
        let s = (d[..dim].iter().map(|v| v * v).sum::<f64>() + eps * eps).sqrt();
        if s == 0.0 {
            continue;
        }
        let wq = rule.weight[q];
        f += wq * s;
        for (j, aj) in r1.iter().enumerate() {
            for c in 0..dim {
                let a = (first + j) * dim + c;
                grad[a] += wq * aj * d[c] / s;
                for (k, ak) in r1.iter().enumerate() {
                    for e in 0..dim {
                        let b = (first + k) * dim + e;
                        if b < a {
                            continue;
                        }
                        let delta = if c == e { 1.0 / s } else { 0.0 };
                        hess[a * (band + 1) + (b - a)] +=
                            wq * aj * ak * (delta - d[c] * d[e] / (s * s * s));
                    }
                }
            }
        }
    }
    f
}

/// Solves `(H + μ·diag)·s = −g` on the free variables (`free[a]`), others 0,
/// by banded Cholesky; `false` if the factorisation fails.
fn newton_step(hess: &[f64], band: usize, grad: &[f64], free: &[bool], step: &mut [f64]) -> bool {
    let n = grad.len();
    let at = |a: usize, b: usize| -> f64 {
        // Symmetric access, a ≤ b within the band.
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        if b - a > band {
            0.0
        } else {
            hess[a * (band + 1) + (b - a)]
        }
    };
    let diag_max = (0..n)
        .filter(|&a| free[a])
        .fold(0.0_f64, |m, a| m.max(at(a, a)));
    let mu = 1e-13 * diag_max.max(f64::MIN_POSITIVE);
    // l[i·(band+1) + (i − j)] for j in i−band ..= i.
    let mut l = vec![0.0; n * (band + 1)];
    for i in 0..n {
        let lo = i.saturating_sub(band);
        for j in lo..=i {
            let mut s = if !free[i] || !free[j] {
                if i == j {
                    1.0
                } else {
                    0.0
                }
            } else {
                at(j, i) + if i == j { mu } else { 0.0 }
            };
            for k in lo.max(j.saturating_sub(band))..j {
                s -= l[i * (band + 1) + (i - k)] * l[j * (band + 1) + (j - k)];
            }
            if i == j {
                if s.is_nan() || s <= 0.0 || !s.is_finite() {
                    return false;
                }
                l[i * (band + 1)] = s.sqrt();
            } else {
                l[i * (band + 1) + (i - j)] = s / l[j * (band + 1)];
            }
        }
    }
    // Forward and back substitution.
    for i in 0..n {
        let mut s = if free[i] { -grad[i] } else { 0.0 };
        for k in i.saturating_sub(band)..i {
            s -= l[i * (band + 1) + (i - k)] * step[k];
        }
        step[i] = s / l[i * (band + 1)];
    }
    for i in (0..n).rev() {
        let mut s = step[i];
        for k in i + 1..n.min(i + band + 1) {
            s -= l[k * (band + 1) + (k - i)] * step[k];
        }
        step[i] = s / l[i * (band + 1)];
    }
    step.iter().all(|s| s.is_finite())
}

/// The least length: `[certified lower bound, length attained]` and the
/// minimiser.
pub(crate) fn min_length(rules: &Rules, cut: &CutBox) -> ([f64; 2], Vec<f64>) {
    let rule = &rules.fine;
    let dim = cut.dim;
    let n = cut.lo.len();
    let band = rule.width * dim - 1;
    let clamp = |x: &mut [f64]| {
        for (v, x) in x.iter_mut().enumerate() {
            *x = x.clamp(cut.lo[v], cut.hi[v]);
        }
    };
    let mut x = cut.crisp.clone();
    clamp(&mut x);
    let crisp_length = length(rule, dim, &x);
    let span = rule.t.last().copied().unwrap_or(0.0) - rule.t.first().copied().unwrap_or(0.0);
    let speed = (crisp_length / span.max(f64::MIN_POSITIVE)).max(cut.magnitude() * 1e-300);
    let scale = crisp_length.max(cut.magnitude() * f64::EPSILON);
    let mut d = Vec::new();
    let certify = |x: &[f64], d: &mut Vec<f64>| {
        derivatives(rule, dim, x, d);
        let value: f64 = (0..rule.len())
            .map(|q| rule.weight[q] * norm(&d[q * dim..(q + 1) * dim]))
            .sum();
        (value, dual_bound(rule, cut, d))
    };
    let (mut value, mut lower) = certify(&x, &mut d);
    let target = 0.1 * LENGTH_MIN_TOLERANCE;
    let (mut grad, mut hess, mut step) = (vec![0.0; n], vec![0.0; n * (band + 1)], vec![0.0; n]);
    let mut trial = vec![0.0; n];
    'levels: for eps in [1e-3, 1e-6, 1e-9, 1e-12].map(|e| e * speed) {
        for _ in 0..NEWTON_STEPS {
            if value - lower <= target * value.max(scale * 1e-3) {
                break 'levels;
            }
            let f = smoothed(rule, dim, &x, eps, &mut grad, &mut hess, band);
            // The ε-active set: at a bound with the gradient pushing out.
            let reach = (0..n)
                .map(|v| {
                    (x[v] - (x[v] - grad[v] * (cut.hi[v] - cut.lo[v])).clamp(cut.lo[v], cut.hi[v]))
                        .abs()
                })
                .fold(0.0_f64, f64::max);
            let free: Vec<bool> = (0..n)
                .map(|v| {
                    let width = cut.hi[v] - cut.lo[v];
                    let near = reach.min(1e-3 * width);
                    width > 0.0
                        && !((x[v] - cut.lo[v] <= near && grad[v] > 0.0)
                            || (cut.hi[v] - x[v] <= near && grad[v] < 0.0))
                })
                .collect();
            let newton = newton_step(&hess, band, &grad, &free, &mut step);
            if !newton {
                // Scaled gradient: the diagonal of the Hessian.
                for v in 0..n {
                    let h = hess[v * (band + 1)];
                    step[v] = if free[v] && h > 0.0 {
                        -grad[v] / h
                    } else {
                        0.0
                    };
                }
            }
            let mut beta = 1.0;
            let mut moved = false;
            for _ in 0..50 {
                for v in 0..n {
                    trial[v] = (x[v] + beta * step[v]).clamp(cut.lo[v], cut.hi[v]);
                }
                let descent: f64 = (0..n).map(|v| grad[v] * (trial[v] - x[v])).sum();
                let ft = smoothed_value(rule, dim, &trial, eps);
                if ft <= f + 1e-4 * descent.min(0.0) && ft < f {
                    moved = true;
                    break;
                }
                beta *= 0.5;
            }
            if !moved {
                continue 'levels;
            }
            std::mem::swap(&mut x, &mut trial);
            let (v, l) = certify(&x, &mut d);
            value = v;
            lower = lower.max(l);
        }
    }
    let error = (length(&rules.coarse, dim, &x) - value).abs() + 64.0 * f64::EPSILON * value;
    ([lower - error, value + error], x)
}

/// The smoothed length alone.
fn smoothed_value(rule: &Rule, dim: usize, x: &[f64], eps: f64) -> f64 {
    let w = rule.width;
    let mut f = 0.0;
    for q in 0..rule.len() {
        let first = rule.first[q];
        let r1 = &rule.r1[q * w..(q + 1) * w];
        let mut s = eps * eps;
        for c in 0..dim {
            let v: f64 = r1
                .iter()
                .enumerate()
                .map(|(j, a)| a * x[(first + j) * dim + c])
                .sum();
            s += v * v;
        }
        f += rule.weight[q] * s.sqrt();
    }
    f
}

/// The largest length: `[length attained, certified upper bound]`, whether
/// it was found exactly (every vertex), and the maximiser.
pub(crate) fn max_length(rules: &Rules, cut: &CutBox) -> ([f64; 2], bool, Vec<f64>) {
    let free = cut.free();
    let dim = cut.dim;
    let rule = &rules.fine;
    if free.len() <= MAX_ENUMERATED_LENGTH_VARIABLES {
        let x = enumerate(rule, cut, &free);
        let value = length(rule, dim, &x);
        let error = (length(&rules.coarse, dim, &x) - value).abs()
            + (64.0 + (1u64 << free.len()) as f64) * f64::EPSILON * value;
        return ([value - error, value + error], true, x);
    }
    let mut problem = LengthVertices::new(rule, cut, free);
    let order = problem.order();
    let starts = problem.starts();
    let slack = 1e-12;
    let out = maximize(&mut problem, &order, &starts, BRANCH_BUDGET, slack);
    let x = problem.point(&out.choice);
    let value = length(rule, dim, &x);
    let error = (length(&rules.coarse, dim, &x) - value).abs() + 64.0 * f64::EPSILON * value;
    let exact = out.bound <= out.best * (1.0 + slack);
    (
        [out.best - error, out.bound + error + slack * out.bound],
        exact,
        x,
    )
}

/// Every vertex in Gray-code order with incremental updates; the maximiser.
fn enumerate(rule: &Rule, cut: &CutBox, free: &[usize]) -> Vec<f64> {
    let dim = cut.dim;
    let w = rule.width;
    let mut x = cut.lo.clone();
    let mut d = Vec::new();
    derivatives(rule, dim, &x, &mut d);
    let mut norms: Vec<f64> = (0..rule.len())
        .map(|q| norm(&d[q * dim..(q + 1) * dim]))
        .collect();
    let mut total: f64 = (0..rule.len()).map(|q| rule.weight[q] * norms[q]).sum();
    let mut at_hi = vec![false; free.len()];
    let (mut best, mut best_at) = (total, at_hi.clone());
    let ranges: Vec<std::ops::Range<usize>> =
        free.iter().map(|&v| rule.nodes_of(v / dim)).collect();
    for k in 1u64..(1u64 << free.len()) {
        let j = k.trailing_zeros() as usize;
        let v = free[j];
        let delta = if at_hi[j] {
            cut.lo[v] - cut.hi[v]
        } else {
            cut.hi[v] - cut.lo[v]
        };
        at_hi[j] = !at_hi[j];
        let (i, c) = (v / dim, v % dim);
        for q in ranges[j].clone() {
            let a = rule.r1[q * w + (i - rule.first[q])];
            d[q * dim + c] += a * delta;
            let new = norm(&d[q * dim..(q + 1) * dim]);
            total += rule.weight[q] * (new - norms[q]);
            norms[q] = new;
        }
        if total > best {
            best = total;
            best_at.clone_from(&at_hi);
        }
    }
    for (j, &v) in free.iter().enumerate() {
        x[v] = if best_at[j] { cut.hi[v] } else { cut.lo[v] };
    }
    x
}

/// The length at the vertices of the free variables, for branch and bound.
struct LengthVertices<'a> {
    rule: &'a Rule,
    cut: &'a CutBox,
    free: Vec<usize>,
    /// Position of each variable in `free`, if free.
    slot: Vec<Option<usize>>,
    x: Vec<f64>,
    /// The derivatives, their norms and the length at `x`.
    d: Vec<f64>,
    norms: Vec<f64>,
    total: f64,
    /// The nodes of each free variable's control point.
    ranges: Vec<std::ops::Range<usize>>,
    /// Updates since the sums were last made afresh.
    changes: usize,
}

impl<'a> LengthVertices<'a> {
    fn new(rule: &'a Rule, cut: &'a CutBox, free: Vec<usize>) -> Self {
        let mut slot = vec![None; cut.lo.len()];
        for (j, &v) in free.iter().enumerate() {
            slot[v] = Some(j);
        }
        let ranges = free.iter().map(|&v| rule.nodes_of(v / cut.dim)).collect();
        let mut out = LengthVertices {
            rule,
            cut,
            free,
            slot,
            x: cut.lo.clone(),
            d: Vec::new(),
            norms: Vec::new(),
            total: 0.0,
            ranges,
            changes: 0,
        };
        out.refresh();
        out
    }

    /// The sums made afresh at `x`.
    fn refresh(&mut self) {
        let dim = self.cut.dim;
        derivatives(self.rule, dim, &self.x, &mut self.d);
        self.norms = (0..self.rule.len())
            .map(|q| norm(&self.d[q * dim..(q + 1) * dim]))
            .collect();
        self.total = (0..self.rule.len())
            .map(|q| self.rule.weight[q] * self.norms[q])
            .sum();
        self.changes = 0;
    }

    fn point(&self, choice: &[bool]) -> Vec<f64> {
        let mut x = self.cut.lo.clone();
        for (&v, &c) in self.free.iter().zip(choice) {
            x[v] = if c { self.cut.hi[v] } else { self.cut.lo[v] };
        }
        x
    }

    /// The free variables by influence: cut width times `∫ |Rᵢ'|`.
    fn order(&self) -> Vec<usize> {
        let (dim, w) = (self.cut.dim, self.rule.width);
        let mut influence: Vec<(f64, usize)> = self
            .free
            .iter()
            .enumerate()
            .map(|(j, &v)| {
                let i = v / dim;
                let s: f64 = self
                    .rule
                    .nodes_of(i)
                    .map(|q| {
                        self.rule.weight[q] * self.rule.r1[q * w + (i - self.rule.first[q])].abs()
                    })
                    .sum();
                (s * (self.cut.hi[v] - self.cut.lo[v]), j)
            })
            .collect();
        influence.sort_by(|a, b| b.0.total_cmp(&a.0));
        influence.into_iter().map(|(_, j)| j).collect()
    }

    /// Vertices to start from: each variable at the end away from the
    /// crisp curve's neighbours (alternating by point), and all left/right.
    fn starts(&self) -> Vec<Vec<bool>> {
        let dim = self.cut.dim;
        let n = self.free.len();
        vec![
            self.free.iter().map(|&v| (v / dim) % 2 == 0).collect(),
            self.free.iter().map(|&v| (v / dim) % 2 == 1).collect(),
            vec![false; n],
            vec![true; n],
        ]
    }
}

impl VertexProblem for LengthVertices<'_> {
    fn vars(&self) -> usize {
        self.free.len()
    }

    /// Incremental: only the variables that differ from the last vertex
    /// change, and only the nodes where their control points count.
    fn value(&mut self, choice: &[bool]) -> f64 {
        let (rule, dim, w) = (self.rule, self.cut.dim, self.rule.width);
        for (j, (&v, &c)) in self.free.iter().zip(choice).enumerate() {
            let to = if c { self.cut.hi[v] } else { self.cut.lo[v] };
            let delta = to - self.x[v];
            if delta == 0.0 {
                continue;
            }
            self.x[v] = to;
            self.changes += 1;
            let (i, cc) = (v / dim, v % dim);
            for q in self.ranges[j].clone() {
                let a = rule.r1[q * w + (i - rule.first[q])];
                self.d[q * dim + cc] += a * delta;
                let new = norm(&self.d[q * dim..(q + 1) * dim]);
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
        let (rule, cut, dim, w) = (self.rule, self.cut, self.cut.dim, self.rule.width);
        let mut total = 0.0;
        for q in 0..rule.len() {
            let first = rule.first[q];
            let mut sq = 0.0;
            for c in 0..dim {
                let (mut lo, mut hi) = (0.0, 0.0);
                for (j, a) in rule.r1[q * w..(q + 1) * w].iter().enumerate() {
                    let v = (first + j) * dim + c;
                    // A variable that is not free has `lo = hi`.
                    let (l, h) = match self.slot[v].map(|s| fixed[s]) {
                        Some(Some(true)) => (cut.hi[v], cut.hi[v]),
                        Some(Some(false)) => (cut.lo[v], cut.lo[v]),
                        Some(None) | None => (cut.lo[v], cut.hi[v]),
                    };
                    let (p, r) = (a * l, a * h);
                    lo += p.min(r);
                    hi += p.max(r);
                }
                sq += f64::max(lo * lo, hi * hi);
            }
            total += rule.weight[q] * sq.sqrt();
        }
        total
    }
}

/// The bracket of the length. `adaptive` is the length of the curve with
/// given control points by the adaptive quadrature of
/// `NurbsCurve::arc_length` (relative accuracy 1e-10, bisecting where the
/// speed has a corner): the lengths of the two extreme curves found on the
/// fixed rule are taken from it, and each end's bracket holds both the
/// fixed rule's value widened by its error estimate and the adaptive one.
pub(crate) fn length_bracket(
    rules: &Rules,
    cut: &CutBox,
    adaptive: &dyn Fn(&[f64]) -> f64,
) -> Bracket {
    let (least, x_min) = min_length(rules, cut);
    let (largest, enumerated, x_max) = max_length(rules, cut);
    let accuracy = 1e-10;
    let short = adaptive(&x_min);
    let long = adaptive(&x_max);
    // The attained ends by the adaptive quadrature, the bounds widened to
    // hold them with its accuracy; a length is never negative, so a lower
    // bound below 0 (the rule's error estimate on a curve that can stand
    // still) is 0.
    let least = [least[0].min(short * (1.0 - accuracy)).max(0.0), short];
    let largest = [long, largest[1].max(long * (1.0 + accuracy))];
    let tolerance = LENGTH_MIN_TOLERANCE * long.abs().max(f64::MIN_POSITIVE);
    let exact =
        enumerated && least[1] - least[0] <= tolerance && largest[1] - largest[0] <= tolerance;
    Bracket::from_ends(least, largest, exact)
}
