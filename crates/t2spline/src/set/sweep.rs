//! The boxes of a fuzzy curve at one level, sampled so finely in the
//! parameter that the sweep between two neighbours is their convex hull to a
//! stated tolerance: the common ground of regions and station sections.
//!
//! Between two parameters whose box corners move along straight lines, the
//! union of the boxes is exactly the convex hull of the two end boxes: the
//! points `(x, s)` with `x` in the box at `s` form a convex polytope (every
//! constraint `lo_c(s) ≤ x_c ≤ hi_c(s)` is linear in `(x, s)`), whose
//! projection is convex, contains both boxes and lies in their hull. The true
//! corners move along the curves `Σ Rᵢ(t)·endᵢ`; a step is halved until every
//! corner coordinate at its middle lies within the deviation bound of the
//! chord, so the true sweep lies within that bound of the hulls.

use crate::fuzzy::Membership;
use crate::pipeline::FuzzyCurve;
use crate::set::cut_lines::CutLines;
use crate::set::scan::{pieces, rational_basis};

/// Steps every piece starts with, before halving (so that a corner curve
/// that turns back within a piece is seen).
const FIRST_STEPS: usize = 8;
/// Halvings of a first step at most.
const MAX_DEPTH: u32 = 40;
/// Boxes of one sweep at most: past it the tolerance asked cannot be met.
pub(crate) const MAX_BOXES: usize = 4_000_000;

/// A box in two chosen coordinates: `[[x_lo, x_hi], [y_lo, y_hi]]`.
pub(crate) type PlaneBox = [[f64; 2]; 2];

/// The sampled boxes of the curve at one level, in runs: within a run the
/// sweep between neighbours is their hull; runs are separated where the
/// curve has no box (a lower cut absent on a span) or where a piece ends.
#[derive(Clone, Debug, Default)]
pub(crate) struct Sweep {
    pub(crate) runs: Vec<Vec<PlaneBox>>,
}

/// Why a sweep could not be made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct TooManyBoxes;

impl Sweep {
    /// The boxes of `curve` under `membership` at `alpha`, in the coordinates
    /// `axes`, with corner coordinates within `deviation` of the chords.
    pub(crate) fn of<const D: usize>(
        curve: &FuzzyCurve<D>,
        membership: Membership,
        alpha: f64,
        axes: [usize; 2],
        deviation: f64,
    ) -> Result<Sweep, TooManyBoxes> {
        let lines = CutLines::of(curve.points(), membership);
        let (knots, weights) = (curve.knots(), curve.weights());
        let p = curve.degree();
        let mut basis = vec![0.0; p + 1];
        let mut runs: Vec<Vec<PlaneBox>> = Vec::new();
        let mut count = 0usize;
        let all = pieces(knots, weights);
        let mut previous_valid = false;
        for (index, piece) in all.iter().enumerate() {
            let first = piece.first(p);
            if lines.top_of(first, p + 1) < alpha {
                // No box on this piece; at the knot where it meets the next
                // invalid piece a box can still exist (the points without a
                // cut have a zero basis function there).
                let next_valid = all
                    .get(index + 1)
                    .is_some_and(|n| lines.top_of(n.first(p), p + 1) >= alpha);
                if !previous_valid && !next_valid {
                    let t = piece.hi;
                    let span = knots.find_span(t);
                    rational_basis(knots, weights, span, t, &mut basis);
                    let f = span - p;
                    let top = basis
                        .iter()
                        .enumerate()
                        .filter(|(_, &r)| r > 0.0)
                        .fold(1.0_f64, |m, (j, _)| m.min(lines.top[f + j]));
                    if top >= alpha && index + 1 < all.len() {
                        runs.push(vec![plane(lines.box_at(f, &basis, alpha), axes)]);
                    }
                }
                previous_valid = false;
                continue;
            }
            previous_valid = true;
            let mut at = |t: f64| {
                rational_basis(knots, weights, piece.span, t, &mut basis);
                plane(lines.box_at(first, &basis, alpha), axes)
            };
            let mut run = Vec::new();
            let starts: Vec<f64> = piece.params(FIRST_STEPS).collect();
            run.push(at(starts[0]));
            for w in starts.windows(2) {
                let b1 = at(w[1]);
                halve(
                    &mut at,
                    (w[0], *run.last().unwrap_or(&b1)),
                    (w[1], b1),
                    deviation,
                    0,
                    &mut run,
                );
            }
            count += run.len();
            if count > MAX_BOXES {
                return Err(TooManyBoxes);
            }
            runs.push(run);
        }
        Ok(Sweep { runs })
    }
}

/// Pushes the boxes after `(t0, b0)` up to and including `(t1, b1)`, halving
/// the step while a corner coordinate at its middle is off the chord by more
/// than `deviation`.
fn halve(
    at: &mut impl FnMut(f64) -> PlaneBox,
    (t0, b0): (f64, PlaneBox),
    (t1, b1): (f64, PlaneBox),
    deviation: f64,
    depth: u32,
    out: &mut Vec<PlaneBox>,
) {
    let tm = 0.5 * (t0 + t1);
    if depth < MAX_DEPTH && tm > t0 && tm < t1 {
        let bm = at(tm);
        let off = (0..2)
            .flat_map(|c| (0..2).map(move |e| (c, e)))
            .map(|(c, e)| (bm[c][e] - 0.5 * (b0[c][e] + b1[c][e])).abs())
            .fold(0.0_f64, f64::max);
        if off > deviation && out.len() <= MAX_BOXES {
            halve(at, (t0, b0), (tm, bm), deviation, depth + 1, out);
            halve(at, (tm, bm), (t1, b1), deviation, depth + 1, out);
            return;
        }
    }
    out.push(b1);
}

/// The two coordinates `axes` of a box.
fn plane<const D: usize>(b: [[f64; 2]; D], [a, c]: [usize; 2]) -> PlaneBox {
    [b[a], b[c]]
}

/// The convex hull of two boxes grown by `grow` on every side, counter-
/// clockwise, without repeating the first vertex (Andrew's monotone chain).
pub(crate) fn hull_of(b0: &PlaneBox, b1: &PlaneBox, grow: f64) -> Vec<[f64; 2]> {
    let mut pts: Vec<[f64; 2]> = Vec::with_capacity(8);
    for b in [b0, b1] {
        let ([x0, x1], [y0, y1]) = (b[0], b[1]);
        let (x0, x1, y0, y1) = (x0 - grow, x1 + grow, y0 - grow, y1 + grow);
        pts.extend([[x0, y0], [x1, y0], [x1, y1], [x0, y1]]);
    }
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: &[f64; 2], a: &[f64; 2], b: &[f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut hull: Vec<[f64; 2]> = Vec::with_capacity(2 * pts.len());
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 {
            Box::new(pts.iter())
        } else {
            Box::new(pts.iter().rev())
        };
        for p in iter {
            while hull.len() >= start + 2
                && cross(&hull[hull.len() - 2], &hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(*p);
        }
        hull.pop();
    }
    hull
}
