//! The general type-2 reading of a number and its reduction by alpha-planes
//! (docs/method.md §9).
//!
//! No root is solved per level. On the plane at level `z` the Karnik–Mendel
//! function is `F_z = (1 − z)·F₀ + z·F₁`, linear in `z`, so the level whose
//! left end is `c` is explicit: `ζ(c) = −F₀/(−F₀ + F₁)`, a ratio of two
//! non-negative terms. Integrating `∫ z·c(z) dz` by parts turns it into
//! `∫ ζ(c)² dc`, smooth on each piece between breakpoints, where the integrand
//! in `z` grows like `z^(1/3)` and `z^(1/2)` at `z = 0` and rises steeply near
//! `z = 1` for thin primaries. It is integrated by the shared adaptive
//! Gauss–Kronrod quadrature to 1e-14 of the support, and tested against a
//! direct integration in `z` and 40-digit mpmath values
//! (`peer/alpha_planes_reference.py`).

use crate::fuzzy::{Alpha, Interval, Nt2Number};
use crate::quadrature::{integrate_pieces, Tolerance};
use crate::reduction::footprint::{self, Footprint, Frame, KmFunction, Triangles};

/// The accuracy promised for [`AlphaPlanes::defuzzified`], relative to the
/// width of the support `upper.right − upper.left`.
pub const ALPHA_PLANES_TOLERANCE: f64 = 1e-12;

/// The absolute tolerance of each of the two integrals, in local units (the
/// support has length 1): ten times below the promise, since the defuzzified
/// value takes half their difference, and above QUADPACK's rounding floor
/// `50·ε·∫ζ² ≤ 1.2e-14` (ζ² ∈ [0, 1] on at most the unit length).
const QUADRATURE_TOLERANCE: Tolerance = Tolerance {
    relative: 0.0,
    absolute: 1e-13,
};

/// Bisections allowed for one of the two integrals. The integrands are smooth
/// rational functions on each piece; a handful of bisections suffices, and
/// the bound only guarantees that the work ends.
const BISECTIONS: usize = 400;

/// The reduction of a number read as a general type-2 set (docs/method.md §9), by its
/// alpha-planes; made by [`Nt2Number::alpha_planes`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AlphaPlanes {
    widest: Interval,
    defuzzified: f64,
}

impl AlphaPlanes {
    /// The centroid `[c_l(0), c_r(0)]` of the widest plane `z = 0`: the
    /// footprint between LMF and UMF, so the same as [`Nt2Number::centroid`].
    #[must_use]
    pub fn widest(&self) -> Interval {
        self.widest
    }

    /// The defuzzified value `∫ z·(c_l(z) + c_r(z))/2 dz / ∫ z dz`, accurate to
    /// [`ALPHA_PLANES_TOLERANCE`] of the support's width.
    #[must_use]
    pub fn defuzzified(&self) -> f64 {
        self.defuzzified
    }
}

/// The local geometry shared by the planes of one number.
struct Planes {
    frame: Frame,
    b: [f64; 7],
    triangles: Triangles,
}

impl Planes {
    fn of(x: &Nt2Number) -> Option<Planes> {
        let frame = Frame::of(x)?;
        let b = frame.breakpoints(x);
        let triangles = Triangles::new(&b, x.height().get());
        Some(Planes {
            frame,
            b,
            triangles,
        })
    }
}

