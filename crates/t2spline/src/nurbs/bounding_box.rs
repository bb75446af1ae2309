//! The axis-aligned bounding box of a curve.

use crate::nurbs::{Domain, NurbsCurve};

/// An axis-aligned box `[min, max]`, coordinate by coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingBox<const D: usize> {
    /// The smallest value of each coordinate.
    pub min: [f64; D],
    /// The largest value of each coordinate.
    pub max: [f64; D],
}

impl<const D: usize> BoundingBox<D> {
    /// The box of one point.
    #[must_use]
    pub fn of_point(p: [f64; D]) -> Self {
        BoundingBox { min: p, max: p }
    }

    /// The smallest box holding this box and the point `p`.
    #[must_use]
    pub fn with_point(mut self, p: [f64; D]) -> Self {
        for ((lo, hi), x) in self.min.iter_mut().zip(&mut self.max).zip(p) {
            *lo = lo.min(x);
            *hi = hi.max(x);
        }
        self
    }

    /// The smallest box holding both boxes.
    #[must_use]
    pub fn union(self, other: Self) -> Self {
        self.with_point(other.min).with_point(other.max)
    }

    /// Whether `p` lies in the box, enlarged by `tolerance` on every side.
    #[must_use]
    pub fn contains(&self, p: &[f64; D], tolerance: f64) -> bool {
        (0..D).all(|d| self.min[d] - tolerance <= p[d] && p[d] <= self.max[d] + tolerance)
    }
}

/// Samples per knot span, per degree, for the sign changes of `x'(t)`.
const SAMPLES_PER_DEGREE: usize = 16;

impl<const D: usize> NurbsCurve<D> {
    /// The tight axis-aligned bounding box of the curve over its domain (not
    /// the box of the control points, which only contains it).
    ///
    /// On each knot span a coordinate is extreme at the span's ends or where
    /// its derivative vanishes. The derivative is sampled at `16·k + 1`
    /// parameters per span; every sign change is refined by bisection to
    /// rounding, and the curve is evaluated there. Both one-sided limits at a
    /// jump count. An extremum pair closer together than the sampling step
    /// (a derivative touching zero without changing sign between two samples)
    /// could be missed; its effect on the box is below the curve's variation
    /// over one sampling step.
    ///
    /// # Examples
    /// The unit quarter circle lies in `[0, 1]²`; its control points reach
    /// (1, 1), the curve does not:
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
    /// let b = c.bounding_box();
    /// assert_eq!((b.min, b.max), ([0.0, 0.0], [1.0, 1.0]));
    /// // A parabola arch peaks inside: y ≤ 1/2, though its control point has y = 1.
    /// let p = NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], vec![1.0; 3])?;
    /// assert!((p.bounding_box().max[1] - 0.5).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    #[allow(clippy::needless_range_loop)] // `d` indexes the axis of every sample
    pub fn bounding_box(&self) -> BoundingBox<D> {
        let mut b = BoundingBox::of_point(self.eval_unchecked(self.domain().start));
        let steps = SAMPLES_PER_DEGREE * self.order();
        for (span, [lo, hi]) in self.knots().spans() {
            let at = |t: f64| self.derivatives_in_span(span, t, 1);
            b = b.with_point(at(lo)[0]).with_point(at(hi)[0]);
            let ts = Domain { start: lo, end: hi }.uniform_small(steps + 1);
            let ders: Vec<[f64; D]> = ts.iter().map(|&t| at(t)[1]).collect();
            for d in 0..D {
                for j in 0..steps {
                    let (f0, f1) = (ders[j][d], ders[j + 1][d]);
                    if f0 == 0.0 {
                        b = b.with_point(at(ts[j])[0]);
                    } else if f0.signum() != f1.signum() && f1 != 0.0 {
                        let t = bisect(|t| at(t)[1][d], ts[j], ts[j + 1], f0);
                        b = b.with_point(at(t)[0]);
                    }
                }
            }
        }
        b
    }
}

/// A root of `f` in `[a, b]`, where `f(a) = fa` and `f(b)` have opposite signs.
fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, fa: f64) -> f64 {
    loop {
        let m = a + (b - a) / 2.0;
        if m <= a || m >= b {
            return m;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if fm.signum() == fa.signum() {
            a = m;
        } else {
            b = m;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::fixtures::{jump, six_point_quadratic};

    #[test]
    fn box_contains_dense_samples_and_is_reached() {
        let c = six_point_quadratic();
        let b = c.bounding_box();
        let mut dense = BoundingBox::of_point(c.eval(0.0).unwrap());
        for t in c.domain().uniform(100_001).unwrap() {
            let p = c.eval(t).unwrap();
            assert!(b.contains(&p, 1e-14), "{t}: {p:?} outside {b:?}");
            dense = dense.with_point(p);
        }
        for d in 0..2 {
            assert!(
                dense.min[d] - b.min[d] < 1e-8 && b.max[d] - dense.max[d] < 1e-8,
                "{b:?} vs {dense:?}"
            );
        }
    }

    #[test]
    fn both_sides_of_a_jump_count() {
        let c = jump();
        assert_eq!(
            c.bounding_box(),
            BoundingBox {
                min: [0.0, 0.0],
                max: [6.0, 5.0]
            }
        );
    }
}
