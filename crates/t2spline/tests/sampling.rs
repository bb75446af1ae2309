//! The sampling engine (`t2spline::sampling`) against the straightforward
//! evaluators it replaces for dense sampling: `NurbsCurve::eval`,
//! `FuzzyCurve::eval_layers` and the curves of `Solution`, to 1e-12 relative,
//! on random curves with repeated knots up to full multiplicity, at both domain
//! ends, at every knot, and with sorted and unsorted parameters.

use proptest::prelude::*;
use t2spline::sampling::{Bound, CurveSamples, LayerSamples, Params, Sampler, SweepSamples};
use t2spline::{
    strategies, Alpha, Error, FuzzyCurve, KnotVector, Layer, Nt2Number, Nt2Point, NurbsCurve, Side,
    TypeReduction,
};

/// Relative tolerance of the engine against the reference evaluators.
const TOL: f64 = 1e-12;

/// `|a − b| ≤ TOL·scale`, where `scale` is the size of the curve's control
/// values (at least 1): both evaluators round at that scale.
fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= TOL * scale.max(1.0)
}

/// The largest absolute control value of a fuzzy curve.
fn scale<const D: usize>(c: &FuzzyCurve<D>) -> f64 {
    c.points()
        .iter()
        .flat_map(|p| Layer::ALL.map(|l| p.layer(l)))
        .flatten()
        .fold(0.0, |m: f64, x| m.max(x.abs()))
}

/// Parameters that probe the engine: both ends, every knot in the domain (where
/// spans change, including knots of full multiplicity), and `extra` values at
/// fractions of the domain; sorted, as a sampler walks them.
fn probe_params(knots: &KnotVector, fractions: &[f64]) -> Vec<f64> {
    let d = knots.domain();
    let mut t: Vec<f64> = fractions.iter().map(|&s| d.lerp(s)).collect();
    t.extend([d.start, d.end]);
    t.extend(knots.as_slice().iter().filter(|&&u| d.contains(u)));
    t.sort_by(f64::total_cmp);
    t
}

fn fractions() -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(0.0..=1.0f64, 0..40)
}

