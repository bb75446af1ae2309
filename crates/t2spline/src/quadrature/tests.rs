use super::*;

fn relative_error(got: f64, want: f64) -> f64 {
    (got - want).abs() / want.abs()
}

#[test]
fn kronrod_is_exact_for_polynomials_of_degree_22() {
    let p = kronrod(&mut |_, x: f64| x.powi(22), 0, -1.0, 1.0, 0);
    assert!((p.value - 2.0 / 23.0).abs() < 1e-15, "{p:?}");
    // Odd powers vanish by symmetry; the Gauss rule is exact to degree 13.
    let p = kronrod(&mut |_, x: f64| x.powi(12) + x.powi(5), 0, -1.0, 1.0, 0);
    assert!((p.value - 2.0 / 13.0).abs() < 1e-15, "{p:?}");
    assert!(p.error < 1e-14, "{p:?}");
}

/// A named integrand, its interval and its exact integral.
type Case = (&'static str, fn(f64) -> f64, [f64; 2], f64);

#[test]
fn smooth_and_singular_integrands_meet_a_relative_tolerance_of_1e_13() {
    let cases: [Case; 4] = [
        ("exp", f64::exp, [0.0, 1.0], std::f64::consts::E - 1.0),
        // Runge's function: poles at ±i/5, close to the interval.
        (
            "runge",
            |x| 1.0 / (1.0 + 25.0 * x * x),
            [-1.0, 1.0],
            0.4 * 5f64.atan(),
        ),
        // An integrable singularity at an end.
        ("sqrt", f64::sqrt, [0.0, 1.0], 2.0 / 3.0),
        // A narrow peak of width 1e-4 in the middle of the interval.
        (
            "peak",
            |x| 1e-4 / (1e-8 + (x - 0.3) * (x - 0.3)),
            [0.0, 1.0],
            (0.7e4f64).atan() + (0.3e4f64).atan(),
        ),
    ];
    for (name, f, range, exact) in cases {
        let i = integrate(f, range, Tolerance::relative(1e-13), 1000);
        assert!(i.converged, "{name}: {i:?}");
        assert!(
            relative_error(i.value, exact) < 1e-13,
            "{name}: {i:?} vs {exact}"
        );
        // The error estimate bounds the true error.
        assert!(
            (i.value - exact).abs() <= i.error.max(4.0 * f64::EPSILON * exact),
            "{name}: {i:?}"
        );
    }
}

#[test]
fn a_tolerance_never_met_stops_at_the_budget() {
    // With tolerance 0 no piece is ever accurate enough: without the budget
    // this would bisect to depth 60 everywhere.
    let calls = std::cell::Cell::new(0usize);
    let f = |t: f64| {
        calls.set(calls.get() + 1);
        (t * 1e6).sin()
    };
    let i = integrate(f, [0.0, 1.0], Tolerance::relative(0.0), 100);
    assert!(!i.converged);
    // The first estimate and 100 bisections into two pieces of 15 nodes.
    assert_eq!(calls.get(), 15 + 100 * 2 * 15);
    assert!(i.value.is_finite() && i.value.abs() <= 1.0, "{i:?}");
}

#[test]
fn pieces_get_their_own_integrand_and_never_their_ends() {
    // A step at 0.5 between two pieces, and a piece of zero width.
    let pieces = [[0.0, 0.5], [0.5, 0.5], [0.5, 2.0]];
    let f = |k: usize, x: f64| {
        assert!(pieces[k][0] < x && x < pieces[k][1], "{k}: {x}");
        if k == 0 {
            x * x
        } else {
            3.0
        }
    };
    let (i, out) = integrate_pieces(f, &pieces, Tolerance::relative(1e-13), 100);
    assert!(
        i.converged && relative_error(i.value, 1.0 / 24.0 + 4.5) < 1e-15,
        "{i:?}"
    );
    assert!(out.windows(2).all(|w| w[0].hi <= w[1].lo), "{out:?}");
    assert_eq!(out.iter().map(|p| p.value).sum::<f64>(), i.value);
}

#[test]
fn a_zero_integrand_converges_at_once() {
    let calls = std::cell::Cell::new(0usize);
    let i = integrate(
        |_| {
            calls.set(calls.get() + 1);
            0.0
        },
        [0.0, 1.0],
        Tolerance::relative(1e-12),
        100,
    );
    assert_eq!((i.value, i.error, i.converged), (0.0, 0.0, true));
    assert_eq!(calls.get(), 15);
}

#[test]
fn an_absolute_tolerance_stops_early() {
    let loose = integrate(
        |x: f64| (20.0 * x).sin(),
        [0.0, 10.0],
        Tolerance {
            relative: 0.0,
            absolute: 1e-3,
        },
        1000,
    );
    let tight = integrate(
        |x: f64| (20.0 * x).sin(),
        [0.0, 10.0],
        Tolerance::relative(1e-11),
        1000,
    );
    let exact = (1.0 - 200f64.cos()) / 20.0;
    assert!(
        loose.converged && (loose.value - exact).abs() < 1e-3,
        "{loose:?}"
    );
    assert!(
        tight.converged && relative_error(tight.value, exact) < 1e-11,
        "{tight:?}"
    );
    // The integrand cancels: ∫|f| is 250 times the integral, and rounding
    // (the floor 50·ε·∫|f| of the estimate) leaves 1e-13 out of reach.
    let unreachable = integrate(
        |x: f64| (20.0 * x).sin(),
        [0.0, 10.0],
        Tolerance::relative(1e-13),
        1000,
    );
    assert!(!unreachable.converged, "{unreachable:?}");
    assert!(
        relative_error(unreachable.value, exact) < 1e-11,
        "{unreachable:?}"
    );
}
