//! The certified grade on one knot span (curves) or span rectangle
//! (surfaces): an interval branch and bound on Bernstein forms
//! (docs/set.md, "Certified grades").
//!
//! Fix a point `p`, a membership function and a span. Multiplied by the
//! weight function `W = Σ wᵢNᵢ > 0`, the condition "`p` lies within the
//! slack `s` of the box at `(t, alpha)`" is, per coordinate `c`, two
//! polynomial inequalities linear in alpha:
//!
//! ```text
//! left:   Σ wᵢNᵢ(t)·(p_c + s − footˡᵢ) − alpha·Σ wᵢNᵢ(t)·slopeˡᵢ ≥ 0
//! right:  Σ wᵢNᵢ(t)·(footʳᵢ − p_c + s) − alpha·Σ wᵢNᵢ(t)·slopeʳᵢ ≥ 0
//! ```
//! In Bernstein form on a cell `T` (a sub-interval, or sub-rectangle) each
//! is `Σₖ Bₖ(t)·(aₖ − alpha·eₖ) ≥ 0` with `eₖ ≥ 0`. The grade at `t` is
//! `g(t) = min(top, minⱼ aⱼ(t)/eⱼ(t))` (`+∞` for `eⱼ(t) = 0 ≤ aⱼ(t)`,
//! `−∞` for `eⱼ(t) = 0 > aⱼ(t)`). Since `Bₖ ≥ 0` and `Σ Bₖ = 1`, an alpha
//! admitted at some `t ∈ T` makes some coefficient `aₖ − alpha·eₖ ≥ 0`:
//!
//! ```text
//! sup over t ∈ T of g(t)  ≤  ub(T) = min( top, minⱼ maxₖ aⱼₖ/eⱼₖ )
//! ```
//! and the corner coefficients are values of the polynomials, so the grades
//! at the cell's corners are exact lower bounds. Cells are split best first
//! (largest `ub`, across every span of the function at once) until
//! `ub − lb ≤` [`GRADE_TOLERANCE`]; each cell keeps its coefficients, and its
//! halves come from one de Casteljau split. The bound is the Bernstein
//! (interval) kind, whose excess shrinks with the square of the cell's width
//! where the grade is smooth.
//!
//! Where two inequalities cross, one rising and one falling (a corner of the
//! grade, the usual peak), `min` of their bounds shrinks only with the
//! width. On a curve's cell two more bounds then keep the square: above, a
//! positive combination `λ·first + (1 − λ)·second` of the two binding
//! inequalities, which holds wherever both do, with `λ` cancelling their
//! change across the cell (its coefficients bound alpha as one inequality's
//! do); below, the exact grade at the parameter where the chords of the
//! inequalities' grades cross.

use std::collections::BinaryHeap;

use crate::heap_key::heap_ordered_by;

use crate::set::bernstein::{bernstein_value, split_half};
use crate::set::cut_lines::CutEnds;

/// The gap between the certified upper and lower bounds at which a grade is
/// reported: the reported grade is the upper bound, at most this far above
/// the true supremum.
pub const GRADE_TOLERANCE: f64 = 1e-7;

/// Cells split per form and point at most; past it the upper bound reached
/// is reported (still an upper bound, with a wider gap).
const MAX_CELLS: usize = 20_000;

/// One span (curve) or span rectangle (surface) under one membership
/// function in Bézier form: coefficients row by row, `shape[0]` along u and
/// `shape[1]` along v (1 for a curve).
#[derive(Clone, Debug)]
pub(crate) struct Form<const D: usize> {
    pub(crate) shape: [usize; 2],
    /// The least top of the control points acting on the form.
    pub(crate) top: f64,
    /// The box of the acting control points' cuts at level 0 (it holds every
    /// box of the form).
    pub(crate) hull: [[f64; 2]; D],
    /// The Bézier coefficients of `W = Σ wᵢNᵢ`.
    w: Vec<f64>,
    /// Per coefficient and coordinate: those of `Σ wᵢNᵢ·footˡ`,
    /// `Σ wᵢNᵢ·slopeˡ`, `Σ wᵢNᵢ·footʳ`, `Σ wᵢNᵢ·slopeʳ`.
    ends: Vec<[[f64; 4]; D]>,
}

