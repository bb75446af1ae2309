//! The linear map from control values to curve values at the data parameters,
//! and the fits through it with both end values fixed.

use crate::error::Error;
use crate::fit::banded::{condition, least_squares, BandMatrix};
use crate::fit::nnls::nonnegative_least_squares;
use crate::nurbs::basis::basis_functions;
use crate::nurbs::KnotVector;

/// The B-spline basis at every data parameter of a clamped knot vector, and
/// the system for the interior control values once the two end ones are fixed.
///
/// With clamped knots and `ū₀ = 0`, `ū_m = 1` the curve starts at `P₀` and ends
/// at `P_n`, so fixing `P₀ = Q₀` and `P_n = Q_m` interpolates the end points, and
/// the other control values solve (The NURBS Book Eqs. 9.63–9.67)
///
/// ```text
/// min Σ_{k=1}^{m−1} |Rₖ − Σ_{i=1}^{n−1} Nᵢ,ₚ(ūₖ)·Pᵢ|²,   Rₖ = Qₖ − N₀,ₚ(ūₖ)·Q₀ − N_n,ₚ(ūₖ)·Q_m
/// ```
/// For interpolation (`n = m`) the system is square and the minimum is 0: the
/// equations of Algorithm A9.1 with its first and last rows eliminated.
#[derive(Clone, Debug)]
pub(crate) struct Design {
    /// First control index and the `p + 1` basis values at each parameter.
    rows: Vec<(usize, Vec<f64>)>,
    /// Rows 1 … m − 1, columns 1 … n − 1 of the basis matrix.
    interior: BandMatrix,
    count: usize,
    condition: f64,
}

/// The largest condition number a fit may have. Control values computed from
/// a system of condition number κ can be wrong in their last log₁₀ κ digits
/// (the solver is backward stable), so beyond 10¹² fewer than four digits
/// would be left: the fit is refused.
pub(crate) const MAX_CONDITION: f64 = 1e12;

impl Design {
    /// The basis of `knots` (clamped, `count` control points) at `params`
    /// (`ū₀ = 0 … ū_m = 1`, at least two).
    ///
    /// # Errors
    /// [`Error::SingularFit`] if the data cannot determine the interior
    /// control values; [`Error::IllConditionedFit`] if the condition number of
    /// the system exceeds [`MAX_CONDITION`].
    pub(crate) fn new(params: &[f64], knots: &KnotVector) -> Result<Self, Error> {
        let (p, n) = (knots.degree(), knots.count());
        let rows = basis_rows(params, knots);
        let m = rows.len() - 1;
        let mut interior = BandMatrix::new(n.saturating_sub(2), p + 1);
        for (first, values) in &rows[1..m] {
            // Keep the columns 1 … n − 1, renumbered from 0.
            let (skip, start) = if *first == 0 { (1, 0) } else { (0, first - 1) };
            let end = (first + values.len()).min(n - 1);
            let take = end.saturating_sub(first + skip);
            interior.push_row(start, &values[skip..skip + take]);
        }
        let condition = condition(&interior).map_err(|e| shift_column(e, 1))?;
        if condition.is_nan() || condition > MAX_CONDITION {
            return Err(Error::IllConditionedFit { condition });
        }
        Ok(Design {
            rows,
            interior,
            count: n,
            condition,
        })
    }

    /// The estimated condition number of the interior system (1 when there
    /// is nothing to solve).
    pub(crate) fn condition(&self) -> f64 {
        self.condition
    }

    /// The number of control points.
    pub(crate) fn count(&self) -> usize {
        self.count
    }

    /// `N_{0,p}(ūₖ)` and `N_{n,p}(ūₖ)`: the weights of the two end control
    /// points at parameter `k`.
    fn end_basis(&self, k: usize) -> (f64, f64) {
        let (first, values) = &self.rows[k];
        let last = self.count - 1;
        let at = |i: usize| {
            i.checked_sub(*first)
                .and_then(|j| values.get(j))
                .copied()
                .unwrap_or(0.0)
        };
        (at(0), at(last))
    }

