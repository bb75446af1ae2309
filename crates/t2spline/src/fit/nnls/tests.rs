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

/// The signs of the unconstrained solution, where both phases start.
fn unconstrained_signs(problem: &mut Problem) -> Vec<bool> {
    let free = problem.solve_free(&vec![true; problem.a.cols()]).unwrap();
    free.iter().map(|&x| x > 0.0).collect()
}

/// Lawson–Hanson alone, from the signs of the unconstrained solution.
fn lawson_hanson_alone(a: &BandMatrix, b: &[f64]) -> Vec<f64> {
    let mut problem = Problem::new(a, b);
    let passive = unconstrained_signs(&mut problem);
    problem.lawson_hanson(passive).unwrap()
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
    let active_set = lawson_hanson_alone(&a, &b);
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
        let active_set = lawson_hanson_alone(&a, &b);
        assert_kkt(&a, &b, &active_set, 1e-10);
        // The solution is unique: the two ways agree to rounding.
        for (p, q) in x.iter().zip(&active_set) {
            proptest::prop_assert!((p - q).abs() < 1e-10, "{x:?} vs {active_set:?}");
        }
    }
}

/// The interpolation matrix of a cubic B-spline (square, a band of 4) at
/// `n` parameters with random gaps and its averaging knots (The NURBS Book
/// Eq. 9.8), and spreads that are zero or random at random.
fn jumping_spreads(n: usize, seed: u64) -> (BandMatrix, Vec<f64>) {
    let p = 3;
    let mut random = crate::strategies::seeded_uniform(seed);
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
fn large_problems_take_few_solves() {
    // The unconstrained solution oscillates in sign and a thousand
    // constraints are active: Lawson–Hanson alone needs a solve per variable
    // it frees. Block pivoting solves seeds 1 and 2 on its own; with seed 36
    // full exchanges stall among a few clusters of neighbouring variables
    // and Lawson–Hanson finishes.
    for (seed, stalls) in [(1, false), (2, false), (36, true)] {
        let (a, b) = jumping_spreads(5000, seed);
        let mut problem = Problem::new(&a, &b);
        let passive = unconstrained_signs(&mut problem);
        let negative = passive.iter().filter(|&&p| !p).count();
        assert!(
            negative > 500,
            "only {negative} negative unconstrained values"
        );
        let phase_1 = problem.block_pivoting(passive).unwrap();
        assert_eq!(
            matches!(phase_1, Pivoting::Stalled(_)),
            stalls,
            "seed {seed}"
        );
        let (x, solves) = Problem::new(&a, &b).solve().unwrap();
        assert!(solves <= 30, "seed {seed}: {solves} solves");
        assert_kkt(&a, &b, &x, 1e-10);
    }
}

#[test]
fn both_phases_agree_with_lawson_hanson_alone_on_a_mid_sized_problem() {
    for seed in [36, 7] {
        let (a, b) = jumping_spreads(1000, seed);
        let x = nonnegative_least_squares(&a, &b).unwrap();
        let active_set = lawson_hanson_alone(&a, &b);
        assert_kkt(&a, &b, &x, 1e-10);
        for (p, q) in x.iter().zip(&active_set) {
            assert!((p - q).abs() < 1e-12, "{p} vs {q}");
        }
    }
}

#[test]
fn a_feasible_unconstrained_solution_is_returned_unchanged() {
    let a = matrix(&[&[2.0, 1.0], &[1.0, 3.0]]);
    let x = nonnegative_least_squares(&a, &[3.0, 4.0]).unwrap();
    assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
}