impl<const D: usize> Form<D> {
    /// The form of the control points `ends` (row by row, `shape[0]` rows of
    /// `shape[1]`) with weights `weights`, from the Bézier matrices of the
    /// two directions (`mv = [1.0]` for a curve).
    pub(crate) fn new(
        [mu, mv]: [&[f64]; 2],
        shape: [usize; 2],
        weights: &[f64],
        ends: &[[CutEnds; D]],
        top: f64,
    ) -> Self {
        let [nu, nv] = shape;
        let n = nu * nv;
        let mut hull = [[f64::INFINITY, f64::NEG_INFINITY]; D];
        for e in ends {
            for (h, c) in hull.iter_mut().zip(e) {
                h[0] = h[0].min(c.foot_left);
                h[1] = h[1].max(c.foot_right);
            }
        }
        let mut w = vec![0.0; n];
        let mut out = vec![[[0.0; 4]; D]; n];
        for k in 0..nu {
            for l in 0..nv {
                let q = k * nv + l;
                for i in 0..nu {
                    for j in 0..nv {
                        let m = mu[k * nu + i] * mv[l * nv + j] * weights[i * nv + j];
                        if m == 0.0 {
                            continue;
                        }
                        w[q] += m;
                        for (o, e) in out[q].iter_mut().zip(&ends[i * nv + j]) {
                            o[0] += m * e.foot_left;
                            o[1] += m * e.slope_left;
                            o[2] += m * e.foot_right;
                            o[3] += m * e.slope_right;
                        }
                    }
                }
            }
        }
        Form {
            shape,
            top,
            hull,
            w,
            ends: out,
        }
    }

    /// Whether `p` lies within `slack` of the hull (else no box of the form
    /// holds it).
    pub(crate) fn may_hold(&self, p: &[f64; D], slack: f64) -> bool {
        self.hull
            .iter()
            .zip(p)
            .all(|(h, &x)| h[0] - slack <= x && x <= h[1] + slack)
    }

    /// The coefficients of the form's inequalities for the point `p` on the
    /// whole form, channel by channel (`4·D` channels of `shape[0]·shape[1]`):
    /// per coordinate the left `a`, the left `e`, the right `a`, the right `e`.
    fn root(&self, p: &[f64; D], slack: f64, out: &mut [f64]) {
        let n = self.w.len();
        for q in 0..n {
            let w = self.w[q];
            for (c, e) in self.ends[q].iter().enumerate() {
                let x = p[c];
                out[(4 * c) * n + q] = (x + slack) * w - e[0];
                out[(4 * c + 1) * n + q] = e[1];
                out[(4 * c + 2) * n + q] = e[2] - (x - slack) * w;
                out[(4 * c + 3) * n + q] = e[3];
            }
        }
    }

