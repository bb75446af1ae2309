//! The non-zero rational basis functions of a net at one parameter pair.

use crate::nurbs::basis::basis_functions;
use crate::nurbs::KnotVector;

/// The non-zero rational basis functions of a surface at `(u, v)`: the
/// `(p + 1)(q + 1)` values `Rᵢⱼ` for `i = first[0] …`, `j = first[1] …`,
/// row by row. Shared by every evaluator of a net (crisp and fuzzy).
#[derive(Clone, Debug)]
pub(crate) struct TensorBasis {
    first: [usize; 2],
    columns: usize,
    values: Vec<f64>,
}

impl TensorBasis {
    /// The rational basis at `(u, v)` in the domain (spans as
    /// [`KnotVector::find_span`]: from the right at an interior knot, the last
    /// non-empty span at the end).
    pub(crate) fn new(knots: &[KnotVector; 2], weights: &[f64], u: f64, v: f64) -> Self {
        let spans = [knots[0].find_span(u), knots[1].find_span(v)];
        Self::in_spans(knots, weights, spans, u, v)
    }

    /// The rational basis of the polynomial piece on the non-empty spans
    /// `[su, sv]` at `(u, v)` in (or on the border of) that span rectangle.
    pub(crate) fn in_spans(
        knots: &[KnotVector; 2],
        weights: &[f64],
        [su, sv]: [usize; 2],
        u: f64,
        v: f64,
    ) -> Self {
        let [ku, kv] = knots;
        let (p, q) = (ku.degree(), kv.degree());
        let nv = kv.count();
        let mut bu = vec![0.0; p + 1];
        let mut bv = vec![0.0; q + 1];
        basis_functions(ku.as_slice(), p, su, u, &mut bu);
        basis_functions(kv.as_slice(), q, sv, v, &mut bv);
        let first = [su - p, sv - q];
        let mut values = Vec::with_capacity((p + 1) * (q + 1));
        let mut denominator = 0.0;
        for (a, nu) in bu.iter().enumerate() {
            let row = &weights[(first[0] + a) * nv + first[1]..][..=q];
            for (mv, w) in bv.iter().zip(row) {
                let x = nu * mv * w;
                denominator += x;
                values.push(x);
            }
        }
        // As for curves: some NᵢMⱼ ≥ 1/((p + 1)(q + 1)) and every weight is at
        // least 1e-150, so the sum is positive and finite.
        for x in &mut values {
            *x /= denominator;
        }
        TensorBasis {
            first,
            columns: q + 1,
            values,
        }
    }

    /// Calls `f(k, Rᵢⱼ)` for every non-zero basis function, with `k = i·nv + j`
    /// the index of its control point in a net of `nv` columns.
    pub(crate) fn for_each(&self, nv: usize, mut f: impl FnMut(usize, f64)) {
        for (a, row) in self.values.chunks_exact(self.columns).enumerate() {
            let base = (self.first[0] + a) * nv + self.first[1];
            for (b, &r) in row.iter().enumerate() {
                f(base + b, r);
            }
        }
    }
}
