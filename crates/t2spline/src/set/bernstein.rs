//! Bernstein (Bézier) forms of a B-spline on one knot span, and their
//! restriction to a sub-interval: the bounds of the certified grade
//! (docs/set.md, "Certified grades").
//!
//! On the span `[a, b] = [U[s], U[s+1]]` every B-spline function
//! `Σ cᵢ Nᵢ,ₚ(t)` is one polynomial of degree `p`, written in the Bernstein
//! basis of `[a, b]` as `Σₖ βₖ Bₖ,ₚ((t − a)/(b − a))`. Its Bézier coefficients
//! are blossom values (Ramshaw; The NURBS Book §5.6):
//!
//! ```text
//! βₖ = f[a, …, a, b, …, b]      (p − k times a, k times b)
//! ```
//! computed by de Boor's algorithm with the argument `a` at its first `p − k`
//! levels and `b` at the rest. Every step is a convex combination, so the
//! matrix `M` with `βₖ = Σᵢ Mₖᵢ cᵢ` has non-negative entries. The Bernstein
//! functions are non-negative and sum to 1 (the convex hull property), and
//! the first and last coefficients are the values at the ends.

/// The `(p + 1) × (p + 1)` matrix, row `k` for Bézier coefficient `k`,
/// column `i` for the B-spline function `N_{s−p+i}` of the non-empty span
/// `span` of the knot vector `knots` of degree `p`.
pub(crate) fn bezier_matrix(knots: &[f64], p: usize, span: usize) -> Vec<f64> {
    let n = p + 1;
    let (a, b) = (knots[span], knots[span + 1]);
    let mut m = vec![0.0; n * n];
    let mut d = vec![0.0; n];
    for k in 0..n {
        for i in 0..n {
            d.fill(0.0);
            d[i] = 1.0;
            for r in 1..=p {
                let x = if r <= p - k { a } else { b };
                for j in (r..=p).rev() {
                    let g = span - p + j;
                    let den = knots[g + p + 1 - r] - knots[g];
                    // Non-empty span: every denominator of these levels is
                    // positive (it holds [a, b]).
                    let t = if den > 0.0 { (x - knots[g]) / den } else { 0.0 };
                    d[j] = (1.0 - t) * d[j - 1] + t * d[j];
                }
            }
            m[k * n + i] = d[p];
        }
    }
    m
}

/// Restricts the Bézier coefficients `c` (taken `c[0], c[stride], …`,
/// `count` of them) of a polynomial on `[0, 1]` to `[s0, s1]` in place, by
/// two de Casteljau subdivisions (at `s0`, keeping the right part; then at
/// the matching point of that part, keeping the left). Each step is a
/// convex combination, so non-negative coefficients stay non-negative.
pub(crate) fn restrict(c: &mut [f64], stride: usize, count: usize, [s0, s1]: [f64; 2]) {
    if s0 > 0.0 {
        for r in 1..count {
            for j in 0..count - r {
                c[j * stride] = (1.0 - s0) * c[j * stride] + s0 * c[(j + 1) * stride];
            }
        }
    }
    if s1 < 1.0 {
        let s = if s0 > 0.0 { (s1 - s0) / (1.0 - s0) } else { s1 };
        for r in 1..count {
            for j in (r..count).rev() {
                c[j * stride] = (1.0 - s) * c[(j - 1) * stride] + s * c[j * stride];
            }
        }
    }
}

/// The value at `t ∈ [0, 1]` of the polynomial with Bézier coefficients `c`
/// (degree `d = c.len() − 1`) by nested multiplication, with no buffer:
///
/// ```text
/// Σₖ C(d, k)·tᵏ·(1 − t)^(d−k)·cₖ = (…((c₀·s + C(d,1)·t·c₁)·s + C(d,2)·t²·c₂)·s …)·s + tᵈ·c_d,  s = 1 − t
/// ```
pub(crate) fn bernstein_value(c: &[f64], t: f64) -> f64 {
    let degree = c.len() - 1;
    if degree == 0 {
        return c[0];
    }
    let s = 1.0 - t;
    let (mut power, mut binomial) = (1.0, 1.0);
    let mut sum = c[0] * s;
    for (k, &ck) in c.iter().enumerate().take(degree).skip(1) {
        power *= t;
        binomial = binomial * (degree + 1 - k) as f64 / k as f64;
        sum = (sum + power * binomial * ck) * s;
    }
    sum + power * t * c[degree]
}