    /// The upper bound of the grade on a cell whose coefficients are `cell`,
    /// raising `lb` to the grades at its corners; and whether to split the
    /// cell across v rather than u: across the direction in which the
    /// inequality that sets the bound varies most (a coordinate crisp along
    /// u, as the cylinder's z, is then cut down in v alone to its thin strip
    /// of admitted parameters), or across the longer side (`at`, the cell in
    /// the form's unit square) where the top sets it.
    fn bound(&self, cell: &[f64], at: [[f64; 2]; 2], lb: &mut f64) -> (f64, bool) {
        let [nu, nv] = self.shape;
        let n = nu * nv;
        // The grades at the corners: exact values of the polynomials.
        let corners = [0, nv - 1, (nu - 1) * nv, n - 1];
        let corners = if nv == 1 {
            &corners[1..3]
        } else {
            &corners[..]
        };
        for &q in corners {
            let mut g = self.top;
            for j in 0..2 * D {
                g = g.min(level(cell[2 * j * n + q], cell[(2 * j + 1) * n + q]));
            }
            *lb = lb.max(g);
        }
        let mut ub = self.top;
        let mut binding = None;
        // The inequality with the next smallest bound below the top.
        let mut runner: Option<(f64, usize)> = None;
        for j in 0..2 * D {
            let a = &cell[2 * j * n..(2 * j + 1) * n];
            let e = &cell[(2 * j + 1) * n..(2 * j + 2) * n];
            let best = a
                .iter()
                .zip(e)
                .map(|(&a, &e)| level(a, e))
                .fold(f64::NEG_INFINITY, f64::max);
            if best < ub {
                if let Some(b) = binding {
                    runner = Some((ub, b));
                }
                ub = best;
                binding = Some(j);
            } else if best < self.top && runner.is_none_or(|(r, _)| best < r) {
                runner = Some((best, j));
            }
            if ub <= *lb {
                return (ub, false);
            }
        }
        if nv == 1 {
            *lb = lb.max(self.grade_at_crossing(cell));
            if let (Some(j1), Some((_, j2))) = (binding, runner) {
                ub = ub.min(combined_bound(cell, n, [j1, j2], ub));
            }
            if ub <= *lb {
                return (ub, false);
            }
        }
        let longer_v = at[1][1] - at[1][0] > at[0][1] - at[0][0];
        let along_v = match binding {
            _ if nv == 1 => false,
            None => longer_v,
            Some(j) => {
                // The inequality's coefficients at the bound's level, and
                // their largest step along each direction.
                let alpha = if ub.is_finite() { ub } else { 0.0 };
                let d = |q: usize| cell[2 * j * n + q] - alpha * cell[(2 * j + 1) * n + q];
                let (mut along_u, mut along_v) = (0.0_f64, 0.0_f64);
                for k in 0..nu {
                    for l in 0..nv {
                        let here = d(k * nv + l);
                        if k + 1 < nu {
                            along_u = along_u.max((d((k + 1) * nv + l) - here).abs());
                        }
                        if l + 1 < nv {
                            along_v = along_v.max((d(k * nv + l + 1) - here).abs());
                        }
                    }
                }
                if along_u == along_v {
                    longer_v
                } else {
                    along_v > along_u
                }
            }
        };
        (ub, along_v)
    }

    /// Splits the cell whose coefficients are `left` in two halves across v
    /// (`along_v`) or u: `left` keeps the first half, `right` gets the second.
    fn split(&self, left: &mut [f64], right: &mut [f64], along_v: bool) {
        let [nu, nv] = self.shape;
        let n = nu * nv;
        for (l, r) in left.chunks_mut(n).zip(right.chunks_mut(n)) {
            if along_v {
                for k in 0..nu {
                    split_half(&mut l[k * nv..], &mut r[k * nv..], 1, nv);
                }
            } else {
                for j in 0..nv {
                    split_half(&mut l[j..], &mut r[j..], nv, nu);
                }
            }
        }
    }

