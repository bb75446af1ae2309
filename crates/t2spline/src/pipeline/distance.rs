//! The distance between the crisp and the defuzzified curve (docs/method.md §7).

use crate::brent::brent_min;
use crate::nurbs::pieces::{tame_pieces, Piece};
use crate::nurbs::span_eval::SpanEvaluator;
use crate::nurbs::{KnotVector, NurbsCurve};
use crate::quadrature::{integrate_pieces, Tolerance};
use crate::vector::euclidean_norm;

/// How far the defuzzified curve `D(t)` lies from the crisp curve `C(t)` at equal
/// parameters, over the whole domain `[a, b]` (docs/method.md §7):
///
/// ```text
/// d(t) = ‖D(t) − C(t)‖₂
/// max  = max over t ∈ [a, b] of d(t),        max_at = the t where it is reached
/// rms  = √( 1/(b − a) · ∫ₐᵇ d(t)² dt )
/// ```
/// Both curves share weights and knots, so `D − C` is itself a rational
/// B-spline whose control points are the differences `Dᵢ − Pᵢ`; `d` is its norm.
/// Neither figure depends on the job's `samples`. Both work on the knot spans,
/// cut where the weights vary by more than a factor 4 (where a rational curve
/// can move within a small part of a span; see ARCHITECTURE.md, "Tame pieces
/// for rational curves"):
///
/// - `max`: a scan of 32 steps per piece, each local maximum of the scan
///   refined by Brent's method until its bracket is 4·10⁻⁹ of the piece wide.
///   `d` is flat at a peak (`d(t*) − d(t) ≈ |d''|·δ²/2`), so the value is
///   exact to rounding, while `max_at` is known only as far as rounding lets
///   the values differ: to about √ε ≈ 10⁻⁸ of the piece. A larger distance
///   met by the rms quadrature counts too.
/// - `rms`: adaptive Gauss–Kronrod quadrature (7/15 points), to a relative
///   accuracy of 10⁻¹².
///
/// With symmetric spreads both are 0.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Distance {
    /// The largest distance.
    pub max: f64,
    /// A parameter where the largest distance is reached.
    pub max_at: f64,
    /// The root mean square distance over the domain.
    pub rms: f64,
}

/// Steps of the scan for the maximum, per knot span.
const SCAN_STEPS: usize = 32;
/// The width, relative to its piece, to which Brent's method narrows the
/// bracket of a peak: below about 10⁻⁸ rounding decides the comparisons
/// anyway, and the value is exact to rounding long before.
const REFINEMENT: f64 = 1e-9;
/// The relative accuracy aimed at for the mean square `rms²`: `rms` is then
/// accurate to half of it, within the promised 10⁻¹².
const MEAN_SQUARE_TARGET: f64 = 1e-13;
/// Bisections allowed for the mean square: this many plus
/// [`BISECTIONS_PER_PIECE`] per piece.
const BISECTIONS: usize = 1000;
/// See [`BISECTIONS`].
const BISECTIONS_PER_PIECE: usize = 64;

impl Distance {
    /// Measures the norm of `difference(t)` over its domain.
    ///
    /// The mean square is integrated in the variable `s = (t − a)/(b − a)`
    /// of the unit interval, as the integral of `(d(t)/scale)²` with `scale`
    /// the largest distance found: squaring a distance near 1e-170 directly
    /// would underflow, and dividing by `b − a` at the end would lose a
    /// domain narrower than about 1e-300. Every evaluation is on a chosen
    /// knot span, without allocation ([`SpanEvaluator`]).
    pub(crate) fn of_curve<const D: usize>(difference: &NurbsCurve<D>) -> Distance {
        let domain = difference.domain();
        let weights = difference.weights();
        let pieces = tame_pieces(
            difference.knots(),
            weights,
            |i| vec![weights[i]],
            domain.start,
            domain.end,
        );
        Distance::of_gap(&mut Gap::new(difference, None), &pieces)
    }

    /// Measures `‖a(t) − b(t)‖` over the domain of two curves with the same
    /// knots and weights of their own (fuzzy weights, docs/method.md §16),
    /// on the pieces where both curves' weights are tame.
    pub(crate) fn between<const D: usize>(a: &NurbsCurve<D>, b: &NurbsCurve<D>) -> Distance {
        let domain = a.domain();
        let pieces = |c: &NurbsCurve<D>| {
            let w = c.weights();
            tame_pieces(c.knots(), w, |i| vec![w[i]], domain.start, domain.end)
        };
        let pieces = common_pieces(a.knots(), &pieces(a), &pieces(b));
        Distance::of_gap(&mut Gap::new(a, Some(b)), &pieces)
    }

