//! Arc length and the parameter at a given length.
//!
//! The length `L(a, b) = ∫ₐᵇ ‖C'(t)‖ dt` is integrated by the shared adaptive
//! Gauss–Kronrod quadrature ([`crate::quadrature`]) over pieces on which the
//! curve is tame ([`crate::nurbs::pieces`]): the knot spans (the speed is
//! smooth inside a span, not across knots), and where the weights vary by
//! orders of magnitude on a span, or a span is too narrow to sample in `t`,
//! halves of the span's Bézier form, integrated in their own variable
//! `s ∈ [0, 1]` (a length does not depend on the parametrization). Without
//! those cuts, weights spread over orders of magnitude hid narrow windows of
//! fast motion between the rule's nodes, and the length came out short (8% for
//! weights from 10⁻³ to 10³, a fifth from 10⁻¹² to 10¹²) with a small error
//! estimate. The pieces with the largest error estimates are
//! bisected until the estimates add up to `10⁻¹¹·L`, so that the relative
//! error of the length stays below [`LENGTH_TOLERANCE`]. The work is bounded
//! (1000 bisections plus 64 per piece): a speed so noisy from rounding that
//! its error estimate never meets the tolerance (extreme coordinates) gets
//! the estimate reached by then.

use crate::error::Error;
use crate::nurbs::homogeneous::from_rows;
use crate::nurbs::pieces::{tame_pieces, Piece};
use crate::nurbs::span_eval::SpanEvaluator;
use crate::nurbs::{KnotVector, NurbsCurve};
use crate::quadrature::{integrate, integrate_pieces, Tolerance};
use crate::vector::norm;

/// The relative accuracy promised for lengths.
pub const LENGTH_TOLERANCE: f64 = 1e-10;
/// The relative accuracy aimed at, below [`LENGTH_TOLERANCE`] for a margin
/// over the error estimate.
const TARGET: f64 = 1e-11;
/// Bisections allowed in one length computation: this many, plus
/// [`BISECTIONS_PER_PIECE`] per piece. A smooth piece needs a handful; the
/// bound only stops a speed that rounding makes noisy, where the error
/// estimate never meets the tolerance.
const BISECTIONS: usize = 1000;
/// See [`BISECTIONS`].
const BISECTIONS_PER_PIECE: usize = 64;
/// Bisections allowed for one partial length inside a part, in the search
/// of [`NurbsCurve::param_at_length`].
const PARTIAL_BISECTIONS: usize = 64;

/// The bisections allowed for a length over `pieces` pieces.
fn bisection_budget(pieces: usize) -> usize {
    BISECTIONS.saturating_add(BISECTIONS_PER_PIECE.saturating_mul(pieces))
}

/// A piece of a length computation with the curve that describes it: the
/// curve itself on a knot span (variable `t`), or the piece's own rational
/// Bézier curve (variable `s ∈ [0, 1]`).
struct Section<const D: usize> {
    piece: Piece,
    bezier: Option<NurbsCurve<D>>,
}

impl<const D: usize> Section<D> {
    /// The range of the section's own variable.
    fn range(&self) -> [f64; 2] {
        match self.bezier {
            Some(_) => [0.0, 1.0],
            None => [self.piece.lo, self.piece.hi],
        }
    }

    /// The curve parameter `t` at the section's own variable `x`.
    fn param(&self, x: f64) -> f64 {
        let Piece { lo, hi, .. } = self.piece;
        match self.bezier {
            Some(_) => (lo + x * (hi - lo)).clamp(lo, hi),
            None => x,
        }
    }

    /// Chooses the section on `eval`.
    fn choose(&self, eval: &mut SpanEvaluator, curve: &NurbsCurve<D>) {
        match &self.bezier {
            Some(b) => eval.set_span(b, b.degree()),
            None => eval.set_span(curve, self.piece.span),
        }
    }

    /// The speed in the section's own variable at `x`, on a chosen `eval`.
    fn speed(&self, eval: &mut SpanEvaluator, curve: &NurbsCurve<D>, x: f64) -> f64 {
        let on = self.bezier.as_ref().unwrap_or(curve);
        norm(&eval.point_and_derivative(on, x).1)
    }

    /// The chord between the ends.
    fn chord(&self, eval: &mut SpanEvaluator, curve: &NurbsCurve<D>) -> f64 {
        let on = self.bezier.as_ref().unwrap_or(curve);
        let [a, b] = self.range();
        let (from, to) = (eval.point(on, a), eval.point(on, b));
        norm::<D>(&std::array::from_fn(|d| to[d] - from[d]))
    }
}

/// A part of a length: the integral of the speed over `[lo, hi]` (in the
/// section's own variable) inside a tame section, or the chord of a section
/// that is not tame.
#[derive(Clone, Copy, Debug)]
struct Part {
    /// The index of the section it lies in.
    section: usize,
    lo: f64,
    hi: f64,
    length: f64,
}

