//! Arc length and the parameter at a given length.
//!
//! The length `L(a, b) = ∫ₐᵇ ‖C'(t)‖ dt` is integrated per knot span (where the
//! speed is smooth) by adaptive Gauss–Kronrod quadrature (7-point Gauss,
//! 15-point Kronrod; Piessens et al., QUADPACK, QK15), bisecting every interval
//! whose error estimate `|K₁₅ − G₇|` exceeds its share of `10⁻¹¹·L`, so that
//! the relative error of the whole length stays below `10⁻¹⁰`. The work is
//! bounded (1000 bisections plus 64 per knot span): a speed so noisy from
//! rounding that its error estimate never meets the tolerance (extreme weights
//! or coordinates) gets an estimate in bounded time rather than 2⁴⁰
//! bisections.

use crate::error::Error;
use crate::nurbs::derivatives::norm;
use crate::nurbs::NurbsCurve;

/// The relative accuracy promised for lengths.
pub const LENGTH_TOLERANCE: f64 = 1e-10;
/// The relative accuracy aimed at internally, below [`LENGTH_TOLERANCE`]
/// because `|K₁₅ − G₇|` estimates the error of the Gauss rule, not of the far
/// better Kronrod rule whose value is kept.
const TARGET: f64 = 1e-11;
/// Bisections allowed below one knot span (2⁻⁴⁰ of its width).
const MAX_DEPTH: u32 = 40;
/// Bisections allowed in one length computation: this many, plus
/// [`BISECTIONS_PER_SPAN`] per knot span. A smooth span needs a handful; the
/// bound only stops a speed that rounding makes noisy (extreme weights or
/// coordinates), where the error estimate never meets the tolerance, from
/// bisecting 2⁴⁰ times. Pieces left when it runs out keep their K₁₅ value.
const BISECTIONS: usize = 1000;
/// See [`BISECTIONS`].
const BISECTIONS_PER_SPAN: usize = 64;

/// Kronrod nodes on `[−1, 1]` (the positive half; QUADPACK `xgk`).
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights (QUADPACK `wgk`).
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_18,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_83,
];
/// Gauss weights of the nodes `XGK[1], XGK[3], XGK[5], XGK[7]` (QUADPACK `wg`).
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// `(K₁₅, |K₁₅ − G₇|)` for `∫ₐᵇ f`.
fn gauss_kronrod(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let (centre, half) = ((a + b) / 2.0, (b - a) / 2.0);
    let mut kronrod = 0.0;
    let mut gauss = 0.0;
    for (j, (x, w)) in XGK.iter().zip(WGK).enumerate() {
        let values = if *x == 0.0 {
            let v = f(centre);
            [v, 0.0]
        } else {
            [f(centre - half * x), f(centre + half * x)]
        };
        let sum = values[0] + values[1];
        kronrod += w * sum;
        if j % 2 == 1 {
            gauss += WG[j / 2] * sum;
        }
    }
    (kronrod * half, ((kronrod - gauss) * half).abs())
}

/// `∫ₐᵇ f` to the absolute tolerance `tol` per unit of parameter, by
/// bisection until each piece meets `err ≤ tol·width`, using at most `budget`
/// bisections (which it counts down).
fn adaptive(f: &impl Fn(f64) -> f64, a: f64, b: f64, tol: f64, budget: &mut usize) -> f64 {
    let mut total = 0.0;
    let mut stack = vec![(a, b, 0u32)];
    while let Some((lo, hi, depth)) = stack.pop() {
        let (value, err) = gauss_kronrod(f, lo, hi);
        if err <= tol * (hi - lo) || depth >= MAX_DEPTH || *budget == 0 {
            total += value;
        } else {
            *budget -= 1;
            let mid = (lo + hi) / 2.0;
            stack.push((mid, hi, depth + 1));
            stack.push((lo, mid, depth + 1));
        }
    }
    total
}

/// The bisections allowed for a length over `spans` knot spans.
fn bisection_budget(spans: usize) -> usize {
    BISECTIONS.saturating_add(BISECTIONS_PER_SPAN.saturating_mul(spans))
}

impl<const D: usize> NurbsCurve<D> {
    /// The speed `‖C'(t)‖`.
    fn speed(&self, t: f64) -> f64 {
        norm(&self.derivatives_unchecked(t, 1)[1])
    }

    /// The knot spans cut to `[a, b]`, and the absolute tolerance per unit of
    /// parameter that gives the relative accuracy `TARGET` on the length over
    /// `[a, b]` (from a first Kronrod estimate per span).
    fn length_pieces(&self, a: f64, b: f64) -> (Vec<[f64; 2]>, f64) {
        let pieces: Vec<[f64; 2]> = self
            .knots()
            .spans()
            .map(|(_, [lo, hi])| [lo.max(a), hi.min(b)])
            .filter(|[lo, hi]| lo < hi)
            .collect();
        let speed = |t| self.speed(t);
        let estimate: f64 = pieces
            .iter()
            .map(|&[lo, hi]| gauss_kronrod(&speed, lo, hi).0)
            .sum();
        (pieces, TARGET * estimate / (b - a))
    }

