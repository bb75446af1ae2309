//! Globally adaptive Gauss–Kronrod quadrature: the integral of a function of
//! one variable over an interval, or over a list of pieces, to a relative
//! tolerance within a budget of bisections. Shared by the arc length
//! ([`crate::NurbsCurve::arc_length`]) and the root mean square distance
//! ([`crate::Distance`]).
//!
//! Each piece gets the 15-point Kronrod rule and the 7-point Gauss rule on
//! the same nodes (Piessens, de Doncker-Kapenga, Überhuber, Kahaner,
//! *QUADPACK*, 1983, routine QK15) and QUADPACK's error estimate:
//!
//! ```text
//! K₁₅ = Σ wₖᴷ f(xₖ),  G₇ = Σ wₖᴳ f(xₖ)      (nodes and weights scaled to the piece)
//! R = ∫|f − K₁₅/h|  (by the Kronrod rule),  A = ∫|f|
//! error = max( R·min(1, (200·|K₁₅ − G₇|/R)^1.5),  50·ε·A )
//! ```
//! `|K₁₅ − G₇|` is the error of the Gauss rule; the Kronrod value that is kept
//! is far better, which the power 1.5 accounts for, and `50·ε·A` is the
//! rounding floor. As QUADPACK's QAG, the piece with the largest error is
//! bisected next, until the errors add up to at most
//! `max(absolute, relative·|total|)` or the budget of bisections runs out.
//! A piece narrower than 2⁻⁶⁰ of the piece it came from, or too narrow for its
//! midpoint to differ from its ends, is not bisected. The result says whether
//! the tolerance was met.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// Kronrod nodes on `[−1, 1]` (the positive half; QUADPACK `xgk`).
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights (QUADPACK `wgk`).
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_18,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_83,
];
/// Gauss weights of the nodes `XGK[1], XGK[3], XGK[5], XGK[7]` (QUADPACK `wg`).
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];
/// Bisections allowed below one of the given pieces.
const MAX_DEPTH: u32 = 60;

/// What the integration aims for: the estimated error of the total at most
/// `max(absolute, relative·|total|)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tolerance {
    /// Relative to the magnitude of the total.
    pub(crate) relative: f64,
    /// Absolute; 0 for a purely relative tolerance.
    pub(crate) absolute: f64,
}

impl Tolerance {
    /// A purely relative tolerance.
    pub(crate) fn relative(relative: f64) -> Self {
        Tolerance {
            relative,
            absolute: 0.0,
        }
    }

    fn met(self, error: f64, value: f64) -> bool {
        error <= self.absolute.max(self.relative * value.abs())
    }
}

/// The result of an integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Integral {
    /// The estimate.
    pub(crate) value: f64,
    /// Its estimated absolute error: the sum of the pieces' estimates.
    pub(crate) error: f64,
    /// Whether the error estimate met the tolerance; `false` when the budget
    /// ran out or pieces became too narrow to bisect first.
    pub(crate) converged: bool,
}

/// One final piece of an integration: `∫ f` over `[lo, hi]`, part of the
/// given piece `source`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Piece {
    /// The index of the given piece this one lies in.
    pub(crate) source: usize,
    /// Start.
    pub(crate) lo: f64,
    /// End.
    pub(crate) hi: f64,
    /// The Kronrod estimate of the integral over the piece.
    pub(crate) value: f64,
    /// Its error estimate.
    pub(crate) error: f64,
    depth: u32,
}

impl Eq for Piece {}

