use super::*;

fn matrix(rows: &[&[f64]]) -> BandMatrix {
    let cols = rows[0].len();
    let mut a = BandMatrix::new(cols, cols);
    for r in rows {
        a.push_row(0, r);
    }
    a
}

/// Asserts the Karush–Kuhn–Tucker conditions of `x` to `tol`.
fn assert_kkt(a: &BandMatrix, b: &[f64], x: &[f64], tol: f64) {
    let w = gradient(a, b, x);
    for j in 0..a.cols() {
        assert!(x[j] >= 0.0, "negative {j}: {x:?}");
        if x[j] > 0.0 {
            assert!(w[j].abs() < tol, "free variable {j} not optimal: {w:?}");
        } else {
            assert!(w[j] <= tol, "held variable {j} should be freed: {w:?}");
        }
    }
}

/// Block pivoting (within `max_solves`) and Lawson–Hanson, both from the
/// signs of the unconstrained solution as [`nonnegative_least_squares`]
/// starts them.
fn both_methods(
    a: &BandMatrix,
    b: &[f64],
    max_solves: usize,
) -> (Option<(Vec<f64>, usize)>, Vec<f64>) {
    let rhs: Vec<[f64; 1]> = b.iter().map(|&v| [v]).collect();
    let free = least_squares(a, &rhs).unwrap();
    let passive: Vec<bool> = free.iter().map(|x| x[0] > 0.0).collect();
    let tol = gradient_tolerance(b);
    let pivoting = block_pivoting(a, b, &rhs, passive.clone(), tol, max_solves).unwrap();
    (pivoting, lawson_hanson(a, b, &rhs, passive, tol).unwrap())
}

#[test]
fn lawson_hanson_examples() {
    // The examples of scipy.optimize.nnls.
    let a = matrix(&[&[1.0, 0.0], &[1.0, 0.0], &[0.0, 1.0]]);
    let x = nonnegative_least_squares(&a, &[2.0, 1.0, 1.0]).unwrap();
    assert!(
        (x[0] - 1.5).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15,
        "{x:?}"
    );
    let x = nonnegative_least_squares(&a, &[-1.0, -1.0, -1.0]).unwrap();
    assert_eq!(x, vec![0.0, 0.0]);
}

#[test]
fn kkt_conditions_hold_on_a_constrained_problem() {
    // min ‖A·x − b‖ with the unconstrained solution partly negative.
    let a = matrix(&[
        &[1.0, 0.5, 0.0],
        &[0.2, 1.0, 0.3],
        &[0.0, 0.4, 1.0],
        &[0.3, 0.0, 0.6],
    ]);
    let b = [1.0, -2.0, 1.5, 0.7];
    let x = nonnegative_least_squares(&a, &b).unwrap();
    assert_kkt(&a, &b, &x, 1e-12);
    assert!(x.contains(&0.0), "the constraint should be active: {x:?}");
    let (pivoting, active_set) = both_methods(&a, &b, MAX_SOLVES);
    assert_eq!(pivoting.map(|p| p.0), Some(x));
    assert_kkt(&a, &b, &active_set, 1e-12);
}

proptest::proptest! {
    #[test]
    fn both_methods_meet_the_kkt_conditions_on_random_banded_problems(
        random in proptest::collection::vec(
            (0usize..20, proptest::collection::vec(0.05..1.0f64, 1..=4), -3.0..3.0f64),
            25..60,
        )
    ) {
        // 20 columns, rows of up to 4 positive values (like a B-spline
        // basis), plus one row per column so the columns are independent;
        // rows in order of their first column, as the basis gives them.
        let mut rows: Vec<(usize, Vec<f64>, f64)> = (0..20)
            .map(|j| (j, vec![0.5], if j % 3 == 0 { -1.0 } else { 0.7 }))
            .chain(random.into_iter().map(|(first, mut v, rhs)| {
                v.truncate(20 - first);
                (first, v, rhs)
            }))
            .collect();
        rows.sort_by_key(|r| r.0);
        let mut a = BandMatrix::new(20, 4);
        for (first, values, _) in &rows {
            a.push_row(*first, values);
        }
        let b: Vec<f64> = rows.iter().map(|r| r.2).collect();
        let x = nonnegative_least_squares(&a, &b).unwrap();
        assert_kkt(&a, &b, &x, 1e-10);
        let (pivoting, active_set) = both_methods(&a, &b, MAX_SOLVES);
        assert_kkt(&a, &b, &active_set, 1e-10);
        let Some((pivoting, _)) = pivoting else {
            return Err(proptest::test_runner::TestCaseError::fail("pivoting did not finish"));
        };
        assert_kkt(&a, &b, &pivoting, 1e-10);
        // The solution is unique: the two methods agree to rounding.
        for (p, q) in pivoting.iter().zip(&active_set) {
            proptest::prop_assert!((p - q).abs() < 1e-10, "{pivoting:?} vs {active_set:?}");
        }
    }
}

