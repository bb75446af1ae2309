//! The area of a plane curve over the box of cut control points
//! (docs/method.md §11).
//!
//! Under an open curve `A = ∫ y·x' dt`, enclosed by a closed one
//! `A = ½ ∫ (x·y' − y·x') dt`. With `x = Σ Rᵢ Xᵢ`, `y = Σ Rⱼ Yⱼ` both are
//! bilinear in the x and the y values:
//!
//! ```text
//! A = Σᵢⱼ Kᵢⱼ·Xᵢ·Yⱼ,   under: Kᵢⱼ = Mᵢⱼ,   enclosed: Kᵢⱼ = ½ (Mⱼᵢ − Mᵢⱼ),   Mᵢⱼ = ∫ Rᵢ'·Rⱼ dt
//! ```
//! (a closed curve's first and last control point are one point: their rows
//! and columns are added). For fixed X the area is linear in Y with the
//! coefficients `sⱼ = Σᵢ Kᵢⱼ Xᵢ`, so the largest area over Y is
//! `Σⱼ max(sⱼ·lⱼ, sⱼ·rⱼ)` and the least `Σⱼ min(sⱼ·lⱼ, sⱼ·rⱼ)`; over X the area
//! is linear too, so both extremes are at X-vertices. Every X-vertex in
//! Gray-code order (one `Xᵢ` changes, and only the `sⱼ` of its neighbours)
//! gives both exactly while the free x values are at most 20; beyond,
//! branch and bound, with the bound `Σⱼ max(φⱼ(s⁻ⱼ), φⱼ(s⁺ⱼ))` from the range
//! `[s⁻ⱼ, s⁺ⱼ]` of `sⱼ` over the node (`φⱼ` is convex). The least area is the
//! largest of `−A` (the matrix `−K`). The coefficients `Mᵢⱼ` are integrals of
//! smooth functions on each piece of a knot span (exact for polynomial
//! curves); the fine and coarse rules' difference bounds their error, and
//! `Σ |ΔKᵢⱼ|·|Xᵢ|·|Yⱼ|` is added to each bracket.

use crate::measure::bracket::Bracket;
use crate::measure::cut_box::CutBox;
use crate::measure::rule::{Rule, Rules};
use crate::measure::vertices::{maximize, VertexProblem};

/// Free x values at most for enumerating every vertex.
pub const MAX_ENUMERATED_AREA_VARIABLES: usize = 20;
/// Nodes expanded at most by branch and bound.
const BRANCH_BUDGET: usize = 4000;

/// Which area a plane curve has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum AreaKind {
    /// `∫ y·x' dt` under an open curve (signed: positive where the curve runs
    /// towards larger x above the x axis).
    Under,
    /// `½ ∫ (x·y' − y·x') dt` enclosed by a closed curve (positive
    /// counter-clockwise).
    Enclosed,
}

/// The bilinear form `A = Σ K_ab X_a Y_b` on the merged points, by rows and
/// by columns, and the bound of its quadrature error per entry.
#[derive(Clone, Debug)]
pub(crate) struct AreaForm {
    pub(crate) kind: AreaKind,
    /// Number of (merged) points.
    pub(crate) points: usize,
    /// `rows[a]`: `(b, K_ab)`.
    rows: Vec<Vec<(usize, f64)>>,
    /// `cols[b]`: `(a, K_ab)`.
    cols: Vec<Vec<(usize, f64)>>,
    /// `(a, b, |ΔK_ab|)`.
    errors: Vec<(usize, usize, f64)>,
}

/// `Mᵢⱼ = ∫ Rᵢ' Rⱼ` by `rule`, banded: `m[i][j − i + p]`.
fn moments(rule: &Rule, n: usize) -> Vec<Vec<f64>> {
    let w = rule.width;
    let p = w - 1;
    let mut m = vec![vec![0.0; 2 * p + 1]; n];
    for q in 0..rule.len() {
        let first = rule.first[q];
        for j in 0..w {
            let a = rule.weight[q] * rule.r1[q * w + j];
            for k in 0..w {
                m[first + j][k + p - j] += a * rule.r[q * w + k];
            }
        }
    }
    m
}

