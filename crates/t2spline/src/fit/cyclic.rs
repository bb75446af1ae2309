//! The linear map from control values to curve values at the data
//! parameters of a closed curve with periodic knots, its wrapped columns
//! folded, and the fits through it.

use crate::error::Error;
use crate::fit::banded::{condition, least_squares, BandMatrix};
use crate::fit::design::{basis_rows, curve_values, MAX_CONDITION};
use crate::fit::nnls::nonnegative_least_squares;
use crate::nurbs::KnotVector;

/// The periodic basis at the `N` loop parameters of a closed fit with `n`
/// distinct control values, the curve's last `p` repeating its first `p`.
///
/// A closed curve has `n + p` control points with `P_{n+i} = Pᵢ` (`i < p`),
/// so the basis function of column `j + n` multiplies the same unknown as
/// column `j`: the columns **fold**,
///
/// ```text
/// Aₖ,ⱼ = Σ_{i ≡ j (mod n)} Nᵢ,ₚ(ūₖ)   (k = 0 … N − 1, j = 0 … n − 1),   min ‖A·P − Q‖₂
/// ```
/// (The NURBS Book §12.4 on the periodic construction; Dierckx 1993 §6.1).
/// There are no end points to fix: interpolation is the square case `n = N`,
/// least squares `n < N`. Each row is non-zero on `p + 1` cyclically
/// consecutive columns, a band that wraps from the last column to the
/// first. Taken in the interleaved order `0, n − 1, 1, n − 2, 2, …`, in
/// which cyclic neighbours are at most two places apart, every row fits in
/// a band of width `2p + 1`: the system is then solved by the banded Givens
/// QR of the open fit (`banded.rs`), and its non-negative version by the same
/// NNLS, at four times the open fit's cost per row and without a dense
/// matrix.
#[derive(Clone, Debug)]
pub(crate) struct CyclicDesign {
    /// First control index (of the `n + p`) and the `p + 1` basis values at
    /// each parameter, in the order of the data.
    rows: Vec<(usize, Vec<f64>)>,
    /// The folded matrix, columns interleaved, rows sorted by first column.
    band: BandMatrix,
    /// `band` row `r` is the data point `order[r]`.
    order: Vec<usize>,
    /// Control value `j` is `band` column `position[j]`.
    position: Vec<usize>,
    /// The distinct control values `n`.
    distinct: usize,
    degree: usize,
    condition: f64,
}

/// Where column `j` of `n` stands in the interleaved order `0, n − 1, 1,
/// n − 2, …`: cyclic neighbours `j`, `j + 1 (mod n)` are at most two apart.
fn interleaved(j: usize, n: usize) -> usize {
    if 2 * j < n {
        2 * j
    } else {
        2 * (n - 1 - j) + 1
    }
}

impl CyclicDesign {
    /// The folded basis of the periodic `knots` (`n + p` control points, the
    /// domain `[0, 1]`) at the loop parameters `params` (`N ≥ n` values in
    /// `[0, 1)`).
    ///
    /// # Errors
    /// [`Error::SingularFit`] if the data cannot determine the control
    /// values; [`Error::IllConditionedFit`] if the condition number exceeds
    /// [`MAX_CONDITION`].
    pub(crate) fn new(params: &[f64], knots: &KnotVector) -> Result<Self, Error> {
        let p = knots.degree();
        let n = knots.count() - p;
        let rows = basis_rows(params, knots);
        let position: Vec<usize> = (0..n).map(|j| interleaved(j, n)).collect();
        let width = (2 * p + 1).min(n);
        let mut folded: Vec<(usize, Vec<f64>, usize)> = rows
            .iter()
            .enumerate()
            .map(|(k, (first, values))| {
                let places: Vec<(usize, f64)> = values
                    .iter()
                    .enumerate()
                    .map(|(i, &v)| (position[(first + i) % n], v))
                    .collect();
                let start = places.iter().map(|&(c, _)| c).min().unwrap_or(0);
                let mut row = vec![0.0; width];
                for (c, v) in places {
                    // p + 1 ≤ n columns, cyclically consecutive: within the band.
                    row[c - start] += v;
                }
                let used = n - start;
                row.truncate(used.min(width));
                (start, row, k)
            })
            .collect();
        folded.sort_by_key(|(start, _, _)| *start);
        let mut band = BandMatrix::new(n, width);
        for (start, row, _) in &folded {
            band.push_row(*start, row);
        }
        let order = folded.into_iter().map(|(_, _, k)| k).collect();
        let mut design = CyclicDesign {
            rows,
            band,
            order,
            position,
            distinct: n,
            degree: p,
            condition: 1.0,
        };
        let condition = condition(&design.band).map_err(|e| design.column_of(e))?;
        if condition.is_nan() || condition > MAX_CONDITION {
            return Err(Error::IllConditionedFit { condition });
        }
        design.condition = condition;
        Ok(design)
    }

