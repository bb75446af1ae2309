//! Pieces of the parameter domain on which a rational curve is as tame as a
//! polynomial one: knot spans, cut further where the weights vary by orders
//! of magnitude. Quadrature over such pieces sees every feature of the curve
//! (arc length, the root mean square distance).
//!
//! With weights spread over orders of magnitude, a rational curve moves from
//! near one heavy control point to the next within a narrow window of
//! parameters, where `wⱼNⱼ(t)` of the two control points cross. Inside a knot
//! span the window can be far narrower than the span (`10⁻⁸` of it for
//! weights from `10⁻¹²` to `10¹²` at degree 3), and a quadrature rule whose
//! nodes all miss it sees a curve that stands still: the arc length came out
//! a fifth short. The window shows in the denominator `w(t) = Σ wⱼNⱼ(t)`: on
//! a piece `[lo, hi]` of a span, `w` is a polynomial of degree `p` with
//! Bernstein coefficients `b₀ … bₚ`,
//!
//! ```text
//! w(t) = Σₖ bₖ·Bₖ,ₚ(s),   s = (t − lo)/(hi − lo),   bₖ = blossom of w at (lo, …, lo, hi, …, hi)   (k times hi)
//! ```
//! all positive, and `min bₖ ≤ w ≤ max bₖ` on the piece. Where
//! `max bₖ / min bₖ ≤ 4` the piece behaves like a curve with weights within a
//! factor 4: `w` has no zero near the piece, `C = A/w` is analytic in a
//! neighbourhood of fixed relative size, and Gauss–Kronrod rules converge on
//! it as on a polynomial curve. Pieces above the ratio are halved
//! (de Casteljau on the coefficients, convex combinations only) until they
//! are below it; halving brings the ratio towards 1 because a polynomial is
//! nearly constant on a short enough piece. The number of pieces grows with
//! the logarithm of the weights' spread, and curves whose weights stay
//! within a factor 4 on each span keep their spans as they are.

use crate::nurbs::KnotVector;

/// The largest ratio of the denominator's Bernstein coefficients on a piece.
const RATIO: f64 = 4.0;
/// Halvings allowed below one knot span.
const MAX_DEPTH: u32 = 64;

/// A piece `[lo, hi]` of the knot span `span`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SpanPiece {
    /// The knot span (`U[span] < U[span+1]`), for evaluation on it.
    pub(crate) span: usize,
    /// Start.
    pub(crate) lo: f64,
    /// End.
    pub(crate) hi: f64,
}

/// The pieces of `[a, b]` (within the domain, `a < b`) on which the
/// denominator `Σ wⱼNⱼ` varies by at most a factor 4 in Bernstein form, in
/// increasing order; each lies in one knot span.
pub(crate) fn tame_pieces(knots: &KnotVector, weights: &[f64], a: f64, b: f64) -> Vec<SpanPiece> {
    let p = knots.degree();
    let mut out = Vec::new();
    let mut stack = Vec::new();
    for (span, [lo, hi]) in knots.spans() {
        let (lo, hi) = (lo.max(a), hi.min(b));
        if lo >= hi {
            continue;
        }
        let active = &weights[span - p..=span];
        if ratio(active) <= RATIO {
            out.push(SpanPiece { span, lo, hi });
            continue;
        }
        // Depth first, the right half pushed first: pieces come out in order.
        stack.push((lo, hi, denominator_bernstein(knots, weights, span, lo, hi), 0));
        while let Some((lo, hi, coefficients, depth)) = stack.pop() {
            let mid = lo + (hi - lo) / 2.0;
            if ratio(&coefficients) <= RATIO || depth >= MAX_DEPTH || !(lo < mid && mid < hi) {
                out.push(SpanPiece { span, lo, hi });
                continue;
            }
            let (left, right) = halve(&coefficients);
            stack.push((mid, hi, right, depth + 1));
            stack.push((lo, mid, left, depth + 1));
        }
    }
    out
}

/// `max / min` of positive values.
fn ratio(values: &[f64]) -> f64 {
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    hi / lo
}