    /// A curve's cell (`shape[1] = 1`): the exact grade at the parameter
    /// where the chords of the inequalities' grades cross at their highest
    /// (the maximum over `[0, 1]` of the least of the lines through each
    /// inequality's grades at the cell's ends, clamped to `[−1, 2]`), or
    /// `−∞` when that is an end (whose grade is already counted). The
    /// chords only choose the parameter; the grade there is the polynomials'
    /// own value, so it is a lower bound of the sup, and where two
    /// inequalities cross (a corner of the grade) it is within the square of
    /// the cell's width of the peak, as the corners are only within its width.
    fn grade_at_crossing(&self, cell: &[f64]) -> f64 {
        const MOST: usize = 8;
        let n = self.shape[0];
        let m = 2 * D;
        if m > MOST {
            return f64::NEG_INFINITY;
        }
        let mut lines = [(0.0, 0.0); MOST];
        for (j, line) in lines.iter_mut().enumerate().take(m) {
            let end =
                |q: usize| level(cell[2 * j * n + q], cell[(2 * j + 1) * n + q]).clamp(-1.0, 2.0);
            let g0 = end(0);
            *line = (g0, end(n - 1) - g0);
        }
        let lines = &lines[..m];
        let least = |t: f64| {
            lines
                .iter()
                .map(|&(c, d)| c + d * t)
                .fold(f64::INFINITY, f64::min)
        };
        let (mut best_t, mut best) = (None, least(0.0).max(least(1.0)));
        for (i, &(ci, di)) in lines.iter().enumerate() {
            for &(cj, dj) in &lines[i + 1..] {
                if di * dj < 0.0 {
                    let t = (cj - ci) / (di - dj);
                    if t > 0.0 && t < 1.0 && least(t) > best {
                        (best_t, best) = (Some(t), least(t));
                    }
                }
            }
        }
        let Some(t) = best_t else {
            return f64::NEG_INFINITY;
        };
        let mut grade = self.top;
        for j in 0..m {
            grade = grade.min(level(
                bernstein_value(&cell[2 * j * n..(2 * j + 1) * n], t),
                bernstein_value(&cell[(2 * j + 1) * n..(2 * j + 2) * n], t),
            ));
        }
        grade
    }
}

