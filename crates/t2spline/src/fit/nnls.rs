//! Non-negative least squares on banded design matrices: block principal
//! pivoting (Júdice and Pires 1994; Kim and Park 2011) for the bulk of the
//! constraints, the active-set method of Lawson and Hanson (*Solving Least
//! Squares Problems*, 1974, ch. 23, algorithm NNLS) for the last few.

use crate::error::Error;
use crate::fit::banded::{least_squares, BandMatrix};

/// Full exchanges allowed in a row without fewer infeasible variables before
/// block principal pivoting hands over to Lawson–Hanson (Kim and Park's `p̄`).
const BACKUP_EXCHANGES: usize = 3;

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
/// [`least_squares`], banded Givens QR, `O(m·p²)`) and held ones (zero),
/// starting from the signs of the unconstrained solution, in two phases:
///
/// 1. **Block principal pivoting** (Júdice and Pires, *Comput. Oper. Res.* 21,
///    1994; Kim and Park, *SIAM J. Sci. Comput.* 33, 2011, Algorithm 2)
///    exchanges at once every variable that breaks a condition: free ones
///    that came out negative, held ones whose gradient is positive. On
///    fitting problems this takes thousands of infeasible variables to a few
///    in about ten solves, whatever the size. Full exchanges can then cycle
///    among neighbouring variables; when three in a row do not reduce their
///    number (Kim and Park's rule), the phase ends.
/// 2. **Lawson and Hanson's active-set method** goes on from that split: it
///    frees one variable per solve and keeps every iterate feasible, so the
///    objective decreases at every step. From the start it would need a
///    solve per active constraint (time quadratic in the number of data);
///    from the end of phase 1 it needs about as many as were left.
///
/// The returned vector is non-negative entry by entry whatever happens.
///
/// # Errors
/// [`Error::SingularFit`] if the columns of `A` are dependent, as in
/// [`least_squares`].
pub(crate) fn nonnegative_least_squares(a: &BandMatrix, b: &[f64]) -> Result<Vec<f64>, Error> {
    Problem::new(a, b).solve().map(|(x, _)| x)
}

/// One problem and the number of least-squares solves spent on it.
struct Problem<'a> {
    a: &'a BandMatrix,
    b: &'a [f64],
    rhs: Vec<[f64; 1]>,
    /// A gradient below this is rounding noise: each `wⱼ` sums at most `m`
    /// products of basis values (≤ 1) and residuals (≲ |b|).
    tol: f64,
    solves: usize,
}

/// How the first phase ended.
enum Pivoting {
    /// The conditions hold at `x`.
    Solved(Vec<f64>),
    /// Full exchanges stopped making progress at this split.
    Stalled(Vec<bool>),
}

impl<'a> Problem<'a> {
    fn new(a: &'a BandMatrix, b: &'a [f64]) -> Self {
        let tol = 64.0
            * f64::EPSILON
            * b.iter()
                .map(|v| v.abs())
                .sum::<f64>()
                .max(f64::MIN_POSITIVE);
        Problem {
            a,
            b,
            rhs: b.iter().map(|&v| [v]).collect(),
            tol,
            solves: 0,
        }
    }

    /// The solution and the number of solves it took.
    fn solve(mut self) -> Result<(Vec<f64>, usize), Error> {
        let free = self.solve_free(&vec![true; self.a.cols()])?;
        if free.iter().all(|&x| x >= 0.0) {
            return Ok((free, self.solves));
        }
        let passive = free.iter().map(|&x| x > 0.0).collect();
        let x = match self.block_pivoting(passive)? {
            Pivoting::Solved(x) => x,
            Pivoting::Stalled(passive) => self.lawson_hanson(passive)?,
        };
        Ok((x, self.solves))
    }

    /// The least-squares solution on the free (`passive`) variables, zero on
    /// the others.
    fn solve_free(&mut self, passive: &[bool]) -> Result<Vec<f64>, Error> {
        self.solves += 1;
        let keep: Vec<usize> = (0..self.a.cols()).filter(|&j| passive[j]).collect();
        let z = least_squares(&self.a.select_columns(&keep), &self.rhs)?;
        let mut x = vec![0.0; self.a.cols()];
        for (&j, zj) in keep.iter().zip(&z) {
            x[j] = zj[0];
        }
        Ok(x)
    }

    /// `w = Aᵀ(b − A·x)`, the negative gradient of `½‖A·x − b‖²`.
    fn gradient(&self, x: &[f64]) -> Vec<f64> {
        gradient(self.a, self.b, x)
    }

    /// Phase 1 of [`nonnegative_least_squares`] from the split `passive`.
    /// The number of infeasible variables decreases at least every fourth
    /// solve, so the phase ends.
    fn block_pivoting(&mut self, mut passive: Vec<bool>) -> Result<Pivoting, Error> {
        let mut fewest = usize::MAX;
        let mut backup = BACKUP_EXCHANGES;
        loop {
            let x = self.solve_free(&passive)?;
            let w = self.gradient(&x);
            let infeasible: Vec<usize> = (0..x.len())
                .filter(|&j| {
                    if passive[j] {
                        x[j] < 0.0
                    } else {
                        w[j] > self.tol
                    }
                })
                .collect();
            if infeasible.is_empty() {
                return Ok(Pivoting::Solved(x));
            }
            if infeasible.len() < fewest {
                fewest = infeasible.len();
                backup = BACKUP_EXCHANGES;
            } else if backup > 0 {
                backup -= 1;
            } else {
                return Ok(Pivoting::Stalled(passive));
            }
            for &j in &infeasible {
                passive[j] = !passive[j];
            }
        }
    }

    /// Phase 2 of [`nonnegative_least_squares`], the active-set method of
    /// Lawson and Hanson from the split `passive`: repeatedly free the held
    /// variable whose gradient is most positive, solve on the free variables,
    /// and step back towards the feasible region when that solution has a
    /// non-positive entry. Should rounding make the method cycle, it stops
    /// after `3n + 30` steps with the last feasible iterate.
    fn lawson_hanson(&mut self, mut passive: Vec<bool>) -> Result<Vec<f64>, Error> {
        let n = self.a.cols();
        // Feasible start: hold the variables the solution on the free ones
        // makes non-positive, and repeat until that solution is positive. It
        // solves the problem restricted to its free variables: the state the
        // outer loop keeps.
        let mut x = loop {
            let z = self.solve_free(&passive)?;
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
            let w = self.gradient(&x);
            let Some(t) = (0..n)
                .filter(|&j| !passive[j] && !rejected[j] && w[j] > self.tol)
                .max_by(|&i, &j| w[i].total_cmp(&w[j]))
            else {
                break;
            };
            passive[t] = true;
            loop {
                steps += 1;
                let z = self.solve_free(&passive)?;
                let keep: Vec<usize> = (0..n).filter(|&j| passive[j]).collect();
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
}

/// `w = Aᵀ(b − A·x)`, the negative gradient of `½‖A·x − b‖²`.
fn gradient(a: &BandMatrix, b: &[f64], x: &[f64]) -> Vec<f64> {
    let ax = a.mul(x);
    let r: Vec<f64> = b.iter().zip(&ax).map(|(bi, ai)| bi - ai).collect();
    a.mul_transpose(&r)
}

#[cfg(test)]
mod tests;