    /// The estimated condition number of the folded system.
    pub(crate) fn condition(&self) -> f64 {
        self.condition
    }

    /// The data values in the order of the band's rows.
    fn rhs<T: Copy>(&self, q: &[T]) -> Vec<T> {
        self.order.iter().map(|&k| q[k]).collect()
    }

    /// The `n + p` control values of the curve from the band's solution:
    /// back to the order of the columns, the first `p` repeated at the end.
    fn expand<T: Copy>(&self, x: &[T]) -> Vec<T> {
        (0..self.distinct + self.degree)
            .map(|i| x[self.position[i % self.distinct]])
            .collect()
    }

    /// A [`Error::SingularFit`] renumbered from the band's column to the
    /// control value's.
    fn column_of(&self, e: Error) -> Error {
        match e {
            Error::SingularFit { column } => Error::SingularFit {
                column: self
                    .position
                    .iter()
                    .position(|&c| c == column)
                    .unwrap_or(column),
            },
            other => other,
        }
    }

    /// The `n + p` control values fitting `q` (one per parameter) by least
    /// squares; interpolation when `n = N`.
    ///
    /// # Errors
    /// [`Error::SingularFit`] if the data do not determine the control
    /// values.
    pub(crate) fn fit<const R: usize>(&self, q: &[[f64; R]]) -> Result<Vec<[f64; R]>, Error> {
        let x = least_squares(&self.band, &self.rhs(q)).map_err(|e| self.column_of(e))?;
        Ok(self.expand(&x))
    }

    /// Non-negative control values fitting `q`: the curve values are then
    /// non-negative too, since the basis is.
    ///
    /// # Errors
    /// [`Error::SingularFit`] as [`CyclicDesign::fit`].
    pub(crate) fn fit_nonnegative(&self, q: &[f64]) -> Result<Vec<f64>, Error> {
        let x =
            nonnegative_least_squares(&self.band, &self.rhs(q)).map_err(|e| self.column_of(e))?;
        Ok(self.expand(&x))
    }

    /// The curve values at every parameter, for the `n + p` control values.
    pub(crate) fn values<const R: usize>(&self, control: &[[f64; R]]) -> Vec<[f64; R]> {
        curve_values(&self.rows, control)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::periodic_knots;

    #[test]
    fn interleaving_is_a_permutation_keeping_cyclic_neighbours_close() {
        for n in 1..12 {
            let mut seen: Vec<usize> = (0..n).map(|j| interleaved(j, n)).collect();
            for j in 0..n {
                let (a, b) = (interleaved(j, n), interleaved((j + 1) % n, n));
                assert!(a.abs_diff(b) <= 2, "n {n}, j {j}: {a}, {b}");
            }
            seen.sort_unstable();
            assert_eq!(seen, (0..n).collect::<Vec<_>>());
        }
    }

    #[test]
    fn folded_band_equals_the_dense_folded_matrix() {
        // Uneven loop parameters, every degree and count: A·x from the band
        // (in interleaved order) equals the dense fold of the basis.
        let params: Vec<f64> = (0..11).map(|k| (f64::from(k) / 11.0).powf(1.2)).collect();
        for p in 1..=4 {
            for n in p + 1..=11 {
                let knots = periodic_knots(&params, p, n).unwrap();
                let d = CyclicDesign::new(&params, &knots).unwrap();
                let x: Vec<f64> = (0..n).map(|j| 1.0 + (j * j) as f64).collect();
                let banded_x: Vec<f64> = {
                    let mut v = vec![0.0; n];
                    for (j, &c) in d.position.iter().enumerate() {
                        v[c] = x[j];
                    }
                    v
                };
                let got = d.band.mul(&banded_x);
                for (r, &k) in d.order.iter().enumerate() {
                    let (first, values) = &d.rows[k];
                    let want: f64 = values
                        .iter()
                        .enumerate()
                        .map(|(i, b)| b * x[(first + i) % n])
                        .sum();
                    assert!(
                        (got[r] - want).abs() < 1e-14 * want.abs().max(1.0),
                        "p {p}, n {n}, row {k}: {} vs {want}",
                        got[r]
                    );
                }
            }
        }
    }
}
