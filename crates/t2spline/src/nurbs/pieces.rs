//! Pieces of the parameter domain on which a rational curve is as tame as a
//! polynomial one: knot spans, cut further where the weights vary by orders
//! of magnitude. Quadrature over such pieces sees every feature of the curve
//! (arc length, the root mean square distance).
//!
//! With weights spread over orders of magnitude, a rational curve moves from
//! near one heavy control point to the next within a narrow window of
//! parameters, where `wⱼNⱼ(t)` of the two control points cross. Inside a knot
//! span the window can be far narrower than the span (`10⁻⁸` of it for
//! weights from `10⁻¹²` to `10¹²` at degree 3, `10⁻²⁴` at degree 1), and a
//! quadrature rule whose nodes all miss it sees a curve that stands still:
//! the arc length came out up to a fifth short. The window shows in the
//! denominator `w(t) = Σ wⱼNⱼ(t)`. On a piece `[lo, hi]` of a span the curve
//! is a rational Bézier curve whose homogeneous control points `(wₖPₖ, wₖ)`
//! come from knot insertion (`lo` and `hi` to multiplicity `p`, The NURBS
//! Book §5.3), and its weights `wₖ` are the Bernstein coefficients of `w`:
//!
//! ```text
//! w(t) = Σₖ wₖ·Bₖ,ₚ(s),   s = (t − lo)/(hi − lo),   min wₖ ≤ w(t) ≤ max wₖ
//! ```
//! Where `max wₖ / min wₖ ≤ 4` the piece behaves like a curve with weights
//! within a factor 4: `w` has no zero near the piece, `C = A/w` is analytic in
//! a neighbourhood of fixed relative size, and Gauss–Kronrod rules converge on
//! it as on a polynomial curve. Pieces above the ratio are halved (de
//! Casteljau at `s = 1/2`, convex combinations only) until they are below it;
//! halving brings the ratio towards 1 because a polynomial is nearly constant
//! on a short enough piece. The number of pieces grows with the logarithm of
//! the weights' spread, and spans whose weights stay within a factor 4 are
//! kept whole.
//!
//! A halved piece keeps its Bézier control points: in its own variable `s` it
//! can be sampled however narrow it is in `t`, where parameters a few units
//! in the last place apart could not show the curve's motion.

use crate::nurbs::homogeneous::Row;
use crate::nurbs::split::segment;
use crate::nurbs::KnotVector;

/// The largest ratio of the weights on a piece.
const RATIO: f64 = 4.0;
/// Halvings allowed below one knot span: enough for the widest ratio of
/// weights the library accepts (10³⁰⁰) at degree 1, where the window is
/// 10⁻³⁰⁰ of the span.
const MAX_DEPTH: u32 = 1100;
/// Halvings allowed in all: this many plus [`HALVINGS_PER_SPAN`] per knot
/// span, so that no input can ask for unbounded work.
const HALVINGS: usize = 10_000;
/// See [`HALVINGS`].
const HALVINGS_PER_SPAN: usize = 256;
/// A knot span narrower than this fraction of its position is extracted in
/// Bézier form: sampled in `t`, quadrature nodes would be rounded by a
/// noticeable fraction of the span.
const NARROW: f64 = 1.0 / (1u64 << 24) as f64;

/// A piece `[lo, hi]` of the knot span `span`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Piece {
    /// The knot span (`U[span] < U[span+1]`), for evaluation on it in `t`.
    pub(crate) span: usize,
    /// Start.
    pub(crate) lo: f64,
    /// End.
    pub(crate) hi: f64,
    /// Whether the weights lie within a factor 4 on the piece; `false` only
    /// where halving stopped at its bounds ([`MAX_DEPTH`] halvings below a
    /// span, or the bound on all halvings).
    pub(crate) tame: bool,
    /// The piece as a rational Bézier curve in `s ∈ [0, 1]`: its `p + 1`
    /// homogeneous control points, weight last. `None` for a knot span kept
    /// whole, to be evaluated in `t`.
    pub(crate) bezier: Option<Vec<Row>>,
}