/// The closing of an enclosed area: the rational basis at both ends of the
/// domain, `(first index, values)`, for the chord from the end back to the
/// start, and how many last points are one point with the first.
pub(crate) struct Closing {
    pub(crate) start: (usize, Vec<f64>),
    pub(crate) end: (usize, Vec<f64>),
    pub(crate) merged: usize,
    /// What to say of the closing ([`Closure::note`](crate::measure::Closure::note)).
    pub(crate) note: Option<String>,
}

impl AreaForm {
    /// The form of a curve with `n` control points: under it, or enclosed
    /// with `closing`, whose chord from `C(b)` back to `C(a)` adds
    /// `½ (Rᵢ(b)·Rⱼ(a) − Rᵢ(a)·Rⱼ(b))` to `Kᵢⱼ` (exact: no quadrature), and
    /// whose last `merged` points are the first `merged` again.
    pub(crate) fn new(rules: &Rules, n: usize, closing: Option<&Closing>) -> Self {
        let kind = if closing.is_some() {
            AreaKind::Enclosed
        } else {
            AreaKind::Under
        };
        let p = rules.fine.width - 1;
        let fine = moments(&rules.fine, n);
        let coarse = moments(&rules.coarse, n);
        let wrap = closing.map_or(0, |c| c.merged);
        let merged = |i: usize| if i + wrap >= n { i + wrap - n } else { i };
        let points = n - wrap;
        let get = |m: &Vec<Vec<f64>>, i: usize, j: usize| -> f64 {
            if j + p < i || j > i + p {
                0.0
            } else {
                m[i][j + p - i]
            }
        };
        let entry = |m: &Vec<Vec<f64>>, i: usize, j: usize| match kind {
            AreaKind::Under => get(m, i, j),
            AreaKind::Enclosed => 0.5 * (get(m, j, i) - get(m, i, j)),
        };
        let mut dense: std::collections::BTreeMap<(usize, usize), (f64, f64)> = Default::default();
        for i in 0..n {
            for j in i.saturating_sub(p)..(i + p + 1).min(n) {
                let e = dense.entry((merged(i), merged(j))).or_insert((0.0, 0.0));
                e.0 += entry(&fine, i, j);
                e.1 += entry(&coarse, i, j);
            }
        }
        // Wrapped points that are one point close every admissible curve.
        if let Some(c) = closing.filter(|c| c.merged == 0) {
            let (sa, ra) = (&c.start.0, &c.start.1);
            let (sb, rb) = (&c.end.0, &c.end.1);
            let mut add = |i: usize, j: usize, k: f64| {
                let e = dense.entry((merged(i), merged(j))).or_insert((0.0, 0.0));
                e.0 += k;
                e.1 += k;
            };
            for (di, rib) in rb.iter().enumerate() {
                for (dj, rja) in ra.iter().enumerate() {
                    add(sb + di, sa + dj, 0.5 * rib * rja);
                    add(sa + dj, sb + di, -0.5 * rja * rib);
                }
            }
        }
        let mut rows = vec![Vec::new(); points];
        let mut cols = vec![Vec::new(); points];
        let mut errors = Vec::new();
        for ((a, b), (k, kc)) in dense {
            if k != 0.0 {
                rows[a].push((b, k));
                cols[b].push((a, k));
            }
            errors.push((a, b, (k - kc).abs() + 4.0 * f64::EPSILON * k.abs()));
        }
        AreaForm {
            kind,
            points,
            rows,
            cols,
            errors,
        }
    }