/// Splits the Bézier coefficients `left` (taken `left[0], left[stride], …`,
/// `count` of them) of a polynomial on `[0, 1]` at `1/2` by de Casteljau's
/// algorithm: `left` keeps those of `[0, 1/2]`, `right` (same layout) gets
/// those of `[1/2, 1]`, each rescaled to `[0, 1]`. Every step halves a sum,
/// so non-negative coefficients stay non-negative.
pub(crate) fn split_half(left: &mut [f64], right: &mut [f64], stride: usize, count: usize) {
    for j in 0..count {
        right[j * stride] = left[j * stride];
    }
    for r in 1..count {
        for j in 0..count - r {
            right[j * stride] = 0.5 * (right[j * stride] + right[(j + 1) * stride]);
        }
        left[r * stride] = right[0];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::basis::basis_functions;

    /// The Bézier form reproduces the B-spline functions on their span.
    #[test]
    fn bezier_matrix_reproduces_the_basis() {
        let knots = [0.0, 0.0, 0.0, 0.3, 0.45, 1.0, 1.0, 1.0];
        let p = 2;
        for span in 2..5 {
            let m = bezier_matrix(&knots, p, span);
            let (a, b) = (knots[span], knots[span + 1]);
            for step in 0..=10 {
                let s = f64::from(step) / 10.0;
                let t = a + s * (b - a);
                let mut n = [0.0; 3];
                basis_functions(&knots, p, span, t, &mut n);
                let bern = [(1.0 - s) * (1.0 - s), 2.0 * s * (1.0 - s), s * s];
                for (i, ni) in n.iter().enumerate() {
                    let v: f64 = (0..3).map(|k| m[k * 3 + i] * bern[k]).sum();
                    assert!(
                        (v - ni).abs() < 1e-14,
                        "span {span}, s {s}, i {i}: {v} vs {ni}"
                    );
                }
            }
        }
    }

    /// Restriction keeps the polynomial: its ends are the values at `s0`, `s1`.
    #[test]
    fn restriction_keeps_the_polynomial() {
        let c = [1.0, -2.0, 0.5, 3.0];
        let value = |s: f64| {
            let mut d = c;
            for r in 1..4 {
                for j in 0..4 - r {
                    d[j] = (1.0 - s) * d[j] + s * d[j + 1];
                }
            }
            d[0]
        };
        let mut r = c;
        restrict(&mut r, 1, 4, [0.2, 0.7]);
        assert!((r[0] - value(0.2)).abs() < 1e-14 && (r[3] - value(0.7)).abs() < 1e-14);
        let mut strided = [c[0], 9.0, c[1], 9.0, c[2], 9.0, c[3], 9.0];
        restrict(&mut strided, 2, 4, [0.2, 0.7]);
        assert_eq!([strided[0], strided[2], strided[4], strided[6]], r);
        assert_eq!(strided[1], 9.0);
    }

    /// Splitting at 1/2 gives the restrictions to both halves, strided too.
    #[test]
    fn split_half_gives_both_restrictions() {
        let c = [1.0, -2.0, 0.5, 3.0];
        let (mut l, mut r) = (c, c);
        restrict(&mut l, 1, 4, [0.0, 0.5]);
        restrict(&mut r, 1, 4, [0.5, 1.0]);
        let mut left = [c[0], 9.0, c[1], 9.0, c[2], 9.0, c[3], 9.0];
        let mut right = [0.0; 8];
        split_half(&mut left, &mut right, 2, 4);
        for k in 0..4 {
            assert!((left[2 * k] - l[k]).abs() < 1e-14, "left {k}");
            assert!((right[2 * k] - r[k]).abs() < 1e-14, "right {k}");
        }
        assert_eq!(left[1], 9.0);
    }

    /// The nested value agrees with de Casteljau's (the restriction's end).
    #[test]
    fn bernstein_value_is_de_casteljaus() {
        let c = [1.0, -2.0, 0.5, 3.0, -1.25];
        for step in 0..=8 {
            let t = f64::from(step) / 8.0;
            let mut r = c;
            restrict(&mut r, 1, 5, [t, 1.0]);
            assert!((bernstein_value(&c, t) - r[0]).abs() < 1e-14, "t {t}");
        }
        assert_eq!(bernstein_value(&[2.5], 0.3), 2.5);
    }
}
