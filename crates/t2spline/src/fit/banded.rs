//! Banded least squares by Givens rotations.
//!
//! Every system of curve fitting has a design matrix whose rows are the
//! B-spline basis at one data parameter: at most `p + 1` non-zero values in
//! consecutive columns (The NURBS Book §9.2.1, §9.4.1). This module solves
//!
//! ```text
//! min ‖A·x − b‖₂      A: m × n, row r non-zero only in columns first[r] … first[r] + width − 1
//! ```
//! by reducing `A` to an upper triangular band `R` one row at a time with Givens
//! rotations, as FITPACK does (Dierckx, *Curve and Surface Fitting with Splines*,
//! 1993, §4.1, routines `fpgivs`/`fprota`), then back-substituting. This is
//! backward stable without forming the normal equations `AᵀA`, whose condition
//! number is the square of `A`'s, and costs `O(m·width²)`; interpolation
//! (`m = n`) is the special case with zero residual.

use crate::error::Error;

/// A matrix whose row `r` has its non-zero values in the columns
/// `first[r] … first[r] + width − 1` (fewer at the right edge).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct BandMatrix {
    cols: usize,
    width: usize,
    first: Vec<usize>,
    /// Row-major, `width` values per row, zero where the row is shorter.
    values: Vec<f64>,
}

impl BandMatrix {
    /// An empty matrix with `cols` columns and band `width`.
    pub(crate) fn new(cols: usize, width: usize) -> Self {
        BandMatrix {
            cols,
            width,
            first: Vec::new(),
            values: Vec::new(),
        }
    }

    /// Appends a row whose values start at column `first`.
    ///
    /// Rows must come in order of their first column, as the basis at
    /// increasing parameters does: the row-by-row reduction of
    /// [`least_squares`] relies on it (an earlier row never reaches further
    /// right than a later one's band).
    ///
    /// # Panics
    /// If `values` is longer than the band, reaches past the last column (with
    /// non-zero values), or `first` is less than the previous row's; all are
    /// internal invariants of the callers.
    pub(crate) fn push_row(&mut self, first: usize, values: &[f64]) {
        assert!(values.len() <= self.width, "row longer than the band");
        assert!(
            self.first.last().is_none_or(|&previous| previous <= first),
            "rows out of order"
        );
        assert!(
            values
                .iter()
                .enumerate()
                .all(|(i, &v)| v == 0.0 || first + i < self.cols),
            "row reaches past the last column"
        );
        self.first.push(first);
        self.values.extend_from_slice(values);
        self.values
            .extend(std::iter::repeat_n(0.0, self.width - values.len()));
    }

    /// Number of rows.
    pub(crate) fn rows(&self) -> usize {
        self.first.len()
    }

    /// Number of columns.
    pub(crate) fn cols(&self) -> usize {
        self.cols
    }

    /// Row `r`: its first column and its `width` values.
    pub(crate) fn row(&self, r: usize) -> (usize, &[f64]) {
        (
            self.first[r],
            &self.values[r * self.width..(r + 1) * self.width],
        )
    }

    /// `A·x`.
    pub(crate) fn mul(&self, x: &[f64]) -> Vec<f64> {
        (0..self.rows())
            .map(|r| {
                let (first, v) = self.row(r);
                v.iter()
                    .enumerate()
                    .filter(|(_, &a)| a != 0.0)
                    .map(|(i, a)| a * x[first + i])
                    .sum()
            })
            .collect()
    }

    /// `Aᵀ·y`.
    pub(crate) fn mul_transpose(&self, y: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.cols];
        for (r, &yr) in y.iter().enumerate() {
            let (first, v) = self.row(r);
            for (i, &a) in v.iter().enumerate() {
                if a != 0.0 {
                    out[first + i] += a * yr;
                }
            }
        }
        out
    }

    /// The matrix made of the columns `keep` (strictly increasing), renumbered
    /// `0 … keep.len() − 1`. A row's columns inside `keep` are consecutive after
    /// renumbering, so the band width does not grow.
    pub(crate) fn select_columns(&self, keep: &[usize]) -> BandMatrix {
        let mut index = vec![usize::MAX; self.cols];
        for (new, &old) in keep.iter().enumerate() {
            index[old] = new;
        }
        let mut out = BandMatrix::new(keep.len(), self.width);
        let mut row = Vec::with_capacity(self.width);
        let mut previous = 0;
        for r in 0..self.rows() {
            let (first, v) = self.row(r);
            row.clear();
            let mut start = None;
            for (i, &a) in v.iter().enumerate() {
                let new = index.get(first + i).copied().unwrap_or(usize::MAX);
                if new != usize::MAX {
                    start.get_or_insert(new);
                    row.push(a);
                }
            }
            // A row with no kept column is zero; keep the order of first columns.
            previous = start.unwrap_or(previous);
            out.push_row(previous, &row);
        }
        out
    }
}