impl Nt2Number {
    /// The centroid `[c_l(z), c_r(z)]` of the alpha-plane at level `z` of the
    /// number read as a general type-2 set (Liu 2008, "An efficient centroid
    /// type-reduction strategy for general type-2 fuzzy logic system",
    /// Information Sciences 178:2224–2236; Mendel, Liu and Zhai 2009,
    /// "α-plane representation for type-2 fuzzy sets: theory and
    /// applications", IEEE TFS 17(5):1189–1207; docs/method.md §9).
    ///
    /// At every `x` the secondary membership is the triangle over
    /// `[LMF(x), UMF(x)]` with apex at the primary membership, so the plane at
    /// level `z` (the zSlice of Wagner and Hagras 2010, "Toward general type-2
    /// fuzzy logic systems based on zSlices", IEEE TFS 18(4):637–660) is the
    /// interval type-2 set between
    /// ```text
    /// lower_z = LMF + z·(primary − LMF),   upper_z = UMF − z·(UMF − primary)
    /// ```
    /// Both are piecewise linear with breakpoints at the seven values, so
    /// the exact centroid of [`Nt2Number::centroid`] applies. The planes nest:
    /// `c_l(z)` increases and `c_r(z)` decreases with `z`; `z = 0` gives the
    /// centroid of the footprint and `z = 1` the centroid of the primary
    /// triangle, `(primary.left + crisp + primary.right)/3`, at both ends
    /// (also when the primary triangle has zero width, where the plane at
    /// `z = 1` has no area; the planes below it then all have the centroid
    /// `[upper.left, upper.right]`).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, Nt2Number};
    /// let x = Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)?;
    /// let (c0, c1) = (x.alpha_plane_centroid(Alpha::try_new(0.0)?), x.alpha_plane_centroid(Alpha::try_new(1.0)?));
    /// assert_eq!(c0, x.centroid());
    /// assert!((c1.left() - 3.2 / 3.0).abs() < 1e-15 && (c1.right() - 3.2 / 3.0).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn alpha_plane_centroid(&self, z: Alpha) -> Interval {
        let z = z.get();
        let Some(p) = Planes::of(self) else {
            return Interval::new_unchecked(self.crisp(), self.crisp());
        };
        if z == 1.0 {
            let (c, _) = p.triangles.primary_centroid_and_area();
            let c = p.frame.global(c);
            return Interval::new_unchecked(c, c);
        }
        let [l, r] = footprint::centroid(&Footprint::plane(&p.b, &p.triangles, z));
        Interval::new_unchecked(p.frame.global(l), p.frame.global(r))
    }

    /// The alpha-plane reduction of the number read as a general type-2 set
    /// (docs/method.md §9; Liu 2008; Mendel, Liu and Zhai 2009): the type-1 set that
    /// gives `[c_l(z), c_r(z)]` ([`Nt2Number::alpha_plane_centroid`]) the
    /// membership `z`, defuzzified by its centroid
    /// ```text
    /// D = ∫₀¹ z·(c_l(z) + c_r(z))/2 dz / ∫₀¹ z dz = ∫₀¹ z·(c_l(z) + c_r(z)) dz
    /// ```
    ///
    /// **Computation.** On the plane at `z` the Karnik–Mendel function is
    /// linear in `z`: `F_z(c) = (1 − z)·F₀(c) + z·F₁(c)`, with `F₀` the
    /// function of the footprint (z = 0) and `F₁(c) = A_P·(c_P − c)` that of
    /// the primary triangle (area `A_P`, centroid `c_P`). So the level whose
    /// left end is `c` is explicit,
    /// ```text
    /// ζ_l(c) = −F₀(c) / (−F₀(c) + F₁(c)),   c ∈ [c_l(0), c_P]
    /// ```
    /// a ratio of two non-negative terms (no cancellation), increasing from 0
    /// to 1; `c_l(z)` is its inverse. Integrating by parts,
    /// ```text
    /// ∫₀¹ z·c_l(z) dz = c_P/2 − ½·∫_{c_l(0)}^{c_P} ζ_l(c)² dc
    /// ∫₀¹ z·c_r(z) dz = c_P/2 + ½·∫_{c_P}^{c_r(0)} ζ_r(c)² dc
    /// D = c_P + ½·( ∫_{c_P}^{c_r(0)} ζ_r² − ∫_{c_l(0)}^{c_P} ζ_l² )
    /// ```
    /// with `ζ_r` the same construction on the mirrored number. The integrands
    /// are smooth (ratios of a cubic and a line, bounded by 0 and 1) between
    /// consecutive breakpoints, where the integrals are split; each piece is
    /// integrated by adaptive Gauss–Kronrod (G7/K15) to `1e-14` per unit of
    /// the support's width, so that `D` is within
    /// [`ALPHA_PLANES_TOLERANCE`] = `1e-12` of the support's width (the
    /// tests check it against a direct integration over `z` to 1e-14). No
    /// root is solved inside the quadrature: `F₀` is evaluated directly.
    ///
    /// A symmetric number gives `crisp`; a crisp one gives `crisp`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::Nt2Number;
    /// // Upper = primary = T(0, 0, 1, 1), LMF of zero width: by hand (see the
    /// // tests) D = 16183/12960 − (320/243)·ln 2.
    /// let x = Nt2Number::try_new(0.0, [0.0, 1.0], [0.0, 1.0], [0.0, 0.0], 0.5)?;
    /// let d = x.alpha_planes().defuzzified();
    /// assert!((d - (16183.0 / 12960.0 - 320.0 / 243.0 * 2f64.ln())).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn alpha_planes(&self) -> AlphaPlanes {
        let Some(p) = Planes::of(self) else {
            let c = self.crisp();
            return AlphaPlanes {
                widest: Interval::new_unchecked(c, c),
                defuzzified: c,
            };
        };
        let (c_p, a_p) = p.triangles.primary_centroid_and_area();
        let fp = Footprint::plane(&p.b, &p.triangles, 0.0);
        let mirror = fp.mirrored();
        let (left, right) = (KmFunction::new(&fp), KmFunction::new(&mirror));
        let (c_l, c_r) = (left.root(), -right.root());
        let lower_part = squared_level_integral(&left, fp.breakpoints(), c_l, c_p, a_p);
        let upper_part = squared_level_integral(&right, mirror.breakpoints(), -c_r, -c_p, a_p);
        let d = (c_p + (upper_part - lower_part) / 2.0).clamp(c_l, c_r);
        AlphaPlanes {
            widest: Interval::new_unchecked(p.frame.global(c_l), p.frame.global(c_r.max(c_l))),
            defuzzified: p.frame.global(d),
        }
    }
}

