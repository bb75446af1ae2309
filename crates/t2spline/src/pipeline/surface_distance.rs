//! The distance between the crisp and the defuzzified surface over the whole
//! domain (docs/method.md §8).

use crate::cubature::Cubature;
use crate::nurbs::surface::patches::{patch_min, Patch, HULL_SLACK};
use crate::nurbs::{Direction, NurbsSurface};
use crate::vector::euclidean_norm;

/// How far the defuzzified surface `D(u, v)` lies from the crisp surface
/// `C(u, v)` at equal parameters over the whole domain `[a, b] × [c, d]`
/// (docs/method.md §8):
///
/// ```text
/// d(u, v) = ‖D(u, v) − C(u, v)‖₂
/// max     = max over the domain of d,     max_at = a (u, v) where it is reached
/// rms     = √( 1/((b − a)(d − c)) · ∫∫ d(u, v)² du dv )
/// ```
/// Both surfaces share weights and knots, so `D − C` is itself a rational
/// surface whose control points are the differences `Dᵢⱼ − Pᵢⱼ`; on each span
/// rectangle `d` is the norm of one smooth rational patch. Neither figure
/// depends on a sampling grid:
///
/// - **max**: each span rectangle is scanned on a 17 × 17 grid, and every
///   local maximum of the scan (edges and corners included) is refined by
///   Nelder–Mead on the patch (restarted once; the rectangle made unconstrained by a change of variables), to a simplex of `10⁻¹⁰` of
///   the rectangle. The value of a smooth maximum found so is within about
///   `10⁻¹⁶` of the true one (the error is quadratic in the position); the
///   result is never below any scan value. As for curves, a peak that is
///   narrower than a scan cell and lower than some scan value elsewhere at its
///   own scan points can be missed; patches of the low degrees in use have no
///   such peaks. Along a knot of full multiplicity, where the surfaces may
///   jump, each patch counts with its border (both one-sided limits).
/// - **rms**: the mean of `(d/max)²` over each span rectangle by adaptive
///   tensor Gauss–Legendre cubature (8 × 8 points per cell, a cell split in
///   four until it agrees with its quarters to `10⁻¹³` of the mean square's
///   size); polynomial patches of degree up to 7 are integrated exactly at
///   once. The relative error of `rms` is below `10⁻¹²` unless the budget of
///   20 000 subdivisions runs out (extreme weights over very many patches).
///
/// With symmetric spreads both are 0.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SurfaceDistance {
    /// The largest distance.
    pub max: f64,
    /// A parameter pair `[u, v]` where the largest distance is reached.
    pub max_at: [f64; 2],
    /// The root mean square distance over the domain.
    pub rms: f64,
}

/// The cubature's tolerance relative to the mean square.
const CUBATURE_TOLERANCE: f64 = 1e-13;
/// Cell subdivisions of the cubature over the whole domain.
const SUBDIVISIONS: usize = 20_000;

impl SurfaceDistance {
    /// Measures the norm of `difference(u, v)` over its domain.
    pub(crate) fn of_surface<const D: usize>(difference: &NurbsSurface<D>) -> SurfaceDistance {
        let patches = difference.patches();
        // By the convex hull property (positive weights), `d` on a patch is at
        // most the largest norm of the patch's difference control points
        // (plus rounding: a few units in the last place per basis term,
        // covered by HULL_SLACK). Patches are measured from the largest bound
        // down, and one whose bound is below the largest distance found so
        // far is skipped: it cannot hold the maximum. Ties go to the patch first in the net's
        // order, as if every patch had been measured in that order.
        let bounds: Vec<f64> = patches.iter().map(|p| hull_bound(difference, p)).collect();
        let mut by_bound: Vec<usize> = (0..patches.len()).collect();
        by_bound.sort_by(|&a, &b| bounds[b].total_cmp(&bounds[a]));
        let mut best = (
            0.0,
            [
                difference.domain(Direction::U).start,
                difference.domain(Direction::V).start,
            ],
            usize::MAX,
        );
        for k in by_bound {
            if bounds[k] < best.0 {
                break;
            }
            let found = patch_max(difference, &patches[k]);
            if found.0 > best.0 || (found.0 == best.0 && found.0 > 0.0 && k < best.2) {
                best = (found.0, found.1, k);
            }
        }
        let rms = if best.0 > 0.0 {
            best.0 * mean_square(difference, &patches, best.0).sqrt()
        } else {
            0.0
        };
        SurfaceDistance {
            max: best.0,
            max_at: best.1,
            rms,
        }
    }
}

