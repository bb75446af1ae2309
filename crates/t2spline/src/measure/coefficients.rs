//! The rational basis functions and their derivatives at a parameter: the
//! signed coefficients that make every derivative of the curve a linear
//! function of its control points (weights and knots crisp).
//!
//! With `W = Σ wᵢNᵢ` and `Rᵢ = wᵢNᵢ/W`, Leibniz's rule on `W·Rᵢ = wᵢNᵢ`
//! (The NURBS Book, Eq. 4.8 applied to each basis function) gives
//!
//! ```text
//! Rᵢ⁽ᵏ⁾ = ( wᵢNᵢ⁽ᵏ⁾ − Σⱼ₌₁ᵏ C(k, j)·W⁽ʲ⁾·Rᵢ⁽ᵏ⁻ʲ⁾ ) / W
//! C⁽ᵏ⁾(t) = Σᵢ Rᵢ⁽ᵏ⁾(t)·Pᵢ
//! ```
//! with the basis derivatives `Nᵢ⁽ᵏ⁾` of The NURBS Book A2.3.

use crate::nurbs::derivatives::{basis_derivatives, binomial};
use crate::nurbs::KnotVector;

/// `R⁽ʲ⁾` of the `p + 1` control points that count on the span `span` at
/// `t`, for `j = 0 ..= order`: `out[j][r]` belongs to control point
/// `span − p + r`. At an interior knot the span to its right (one-sided
/// derivatives where the curve is not smooth), as `NurbsCurve::derivatives`.
pub(crate) fn rational_derivatives(
    knots: &KnotVector,
    weights: &[f64],
    span: usize,
    t: f64,
    order: usize,
) -> Vec<Vec<f64>> {
    let p = knots.degree();
    let first = span - p;
    let n = basis_derivatives(knots.as_slice(), p, span, t, order.min(p));
    let w = &weights[first..=span];
    // W⁽ʲ⁾ = Σ wᵢ Nᵢ⁽ʲ⁾ (zero above the degree).
    let big_w: Vec<f64> = (0..=order)
        .map(|j| {
            n.get(j)
                .map_or(0.0, |row| row.iter().zip(w).map(|(a, b)| a * b).sum())
        })
        .collect();
    let mut r: Vec<Vec<f64>> = Vec::with_capacity(order + 1);
    for k in 0..=order {
        let row = (0..=p)
            .map(|i| {
                let mut v = n.get(k).map_or(0.0, |row| w[i] * row[i]);
                for j in 1..=k {
                    v -= binomial(k, j) * big_w[j] * r[k - j][i];
                }
                v / big_w[0]
            })
            .collect();
        r.push(row);
    }
    r
}

/// The first control point that counts at `t` and `R⁽ʲ⁾` there
/// ([`rational_derivatives`] on the span of `t`).
pub(crate) fn at(
    knots: &KnotVector,
    weights: &[f64],
    t: f64,
    order: usize,
) -> (usize, Vec<Vec<f64>>) {
    let span = knots.find_span(t);
    (
        span - knots.degree(),
        rational_derivatives(knots, weights, span, t, order),
    )
}