    /// The interior right-hand sides `Rₖ` for data `q` with the end control
    /// values `start`, `end`.
    fn interior_rhs<const R: usize>(
        &self,
        q: &[[f64; R]],
        start: [f64; R],
        end: [f64; R],
    ) -> Vec<[f64; R]> {
        let m = q.len() - 1;
        (1..m)
            .map(|k| {
                let (n0, nn) = self.end_basis(k);
                std::array::from_fn(|d| q[k][d] - n0 * start[d] - nn * end[d])
            })
            .collect()
    }

    /// Control values fitting `q` (one per parameter) with the end values
    /// fixed to the end data; exact interpolation when `n = m`.
    ///
    /// # Errors
    /// [`Error::SingularFit`] if the data do not determine the interior
    /// control values.
    pub(crate) fn fit<const R: usize>(&self, q: &[[f64; R]]) -> Result<Vec<[f64; R]>, Error> {
        let (start, end) = (q[0], q[q.len() - 1]);
        let inner = least_squares(&self.interior, &self.interior_rhs(q, start, end))
            .map_err(|e| shift_column(e, 1))?;
        Ok(std::iter::once(start)
            .chain(inner)
            .chain(std::iter::once(end))
            .collect())
    }

    /// Non-negative control values fitting `q` (one per parameter), the ends
    /// fixed to `max(0, q₀)` and `max(0, q_m)`: the curve values are then
    /// non-negative too, since the basis is.
    ///
    /// # Errors
    /// [`Error::SingularFit`] as [`Design::fit`].
    pub(crate) fn fit_nonnegative(&self, q: &[f64]) -> Result<Vec<f64>, Error> {
        let (start, end) = (q[0].max(0.0), q[q.len() - 1].max(0.0));
        let wrapped: Vec<[f64; 1]> = q.iter().map(|&v| [v]).collect();
        let rhs: Vec<f64> = self
            .interior_rhs(&wrapped, [start], [end])
            .into_iter()
            .map(|r| r[0])
            .collect();
        let inner =
            nonnegative_least_squares(&self.interior, &rhs).map_err(|e| shift_column(e, 1))?;
        Ok(std::iter::once(start)
            .chain(inner)
            .chain(std::iter::once(end))
            .collect())
    }

    /// The curve values `Σᵢ Nᵢ,ₚ(ūₖ)·Pᵢ` at every parameter.
    pub(crate) fn values<const R: usize>(&self, control: &[[f64; R]]) -> Vec<[f64; R]> {
        curve_values(&self.rows, control)
    }
}

/// For each parameter, the index of the first control point that counts
/// there and the `p + 1` basis values `N_{first,p} … N_{first+p,p}`.
pub(crate) fn basis_rows(params: &[f64], knots: &KnotVector) -> Vec<(usize, Vec<f64>)> {
    let p = knots.degree();
    params
        .iter()
        .map(|&t| {
            let span = knots.find_span(t);
            let mut values = vec![0.0; p + 1];
            basis_functions(knots.as_slice(), p, span, t, &mut values);
            (span - p, values)
        })
        .collect()
}

/// The curve values `Σᵢ Nᵢ,ₚ(ūₖ)·Pᵢ` at the parameters of `rows`.
pub(crate) fn curve_values<const R: usize>(
    rows: &[(usize, Vec<f64>)],
    control: &[[f64; R]],
) -> Vec<[f64; R]> {
    rows.iter()
        .map(|(first, basis)| {
            let mut out = [0.0; R];
            for (b, p) in basis.iter().zip(&control[*first..]) {
                for (o, x) in out.iter_mut().zip(p) {
                    *o += b * x;
                }
            }
            out
        })
        .collect()
}

/// Renumbers the column of a [`Error::SingularFit`] from the interior system
/// to the control points.
fn shift_column(e: Error, by: usize) -> Error {
    match e {
        Error::SingularFit { column } => Error::SingularFit {
            column: column + by,
        },
        other => other,
    }
}
