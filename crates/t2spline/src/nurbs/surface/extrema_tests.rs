//! Tests of the closest point and the bounding box of a surface: closed
//! forms, and properties of random rational surfaces against dense sampling.

use proptest::prelude::*;

use super::tests::{quarter_cylinder, wavy};
use super::*;
use crate::error::Error;
use crate::nurbs::BoundingBox;
use crate::vector::euclidean_norm;

fn dist<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    euclidean_norm(&std::array::from_fn::<f64, D, _>(|d| a[d] - b[d]))
}

/// `n × n` parameters spread evenly over the domain, ends included.
fn dense<const D: usize>(s: &NurbsSurface<D>, n: usize) -> Vec<[f64; 2]> {
    let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
    let (us, vs) = (du.uniform(n).unwrap(), dv.uniform(n).unwrap());
    us.iter()
        .flat_map(|&u| vs.iter().map(move |&v| [u, v]))
        .collect()
}

fn assert_close(a: f64, b: f64, tol: f64, what: &str) {
    assert!((a - b).abs() <= tol, "{what}: {a} vs {b}");
}

#[test]
fn on_a_plane_the_closest_point_is_the_orthogonal_projection_or_a_border() {
    // S(u, v) = (3u, 2v, 0).
    let net = vec![
        vec![[0.0, 0.0, 0.0], [0.0, 2.0, 0.0]],
        vec![[3.0, 0.0, 0.0], [3.0, 2.0, 0.0]],
    ];
    let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0; 2]; 2]).unwrap();
    // Interior: the foot of the perpendicular.
    let c = s.closest_point([1.2, 0.5, 4.0]).unwrap();
    assert_close(c.u, 0.4, 1e-15, "u");
    assert_close(c.v, 0.25, 1e-15, "v");
    assert_close(c.distance, 4.0, 1e-15, "distance");
    // Past a corner: the corner.
    let c = s.closest_point([5.0, -1.0, 2.0]).unwrap();
    assert_eq!((c.u, c.v, c.point), (1.0, 0.0, [3.0, 0.0, 0.0]));
    assert_close(c.distance, 3.0, 1e-15, "corner distance");
    // Past a border: the foot on the border.
    let c = s.closest_point([1.5, 3.0, -1.0]).unwrap();
    assert_eq!(c.v, 1.0);
    assert_close(c.u, 0.5, 1e-15, "u on the border");
    assert_close(c.distance, 2f64.sqrt(), 1e-15, "border distance");
}

#[test]
fn on_a_bilinear_patch_a_point_on_a_normal_projects_to_its_foot() {
    // S(u, v) = (u, v, u·v), curvature radius above 1 everywhere.
    let net = vec![
        vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]],
    ];
    let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0; 2]; 2]).unwrap();
    for (u, v, h) in [(0.3, 0.6, 0.2), (0.7, 0.2, -0.3), (0.5, 0.5, 0.1)] {
        let (p, n) = (s.eval(u, v).unwrap(), s.normal(u, v).unwrap());
        let target = std::array::from_fn(|d| p[d] + h * n[d]);
        let c = s.closest_point(target).unwrap();
        assert_close(c.u, u, 1e-12, "u");
        assert_close(c.v, v, 1e-12, "v");
        assert_close(c.distance, h.abs(), 1e-14, "distance");
    }
}

#[test]
fn on_the_quarter_cylinder_the_closest_point_is_the_radial_projection() {
    let s = quarter_cylinder(1.0);
    for (r, theta, z) in [
        (2.5_f64, 0.3_f64, 0.5),
        (0.4, 1.2, 1.7),
        (3.0, 0.785, 1.0),
        (1.5, 0.01, 0.0),
    ] {
        let (c, t) = (theta.cos(), theta.sin());
        let near = s.closest_point([r * c, r * t, z]).unwrap();
        assert_close(near.distance, (r - 1.0_f64).abs(), 1e-14, "distance");
        for (x, y) in near.point.iter().zip([c, t, z]) {
            assert_close(*x, y, 1e-12, "point");
        }
    }
    // Above the top border: the point on the top circle.
    let near = s.closest_point([2.0 * 0.6, 2.0 * 0.8, 3.0]).unwrap();
    assert_eq!(near.v, 1.0);
    assert_close(near.distance, 2f64.sqrt(), 1e-14, "border distance");
    // Beyond the angle θ = 0 and below: the corner (1, 0, 0).
    let near = s.closest_point([2.0, -1.0, -1.0]).unwrap();
    assert_eq!((near.u, near.v), (0.0, 0.0));
    assert_close(near.distance, 3f64.sqrt(), 1e-15, "corner distance");
}

#[test]
fn targets_that_are_not_finite_or_too_large_are_errors() {
    let s = quarter_cylinder(1.0);
    let e = s.closest_point([0.0, f64::NAN, 0.0]).unwrap_err();
    assert_eq!(e.to_string(), "y: target = NaN is not a finite number");
    assert!(matches!(
        s.closest_point([f64::INFINITY, 0.0, 0.0]),
        Err(Error::NotFinite { .. })
    ));
    assert!(matches!(
        s.closest_point([0.0, 0.0, 1e200]),
        Err(Error::OutOfRange { .. })
    ));
}

