//! The span rectangles of a surface and the search for the smallest value of
//! a function on one of them: shared by the distance between two surfaces
//! (`pipeline/surface_distance.rs`), the closest point and the bounding box.
//!
//! On a span rectangle (a *patch*) the surface is one smooth rational piece,
//! a convex combination of the `(p + 1)(q + 1)` control points acting there
//! (the convex hull property, The NURBS Book §4.4): bounds from those points
//! decide which patches need a search at all.

use super::tensor_product::NurbsSurface;
use crate::nelder_mead::nelder_mead_min;
use crate::nurbs::BoundingBox;
use crate::place::Direction;

/// A span rectangle: its span indices `[su, sv]` and its ranges in u and v.
pub(crate) type Patch = ([usize; 2], [[f64; 2]; 2]);

/// Scan steps per span, in each direction.
const SCAN_STEPS: usize = 16;
/// The simplex size at which the refinement stops, relative to the rectangle.
const REFINE_TOLERANCE: f64 = 1e-10;
/// Evaluations per Nelder–Mead run.
const REFINE_EVALUATIONS: usize = 2000;

/// The relative margin of a convex hull bound for the rounding of an
/// evaluation (at most `ku·kv ≤ 1024` terms of relative error `2⁻⁵³` each,
/// about `2.3·10⁻¹³`), with room to spare.
pub(crate) const HULL_SLACK: f64 = 1e-9;

impl<const D: usize> NurbsSurface<D> {
    /// The non-empty span rectangles, row by row (u outer, v inner).
    pub(crate) fn patches(&self) -> Vec<Patch> {
        let spans: Vec<Vec<(usize, [f64; 2])>> = Direction::BOTH
            .iter()
            .map(|&d| self.knots(d).spans().collect())
            .collect();
        spans[0]
            .iter()
            .flat_map(|&(su, ru)| spans[1].iter().map(move |&(sv, rv)| ([su, sv], [ru, rv])))
            .collect()
    }

    /// The control points acting on a patch: rows `su + 1 − ku ..= su`,
    /// columns `sv + 1 − kv ..= sv` of the net.
    pub(crate) fn patch_points(
        &self,
        &([su, sv], _): &Patch,
    ) -> impl Iterator<Item = &[f64; D]> + '_ {
        let ([ku, kv], nv) = (self.order(), self.shape()[1]);
        self.control_points()
            .chunks(nv)
            .skip(su + 1 - ku)
            .take(ku)
            .flat_map(move |row| row.iter().skip(sv + 1 - kv).take(kv))
    }

    /// The box of the control points acting on a patch, which holds the
    /// patch (convex hull property) but for rounding ([`HULL_SLACK`]).
    pub(crate) fn patch_box(&self, patch: &Patch) -> BoundingBox<D> {
        let mut points = self.patch_points(patch);
        // A patch has at least one point acting on it (orders ≥ 1).
        let first = points.next().copied().unwrap_or([0.0; D]);
        points.fold(BoundingBox::of_point(first), |b, p| b.with_point(*p))
    }
}

/// The smallest value of `f` on a patch's rectangle (borders included) and
/// where it is reached.
///
/// The rectangle is scanned on a 17 × 17 grid; every local minimum of the
/// scan (edges and corners included) for which `refine(value)` holds is
/// refined by Nelder–Mead ([`nelder_mead_min`]; restarted once from its
/// result with a small simplex, as is usual, since it can stop on a
/// flattened simplex), to a simplex of `10⁻¹⁰` of the rectangle. The result
/// is never above any scan value; a dip narrower than a scan cell that is
/// not below some scan value at its own scan points can be missed.
pub(crate) fn patch_min(
    &(_, [[a0, b0], [a1, b1]]): &Patch,
    f: impl Fn([f64; 2]) -> f64,
    refine: impl Fn(f64) -> bool,
) -> (f64, [f64; 2]) {
    let at = |k: usize, a: f64, b: f64| {
        if k == SCAN_STEPS {
            b
        } else {
            (a + (b - a) * (k as f64 / SCAN_STEPS as f64)).min(b)
        }
    };
    let n = SCAN_STEPS + 1;
    let grid: Vec<[f64; 2]> = (0..n * n)
        .map(|k| [at(k / n, a0, b0), at(k % n, a1, b1)])
        .collect();
    let values: Vec<f64> = grid.iter().map(|&x| f(x)).collect();
    let mut best = (values[0], grid[0]);
    let steps = [(b0 - a0) / SCAN_STEPS as f64, (b1 - a1) / SCAN_STEPS as f64];
    let tolerance = [REFINE_TOLERANCE * (b0 - a0), REFINE_TOLERANCE * (b1 - a1)];
    let bounds = [[a0, a1], [b0, b1]];
    for k in 0..n * n {
        let d = values[k];
        if d < best.0 {
            best = (d, grid[k]);
        }
        if refine(d) && is_local_min(&values, n, k) {
            let first = nelder_mead_min(&f, grid[k], steps, bounds, tolerance, REFINE_EVALUATIONS);
            let small = [steps[0] / 8.0, steps[1] / 8.0];
            let again = nelder_mead_min(&f, first.1, small, bounds, tolerance, REFINE_EVALUATIONS);
            let (v, x) = if again.0 < first.0 { again } else { first };
            if v < best.0 {
                best = (v, x);
            }
        }
    }
    best
}

/// Whether scan value `k` of an `n × n` grid is a local minimum: below its
/// neighbours that come before it and not above those after it, so that a
/// flat region counts once.
fn is_local_min(values: &[f64], n: usize, k: usize) -> bool {
    let (i, j) = ((k / n) as isize, (k % n) as isize);
    let d = values[k];
    for di in -1..=1isize {
        for dj in -1..=1isize {
            let (a, b) = (i + di, j + dj);
            if (di, dj) == (0, 0) || a < 0 || b < 0 || a >= n as isize || b >= n as isize {
                continue;
            }
            let m = a as usize * n + b as usize;
            let other = values[m];
            if (m < k && other <= d) || (m > k && other < d) {
                return false;
            }
        }
    }
    true
}
