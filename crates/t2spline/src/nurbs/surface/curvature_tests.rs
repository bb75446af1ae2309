//! Curvature of surfaces: closed forms (plane, sphere, cylinder, saddle), the
//! classical formulas of the fundamental forms, the fuzzy surface layer by
//! layer, and the errors.

use super::tests::quarter_cylinder;
use super::*;
use crate::error::Error;
use crate::fuzzy::{Layer, Nt2Number, Nt2Point};
use crate::nurbs::KnotVector;
use crate::pipeline::FuzzySurface;
use crate::vector::cross;
use crate::vector::dot;
use crate::vector::euclidean_norm;

/// The octant of the sphere of radius `r` about the origin: the quarter
/// circle from `(r, 0, 0)` to the pole `(0, 0, r)` (u, rational quadratic)
/// revolved by a quarter turn about z (v); the row `u = 1` is the pole.
fn sphere_octant(r: f64) -> NurbsSurface<3> {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let meridian = [(r, 0.0, 1.0), (r, r, w), (0.0, r, 1.0)];
    let turn = [(1.0, 0.0, 1.0), (1.0, 1.0, w), (0.0, 1.0, 1.0)];
    let net = meridian
        .iter()
        .map(|&(x, z, _)| turn.iter().map(|&(c, s, _)| [x * c, x * s, z]).collect())
        .collect();
    let weights = meridian
        .iter()
        .map(|&(_, _, a)| turn.iter().map(|&(_, _, b)| a * b).collect())
        .collect();
    NurbsSurface::try_clamped([2, 2], net, weights).unwrap()
}

/// `S(u, v) = (2u − 1, 2v − 1, (2u − 1)(2v − 1))`: the saddle `z = xy` over
/// `[−1, 1]²`.
fn saddle() -> NurbsSurface<3> {
    let net = vec![
        vec![[-1.0, -1.0, 1.0], [-1.0, 1.0, -1.0]],
        vec![[1.0, -1.0, -1.0], [1.0, 1.0, 1.0]],
    ];
    NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0; 2]; 2]).unwrap()
}

/// The parameters `(u, v)` of an `n × n` grid over `[lo, hi]²`.
fn grid(n: usize, lo: f64, hi: f64) -> Vec<(f64, f64)> {
    let t = |k: usize| lo + (hi - lo) * k as f64 / (n - 1) as f64;
    (0..n)
        .flat_map(|a| (0..n).map(move |b| (t(a), t(b))))
        .collect()
}

/// Unit, tangent (against `n`), orthogonal, and right-handed with `n`.
fn assert_frame(c: &SurfaceCurvature, n: &[f64; 3], tol: f64, at: (f64, f64)) {
    let [e1, e2] = &c.directions;
    assert!((euclidean_norm(e1) - 1.0).abs() <= tol, "{at:?}: {c:?}");
    assert!((euclidean_norm(e2) - 1.0).abs() <= tol, "{at:?}: {c:?}");
    assert!(dot(e1, e2).abs() <= tol, "{at:?}: {c:?}");
    assert!(dot(e1, n).abs() <= tol && dot(e2, n).abs() <= tol, "{at:?}");
    let handed = cross(e1, e2);
    assert!(
        handed.iter().zip(n).all(|(a, b)| (a - b).abs() <= tol),
        "{at:?}"
    );
}

/// K and H by the classical formulas of the fundamental forms (do Carmo
/// §3-3), from the partial derivatives.
fn classical(s: &NurbsSurface<3>, u: f64, v: f64) -> (f64, f64) {
    let d = s.derivatives(u, v, 2).unwrap();
    let n = s.normal(u, v).unwrap();
    let (su, sv) = (&d[1][0], &d[0][1]);
    let (e, f, g) = (dot(su, su), dot(su, sv), dot(sv, sv));
    let (l, m, nn) = (dot(&d[2][0], &n), dot(&d[1][1], &n), dot(&d[0][2], &n));
    let det = e * g - f * f;
    (
        (l * nn - m * m) / det,
        (e * nn - 2.0 * f * m + g * l) / (2.0 * det),
    )
}

