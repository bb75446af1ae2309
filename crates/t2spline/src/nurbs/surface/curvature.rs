//! The curvature of a surface in space: Gaussian and mean curvature, the
//! principal curvatures and their directions, from the first and second
//! fundamental forms (do Carmo, *Differential Geometry of Curves and
//! Surfaces*, §3-2 and §3-3; Farin, *Curves and Surfaces for CAGD*, the
//! chapter on the differential geometry of surfaces).

use super::tensor_product::NurbsSurface;
use crate::error::Error;
use crate::vector::cross;
use crate::vector::dot;
use crate::vector::euclidean_norm;

/// The curvature of a surface in space at one point
/// ([`NurbsSurface::curvature`]).
///
/// Signs follow the unit normal `n` of [`NurbsSurface::normal`]: a normal
/// curvature is positive where the surface bends toward `n`. Reversing the
/// normal (swapping u and v) negates `mean` and both principal curvatures and
/// keeps `gaussian`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SurfaceCurvature {
    /// The Gaussian curvature `K = k₁·k₂`.
    pub gaussian: f64,
    /// The mean curvature `H = (k₁ + k₂)/2`.
    pub mean: f64,
    /// The principal curvatures `[k₁, k₂]`, `k₁ ≥ k₂`: the largest and the
    /// smallest normal curvature over the tangent directions.
    pub principal: [f64; 2],
    /// The unit principal directions `[e₁, e₂]` in space, tangent to the
    /// surface: the normal curvature is `k₁` along `e₁` and `k₂` along `e₂`,
    /// and `(e₁, e₂, n)` is a right-handed orthonormal frame. At an umbilic
    /// (`k₁ = k₂` within rounding) every tangent direction is principal;
    /// then `e₁ = S_u/‖S_u‖` and `e₂ = n × e₁`.
    pub directions: [[f64; 3]; 2],
}

/// Half the gap, `(k₁ − k₂)/2`, below which a point is taken as umbilic,
/// relative to the size of the second derivatives seen in the tangent frame
/// (the scale of the rounding in `k₁` and `k₂`, about 10⁻¹⁶ of it on the
/// sphere of the tests): a thousand times that rounding and more.
const UMBILIC_GAP: f64 = 1e-12;

impl NurbsSurface<3> {
    /// The curvature at `(u, v)`: Gaussian and mean curvature, the principal
    /// curvatures and directions, one-sided at knots as
    /// [`NurbsSurface::derivatives`].
    ///
    /// With the partial derivatives `S_u, S_v, S_uu, S_uv, S_vv` and the unit
    /// normal `n = S_u × S_v / ‖S_u × S_v‖` (do Carmo §3-3):
    ///
    /// ```text
    /// first fundamental form   E = S_u·S_u,   F = S_u·S_v,   G = S_v·S_v
    /// second fundamental form  L = S_uu·n,    M = S_uv·n,    N = S_vv·n
    ///
    /// K = (LN − M²) / (EG − F²)
    /// H = (EN − 2FM + GL) / (2(EG − F²))
    /// k₁,₂ = H ± √(H² − K)
    /// ```
    /// The normal curvature of the tangent `t = S_u·du + S_v·dv` is
    /// `κₙ = (L du² + 2M du dv + N dv²)/(E du² + 2F du dv + G dv²)`, the
    /// component along `n` of the curvature vector of any curve on the
    /// surface with that tangent; `k₁` and `k₂` are its extremes, and at the
    /// angle `θ` from `e₁` it is `k₁cos²θ + k₂sin²θ` (Euler's formula, do
    /// Carmo §3-2).
    ///
    /// The quantities are computed in the orthonormal tangent frame
    /// `a = S_u/‖S_u‖, b = n × a`, where the shape operator (Weingarten map)
    /// is the symmetric matrix `W = J⁻ᵀ·II·J⁻¹` (`J` the upper triangular
    /// matrix of `S_u, S_v` in that frame, `II` the matrix of `L, M, N`):
    ///
    /// ```text
    /// W = | w₁₁ w₁₂ |   H = (w₁₁ + w₂₂)/2,   K = det W = (LN − M²)·det J⁻¹²,
    ///     | w₁₂ w₂₂ |   r = √(((w₁₁ − w₂₂)/2)² + w₁₂²),   k₁,₂ = H ± r,
    ///                   e₁ = cos φ·a + sin φ·b,   φ = ½·atan2(2w₁₂, w₁₁ − w₂₂) ∈ (−π/2, π/2],
    ///                   e₂ = n × e₁
    /// ```
    /// The same numbers as the formulas above, but the discriminant `r²` is a
    /// sum of squares (never negative from rounding), the principal
    /// curvature of smaller magnitude is taken as `K/(H ± r)` (no
    /// cancellation where one is near 0), and the directions are orthonormal
    /// by construction. Where `k₁ − k₂` is within rounding of 0
    /// (an umbilic: a sphere, a plane) `φ = 0`; where `w₁₂` alone is, it
    /// counts as 0 (`φ = 0` or `π/2`).
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `(u, v)` is
    /// outside the domain; [`Error::SingularNormal`] where the normal is
    /// undefined (the test of [`NurbsSurface::normal`]);
    /// [`Error::IllConditioned`] where a result would not be a finite float
    /// (second derivatives beyond the float range, from knot spans far
    /// narrower than the coordinates).
    ///
    /// # Examples
    /// The cylinder of radius 2 about the z axis: no curvature along the
    /// axis, `−1/2` around it (the normal points outward, the surface bends
    /// away from it).
    /// ```
    /// # use t2spline::NurbsSurface;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let net = vec![
    ///     vec![[2.0, 0.0, 0.0], [2.0, 0.0, 1.0]],
    ///     vec![[2.0, 2.0, 0.0], [2.0, 2.0, 1.0]],
    ///     vec![[0.0, 2.0, 0.0], [0.0, 2.0, 1.0]],
    /// ];
    /// let s = NurbsSurface::try_clamped([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]])?;
    /// let c = s.curvature(0.3, 0.5)?;
    /// assert!(c.gaussian.abs() < 1e-15 && (c.mean + 0.25).abs() < 1e-15);
    /// assert!(c.principal[0].abs() < 1e-15 && (c.principal[1] + 0.5).abs() < 1e-15);
    /// assert!((c.directions[0][2].abs() - 1.0).abs() < 1e-15); // e₁ along the axis
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn curvature(&self, u: f64, v: f64) -> Result<SurfaceCurvature, Error> {
        self.check(u, v)?;
        self.curvature_unchecked(u, v)
    }