    /// The form itself, or for an enclosed area `−K` where the crisp
    /// curve (its control points `crisp`, x and y interleaved) runs
    /// clockwise: an enclosed area is positive whichever way the curve runs.
    pub(crate) fn positive_for(self, crisp: &[f64]) -> Self {
        if self.kind == AreaKind::Under {
            return self;
        }
        let value: f64 = self
            .rows
            .iter()
            .enumerate()
            .flat_map(|(a, row)| row.iter().map(move |&(b, k)| (a, b, k)))
            .map(|(a, b, k)| k * crisp[2 * a] * crisp[2 * b + 1])
            .sum();
        if value < 0.0 {
            self.negated()
        } else {
            self
        }
    }

    /// The form with `−K`.
    fn negated(&self) -> Self {
        let neg = |v: &Vec<Vec<(usize, f64)>>| -> Vec<Vec<(usize, f64)>> {
            v.iter()
                .map(|r| r.iter().map(|&(j, k)| (j, -k)).collect())
                .collect()
        };
        AreaForm {
            kind: self.kind,
            points: self.points,
            rows: neg(&self.rows),
            cols: neg(&self.cols),
            errors: self.errors.clone(),
        }
    }
}

/// The x and y cuts of the merged points.
struct Cuts {
    x: Vec<[f64; 2]>,
    y: Vec<[f64; 2]>,
}

impl Cuts {
    fn of(cut: &CutBox, points: usize) -> Self {
        Cuts {
            x: (0..points)
                .map(|i| [cut.lo[2 * i], cut.hi[2 * i]])
                .collect(),
            y: (0..points)
                .map(|i| [cut.lo[2 * i + 1], cut.hi[2 * i + 1]])
                .collect(),
        }
    }
}

/// `max(s·l, s·r)` and `min(s·l, s·r)`.
fn ends(s: f64, [l, r]: [f64; 2]) -> (f64, f64) {
    let (a, b) = (s * l, s * r);
    (a.max(b), a.min(b))
}

/// The bracket of the area of a plane curve over `cut` (a closed curve's
/// first and last point carry the same numbers, so their cuts are equal).
pub(crate) fn area_bracket(form: &AreaForm, cut: &CutBox) -> Bracket {
    let cuts = Cuts::of(cut, form.points);
    let free: Vec<usize> = (0..form.points)
        .filter(|&a| cuts.x[a][0] < cuts.x[a][1])
        .collect();
    let error: f64 = form
        .errors
        .iter()
        .map(|&(a, b, e)| {
            e * cuts.x[a][0].abs().max(cuts.x[a][1].abs())
                * cuts.y[b][0].abs().max(cuts.y[b][1].abs())
        })
        .sum();
    if free.len() <= MAX_ENUMERATED_AREA_VARIABLES {
        let ([lo, hi], drift) = enumerate(form, &cuts, &free);
        let e = error + drift;
        return Bracket::from_ends([lo - e, lo + e], [hi - e, hi + e], true);
    }
    let up = branch(form, &cuts, &free);
    let negated = form.negated();
    let down = branch(&negated, &cuts, &free);
    let exact = up[1] <= up[0] && down[1] <= down[0];
    Bracket::from_ends(
        [-down[1] - error, -down[0] + error],
        [up[0] - error, up[1] + error],
        exact,
    )
}