/// Relative size below which a diagonal value of `R` counts as zero: the
/// columns of `A` are then dependent to working precision.
const RANK_TOLERANCE: f64 = 1e-13;

/// The triangular factor `R` of `A = Q·R`, in band storage: row `j` holds
/// `R[j, j … j + width − 1]`.
#[derive(Clone, Debug)]
pub(crate) struct Triangle {
    n: usize,
    w: usize,
    values: Vec<f64>,
}

impl Triangle {
    fn at(&self, j: usize, k: usize) -> f64 {
        self.values[j * self.w + k]
    }

    /// `Err` if a diagonal value is zero or negligible next to the largest.
    fn check_rank(&self) -> Result<(), Error> {
        let largest = (0..self.n).map(|j| self.at(j, 0).abs()).fold(0.0, f64::max);
        let negligible = |d: f64| d.is_nan() || d <= RANK_TOLERANCE * largest;
        match (0..self.n).find(|&j| negligible(self.at(j, 0).abs())) {
            Some(column) => Err(Error::SingularFit { column }),
            None => Ok(()),
        }
    }

    /// Solves `R·x = z` by back substitution.
    fn solve<const R: usize>(&self, z: &[[f64; R]]) -> Vec<[f64; R]> {
        let mut x = vec![[0.0; R]; self.n];
        for j in (0..self.n).rev() {
            let mut acc = z[j];
            for k in 1..self.w.min(self.n - j) {
                let rk = self.at(j, k);
                if rk != 0.0 {
                    for d in 0..R {
                        acc[d] -= rk * x[j + k][d];
                    }
                }
            }
            x[j] = acc.map(|v| v / self.at(j, 0));
        }
        x
    }

    /// Solves `Rᵀ·x = y` by forward substitution.
    fn solve_transpose(&self, y: &[f64]) -> Vec<f64> {
        let mut x = vec![0.0; self.n];
        for j in 0..self.n {
            let mut acc = y[j];
            for k in 1..self.w.min(j + 1) {
                acc -= self.at(j - k, k) * x[j - k];
            }
            x[j] = acc / self.at(j, 0);
        }
        x
    }

