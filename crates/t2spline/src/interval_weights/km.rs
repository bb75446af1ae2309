//! The exact Karnik–Mendel extremes of a weighted average with interval
//! weights (docs/method.md §15): the one computation that the envelope, the
//! support function, the membership test and the section of a curve with
//! uncertain weights all stand on.
//!
//! For values `vᵢ` and weights `θᵢ ∈ [aᵢ, bᵢ]`, `0 ≤ aᵢ ≤ bᵢ`,
//! ```text
//! y(θ) = Σ θᵢ vᵢ / Σ θᵢ,     max_θ y(θ) = max_m y_m,   y_m = (Σ_{top m} bᵢvᵢ + Σ_{rest} aᵢvᵢ) / (Σ_{top m} bᵢ + Σ_{rest} aᵢ)
//! ```
//! where "top m" are the `m` largest values (`m = 0 … n`).
//!
//! **Why the switch points suffice** (Karnik and Mendel 2001; Mendel and
//! Liu 2007). `∂y/∂θᵢ = (vᵢ − y)/Σθ`, so at a maximiser `θ*` with value `y*`
//! every `θᵢ` with `vᵢ > y*` is at `bᵢ` and every `θᵢ` with `vᵢ < y*` at
//! `aᵢ` (else moving it towards that end raises `y`); a `θᵢ` with
//! `vᵢ = y*` does not change the average and may be put at `bᵢ`. So some
//! maximiser takes `b` on the values `≥ y*` and `a` on the rest: a prefix of
//! the values in decreasing order, one of the `n + 1` switch points. A
//! maximiser exists because `y` is continuous on the box when `Σ aᵢ > 0`.
//! The minimum is `−max` of `−v`.
//!
//! Unlike the iterations of [`crate::reduction::discrete`] (KM, EKM, EIASC,
//! which search the switch point of sampled membership functions), every
//! switch point is tried here: the terms of one curve at one parameter are
//! few (the order of the curve), one sort and one pass of running sums is
//! `O(n log n)`, and the answer is the maximum over all of them, with no
//! convergence to argue. The value at the best switch point is then summed
//! afresh, so the running sums leave no rounding behind. Sums are formed
//! relative to the middle of the values' range and with the weights divided
//! by the largest `bᵢ`, so that values near `1e150` and weights from `1e-150`
//! to `1e150` neither overflow nor lose their digits.

use crate::error::Error;
use crate::fuzzy::Interval;

/// One end of the weighted average's range: its value and, for each term,
/// whether that term's weight is at its upper end `bᵢ` (else at `aᵢ`).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SwitchPoint {
    pub(crate) value: f64,
    pub(crate) at_upper: Vec<bool>,
}

/// The largest weighted average `max Σ θᵢvᵢ / Σ θᵢ` over `aᵢ ≤ θᵢ ≤ bᵢ`, at
/// the best switch point. Callers guarantee equal lengths, finite values,
/// `0 ≤ aᵢ ≤ bᵢ` finite and `Σ aᵢ > 0` (after scaling by the largest `bᵢ`).
pub(crate) fn max_switch(values: &[f64], lower: &[f64], upper: &[f64]) -> SwitchPoint {
    let n = values.len();
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| {
            (l.min(v), h.max(v))
        });
    if n == 0 || lo == hi {
        // One value (or none): every choice of weights gives it.
        return SwitchPoint {
            value: if n == 0 { 0.0 } else { lo },
            at_upper: vec![true; n],
        };
    }
    let origin = lo + (hi - lo) / 2.0;
    let scale = binary_scale(upper);
    let mut order: Vec<usize> = (0..n).collect();
    // Decreasing values; equal values stay in index order.
    order.sort_by(|&i, &j| values[j].total_cmp(&values[i]).then(i.cmp(&j)));
    // m = 0: every weight at its lower end.
    let (mut num, mut den) = (0.0, 0.0);
    for i in 0..n {
        let a = lower[i] / scale;
        num += a * (values[i] - origin);
        den += a;
    }
    let mut best = (f64::NEG_INFINITY, 0);
    if den > 0.0 {
        best = (num / den, 0);
    }
    for (m, &i) in order.iter().enumerate() {
        let step = (upper[i] - lower[i]) / scale;
        num += step * (values[i] - origin);
        den += step;
        if den > 0.0 && num / den > best.0 {
            best = (num / den, m + 1);
        }
    }
    let mut at_upper = vec![false; n];
    for &i in order.iter().take(best.1) {
        at_upper[i] = true;
    }
    let value = average(values, lower, upper, &at_upper, origin, scale).clamp(lo, hi);
    SwitchPoint { value, at_upper }
}