/// The pieces of `[a, b]` (within the domain, `a < b`), in increasing order,
/// each in one knot span: the spans where the weights stay within a factor 4
/// and the span is not narrow, and otherwise halves of the span's Bézier
/// form until their weights do. `row(i)` is the homogeneous control point
/// `i`, weight last, of any width (`[wᵢ]` alone when only the pieces are
/// wanted); it is asked for only where a span is cut.
///
/// A halved piece's range in `t` is rounded (two halves of a piece a few
/// units in the last place wide may have an empty range); its Bézier form is
/// not.
pub(crate) fn tame_pieces(
    knots: &KnotVector,
    weights: &[f64],
    row: impl Fn(usize) -> Row,
    a: f64,
    b: f64,
) -> Vec<Piece> {
    let p = knots.degree();
    let u = knots.as_slice();
    let mut out = Vec::new();
    let mut stack = Vec::new();
    let mut budget = HALVINGS.saturating_add(HALVINGS_PER_SPAN.saturating_mul(knots.count()));
    for (span, [lo, hi]) in knots.spans() {
        let (lo, hi) = (lo.max(a), hi.min(b));
        if lo >= hi {
            continue;
        }
        let active = &weights[span - p..=span];
        let (least, most) = active
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(l, m), &w| (l.min(w), m.max(w)));
        let narrow = hi - lo < NARROW * lo.abs().max(hi.abs());
        if most <= RATIO * least && !narrow {
            out.push(Piece {
                span,
                lo,
                hi,
                tame: true,
                bezier: None,
            });
            continue;
        }
        // The span alone, as a curve with p + 1 control points, cut to
        // [lo, hi]: a rational Bézier curve.
        let local = KnotVector::from_parts_unchecked(u[span - p..=span + p + 1].to_vec(), p);
        let rows: Vec<Row> = (span - p..=span).map(&row).collect();
        // lo < hi lie in the span, the local curve's domain: segment cannot fail.
        #[allow(clippy::expect_used)]
        let (_, bezier) = segment(&local, &rows, lo, hi)
            .expect("lo < hi lie in the span, the domain of the local curve");
        // Depth first, the right half pushed first: pieces come out in order.
        stack.push((lo, hi, bezier, 0));
        while let Some((lo, hi, bezier, depth)) = stack.pop() {
            let tame = ratio(&bezier) <= RATIO;
            if tame || depth >= MAX_DEPTH || budget == 0 {
                out.push(Piece {
                    span,
                    lo,
                    hi,
                    tame,
                    bezier: Some(bezier),
                });
                continue;
            }
            budget -= 1;
            let mid = (lo + (hi - lo) / 2.0).clamp(lo, hi);
            let (left, right) = halve(&bezier);
            stack.push((mid, hi, right, depth + 1));
            stack.push((lo, mid, left, depth + 1));
        }
    }
    out
}

/// `max / min` of the weights (the last entries) of positive rows.
fn ratio(rows: &[Row]) -> f64 {
    let (lo, hi) = rows.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), r| {
        let w = r[r.len() - 1];
        (lo.min(w), hi.max(w))
    });
    hi / lo
}