    /// An estimate of the 1-norm condition number `‖R‖₁·‖R⁻¹‖₁`, which is
    /// within a small factor of the 2-norm condition number of `A`.
    ///
    /// `‖R⁻¹‖₁` by Hager's method as refined by Higham (*Accuracy and Stability
    /// of Numerical Algorithms*, 2002, Algorithm 15.4, LAPACK `xLACON`): a few
    /// solves with `R` and `Rᵀ`, a lower bound that is almost always within a
    /// factor 3 of the true value.
    fn condition(&self) -> f64 {
        let n = self.n;
        if n == 0 {
            return 1.0;
        }
        let mut norm: f64 = 0.0;
        for col in 0..n {
            let sum: f64 = (0..self.w.min(col + 1))
                .map(|k| self.at(col - k, k).abs())
                .sum();
            norm = norm.max(sum);
        }
        let one_norm = |v: &[f64]| v.iter().map(|x| x.abs()).sum::<f64>();
        let solve = |v: &[f64]| -> Vec<f64> {
            let z: Vec<[f64; 1]> = v.iter().map(|&x| [x]).collect();
            self.solve(&z).into_iter().map(|x| x[0]).collect()
        };
        let mut x = vec![1.0 / n as f64; n];
        let mut estimate = 0.0;
        let mut last = usize::MAX;
        for _ in 0..5 {
            let y = solve(&x);
            estimate = one_norm(&y);
            let signs: Vec<f64> = y
                .iter()
                .map(|v| if *v < 0.0 { -1.0 } else { 1.0 })
                .collect();
            let z = self.solve_transpose(&signs);
            let (j, zj) = z
                .iter()
                .enumerate()
                .map(|(j, v)| (j, v.abs()))
                .fold((0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
            let ztx: f64 = z.iter().zip(&x).map(|(a, b)| a * b).sum();
            if zj <= ztx || j == last {
                break;
            }
            last = j;
            x = vec![0.0; n];
            x[j] = 1.0;
        }
        // Higham's alternative vector guards against the rare bad case.
        let alt: Vec<f64> = (0..n)
            .map(|i| {
                let s = if i % 2 == 0 { 1.0 } else { -1.0 };
                s * (1.0 + i as f64 / (n.max(2) - 1) as f64)
            })
            .collect();
        let alt_estimate = 2.0 * one_norm(&solve(&alt)) / (3.0 * n as f64);
        norm * estimate.max(alt_estimate)
    }
}

/// Reduces `A` to its triangular factor by Givens rotations, applying them to
/// the right-hand sides: returns `R` and the first `n` rows of `Qᵀ·b`.
fn triangularize<const R: usize>(a: &BandMatrix, b: &[[f64; R]]) -> (Triangle, Vec<[f64; R]>) {
    debug_assert_eq!(a.rows(), b.len());
    let (n, w) = (a.cols(), a.width);
    let mut tri = vec![0.0; n * w];
    let mut z = vec![[0.0; R]; n];
    let mut filled = vec![false; n];
    let mut h = vec![0.0; w];
    for (r, rhs) in b.iter().enumerate() {
        let (first, v) = a.row(r);
        h.copy_from_slice(v);
        let mut y = *rhs;
        for i in 0..w {
            let j = first + i;
            if h[i] == 0.0 || j >= n {
                continue;
            }
            let row = &mut tri[j * w..(j + 1) * w];
            if !filled[j] {
                // An empty row of R takes what is left of h, shifted to column j.
                row[..w - i].copy_from_slice(&h[i..]);
                z[j] = y;
                filled[j] = true;
                break;
            }
            // Givens rotation zeroing h[i] against the diagonal R[j, j].
            let (c, s, diag) = givens(row[0], h[i]);
            row[0] = diag;
            for k in 1..w - i {
                let (rk, hk) = (row[k], h[i + k]);
                row[k] = c * rk + s * hk;
                h[i + k] = c * hk - s * rk;
            }
            for d in 0..R {
                let (zj, yd) = (z[j][d], y[d]);
                z[j][d] = c * zj + s * yd;
                y[d] = c * yd - s * zj;
            }
            h[i] = 0.0;
        }
    }
    (Triangle { n, w, values: tri }, z)
}

/// Solves `min ‖A·x − b‖₂` for each of the `R` right-hand sides (columns of
/// `b`, one row of `b` per row of `A`).
///
/// # Errors
/// [`Error::SingularFit`] if the columns of `A` are linearly dependent to
/// working precision (a diagonal value of the triangular factor is below
/// `1e-13` times the largest): the fit is not determined by the data.
pub(crate) fn least_squares<const R: usize>(
    a: &BandMatrix,
    b: &[[f64; R]],
) -> Result<Vec<[f64; R]>, Error> {
    let (tri, z) = triangularize(a, b);
    tri.check_rank()?;
    Ok(tri.solve(&z))
}

/// An estimate of the condition number of `A`: the 1-norm condition number
/// of its triangular factor, within a factor `√n` of the 2-norm condition
/// number `σ_max/σ_min` of `A`.
///
/// # Errors
/// [`Error::SingularFit`] as [`least_squares`].
pub(crate) fn condition(a: &BandMatrix) -> Result<f64, Error> {
    let rows = vec![[0.0; 0]; a.rows()];
    let (tri, _) = triangularize(a, &rows);
    tri.check_rank()?;
    Ok(tri.condition())
}

/// The rotation `(c, s)` with `c·a + s·b = r`, `−s·a + c·b = 0`, and `r`.
fn givens(a: f64, b: f64) -> (f64, f64, f64) {
    let r = a.hypot(b);
    (a / r, b / r, r)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dense(a: &BandMatrix) -> Vec<Vec<f64>> {
        (0..a.rows())
            .map(|r| {
                let (first, v) = a.row(r);
                let mut row = vec![0.0; a.cols()];
                for (i, &x) in v.iter().enumerate() {
                    if x != 0.0 {
                        row[first + i] = x;
                    }
                }
                row
            })
            .collect()
    }

    #[test]
    fn square_tridiagonal_system_is_solved_exactly() {
        // [2 1 0; 1 2 1; 0 1 2]·x = [4, 8, 8] has x = (1, 2, 3).
        let mut a = BandMatrix::new(3, 3);
        a.push_row(0, &[2.0, 1.0]);
        a.push_row(0, &[1.0, 2.0, 1.0]);
        a.push_row(1, &[1.0, 2.0]);
        let x = least_squares(&a, &[[4.0], [8.0], [8.0]]).unwrap();
        for (got, want) in x.iter().zip([1.0, 2.0, 3.0]) {
            assert!((got[0] - want).abs() < 1e-14, "{x:?}");
        }
    }

    #[test]
    fn overdetermined_line_fit_matches_the_normal_equations() {
        // Fit y = x0 + x1·t through (0, 1), (1, 2), (2, 2), (3, 4): columns 1 and t.
        let t = [0.0, 1.0, 2.0, 3.0];
        let y = [1.0, 2.0, 2.0, 4.0];
        let mut a = BandMatrix::new(2, 2);
        for &ti in &t {
            a.push_row(0, &[1.0, ti]);
        }
        let x = least_squares(&a, &y.map(|v| [v])).unwrap();
        // Normal equations: [4 6; 6 14]·x = [9, 18] → x = (0.9, 0.9).
        let (s, st, stt, sy, sty) = (4.0, 6.0, 14.0, 9.0, 18.0);
        let det = s * stt - st * st;
        let want = [(stt * sy - st * sty) / det, (s * sty - st * sy) / det];
        assert!((x[0][0] - want[0]).abs() < 1e-14 && (x[1][0] - want[1]).abs() < 1e-14);
        // The residual is orthogonal to the columns.
        let r: Vec<f64> = a
            .mul(&[x[0][0], x[1][0]])
            .iter()
            .zip(y)
            .map(|(p, q)| q - p)
            .collect();
        let g = a.mul_transpose(&r);
        assert!(g.iter().all(|v| v.abs() < 1e-13), "{g:?}");
    }

    #[test]
    fn dependent_columns_are_reported() {
        let mut a = BandMatrix::new(2, 2);
        a.push_row(0, &[1.0, 1.0]);
        a.push_row(0, &[2.0, 2.0]);
        assert_eq!(
            least_squares(&a, &[[1.0], [2.0]]),
            Err(Error::SingularFit { column: 1 })
        );
        // A column no row touches.
        let mut a = BandMatrix::new(3, 2);
        a.push_row(0, &[1.0, 1.0]);
        a.push_row(0, &[1.0, 2.0]);
        assert!(matches!(
            least_squares(&a, &[[1.0], [2.0]]),
            Err(Error::SingularFit { column: 2 })
        ));
    }

    #[test]
    fn condition_estimate_of_a_diagonal_matrix_is_exact() {
        let mut a = BandMatrix::new(3, 1);
        for v in [2.0, 0.5, 8.0] {
            let r = a.rows();
            a.push_row(r, &[v]);
        }
        let c = condition(&a).unwrap();
        assert!((c - 16.0).abs() < 1e-12, "{c}");
    }

    #[test]
    fn condition_estimate_of_a_bidiagonal_matrix_is_close() {
        // [1 −1; 0 ε] has ‖A‖₁ = 1 + ε and A⁻¹ = [1 1/ε; 0 1/ε], ‖A⁻¹‖₁ = 2/ε.
        let eps = 1e-6;
        let mut a = BandMatrix::new(2, 2);
        a.push_row(0, &[1.0, -1.0]);
        a.push_row(1, &[eps]);
        let want = (1.0 + eps) * 2.0 / eps;
        let got = condition(&a).unwrap();
        assert!((got - want).abs() < 1e-9 * want, "{got} vs {want}");
    }

    #[test]
    fn select_columns_keeps_values_in_place() {
        let mut a = BandMatrix::new(5, 3);
        a.push_row(0, &[1.0, 2.0, 3.0]);
        a.push_row(2, &[4.0, 5.0, 6.0]);
        let s = a.select_columns(&[0, 2, 4]);
        assert_eq!(dense(&s), vec![vec![1.0, 3.0, 0.0], vec![0.0, 4.0, 6.0]]);
    }
}
