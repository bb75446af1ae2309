//! The centroid of a number read as an interval type-2 set (docs/method.md §9): exact,
//! without sampling.
//!
//! `c_r` needs no root finder of its own: swapping UMF and LMF in the
//! Karnik–Mendel function is the same as mirroring `x`, so the routine that
//! finds `c_l` finds `c_r` on the mirrored footprint (and serves both integrals
//! of the alpha-plane value in `alpha_planes.rs`).

use crate::fuzzy::{Interval, Nt2Number};
use crate::reduction::footprint::{self, Footprint, Frame, Triangles};

impl Nt2Number {
    /// The centroid `[c_l, c_r]` of the number as an interval type-2 set: the
    /// smallest and largest centroid of a type-1 set embedded in its footprint
    /// of uncertainty, `LMF ≤ θ ≤ UMF` (Karnik and Mendel 2001, "Centroid of a
    /// type-2 fuzzy set", Information Sciences 132:195–220; docs/method.md §9).
    ///
    /// The centroid is computed exactly, from the triangles themselves; no
    /// sampling, no iteration over switch points.
    ///
    /// **Derivation.** The smallest centroid takes `θ = UMF` left of a switch
    /// point `ξ` and `θ = LMF` right of it (moving membership to the left can
    /// only lower a centroid); the best `ξ` is where the centroid equals `ξ`
    /// itself (Karnik and Mendel's switch-point condition), i.e. `c_l` is the
    /// root of
    /// ```text
    /// F(c) = ∫_{x<c} (x − c)·UMF(x) dx + ∫_{x>c} (x − c)·LMF(x) dx
    /// ```
    /// and `c_r` the root of the same with UMF and LMF swapped. Differentiating
    /// under the integral (the integrand vanishes at `x = c`):
    /// ```text
    /// F'(c)  = −( ∫_{x<c} UMF + ∫_{x>c} LMF ) < 0     F is strictly decreasing
    /// F''(c) = LMF(c) − UMF(c)                         piecewise linear
    /// F'''   = slope(LMF) − slope(UMF)                 piecewise constant
    /// ```
    /// So `F` is a cubic on each piece between consecutive values of
    /// `upper.left ≤ … ≤ upper.right` (the triangles' feet and apex), and
    /// `F(upper.left) = ∫ (x − upper.left)·LMF ≥ 0 ≥ ∫ (x − upper.right)·UMF =
    /// F(upper.right)`: the root is unique. It is found by evaluating `F` at
    /// the seven breakpoints (sums of trapezoid areas and moments), which
    /// picks the piece, and then the root of that piece's cubic
    /// ```text
    /// p(s) = F_j + w·s·( F'_j + w·s·( (LMF − UMF)(b_j⁺)/2 + (ΔLMF − ΔUMF)·s/6 ) ),  s ∈ [0, 1]
    /// ```
    /// (its Taylor expansion at the piece's left end `b_j`, width `w`) by
    /// Newton's method kept inside a bisection bracket, to about one unit in
    /// the last place. `c_r` is `c_l` of the mirrored number. All of it runs
    /// in coordinates where `crisp = 0` and the support has width 1, so spreads
    /// from 1e-300 to 1e150 neither underflow nor overflow.
    ///
    /// Unlike the paper's reduction (docs/method.md §3), `c_l ≤ crisp ≤ c_r` need not
    /// hold: a number with a much longer right side has both ends right of
    /// `crisp`. Always `upper.left ≤ c_l ≤ c_r ≤ upper.right`, and `c_l`/`c_r`
    /// bound the centroid of every embedded set: the primary triangle, the LMF
    /// (normalised) and the UMF. A crisp number gives `[crisp, crisp]`; an
    /// LMF of zero width gives `c_l = upper.left`, `c_r = upper.right` (an
    /// embedded set may then put all its mass near either foot).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::Nt2Number;
    /// // UMF = T(x; −1, 0, 1, 1), LMF = its half: c_l = t − 1 with t³ + 6t − 6 = 0.
    /// let x = Nt2Number::try_new(0.0, [-1.0, 1.0], [-1.0, 1.0], [-1.0, 1.0], 0.5)?;
    /// let t = (3.0 + 17f64.sqrt()).cbrt() - (17f64.sqrt() - 3.0).cbrt();
    /// let c = x.centroid();
    /// assert!((c.left() - (t - 1.0)).abs() < 1e-15 && (c.right() - (1.0 - t)).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn centroid(&self) -> Interval {
        let Some(frame) = Frame::of(self) else {
            return Interval::new_unchecked(self.crisp(), self.crisp());
        };
        let b = frame.breakpoints(self);
        let t = Triangles::new(&b, self.height().get());
        let [l, r] = footprint::centroid(&Footprint::plane(&b, &t, 0.0));
        Interval::new_unchecked(frame.global(l), frame.global(r))
    }
}

