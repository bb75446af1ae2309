//! The point of a curve closest to a given point (The NURBS Book, §6.1).

use crate::golden_section::golden_section_min;
use crate::nurbs::{Domain, NurbsCurve};
use crate::vector::{dot, norm, sub};

/// The result of [`NurbsCurve::closest_point`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosestPoint<const D: usize> {
    /// The parameter of the closest point.
    pub t: f64,
    /// The closest point `C(t)`.
    pub point: [f64; D],
    /// Its distance to the given point.
    pub distance: f64,
}

/// Samples per knot span, per degree, for the starting values.
const SAMPLES_PER_DEGREE: usize = 8;
/// Newton steps allowed from one start.
const NEWTON_STEPS: usize = 50;

impl<const D: usize> NurbsCurve<D> {
    /// The point of the curve closest to `target`, over the whole domain
    /// (both ends, every knot span, and both sides of a jump: at a knot where
    /// the curve jumps, `point` may be the left limit at `t`).
    ///
    /// Each knot span is sampled at `8·k + 1` parameters; from every sampled
    /// local minimum of the distance, Newton's method solves
    ///
    /// ```text
    /// f(t) = C'(t)·(C(t) − P) = 0,   f'(t) = C''(t)·(C(t) − P) + ‖C'(t)‖²
    /// ```
    /// inside the bracket of the neighbouring samples (The NURBS Book, Eq. 6.3),
    /// stopping on point coincidence, zero cosine or a parameter step below
    /// rounding (§6.1's criteria). A step that leaves the bracket, or a
    /// non-positive `f'`, falls back to golden-section search on the bracket.
    /// The best candidate wins. A local minimum narrower than the sampling step
    /// that is not the global one by more than the sampled values show can in
    /// principle be missed; the tests compare with dense sampling.
    ///
    /// # Examples
    /// The point of the unit quarter circle closest to (2, 2) is (√½, √½):
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
    /// let near = c.closest_point([2.0, 2.0]);
    /// assert!((near.point[0] - w).abs() < 1e-14 && (near.point[1] - w).abs() < 1e-14);
    /// assert!((near.distance - (8f64.sqrt() - 1.0)).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn closest_point(&self, target: [f64; D]) -> ClosestPoint<D> {
        let at = |t: f64| {
            let point = self.eval_unchecked(t);
            ClosestPoint {
                t,
                point,
                distance: norm(&sub(&point, &target)),
            }
        };
        let d = self.domain();
        let mut best = at(d.start);
        let steps = SAMPLES_PER_DEGREE * self.order();
        for (span, [a, b]) in self.knots().spans() {
            let ts = Domain { start: a, end: b }.uniform_small(steps + 1);
            // The end of a span is evaluated with its own piece (left limit).
            let dist: Vec<f64> = ts
                .iter()
                .map(|&t| norm(&sub(&self.eval_piece(t, span), &target)))
                .collect();
            for j in 0..=steps {
                let left = j == 0 || dist[j - 1] >= dist[j];
                let right = j == steps || dist[j + 1] >= dist[j];
                if !(left && right) {
                    continue;
                }
                let bracket = [ts[j.saturating_sub(1)], ts[(j + 1).min(steps)]];
                // The sample itself stays a candidate: at an end of the domain
                // the minimum need not be a root of f.
                let refined = self.refine_closest(&target, ts[j], bracket, span);
                for t in [ts[j], refined] {
                    let point = self.eval_piece(t, span);
                    let distance = norm(&sub(&point, &target));
                    if distance < best.distance {
                        best = ClosestPoint { t, point, distance };
                    }
                }
            }
        }
        best
    }

    /// `C(t)` on the polynomial piece of `span` (at its right end, the left
    /// limit, which differs from `C(t)` only at a jump).
    fn eval_piece(&self, t: f64, span: usize) -> [f64; D] {
        self.derivatives_in_span(span, t, 0)[0]
    }

    /// Newton's method for `C'(t)·(C(t) − P) = 0` from `t0` inside `bracket`,
    /// with golden-section search as the fallback.
    fn refine_closest(&self, target: &[f64; D], t0: f64, [lo, hi]: [f64; 2], span: usize) -> f64 {
        let eps = 1e-15 * (1.0 + norm(target));
        let mut t = t0;
        for _ in 0..NEWTON_STEPS {
            let d = self.derivatives_in_span(span, t, 2);
            let r = sub(&d[0], target);
            let (rn, sn) = (norm(&r), norm(&d[1]));
            if rn <= eps || sn == 0.0 {
                return t;
            }
            let f = dot(&d[1], &r);
            if f.abs() <= 1e-15 * sn * rn {
                return t;
            }
            let fp = dot(&d[2], &r) + sn * sn;
            if fp <= 0.0 {
                break;
            }
            let next = t - f / fp;
            if !(lo..=hi).contains(&next) {
                break;
            }
            if ((next - t) * sn).abs() <= eps {
                return next;
            }
            t = next;
        }
        let distance = |t: f64| norm(&sub(&self.eval_piece(t, span), target));
        let tolerance = 4.0 * f64::EPSILON * hi.abs().max(lo.abs()).max(f64::MIN_POSITIVE);
        golden_section_min(distance, [lo, hi], tolerance).1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::fixtures::{jump, six_point_quadratic};

    fn brute_force<const D: usize>(c: &NurbsCurve<D>, p: [f64; D]) -> f64 {
        c.domain()
            .uniform(200_001)
            .unwrap()
            .into_iter()
            .map(|t| norm(&sub(&c.eval(t).unwrap(), &p)))
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn closest_point_beats_dense_sampling() {
        let c = six_point_quadratic();
        for p in [
            [2.0, 1.0],
            [-3.0, -3.0],
            [10.0, 1.0],
            [3.5, 0.4],
            [1.0, 2.0],
        ] {
            let near = c.closest_point(p);
            let brute = brute_force(&c, p);
            assert!(near.distance <= brute + 1e-12, "{p:?}: {near:?} vs {brute}");
            assert!(brute - near.distance < 1e-6, "{p:?}: {near:?} vs {brute}");
        }
    }

    #[test]
    fn ends_and_points_on_the_curve() {
        let c = NurbsCurve::try_clamped(
            3,
            vec![[0.0, 0.0], [1.0, 2.0], [2.0, -1.0], [3.0, 1.0]],
            vec![1.0, 2.0, 1.0, 1.0],
        )
        .unwrap();
        let start = c.closest_point([-1.0, -1.0]);
        assert_eq!((start.t, start.point), (0.0, [0.0, 0.0]));
        let end = c.closest_point([5.0, 1.5]);
        assert_eq!(end.t, 1.0);
        let on = c.eval(0.61).unwrap();
        let found = c.closest_point(on);
        assert!(
            found.distance < 1e-14 && (found.t - 0.61).abs() < 1e-9,
            "{found:?}"
        );
    }

    #[test]
    fn both_sides_of_a_jump_are_candidates() {
        let c = jump();
        // (1, 0) is the left limit at t = 0.5; C(0.5) itself is (5, 5).
        let near = c.closest_point([1.2, 0.1]);
        assert!(
            (near.point[0] - 1.0).abs() < 1e-12 && near.point[1] == 0.0,
            "{near:?}"
        );
    }
}
