//! Curvature at a parameter over the box of cut control points
//! (docs/method.md §11): a certified enclosure by interval arithmetic with
//! subdivision of the box.
//!
//! At `t` only the `p + 1` control points that count there matter:
//! `C' = Σⱼ aⱼPⱼ`, `C'' = Σⱼ bⱼPⱼ` with `aⱼ = Rⱼ'(t)`, `bⱼ = Rⱼ''(t)`, and
//! `κ = ‖C' × C''‖ / ‖C'‖³`. Each component of the cross product is bilinear
//! in two coordinates,
//!
//! ```text
//! (C' × C'')_{c,e} = Σⱼ Pⱼ,c · Σₖ (aⱼbₖ − bⱼaₖ)·Pₖ,e
//! ```
//! so on a sub-box the inner sums are exact ranges of linear functions and
//! the outer sum an interval product; `‖C'‖` is exact per coordinate. The
//! quotient of the two gives an enclosure of κ on the sub-box. Branch and
//! bound splits the sub-box whose bound is worst along its most influential
//! variable (width times `|aⱼ| + |bⱼ|`), and evaluates κ at every sub-box's
//! centre (values attained), until the bound is within `10⁻⁹` of the best
//! value or the budget is spent; the bracket's `gap` is what remains.
//! Where the derivative box holds the origin, some admissible curve stops at
//! `t` and has no curvature there: the quantity is undefined.

use std::collections::BinaryHeap;

use crate::heap_key::heap_ordered_by;

use crate::measure::bracket::Bracket;
use crate::measure::cut_box::CutBox;
use crate::measure::derivative::{derivative_box, holds_origin};

/// Sub-boxes expanded at most for each end.
const BUDGET: usize = 1500;
/// The relative agreement of bound and value that stops the search.
const AGREEMENT: f64 = 1e-9;

/// The curvature's local problem: the coefficients and the cuts of the
/// points that count at `t`.
pub(crate) struct Local {
    dim: usize,
    a: Vec<f64>,
    b: Vec<f64>,
    /// `aⱼbₖ − bⱼaₖ`, row `j`, column `k`.
    cross: Vec<f64>,
    lo: Vec<f64>,
    hi: Vec<f64>,
}

fn square([lo, hi]: [f64; 2]) -> [f64; 2] {
    if lo <= 0.0 && hi >= 0.0 {
        [0.0, lo.abs().max(hi.abs()).powi(2)]
    } else {
        let (l, h) = (lo.abs().min(hi.abs()), lo.abs().max(hi.abs()));
        [l * l, h * h]
    }
}

fn times([a, b]: [f64; 2], [c, d]: [f64; 2]) -> [f64; 2] {
    let p = [a * c, a * d, b * c, b * d];
    [
        p.iter().copied().fold(f64::INFINITY, f64::min),
        p.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    ]
}

impl Local {
    /// The points `first ..= first + p` of `cut` with coefficients `a`, `b`.
    pub(crate) fn new(cut: &CutBox, first: usize, a: &[f64], b: &[f64]) -> Self {
        let d = cut.dim;
        let range = first * d..(first + a.len()) * d;
        let n = a.len();
        let cross = (0..n * n)
            .map(|q| a[q / n] * b[q % n] - b[q / n] * a[q % n])
            .collect();
        Local {
            dim: d,
            a: a.to_vec(),
            b: b.to_vec(),
            cross,
            lo: cut.lo[range.clone()].to_vec(),
            hi: cut.hi[range].to_vec(),
        }
    }

    /// κ at the control points `x` (local, `D` per point); `None` where the
    /// first derivative vanishes.
    pub(crate) fn value(&self, x: &[f64]) -> Option<f64> {
        let d = self.dim;
        let comb = |coef: &[f64], c: usize| -> f64 {
            coef.iter().enumerate().map(|(j, a)| a * x[j * d + c]).sum()
        };
        // The two derivatives, on the stack for every dimension but huge ones.
        let mut small = [0.0; 16];
        let mut large = Vec::new();
        let both: &mut [f64] = if 2 * d <= small.len() {
            &mut small[..2 * d]
        } else {
            large.resize(2 * d, 0.0);
            &mut large
        };
        let (d1, d2) = both.split_at_mut(d);
        for c in 0..d {
            d1[c] = comb(&self.a, c);
            d2[c] = comb(&self.b, c);
        }
        let speed2: f64 = d1.iter().map(|v| v * v).sum();
        if speed2 == 0.0 {
            return None;
        }
        let mut cross2 = 0.0;
        for c in 0..d {
            for e in c + 1..d {
                let v = d1[c] * d2[e] - d1[e] * d2[c];
                cross2 += v * v;
            }
        }
        Some(cross2.sqrt() / (speed2 * speed2.sqrt()))
    }