#[test]
fn a_plane_has_no_curvature_and_the_frame_of_s_u() {
    // A tilted plane z = 0.3x − 0.2y + 1 on an uneven rational bicubic net:
    // the second derivatives are far from zero, all tangent to the plane.
    let plane = |x: f64, y: f64| [x, y, 0.3 * x - 0.2 * y + 1.0];
    let net = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let (x, y) = (f64::from(i), f64::from(j));
                    plane(x + 0.3 * (x * y).sin(), y * y * 0.4 + 0.2 * x)
                })
                .collect()
        })
        .collect();
    let weights = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| 0.5 + f64::from((i * 5 + j * 3) % 4))
                .collect()
        })
        .collect();
    let s = NurbsSurface::try_clamped([3, 3], net, weights).unwrap();
    for (u, v) in grid(9, 0.0, 1.0) {
        let c = s.curvature(u, v).unwrap();
        let n = s.normal(u, v).unwrap();
        for k in [c.gaussian, c.mean, c.principal[0], c.principal[1]] {
            assert!(k.abs() < 1e-13, "({u}, {v}): {c:?}");
        }
        assert_frame(&c, &n, 1e-15, (u, v));
        // The umbilic choice: e₁ = S_u/‖S_u‖.
        let su = s.derivatives(u, v, 1).unwrap()[1][0];
        let a = su.map(|x| x / euclidean_norm(&su));
        assert!(c.directions[0]
            .iter()
            .zip(&a)
            .all(|(x, y)| (x - y).abs() < 1e-15));
    }
}

#[test]
fn a_sphere_is_umbilic_with_curvature_one_over_r() {
    for r in [1.0, 0.25, 40.0] {
        let s = sphere_octant(r);
        // The pole u = 1 is singular; up to u = 0.95 the patch is regular.
        for (u, v) in grid(11, 0.0, 0.95) {
            let c = s.curvature(u, v).unwrap();
            let (n, p) = (s.normal(u, v).unwrap(), s.eval(u, v).unwrap());
            // The normal is inward (n = −p/r): the sphere bends toward it.
            assert!((dot(&n, &p) + r).abs() < 1e-14 * r);
            // Relative 1e-13: near the pole S_v shrinks (at u = 0.95 to a
            // tenth of its size at the equator) and the rounding of the
            // frame grows with 1/‖S_v‖².
            let k = 1.0 / r;
            assert!((c.mean - k).abs() <= 1e-13 * k, "r = {r} ({u}, {v}): {c:?}");
            assert!((c.gaussian - k * k).abs() <= 1e-13 * k * k, "{c:?}");
            for ki in c.principal {
                assert!((ki - k).abs() <= 1e-13 * k, "{c:?}");
            }
            assert_frame(&c, &n, 1e-15, (u, v));
            let su = s.derivatives(u, v, 1).unwrap()[1][0];
            let a = su.map(|x| x / euclidean_norm(&su));
            assert!(
                c.directions[0]
                    .iter()
                    .zip(&a)
                    .all(|(x, y)| (x - y).abs() < 1e-15),
                "umbilic choice at ({u}, {v}): {c:?}"
            );
        }
    }
}

#[test]
fn a_cylinder_bends_around_its_axis_only() {
    for r in [1.0, 2.5, 0.1] {
        let s = quarter_cylinder(r);
        for (u, v) in grid(9, 0.0, 1.0) {
            let c = s.curvature(u, v).unwrap();
            let n = s.normal(u, v).unwrap();
            // Outward normal: the circle bends away from it.
            let k = 1.0 / r;
            assert!(c.gaussian.abs() <= 1e-14 * k * k, "{c:?}");
            assert!((c.mean + 0.5 * k).abs() <= 1e-14 * k, "{c:?}");
            assert!(c.principal[0].abs() <= 1e-14 * k, "{c:?}");
            assert!((c.principal[1] + k).abs() <= 1e-14 * k, "{c:?}");
            // The zero curvature runs along the axis z, the other around it.
            // S_u's z (0) is rounded relative to the height 2, so e₂'s z
            // to about 1e-16·2/r.
            let tol = 1e-15 * (2.0 / r).max(1.0);
            assert!((c.directions[0][2] - 1.0).abs() <= 1e-15, "{c:?}");
            assert!(c.directions[1][2].abs() <= tol, "{c:?}");
            assert_frame(&c, &n, tol, (u, v));
        }
    }
}