/// The Bézier control points of both halves (de Casteljau at `s = 1/2`).
fn halve(rows: &[Row]) -> (Vec<Row>, Vec<Row>) {
    let n = rows.len();
    let mut work = rows.to_vec();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![Vec::new(); n];
    for level in 0..n {
        left.push(work[0].clone());
        right[n - 1 - level] = work[n - 1 - level].clone();
        for i in 0..n - 1 - level {
            let next = std::mem::take(&mut work[i + 1]);
            for (x, y) in work[i].iter_mut().zip(&next) {
                *x = (*x + y) / 2.0;
            }
            work[i + 1] = next;
        }
    }
    (left, right)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::basis::basis_functions;

    /// `Σₖ bₖ·Bₖ,ₚ(s)` for the weights `bₖ` of Bézier rows.
    fn bernstein_value(rows: &[Row], s: f64) -> f64 {
        let p = rows.len() - 1;
        let binomial = |k: usize| crate::nurbs::derivatives::binomial(p, k);
        rows.iter()
            .enumerate()
            .map(|(k, r)| {
                r[r.len() - 1] * binomial(k) * s.powi(k as i32) * (1.0 - s).powi((p - k) as i32)
            })
            .sum()
    }

    /// The pieces for the weights `w` alone.
    fn pieces(u: &KnotVector, w: &[f64], a: f64, b: f64) -> Vec<Piece> {
        tame_pieces(u, w, |i| vec![w[i]], a, b)
    }

    #[test]
    fn bezier_weights_reproduce_the_denominator() {
        let u = KnotVector::try_new(
            vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0],
            3,
            7,
        )
        .unwrap();
        let w = [1.0, 4000.0, 0.3, 2.0, 0.5, 7e3, 1.5];
        let pieces = pieces(&u, &w, 0.05, 0.95);
        assert!(pieces.len() > 3, "{pieces:?}");
        for piece in &pieces {
            let Some(bezier) = &piece.bezier else {
                continue;
            };
            for s in [0.0, 0.25, 0.6, 1.0] {
                let t = piece.lo + s * (piece.hi - piece.lo);
                let mut n = [0.0; 4];
                basis_functions(u.as_slice(), 3, piece.span, t, &mut n);
                let direct: f64 = n.iter().zip(&w[piece.span - 3..]).map(|(n, w)| n * w).sum();
                let got = bernstein_value(bezier, s);
                assert!(
                    (got - direct).abs() < 1e-12 * direct,
                    "{piece:?} {s}: {got} {direct}"
                );
            }
        }
    }

    #[test]
    fn tame_weights_keep_the_knot_spans() {
        let u = KnotVector::clamped_uniform(2, 5).unwrap();
        let pieces = pieces(&u, &[1.0, 2.0, 3.0, 1.0, 0.9], 0.1, 1.0);
        assert!(pieces.iter().all(|p| p.tame && p.bezier.is_none()));
        let spans: Vec<[f64; 2]> = pieces.iter().map(|p| [p.lo, p.hi]).collect();
        assert_eq!(
            spans,
            [[0.1, 1.0 / 3.0], [1.0 / 3.0, 2.0 / 3.0], [2.0 / 3.0, 1.0]]
        );
    }

    #[test]
    fn extreme_weights_are_cut_until_tame() {
        let u = KnotVector::clamped_uniform(3, 6).unwrap();
        let w = [1.0, 1e12, 1e-12, 1e6, 1e-6, 1.0];
        let pieces = pieces(&u, &w, 0.0, 1.0);
        assert!(pieces.len() > 20, "{}", pieces.len());
        assert!(pieces.iter().all(|p| p.tame));
        assert!(pieces
            .windows(2)
            .all(|p| p[0].hi == p[1].lo && p[0].span <= p[1].span));
        assert!(
            pieces.iter().all(|p| p.lo < p.hi),
            "pieces of one unit in the last place"
        );
        assert_eq!((pieces[0].lo, pieces[pieces.len() - 1].hi), (0.0, 1.0));
        for piece in &pieces {
            if let Some(bezier) = &piece.bezier {
                assert!(ratio(bezier) <= RATIO, "{piece:?}");
            }
        }
    }

    #[test]
    fn narrow_spans_come_in_bezier_form() {
        let u = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 0.5 + 1e-14, 1.0, 1.0, 1.0], 2, 5)
            .unwrap();
        let pieces = pieces(&u, &[1.0; 5], 0.0, 1.0);
        let forms: Vec<bool> = pieces.iter().map(|p| p.bezier.is_some()).collect();
        assert_eq!(forms, [false, true, false]);
    }

    #[test]
    fn a_window_below_the_parameters_resolution_is_cut_in_bezier_form() {
        // Degree 1, weights 1e-12 and 1e12 on the span [0.1, 0.2]: the curve
        // crosses within 1e-24·0.1 of t = 0.1, below the spacing of floats
        // there (1.4e-17). The halves keep going in Bézier form.
        let u = KnotVector::try_new(vec![0.0, 0.0, 0.1, 0.2, 1.0, 1.0], 1, 4).unwrap();
        let pieces = pieces(&u, &[1.0, 1e-12, 1e12, 1.0], 0.0, 1.0);
        assert!(pieces.iter().all(|p| p.tame));
        let empty = pieces.iter().filter(|p| p.lo == p.hi).count();
        assert!(empty > 10, "{pieces:?}");
        // The Bézier pieces of the span join up: each ends where the next starts.
        let span: Vec<&Piece> = pieces.iter().filter(|p| p.span == 2).collect();
        for w in span.windows(2) {
            let (a, b) = (w[0].bezier.as_ref().unwrap(), w[1].bezier.as_ref().unwrap());
            assert_eq!(a[a.len() - 1], b[0]);
        }
    }
}
