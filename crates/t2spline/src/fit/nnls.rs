//! Non-negative least squares (Lawson & Hanson, *Solving Least Squares
//! Problems*, 1974, ch. 23, algorithm NNLS) on banded design matrices.

use crate::error::Error;
use crate::fit::banded::{least_squares, BandMatrix};

/// Solves `min ‖A·x − b‖₂` subject to `x ≥ 0`.
///
/// The active-set method of Lawson and Hanson, warm-started from the
/// unconstrained solution (below); repeatedly free the variable whose gradient
/// `w = Aᵀ(b − A·x)` is most positive, solve the unconstrained problem on the
/// free variables ([`least_squares`], banded Givens QR), and step back towards
/// the feasible region when that solution has a non-positive entry. It ends
/// when no held variable has a positive gradient: the Karush–Kuhn–Tucker
/// conditions of the problem. When the unconstrained solution is already
/// non-negative it is returned at once, so the result then equals plain least
/// squares.
///
/// Every iterate is feasible and the returned vector is non-negative entry by
/// entry whatever happens; should rounding make the method cycle, it stops
/// after `3n + 30` steps with the last feasible iterate (not seen in tests).
///
/// # Errors
/// [`Error::SingularFit`] if the columns of `A` are dependent, as in
/// [`least_squares`].
pub(crate) fn nonnegative_least_squares(a: &BandMatrix, b: &[f64]) -> Result<Vec<f64>, Error> {
    let n = a.cols();
    let rhs: Vec<[f64; 1]> = b.iter().map(|&v| [v]).collect();
    let free = least_squares(a, &rhs)?;
    if free.iter().all(|x| x[0] >= 0.0) {
        return Ok(free.into_iter().map(|x| x[0]).collect());
    }
    // A gradient below this is rounding noise: each wⱼ sums at most m products
    // of basis values (≤ 1) and residuals (≲ |b|).
    let tol = 64.0
        * f64::EPSILON
        * b.iter()
            .map(|v| v.abs())
            .sum::<f64>()
            .max(f64::MIN_POSITIVE);
    // Warm start: hold the variables the unconstrained solution makes
    // non-positive, solve on the others, and repeat until that solution is
    // positive. The result is feasible and solves the problem restricted to
    // its free variables: the state the outer loop of Lawson–Hanson keeps,
    // so the method may go on from there (the objective still decreases at
    // every step). From x = 0 it would free the variables one by one, a
    // least-squares solve each, quadratic in the number of data.
    let mut passive: Vec<bool> = free.iter().map(|x| x[0] > 0.0).collect();
    let mut x = vec![0.0; n];
    loop {
        let keep: Vec<usize> = (0..n).filter(|&j| passive[j]).collect();
        let z = least_squares(&a.select_columns(&keep), &rhs)?;
        if z.iter().all(|zj| zj[0] > 0.0) {
            for (&j, zj) in keep.iter().zip(&z) {
                x[j] = zj[0];
            }
            break;
        }
        for (&j, zj) in keep.iter().zip(&z) {
            if zj[0] <= 0.0 {
                passive[j] = false;
            }
        }
    }
    // Variables freed and at once pushed back to zero since x last changed.
    let mut rejected = vec![false; n];
    let mut steps = 0;
    let limit = 3 * n + 30;
    'outer: while steps < limit {
        let w = gradient(a, b, &x);
        let Some(t) = (0..n)
            .filter(|&j| !passive[j] && !rejected[j] && w[j] > tol)
            .max_by(|&i, &j| w[i].total_cmp(&w[j]))
        else {
            break;
        };
        passive[t] = true;
        loop {
            steps += 1;
            let keep: Vec<usize> = (0..n).filter(|&j| passive[j]).collect();
            let sub = a.select_columns(&keep);
            let z_sub = least_squares(&sub, &rhs)?;
            let mut z = vec![0.0; n];
            for (&j, zj) in keep.iter().zip(&z_sub) {
                z[j] = zj[0];
            }
            if keep.iter().all(|&j| z[j] > 0.0) {
                x = z;
                rejected.iter_mut().for_each(|r| *r = false);
                continue 'outer;
            }
            // Step from x towards z as far as feasibility allows. Some
            // z[j] <= 0 here (else the loop went on above).
            #[allow(clippy::expect_used)]
            let (blocking, step) = keep
                .iter()
                .filter(|&&j| z[j] <= 0.0)
                .map(|&j| (j, x[j] / (x[j] - z[j])))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .expect("some z[j] <= 0 here");
            if step <= 0.0 && blocking == t && x[t] == 0.0 {
                // Freeing t does not help (its solution is not positive):
                // hold it again and try the next candidate.
                passive[t] = false;
                rejected[t] = true;
                continue 'outer;
            }
            for &j in &keep {
                x[j] += step * (z[j] - x[j]);
                if j == blocking || x[j] <= 0.0 {
                    x[j] = 0.0;
                    passive[j] = false;
                }
            }
            rejected.iter_mut().for_each(|r| *r = false);
            if steps >= limit {
                break 'outer;
            }
        }
    }
    Ok(x)
}

/// `w = Aᵀ(b − A·x)`, the negative gradient of `½‖A·x − b‖²`.
fn gradient(a: &BandMatrix, b: &[f64], x: &[f64]) -> Vec<f64> {
    let ax = a.mul(x);
    let r: Vec<f64> = b.iter().zip(&ax).map(|(bi, ai)| bi - ai).collect();
    a.mul_transpose(&r)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matrix(rows: &[&[f64]]) -> BandMatrix {
        let cols = rows[0].len();
        let mut a = BandMatrix::new(cols, cols);
        for r in rows {
            a.push_row(0, r);
        }
        a
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
        let w = gradient(&a, &b, &x);
        for j in 0..3 {
            assert!(x[j] >= 0.0, "{x:?}");
            if x[j] > 0.0 {
                assert!(w[j].abs() < 1e-12, "free variable {j} not optimal: {w:?}");
            } else {
                assert!(w[j] <= 1e-12, "held variable {j} should be freed: {w:?}");
            }
        }
        assert!(x.contains(&0.0), "the constraint should be active: {x:?}");
    }

    proptest::proptest! {
        #[test]
        fn kkt_conditions_hold_on_random_banded_problems(
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
            let w = gradient(&a, &b, &x);
            for j in 0..20 {
                proptest::prop_assert!(x[j] >= 0.0);
                if x[j] > 0.0 {
                    proptest::prop_assert!(w[j].abs() < 1e-10, "free {j}: {w:?}");
                } else {
                    proptest::prop_assert!(w[j] <= 1e-10, "held {j}: {w:?}");
                }
            }
        }
    }

    #[test]
    fn a_feasible_unconstrained_solution_is_returned_unchanged() {
        let a = matrix(&[&[2.0, 1.0], &[1.0, 3.0]]);
        let x = nonnegative_least_squares(&a, &[3.0, 4.0]).unwrap();
        assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
    }
}