impl<const D: usize> NurbsCurve<D> {
    /// The sections of `[a, b]` (`a < b`) and the parts of the length over
    /// them, in order, with the total.
    ///
    /// A section that is not tame ([`Piece::tame`]: halving stopped at its
    /// bounds with weights still far apart, beyond what the library's range
    /// of weights allows at degree 2 and above) counts its chord, a lower
    /// bound of its length (exact at degree 1, where the curve is a straight
    /// line).
    fn length_parts(&self, a: f64, b: f64) -> (Vec<Section<D>>, Vec<Part>, f64) {
        let rows = |i: usize| {
            let w = self.weights()[i];
            self.control_points()[i]
                .iter()
                .map(|x| w * x)
                .chain([w])
                .collect()
        };
        let p = self.degree();
        let bezier_knots: Vec<f64> = [0.0, 1.0]
            .iter()
            .flat_map(|&u| [u; 1].repeat(p + 1))
            .collect();
        let sections: Vec<Section<D>> = tame_pieces(self.knots(), self.weights(), rows, a, b)
            .into_iter()
            .map(|piece| {
                let bezier = piece.bezier.as_ref().map(|rows| {
                    let (points, weights) = from_rows::<D>(rows);
                    let knots = KnotVector::from_parts_unchecked(bezier_knots.clone(), p);
                    NurbsCurve::from_parts_unchecked(points, weights, knots)
                });
                Section { piece, bezier }
            })
            .collect();
        // Sections that are not tame get an empty range: no quadrature there.
        let ranges: Vec<[f64; 2]> = sections
            .iter()
            .map(|s| if s.piece.tame { s.range() } else { [0.0, 0.0] })
            .collect();
        let mut eval = SpanEvaluator::new(self.degree());
        let mut chosen = usize::MAX;
        let (_, leaves) = integrate_pieces(
            |k, x| {
                if k != chosen {
                    sections[k].choose(&mut eval, self);
                    chosen = k;
                }
                sections[k].speed(&mut eval, self, x)
            },
            &ranges,
            Tolerance::relative(TARGET),
            bisection_budget(sections.len()),
        );
        let mut parts = Vec::with_capacity(leaves.len());
        let mut leaves = leaves.into_iter().peekable();
        for (k, section) in sections.iter().enumerate() {
            if section.piece.tame {
                while let Some(leaf) = leaves.next_if(|l| l.source == k) {
                    parts.push(Part {
                        section: k,
                        lo: leaf.lo,
                        hi: leaf.hi,
                        length: leaf.value,
                    });
                }
            } else {
                section.choose(&mut eval, self);
                let [lo, hi] = section.range();
                parts.push(Part {
                    section: k,
                    lo,
                    hi,
                    length: section.chord(&mut eval, self),
                });
            }
        }
        let total = parts.iter().map(|p| p.length).sum();
        (sections, parts, total)
    }