#[test]
fn the_saddle_z_equals_xy_matches_the_monge_patch() {
    let s = saddle();
    let c = s.curvature(0.5, 0.5).unwrap();
    assert_eq!(c.gaussian, -1.0);
    assert_eq!(c.mean, 0.0);
    assert_eq!(c.principal, [1.0, -1.0]);
    // The surface rises along x = y (toward n = +z) and falls along x = −y.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let close = |a: &[f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-15);
    assert!(close(&c.directions[0], [h, h, 0.0]), "{c:?}");
    assert!(close(&c.directions[1], [-h, h, 0.0]), "{c:?}");
    // Everywhere: K = −1/(1 + x² + y²)², H = −xy/(1 + x² + y²)^(3/2) with the
    // upward normal (−y, −x, 1)/√(1 + x² + y²).
    for (u, v) in grid(9, 0.0, 1.0) {
        let (x, y) = (2.0 * u - 1.0, 2.0 * v - 1.0);
        let q = 1.0 + x * x + y * y;
        let c = s.curvature(u, v).unwrap();
        assert!(
            (c.gaussian + 1.0 / (q * q)).abs() < 1e-15,
            "({x}, {y}): {c:?}"
        );
        assert!(
            (c.mean + x * y / q.powf(1.5)).abs() < 1e-15,
            "({x}, {y}): {c:?}"
        );
        assert_frame(&c, &s.normal(u, v).unwrap(), 1e-15, (u, v));
    }
}

#[test]
fn curvature_agrees_with_the_classical_formulas() {
    let s = super::tests::wavy();
    let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
    for (a, b) in grid(13, 0.0, 1.0) {
        let (u, v) = (
            du.start + a * (du.end - du.start),
            dv.start + b * (dv.end - dv.start),
        );
        let c = s.curvature(u, v).unwrap();
        let (k, h) = classical(&s, u, v);
        let scale = c.principal[0].abs().max(c.principal[1].abs());
        assert!(
            (c.gaussian - k).abs() <= 1e-12 * scale * scale,
            "({u}, {v}): {c:?} vs {k}"
        );
        assert!(
            (c.mean - h).abs() <= 1e-12 * scale,
            "({u}, {v}): {c:?} vs {h}"
        );
        assert!(c.principal[0] >= c.principal[1]);
        assert_frame(&c, &s.normal(u, v).unwrap(), 1e-14, (u, v));
    }
}

#[test]
fn swapping_u_and_v_reverses_the_normal_and_the_signs() {
    let s = super::tests::wavy();
    let [nu, nv] = s.shape();
    let net = (0..nv)
        .map(|j| (0..nu).map(|i| s.control_point(i, j).unwrap()).collect())
        .collect();
    let weights = (0..nv)
        .map(|j| (0..nu).map(|i| s.weights()[i * nv + j]).collect())
        .collect();
    let knots = [s.knots(Direction::V).clone(), s.knots(Direction::U).clone()];
    let t = NurbsSurface::try_new(net, weights, knots).unwrap();
    for (u, v) in [(0.2, 0.1), (0.7, 1.3), (0.45, -0.6)] {
        let (a, b) = (s.curvature(u, v).unwrap(), t.curvature(v, u).unwrap());
        let tol = 1e-12 * a.principal[0].abs().max(a.principal[1].abs());
        assert!((a.gaussian - b.gaussian).abs() <= tol * tol.max(1.0));
        assert!((a.mean + b.mean).abs() <= tol);
        assert!((a.principal[0] + b.principal[1]).abs() <= tol);
        assert!((a.principal[1] + b.principal[0]).abs() <= tol);
    }
}