/// `∫_{from}^{to} ζ(c)² dc` with `ζ(c) = −F₀(c) / (−F₀(c) + A_P·(c_P − c))`,
/// `to = c_P`, split at the breakpoints inside.
fn squared_level_integral(km: &KmFunction, b: &[f64; 7], from: f64, c_p: f64, a_p: f64) -> f64 {
    if from >= c_p {
        return 0.0;
    }
    let zeta2 = |c: f64| {
        // F₀ ≤ 0 right of its root, F₁ ≥ 0 left of c_P: clamp off rounding.
        let below = (-km.eval(c)).max(0.0);
        let above = (a_p * (c_p - c)).max(0.0);
        let total = below + above;
        if total > 0.0 {
            let z = below / total;
            z * z
        } else {
            // Only where both vanish: a single point c = c_l(0) = c_P.
            0.0
        }
    };
    // Pieces between the breakpoints, where ζ² is smooth.
    let mut pieces = Vec::with_capacity(8);
    let mut lo = from;
    for &knot in b.iter().filter(|&&k| k > from && k < c_p).chain([&c_p]) {
        pieces.push([lo, knot]);
        lo = knot;
    }
    integrate_pieces(|_, c| zeta2(c), &pieces, QUADRATURE_TOLERANCE, BISECTIONS)
        .0
        .value
}

#[cfg(test)]
mod tests {
    use super::*;

    fn n(crisp: f64, upper: [f64; 2], primary: [f64; 2], lower: [f64; 2], h: f64) -> Nt2Number {
        Nt2Number::try_new(crisp, upper, primary, lower, h).unwrap()
    }

