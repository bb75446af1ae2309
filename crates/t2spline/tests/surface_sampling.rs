//! The grid engine (`GridSampler` and the surface `sample_*` calls) against the
//! straightforward evaluators `NurbsSurface::eval`, `FuzzySurface::eval_layers`
//! and the surfaces of `SurfaceSolution`, to 1e-12 relative: random surfaces
//! with knots repeated up to full multiplicity, both domain ends, every knot,
//! sorted and unsorted parameters, extreme weights; and one thread against two.

use proptest::prelude::*;
use t2spline::sampling::{Grid, GridSampler, LayerSamples, Params};
use t2spline::{
    strategies, Alpha, Direction, KnotVector, Layer, NurbsSurface, Side, TypeReduction,
};

const TOL: f64 = 1e-12;

mod probes;
use probes::probes;

fn fractions() -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(0.0..=1.0f64, 0..12)
}

fn check<const D: usize>(
    got: &t2spline::sampling::CurveSamples<D>,
    shape: [usize; 2],
    u: &[f64],
    v: &[f64],
    scale: f64,
    reference: impl Fn(f64, f64) -> [f64; D],
) -> Result<(), TestCaseError> {
    prop_assert_eq!(got.len(), shape[0] * shape[1]);
    for (a, &x) in u.iter().enumerate() {
        for (b, &y) in v.iter().enumerate() {
            let (p, q) = (got.point(a * v.len() + b).unwrap(), reference(x, y));
            prop_assert!(
                p.iter()
                    .zip(&q)
                    .all(|(s, t)| (s - t).abs() <= TOL * scale.max(1.0)),
                "({}, {}): engine {:?}, reference {:?}",
                x,
                y,
                p,
                q
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(strategies::cases(50, 100))]

    #[test]
    fn crisp_grid_matches_eval(s in strategies::surface::<3>(), fu in fractions(), fv in fractions(), rotate in 0usize..20) {
        let scale = s.control_points().iter().flatten().fold(0.0, |m: f64, x| m.max(x.abs()));
        let u = probes(s.knots(Direction::U), &fu);
        let mut v = probes(s.knots(Direction::V), &fv);
        let g = s.sample_grid(&u, &v).unwrap();
        check(g.samples(), g.shape(), &u, &v, scale, |x, y| s.eval(x, y).unwrap())?;
        // Unsorted parameters in v.
        v.reverse();
        let k = rotate % v.len();
        v.rotate_left(k);
        let g = s.sample_grid(&u, &v).unwrap();
        check(g.samples(), g.shape(), &u, &v, scale, |x, y| s.eval(x, y).unwrap())?;
    }

    #[test]
    fn layer_grid_matches_eval_layers_and_keeps_the_order(s in strategies::fuzzy_surface::<3>(), fu in fractions(), fv in fractions()) {
        let scale = s.points().iter().flat_map(|p| Layer::ALL.map(|l| p.layer(l))).flatten().fold(0.0, |m: f64, x| m.max(x.abs()));
        let u = probes(s.knots(Direction::U), &fu);
        let v = probes(s.knots(Direction::V), &fv);
        let g = s.sample_layers(&u, &v).unwrap();
        for layer in Layer::ALL {
            check(&g.samples()[layer], g.shape(), &u, &v, scale, |x, y| s.eval_layers(x, y).unwrap()[layer])?;
        }
        for k in 0..u.len() * v.len() {
            for d in 0..3 {
                let values = Layer::ALL.map(|l| g.samples()[l].coord(d)[k]);
                prop_assert!(values.windows(2).all(|w| w[0] <= w[1]), "{:?}", values);
            }
        }
    }

    #[test]
    fn sweep_matches_the_solution_surfaces(
        s in strategies::fuzzy_surface::<3>(),
        a in proptest::collection::vec(0.0..=1.0f64, 1..4),
        method in proptest::sample::select(TypeReduction::ALL.to_vec()),
    ) {
        let alphas: Vec<Alpha> = a.iter().map(|&x| Alpha::try_new(x).unwrap()).collect();
        let u = probes(s.knots(Direction::U), &[0.3]);
        let v = probes(s.knots(Direction::V), &[0.8]);
        let scale = s.points().iter().flat_map(|p| Layer::ALL.map(|l| p.layer(l))).flatten().fold(0.0, |m: f64, x| m.max(x.abs()));
        let g = s.sample_sweep_with(&u, &v, &alphas, method).unwrap();
        for (level, &alpha) in g.samples().levels().iter().zip(&alphas) {
            let solution = s.solve_with(alpha, method);
            for layer in Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp) {
                match (level.alpha_cut(layer), solution.alpha_cut_surface(layer)) {
                    (Some(got), Some(surface)) => check(got, g.shape(), &u, &v, scale, |x, y| surface.eval(x, y).unwrap())?,
                    (None, None) => {}
                    _ => prop_assert!(false, "{} present in one only", layer),
                }
            }
            for side in [Side::Left, Side::Right] {
                let surface = solution.type_reduced_surface(side);
                check(level.type_reduced(side), g.shape(), &u, &v, scale, |x, y| surface.eval(x, y).unwrap())?;
            }
            let surface = solution.defuzzified_surface();
            check(level.defuzzified(), g.shape(), &u, &v, scale, |x, y| surface.eval(x, y).unwrap())?;
            let stages = solution.sample_stages(&u, &v).unwrap();
            prop_assert_eq!(stages.samples(), level);
            // The grid engine keeps left ≤ defuzzified ≤ right exactly.
            let [l, r] = [Side::Left, Side::Right].map(|side| level.type_reduced(side));
            for k in 0..l.len() {
                for d in 0..3 {
                    let y = level.defuzzified().coord(d)[k];
                    prop_assert!(l.coord(d)[k] <= y && y <= r.coord(d)[k], "{}: point {}", method, k);
                }
            }
        }
    }

    #[test]
    fn extreme_weights_match_eval(
        s in strategies::surface::<3>(),
        exponents in proptest::collection::vec(-12.0..12.0f64, 64),
    ) {
        // The same net with weights spread over 24 orders of magnitude.
        let [nu, nv] = s.shape();
        let points = (0..nu).map(|i| (0..nv).map(|j| s.control_point(i, j).unwrap()).collect()).collect();
        let weights = (0..nu).map(|i| (0..nv).map(|j| 10f64.powf(exponents[(i * nv + j) % 64])).collect()).collect();
        let knots = Direction::BOTH.map(|d| s.knots(d).clone());
        let s = NurbsSurface::try_new(points, weights, knots).unwrap();
        let scale = s.control_points().iter().flatten().fold(0.0, |m: f64, x| m.max(x.abs()));
        let u = probes(s.knots(Direction::U), &[0.1, 0.5]);
        let v = probes(s.knots(Direction::V), &[0.25, 0.75]);
        let g = s.sample_grid(&u, &v).unwrap();
        check(g.samples(), g.shape(), &u, &v, scale, |x, y| s.eval(x, y).unwrap())?;
    }
}

#[test]
fn uniform_parameters_are_the_domain_grid_and_errors_name_the_direction() {
    let s = t2spline::sampling::benchmark_surface().crisp_surface();
    let g = s
        .sample_grid(Params::Uniform(7), Params::Uniform(5))
        .unwrap();
    let (u, v) = (
        s.domain(Direction::U).uniform(7).unwrap(),
        s.domain(Direction::V).uniform(5).unwrap(),
    );
    let k = g.index(6, 4).unwrap();
    assert_eq!(g.samples().point(k), s.eval(u[6], v[4]).ok());
    let e = s.sample_grid(&[0.5][..], &[1.5][..]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "parameter v = 1.5 is outside the domain [0, 1]"
    );
    let empty = s
        .sample_grid(Params::Uniform(0), Params::Uniform(5))
        .unwrap();
    assert!(empty.samples().is_empty());
}

#[test]
fn two_threads_give_the_same_bits_as_one_and_into_forms_reuse() {
    let s = t2spline::sampling::benchmark_surface();
    let pool = |t| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build()
            .unwrap()
    };
    let one = pool(1).install(|| {
        s.sample_layers(Params::Uniform(301), Params::Uniform(257))
            .unwrap()
    });
    let two = pool(2).install(|| {
        s.sample_layers(Params::Uniform(301), Params::Uniform(257))
            .unwrap()
    });
    assert_eq!(one, two);
    let mut out = Grid::buffer(LayerSamples::empty());
    pool(2)
        .install(|| s.sample_layers_into(Params::Uniform(301), Params::Uniform(257), &mut out))
        .unwrap();
    assert_eq!(out, one);
    let before = out.samples()[Layer::Crisp].coord(0).as_ptr();
    s.sample_layers_into(Params::Uniform(301), Params::Uniform(257), &mut out)
        .unwrap();
    assert_eq!(out, one);
    // The vectors are reused (some vector keeps its allocation).
    let reused = Layer::ALL
        .iter()
        .any(|&l| (0..3).any(|d| out.samples()[l].coord(d).as_ptr() == before));
    assert!(reused);
}