/// The power of two at or below the largest of `weights` (1 if none is a
/// positive normal number): dividing by it is exact, and brings the weights
/// below 2 so that their sums and products cannot overflow.
pub(crate) fn binary_scale(weights: &[f64]) -> f64 {
    let largest = weights.iter().fold(0.0_f64, |m, &b| m.max(b));
    let scale = f64::from_bits(largest.to_bits() & 0x7ff0_0000_0000_0000);
    if scale.is_normal() {
        scale
    } else {
        1.0
    }
}

/// The smallest weighted average, at its switch point: [`max_switch`] of the
/// negated values.
pub(crate) fn min_switch(values: &[f64], lower: &[f64], upper: &[f64]) -> SwitchPoint {
    let negated: Vec<f64> = values.iter().map(|v| -v).collect();
    let s = max_switch(&negated, lower, upper);
    SwitchPoint {
        value: -s.value,
        at_upper: s.at_upper,
    }
}

/// `Σ θᵢvᵢ / Σ θᵢ` with `θᵢ = bᵢ` where `at_upper[i]`, else `aᵢ`, summed
/// afresh relative to `origin` with the weights divided by `scale`.
fn average(
    values: &[f64],
    lower: &[f64],
    upper: &[f64],
    at_upper: &[bool],
    origin: f64,
    scale: f64,
) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for i in 0..values.len() {
        let w = if at_upper[i] { upper[i] } else { lower[i] } / scale;
        num += w * (values[i] - origin);
        den += w;
    }
    if den > 0.0 {
        origin + num / den
    } else {
        origin
    }
}

