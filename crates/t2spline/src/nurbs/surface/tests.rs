//! Unit tests of the surface: closed forms, the rules of the domain, errors
//! that name their place, and the operations against the original surface.

use super::*;
use crate::error::Error;
use crate::nurbs::KnotVector;
use crate::nurbs::NurbsCurve;

/// The quarter cylinder of radius `r` about the z axis, height 2: rational
/// quadratic in u (weights 1, √2/2, 1), linear in v.
pub(crate) fn quarter_cylinder(r: f64) -> NurbsSurface<3> {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let net = vec![
        vec![[r, 0.0, 0.0], [r, 0.0, 2.0]],
        vec![[r, r, 0.0], [r, r, 2.0]],
        vec![[0.0, r, 0.0], [0.0, r, 2.0]],
    ];
    NurbsSurface::try_clamped([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]]).unwrap()
}

/// A rational surface of degrees (3, 2) on a 5 × 4 net with an interior knot
/// in each direction and uneven weights.
pub(crate) fn wavy() -> NurbsSurface<3> {
    let (nu, nv) = (5, 4);
    let points = (0..nu)
        .map(|i| {
            (0..nv)
                .map(|j| {
                    let (x, y) = (i as f64, j as f64);
                    [
                        x + 0.3 * y,
                        y - 0.2 * x,
                        (1.3 * x).sin() + (0.7 * y).cos() * x,
                    ]
                })
                .collect()
        })
        .collect();
    let weights = (0..nu)
        .map(|i| {
            (0..nv)
                .map(|j| 0.4 + ((i * 3 + j * 5) % 7) as f64 * 0.5)
                .collect()
        })
        .collect();
    let ku = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0], 3, 5).unwrap();
    let kv = KnotVector::try_new(vec![-1.0, -1.0, -1.0, 0.5, 2.0, 2.0, 2.0], 2, 4).unwrap();
    NurbsSurface::try_new(points, weights, [ku, kv]).unwrap()
}

fn grid(s: &NurbsSurface<3>, n: usize) -> Vec<(f64, f64)> {
    let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
    du.uniform(n)
        .unwrap()
        .into_iter()
        .flat_map(|u| dv.uniform(n).unwrap().into_iter().map(move |v| (u, v)))
        .collect()
}

fn assert_same_surface(a: &NurbsSurface<3>, b: &NurbsSurface<3>, tol: f64) {
    for (u, v) in grid(a, 23) {
        let (p, q) = (a.eval(u, v).unwrap(), b.eval(u, v).unwrap());
        assert!(
            p.iter().zip(&q).all(|(x, y)| (x - y).abs() <= tol),
            "({u}, {v}): {p:?} vs {q:?}"
        );
    }
}

#[test]
fn quarter_cylinder_has_radius_r_everywhere_and_the_radial_normal() {
    for r in [1.0, 2.5] {
        let s = quarter_cylinder(r);
        for (u, v) in grid(&s, 41) {
            let [x, y, z] = s.eval(u, v).unwrap();
            assert!((x.hypot(y) - r).abs() <= 1e-15 * r, "({u}, {v})");
            assert!((z - 2.0 * v).abs() <= 1e-15);
            let n = s.normal(u, v).unwrap();
            assert!((n[0] - x / r).abs() < 1e-14 && (n[1] - y / r).abs() < 1e-14 && n[2] == 0.0);
        }
    }
}

