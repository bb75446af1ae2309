//! Nie and Tan's reduction of a number: the centroid of the average of its
//! lower and upper membership functions (docs/method.md §9), in closed form.

use crate::fuzzy::Nt2Number;
use crate::reduction::footprint::Frame;

impl Nt2Number {
    /// Nie and Tan's value: the centroid of `(LMF + UMF) / 2` (Nie and Tan
    /// 2008, "Towards an efficient type-reduction method for interval type-2
    /// fuzzy logic systems", Proc. FUZZ-IEEE 2008, 1425–1432; docs/method.md §9).
    ///
    /// A triangle `T(x; a, c, b, top)` has area `top·(b − a)/2` and centroid
    /// `(a + c + b)/3`, so the centroid of the sum of two triangles is their
    /// area-weighted mean:
    /// ```text
    /// A_U = (upper.right − upper.left)/2,   A_L = h·(lower.right − lower.left)/2
    /// nie_tan = ( A_U·(upper.left + crisp + upper.right) + A_L·(lower.left + crisp + lower.right) )
    ///           / ( 3·(A_U + A_L) )
    /// ```
    /// (evaluated relative to `crisp` and with the support scaled to width 1,
    /// so that no product over- or underflows). It always lies in
    /// [`centroid`](Nt2Number::centroid): `(LMF + UMF)/2` is an embedded set.
    /// A crisp number gives `crisp`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::Nt2Number;
    /// // UMF = T(0, 0, 1, 1): area 1/2, centroid 1/3; LMF of zero width.
    /// let x = Nt2Number::try_new(0.0, [0.0, 1.0], [0.0, 0.5], [0.0, 0.0], 0.6)?;
    /// assert!((x.nie_tan() - 1.0 / 3.0).abs() < 1e-16);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn nie_tan(&self) -> f64 {
        let Some(frame) = Frame::of(self) else {
            return self.crisp();
        };
        let b = frame.breakpoints(self);
        let area_upper = (b[6] - b[0]) / 2.0;
        let area_lower = self.height().get() * (b[4] - b[2]) / 2.0;
        let moment = area_upper * (b[0] + b[6]) + area_lower * (b[2] + b[4]);
        // area_upper ≈ 1/2 > 0 in local coordinates.
        frame.global(moment / (3.0 * (area_upper + area_lower)))
    }
}

#[cfg(test)]
mod tests {
    use crate::fuzzy::Nt2Number;

    #[test]
    fn two_triangles_by_hand() {
        // UMF = T(−1, 0, 2, 1): area 3/2, centroid 1/3.
        // LMF = T(−0.5, 0, 0.5, 0.4): area 0.2, centroid 0.
        // Nie–Tan = (3/2 · 1/3 + 0.2 · 0) / (3/2 + 0.2) = 0.5 / 1.7 = 5/17.
        let x = Nt2Number::try_new(0.0, [-1.0, 2.0], [-0.7, 1.0], [-0.5, 0.5], 0.4).unwrap();
        assert!((x.nie_tan() - 5.0 / 17.0).abs() < 1e-16, "{}", x.nie_tan());
    }

    #[test]
    fn extreme_magnitudes_stay_finite_and_exact() {
        for s in [1e-300, 1e149] {
            let x = Nt2Number::try_new(0.0, [-s, 2.0 * s], [-0.7 * s, s], [-0.5 * s, 0.5 * s], 0.4)
                .unwrap();
            let v = x.nie_tan();
            assert!((v / s - 5.0 / 17.0).abs() < 1e-15, "{s}: {v}");
        }
    }
}
