//! The capability traits (`t2spline::capability`): generic code written once
//! runs on curves and surfaces, crisp and fuzzy, and agrees with each type's
//! own methods and with its layers.

use proptest::prelude::*;
use t2spline::capability::layered::per_layer;
use t2spline::strategies;
use t2spline::{
    Bounded, Closest, Curvature, Differentiable, Direction, Error, FuzzyCurve, FuzzySurface,
    KnotOperations, Layer, Layered, NurbsCurve, NurbsSurface, Parametric,
};

/// Every point at the sampled parameters lies in the object's bounding box
/// (to rounding): one function for every crisp type.
fn points_inside_box<const D: usize, T>(object: &T, params: &[T::Param]) -> Result<(), String>
where
    T: Parametric<Point = [f64; D]> + Bounded<D>,
{
    let b = object.bounding_box();
    let slack = 1e-9
        * (1.0
            + b.min
                .iter()
                .chain(&b.max)
                .fold(0.0f64, |m, x| m.max(x.abs())));
    for &at in params {
        let p = object.point_at(at).map_err(|e| e.to_string())?;
        if !b.contains(&p, slack) {
            return Err(format!("{p:?} outside {b:?}"));
        }
    }
    Ok(())
}

/// The closest point to a point of the object is that point, at distance 0
/// (to rounding): one function for every crisp type.
fn closest_to_own_point<const D: usize, T>(object: &T, at: T::Param) -> Result<f64, Error>
where
    T: Parametric<Point = [f64; D]> + Closest<D>,
    T::Nearest: Into<Nearest>,
{
    let p = object.point_at(at)?;
    Ok(object.closest_to(p)?.into().distance)
}

/// The distance of a nearest point, from a curve's or a surface's.
struct Nearest {
    distance: f64,
}

impl<const D: usize> From<t2spline::ClosestPoint<D>> for Nearest {
    fn from(c: t2spline::ClosestPoint<D>) -> Self {
        Nearest {
            distance: c.distance,
        }
    }
}

impl<const D: usize> From<t2spline::ClosestSurfacePoint<D>> for Nearest {
    fn from(c: t2spline::ClosestSurfacePoint<D>) -> Self {
        Nearest {
            distance: c.distance,
        }
    }
}

/// A fuzzy object's layered capability equals the capability of each layer
/// object: one function for fuzzy curves and fuzzy surfaces.
fn layered_agrees<const D: usize, T>(fuzzy: &T, at: T::Param) -> Result<(), String>
where
    T: Layered<D> + Parametric + Differentiable + Bounded<D>,
    T::Crisp: Differentiable<Param = T::Param> + Bounded<D>,
    T::Derivatives: PartialEq<t2spline::Layers<<T::Crisp as Differentiable>::Derivatives>>,
{
    let own = fuzzy.derivatives_at(at, 2).map_err(|e| e.to_string())?;
    let layers = per_layer(fuzzy, |c| c.derivatives_at(at, 2)).map_err(|e| e.to_string())?;
    if own != layers {
        return Err("derivatives differ from the layers'".into());
    }
    let b = fuzzy.bounding_box();
    for layer in Layer::ALL {
        let lb = fuzzy.layer(layer).bounding_box();
        let inside = (0..D).all(|d| b.min[d] <= lb.min[d] && lb.max[d] <= b.max[d]);
        if !inside {
            return Err(format!("layer {layer:?}'s box {lb:?} outside {b:?}"));
        }
    }
    Ok(())
}

fn curve_params<const D: usize>(c: &NurbsCurve<D>) -> Vec<f64> {
    let d = c.domain();
    (0..=16).map(|i| d.lerp(f64::from(i) / 16.0)).collect()
}

fn surface_params<const D: usize>(s: &NurbsSurface<D>) -> Vec<[f64; 2]> {
    let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
    (0..=6)
        .flat_map(|i| {
            (0..=6).map(move |j| [du.lerp(f64::from(i) / 6.0), dv.lerp(f64::from(j) / 6.0)])
        })
        .collect()
}

proptest! {
    #![proptest_config(strategies::cases(10, 40))]

    #[test]
    fn crisp_curves_and_surfaces_lie_in_their_boxes(
        c in strategies::curve::<2>(),
        s in strategies::surface::<3>(),
    ) {
        prop_assert_eq!(points_inside_box(&c, &curve_params(&c)), Ok(()));
        prop_assert_eq!(points_inside_box(&s, &surface_params(&s)), Ok(()));
    }

    #[test]
    fn fuzzy_capabilities_are_those_of_the_layers(
        c in strategies::fuzzy_curve::<3>(),
        s in strategies::fuzzy_surface::<3>(),
        f in 0.0..=1.0f64,
    ) {
        let t = c.domain().lerp(f);
        prop_assert_eq!(layered_agrees(&c, t), Ok(()));
        let at = [s.domain(Direction::U).lerp(f), s.domain(Direction::V).lerp(1.0 - f)];
        prop_assert_eq!(layered_agrees(&s, at), Ok(()));
    }

    #[test]
    fn trait_and_inherent_methods_agree(
        c in strategies::fuzzy_curve::<2>(),
        s in strategies::fuzzy_surface::<3>(),
        f in 0.0..=1.0f64,
    ) {
        let t = c.domain().lerp(f);
        prop_assert_eq!(c.point_at(t).ok(), c.eval_layers(t).ok());
        prop_assert_eq!(Bounded::bounding_box(&c), c.bounding_box());
        let crisp = c.crisp_curve();
        prop_assert_eq!(crisp.point_at(t).ok(), crisp.eval(t).ok());
        prop_assert_eq!(crisp.curvature_at(t).ok(), crisp.curvature(t).ok());
        for layer in Layer::ALL {
            let k = c.curvatures(t).map(|k| k[layer]).ok();
            if let Some(k) = k {
                prop_assert_eq!(Some(k), c.layer_curve(layer).curvature(t).ok());
            }
        }
        let (u, v) = (s.domain(Direction::U).lerp(f), s.domain(Direction::V).lerp(f));
        prop_assert_eq!(s.point_at([u, v]).ok(), s.eval_layers(u, v).ok());
        prop_assert_eq!(s.curvature_at([u, v]).ok(), s.curvatures(u, v).ok());
        prop_assert_eq!(s.derivatives_at([u, v], 1).ok(), s.derivatives(u, v, 1).ok());
        let target = [0.25, -0.5, 1.0];
        prop_assert_eq!(s.closest_to(target).ok(), s.closest_points(target).ok());
    }

    #[test]
    fn closest_point_of_an_own_point_is_at_distance_zero(
        c in strategies::curve::<3>(),
        f in 0.0..=1.0f64,
    ) {
        let t = c.domain().lerp(f);
        let scale = 1.0 + c.bounding_box().max.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let d = closest_to_own_point(&c, t).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(d <= 1e-9 * scale, "distance {d}");
    }
}

