//! Non-negative least squares on banded design matrices: block principal
//! pivoting (Júdice and Pires 1994; Kim and Park 2011), with the active-set
//! method of Lawson and Hanson (*Solving Least Squares Problems*, 1974,
//! ch. 23, algorithm NNLS) as its fallback.

use crate::error::Error;
use crate::fit::banded::{least_squares, BandMatrix};

/// Full exchanges allowed without fewer infeasible variables before block
/// principal pivoting exchanges one variable per cluster (Kim and Park's `p̄`).
const BACKUP_EXCHANGES: usize = 3;
/// Least-squares solves allowed to block principal pivoting before
/// Lawson–Hanson takes over.
const MAX_SOLVES: usize = 100;

/// Solves `min ‖A·x − b‖₂` subject to `x ≥ 0`.
///
/// The solution is the one point (the columns of `A` are independent) that
/// meets the Karush–Kuhn–Tucker conditions
///
/// ```text
/// x ≥ 0,   w = Aᵀ(b − A·x),   wⱼ = 0 where xⱼ > 0,   wⱼ ≤ 0 where xⱼ = 0
/// ```
/// When the unconstrained solution is already non-negative it is returned at
/// once, so the result then equals plain least squares. Otherwise the
/// variables are split into free ones (solved by unconstrained least squares,
/// [`least_squares`], banded Givens QR) and held ones (zero), starting from the
/// signs of the unconstrained solution, and **block principal pivoting**
/// (Júdice and Pires, *Comput. Oper. Res.* 21, 1994; Kim and Park, *SIAM J.
/// Sci. Comput.* 33, 2011, Algorithm 2) exchanges at once every variable that
/// breaks a condition: free ones that came out negative, held ones whose
/// gradient is positive. Each exchange costs one banded solve, `O(m·p²)`.
///
/// Full exchanges can cycle among a few neighbouring variables. Kim and Park
/// then exchange only the last infeasible variable (Murty's rule, finite). On
/// a banded matrix the variables that cycle sit in small clusters far apart
/// (a few columns each, thousands of columns between them), nearly
/// independent problems, so here Murty's rule is applied in every cluster at
/// once: the last infeasible variable of each run of infeasible variables
/// less than `2·width` columns apart. The rule only decides which
/// variables to try; the result is returned only once the conditions above
/// hold (to the rounding tolerance below). Should pivoting not get there in
/// 100 solves, Lawson and Hanson's active-set method, which frees one variable
/// per solve (time quadratic in the number of data), finishes from a feasible
/// start.
///
/// The returned vector is non-negative entry by entry whatever happens.
///
/// # Errors
/// [`Error::SingularFit`] if the columns of `A` are dependent, as in
/// [`least_squares`].
pub(crate) fn nonnegative_least_squares(a: &BandMatrix, b: &[f64]) -> Result<Vec<f64>, Error> {
    let rhs: Vec<[f64; 1]> = b.iter().map(|&v| [v]).collect();
    let free = least_squares(a, &rhs)?;
    if free.iter().all(|x| x[0] >= 0.0) {
        return Ok(free.into_iter().map(|x| x[0]).collect());
    }
    let tol = gradient_tolerance(b);
    let passive: Vec<bool> = free.iter().map(|x| x[0] > 0.0).collect();
    match block_pivoting(a, b, &rhs, passive.clone(), tol, MAX_SOLVES)? {
        Some((x, _)) => Ok(x),
        None => lawson_hanson(a, b, &rhs, passive, tol),
    }
}

/// A gradient below this is rounding noise: each `wⱼ` sums at most `m`
/// products of basis values (≤ 1) and residuals (≲ |b|).
fn gradient_tolerance(b: &[f64]) -> f64 {
    64.0 * f64::EPSILON
        * b.iter()
            .map(|v| v.abs())
            .sum::<f64>()
            .max(f64::MIN_POSITIVE)
}

/// The least-squares solution on the free (`passive`) variables, zero on the
/// others.
fn solve_free(a: &BandMatrix, rhs: &[[f64; 1]], passive: &[bool]) -> Result<Vec<f64>, Error> {
    let keep: Vec<usize> = (0..a.cols()).filter(|&j| passive[j]).collect();
    let z = least_squares(&a.select_columns(&keep), rhs)?;
    let mut x = vec![0.0; a.cols()];
    for (&j, zj) in keep.iter().zip(&z) {
        x[j] = zj[0];
    }
    Ok(x)
}

/// Block principal pivoting from the split `passive` (see
/// [`nonnegative_least_squares`]): the solution and the number of solves it
/// took, or `None` if the conditions are not met within `max_solves` solves.
fn block_pivoting(
    a: &BandMatrix,
    b: &[f64],
    rhs: &[[f64; 1]],
    mut passive: Vec<bool>,
    tol: f64,
    max_solves: usize,
) -> Result<Option<(Vec<f64>, usize)>, Error> {
    let reach = 2 * a.width();
    let mut fewest = usize::MAX;
    let mut backup = BACKUP_EXCHANGES;
    let mut stalled = false;
    for solves in 1..=max_solves {
        let x = solve_free(a, rhs, &passive)?;
        let w = gradient(a, b, &x);
        let infeasible: Vec<usize> = (0..a.cols())
            .filter(|&j| if passive[j] { x[j] < 0.0 } else { w[j] > tol })
            .collect();
        if infeasible.is_empty() {
            return Ok(Some((x, solves)));
        }
        if !stalled && infeasible.len() < fewest {
            fewest = infeasible.len();
            backup = BACKUP_EXCHANGES;
        } else if !stalled && backup > 0 {
            backup -= 1;
        } else {
            // Full exchanges have stalled: one per cluster from now on.
            stalled = true;
        }
        for (k, &j) in infeasible.iter().enumerate() {
            let last_of_cluster = infeasible
                .get(k + 1)
                .is_none_or(|&next| next - j >= reach);
            if !stalled || last_of_cluster {
                passive[j] = !passive[j];
            }
        }
    }
    Ok(None)
}

/// The active-set method of Lawson and Hanson from the split `passive`:
/// repeatedly free the held variable whose gradient is most positive, solve
/// on the free variables, and step back towards the feasible region when that
/// solution has a non-positive entry. Every iterate is feasible; should
/// rounding make the method cycle, it stops after `3n + 30` steps with the
/// last feasible iterate.
fn lawson_hanson(
    a: &BandMatrix,
    b: &[f64],
    rhs: &[[f64; 1]],
    mut passive: Vec<bool>,
    tol: f64,
) -> Result<Vec<f64>, Error> {
    let n = a.cols();
    // Feasible start: hold the variables the solution on the free ones makes
    // non-positive, and repeat until that solution is positive. It solves the
    // problem restricted to its free variables: the state the outer loop
    // keeps. (From x = 0 the method would free the variables one by one.)
    let mut x = loop {
        let z = solve_free(a, rhs, &passive)?;
        if (0..n).all(|j| !passive[j] || z[j] > 0.0) {
            break z;
        }
        for (p, zj) in passive.iter_mut().zip(&z) {
            *p &= *zj > 0.0;
        }
    };
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
            let z = solve_free(a, rhs, &passive)?;
            let keep: Vec<usize> = (0..n).filter(|&j| passive[j]).collect();
            if keep.iter().all(|&j| z[j] > 0.0) {
                x = z;
                rejected.iter_mut().for_each(|r| *r = false);
                continue 'outer;
            }
            // Step from x towards z as far as feasibility allows.
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
mod tests;