/// Checks every sample against `reference(t)`.
fn check_curve<const D: usize>(
    got: &CurveSamples<D>,
    params: &[f64],
    scale: f64,
    reference: impl Fn(f64) -> [f64; D],
) -> Result<(), TestCaseError> {
    prop_assert_eq!(got.len(), params.len());
    for (i, &t) in params.iter().enumerate() {
        let (a, b) = (got.point(i).unwrap(), reference(t));
        prop_assert!(
            a.iter().zip(&b).all(|(&x, &y)| close(x, y, scale)),
            "t = {t}: engine {a:?}, reference {b:?}"
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn crisp_sampling_matches_eval(c in strategies::curve::<2>(), s in fractions(), rotate in 0usize..50) {
        let scale = c.control_points().iter().flatten().fold(0.0, |m: f64, x| m.max(x.abs()));
        let sorted = probe_params(c.knots(), &s);
        check_curve(&c.sample_soa(&sorted).unwrap(), &sorted, scale, |t| c.eval(t).unwrap())?;
        // The same parameters out of order: found by search instead of walking.
        let mut shuffled = sorted.clone();
        shuffled.reverse();
        let k = rotate % shuffled.len();
        shuffled.rotate_left(k);
        check_curve(&c.sample_soa(&shuffled).unwrap(), &shuffled, scale, |t| c.eval(t).unwrap())?;
    }

    #[test]
    fn layer_sampling_matches_eval_layers_and_keeps_the_order(
        c in strategies::fuzzy_curve::<2>(), s in fractions(),
    ) {
        let params = probe_params(c.knots(), &s);
        let got = c.sample_layers(&params).unwrap();
        let scale = scale(&c);
        for layer in Layer::ALL {
            check_curve(&got[layer], &params, scale, |t| c.eval_layers(t).unwrap()[layer])?;
        }
        for (i, t) in params.iter().enumerate() {
            for d in 0..2 {
                let v = Layer::ALL.map(|l| got[l].coord(d)[i]);
                prop_assert!(v.windows(2).all(|w| w[0] <= w[1]), "t = {t}: {v:?}");
            }
        }
    }

    #[test]
    fn layers_into_slices_are_sample_layers_bit_for_bit(
        c in strategies::fuzzy_curve::<3>(), s in fractions(), uniform in 2usize..40,
    ) {
        let params = probe_params(c.knots(), &s);
        for p in [Params::Given(&params), Params::Uniform(uniform)] {
            let want = c.sample_layers(p).unwrap();
            let n = p.len();
            let mut buffer = vec![f64::NAN; 7 * 3 * n];
            let mut out: Vec<&mut [f64]> = buffer.chunks_mut(n.max(1)).collect();
            out.resize_with(21, || &mut []);
            c.sample_layers_into_slices(p, &mut out).unwrap();
            for layer in Layer::ALL {
                for d in 0..3 {
                    let got = &buffer[(layer.index() * 3 + d) * n..][..n];
                    let want = want[layer].coord(d);
                    prop_assert!(
                        got.iter().zip(want).all(|(a, b)| a.to_bits() == b.to_bits()),
                        "{layer} coordinate {d}: {got:?} != {want:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn sweep_matches_the_curves_of_every_stage(
        c in strategies::fuzzy_curve::<3>(),
        s in fractions(),
        alphas in proptest::collection::vec(0.0..=1.0f64, 1..4),
        method in proptest::sample::select(TypeReduction::ALL.to_vec()),
    ) {
        let alphas: Vec<Alpha> = alphas.into_iter().map(|a| Alpha::try_new(a).unwrap()).collect();
        let params = probe_params(c.knots(), &s);
        let sweep = c.sample_sweep_with(&params, &alphas, method).unwrap();
        let scale = scale(&c);
        prop_assert_eq!(sweep.levels().len(), alphas.len());
        for (level, &alpha) in sweep.levels().iter().zip(&alphas) {
            let solution = c.solve_with(alpha, method);
            prop_assert_eq!(level.alpha(), alpha);
            prop_assert!(level.alpha_cut(Layer::Crisp).is_none());
            for layer in Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp) {
                match (level.alpha_cut(layer), solution.alpha_cut_curve(layer)) {
                    (Some(got), Some(curve)) => check_curve(got, &params, scale, |t| curve.eval(t).unwrap())?,
                    (None, None) => {}
                    (got, want) => prop_assert!(false, "{layer}: {:?} vs {:?}", got.is_some(), want.is_some()),
                }
            }
            let left = solution.type_reduced_curve(Side::Left);
            let right = solution.type_reduced_curve(Side::Right);
            let solved = solution.defuzzified_curve();
            check_curve(level.type_reduced(Side::Left), &params, scale, |t| left.eval(t).unwrap())?;
            check_curve(level.type_reduced(Side::Right), &params, scale, |t| right.eval(t).unwrap())?;
            check_curve(level.defuzzified(), &params, scale, |t| solved.eval(t).unwrap())?;
            // Orders that hold for the exact curves hold for the samples:
            // left ≤ defuzzified ≤ right always, left ≤ crisp ≤ right for
            // the paper's reduction only (a centroid may lie off crisp).
            let crisp = &sweep.layers()[Layer::Crisp];
            for i in 0..crisp.len() {
                for d in 0..3 {
                    let (l, x, r) = (
                        level.type_reduced(Side::Left).coord(d)[i],
                        crisp.coord(d)[i],
                        level.type_reduced(Side::Right).coord(d)[i],
                    );
                    let y = level.defuzzified().coord(d)[i];
                    prop_assert!(l <= y && y <= r, "{method}: {l} {y} {r}");
                    if method == TypeReduction::Paper {
                        prop_assert!(l <= x && x <= r, "{l} {x} {r}");
                    }
                }
            }
            let stages = solution.sample_stages(&params).unwrap();
            prop_assert_eq!(&stages, level);
        }
    }

    #[test]
    fn uniform_params_are_the_domain_grid(c in strategies::curve::<2>(), n in 2usize..300) {
        let grid = c.domain().uniform(n).unwrap();
        prop_assert_eq!(c.sample_soa(Params::Uniform(n)).unwrap(), c.sample_soa(&grid).unwrap());
    }
}

/// A curve of degree `p` with awkward weights and uneven knots, for the
/// conditioning of the power form at high degree.
fn high_degree_curve(p: usize) -> NurbsCurve<2> {
    let n = p + 6;
    let points: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let x = i as f64;
            [x * 3.0 - 7.0, (x * 1.7).sin() * 9.0]
        })
        .collect();
    let weights: Vec<f64> = (0..n).map(|i| [1.0, 0.2, 5.0, 0.7][i % 4]).collect();
    let mut knots = vec![0.0; p + 1];
    let interior = [0.01, 0.02, 0.5, 0.5, 0.97];
    knots.extend(interior);
    knots.extend(vec![1.0; p + 1]);
    let u = KnotVector::try_new(knots, p, n).unwrap();
    NurbsCurve::try_new(points, weights, u).unwrap()
}

#[test]
fn high_degrees_stay_within_tolerance() {
    for p in 1..=12 {
        let c = high_degree_curve(p);
        let params = c.domain().uniform(2001).unwrap();
        let got = c.sample_soa(&params).unwrap();
        for (i, &t) in params.iter().enumerate() {
            let want = c.eval(t).unwrap();
            let a = got.point(i).unwrap();
            assert!(
                close(a[0], want[0], 21.0) && close(a[1], want[1], 21.0),
                "degree {p}, t = {t}: {a:?} vs {want:?}"
            );
        }
    }
}

/// A cubic with one span `width` wide at `left` and extreme coordinates
/// (the hostile-input ranges).
fn narrow_span_curve(width: f64, left: f64, weights: &[f64]) -> NurbsCurve<2> {
    let points: Vec<[f64; 2]> = [1e150, -3e149, 2e-150, 7e149, -1e150, 5e148]
        .iter()
        .map(|&x| [x, -x * 0.5])
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 0.0, left, left + width, 1.0, 1.0, 1.0, 1.0];
    let u = KnotVector::try_new(knots, 3, 6).unwrap();
    NurbsCurve::try_new(points, weights.to_vec(), u).unwrap()
}

#[test]
fn narrow_and_subnormal_spans_give_finite_samples_equal_to_eval() {
    // Spans 1e-140 wide overflowed the derivatives of the basis in `t`
    // (1/width³) and gave NaN and infinite samples; spans below 1e-308 made
    // 2/width overflow; clamping far knots in the local variable changed the
    // basis when the span was not in the middle (found by fuzzing). Moderate
    // weights take the power form, extreme ones the direct evaluation.
    let moderate = [1.0, 0.5, 3.0, 1.0, 0.7, 2.0];
    let extreme = [1e12, 1e-12, 3.0, 1e12, 0.5, 1e-12];
    for weights in [&moderate[..], &extreme[..]] {
        for left in [0.5, 0.1, 0.93] {
            for width in [1e-10, 1e-140, 1e-250, 1e-300, 1e-310, 1e-320, 5e-324] {
                let c = narrow_span_curve(width, left, weights);
                let mut params = c.domain().uniform(101).unwrap();
                params.extend([left, left + width / 3.0, left + width / 2.0, left + width]);
                params.sort_by(f64::total_cmp);
                let got = c.sample_soa(&params).unwrap();
                for (i, &t) in params.iter().enumerate() {
                    let want = c.eval(t).unwrap();
                    let a = got.point(i).unwrap();
                    assert!(
                        a.iter().all(|x| x.is_finite())
                            && close(a[0], want[0], 1e150)
                            && close(a[1], want[1], 1e150),
                        "weights {weights:?}, span at {left} of width {width:e}, t = {t}: {a:?} vs {want:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_narrow_first_span_between_distinct_far_knots_matches_eval() {
    // Found by fuzzing: an unclamped cubic whose first span is 8.75e-303
    // wide, with distinct knots far from it on both sides. Their distances
    // (−5.125, −4 against 0.375) enter one ratio of the basis; mapping the
    // knots to the span's local variable and clamping them at ±1e300 gave
    // (1.505, 1.572) instead of (1.916, 2.342) at t = 0.
    let w = 8.751082007644295e-303;
    let u = KnotVector::try_new(
        vec![
            -6.125, -5.125, -4.0, 0.0, w, 0.375, 0.375, 0.875, 1.0, 2.0, 3.0,
        ],
        3,
        7,
    )
    .unwrap();
    let points = vec![
        [0.0, 0.0],
        [1.0, 0.625],
        [2.0, 2.5],
        [3.0, 0.625],
        [4.0, 0.0],
        [5.0, 0.625],
        [6.0, 2.5],
    ];
    let weights = vec![1.5, 1.53125, 1.5625, 1.59375, 1.625, 1.65625, 1.6875];
    let c = NurbsCurve::try_new(points, weights, u).unwrap();
    let params = [0.0, w / 2.0, w, 0.2, 0.375, 0.875];
    let got = c.sample_soa(&params[..]).unwrap();
    // The value at t = 0 from exact rational arithmetic (Cox–de Boor with
    // Python's fractions).
    let exact = [1.9158557527189468, 2.342229536348025];
    assert!(
        close(got.point(0).unwrap()[0], exact[0], 3.0)
            && close(got.point(0).unwrap()[1], exact[1], 3.0)
    );
    for (i, &t) in params.iter().enumerate() {
        let want = c.eval(t).unwrap();
        let a = got.point(i).unwrap();
        assert!(
            close(a[0], want[0], 6.0) && close(a[1], want[1], 6.0),
            "t = {t}: {a:?} vs {want:?}"
        );
    }
}

#[test]
fn full_multiplicity_knot_takes_the_value_from_the_right() {
    let u = KnotVector::try_new(vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0], 1, 4).unwrap();
    let c = NurbsCurve::try_new(
        vec![[0.0, 0.0], [1.0, 0.0], [5.0, 5.0], [6.0, 5.0]],
        vec![1.0; 4],
        u,
    )
    .unwrap();
    let s = c.sample_soa(&[0.0, 0.25, 0.5, 1.0]).unwrap();
    assert!((s.point(1).unwrap()[0] - 0.5).abs() < 1e-15);
    assert!(
        (s.point(2).unwrap()[0] - 5.0).abs() < 1e-15
            && (s.point(2).unwrap()[1] - 5.0).abs() < 1e-15
    );
    assert!((s.point(3).unwrap()[0] - 6.0).abs() < 1e-15);
}

#[test]
fn bad_parameters_and_outputs_are_errors() {
    let c = high_degree_curve(3);
    assert!(matches!(
        c.sample_soa(&[0.5, 1.5]),
        Err(Error::OutOfDomain { t, .. }) if t == 1.5
    ));
    assert!(matches!(
        c.sample_soa(&[f64::NAN]),
        Err(Error::OutOfDomain { .. })
    ));
    let sampler = c.sampler();
    let mut a = vec![0.0; 3];
    let mut b = vec![0.0; 2];
    let mut out: Vec<&mut [f64]> = vec![&mut a, &mut b];
    assert!(matches!(
        sampler.sample_into(Params::Uniform(3), &mut out),
        Err(Error::Length {
            expected: 3,
            found: 2,
            ..
        })
    ));
    assert!(matches!(
        sampler.sample_into(Params::Uniform(3), &mut out[..1]),
        Err(Error::Length {
            expected: 2,
            found: 1,
            ..
        })
    ));
    let knots = KnotVector::clamped_uniform(1, 2).unwrap();
    assert!(matches!(
        Sampler::try_new(&knots, &[1.0, 1.0], &[[0.0, f64::INFINITY]]),
        Err(Error::NotFinite { .. })
    ));
    assert!(matches!(
        Sampler::try_new(&knots, &[1.0, -1.0], &[[0.0, 1.0]]),
        Err(Error::Weight { index: 1, .. })
    ));
}

#[test]
fn layers_into_slices_refuse_wrong_outputs_and_parameters() {
    let c = paper_like_curve();
    let mut buffer = vec![0.0; 14 * 3];
    let mut out: Vec<&mut [f64]> = buffer.chunks_mut(3).collect();
    assert!(matches!(
        c.sample_layers_into_slices(Params::Uniform(3), &mut out[..13]),
        Err(Error::Length {
            expected: 14,
            found: 13,
            ..
        })
    ));
    assert!(matches!(
        c.sample_layers_into_slices(Params::Uniform(4), &mut out),
        Err(Error::Length {
            expected: 4,
            found: 3,
            ..
        })
    ));
    assert!(matches!(
        c.sample_layers_into_slices(&[0.0, 0.5, 2.0], &mut out),
        Err(Error::OutOfDomain { t, .. }) if t == 2.0
    ));
}

#[test]
fn empty_params_give_empty_samples() {
    let c = high_degree_curve(2);
    assert!(c.sample_soa(Params::Uniform(0)).unwrap().is_empty());
    assert!(c.sample_soa(&[]).unwrap().is_empty());
}

/// A number with the spreads of the paper's example around `c`.
fn paper_number(c: f64) -> Nt2Number {
    Nt2Number::try_new(
        c,
        [c - 0.6, c + 0.9],
        [c - 0.4, c + 0.6],
        [c - 0.2, c + 0.3],
        0.6,
    )
    .unwrap()
}

/// A fuzzy curve big enough to pass the parallel threshold.
fn paper_like_curve() -> FuzzyCurve<2> {
    let n = paper_number;
    let points = (0..10)
        .map(|i| {
            let x = i as f64;
            Nt2Point::new([n(x), n((x * 1.3).sin() * 3.0)])
        })
        .collect();
    FuzzyCurve::try_new(
        3,
        points,
        vec![1.0, 0.5, 2.0, 1.0, 3.0, 0.7, 1.0, 1.5, 0.8, 1.0],
        None,
    )
    .unwrap()
}

#[cfg(feature = "parallel")]
#[test]
fn threads_give_bit_identical_results() {
    let c = paper_like_curve();
    let alphas = [Alpha::try_new(0.3).unwrap(), Alpha::try_new(0.8).unwrap()];
    let mut t = c.domain().uniform(50_001).unwrap();
    t.swap(10, 40_000); // some unsorted parameters too
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            (
                c.sample_sweep(&t, &alphas).unwrap(),
                c.sample_layers(Params::Uniform(100_003)).unwrap(),
            )
        })
    };
    let (one, three) = (run(1), run(3));
    // PartialEq on f64 vectors: equal values, bit for bit except ±0 (none here).
    assert!(one == three, "results differ between 1 and 3 threads");
}

#[test]
fn fuzzy_curve_with_crisp_numbers_gives_seven_equal_layers() {
    let points = (0..6)
        .map(|i| {
            let x = Nt2Number::try_crisp(i as f64).unwrap();
            Nt2Point::new([x, Nt2Number::try_crisp((i * i) as f64).unwrap()])
        })
        .collect();
    let c = FuzzyCurve::try_new(2, points, vec![1.0, 2.0, 0.5, 1.0, 3.0, 1.0], None).unwrap();
    let s = c.sample_layers(Params::Uniform(257)).unwrap();
    for l in Layer::ALL {
        assert_eq!(s[l], s[Layer::Crisp], "{l}");
    }
}

#[test]
fn bounds_clamp_channels_and_ignore_self_bounds() {
    // Three constant channels 1, 0, 2 on a line; bound channel 0 into [ch1, ch2]
    // (no change), channel 1 at least channel 0 (raised to 1), and channel 2 by
    // itself (a no-op, not an error).
    let knots = KnotVector::clamped_uniform(1, 2).unwrap();
    let s = Sampler::try_new(&knots, &[1.0, 3.0], &[[1.0, 1.0], [0.0, 0.0], [2.0, 2.0]])
        .unwrap()
        .with_bounds(&[
            Bound {
                channel: 0,
                at_least: Some(1),
                at_most: Some(2),
            },
            Bound {
                channel: 1,
                at_least: Some(0),
                at_most: None,
            },
            Bound {
                channel: 2,
                at_least: Some(2),
                at_most: Some(2),
            },
        ])
        .unwrap();
    let out = s.sample(Params::Uniform(5)).unwrap();
    assert!(out[0].iter().all(|&x| (x - 1.0).abs() < 1e-15), "{out:?}");
    assert_eq!(out[1], out[0]);
    assert!(out[2].iter().all(|&x| (x - 2.0).abs() < 1e-15), "{out:?}");
    assert!(matches!(
        s.with_bounds(&[Bound {
            channel: 3,
            at_least: None,
            at_most: None
        }]),
        Err(Error::Length {
            expected: 3,
            found: 4,
            ..
        })
    ));
}

#[test]
fn one_level_alone_equals_that_level_of_a_sweep() {
    let c = paper_like_curve();
    for a in [0.0, 0.45, 0.6, 0.61, 1.0] {
        let alpha = Alpha::try_new(a).unwrap();
        let alone = c.solve(alpha).sample_stages(Params::Uniform(777)).unwrap();
        let sweep = c.sample_sweep(Params::Uniform(777), &[alpha]).unwrap();
        assert_eq!(alone, sweep.levels()[0], "alpha = {a}");
    }
}

#[test]
fn reused_buffers_give_the_same_samples_at_any_size() {
    let c = paper_like_curve();
    let alphas = [Alpha::try_new(0.2).unwrap(), Alpha::try_new(0.9).unwrap()];
    let mut layers = LayerSamples::empty();
    let mut sweep = SweepSamples::empty();
    let mut crisp = CurveSamples::empty();
    for n in [1000, 10, 3001] {
        let p = Params::Uniform(n);
        c.sample_layers_into(p, &mut layers).unwrap();
        assert_eq!(layers, c.sample_layers(p).unwrap(), "{n}");
        c.sample_sweep_into(p, &alphas, &mut sweep).unwrap();
        assert_eq!(sweep, c.sample_sweep(p, &alphas).unwrap(), "{n}");
        c.crisp_curve().sample_soa_into(p, &mut crisp).unwrap();
        assert_eq!(crisp, layers[Layer::Crisp], "{n}");
    }
    assert!(c.sample_layers_into(&[2.0], &mut layers).is_err());
    assert!(layers.is_empty());
}

#[test]
fn fewer_parameters_than_spans_match_the_curves_of_every_stage() {
    // 400 control points of order 12, 101 parameters: every span is
    // evaluated from the basis instead of converted to power form.
    let n = paper_number;
    let points = (0..400)
        .map(|i| {
            let x = f64::from(i);
            Nt2Point::new([n(x), n((x * 1.3).sin() * 3.0)])
        })
        .collect();
    let weights = (0..400).map(|i| 1.0 + f64::from(i % 7) * 0.4).collect();
    let c = FuzzyCurve::try_new(11, points, weights, None).unwrap();
    let alpha = Alpha::try_new(0.8).unwrap();
    let sweep = c.sample_sweep(Params::Uniform(101), &[alpha]).unwrap();
    let grid = c.knots().domain().uniform(101).unwrap();
    let solved = c.solve(alpha).defuzzified_curve();
    let crisp = c.crisp_curve();
    for (i, &t) in grid.iter().enumerate() {
        let (want, got) = (
            solved.eval(t).unwrap(),
            sweep.levels()[0].defuzzified().point(i).unwrap(),
        );
        let (x, y) = (
            crisp.eval(t).unwrap(),
            sweep.layers()[Layer::Crisp].point(i).unwrap(),
        );
        for d in 0..2 {
            assert!(
                close(got[d], want[d], 400.0) && close(y[d], x[d], 400.0),
                "t = {t}"
            );
        }
    }
}