#[test]
fn rational_basis_is_non_negative_and_sums_to_one() {
    let s = wavy();
    for (u, v) in grid(&s, 17) {
        let r = s.rational_basis(u, v).unwrap();
        let all: Vec<f64> = r.into_iter().flatten().collect();
        assert!(all.iter().all(|&x| x >= 0.0));
        assert!((all.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }
}

#[test]
fn full_multiplicity_knot_takes_the_value_from_the_right() {
    // Degree 1 in v with a knot of multiplicity 2 at 0.5: the surface jumps there.
    let kv = KnotVector::try_new(vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0], 1, 4).unwrap();
    let ku = KnotVector::clamped_uniform(1, 2).unwrap();
    let row = |x: f64| vec![[x, 0.0, 0.0], [x, 1.0, 0.0], [x, 5.0, 5.0], [x, 6.0, 5.0]];
    let s =
        NurbsSurface::try_new(vec![row(0.0), row(1.0)], vec![vec![1.0; 4]; 2], [ku, kv]).unwrap();
    assert_eq!(s.eval(0.5, 0.5).unwrap(), [0.5, 5.0, 5.0]);
    assert_eq!(s.eval(1.0, 1.0).unwrap(), [1.0, 6.0, 5.0]);
    let before = s.eval(0.5, 0.5 - 1e-12).unwrap();
    assert!((before[1] - 1.0).abs() < 1e-10, "{before:?}");
    // The isocurve in u at v = 0.5 is the right limit too.
    let c = s.isocurve(Direction::V, 0.5).unwrap();
    assert_eq!(c.eval(0.25).unwrap(), [0.25, 5.0, 5.0]);
}

#[test]
fn errors_name_the_direction_and_the_net_place() {
    let s = wavy();
    let e = s.eval(0.5, 2.5).unwrap_err();
    assert_eq!(
        e.to_string(),
        "parameter v = 2.5 is outside the domain [-1, 2]"
    );
    assert!(matches!(
        s.eval(f64::NAN, 0.0),
        Err(Error::InDirection {
            direction: Direction::U,
            ..
        })
    ));
    let mut net = vec![vec![[0.0; 3]; 2]; 2];
    net[1][0][1] = f64::INFINITY;
    let e = NurbsSurface::try_clamped([1, 1], net.clone(), vec![vec![1.0; 2]; 2]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "points[1][0].y: coordinate = inf is not a finite number"
    );
    net[1][0][1] = 2e150;
    let e = NurbsSurface::try_clamped([1, 1], net.clone(), vec![vec![1.0; 2]; 2]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "points[1][0].y: coordinate = 2e150 is outside [-1e150, 1e150]"
    );
    net[1][0][1] = 0.0;
    let e = NurbsSurface::try_clamped([1, 1], net.clone(), vec![vec![1.0; 2]; 2 + 1]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "weights[2]: expected 2 entries (as points), got 3"
    );
    let e = NurbsSurface::try_clamped([1, 1], net.clone(), vec![vec![1.0; 2], vec![1e-151, 1.0]])
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "weights[1][0] = 1e-151 is outside [1e-150, 1e150]"
    );
    let ku = KnotVector::clamped_uniform(1, 3).unwrap();
    let kv = KnotVector::clamped_uniform(1, 2).unwrap();
    let e = NurbsSurface::try_new(net, vec![vec![1.0; 2]; 2], [ku, kv]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "knots.u: expected 4 values (rows + order in u), got 5"
    );
    // A knot rule of one direction names that direction's knot vector, as a
    // job file does.
    let e = knots_in(Direction::V, Some(vec![0.0, 0.0, 0.5, 0.2, 1.0]), 1, 3).unwrap_err();
    assert_eq!(
        e.to_string(),
        "knots.v[3] = 0.2 is less than knots.v[2] = 0.5: knots.v must not decrease"
    );
    let e = knots_in(Direction::V, Some(vec![0.0, 0.0, 1.0]), 1, 2).unwrap_err();
    assert_eq!(
        e.to_string(),
        "knots.v: expected 4 values (columns + order in v), got 3"
    );
}

