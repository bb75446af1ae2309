//! The fallback of the sampling engine for spans whose power form is
//! ill-conditioned ([`Span::direct`]): the rational basis evaluated from the
//! knots at every parameter (The NURBS Book, A2.2 and Eq. 4.2), as
//! [`NurbsCurve::eval`](crate::NurbsCurve::eval) does.

use crate::nurbs::basis::basis_functions;
use crate::sampling::power_form::Span;

/// What the direct evaluation needs: the knots, the weights and every
/// channel's control values.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Direct {
    knots: Vec<f64>,
    degree: usize,
    weights: Vec<f64>,
    /// `values[c]`: channel `c`'s value at every control point.
    values: Vec<Vec<f64>>,
}

impl Direct {
    pub(crate) fn new<C: AsRef<[f64]>>(
        knots: &[f64],
        degree: usize,
        weights: &[f64],
        channels: &[C],
    ) -> Self {
        Direct {
            knots: knots.to_vec(),
            degree,
            weights: weights.to_vec(),
            values: channels.iter().map(|c| c.as_ref().to_vec()).collect(),
        }
    }

    /// Evaluates the parameters `t`, all in `span`, into `out[..][at ..]`:
    ///
    /// ```text
    /// Rⱼ(t) = wⱼ Nⱼ,ₚ(t) / Σₗ wₗ Nₗ,ₚ(t),   Cᶜ(t) = Σⱼ Rⱼ(t) vᶜⱼ
    /// ```
    /// The rational basis `Rⱼ` lies in `[0, 1]`, so no sum here cancels
    /// beyond what the control values themselves do.
    pub(crate) fn evaluate(&self, span: &Span, t: &[f64], out: &mut [&mut [f64]], at: usize) {
        let order = self.degree + 1;
        let index = span.first + self.degree;
        let weights = &self.weights[span.first..span.first + order];
        let mut basis = vec![0.0; order];
        for (i, &t) in t.iter().enumerate() {
            basis_functions(&self.knots, self.degree, index, t, &mut basis);
            for (n, w) in basis.iter_mut().zip(weights) {
                *n *= w;
            }
            let denominator: f64 = basis.iter().sum();
            for n in &mut basis {
                *n /= denominator;
            }
            for (values, o) in self.values.iter().zip(out.iter_mut()) {
                let v = &values[span.first..span.first + order];
                o[at + i] = basis.iter().zip(v).map(|(r, v)| r * v).sum();
            }
        }
    }
}