#[test]
fn grid_sampler_checks_its_input() {
    let k = KnotVector::clamped_uniform(1, 2).unwrap();
    let knots = [k.clone(), k];
    let e = GridSampler::try_new(&knots, &[1.0; 3], &[[0.0; 4]]).unwrap_err();
    assert!(
        matches!(
            e,
            t2spline::Error::Length {
                expected: 4,
                found: 3,
                ..
            }
        ),
        "{e}"
    );
    let e = GridSampler::try_new(&knots, &[1.0, 1.0, 0.0, 1.0], &[[0.0; 4]]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "weights[1][0] = 0 must be finite and greater than 0"
    );
    let e = GridSampler::try_new(&knots, &[1.0; 4], &[[0.0, 0.0, 0.0, f64::NAN]]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "points[1][1]: channel value = NaN is not a finite number"
    );
    let g = GridSampler::try_new(&knots, &[1.0; 4], &[[0.0, 1.0, 2.0, 3.0]]).unwrap();
    let mut out = vec![0.0; 6];
    g.sample_into(Params::Uniform(2), Params::Uniform(3), &mut [&mut out[..]])
        .unwrap();
    assert_eq!(out, [0.0, 0.5, 1.0, 2.0, 2.5, 3.0]);
    assert!(g
        .sample_into(Params::Uniform(2), Params::Uniform(2), &mut [&mut out[..]])
        .is_err());
}