/// The largest norm of the control points that act on a patch: an upper
/// bound of the patch's norm, which is a convex combination of them.
fn hull_bound<const D: usize>(s: &NurbsSurface<D>, patch: &Patch) -> f64 {
    s.patch_points(patch)
        .map(|p| euclidean_norm(p))
        .fold(0.0_f64, f64::max)
        * (1.0 + HULL_SLACK)
}

/// The largest distance on one patch and where it is reached: the smallest
/// value of `−d` ([`patch_min`]), refined from the scan's local maxima of
/// positive `d`.
fn patch_max<const D: usize>(s: &NurbsSurface<D>, patch: &Patch) -> (f64, [f64; 2]) {
    let minus = |[u, v]: [f64; 2]| -euclidean_norm(&s.eval_in_spans(patch.0, u, v));
    let (value, at) = patch_min(patch, minus, |v| v < 0.0);
    (-value, at)
}

/// The mean of `(d/scale)²` over the domain: per patch, its share of the
/// domain's area times the patch's own mean (in patch coordinates, so that
/// neither a tiny domain nor a tiny patch underflows).
fn mean_square<const D: usize>(s: &NurbsSurface<D>, patches: &[Patch], scale: f64) -> f64 {
    let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
    let cubature = Cubature::new();
    let integrand = |&(spans, [[a0, b0], [a1, b1]]): &Patch| {
        move |x: f64, y: f64| {
            let u = (a0 + (b0 - a0) * x).min(b0);
            let v = (a1 + (b1 - a1) * y).min(b1);
            let d = euclidean_norm(&s.eval_in_spans(spans, u, v)) / scale;
            d * d
        }
    };
    let share = |&(_, [[a0, b0], [a1, b1]]): &Patch| {
        ((b0 - a0) / (du.end - du.start)) * ((b1 - a1) / (dv.end - dv.start))
    };
    // A first estimate of the mean square sets the absolute tolerance.
    let mut none = 0;
    let rough: f64 = patches
        .iter()
        .map(|p| share(p) * cubature.mean(&integrand(p), f64::INFINITY, &mut none))
        .sum();
    let tolerance = CUBATURE_TOLERANCE * rough;
    let mut budget = SUBDIVISIONS;
    patches
        .iter()
        .map(|p| share(p) * cubature.mean(&integrand(p), tolerance, &mut budget))
        .sum()
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    /// Every patch measured, in the net's order: what the bound skips.
    fn every_patch<const D: usize>(s: &NurbsSurface<D>) -> (f64, [f64; 2]) {
        let mut best = (
            0.0,
            [s.domain(Direction::U).start, s.domain(Direction::V).start],
        );
        for patch in s.patches() {
            let found = patch_max(s, &patch);
            if found.0 > best.0 {
                best = found;
            }
        }
        best
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// Skipping the patches whose control points are all nearer than the
        /// distance found changes neither `max` nor `max_at`, ties included
        /// (levels drawn from a few values make equal patches common).
        #[test]
        fn the_hull_bound_skips_only_patches_that_cannot_hold_the_maximum(
            degrees in (1usize..4, 1usize..4),
            extra in (0usize..4, 0usize..4),
            levels in prop::collection::vec(0usize..4, 64),
            weights in prop::collection::vec(0.3f64..3.0, 64),
        ) {
            let [nu, nv] = [degrees.0 + 1 + extra.0, degrees.1 + 1 + extra.1];
            let net: Vec<Vec<[f64; 3]>> = (0..nu)
                .map(|i| (0..nv).map(|j| {
                    let h = [0.0, 0.5, 1.0, 1.0][levels[(i * nv + j) % 64]];
                    [0.0, 0.0, h]
                }).collect())
                .collect();
            let w: Vec<Vec<f64>> = (0..nu)
                .map(|i| (0..nv).map(|j| weights[(i * nv + j) % 64]).collect())
                .collect();
            let s = NurbsSurface::try_clamped([degrees.0, degrees.1], net, w).unwrap();
            let pruned = SurfaceDistance::of_surface(&s);
            let (max, max_at) = every_patch(&s);
            prop_assert_eq!(pruned.max.to_bits(), max.to_bits());
            prop_assert_eq!(pruned.max_at, max_at);
        }
    }
}