/// The least and the largest area over every X-vertex, and a bound of the
/// rounding of the running sums.
fn enumerate(form: &AreaForm, cuts: &Cuts, free: &[usize]) -> ([f64; 2], f64) {
    let n = form.points;
    let mut x: Vec<f64> = cuts.x.iter().map(|c| c[0]).collect();
    let mut s = vec![0.0; n];
    for (a, row) in form.rows.iter().enumerate() {
        for &(b, k) in row {
            s[b] += k * x[a];
        }
    }
    let totals = |s: &[f64]| -> (f64, f64) {
        s.iter()
            .zip(&cuts.y)
            .map(|(&s, &y)| ends(s, y))
            .fold((0.0, 0.0), |(p, q), (a, b)| (p + a, q + b))
    };
    let (mut hi, mut lo) = totals(&s);
    let (mut best_hi, mut best_lo) = (hi, lo);
    let mut magnitude = hi.abs().max(lo.abs());
    for k in 1u64..(1u64 << free.len()) {
        let j = k.trailing_zeros() as usize;
        let a = free[j];
        let to = if x[a] == cuts.x[a][0] {
            cuts.x[a][1]
        } else {
            cuts.x[a][0]
        };
        let delta = to - x[a];
        x[a] = to;
        for &(b, kab) in &form.rows[a] {
            let (h0, l0) = ends(s[b], cuts.y[b]);
            s[b] += kab * delta;
            let (h1, l1) = ends(s[b], cuts.y[b]);
            hi += h1 - h0;
            lo += l1 - l0;
        }
        if k % 4096 == 0 {
            // Fresh sums, so that rounding does not build up over the walk.
            s.iter_mut().for_each(|v| *v = 0.0);
            for (a, row) in form.rows.iter().enumerate() {
                for &(b, k) in row {
                    s[b] += k * x[a];
                }
            }
            (hi, lo) = totals(&s);
        }
        magnitude = magnitude.max(hi.abs()).max(lo.abs());
        best_hi = best_hi.max(hi);
        best_lo = best_lo.min(lo);
    }
    let drift = 4096.0 * 4.0 * f64::EPSILON * magnitude;
    ([best_lo, best_hi], drift)
}

/// The largest area: `[attained, upper bound]`.
fn branch(form: &AreaForm, cuts: &Cuts, free: &[usize]) -> [f64; 2] {
    let mut problem = AreaVertices {
        form,
        cuts,
        free,
        slot: {
            let mut slot = vec![None; form.points];
            for (j, &a) in free.iter().enumerate() {
                slot[a] = Some(j);
            }
            slot
        },
        x: cuts.x.iter().map(|c| c[0]).collect(),
    };
    let mut influence: Vec<(f64, usize)> = free
        .iter()
        .enumerate()
        .map(|(j, &a)| {
            let k: f64 = form.rows[a]
                .iter()
                .map(|&(b, k)| k.abs() * cuts.y[b][0].abs().max(cuts.y[b][1].abs()))
                .sum();
            (k * (cuts.x[a][1] - cuts.x[a][0]), j)
        })
        .collect();
    influence.sort_by(|a, b| b.0.total_cmp(&a.0));
    let order: Vec<usize> = influence.into_iter().map(|(_, j)| j).collect();
    let starts = vec![vec![false; free.len()], vec![true; free.len()]];
    let out = maximize(&mut problem, &order, &starts, BRANCH_BUDGET, 1e-13);
    [out.best, out.bound]
}

struct AreaVertices<'a> {
    form: &'a AreaForm,
    cuts: &'a Cuts,
    free: &'a [usize],
    slot: Vec<Option<usize>>,
    x: Vec<f64>,
}

impl VertexProblem for AreaVertices<'_> {
    fn vars(&self) -> usize {
        self.free.len()
    }

    fn value(&mut self, choice: &[bool]) -> f64 {
        for (&a, &c) in self.free.iter().zip(choice) {
            self.x[a] = self.cuts.x[a][usize::from(c)];
        }
        (0..self.form.points)
            .map(|b| {
                let s: f64 = self.form.cols[b].iter().map(|&(a, k)| k * self.x[a]).sum();
                ends(s, self.cuts.y[b]).0
            })
            .sum()
    }

    fn bound(&mut self, fixed: &[Option<bool>]) -> f64 {
        (0..self.form.points)
            .map(|b| {
                let (mut lo, mut hi) = (0.0, 0.0);
                for &(a, k) in &self.form.cols[b] {
                    let [l, r] = match self.slot[a].map(|j| fixed[j]) {
                        Some(Some(c)) => {
                            let v = self.cuts.x[a][usize::from(c)];
                            [v, v]
                        }
                        _ => self.cuts.x[a],
                    };
                    let (p, q) = (k * l, k * r);
                    lo += p.min(q);
                    hi += p.max(q);
                }
                ends(lo, self.cuts.y[b]).0.max(ends(hi, self.cuts.y[b]).0)
            })
            .sum()
    }
}