    /// The length of the curve between the parameters `a ≤ b`:
    ///
    /// ```text
    /// L(a, b) = ∫ₐᵇ ‖C'(t)‖ dt
    /// ```
    /// to a relative accuracy of 10⁻¹⁰ (adaptive Gauss–Kronrod per knot span). A
    /// jump at a knot of full multiplicity adds no length.
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
            Some(std::cmp::Ordering::Less) => self.length_unchecked(a, b),
            Some(std::cmp::Ordering::Greater) => -self.length_unchecked(b, a),
            _ => 0.0,
        })
    }

    fn length_unchecked(&self, a: f64, b: f64) -> f64 {
        let (pieces, tol) = self.length_pieces(a, b);
        let speed = |t| self.speed(t);
        let mut budget = bisection_budget(pieces.len());
        pieces
            .iter()
            .map(|&[lo, hi]| adaptive(&speed, lo, hi, tol, &mut budget))
            .sum()
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
        self.length_unchecked(d.start, d.end)
    }

    /// The parameter `t` at which the arc length from the start of the domain
    /// is `length`: `L(a, t) = length`.
    ///
    /// The span holding `length` is found from the lengths of the spans; inside
    /// it Newton's method on `L(a, t) − length` (derivative: the speed) is
    /// safeguarded by bisection, to `|L(a, t) − length| ≤ 10⁻¹²·L`. Where the
    /// speed vanishes on an interval (a constant piece) the smallest such `t` is
    /// not guaranteed; any `t` with that length may come back.
    ///
    /// # Errors
    /// [`Error::LengthOutside`] if `length` is NaN or outside `[0, L]`.
    ///
    /// # Examples
    /// Half the length of the quarter circle is at the angle π/4, i.e. `t = 1/2`:
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
    /// let t = c.param_at_length(std::f64::consts::FRAC_PI_4)?;
    /// assert!((t - 0.5).abs() < 1e-10);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn param_at_length(&self, length: f64) -> Result<f64, Error> {
        let d = self.domain();
        let (pieces, tol) = self.length_pieces(d.start, d.end);
        let speed = |t| self.speed(t);
        let mut budget = bisection_budget(pieces.len());
        let lengths: Vec<f64> = pieces
            .iter()
            .map(|&[lo, hi]| adaptive(&speed, lo, hi, tol, &mut budget))
            .collect();
        let total: f64 = lengths.iter().sum();
        if !(0.0..=total).contains(&length) {
            return Err(Error::LengthOutside { length, total });
        }
        let mut before = 0.0;
        let mut piece = pieces.len() - 1;
        for (i, l) in lengths.iter().enumerate() {
            if before + l >= length {
                piece = i;
                break;
            }
            before += l;
        }
        let [a, b] = pieces[piece];
        let target = length - before;
        let span_length = lengths[piece];
        if target <= 0.0 {
            return Ok(a);
        }
        if target >= span_length {
            return Ok(b);
        }
        let accuracy = 1e-12 * total;
        let (mut lo, mut hi) = (a, b);
        let mut t = a + (b - a) * (target / span_length);
        for _ in 0..200 {
            let g = adaptive(&speed, a, t, tol, &mut budget) - target;
            if g.abs() <= accuracy {
                return Ok(t);
            }
            if g < 0.0 {
                lo = t;
            } else {
                hi = t;
            }
            let v = speed(t);
            let newton = t - g / v;
            t = if v > 0.0 && lo < newton && newton < hi {
                newton
            } else {
                (lo + hi) / 2.0
            };
            if hi - lo <= f64::EPSILON * hi.abs().max(lo.abs()) {
                break;
            }
        }
        Ok(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn issue_6_a_tolerance_never_met_stops_at_the_budget() {
        // With tolerance 0 no piece is ever accurate enough: without the
        // budget this would bisect to depth 40 everywhere (2⁴⁰ pieces).
        let calls = std::cell::Cell::new(0usize);
        let f = |t: f64| {
            calls.set(calls.get() + 1);
            (t * 1e6).sin()
        };
        let mut budget = 100;
        let value = adaptive(&f, 0.0, 1.0, 0.0, &mut budget);
        assert_eq!(budget, 0);
        // 100 bisections make 201 pieces of 15 evaluations.
        assert_eq!(calls.get(), 201 * 15);
        assert!(value.is_finite() && value.abs() <= 1.0, "{value}");
    }

    #[test]
    fn gauss_kronrod_is_exact_for_polynomials_of_degree_22() {
        let (k, _) = gauss_kronrod(&|x: f64| x.powi(22), -1.0, 1.0);
        assert!((k - 2.0 / 23.0).abs() < 1e-15, "{k}");
    }

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
