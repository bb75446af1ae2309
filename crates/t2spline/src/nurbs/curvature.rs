//! The curvature of a curve at a parameter, in any dimension, from its first
//! two derivatives ([`NurbsCurve::derivatives`], The NURBS Book A4.2), by the
//! classical formula for any regular parametrization.

use crate::error::Error;
use crate::nurbs::NurbsCurve;
use crate::vector::norm;

impl<const D: usize> NurbsCurve<D> {
    /// The curvature at `t`, in any dimension:
    ///
    /// ```text
    /// κ = √(‖C'‖²‖C''‖² − (C'·C'')²) / ‖C'‖³     (= ‖C' × C''‖ / ‖C'‖³ in 3-D)
    /// ```
    /// One-sided at knots as in [`NurbsCurve::derivatives`].
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is outside the domain; [`Error::Singular`]
    /// where the first derivative vanishes (test as in [`NurbsCurve::tangent`]).
    ///
    /// # Examples
    /// A circle of radius 1 has curvature 1:
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
    /// assert!((c.curvature(0.3)? - 1.0).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn curvature(&self, t: f64) -> Result<f64, Error> {
        self.domain().check(t)?;
        let d = self.derivatives_unchecked(t, 2);
        let (h, s) = self.scales(t);
        let speed = norm(&d[1]);
        if speed * h <= 1e-14 * s {
            return Err(Error::Singular {
                what: "curvature",
                t,
            });
        }
        let dot: f64 = d[1].iter().zip(&d[2]).map(|(a, b)| a * b).sum();
        let cross2 = (speed * speed * norm(&d[2]).powi(2) - dot * dot).max(0.0);
        Ok(cross2.sqrt() / speed.powi(3))
    }
}

#[cfg(test)]
mod tests {
    use crate::error::Error;
    use crate::nurbs::NurbsCurve;

    #[test]
    fn a_circle_of_radius_two_has_curvature_one_half() {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let c = NurbsCurve::try_clamped(
            2,
            vec![[2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
            vec![1.0, w, 1.0],
        )
        .unwrap();
        for t in [0.0, 0.25, 0.5, 0.9, 1.0] {
            assert!((c.curvature(t).unwrap() - 0.5).abs() < 1e-14, "t = {t}");
        }
    }

    #[test]
    fn a_line_has_curvature_zero_and_a_vanishing_speed_is_singular() {
        let line = NurbsCurve::try_clamped(1, vec![[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]], vec![1.0; 2])
            .unwrap();
        assert_eq!(line.curvature(0.4).unwrap(), 0.0);
        let c = NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [0.0, 0.0], [2.0, 0.0]], vec![1.0; 3])
            .unwrap();
        assert!(matches!(c.curvature(0.0), Err(Error::Singular { .. })));
        assert!(matches!(c.curvature(1.5), Err(Error::OutOfDomain { .. })));
    }
}