    /// An enclosure of κ over the sub-box `[lo, hi]`; the upper end is
    /// infinite where the speed's range reaches 0.
    fn enclosure(&self, lo: &[f64], hi: &[f64]) -> [f64; 2] {
        let d = self.dim;
        let n = self.a.len();
        let linear = |coef: &dyn Fn(usize) -> f64, c: usize| -> [f64; 2] {
            let (mut l, mut h) = (0.0, 0.0);
            for j in 0..n {
                let k = coef(j);
                let (p, q) = (k * lo[j * d + c], k * hi[j * d + c]);
                l += p.min(q);
                h += p.max(q);
            }
            [l, h]
        };
        let mut speed2 = [0.0, 0.0];
        for c in 0..d {
            let s = square(linear(&|j| self.a[j], c));
            speed2 = [speed2[0] + s[0], speed2[1] + s[1]];
        }
        let mut cross2 = [0.0, 0.0];
        for c in 0..d {
            for e in c + 1..d {
                let mut comp = [0.0, 0.0];
                for j in 0..n {
                    let inner = linear(&|k| self.cross[j * n + k], e);
                    let p = times([lo[j * d + c], hi[j * d + c]], inner);
                    comp = [comp[0] + p[0], comp[1] + p[1]];
                }
                let s = square(comp);
                cross2 = [cross2[0] + s[0], cross2[1] + s[1]];
            }
        }
        let lo_k = cross2[0].sqrt() / (speed2[1] * speed2[1].sqrt());
        let hi_k = if speed2[0] > 0.0 {
            cross2[1].sqrt() / (speed2[0] * speed2[0].sqrt())
        } else {
            f64::INFINITY
        };
        // Outward by the rounding of the sums.
        let r = 1.0 + 64.0 * f64::EPSILON * (n * d) as f64;
        [lo_k / r, hi_k * r]
    }

    fn centre(lo: &[f64], hi: &[f64]) -> Vec<f64> {
        lo.iter().zip(hi).map(|(l, h)| l + (h - l) / 2.0).collect()
    }

    /// The variable to split: width times `|aⱼ| + |bⱼ|`.
    fn split(&self, lo: &[f64], hi: &[f64]) -> Option<usize> {
        let d = self.dim;
        (0..lo.len())
            .filter(|&v| lo[v] < hi[v])
            .map(|v| {
                (
                    (hi[v] - lo[v]) * (self.a[v / d].abs() + self.b[v / d].abs()),
                    v,
                )
            })
            .max_by(|x, y| x.0.total_cmp(&y.0))
            .map(|(_, v)| v)
    }

    /// The bracket of the largest (`up`) or, negated, the least κ:
    /// `[attained, bound]` in the direction searched.
    fn search(&self, up: bool, start: f64) -> [f64; 2] {
        let sign = if up { 1.0 } else { -1.0 };
        let key = |e: [f64; 2]| if up { e[1] } else { -e[0] };
        let mut best = sign * start;
        // The sub-boxes: `lo` then `hi` in a slot of `store` each, reused
        // once dropped.
        let len = self.lo.len();
        let mut store: Vec<f64> = self.lo.iter().chain(&self.hi).copied().collect();
        let mut free: Vec<usize> = Vec::new();
        let mut heap = BinaryHeap::new();
        heap.push(Cell {
            key: key(self.enclosure(&self.lo, &self.hi)),
            slot: 0,
        });
        let mut expanded = 0;
        let mut centre = self.lo.clone();
        while let Some(cell) = heap.peek() {
            if cell.key <= best + AGREEMENT * best.abs() || expanded >= BUDGET {
                break;
            }
            let Some(Cell { slot, .. }) = heap.pop() else {
                break;
            };
            expanded += 1;
            let (lo, hi) = store[slot..slot + 2 * len].split_at(len);
            let Some(v) = self.split(lo, hi) else {
                // A single point: its value is its bound.
                if let Some(k) = self.value(lo) {
                    best = best.max(sign * k);
                }
                free.push(slot);
                continue;
            };
            let mid = lo[v] + (hi[v] - lo[v]) / 2.0;
            // The upper half in a copy; the lower half in place.
            let upper = match free.pop() {
                Some(t) => {
                    store.copy_within(slot..slot + 2 * len, t);
                    t
                }
                None => {
                    let t = store.len();
                    store.extend_from_within(slot..slot + 2 * len);
                    t
                }
            };
            store[slot + len + v] = mid;
            store[upper + v] = mid;
            for s in [slot, upper] {
                let (lo, hi) = store[s..s + 2 * len].split_at(len);
                for ((m, l), h) in centre.iter_mut().zip(lo).zip(hi) {
                    *m = l + (h - l) / 2.0;
                }
                if let Some(k) = self.value(&centre) {
                    best = best.max(sign * k);
                }
                let key = key(self.enclosure(lo, hi));
                if key > best + AGREEMENT * best.abs() {
                    heap.push(Cell { key, slot: s });
                } else {
                    free.push(s);
                }
            }
        }
        let open = heap.peek().map_or(f64::NEG_INFINITY, |c| c.key);
        [sign * best, sign * open.max(best)]
    }
}

/// A sub-box waiting in the search: its bound, and where its ends are stored.
struct Cell {
    key: f64,
    slot: usize,
}

heap_ordered_by!(Cell, key);

/// The bracket of κ at a parameter whose first-derivative coefficients are
/// `a` and second `b`, on the points from `first`; `None` where the
/// derivative box holds the origin (undefined).
pub(crate) fn curvature_bracket(
    cut: &CutBox,
    first: usize,
    a: &[f64],
    b: &[f64],
) -> Option<Bracket> {
    if holds_origin(&derivative_box(cut, first, a)) {
        return None;
    }
    let local = Local::new(cut, first, a, b);
    let d = cut.dim;
    let crisp = &cut.crisp[first * d..(first + a.len()) * d];
    let start = local
        .value(crisp)
        .or_else(|| local.value(&Local::centre(&local.lo, &local.hi)))?;
    let [max_attained, max_bound] = local.search(true, start);
    let [min_attained, min_bound] = local.search(false, start);
    let exact = max_bound <= max_attained * (1.0 + AGREEMENT) + f64::MIN_POSITIVE
        && min_bound >= min_attained * (1.0 - AGREEMENT);
    Some(Bracket::from_ends(
        [min_bound.max(0.0), min_attained],
        [max_attained, max_bound],
        exact,
    ))
}