/// The range `[min, max]` of the weighted average `Σ θᵢvᵢ / Σ θᵢ` over every
/// choice of weights `θᵢ ∈ weights[i] = [aᵢ, bᵢ]`: the interval-weights
/// problem of Karnik and Mendel, solved exactly by trying every switch point
/// (module docs; docs/method.md §15).
///
/// # Errors
/// [`Error::Length`] if `weights` is not as long as `values` or both are
/// empty; [`Error::Sample`] (`what` = `"values"`) for a value that is not
/// finite; [`Error::WeightCut`] for a weight cut with an end that is not
/// finite, negative, or out of order, or if every lower end is 0.
///
/// # Examples
/// ```
/// # use t2spline::interval_weights::weighted_average_range;
/// // Values 0 and 1 with weights in [1, 3]: from 1/4 (3 on 0, 1 on 1) to 3/4.
/// let r = weighted_average_range(&[0.0, 1.0], &[[1.0, 3.0], [1.0, 3.0]])?;
/// assert_eq!((r.left(), r.right()), (0.25, 0.75));
/// assert!(weighted_average_range(&[0.0, 1.0], &[[1.0, 3.0], [2.0, 1.0]]).is_err());
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn weighted_average_range(values: &[f64], weights: &[[f64; 2]]) -> Result<Interval, Error> {
    if values.is_empty() || weights.len() != values.len() {
        return Err(Error::Length {
            what: "weights",
            expected: values.len().max(1),
            found: weights.len(),
        });
    }
    for (index, &value) in values.iter().enumerate() {
        if !value.is_finite() {
            return Err(Error::Sample {
                what: "values",
                index,
                value,
                rule: "is not a finite number",
            });
        }
    }
    for (index, &[left, right]) in weights.iter().enumerate() {
        let rule = if !(left.is_finite() && right.is_finite()) {
            Some("has an end that is not a finite number")
        } else if left < 0.0 {
            Some("has a negative left end; weights are at least 0")
        } else if left > right {
            Some("is out of order: its left end is above its right end")
        } else {
            None
        };
        if let Some(rule) = rule {
            return Err(Error::WeightCut {
                index,
                left,
                right,
                rule,
            });
        }
    }
    let lower: Vec<f64> = weights.iter().map(|w| w[0]).collect();
    let upper: Vec<f64> = weights.iter().map(|w| w[1]).collect();
    let scale = upper.iter().fold(0.0_f64, |m, &b| m.max(b));
    if !(lower.iter().any(|&a| a / scale > 0.0)) {
        return Err(Error::WeightCut {
            index: 0,
            left: lower[0],
            right: upper[0],
            rule: "and every other lower end are 0 (or too small beside the largest upper end); the average needs a positive sum of weights",
        });
    }
    let lo = min_switch(values, &lower, &upper).value;
    let hi = max_switch(values, &lower, &upper).value;
    Ok(Interval::new_unchecked(lo.min(hi), hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every vertex of the weight box, by brute force.
    fn brute(values: &[f64], lower: &[f64], upper: &[f64]) -> (f64, f64) {
        let n = values.len();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for mask in 0..(1usize << n) {
            let (mut num, mut den) = (0.0, 0.0);
            for i in 0..n {
                let w = if mask >> i & 1 == 1 {
                    upper[i]
                } else {
                    lower[i]
                };
                num += w * values[i];
                den += w;
            }
            lo = lo.min(num / den);
            hi = hi.max(num / den);
        }
        (lo, hi)
    }

    #[test]
    fn switch_points_match_every_vertex() {
        let mut r = crate::strategies::seeded_uniform(11);
        for _ in 0..500 {
            let n = 1 + (r() * 7.0) as usize;
            let values: Vec<f64> = (0..n).map(|_| r() * 10.0 - 5.0).collect();
            let lower: Vec<f64> = (0..n).map(|_| 0.1 + r()).collect();
            let upper: Vec<f64> = lower.iter().map(|a| a + r() * 3.0).collect();
            let (lo, hi) = brute(&values, &lower, &upper);
            let max = max_switch(&values, &lower, &upper);
            let min = min_switch(&values, &lower, &upper);
            assert!(
                (max.value - hi).abs() <= 1e-13 * (1.0 + hi.abs()),
                "{max:?} {hi}"
            );
            assert!(
                (min.value - lo).abs() <= 1e-13 * (1.0 + lo.abs()),
                "{min:?} {lo}"
            );
        }
    }

    #[test]
    fn ties_and_single_values() {
        let s = max_switch(&[2.0, 2.0], &[1.0, 1.0], &[5.0, 5.0]);
        assert_eq!(s.value, 2.0);
        let s = max_switch(&[1.0, 3.0, 3.0], &[1.0, 1.0, 1.0], &[1.0, 2.0, 2.0]);
        assert_eq!(s.at_upper, [false, true, true]);
        assert!((s.value - 13.0 / 5.0).abs() < 1e-15);
    }

    #[test]
    fn bad_weights_are_errors() {
        for w in [[f64::NAN, 1.0], [-1.0, 1.0], [2.0, 1.0]] {
            let e = weighted_average_range(&[0.0, 1.0], &[[1.0, 1.0], w]).unwrap_err();
            assert!(matches!(e, Error::WeightCut { index: 1, .. }), "{e}");
        }
        assert!(weighted_average_range(&[0.0], &[[0.0, 1.0]]).is_err());
        assert!(weighted_average_range(&[f64::NAN], &[[1.0, 1.0]]).is_err());
        assert!(weighted_average_range(&[], &[]).is_err());
    }
}