    fn z(v: f64) -> Alpha {
        Alpha::try_new(v).unwrap()
    }

    #[test]
    fn right_triangle_planes_by_hand() {
        // Number: crisp 0, upper = primary = [0, 1], lower = [0, 0]. On [0, 1]
        // UMF = primary = 1 − x and LMF = 0, so upper_z = 1 − x and
        // lower_z = z·(1 − x). With ∫_c^1 (x − c)(1 − x) dx = (1 − c)³/6 and
        // ∫_0^1 (x − c)(1 − x) dx = 1/6 − c/2:
        //   F_z(c) = 1/6 − c/2 − (1 − z)(1 − c)³/6 = 0
        //     ⇔ (1 − z)u³ − 3u + 2 = 0 with u = 1 − c,       (left end)
        //   G_z(c) = z(1/6 − c/2) + (1 − z)(1 − c)³/6 = 0
        //     ⇔ z(1 − 3c) + (1 − z)(1 − c)³ = 0.              (right end)
        // At z = 1/2: u³ − 6u + 4 = 0 gives u = √3 − 1, c_l = 2 − √3; and
        // (1 − c)³ = 3c − 1 gives, with v = 1 − c, v³ + 3v − 2 = 0, v = ∛(1 + √2) − ∛(√2 − 1).
        let x = n(0.0, [0.0, 1.0], [0.0, 1.0], [0.0, 0.0], 0.5);
        let c = x.alpha_plane_centroid(z(0.5));
        let v = (1.0 + 2f64.sqrt()).cbrt() - (2f64.sqrt() - 1.0).cbrt();
        assert!((c.left() - (2.0 - 3f64.sqrt())).abs() < 2e-16, "{c:?}");
        assert!((c.right() - (1.0 - v)).abs() < 2e-16, "{c:?}");
        // z = 0: u³ − 3u + 2 = (u − 1)²(u + 2), c_l = 0; G_0 = (1 − c)³/6, c_r = 1.
        let c = x.alpha_plane_centroid(z(0.0));
        assert_eq!((c.left(), c.right()), (0.0, 1.0));
        // D: with ζ_l from the left equation, z = (u³ − 3u + 2)/u³, u ∈ [2/3, 1]:
        //   ∫ ζ_l² dc = ∫_{2/3}^{1} (1 − 3/u² + 2/u³)² du = 11/240;
        // with ζ_r from the right one, z = v³/((v − 1)²(v + 2)), v = 1 − c ∈ [0, 2/3]:
        //   ∫ ζ_r² dc = ∫_0^{2/3} v⁶/((v − 1)⁴(v + 2)²) dv = 152/81 − (640/243)·ln 2
        // (partial fractions), so D = 1/3 + (152/81 − 640/243·ln 2 − 11/240)/2
        //                           = 16183/12960 − (320/243)·ln 2 ≈ 0.33590186099.
        let d = x.alpha_planes().defuzzified();
        let exact = 16183.0 / 12960.0 - 320.0 / 243.0 * 2f64.ln();
        assert!((d - exact).abs() < 1e-15, "{d} vs {exact}");
    }

    #[test]
    fn zero_width_primary_has_planes_at_the_feet() {
        // Primary and lower collapse to crisp: every plane below z = 1 is a
        // scaled UMF over a zero LMF, with centroid [upper.left, upper.right].
        let x = n(0.0, [-1.0, 3.0], [0.0, 0.0], [0.0, 0.0], 0.5);
        assert_eq!(
            x.alpha_plane_centroid(z(0.7)),
            Interval::new_unchecked(-1.0, 3.0)
        );
        assert_eq!(
            x.alpha_plane_centroid(z(1.0)),
            Interval::new_unchecked(0.0, 0.0)
        );
        let d = x.alpha_planes().defuzzified();
        assert!((d - 1.0).abs() < 1e-15, "{d}");
    }
}