/// The Bernstein coefficients on `[lo, hi]` (inside the knot span `span`) of
/// `w(t) = Σ wⱼNⱼ,ₚ(t)`: blossoms evaluated by de Boor's algorithm with the
/// argument `lo` on the first `p − k` levels and `hi` on the others (The
/// NURBS Book §5.2; Ramshaw 1989). Both arguments lie in the span, so every
/// step is a convex combination of positive numbers.
fn denominator_bernstein(
    knots: &KnotVector,
    weights: &[f64],
    span: usize,
    lo: f64,
    hi: f64,
) -> Vec<f64> {
    let u = knots.as_slice();
    let p = knots.degree();
    let mut d = vec![0.0; p + 1];
    (0..=p)
        .map(|k| {
            d.copy_from_slice(&weights[span - p..=span]);
            for r in 1..=p {
                let x = if r <= p - k { lo } else { hi };
                for i in (r..=p).rev() {
                    let j = span - p + i;
                    let alpha = ((x - u[j]) / (u[j + p + 1 - r] - u[j])).clamp(0.0, 1.0);
                    d[i] = (1.0 - alpha) * d[i - 1] + alpha * d[i];
                }
            }
            d[p]
        })
        .collect()
}

/// The Bernstein coefficients of both halves (de Casteljau at `s = 1/2`).
fn halve(c: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let mut work = c.to_vec();
    let n = c.len();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![0.0; n];
    for level in 0..n {
        left.push(work[0]);
        right[n - 1 - level] = work[n - 1 - level];
        for i in 0..n - 1 - level {
            work[i] = (work[i] + work[i + 1]) / 2.0;
        }
    }
    (left, right)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::basis::basis_functions;

    /// `Σₖ bₖ·Bₖ,ₚ(s)`.
    fn bernstein_value(b: &[f64], s: f64) -> f64 {
        let p = b.len() - 1;
        let binomial = |k: usize| crate::nurbs::derivatives::binomial(p, k);
        b.iter()
            .enumerate()
            .map(|(k, bk)| bk * binomial(k) * s.powi(k as i32) * (1.0 - s).powi((p - k) as i32))
            .sum()
    }

    #[test]
    fn bernstein_coefficients_reproduce_the_denominator() {
        let u = KnotVector::try_new(
            vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0],
            3,
            7,
        )
        .unwrap();
        let w = [1.0, 4.0, 0.3, 2.0, 0.5, 7.0, 1.5];
        for (span, [a, b]) in u.spans() {
            let (lo, hi) = (a + 0.1 * (b - a), a + 0.8 * (b - a));
            let c = denominator_bernstein(&u, &w, span, lo, hi);
            for s in [0.0, 0.25, 0.6, 1.0] {
                let t = lo + s * (hi - lo);
                let mut n = [0.0; 4];
                basis_functions(u.as_slice(), 3, span, t, &mut n);
                let direct: f64 = n.iter().zip(&w[span - 3..]).map(|(n, w)| n * w).sum();
                assert!((bernstein_value(&c, s) - direct).abs() < 1e-14, "{span} {s}");
            }
            // The halves reproduce it too.
            let (left, right) = halve(&c);
            for s in [0.0, 0.3, 1.0] {
                let (l, r) = (bernstein_value(&left, s), bernstein_value(&right, s));
                assert!((l - bernstein_value(&c, s / 2.0)).abs() < 1e-14);
                assert!((r - bernstein_value(&c, 0.5 + s / 2.0)).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn tame_weights_keep_the_knot_spans() {
        let u = KnotVector::clamped_uniform(2, 5).unwrap();
        let pieces = tame_pieces(&u, &[1.0, 2.0, 3.0, 1.0, 0.9], 0.1, 1.0);
        let spans: Vec<[f64; 2]> = pieces.iter().map(|p| [p.lo, p.hi]).collect();
        assert_eq!(spans, [[0.1, 1.0 / 3.0], [1.0 / 3.0, 2.0 / 3.0], [2.0 / 3.0, 1.0]]);
    }

    #[test]
    fn extreme_weights_are_cut_until_tame() {
        let u = KnotVector::clamped_uniform(3, 6).unwrap();
        let w = [1.0, 1e12, 1e-12, 1e6, 1e-6, 1.0];
        let pieces = tame_pieces(&u, &w, 0.0, 1.0);
        assert!(pieces.len() > 20, "{}", pieces.len());
        assert!(pieces.windows(2).all(|p| p[0].hi == p[1].lo && p[0].span <= p[1].span));
        assert_eq!((pieces[0].lo, pieces[pieces.len() - 1].hi), (0.0, 1.0));
        for piece in &pieces {
            let c = denominator_bernstein(&u, &w, piece.span, piece.lo, piece.hi);
            assert!(ratio(&c) <= RATIO * (1.0 + 1e-12), "{piece:?}: {c:?}");
        }
    }
}