    /// The length of the curve between the parameters `a ≤ b`:
    ///
    /// ```text
    /// L(a, b) = ∫ₐᵇ ‖C'(t)‖ dt
    /// ```
    /// to a relative accuracy of 10⁻¹⁰ ([`LENGTH_TOLERANCE`]; adaptive
    /// Gauss–Kronrod over the knot spans, cut where the weights vary by
    /// orders of magnitude). A jump at a knot of full multiplicity adds no
    /// length.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `a` or `b` lies outside the domain. `a > b`
    /// gives the negative length.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let c = NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [3.0, 4.0]], vec![1.0, 1.0])?;
    /// assert!((c.arc_length_between(0.2, 0.6)? - 2.0).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn arc_length_between(&self, a: f64, b: f64) -> Result<f64, Error> {
        self.domain().check(a)?;
        self.domain().check(b)?;
        Ok(match a.partial_cmp(&b) {
            Some(std::cmp::Ordering::Less) => self.length_parts(a, b).2,
            Some(std::cmp::Ordering::Greater) => -self.length_parts(b, a).2,
            _ => 0.0,
        })
    }

    /// The length of the whole curve; see [`NurbsCurve::arc_length_between`].
    ///
    /// # Examples
    /// The quarter circle has length π/2:
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
    /// assert!((c.arc_length() / std::f64::consts::FRAC_PI_2 - 1.0).abs() < 1e-10);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn arc_length(&self) -> f64 {
        let d = self.domain();
        self.length_parts(d.start, d.end).2
    }

    /// The parameter `t` at which the arc length from the start of the domain
    /// is `length`: `L(a, t) = length`.
    ///
    /// The total is [`NurbsCurve::arc_length`], computed once; its final
    /// quadrature pieces and their lengths locate the piece holding `length`,
    /// and inside it Newton's method on `L(lo, t) − rest` (derivative: the
    /// speed) is safeguarded by bisection, to `10⁻¹²·L`. Lengths up to
    /// [`LENGTH_TOLERANCE`]`·L` outside `[0, L]` (the accuracy of `L` itself)
    /// give the ends of the domain: a length computed another way, or the
    /// exact length of a circle, is not refused for rounding. Where the speed
    /// vanishes on an interval (a constant piece) the smallest such `t` is
    /// not guaranteed; any `t` with that length may come back.
    ///
    /// # Errors
    /// [`Error::LengthOutside`] if `length` is NaN or outside
    /// `[−10⁻¹⁰·L, (1 + 10⁻¹⁰)·L]`.
    ///
    /// # Examples
    /// Half the length of the quarter circle is at the angle π/4, i.e. `t = 1/2`,
    /// and its exact length π/2 gives the end:
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
    /// let t = c.param_at_length(std::f64::consts::FRAC_PI_4)?;
    /// assert!((t - 0.5).abs() < 1e-10);
    /// assert_eq!(c.param_at_length(std::f64::consts::FRAC_PI_2)?, 1.0);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn param_at_length(&self, length: f64) -> Result<f64, Error> {
        let d = self.domain();
        let (sections, parts, total) = self.length_parts(d.start, d.end);
        let slack = LENGTH_TOLERANCE * total;
        if !(-slack..=total + slack).contains(&length) {
            return Err(Error::LengthOutside { length, total });
        }
        if length <= 0.0 {
            return Ok(d.start);
        }
        if length >= total {
            return Ok(d.end);
        }
        let mut before = 0.0;
        let mut part = parts[parts.len() - 1];
        for p in &parts {
            if before + p.length >= length {
                part = *p;
                break;
            }
            before += p.length;
        }
        let section = &sections[part.section];
        let (a, b) = (part.lo, part.hi);
        let target = length - before;
        if target <= 0.0 {
            return Ok(section.param(a));
        }
        if target >= part.length {
            return Ok(section.param(b));
        }
        if !section.piece.tame {
            // A step no quadrature resolved: the nearer end.
            return Ok(section.param(if target < part.length / 2.0 { a } else { b }));
        }
        let mut eval = SpanEvaluator::new(self.degree());
        section.choose(&mut eval, self);
        let accuracy = 1e-12 * total;
        let (mut lo, mut hi) = (a, b);
        let mut x = a + (b - a) * (target / part.length);
        for _ in 0..200 {
            let partial = integrate(
                |y| section.speed(&mut eval, self, y),
                [a, x],
                Tolerance {
                    relative: TARGET,
                    absolute: accuracy / 4.0,
                },
                PARTIAL_BISECTIONS,
            );
            let g = partial.value - target;
            if g.abs() <= accuracy {
                break;
            }
            if g < 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            let v = section.speed(&mut eval, self, x);
            let newton = x - g / v;
            x = if v > 0.0 && lo < newton && newton < hi {
                newton
            } else {
                (lo + hi) / 2.0
            };
            if hi - lo <= f64::EPSILON * hi.abs().max(lo.abs()) {
                break;
            }
        }
        Ok(section.param(x))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parabola_length_matches_the_closed_form() {
        // C(t) = (2t, 2t(1 − t))·… from control points (0,0), (1,1), (2,0):
        // x = 2t, y = 2t − 2t², speed = 2√(1 + (1 − 2t)²).
        let c = NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], vec![1.0; 3])
            .unwrap();
        // ∫₀¹ 2√(1 + u²) du over u = 1 − 2t ∈ [−1, 1]: √2 + asinh(1).
        let exact = 2f64.sqrt() + 1f64.asinh();
        assert!(
            (c.arc_length() / exact - 1.0).abs() < 1e-13,
            "{}",
            c.arc_length()
        );
        let t = c.param_at_length(exact / 2.0).unwrap();
        assert!((t - 0.5).abs() < 1e-11, "{t}");
    }

    #[test]
    fn lengths_add_up_and_reverse() {
        let c = NurbsCurve::try_clamped(
            3,
            vec![[0.0, 0.0], [1.0, 3.0], [3.0, -1.0], [4.0, 2.0], [5.0, 0.0]],
            vec![1.0, 4.0, 0.3, 1.0, 2.0],
        )
        .unwrap();
        let whole = c.arc_length();
        let parts =
            c.arc_length_between(0.0, 0.37).unwrap() + c.arc_length_between(0.37, 1.0).unwrap();
        assert!((whole - parts).abs() < 1e-10 * whole);
        assert_eq!(
            c.arc_length_between(0.6, 0.2).unwrap(),
            -c.arc_length_between(0.2, 0.6).unwrap()
        );
        assert_eq!(c.arc_length_between(0.3, 0.3).unwrap(), 0.0);
    }
}
