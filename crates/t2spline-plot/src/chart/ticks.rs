//! Axis ticks at "nice" numbers (1, 2, 2.5, 5 × 10ᵏ) and their labels, and the
//! fixed-decimal numbers written into SVG files.

/// Tick values covering `[lo, hi]` with about `target` intervals, each a
/// multiple of a nice step, and the step.
#[must_use]
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> (Vec<f64>, f64) {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) {
        return (vec![lo], 1.0);
    }
    let raw = span / target.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|&s| s >= raw)
        .unwrap_or(10.0 * mag);
    let (first, last) = ((lo / step).ceil(), (hi / step).floor());
    // A span near the smallest subnormal numbers makes `mag` underflow to 0
    // (and `lo / step` infinite or NaN): the ends alone are the ticks then.
    if !(step > 0.0 && first.is_finite() && last.is_finite() && last - first <= MAX_TICKS) {
        return (vec![lo, hi], span);
    }
    // Multiplying the integer index keeps ticks free of accumulated error.
    let ticks = (first as i64..=last as i64)
        .map(|i| i as f64 * step)
        .collect();
    (ticks, step)
}

/// More ticks than any panel asks for: a guard against a degenerate step.
const MAX_TICKS: f64 = 1000.0;

/// The number of decimals that shows every multiple of `step` exactly.
#[must_use]
pub fn decimals_for(step: f64) -> usize {
    (0..=8)
        .find(|&d| {
            let scaled = step * 10f64.powi(d as i32);
            (scaled - scaled.round()).abs() < 1e-9 * scaled.max(1.0)
        })
        .unwrap_or(8)
}

/// A tick label: `value` with `decimals` decimals, a true minus sign, no `-0`.
#[must_use]
pub fn tick_label(value: f64, decimals: usize) -> String {
    let s = format!("{value:.decimals$}");
    let s = if s
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_owned()
    } else {
        s
    };
    s.replace('-', "−")
}

/// `v` with at most `digits` significant decimals after trimming trailing
/// zeros, in fixed notation with an ASCII minus: `0.0448`, `6`, `-0.6`.
#[must_use]
pub fn significant(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v.is_finite() {
            "0".into()
        } else {
            v.to_string()
        };
    }
    let mag = v.abs().log10().floor() as i32;
    let decimals = (digits as i32 - 1 - mag).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        s
    }
}

/// A number for a label in a figure: [`significant`] with a true minus
/// sign, e.g. `0.0448`, `6`, `−0.6`.
#[must_use]
pub fn short(v: f64, digits: usize) -> String {
    significant(v, digits).replace('-', "−")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_near_the_smallest_subnormal_give_the_ends() {
        for (lo, hi) in [(0.0, 5e-324), (0.0, 1e-320), (-5e-324, 5e-324)] {
            let (t, _) = nice_ticks(lo, hi, 7);
            assert!(!t.is_empty() && t.len() <= 1001, "{lo} {hi}: {t:?}");
            assert!(t.iter().all(|v| v.is_finite()));
        }
    }

    #[test]
    fn ticks_cover_the_range_with_nice_steps() {
        let (t, s) = nice_ticks(0.13, 6.9, 7);
        assert_eq!(s, 1.0);
        assert_eq!(t, [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let (t, s) = nice_ticks(-0.04, 1.04, 5);
        assert_eq!(s, 0.25);
        assert_eq!(t, [0.0, 0.25, 0.5, 0.75, 1.0]);
        let (t, s) = nice_ticks(3.2, 3.9, 5);
        assert_eq!(s, 0.2);
        assert_eq!(t.len(), 4, "3.2, 3.4, 3.6, 3.8: {t:?}");
        assert_eq!(decimals_for(s), 1);
        assert_eq!(decimals_for(0.25), 2);
        assert_eq!(decimals_for(5.0), 0);
    }

    #[test]
    fn labels_have_no_negative_zero_and_use_the_minus_sign() {
        assert_eq!(tick_label(-0.0, 1), "0.0");
        assert_eq!(tick_label(-1.5, 1), "−1.5");
        assert_eq!(short(0.044_812, 3), "0.0448");
        assert_eq!(short(6.0, 3), "6");
        assert_eq!(short(-2.345_67, 3), "−2.35");
    }
}
