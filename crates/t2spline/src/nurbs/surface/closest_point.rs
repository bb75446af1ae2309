//! The point of a surface closest to a given point (The NURBS Book, §6.1,
//! Eqs. 6.5–6.8), a global minimum over the whole domain.

use super::tensor_product::NurbsSurface;
use crate::error::{Error, Place};
use crate::fuzzy::Axis;
use crate::limits::{within_magnitude, MAGNITUDE_RANGE};
use crate::nurbs::surface::patches::{patch_min, Patch, HULL_SLACK};
use crate::nurbs::BoundingBox;
use crate::vector::euclidean_norm;
use crate::vector::{dot, sub};

/// The result of [`NurbsSurface::closest_point`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosestSurfacePoint<const D: usize> {
    /// The parameter `u` of the closest point.
    pub u: f64,
    /// The parameter `v` of the closest point.
    pub v: f64,
    /// The closest point `S(u, v)`.
    pub point: [f64; D],
    /// Its distance to the given point.
    pub distance: f64,
}

/// Newton steps allowed from the refined scan minimum.
const NEWTON_STEPS: usize = 30;

impl<const D: usize> NurbsSurface<D> {
    /// The point of the surface closest to `target`, over the whole domain
    /// (interior, borders and corners; along a knot of full multiplicity,
    /// where the surface may jump, both one-sided limits count, and `point`
    /// may be the limit from the left at `(u, v)`).
    ///
    /// Each span rectangle (patch) is a convex combination of the control
    /// points acting on it, so the distance from `target` to their bounding
    /// box is a lower bound of the distance to the patch. Patches are searched
    /// from the smallest bound up, and the search stops at the first whose
    /// bound exceeds the best distance found. On a searched patch the distance
    /// is scanned on a 17 × 17 grid, every local minimum of the scan is
    /// refined by Nelder–Mead inside the patch (borders and corners
    /// included), and the best is polished by Newton's method on the normal
    /// equations (The NURBS Book, Eqs. 6.6–6.8), `r = S(u, v) − P`:
    ///
    /// ```text
    /// f = r·S_u = 0,  g = r·S_v = 0
    /// J = | ‖S_u‖² + r·S_uu    S_u·S_v + r·S_uv |
    ///     | S_u·S_v + r·S_uv   ‖S_v‖² + r·S_vv  |
    /// ```
    /// A step is clamped to the patch (on a border, the free parameter takes
    /// its own one-dimensional Newton step) and kept only while it lowers the
    /// distance. Ties go to the patch first in the net's order. As for
    /// curves, a local minimum narrower than a scan cell that is not the
    /// global one by what the scan shows can in principle be missed; the
    /// tests compare with dense sampling.
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::OutOfRange`] naming the axis if a
    /// coordinate of `target` is not finite or of magnitude above
    /// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE).
    ///
    /// # Examples
    /// The point of the unit quarter cylinder closest to (2, 2, 0.5) is the
    /// radial projection (√½, √½, 0.5), at distance √8 − 1:
    /// ```
    /// # use t2spline::NurbsSurface;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let net = vec![
    ///     vec![[1.0, 0.0, 0.0], [1.0, 0.0, 2.0]],
    ///     vec![[1.0, 1.0, 0.0], [1.0, 1.0, 2.0]],
    ///     vec![[0.0, 1.0, 0.0], [0.0, 1.0, 2.0]],
    /// ];
    /// let s = NurbsSurface::try_clamped([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]])?;
    /// let near = s.closest_point([2.0, 2.0, 0.5])?;
    /// assert!((near.point[0] - w).abs() < 1e-14 && (near.point[2] - 0.5).abs() < 1e-14);
    /// assert!((near.distance - (8f64.sqrt() - 1.0)).abs() < 1e-14);
    /// assert!(s.closest_point([f64::NAN, 0.0, 0.0]).is_err());
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn closest_point(&self, target: [f64; D]) -> Result<ClosestSurfacePoint<D>, Error> {
        check_target(&target)?;
        Ok(self.closest_point_searching(target, true))
    }

    /// The closest point, with the patches pruned by their bounds or (for
    /// the tests) every patch searched in the net's order.
    pub(crate) fn closest_point_searching(
        &self,
        target: [f64; D],
        prune: bool,
    ) -> ClosestSurfacePoint<D> {
        let patches = self.patches();
        let bounds: Vec<f64> = patches
            .iter()
            .map(|p| self.distance_bound(p, &target))
            .collect();
        let mut order: Vec<usize> = (0..patches.len()).collect();
        if prune {
            order.sort_by(|&a, &b| bounds[a].total_cmp(&bounds[b]));
        }
        // The start corner lies on the first patch, whose search never ends
        // above it, so it is replaced (index `usize::MAX` loses every tie).
        let (u, v) = (patches[0].1[0][0], patches[0].1[1][0]);
        let mut best = (self.candidate(patches[0].0, [u, v], &target), usize::MAX);
        for k in order {
            if prune && bounds[k] > best.0.distance {
                break;
            }
            let found = self.patch_closest(&patches[k], &target);
            if found.distance < best.0.distance || (found.distance == best.0.distance && k < best.1)
            {
                best = (found, k);
            }
        }
        best.0
    }