/// An upper bound of the grade on a cell from a positive combination of
/// two inequalities `j1`, `j2` (their coefficients in `cell`, `n` each):
/// where both hold at `(t, alpha)`, so does `λ·first + (1 − λ)·second` for
/// every `λ ∈ [0, 1]`, and its Bernstein coefficients bound alpha as each
/// inequality's do (the largest `Aₖ/Eₖ`). `λ` cancels the change of the
/// combination across the cell at the level `alpha` (the bound so far), so
/// that where the two cross, one rising and one falling (a corner of the
/// grade), the bound's excess shrinks with the square of the cell's width
/// rather than with its width. `+∞` when the changes do not oppose.
fn combined_bound(cell: &[f64], n: usize, [j1, j2]: [usize; 2], alpha: f64) -> f64 {
    if !alpha.is_finite() {
        return f64::INFINITY;
    }
    let a = |j: usize, q: usize| cell[2 * j * n + q];
    let e = |j: usize, q: usize| cell[(2 * j + 1) * n + q];
    let change = |j: usize| (a(j, n - 1) - alpha * e(j, n - 1)) - (a(j, 0) - alpha * e(j, 0));
    let (d1, d2) = (change(j1), change(j2));
    let opposed = d1 * d2 < 0.0;
    if !opposed {
        return f64::INFINITY;
    }
    let lambda = d2 / (d2 - d1);
    (0..n)
        .map(|q| {
            level(
                lambda * a(j1, q) + (1.0 - lambda) * a(j2, q),
                lambda * e(j1, q) + (1.0 - lambda) * e(j2, q),
            )
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

/// The certified sup of the grade of `p` over `forms` (the spans, or span
/// rectangles, of one membership function), searched best first across all
/// of them at once: an upper bound at most [`GRADE_TOLERANCE`] above
/// `max(lb, sup)`. `lb` is a grade already reached (0 for a grade, whose
/// value is `max(0, sup)`; `−∞` for a test); cells whose bound is at most
/// `max(lb, floor)` are dropped (`floor` is a level not worth reaching, not
/// a grade reached), and forms whose hull misses `p` are never opened. The
/// search stops as soon as the grade reached is `stop_at` (then that grade
/// is returned), which is enough to tell whether the grade reaches a level.
///
/// Each cell keeps its own coefficients; its halves come from one de
/// Casteljau split at 1/2 (`set/bernstein.rs`), and the cell with the largest
/// bound over every form is split next, so no form is refined further than
/// the best grade elsewhere requires.
pub(crate) fn sup_of<const D: usize>(
    forms: &[Form<D>],
    p: &[f64; D],
    slack: f64,
    [mut lb, floor, stop_at]: [f64; 3],
    work: &mut Work,
) -> f64 {
    work.heap.clear();
    work.store.clear();
    work.free.clear();
    work.size = forms.iter().map(|f| 4 * D * f.w.len()).max().unwrap_or(0);
    let whole = [[0.0, 1.0], [0.0, 1.0]];
    for (index, f) in forms.iter().enumerate() {
        if lb >= stop_at {
            return lb;
        }
        if f.top <= lb.max(floor) || !f.may_hold(p, slack) {
            continue;
        }
        let slot = work.take();
        let len = 4 * D * f.w.len();
        f.root(p, slack, &mut work.store[slot..slot + len]);
        let (ub, along_v) = f.bound(&work.store[slot..slot + len], whole, &mut lb);
        if lb >= stop_at {
            return lb;
        }
        if ub > lb.max(floor) {
            work.heap.push(Cell {
                ub,
                at: whole,
                along_v,
                form: index,
                slot,
            });
        } else {
            work.free.push(slot);
        }
    }
    let mut terminal = f64::NEG_INFINITY;
    let mut count = 0usize;
    while let Some(&Cell {
        ub,
        at,
        along_v,
        form,
        slot,
    }) = work.heap.peek()
    {
        if ub <= lb.max(floor) {
            break;
        }
        if ub - lb <= GRADE_TOLERANCE || count >= MAX_CELLS {
            return ub.max(terminal);
        }
        work.heap.pop();
        let f = &forms[form];
        let len = 4 * D * f.w.len();
        let [[u0, u1], [v0, v1]] = at;
        let (a, b) = if along_v { (v0, v1) } else { (u0, u1) };
        let mid = 0.5 * (a + b);
        if !(a < mid && mid < b) {
            // A cell at the last bit of the parameter: no split is left.
            terminal = terminal.max(ub);
            work.free.push(slot);
            continue;
        }
        let other = work.take();
        {
            let (lo, hi) = work.store.split_at_mut(slot.max(other));
            let (first, second) = if slot < other {
                (&mut lo[slot..slot + len], &mut hi[..len])
            } else {
                (&mut hi[..len], &mut lo[other..other + len])
            };
            f.split(first, second, along_v);
        }
        for (half, s) in [([a, mid], slot), ([mid, b], other)] {
            let child = if along_v {
                [at[0], half]
            } else {
                [half, at[1]]
            };
            count += 1;
            let (ub, along_v) = f.bound(&work.store[s..s + len], child, &mut lb);
            if lb >= stop_at {
                return lb;
            }
            if ub > lb.max(floor) {
                work.heap.push(Cell {
                    ub,
                    at: child,
                    along_v,
                    form,
                    slot: s,
                });
            } else {
                work.free.push(s);
            }
        }
    }
    terminal.max(lb)
}

/// The largest alpha with `a − alpha·e ≥ 0` for `e ≥ 0`: `a/e`, or `±∞`
/// for `e = 0` as `a ≥ 0` or not.
fn level(a: f64, e: f64) -> f64 {
    if e > 0.0 {
        a / e
    } else if a >= 0.0 {
        f64::INFINITY
    } else {
        f64::NEG_INFINITY
    }
}

/// A cell waiting in the search, ordered by its upper bound: its place in
/// the unit square of form `form`, and where its coefficients are stored.
#[derive(Clone, Copy, Debug)]
struct Cell {
    ub: f64,
    at: [[f64; 2]; 2],
    along_v: bool,
    form: usize,
    slot: usize,
}

heap_ordered_by!(Cell, ub);

/// Buffers of one search, reused from point to point: the waiting cells,
/// the coefficients of each in a slot of `store` (all of one size), and the
/// slots free for reuse.
#[derive(Clone, Debug, Default)]
pub(crate) struct Work {
    heap: BinaryHeap<Cell>,
    store: Vec<f64>,
    free: Vec<usize>,
    size: usize,
}

impl Work {
    /// A slot of `size` values (the start of it), reused or new.
    fn take(&mut self) -> usize {
        if let Some(slot) = self.free.pop() {
            slot
        } else {
            let slot = self.store.len();
            self.store.resize(slot + self.size, 0.0);
            slot
        }
    }
}
