//! Derivatives at a parameter and the tangent direction (docs/method.md §11).
//!
//! With crisp weights and knots, `C⁽ᵏ⁾(t) = Σᵢ cᵢ·Pᵢ` with the signed
//! coefficients `cᵢ = Rᵢ⁽ᵏ⁾(t)`, a linear function of the control points
//! that is separate in each coordinate; over the box of cut control points
//! its extremes are taken coordinate by coordinate at the ends the signs
//! choose:
//!
//! ```text
//! min = Σ_{cᵢ > 0} cᵢ·lᵢ + Σ_{cᵢ < 0} cᵢ·rᵢ,   max = Σ_{cᵢ > 0} cᵢ·rᵢ + Σ_{cᵢ < 0} cᵢ·lᵢ
//! ```
//! This is exact: each end is the derivative of one admissible curve. It is
//! not the derivative of a layer curve, which puts every point at its left
//! (or right) end whatever the sign of its coefficient.
//!
//! The tangent direction of a plane curve is the angle of `C'(t)`. The
//! derivative box `D = [a₁, b₁] × [a₂, b₂]` is exactly the set of first
//! derivatives; where it holds the origin some admissible curve stands still
//! and the direction is undefined. Elsewhere `D` lies in an open half-plane
//! through the origin, its angles form an interval shorter than π, and the
//! extremes are at corners (the angle is monotone along each side).

use crate::measure::bracket::Bracket;
use crate::measure::cut_box::CutBox;

/// The range of a linear function `Σⱼ coefficients[j]·x_{first+j, c}` of
/// coordinate `c` over the box.
pub(crate) fn linear_range(cut: &CutBox, first: usize, coefficients: &[f64], c: usize) -> [f64; 2] {
    let d = cut.dim;
    let (mut lo, mut hi) = (0.0, 0.0);
    for (j, &a) in coefficients.iter().enumerate() {
        let v = (first + j) * d + c;
        let (l, r) = (a * cut.lo[v], a * cut.hi[v]);
        lo += l.min(r);
        hi += l.max(r);
    }
    [lo, hi]
}

/// The derivative box: per coordinate `[min, max]` of `Σⱼ cⱼ·P_{first+j}`.
pub(crate) fn derivative_box(cut: &CutBox, first: usize, coefficients: &[f64]) -> Vec<[f64; 2]> {
    (0..cut.dim)
        .map(|c| linear_range(cut, first, coefficients, c))
        .collect()
}

/// Whether a box of vectors holds the origin.
pub(crate) fn holds_origin(bx: &[[f64; 2]]) -> bool {
    bx.iter().all(|&[lo, hi]| lo <= 0.0 && hi >= 0.0)
}

/// The interval of the angles (radians) of the vectors of a plane box that
/// does not hold the origin; `None` if it does. `min` lies in `(−π, π]`;
/// `max − min < π`, so `max` may pass π (an interval across the negative x
/// axis).
pub(crate) fn angle_range(bx: &[[f64; 2]]) -> Option<Bracket> {
    if bx.len() != 2 || holds_origin(bx) {
        return None;
    }
    let [[x0, x1], [y0, y1]] = [bx[0], bx[1]];
    // The centre is inside the box, so not the origin: angles are measured
    // from its direction, where no corner is more than π/2 … π away.
    let centre = ((y0 + y1) / 2.0).atan2((x0 + x1) / 2.0);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (x, y) in [(x0, y0), (x0, y1), (x1, y0), (x1, y1)] {
        let mut a = y.atan2(x) - centre;
        if a > std::f64::consts::PI {
            a -= std::f64::consts::TAU;
        } else if a < -std::f64::consts::PI {
            a += std::f64::consts::TAU;
        }
        lo = lo.min(a);
        hi = hi.max(a);
    }
    let (mut min, mut max) = (centre + lo, centre + hi);
    if min <= -std::f64::consts::PI {
        min += std::f64::consts::TAU;
        max += std::f64::consts::TAU;
    } else if min > std::f64::consts::PI {
        min -= std::f64::consts::TAU;
        max -= std::f64::consts::TAU;
    }
    Some(Bracket {
        min,
        max,
        exact: true,
        gap: 0.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_of_boxes() {
        let a = angle_range(&[[1.0, 2.0], [-1.0, 1.0]]).unwrap();
        assert!((a.min + std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert!((a.max - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        // Across the negative x axis: from 3π/4 to 5π/4.
        let b = angle_range(&[[-2.0, -1.0], [-1.0, 1.0]]).unwrap();
        assert!((b.min - 0.75 * std::f64::consts::PI).abs() < 1e-15);
        assert!((b.max - 1.25 * std::f64::consts::PI).abs() < 1e-15);
        assert!(angle_range(&[[-1.0, 1.0], [0.0, 1.0]]).is_none());
    }
}