impl PartialOrd for Piece {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Piece {
    /// By error, so that the heap yields the worst piece first.
    fn cmp(&self, other: &Self) -> Ordering {
        self.error.total_cmp(&other.error)
    }
}

/// `∫ₐᵇ f` to `tolerance` with at most `budget` bisections.
pub(crate) fn integrate(
    mut f: impl FnMut(f64) -> f64,
    [a, b]: [f64; 2],
    tolerance: Tolerance,
    budget: usize,
) -> Integral {
    integrate_pieces(|_, x| f(x), &[[a, b]], tolerance, budget).0
}

/// `Σₖ ∫ f` over the pieces `pieces[k] = [lo, hi]` (disjoint; each `lo ≤ hi`),
/// to `tolerance` of the total with at most `budget` bisections. `f(k, x)` is
/// called with the index `k` of the given piece that holds `x` (inside it,
/// never at its ends), so that the integrand may differ from piece to piece,
/// as a curve does between knot spans. Returns the integral and the final
/// pieces, in the order of the given ones and increasing within each.
pub(crate) fn integrate_pieces(
    mut f: impl FnMut(usize, f64) -> f64,
    pieces: &[[f64; 2]],
    tolerance: Tolerance,
    budget: usize,
) -> (Integral, Vec<Piece>) {
    let mut heap: BinaryHeap<Piece> = pieces
        .iter()
        .enumerate()
        .filter(|(_, [lo, hi])| lo < hi)
        .map(|(k, &[lo, hi])| kronrod(&mut f, k, lo, hi, 0))
        .collect();
    let mut done = Vec::new();
    let (mut value, mut error) = sums(heap.iter().chain(&done));
    let mut budget = budget;
    while !tolerance.met(error, value) {
        let Some(worst) = heap.pop() else { break };
        let mid = worst.lo + (worst.hi - worst.lo) / 2.0;
        if worst.depth >= MAX_DEPTH || !(worst.lo < mid && mid < worst.hi) {
            done.push(worst);
            continue;
        }
        if budget == 0 {
            heap.push(worst);
            break;
        }
        budget -= 1;
        let left = kronrod(&mut f, worst.source, worst.lo, mid, worst.depth + 1);
        let right = kronrod(&mut f, worst.source, mid, worst.hi, worst.depth + 1);
        value += left.value + right.value - worst.value;
        error += left.error + right.error - worst.error;
        heap.push(left);
        heap.push(right);
        if tolerance.met(error, value) || error < 0.0 {
            // The running sums drift; decide on exact ones.
            (value, error) = sums(heap.iter().chain(&done));
        }
    }
    let mut all: Vec<Piece> = heap.into_vec();
    all.append(&mut done);
    all.sort_by(|p, q| p.source.cmp(&q.source).then(p.lo.total_cmp(&q.lo)));
    let (value, error) = sums(all.iter());
    let integral = Integral {
        value,
        error,
        converged: tolerance.met(error, value),
    };
    (integral, all)
}

/// The sums of the values and of the errors.
fn sums<'a>(pieces: impl Iterator<Item = &'a Piece>) -> (f64, f64) {
    pieces.fold((0.0, 0.0), |(v, e), p| (v + p.value, e + p.error))
}

/// The Kronrod estimate of `∫ f(source, ·)` over `[lo, hi]` and QUADPACK's
/// error estimate (QK15).
fn kronrod(
    f: &mut impl FnMut(usize, f64) -> f64,
    source: usize,
    lo: f64,
    hi: f64,
    depth: u32,
) -> Piece {
    let ([value], [error]) = kronrod_vector(|x| [f(source, x)], lo, hi);
    Piece {
        source,
        lo,
        hi,
        value,
        error,
        depth,
    }
}

/// The Kronrod estimates of `∫ f` over `[lo, hi]` for each of the `N`
/// components of `f`, and QUADPACK's error estimate of each (QK15, module
/// docs), from one evaluation of `f` per node.
pub(crate) fn kronrod_vector<const N: usize>(
    mut f: impl FnMut(f64) -> [f64; N],
    lo: f64,
    hi: f64,
) -> ([f64; N], [f64; N]) {
    let (centre, half) = (lo + (hi - lo) / 2.0, (hi - lo) / 2.0);
    // Nodes are kept inside the piece: rounding must not move one onto an
    // end or past it.
    let at = |x: f64| x.clamp(lo, hi);
    let mut values = [[[0.0; N]; 2]; 8];
    for (v, x) in values.iter_mut().zip(XGK) {
        *v = if x == 0.0 {
            [f(centre), [0.0; N]]
        } else {
            [f(at(centre - half * x)), f(at(centre + half * x))]
        };
    }
    let (mut value, mut error) = ([0.0; N], [0.0; N]);
    for c in 0..N {
        // The centre node's second value is 0 and adds nothing.
        let (mut kronrod, mut gauss, mut absolute) = (0.0, 0.0, 0.0);
        for (j, (v, w)) in values.iter().zip(WGK).enumerate() {
            kronrod += w * (v[0][c] + v[1][c]);
            absolute += w * (v[0][c].abs() + v[1][c].abs());
            if j % 2 == 1 {
                gauss += WG[j / 2] * (v[0][c] + v[1][c]);
            }
        }
        let mean = kronrod / 2.0;
        // The centre node (j = 7) is one node; the others come in pairs.
        let spread: f64 = values
            .iter()
            .zip(WGK)
            .enumerate()
            .map(|(j, (v, w))| {
                let pair = if j == 7 { 0.0 } else { (v[1][c] - mean).abs() };
                w * ((v[0][c] - mean).abs() + pair)
            })
            .sum();
        let (scale, spread, absolute) = (half.abs(), spread * half.abs(), absolute * half.abs());
        let mut e = ((kronrod - gauss) * scale).abs();
        if spread != 0.0 && e != 0.0 {
            e = spread * (200.0 * e / spread).powf(1.5).min(1.0);
        }
        if absolute > f64::MIN_POSITIVE / (50.0 * f64::EPSILON) {
            e = e.max(50.0 * f64::EPSILON * absolute);
        }
        value[c] = kronrod * half;
        error[c] = e;
    }
    (value, error)
}

#[cfg(test)]
mod tests;