/// The interpolation matrix of a cubic B-spline (square, a band of 4) at
/// `n` parameters with random gaps and its averaging knots (The NURBS Book
/// Eq. 9.8), and spreads that are zero or random at random.
fn jumping_spreads(n: usize, seed: u64) -> (BandMatrix, Vec<f64>) {
    let p = 3;
    let mut state = seed;
    // A linear congruential generator (Knuth's MMIX constants), in [0, 1).
    let mut random = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut params = vec![0.0];
    for _ in 1..n {
        let last = params[params.len() - 1];
        params.push(last + 0.1 + 2.9 * random());
    }
    let total = params[n - 1];
    params.iter_mut().for_each(|u| *u /= total);
    let knots = crate::fit::averaging_knots(&params, p).unwrap();
    let mut a = BandMatrix::new(n, p + 1);
    let mut b = Vec::new();
    for &t in &params {
        let span = knots.find_span(t);
        let mut values = [0.0; 4];
        crate::nurbs::basis::basis_functions(knots.as_slice(), p, span, t, &mut values);
        a.push_row(span - p, &values);
        let r = random();
        b.push(if r < 0.5 { 0.0 } else { 3.0 * r - 1.5 });
    }
    (a, b)
}

#[test]
fn pivoting_solves_large_problems_in_few_solves() {
    // The unconstrained solution oscillates in sign and a thousand
    // constraints are active: Lawson–Hanson needs a solve per variable it
    // frees. With seed 36, full exchanges stall after four solves among a few
    // clusters of variables, which the exchange per cluster resolves (18
    // solves; one exchange at a time would add up the clusters' needs).
    for (seed, most) in [(1, 8), (2, 8), (36, 30)] {
        let (a, b) = jumping_spreads(5000, seed);
        let rhs: Vec<[f64; 1]> = b.iter().map(|&v| [v]).collect();
        let free = least_squares(&a, &rhs).unwrap();
        let negative = free.iter().filter(|x| x[0] < 0.0).count();
        assert!(negative > 500, "only {negative} negative unconstrained values");
        let passive: Vec<bool> = free.iter().map(|x| x[0] > 0.0).collect();
        let (x, solves) = block_pivoting(&a, &b, &rhs, passive, gradient_tolerance(&b), most)
            .unwrap()
            .unwrap_or_else(|| panic!("seed {seed}: no solution within {most} solves"));
        if seed == 36 {
            assert!(solves > 10, "seed 36 no longer stalls ({solves} solves)");
        }
        assert_kkt(&a, &b, &x, 1e-10);
        assert_eq!(nonnegative_least_squares(&a, &b).unwrap(), x);
    }
}

#[test]
fn lawson_hanson_agrees_with_pivoting_on_a_mid_sized_problem() {
    let (a, b) = jumping_spreads(300, 7);
    let (pivoting, active_set) = both_methods(&a, &b, MAX_SOLVES);
    let (pivoting, _) = pivoting.expect("pivoting finishes");
    assert_kkt(&a, &b, &active_set, 1e-10);
    for (p, q) in pivoting.iter().zip(&active_set) {
        assert!((p - q).abs() < 1e-12, "{p} vs {q}");
    }
    // Without solves left for pivoting, the fallback gives the answer.
    let (none, _) = both_methods(&a, &b, 0);
    assert!(none.is_none());
}

#[test]
fn a_feasible_unconstrained_solution_is_returned_unchanged() {
    let a = matrix(&[&[2.0, 1.0], &[1.0, 3.0]]);
    let x = nonnegative_least_squares(&a, &[3.0, 4.0]).unwrap();
    assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
}