/// The knot operations through the trait: a curve and a surface each keep
/// their points, one generic check for both.
fn keeps_points<T>(object: &T, along: T::Along, t: f64, params: &[T::Param]) -> Result<(), String>
where
    T: KnotOperations + Parametric,
    T::Point: std::fmt::Debug + Into<Vec<f64>>,
{
    let refined = object
        .insert_knot_along(along, t, 1)
        .map_err(|e| e.to_string())?;
    for &at in params {
        let a: Vec<f64> = object.point_at(at).map_err(|e| e.to_string())?.into();
        let b: Vec<f64> = refined.point_at(at).map_err(|e| e.to_string())?.into();
        if a.iter()
            .zip(&b)
            .any(|(x, y)| (x - y).abs() > 1e-9 * (1.0 + x.abs()))
        {
            return Err(format!("{a:?} became {b:?}"));
        }
    }
    Ok(())
}

#[test]
fn knot_insertion_through_the_trait_keeps_curves_and_surfaces() {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let c = NurbsCurve::try_clamped(
        2,
        vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        vec![1.0, w, 1.0],
    )
    .unwrap();
    keeps_points(&c, (), 0.3, &curve_params(&c)).unwrap();
    let net = vec![
        vec![[2.0, 0.0, 0.0], [2.0, 0.0, 1.0]],
        vec![[2.0, 2.0, 0.0], [2.0, 2.0, 1.0]],
        vec![[0.0, 2.0, 0.0], [0.0, 2.0, 1.0]],
    ];
    let s = NurbsSurface::try_clamped([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]])
        .unwrap();
    keeps_points(&s, Direction::U, 0.4, &surface_params(&s)).unwrap();
    keeps_points(&s, Direction::V, 0.7, &surface_params(&s)).unwrap();
    let [a, b] = s.split_along(Direction::V, 0.5).unwrap();
    assert_eq!(a.domain(Direction::V).end, 0.5);
    assert_eq!(b.domain(Direction::V).start, 0.5);
}

#[test]
fn a_fuzzy_curve_knows_its_curvatures_and_refuses_where_a_layer_stands_still() {
    let n = |c: f64, spread: f64| {
        t2spline::Nt2Number::try_new(c, [c - spread, c + spread], [c, c], [c, c], 0.5).unwrap()
    };
    // The upper_left layer has two equal control points: with degree 1 it
    // stands still on its first span, and its curvature is undefined there.
    let points = vec![
        t2spline::Nt2Point::new([n(0.0, 0.0), n(0.0, 0.0)]),
        t2spline::Nt2Point::new([n(1.0, 1.0), n(0.0, 0.0)]),
        t2spline::Nt2Point::new([n(2.0, 0.0), n(1.0, 0.0)]),
    ];
    let c = FuzzyCurve::try_new(1, points, vec![1.0; 3], None).unwrap();
    let e = c.curvatures(0.25).unwrap_err();
    assert!(
        matches!(
            &e,
            Error::InLayer {
                layer: Layer::UpperLeft,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(matches!(c.curvatures(2.0), Err(Error::OutOfDomain { .. })));
    // Where every layer moves, the crisp layer's curvature of a polyline is 0.
    assert_eq!(c.curvatures(0.75).unwrap()[Layer::Crisp], 0.0);
}

#[test]
fn a_fuzzy_surface_has_derivatives_per_layer() {
    let n =
        |c: f64| t2spline::Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c, c], [c, c], 0.5).unwrap();
    let p = |x: f64, y: f64, z: f64| t2spline::Nt2Point::new([n(x), n(y), n(z)]);
    let net = vec![
        vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 1.0)],
        vec![p(1.0, 0.0, 2.0), p(1.0, 1.0, 3.0)],
    ];
    let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).unwrap();
    let d = s.derivatives(0.5, 0.5, 1).unwrap();
    // A translation of the net by a constant spread moves the point, not the
    // tangents: every layer has S_u = (1, 0, 2) and S_v = (0, 1, 1).
    for layer in Layer::ALL {
        assert_eq!(d[layer][1][0], [1.0, 0.0, 2.0], "{layer:?}");
        assert_eq!(d[layer][0][1], [0.0, 1.0, 1.0], "{layer:?}");
    }
    assert!(s.derivatives(0.5, 1.5, 1).is_err());
}