    /// [`NurbsSurface::curvature`] for `(u, v)` in the domain.
    pub(crate) fn curvature_unchecked(&self, u: f64, v: f64) -> Result<SurfaceCurvature, Error> {
        let d = self.derivatives_unchecked(u, v, 2);
        let (su, sv) = (&d[1][0], &d[0][1]);
        let (n, sine) = self.unit_normal(u, v, su, sv)?;
        let (suu, suv, svv) = (&d[2][0], &d[1][1], &d[0][2]);
        // The tangent frame a, b = n × a, and J⁻¹ = [[p11, p12], [0, p22]] for
        // J = [[‖S_u‖, S_v·a], [0, ‖S_v‖·sin ∠(S_u, S_v)]] (= ‖S_u × S_v‖/‖S_u‖).
        let length_u = euclidean_norm(su);
        let a = su.map(|x| x / length_u);
        let b = cross(&n, &a);
        let (p11, p22) = (1.0 / length_u, 1.0 / (euclidean_norm(sv) * sine));
        let p12 = -dot(sv, &a) * p11 * p22;
        let (l, m, nn) = (dot(suu, &n), dot(suv, &n), dot(svv, &n));
        // W = J⁻ᵀ·II·J⁻¹.
        let w11 = l * p11 * p11;
        let w12 = p11 * (l * p12 + m * p22);
        let w22 = l * p12 * p12 + 2.0 * m * p12 * p22 + nn * p22 * p22;
        let mean = 0.5 * (w11 + w22);
        // det W = det II · det J⁻¹² = (LN − M²)·(p11·p22)²: no cancellation
        // beyond that of LN − M².
        let gaussian = (l * nn - m * m) * (p11 * p22) * (p11 * p22);
        let half_gap = (0.5 * (w11 - w22)).hypot(w12);
        // The root of larger magnitude by H ± r, the other as K over it (the
        // stable form of a quadratic's roots).
        let larger = mean + half_gap.copysign(mean);
        let smaller = if larger == 0.0 {
            0.0
        } else {
            gaussian / larger
        };
        // The size the rounding of W is relative to: the second derivatives
        // mapped into the frame.
        let scale = (p11 * p11 + p12 * p12 + p22 * p22)
            * (euclidean_norm(suu) + 2.0 * euclidean_norm(suv) + euclidean_norm(svv));
        let tiny = UMBILIC_GAP * scale;
        let phi = if half_gap <= tiny {
            0.0
        } else {
            // W diagonal within rounding: e₁ along a or b exactly (a rounding
            // sign of w₁₂ would flip e₁ between φ = π/2 and −π/2).
            let w12 = if w12.abs() <= tiny { 0.0 } else { w12 };
            0.5 * (2.0 * w12).atan2(w11 - w22)
        };
        let (sin, cos) = phi.sin_cos();
        let e1 = std::array::from_fn(|k| cos * a[k] + sin * b[k]);
        let e2 = std::array::from_fn(|k| cos * b[k] - sin * a[k]);
        let c = SurfaceCurvature {
            gaussian,
            mean,
            principal: [larger.max(smaller), larger.min(smaller)],
            directions: [e1, e2],
        };
        check_finite(&c)?;
        Ok(c)
    }
}

/// `Ok` if every value of `c` is a finite float.
///
/// # Errors
/// [`Error::IllConditioned`] naming the first value that is not.
fn check_finite(c: &SurfaceCurvature) -> Result<(), Error> {
    let curvatures = [c.gaussian, c.mean, c.principal[0], c.principal[1]];
    let directions = c.directions.iter().flatten().copied();
    let what = curvatures
        .into_iter()
        .map(|x| ("a curvature", x))
        .chain(directions.map(|x| ("a principal direction", x)))
        .find(|(_, x)| !x.is_finite());
    match what {
        None => Ok(()),
        Some((what, value)) => Err(Error::IllConditioned {
            operation: "curvature",
            what,
            value,
            range: "the finite floats",
        }),
    }
}