    /// The maximum and the rms of `gap` over its domain, on `pieces`.
    fn of_gap<const D: usize>(gap: &mut Gap<'_, D>, pieces: &[Piece]) -> Distance {
        let domain = gap.a.domain();
        gap.set_span(gap.a.knots().find_span(domain.start));
        let start = gap.at(domain.start);
        let mut max = (start, domain.start);
        let mut scan = Vec::with_capacity(SCAN_STEPS + 1);
        for &Piece {
            span, lo: a, hi: b, ..
        } in pieces
        {
            if a >= b {
                continue;
            }
            gap.set_span(span);
            let mut norm = |t: f64| gap.at(t);
            let step = (b - a) / SCAN_STEPS as f64;
            let tolerance = REFINEMENT * (b - a).max(f64::MIN_POSITIVE);
            scan.clear();
            scan.extend((0..=SCAN_STEPS).map(|j| {
                // `min`: in a span a few subnormal units wide the rounded step
                // can overshoot `b` (found by fuzzing).
                let t = if j == SCAN_STEPS {
                    b
                } else {
                    (a + step * j as f64).min(b)
                };
                (norm(t), t)
            }));
            for j in 0..=SCAN_STEPS {
                let (d, t) = scan[j];
                if d > max.0 {
                    max = (d, t);
                }
                // Every local maximum of the scan is refined, not only the
                // largest: a peak between scan points can beat a higher scan
                // point elsewhere.
                let rises = j == 0 || scan[j - 1].0 < d;
                let falls = j == SCAN_STEPS || scan[j + 1].0 <= d;
                if rises && falls {
                    let bracket = [scan[j.saturating_sub(1)].1, scan[(j + 1).min(SCAN_STEPS)].1];
                    let (d, t) = brent_min(|t| -norm(t), bracket, (t, -d), tolerance);
                    if -d > max.0 {
                        max = (-d, t);
                    }
                }
            }
        }
        let scale = max.0;
        let mut rms = 0.0;
        if scale > 0.0 {
            let (mean, seen) = mean_square(gap, pieces, scale);
            rms = scale * mean.sqrt();
            // The quadrature's nodes are distances too; one above the scan's
            // maximum (a peak narrower than the scan's steps) is the maximum.
            if seen.0 > max.0 {
                max = seen;
            }
        }
        Distance {
            max: max.0,
            max_at: max.1,
            rms,
        }
    }
}

/// The distance `d(t)` between a curve and a second curve with the same
/// knots (or `0`), evaluated on a chosen knot span without allocation.
struct Gap<'a, const D: usize> {
    a: &'a NurbsCurve<D>,
    b: Option<&'a NurbsCurve<D>>,
    eval_a: SpanEvaluator,
    eval_b: SpanEvaluator,
    span: usize,
}

impl<'a, const D: usize> Gap<'a, D> {
    fn new(a: &'a NurbsCurve<D>, b: Option<&'a NurbsCurve<D>>) -> Self {
        Gap {
            a,
            b,
            eval_a: SpanEvaluator::new(a.degree()),
            eval_b: SpanEvaluator::new(a.degree()),
            span: usize::MAX,
        }
    }

    /// Chooses the knot span of the parameters asked next.
    fn set_span(&mut self, span: usize) {
        if span != self.span {
            self.span = span;
            self.eval_a.set_span(self.a, span);
            if let Some(b) = self.b {
                self.eval_b.set_span(b, span);
            }
        }
    }

    /// `d(t)` for `t` in the chosen span, as the span evaluator gives the
    /// curves: at the knot that ends the span inside the domain, the value
    /// from the right. The span's polynomial gives the left limit there,
    /// which no parameter reaches where the curve jumps (a knot of full
    /// multiplicity) and which, with weights far apart, can differ from every
    /// value at parameters before it.
    fn at(&mut self, t: f64) -> f64 {
        let end = self.a.knots().as_slice()[self.span + 1];
        let from_right = t >= end && end < self.a.domain().end;
        let mut p = if from_right {
            self.a.eval_unchecked(t)
        } else {
            self.eval_a.point(self.a, t)
        };
        if let Some(b) = self.b {
            let q = if from_right {
                b.eval_unchecked(t)
            } else {
                self.eval_b.point(b, t)
            };
            for (x, y) in p.iter_mut().zip(q) {
                *x -= y;
            }
        }
        euclidean_norm(&p)
    }
}

/// The pieces of both lists cut at every end of either: each lies in one
/// knot span of `knots` and inside a piece of each list.
fn common_pieces(knots: &KnotVector, a: &[Piece], b: &[Piece]) -> Vec<Piece> {
    let mut cuts: Vec<f64> = a.iter().chain(b).flat_map(|p| [p.lo, p.hi]).collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    cuts.windows(2)
        .filter_map(|w| match *w {
            [lo, hi] if lo < hi => Some(Piece {
                span: knots.find_span(lo + (hi - lo) / 2.0),
                lo,
                hi,
                tame: true,
                bezier: None,
            }),
            _ => None,
        })
        .collect()
}

/// `1/(b − a) · ∫ₐᵇ (d(t)/scale)² dt`, integrated over `s ∈ [0, 1]` on the
/// tame pieces, and the largest distance met on the way with its parameter.
fn mean_square<const D: usize>(
    gap: &mut Gap<'_, D>,
    pieces: &[Piece],
    scale: f64,
) -> (f64, (f64, f64)) {
    let domain = gap.a.domain();
    let width = domain.end - domain.start;
    let to_s = |t: f64| ((t - domain.start) / width).clamp(0.0, 1.0);
    let ranges: Vec<[f64; 2]> = pieces.iter().map(|p| [to_s(p.lo), to_s(p.hi)]).collect();
    let mut seen = (0.0, domain.start);
    let (integral, _) = integrate_pieces(
        |k, s| {
            let piece = &pieces[k];
            gap.set_span(piece.span);
            let t = (domain.start + s * width).clamp(piece.lo, piece.hi);
            let d = gap.at(t);
            if d > seen.0 {
                seen = (d, t);
            }
            let d = d / scale;
            d * d
        },
        &ranges,
        Tolerance::relative(MEAN_SQUARE_TARGET),
        BISECTIONS.saturating_add(BISECTIONS_PER_PIECE.saturating_mul(pieces.len())),
    );
    (integral.value, seen)
}

#[cfg(test)]
mod tests;
