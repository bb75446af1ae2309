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
    /// κ = ‖C' ∧ C''‖ / ‖C'‖³,   ‖a ∧ b‖² = Σ_{i<j} (a_i b_j − a_j b_i)²
    /// ```
    /// (‖C' × C''‖ / ‖C'‖³ in 3-D, |x'y'' − y'x''| / ‖C'‖³ in the plane).
    /// The wedge is summed from its 2 × 2 minors, not as
    /// √(‖C'‖²‖C''‖² − (C'·C'')²), which cancels to 0 where C'' is nearly
    /// along C' (a nearly straight part); both derivatives are scaled by
    /// their largest component first, so that nothing overflows for
    /// coordinates up to 1e150. One-sided at knots as in
    /// [`NurbsCurve::derivatives`].
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
        let (a, sa) = scaled(&d[1]);
        let (b, sb) = scaled(&d[2]);
        let unit_speed = norm(&a);
        let speed = sa * unit_speed;
        if speed * h <= 1e-14 * s || sa == 0.0 {
            return Err(Error::Singular {
                what: "curvature",
                t,
            });
        }
        if sb == 0.0 {
            return Ok(0.0);
        }
        let minors: Vec<f64> = (0..D)
            .flat_map(|i| (i + 1..D).map(move |j| (i, j)))
            .map(|(i, j)| a[i] * b[j] - a[j] * b[i])
            .collect();
        // ‖â ∧ b̂‖, scaled so that tiny minors do not underflow when squared.
        let wedge = scaled_norm(&minors);
        // κ = sa sb ‖â ∧ b̂‖ / (sa ‖â‖)³, in an order that cannot overflow.
        Ok(wedge / unit_speed.powi(3) * (sb / sa) / sa)
    }
}

/// `v / max |v_i|` and `max |v_i|` (0 and `v` itself for the zero vector).
fn scaled<const D: usize>(v: &[f64; D]) -> ([f64; D], f64) {
    let m = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if m == 0.0 || !m.is_finite() {
        return (*v, m);
    }
    (v.map(|x| x / m), m)
}

/// The Euclidean norm of `v`, each component divided by the largest before
/// it is squared (no underflow or overflow of the squares).
fn scaled_norm(v: &[f64]) -> f64 {
    let m = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * v.iter().map(|x| (x / m) * (x / m)).sum::<f64>().sqrt()
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

    #[test]
    fn a_nearly_straight_part_keeps_its_curvature() {
        // C(t) = (2t + t², e t²): C'(0) = (2, 0), C''(0) = (2, 2e), so
        // κ(0) = |2 · 2e − 0 · 2| / 2³ = e / 2 exactly. The form
        // √(‖C'‖²‖C''‖² − (C'·C'')²) cancels 16 + 16e² − 16 to 0 here.
        for e in [1e-3, 1e-9, 1e-15, 1e-200] {
            let c =
                NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [1.0, 0.0], [3.0, e]], vec![1.0; 3])
                    .unwrap();
            let k = c.curvature(0.0).unwrap();
            assert!((k - e / 2.0).abs() <= 1e-12 * e / 2.0, "e = {e}: {k}");
        }
    }

    #[test]
    fn huge_and_tiny_coordinates_scale_the_curvature() {
        // A circle of radius r has curvature 1 / r, for r from 1e-150 to 1e150.
        let w = std::f64::consts::FRAC_1_SQRT_2;
        for r in [1e-150, 1e-80, 1.0, 1e80, 1e150] {
            let c = NurbsCurve::try_clamped(2, vec![[r, 0.0], [r, r], [0.0, r]], vec![1.0, w, 1.0])
                .unwrap();
            let k = c.curvature(0.3).unwrap();
            assert!(k.is_finite() && (k * r - 1.0).abs() < 1e-13, "r = {r}: {k}");
        }
    }
}