#[cfg(test)]
mod tests {
    use crate::fuzzy::Nt2Number;

    fn n(crisp: f64, upper: [f64; 2], primary: [f64; 2], lower: [f64; 2], h: f64) -> Nt2Number {
        Nt2Number::try_new(crisp, upper, primary, lower, h).unwrap()
    }

    #[test]
    fn equal_upper_and_lower_feet_by_hand() {
        // UMF = T(−1, 0, 1, 1), LMF = h·UMF. For c ∈ [−1, 0], t = c + 1:
        //   ∫_{−1}^{c} (x − c)(UMF − LMF) = (1 − h)·∫_0^t (y − t)·y dy = −(1 − h)·t³/6,
        //   ∫ (x − c)·LMF over all x = −c·h (the LMF has area h, mean 0),
        // so F(c) = −(1 − h)·t³/6 − (t − 1)·h. With h = 1/2: t³ + 6t − 6 = 0,
        // whose real root is (Cardano) t = ∛(3 + √17) − ∛(√17 − 3).
        let x = n(0.0, [-1.0, 1.0], [-1.0, 1.0], [-1.0, 1.0], 0.5);
        let t = (3.0 + 17f64.sqrt()).cbrt() - (17f64.sqrt() - 3.0).cbrt();
        let c = x.centroid();
        assert!((c.left() - (t - 1.0)).abs() < 2e-16, "{c:?} vs {}", t - 1.0);
        assert!((c.right() - (1.0 - t)).abs() < 2e-16, "{c:?}");
        // h = 1 leaves no uncertainty: the centroid of the triangle, 0.
        let x = n(0.0, [-1.0, 1.0], [-1.0, 1.0], [-1.0, 1.0], 1.0);
        assert_eq!(x.centroid().left(), 0.0);
        assert_eq!(x.centroid().right(), 0.0);
    }

    #[test]
    fn right_triangle_with_a_point_lower_by_hand() {
        // UMF(x) = 1 − x on [0, 1] (vertical edge at crisp = 0), LMF of zero
        // width. F(c) = ∫_0^c (x − c)(1 − x) dx < 0 for every c > 0 = F(0):
        // c_l = 0. For c_r, G(c) = ∫_c^1 (x − c)(1 − x) dx = (1 − c)³/6 > 0
        // for c < 1: c_r = 1.
        let x = n(0.0, [0.0, 1.0], [0.0, 0.5], [0.0, 0.0], 0.7);
        let c = x.centroid();
        assert_eq!((c.left(), c.right()), (0.0, 1.0));
    }

    #[test]
    fn right_triangle_with_equal_lower_by_hand() {
        // UMF(x) = 1 − x, LMF(x) = (1 − x)/2 on [0, 1]. With u = 1 − c:
        //   ∫_0^c (x − c)(1 − x) = 1/6 − c/2 − u³/6,  ∫_c^1 (x − c)(1 − x) = u³/6,
        // F(c) = 1/6 − c/2 − u³/6 + u³/12 = 0  ⇔  u³ − 6u + 4 = 0 ⇔ (u − 2)(u² + 2u − 2) = 0,
        // so u = √3 − 1 and c_l = 2 − √3. G(c) = (1/6 − c/2 − u³/6)/2 + u³/6 = 0
        //   ⇔ u³ + 3u − 2 = 0 (with 1/6 − c/2 = (3u − 2)/6), whose real root is
        // u = ∛(1 + √2) − ∛(√2 − 1) (Cardano), and c_r = 1 − u.
        let x = n(0.0, [0.0, 1.0], [0.0, 1.0], [0.0, 1.0], 0.5);
        let c = x.centroid();
        let u = (1.0 + 2f64.sqrt()).cbrt() - (2f64.sqrt() - 1.0).cbrt();
        assert!((c.left() - (2.0 - 3f64.sqrt())).abs() < 2e-16, "{c:?}");
        assert!(
            (c.right() - (1.0 - u)).abs() < 2e-16,
            "{c:?} vs {}",
            1.0 - u
        );
    }

    #[test]
    fn translation_and_scale_carry_over() {
        let base = n(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6);
        let c = base.centroid();
        for (shift, scale) in [(1e6, 1.0), (-3.0, 1e-200), (0.0, 1e140)] {
            let m = |v: f64| (v - 1.0) * scale + shift;
            let x = n(
                m(1.0),
                [m(0.4), m(1.9)],
                [m(0.6), m(1.6)],
                [m(0.8), m(1.3)],
                0.6,
            );
            let d = x.centroid();
            let tol = 1e-15 * (shift.abs() + 1.5 * scale);
            assert!(
                (d.left() - m(c.left())).abs() <= tol,
                "{shift} {scale}: {d:?}"
            );
            assert!(
                (d.right() - m(c.right())).abs() <= tol,
                "{shift} {scale}: {d:?}"
            );
        }
    }
}
