//! Curvature of surfaces on random rational surfaces: the relations between
//! the quantities, the classical formulas of the fundamental forms, and
//! Euler's formula against the normal curvature of curves on the surface
//! (isocurves exactly, straight lines in (u, v) by central differences).

use proptest::prelude::*;
use t2spline::{strategies, Direction, Error, NurbsSurface, SurfaceCurvature};

const EPS: f64 = f64::EPSILON;

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `Σ cₖ·vₖ`.
fn combine(terms: &[(f64, &[f64; 3])]) -> [f64; 3] {
    std::array::from_fn(|d| terms.iter().map(|(c, v)| c * v[d]).sum())
}

/// A rational bicubic patch on a 4 × 4 net: mostly a wavy graph over the
/// unit grid (regular everywhere), sometimes any net in `[−10, 10]³`.
fn bicubic() -> impl Strategy<Value = NurbsSurface<3>> {
    let graph = proptest::collection::vec(
        (-0.4..0.4f64, -0.4..0.4f64, -2.0..2.0f64).prop_map(|(a, b, z)| [a, b, z]),
        16,
    )
    .prop_map(|offsets| {
        (0..16)
            .map(|k| {
                let [a, b, z] = offsets[k];
                [(k / 4) as f64 + a, (k % 4) as f64 + b, z]
            })
            .collect::<Vec<_>>()
    });
    let wild = proptest::collection::vec(proptest::array::uniform3(-10.0..10.0f64), 16);
    (
        prop_oneof![3 => graph, 1 => wild],
        proptest::collection::vec(0.3..3.0f64, 16),
    )
        .prop_map(|(points, weights)| {
            let net = points.chunks(4).map(<[_]>::to_vec).collect();
            let weights = weights.chunks(4).map(<[_]>::to_vec).collect();
            NurbsSurface::try_clamped([3, 3], net, weights).unwrap()
        })
}

/// The point `(a, b)` of the unit square mapped into the domain.
fn at(s: &NurbsSurface<3>, a: f64, b: f64) -> (f64, f64) {
    let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
    (
        du.start + a * (du.end - du.start),
        dv.start + b * (dv.end - dv.start),
    )
}

/// The curvature at `(u, v)`, or `None` where the normal is singular (then
/// `normal` says so too).
fn curvature(s: &NurbsSurface<3>, u: f64, v: f64) -> Option<SurfaceCurvature> {
    match s.curvature(u, v) {
        Ok(c) => Some(c),
        Err(e) => {
            assert_eq!(e, Error::SingularNormal { u, v });
            assert_eq!(s.normal(u, v), Err(e));
            None
        }
    }
}