#[test]
fn the_box_of_a_wavy_surface_holds_and_reaches_dense_samples() {
    let s = wavy();
    let (b, at) = s.bounding_box_reached(true);
    let mut sampled = BoundingBox::of_point(s.eval(0.0, -1.0).unwrap());
    for [u, v] in dense(&s, 301) {
        let p = s.eval(u, v).unwrap();
        assert!(b.contains(&p, 1e-13), "{p:?} outside {b:?}");
        sampled = sampled.with_point(p);
    }
    for (d, ([u0, v0], [u1, v1])) in at[0].into_iter().zip(at[1]).enumerate() {
        assert_close(s.eval(u0, v0).unwrap()[d], b.min[d], 1e-12, "min");
        assert_close(s.eval(u1, v1).unwrap()[d], b.max[d], 1e-12, "max");
        // The sampling reaches the faces up to its own resolution.
        assert!(sampled.min[d] - b.min[d] < 1e-3 && b.max[d] - sampled.max[d] < 1e-3);
    }
}

/// A random rational surface: degrees 1–3, up to 3 control points more than
/// the order in each direction, coordinates in [−2, 2], weights in [0.3, 3].
fn surface() -> impl Strategy<Value = NurbsSurface<3>> {
    (1usize..4, 1usize..4, 0usize..4, 0usize..4).prop_flat_map(|(p, q, eu, ev)| {
        let (nu, nv) = (p + 1 + eu, q + 1 + ev);
        (
            prop::collection::vec(prop::array::uniform3(-2.0f64..2.0), nu * nv),
            prop::collection::vec(0.3f64..3.0, nu * nv),
        )
            .prop_map(move |(points, weights)| {
                let net = points.chunks(nv).map(<[_]>::to_vec).collect();
                let w = weights.chunks(nv).map(<[_]>::to_vec).collect();
                NurbsSurface::try_clamped([p, q], net, w).unwrap()
            })
    })
}

/// Whether `t` is at a knot of `direction` (where first derivatives of a
/// degree-1 surface jump) or at an end of the domain.
fn at_a_knot(s: &NurbsSurface<3>, direction: Direction, t: f64) -> bool {
    s.knots(direction)
        .as_slice()
        .iter()
        .any(|k| (k - t).abs() < 1e-9)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// No sample of a dense grid is nearer than the closest point, which is
    /// `S(u, v)`; at an interior minimum the residual is normal to `S_u` and
    /// `S_v`.
    #[test]
    fn the_closest_point_beats_dense_sampling(
        s in surface(),
        target in prop::array::uniform3(-4.0f64..4.0),
    ) {
        let c = s.closest_point(target).unwrap();
        let sampled = dense(&s, 61)
            .into_iter()
            .map(|[u, v]| dist(&s.eval(u, v).unwrap(), &target))
            .fold(f64::INFINITY, f64::min);
        prop_assert!(c.distance <= sampled * (1.0 + 1e-12), "{c:?} vs {sampled}");
        let p = s.eval(c.u, c.v).unwrap();
        prop_assert!(dist(&p, &c.point) <= 1e-13, "{p:?} vs {c:?}");
        prop_assert!((dist(&p, &target) - c.distance).abs() <= 1e-13);
        let interior = !at_a_knot(&s, Direction::U, c.u) && !at_a_knot(&s, Direction::V, c.v);
        if interior && c.distance > 1e-6 {
            let d = s.derivatives(c.u, c.v, 1).unwrap();
            let r: [f64; 3] = std::array::from_fn(|k| c.point[k] - target[k]);
            for tangent in [d[1][0], d[0][1]] {
                let dot: f64 = r.iter().zip(tangent).map(|(a, b)| a * b).sum();
                prop_assert!(
                    dot.abs() <= 1e-9 * c.distance * euclidean_norm(&tangent),
                    "cosine {} at {c:?}", dot / (c.distance * euclidean_norm(&tangent))
                );
            }
        }
    }

    /// Skipping the patches whose control points are all farther than the
    /// distance found changes nothing, to the bit.
    #[test]
    fn pruning_gives_the_answer_of_searching_every_patch(
        s in surface(),
        target in prop::array::uniform3(-4.0f64..4.0),
    ) {
        let pruned = s.closest_point_searching(target, true);
        let every = s.closest_point_searching(target, false);
        prop_assert_eq!(pruned, every);
    }

    /// Skipping the patches whose control points cannot move a face changes
    /// nothing, to the bit.
    #[test]
    fn pruning_gives_the_box_of_searching_every_patch(s in surface()) {
        prop_assert_eq!(s.bounding_box_reached(true), s.bounding_box_reached(false));
    }

    /// The box holds a dense grid of samples, and each face is a value of the
    /// surface at the parameters where it is reached.
    #[test]
    fn the_box_holds_dense_samples_and_each_face_is_reached(s in surface()) {
        let (b, at) = s.bounding_box_reached(true);
        prop_assert_eq!(b, s.bounding_box());
        for [u, v] in dense(&s, 81) {
            let p = s.eval(u, v).unwrap();
            prop_assert!(b.contains(&p, 1e-12), "{p:?} outside {b:?}");
        }
        for (d, ([u0, v0], [u1, v1])) in at[0].into_iter().zip(at[1]).enumerate() {
            let lo = s.eval(u0, v0).unwrap()[d];
            let hi = s.eval(u1, v1).unwrap()[d];
            prop_assert!((lo - b.min[d]).abs() <= 1e-9 && (hi - b.max[d]).abs() <= 1e-9);
        }
    }
}
