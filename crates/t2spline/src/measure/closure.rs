//! Whether a plane curve is closed, and which of its control points are one
//! point (docs/method.md §11).
//!
//! A curve **closes** when its crisp layer ends where it starts,
//! `C(a) = C(b)` on its domain `[a, b]` (to `10⁻⁹` of the size of its crisp
//! control polygon). The two usual constructions both close:
//!
//! - **clamped** knots with the last control point equal to the first
//!   (`C(a) = P₀`, `C(b) = Pₙ`): the last point **wraps** onto the first;
//! - **periodic**: unclamped knots whose first `2p` spans are as long as
//!   their last `2p` spans, with the last `p` control points (and weights)
//!   repeating the first `p`: point `n − p + 1 + i` wraps onto point `i`.
//!
//! Where the wrapped points carry the same fuzzy numbers (and weights) they
//! are one point of the box of control points, so every admissible curve
//! closes, and the measures take them as one ([`Closure::merged`]). Where
//! only their crisp values agree, the curve closes in its crisp layer but
//! an admissible curve need not: the enclosed area is then that of the
//! curve closed by the chord from its end back to its start, and the
//! closure says so ([`Closure::note`]).

use crate::error::Error;
use crate::fuzzy::Nt2Point;
use crate::nurbs::curve::rational_basis_span;
use crate::nurbs::KnotVector;
use crate::pipeline::FuzzyCurve;

/// How far apart the crisp ends may be, relative to the size of the crisp
/// control polygon, and still close.
pub const CLOSURE_TOLERANCE: f64 = 1e-9;

/// A curve that closes: how many control points wrap, and whether they
/// are one point with the points they wrap onto.
#[derive(Clone, Debug, PartialEq)]
pub struct Closure {
    /// The last `wrap` control points are the first `wrap` again.
    pub wrap: usize,
    /// Whether the wrapped points carry the same fuzzy numbers and weights
    /// as the points they repeat (then they are one point).
    pub merged: bool,
}

impl Closure {
    /// The note to give with an enclosed area whose wrapped points differ
    /// in their spreads; `None` when they are one point.
    #[must_use]
    pub fn note(&self) -> Option<String> {
        let which = match self.wrap {
            0 => "its knots do not wrap".to_owned(),
            1 => {
                "its last control point differs from its first in its spreads or weight".to_owned()
            }
            w => format!(
                "its last {w} control points differ from its first {w} in their spreads or weights"
            ),
        };
        (!self.merged).then(|| {
            format!(
                "the curve closes in its crisp layer only ({which}): the area enclosed is that of each admissible curve closed by the chord from its end to its start"
            )
        })
    }
}

impl<const D: usize> FuzzyCurve<D> {
    /// The curve's closure, or `None` if its crisp layer does not end where
    /// it starts (docs/method.md §11).
    #[must_use]
    pub fn closure(&self) -> Option<Closure> {
        self.closure_gap().ok()
    }

    /// The closure, or why the curve does not close: the crisp ends apart
    /// ([`Error::NotClosed`] with both ends).
    ///
    /// # Errors
    /// [`Error::NotClosed`] when the crisp layer's ends differ by more than
    /// [`CLOSURE_TOLERANCE`] of the size of the crisp control polygon.
    pub fn closure_gap(&self) -> Result<Closure, Error> {
        let crisp: Vec<[f64; D]> = self.points().iter().map(Nt2Point::crisp).collect();
        let (a, b) = (self.domain().start, self.domain().end);
        let start = point_at(self, &crisp, a);
        let end = point_at(self, &crisp, b);
        let size = extent(&crisp);
        let apart = start
            .iter()
            .zip(&end)
            .map(|(s, e)| (s - e).abs())
            .fold(0.0, f64::max);
        if apart > CLOSURE_TOLERANCE * size || self.points().len() < 3 {
            return Err(Error::NotClosed {
                start: start.to_vec(),
                end: end.to_vec(),
            });
        }
        let wrap = wrap(self.knots(), self.degree());
        let n = self.points().len();
        let merged = wrap > 0
            && wrap < n
            && (0..wrap).all(|i| {
                let j = n - wrap + i;
                self.points()[i] == self.points()[j] && self.weights()[i] == self.weights()[j]
            });
        Ok(Closure { wrap, merged })
    }
}

/// The crisp curve at `t` (in the domain).
fn point_at<const D: usize>(c: &FuzzyCurve<D>, crisp: &[[f64; D]], t: f64) -> [f64; D] {
    let (first, r) = rational_basis_span(c.knots(), c.weights(), t);
    let mut out = [0.0; D];
    for (ri, p) in r.iter().zip(&crisp[first..]) {
        for (o, x) in out.iter_mut().zip(p) {
            *o += ri * x;
        }
    }
    out
}

/// The largest extent of the points along a coordinate (1 if they are all
/// one point, so that the tolerance stays relative to something).
pub(crate) fn extent<const D: usize>(points: &[[f64; D]]) -> f64 {
    let mut size: f64 = 0.0;
    for d in 0..D {
        let (lo, hi) = points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[d]), hi.max(p[d]))
            });
        size = size.max(hi - lo);
    }
    if size > 0.0 {
        size
    } else {
        1.0
    }
}

/// How many control points wrap: 1 for clamped knots (the last point is
/// the first), `p` for periodic knots (the first `2p` spans as long as the
/// last `2p`), 0 otherwise.
fn wrap(knots: &KnotVector, p: usize) -> usize {
    if knots.is_clamped() {
        return 1;
    }
    let k = knots.as_slice();
    let m = k.len();
    // m = n + 2p + 1 knots for n + p control points; the comparison below is
    // span i against span i + n, which needs n ≥ 1 (for n < 2p the two
    // ranges overlap, and the test is still that the spacing repeats with
    // period n: a closed fit of degree p through p + 1 points has n = p + 1).
    if p == 0 || m < 2 * p + 2 {
        return 0;
    }
    let scale = (k[m - 1] - k[0]).abs().max(f64::MIN_POSITIVE);
    let periodic = (0..2 * p).all(|i| {
        let head = k[i + 1] - k[i];
        let tail = k[m - 2 * p + i] - k[m - 2 * p + i - 1];
        (head - tail).abs() <= 1e-12 * scale
    });
    if periodic {
        p
    } else {
        0
    }
}