    /// A lower bound of the distance from `target` to a patch: the distance
    /// to the bounding box of its control points, widened for rounding.
    fn distance_bound(&self, patch: &Patch, target: &[f64; D]) -> f64 {
        let BoundingBox { min: lo, max: hi } = self.patch_box(patch);
        let gap: [f64; D] = std::array::from_fn(|d| {
            let slack = HULL_SLACK * lo[d].abs().max(hi[d].abs());
            (lo[d] - slack - target[d])
                .max(target[d] - hi[d] - slack)
                .max(0.0)
        });
        euclidean_norm(&gap) * (1.0 - HULL_SLACK)
    }

    /// The point of the patch at `x` and its distance to `target`.
    fn candidate(
        &self,
        spans: [usize; 2],
        [u, v]: [f64; 2],
        target: &[f64; D],
    ) -> ClosestSurfacePoint<D> {
        let point = self.eval_in_spans(spans, u, v);
        ClosestSurfacePoint {
            u,
            v,
            point,
            distance: euclidean_norm(&sub(&point, target)),
        }
    }

    /// The closest point on one patch: scan, Nelder–Mead, then Newton.
    fn patch_closest(&self, patch: &Patch, target: &[f64; D]) -> ClosestSurfacePoint<D> {
        let spans = patch.0;
        let distance =
            |[u, v]: [f64; 2]| euclidean_norm(&sub(&self.eval_in_spans(spans, u, v), target));
        let (_, x) = patch_min(patch, distance, |_| true);
        let mut best = self.candidate(spans, x, target);
        // Near the minimum the distance changes by less than its rounding, so
        // progress is judged by the residual of the normal equations; a step
        // may not raise the distance beyond rounding, which is that of
        // evaluating the point (a few ulps of its size, not of the distance:
        // a point at 1.5 from the origin and 0.2 from the target rounds by
        // 10⁻¹⁵ of the distance).
        let mut residual = f64::INFINITY;
        for _ in 0..NEWTON_STEPS {
            let Some((next, r)) = self.newton_step(patch, [best.u, best.v], target) else {
                break;
            };
            if r >= residual {
                break;
            }
            residual = r;
            let trial = self.candidate(spans, next, target);
            let rounding = 16.0 * f64::EPSILON * (euclidean_norm(&best.point) + best.distance);
            if trial.distance > best.distance + rounding {
                break;
            }
            best = trial;
        }
        best
    }

    /// One Newton step on the normal equations from `x`, clamped to the
    /// patch, and the residual `‖(r·S_u, r·S_v)‖` at `x` (without the
    /// components that push against a border `x` lies on); `None` where the
    /// Jacobian is not positive definite or the step does not move.
    fn newton_step(
        &self,
        (spans, range): &Patch,
        x: [f64; 2],
        target: &[f64; D],
    ) -> Option<([f64; 2], f64)> {
        let d = self.derivatives_in_spans(*spans, x[0], x[1], 2);
        let r = sub(&d[0][0], target);
        let (su, sv) = (&d[1][0], &d[0][1]);
        let g = [dot(&r, su), dot(&r, sv)];
        let j = [
            [
                dot(su, su) + dot(&r, &d[2][0]),
                dot(su, sv) + dot(&r, &d[1][1]),
            ],
            [
                dot(su, sv) + dot(&r, &d[1][1]),
                dot(sv, sv) + dot(&r, &d[0][2]),
            ],
        ];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if !(j[0][0] > 0.0 && det > 0.0) {
            return None;
        }
        let clamp = |k: usize, t: f64| t.clamp(range[k][0], range[k][1]);
        let mut next = [
            x[0] - (j[1][1] * g[0] - j[0][1] * g[1]) / det,
            x[1] - (j[0][0] * g[1] - j[1][0] * g[0]) / det,
        ];
        // On a border the constrained minimum moves along it only.
        let clamped: [bool; 2] = std::array::from_fn(|k| clamp(k, next[k]) != next[k]);
        for k in 0..2 {
            if clamped[1 - k] && !clamped[k] {
                next[k] = x[k] - g[k] / j[k][k];
            }
        }
        let next = [clamp(0, next[0]), clamp(1, next[1])];
        // A component of the gradient that points out of the patch on its
        // border is no residual: the minimum may lie there.
        let free: [f64; 2] = std::array::from_fn(|k| {
            let outward =
                (x[k] == range[k][0] && g[k] > 0.0) || (x[k] == range[k][1] && g[k] < 0.0);
            if outward {
                0.0
            } else {
                g[k]
            }
        });
        let moved = next != x && next.iter().all(|t| t.is_finite());
        moved.then_some((next, free[0].hypot(free[1])))
    }
}

/// Checks that every coordinate of a target point is finite and of magnitude
/// at most [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE).
///
/// # Errors
/// [`Error::NotFinite`] or [`Error::OutOfRange`] naming the axis.
pub(crate) fn check_target<const D: usize>(target: &[f64; D]) -> Result<(), Error> {
    for (&axis, &value) in Axis::first::<D>()?.iter().zip(target) {
        let place = Place {
            axis: Some(axis),
            ..Place::NONE
        };
        if !value.is_finite() {
            return Err(Error::NotFinite {
                place,
                what: "target",
                value,
            });
        }
        if !within_magnitude(value) {
            return Err(Error::OutOfRange {
                place,
                what: "target",
                value,
                range: MAGNITUDE_RANGE,
            });
        }
    }
    Ok(())
}