/// The normal curvature `k₁cos²θ + k₂sin²θ` of Euler's formula in the
/// direction of the tangent `t`.
fn euler(c: &SurfaceCurvature, t: &[f64; 3]) -> f64 {
    let (cos, sin) = (dot(t, &c.directions[0]), dot(t, &c.directions[1]));
    let length2 = cos * cos + sin * sin;
    (c.principal[0] * cos * cos + c.principal[1] * sin * sin) / length2
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// K = k₁k₂, H = (k₁ + k₂)/2, k₁ ≥ k₂, (e₁, e₂, n) a right-handed
    /// orthonormal frame, and K and H as the classical formulas give them,
    /// on surfaces of any degrees and knots.
    ///
    /// Tolerances: 32ε (about 7e-15) relative to the size of the terms
    /// each quantity is a sum of, the forward rounding bound of the formulas
    /// (`(|LN| + M²)/(EG − F²)` for K, `(|EN| + 2|FM| + |GL|)/(2(EG − F²))`
    /// for H, each times `(EG + F²)/(EG − F²)`, the cancellation of the
    /// denominator), and of `κ = max |kᵢ|` for the principal curvatures.
    /// Directions: 1e-14.
    #[test]
    fn curvatures_are_consistent_and_match_the_fundamental_forms(
        s in strategies::surface::<3>(), a in 0.0..=1.0f64, b in 0.0..=1.0f64,
    ) {
        let (u, v) = at(&s, a, b);
        let Some(c) = curvature(&s, u, v) else { return Ok(()) };
        let n = s.normal(u, v).unwrap();
        let d = s.derivatives(u, v, 2).unwrap();
        let (su, sv) = (&d[1][0], &d[0][1]);
        let (e, f, g) = (dot(su, su), dot(su, sv), dot(sv, sv));
        let (l, m, nn) = (dot(&d[2][0], &n), dot(&d[1][1], &n), dot(&d[0][2], &n));
        let det = e * g - f * f;
        prop_assume!(det > 1e-8 * e * g); // the classical formula's own cancellation
        let denominator = (e * g + f * f) / det;
        let [k1, k2] = c.principal;
        let kappa = k1.abs().max(k2.abs());
        let k_size = ((l * nn).abs() + m * m) / det * denominator;
        let h_size = ((e * nn).abs() + 2.0 * (f * m).abs() + (g * l).abs()) / (2.0 * det) * denominator;
        let (k_tol, h_tol) = (32.0 * EPS * k_size, 32.0 * EPS * (h_size + kappa));

        let k = (l * nn - m * m) / det;
        prop_assert!((c.gaussian - k).abs() <= k_tol, "{c:?} vs {k} ± {k_tol}");
        let h = (e * nn - 2.0 * f * m + g * l) / (2.0 * det);
        prop_assert!((c.mean - h).abs() <= h_tol, "{c:?} vs {h} ± {h_tol}");
        prop_assert!(k1 >= k2);
        prop_assert!((c.gaussian - k1 * k2).abs() <= 4.0 * EPS * c.gaussian.abs(), "{c:?}");
        prop_assert!((c.mean - 0.5 * (k1 + k2)).abs() <= h_tol, "{c:?}");
        let [e1, e2] = &c.directions;
        for x in [norm(e1) - 1.0, norm(e2) - 1.0, dot(e1, e2), dot(e1, &n), dot(e2, &n)] {
            prop_assert!(x.abs() <= 1e-14, "{c:?}");
        }
        let handed = cross(e1, e2);
        prop_assert!(handed.iter().zip(&n).all(|(x, y)| (x - y).abs() <= 1e-14));
    }

    /// Euler's formula: the normal curvature `c''·n/‖c'‖²` of a curve on the
    /// surface through the point is `k₁cos²θ + k₂sin²θ`, θ the angle of its
    /// tangent from e₁.
    ///
    /// Isocurves (`NurbsSurface::isocurve`, differentiated by the curve
    /// code) are exact: 1e-14 of `‖c''‖/‖c'‖² + κ`, the size the rounding of
    /// either side is relative to.
    ///
    /// The straight line `c(τ) = S(u + τ·cos ψ, v + τ·sin ψ)` inside the
    /// patch has `c''` by central differences of `eval` with step `h`:
    /// `|c''_h − c''| ≤ h²/12·max|c''''| + 4δ/h²`, with `c''''` taken exactly
    /// (`derivatives` of order 4) at τ = −h, 0, h and doubled for its
    /// variation in between, and `δ = 16ε·max|P|` the rounding of a point
    /// (a convex combination of the control points); divided by `‖c'‖²`.
    #[test]
    fn euler_formula_gives_the_normal_curvature_of_curves_on_the_surface(
        s in bicubic(), a in 0.05..0.95f64, b in 0.05..0.95f64, psi in 0.0..std::f64::consts::PI,
    ) {
        let (u, v) = (a, b);
        let Some(c) = curvature(&s, u, v) else { return Ok(()) };
        let n = s.normal(u, v).unwrap();
        let kappa = c.principal[0].abs().max(c.principal[1].abs());

        // Isocurves: v ↦ S(u, v) and u ↦ S(u, v).
        for (direction, t, along) in [(Direction::U, u, v), (Direction::V, v, u)] {
            let curve = s.isocurve(direction, t).unwrap();
            let dc = curve.derivatives(along, 2).unwrap();
            let speed2 = dot(&dc[1], &dc[1]);
            let normal = dot(&dc[2], &n) / speed2;
            let tol = 1e-14 * (norm(&dc[2]) / speed2 + kappa);
            let want = euler(&c, &dc[1]);
            prop_assert!((normal - want).abs() <= tol, "{direction}: {normal} vs {want} ± {tol}");
        }

        // A straight line in (u, v).
        let (du, dv) = (psi.cos(), psi.sin());
        let h = 1e-3;
        let point = |tau: f64| s.eval(u + tau * du, v + tau * dv).unwrap();
        let fd = combine(&[(1.0, &point(h)), (-2.0, &point(0.0)), (1.0, &point(-h))]).map(|x| x / (h * h));
        let d = s.derivatives(u, v, 1).unwrap();
        let tangent = combine(&[(du, &d[1][0]), (dv, &d[0][1])]);
        let speed2 = dot(&tangent, &tangent);
        let fourth = |tau: f64| {
            let d = s.derivatives(u + tau * du, v + tau * dv, 4).unwrap();
            let binomial = [1.0, 4.0, 6.0, 4.0, 1.0];
            let terms: Vec<(f64, &[f64; 3])> = (0..=4)
                .map(|k| (binomial[k] * du.powi(k as i32) * dv.powi(4 - k as i32), &d[k][4 - k]))
                .collect();
            norm(&combine(&terms))
        };
        let c4 = 2.0 * fourth(-h).max(fourth(0.0)).max(fourth(h));
        let size = s.control_points().iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        let tol = (h * h / 12.0 * c4 + 4.0 * 16.0 * EPS * size / (h * h)) / speed2;
        let normal = dot(&fd, &n) / speed2;
        let want = euler(&c, &tangent);
        prop_assert!((normal - want).abs() <= tol, "ψ = {psi}: {normal} vs {want} ± {tol}");
    }
}