#[test]
fn errors_out_of_the_domain_at_a_singular_normal_and_beyond_the_floats() {
    let s = sphere_octant(1.0);
    for (u, v) in [
        (1.5, 0.5),
        (0.5, -0.1),
        (f64::NAN, 0.5),
        (0.5, f64::INFINITY),
    ] {
        assert!(
            matches!(s.curvature(u, v), Err(Error::InDirection { ref inner, .. }) if matches!(**inner, Error::OutOfDomain { .. })),
            "({u}, {v})"
        );
    }
    // The pole: S_v = 0.
    assert_eq!(
        s.curvature(1.0, 0.5),
        Err(Error::SingularNormal { u: 1.0, v: 0.5 })
    );
    // A span of 1e-150 under coordinates of 1e150: S_uu ≈ 1e450.
    let ku = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1e-150, 1e-150, 1e-150], 2, 3).unwrap();
    let kv = KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0], 1, 2).unwrap();
    let net = vec![
        vec![[0.0, 0.0, 0.0], [0.0, 0.0, 1e150]],
        vec![[1e150, 0.0, 0.0], [1e150, 0.0, 1e150]],
        vec![[0.0, 1e150, 0.0], [0.0, 1e150, 1e150]],
    ];
    let s = NurbsSurface::try_new(net, vec![vec![1.0; 2]; 3], [ku, kv]).unwrap();
    assert!(s.normal(5e-151, 0.5).is_ok());
    assert!(
        matches!(
            s.curvature(5e-151, 0.5),
            Err(Error::IllConditioned {
                operation: "curvature",
                ..
            })
        ),
        "{:?}",
        s.curvature(5e-151, 0.5)
    );
}

#[test]
fn a_fuzzy_surface_gives_the_curvature_of_each_layer() {
    // A fuzzy sphere octant: every coordinate c with feet c − 0.1|c| … c + 0.3|c|.
    let crisp = sphere_octant(2.0);
    let number = |c: f64| {
        let s = c.abs();
        Nt2Number::try_new(
            c,
            [c - 0.1 * s, c + 0.3 * s],
            [c - 0.05 * s, c + 0.2 * s],
            [c - 0.02 * s, c + 0.1 * s],
            0.6,
        )
        .unwrap()
    };
    let [nu, nv] = crisp.shape();
    let net = (0..nu)
        .map(|i| {
            (0..nv)
                .map(|j| Nt2Point::new(crisp.control_point(i, j).unwrap().map(number)))
                .collect()
        })
        .collect();
    let weights = (0..nu)
        .map(|i| crisp.weights()[i * nv..(i + 1) * nv].to_vec())
        .collect();
    let s = FuzzySurface::try_new([2, 2], net, weights, [None, None]).unwrap();
    for (u, v) in [(0.2, 0.3), (0.0, 0.0), (0.9, 1.0)] {
        let layers = s.curvatures(u, v).unwrap();
        for l in Layer::ALL {
            assert_eq!(
                layers[l],
                s.layer_surface(l).curvature(u, v).unwrap(),
                "{l}"
            );
        }
        // Each layer scales the octant: a sphere of radius 2·(1 + spread).
        let k = |f: f64| 1.0 / (2.0 * f);
        assert!((layers[Layer::Crisp].mean - k(1.0)).abs() < 1e-14);
        assert!((layers[Layer::UpperLeft].mean - k(0.9)).abs() < 1e-14);
        assert!((layers[Layer::UpperRight].gaussian - k(1.3).powi(2)).abs() < 1e-14);
    }
    assert!(matches!(
        s.curvatures(2.0, 0.5),
        Err(Error::InDirection { .. })
    ));
    match s.curvatures(1.0, 0.5) {
        Err(Error::InLayer { layer, inner }) => {
            assert_eq!(layer, Layer::UpperLeft);
            assert_eq!(*inner, Error::SingularNormal { u: 1.0, v: 0.5 });
        }
        other => panic!("{other:?}"),
    }
}