#[test]
fn derivatives_match_the_isocurves_and_central_differences() {
    let s = wavy();
    for (u, v) in [(0.1, -0.5), (0.55, 0.7), (0.9, 1.8), (0.4, 0.5)] {
        let d = s.derivatives(u, v, 3).unwrap();
        let p = s.eval(u, v).unwrap();
        assert!(
            d[0][0].iter().zip(&p).all(|(x, y)| (x - y).abs() < 1e-14),
            "{d:?} {p:?}"
        );
        // Pure derivatives in v are those of the isocurve at u, and in u those
        // of the isocurve at v (an independent path: curve A3.2 + A4.2).
        let cv = s
            .isocurve(Direction::U, u)
            .unwrap()
            .derivatives(v, 3)
            .unwrap();
        let cu = s
            .isocurve(Direction::V, v)
            .unwrap()
            .derivatives(u, 3)
            .unwrap();
        for k in 0..=3 {
            for c in 0..3 {
                let scale = 1.0 + cv[k][c].abs();
                assert!(
                    (d[0][k][c] - cv[k][c]).abs() < 1e-11 * scale,
                    "S_v^{k} at ({u}, {v})"
                );
                let scale = 1.0 + cu[k][c].abs();
                assert!(
                    (d[k][0][c] - cu[k][c]).abs() < 1e-11 * scale,
                    "S_u^{k} at ({u}, {v})"
                );
            }
        }
        // Mixed derivatives by central differences of the u-derivative in v.
        let h = 1e-5;
        let (a, b) = (
            s.derivatives(u, v - h, 2).unwrap(),
            s.derivatives(u, v + h, 2).unwrap(),
        );
        for c in 0..3 {
            let fd = (b[1][0][c] - a[1][0][c]) / (2.0 * h);
            assert!(
                (d[1][1][c] - fd).abs() < 1e-5 * (1.0 + fd.abs()),
                "S_uv {fd} {:?}",
                d[1][1]
            );
            // S_uvv jumps at the knot v = 0.5 (degree 2, C¹ there).
            let fd = (b[1][1][c] - a[1][1][c]) / (2.0 * h);
            assert!(
                v == 0.5 || (d[1][2][c] - fd).abs() < 1e-4 * (1.0 + fd.abs()),
                "S_uvv {fd} {:?}",
                d[1][2]
            );
        }
    }
}

#[test]
fn isocurves_equal_the_surface() {
    let s = wavy();
    for t in [0.0, 0.4, 0.77, 1.0] {
        let c: NurbsCurve<3> = s.isocurve(Direction::U, t).unwrap();
        for v in s.domain(Direction::V).uniform(31).unwrap() {
            let (a, b) = (c.eval(v).unwrap(), s.eval(t, v).unwrap());
            assert!(
                a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-13),
                "{t} {v}"
            );
        }
    }
    for t in [-1.0, 0.5, 1.3, 2.0] {
        let c = s.isocurve(Direction::V, t).unwrap();
        for u in s.domain(Direction::U).uniform(31).unwrap() {
            let (a, b) = (c.eval(u).unwrap(), s.eval(u, t).unwrap());
            assert!(
                a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-13),
                "{u} {t}"
            );
        }
    }
}

#[test]
fn operations_keep_the_surface() {
    let s = wavy();
    for d in Direction::BOTH {
        let dom = s.domain(d);
        let mid = dom.lerp(0.37);
        let inserted = s.insert_knot(d, mid, 2).unwrap();
        assert_eq!(inserted.shape()[d.index()], s.shape()[d.index()] + 2);
        assert_same_surface(&s, &inserted, 1e-13);
        let refined = s
            .refine_knots(d, &[dom.lerp(0.1), mid, mid, dom.lerp(0.9)])
            .unwrap();
        assert_same_surface(&s, &refined, 1e-13);
        for times in 1..=2 {
            let e = s.elevate_degree(d, times).unwrap();
            assert_eq!(e.degree()[d.index()], s.degree()[d.index()] + times);
            assert_eq!(e.degree()[1 - d.index()], s.degree()[1 - d.index()]);
            assert_same_surface(&s, &e, 1e-12);
        }
        let [a, b] = s.split_at(d, mid).unwrap();
        for (u, v) in grid(&s, 19) {
            let t = [u, v][d.index()];
            let piece = if t <= mid { &a } else { &b };
            let (p, q) = (s.eval(u, v).unwrap(), piece.eval(u, v).unwrap());
            assert!(
                p.iter().zip(&q).all(|(x, y)| (x - y).abs() < 1e-13),
                "({u}, {v})"
            );
        }
        assert!(matches!(
            s.split_at(d, dom.end),
            Err(Error::InDirection { inner, .. }) if matches!(*inner, Error::SplitOutside { .. })
        ));
    }
    let piece = s.segment([0.2, 0.7], [0.0, 1.5]).unwrap();
    for u in [0.2, 0.45, 0.7] {
        for v in [0.0, 0.5, 1.5] {
            let (p, q) = (s.eval(u, v).unwrap(), piece.eval(u, v).unwrap());
            assert!(
                p.iter().zip(&q).all(|(x, y)| (x - y).abs() < 1e-13),
                "({u}, {v})"
            );
        }
    }
    assert!(s.segment([0.7, 0.2], [0.0, 1.5]).is_err());
    assert!(s.segment([0.2, 0.7], [0.0, 2.5]).is_err());
}
