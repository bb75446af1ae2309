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
/// rectangle `d` is the norm of one smooth rational patch. With fuzzy
/// weights (docs/method.md §16) the two surfaces have weights of their own
/// and the same knots: `d` is then the norm of the difference of two smooth
/// rational patches on each span rectangle, measured the same way. Neither
/// figure depends on a sampling grid:
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
        SurfaceDistance::of_gap(&Gap {
            a: difference,
            b: None,
        })
    }

    /// Measures `‖a(u, v) − b(u, v)‖` over the domain of two surfaces with
    /// the same knots and weights of their own (fuzzy weights,
    /// docs/method.md §16).
    pub(crate) fn between<const D: usize>(
        a: &NurbsSurface<D>,
        b: &NurbsSurface<D>,
    ) -> SurfaceDistance {
        SurfaceDistance::of_gap(&Gap { a, b: Some(b) })
    }

    /// The maximum and the rms of `gap` over its domain.
    fn of_gap<const D: usize>(gap: &Gap<'_, D>) -> SurfaceDistance {
        let surface = gap.a;
        let patches = surface.patches();
        // By the convex hull property (positive weights), `d` on a patch is at
        // most a bound from the control points acting on it (`Gap::bound`).
        // Patches are measured from the largest bound down, and one whose
        // bound is below the largest distance found so far is skipped: it
        // cannot hold the maximum. Ties go to the patch first in the net's
        // order, as if every patch had been measured in that order.
        let bounds: Vec<f64> = patches.iter().map(|p| gap.bound(p)).collect();
        let mut by_bound: Vec<usize> = (0..patches.len()).collect();
        by_bound.sort_by(|&a, &b| bounds[b].total_cmp(&bounds[a]));
        let mut best = (
            0.0,
            [
                surface.domain(Direction::U).start,
                surface.domain(Direction::V).start,
            ],
            usize::MAX,
        );
        for k in by_bound {
            if bounds[k] < best.0 {
                break;
            }
            let found = patch_max(gap, &patches[k]);
            if found.0 > best.0 || (found.0 == best.0 && found.0 > 0.0 && k < best.2) {
                best = (found.0, found.1, k);
            }
        }
        let rms = if best.0 > 0.0 {
            best.0 * mean_square(gap, &patches, best.0).sqrt()
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

/// The distance `d(u, v)` between a surface and a second surface with the
/// same knots (or `0`).
struct Gap<'a, const D: usize> {
    a: &'a NurbsSurface<D>,
    b: Option<&'a NurbsSurface<D>>,
}

impl<const D: usize> Gap<'_, D> {
    /// `d(u, v)` on the patch of the span indices `spans`.
    fn at(&self, spans: [usize; 2], u: f64, v: f64) -> f64 {
        let mut p = self.a.eval_in_spans(spans, u, v);
        if let Some(b) = self.b {
            for (x, y) in p.iter_mut().zip(b.eval_in_spans(spans, u, v)) {
                *x -= y;
            }
        }
        euclidean_norm(&p)
    }

    /// An upper bound of `d` on a patch. One surface: the largest norm of
    /// the control points acting there, of which the patch is a convex
    /// combination. Two: both points are convex combinations of their own
    /// control points, so their difference is one of the differences
    /// `Pₖ − Qₗ`, and its norm is at most the largest of theirs; the
    /// rounding of the two evaluations, relative to the points' own size,
    /// is added.
    fn bound(&self, patch: &Patch) -> f64 {
        let norms = |s: &NurbsSurface<D>| {
            s.patch_points(patch)
                .map(|p| euclidean_norm(p))
                .fold(0.0_f64, f64::max)
        };
        match self.b {
            None => norms(self.a) * (1.0 + HULL_SLACK),
            Some(b) => {
                let mut largest = 0.0_f64;
                for p in self.a.patch_points(patch) {
                    for q in b.patch_points(patch) {
                        let diff: [f64; D] = std::array::from_fn(|k| p[k] - q[k]);
                        largest = largest.max(euclidean_norm(&diff));
                    }
                }
                largest * (1.0 + HULL_SLACK) + HULL_SLACK * (norms(self.a) + norms(b))
            }
        }
    }
}

/// The largest distance on one patch and where it is reached: the smallest
/// value of `−d` ([`patch_min`]), refined from the scan's local maxima of
/// positive `d`.
fn patch_max<const D: usize>(gap: &Gap<'_, D>, patch: &Patch) -> (f64, [f64; 2]) {
    let minus = |[u, v]: [f64; 2]| -gap.at(patch.0, u, v);
    let (value, at) = patch_min(patch, minus, |v| v < 0.0);
    (-value, at)
}

/// The mean of `(d/scale)²` over the domain: per patch, its share of the
/// domain's area times the patch's own mean (in patch coordinates, so that
/// neither a tiny domain nor a tiny patch underflows).
fn mean_square<const D: usize>(gap: &Gap<'_, D>, patches: &[Patch], scale: f64) -> f64 {
    let (du, dv) = (gap.a.domain(Direction::U), gap.a.domain(Direction::V));
    let cubature = Cubature::new();
    let integrand = |&(spans, [[a0, b0], [a1, b1]]): &Patch| {
        move |x: f64, y: f64| {
            let u = (a0 + (b0 - a0) * x).min(b0);
            let v = (a1 + (b1 - a1) * y).min(b1);
            let d = gap.at(spans, u, v) / scale;
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
            let found = patch_max(&Gap { a: s, b: None }, &patch);
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
