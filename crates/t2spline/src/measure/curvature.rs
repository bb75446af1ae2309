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

use std::cmp::Ordering;
use std::collections::BinaryHeap;

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
        Local {
            dim: d,
            a: a.to_vec(),
            b: b.to_vec(),
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
        let d1: Vec<f64> = (0..d).map(|c| comb(&self.a, c)).collect();
        let d2: Vec<f64> = (0..d).map(|c| comb(&self.b, c)).collect();
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
        Some(cross2.sqrt() / speed2.powf(1.5))
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
                    let inner = linear(&|k| self.a[j] * self.b[k] - self.b[j] * self.a[k], e);
                    let p = times([lo[j * d + c], hi[j * d + c]], inner);
                    comp = [comp[0] + p[0], comp[1] + p[1]];
                }
                let s = square(comp);
                cross2 = [cross2[0] + s[0], cross2[1] + s[1]];
            }
        }
        let lo_k = cross2[0].sqrt() / speed2[1].powf(1.5);
        let hi_k = if speed2[0] > 0.0 {
            cross2[1].sqrt() / speed2[0].powf(1.5)
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
        let mut heap = BinaryHeap::new();
        heap.push(Cell {
            key: key(self.enclosure(&self.lo, &self.hi)),
            lo: self.lo.clone(),
            hi: self.hi.clone(),
        });
        let mut expanded = 0;
        while let Some(cell) = heap.peek() {
            if cell.key <= best + AGREEMENT * best.abs() || expanded >= BUDGET {
                break;
            }
            let Some(cell) = heap.pop() else { break };
            expanded += 1;
            let Some(v) = self.split(&cell.lo, &cell.hi) else {
                // A single point: its value is its bound.
                if let Some(k) = self.value(&cell.lo) {
                    best = best.max(sign * k);
                }
                continue;
            };
            let mid = cell.lo[v] + (cell.hi[v] - cell.lo[v]) / 2.0;
            for half in 0..2 {
                let (mut lo, mut hi) = (cell.lo.clone(), cell.hi.clone());
                if half == 0 {
                    hi[v] = mid;
                } else {
                    lo[v] = mid;
                }
                if let Some(k) = self.value(&Self::centre(&lo, &hi)) {
                    best = best.max(sign * k);
                }
                let key = key(self.enclosure(&lo, &hi));
                if key > best + AGREEMENT * best.abs() {
                    heap.push(Cell { key, lo, hi });
                }
            }
        }
        let open = heap.peek().map_or(f64::NEG_INFINITY, |c| c.key);
        [sign * best, sign * open.max(best)]
    }
}

struct Cell {
    key: f64,
    lo: Vec<f64>,
    hi: Vec<f64>,
}

impl PartialEq for Cell {
    fn eq(&self, other: &Self) -> bool {
        self.key.total_cmp(&other.key) == Ordering::Equal
    }
}
impl Eq for Cell {}
impl PartialOrd for Cell {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Cell {
    fn cmp(&self, other: &Self) -> Ordering {
        self.key.total_cmp(&other.key)
    }
}

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
