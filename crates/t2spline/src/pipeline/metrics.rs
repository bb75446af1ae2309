//! The distance between the crisp and the defuzzified curve (SPEC §7).

use crate::golden_section::golden_section_min;
use crate::nurbs::NurbsCurve;

/// How far the defuzzified curve `D(t)` lies from the crisp curve `C(t)` at equal
/// parameters, over the whole domain `[a, b]` (SPEC §7):
///
/// ```text
/// d(t) = ‖D(t) − C(t)‖₂
/// max  = max over t ∈ [a, b] of d(t),        max_at = the t where it is reached
/// rms  = √( 1/(b − a) · ∫ₐᵇ d(t)² dt )
/// ```
/// Both curves share weights and knots, so `D − C` is itself a rational
/// B-spline whose control points are the differences `Dᵢ − Pᵢ`; `d` is its norm.
/// Neither figure depends on the job's `samples`: `max` is found by a scan of 32
/// steps per knot span, each local maximum of the scan refined by
/// golden-section search (to about 1e-13 of the span in `t`), `rms` by 8-point Gauss–Legendre quadrature on quarters of each
/// knot span. With symmetric spreads both are 0.
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
/// Gauss–Legendre points per quadrature cell.
const GAUSS_POINTS: usize = 8;
/// Quadrature cells per knot span.
const CELLS_PER_SPAN: usize = 4;

impl Distance {
    /// Measures the norm of `difference(t)` over its domain.
    ///
    /// The mean square is formed as a weighted mean of `(d(t)/scale)²` with
    /// weights that are fractions of the domain (each knot span's share of
    /// `b − a`, times the quadrature weights), where `scale` is the largest
    /// distance found by the scan. Squaring a distance near 1e-170 directly would
    /// underflow; dividing by `b − a` at the
    /// end would lose a domain narrower than about 1e-300.
    pub(crate) fn of_curve<const D: usize>(difference: &NurbsCurve<D>) -> Distance {
        let norm = |t: f64| norm(&difference.eval_unchecked(t));
        let domain = difference.domain();
        let mut max = (norm(domain.start), domain.start);
        let mut scan = Vec::with_capacity(SCAN_STEPS + 1);
        for (_, [a, b]) in difference.knots().spans() {
            let step = (b - a) / SCAN_STEPS as f64;
            let tolerance = 1e-13 * (b - a).max(f64::MIN_POSITIVE);
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
                    let (d, t) = golden_section_min(|t| -norm(t), bracket, tolerance);
                    if -d > max.0 {
                        max = (-d, t);
                    }
                }
            }
        }
        let scale = max.0;
        let mut mean_square = 0.0;
        if scale > 0.0 {
            let (nodes, weights) = gauss_legendre(GAUSS_POINTS);
            let width = domain.end - domain.start;
            for (_, [a, b]) in difference.knots().spans() {
                // This cell's share of the domain; the Gauss weights sum to 2.
                let share = (b - a) / width / CELLS_PER_SPAN as f64 / 2.0;
                let cell = (b - a) / CELLS_PER_SPAN as f64;
                for c in 0..CELLS_PER_SPAN {
                    let (lo, half) = (a + cell * c as f64, cell / 2.0);
                    for (x, w) in nodes.iter().zip(&weights) {
                        let d = norm((lo + half * (1.0 + x)).clamp(a, b)) / scale;
                        mean_square += share * w * d * d;
                    }
                }
            }
        }
        Distance {
            max: max.0,
            max_at: max.1,
            rms: scale * mean_square.sqrt(),
        }
    }
}

fn norm<const D: usize>(v: &[f64; D]) -> f64 {
    euclidean_norm(v)
}

/// The Euclidean norm `‖v‖₂ = √(Σ vᵢ²)`. Components from 1e-150 to 1e150
/// are squared as they are; beyond, they are first divided by the largest one,
/// so that neither the squares of components near 1e300 overflow nor those
/// near 1e-170 underflow (as `f64::hypot` does for two).
///
/// # Examples
/// ```
/// # use t2spline::pipeline::euclidean_norm;
/// assert_eq!(euclidean_norm(&[3.0, 4.0]), 5.0);
/// assert_eq!(euclidean_norm(&[3e300, 4e300]), 5e300);
/// assert_eq!(euclidean_norm(&[3e-300, -4e-300, 0.0]), 5e-300);
/// assert_eq!(euclidean_norm(&[]), 0.0);
/// ```
#[must_use]
pub fn euclidean_norm(v: &[f64]) -> f64 {
    let largest = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if (1e-150..=1e150).contains(&largest) {
        v.iter().map(|x| x * x).sum::<f64>().sqrt()
    } else if largest == 0.0 || !largest.is_finite() {
        largest
    } else {
        let scaled: f64 = v.iter().map(|x| (x / largest) * (x / largest)).sum();
        largest * scaled.sqrt()
    }
}

/// Nodes and weights of `n`-point Gauss–Legendre quadrature on `[−1, 1]`, by
/// Newton's method on the Legendre polynomial `Pₙ` (Press et al., *Numerical
/// Recipes*, §4.6), using `P_k = ((2k − 1)·x·P_{k−1} − (k − 1)·P_{k−2}) / k` and
/// `Pₙ'(x) = n·(x·Pₙ − P_{n−1}) / (x² − 1)`.
fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    for i in 1..=n {
        let mut x = (std::f64::consts::PI * (i as f64 - 0.25) / (n as f64 + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            let (mut p, mut previous) = (x, 1.0);
            for k in 2..=n {
                let k = k as f64;
                (p, previous) = (((2.0 * k - 1.0) * x * p - (k - 1.0) * previous) / k, p);
            }
            derivative = n as f64 * (x * p - previous) / (x * x - 1.0);
            let dx = p / derivative;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        nodes.push(x);
        weights.push(2.0 / ((1.0 - x * x) * derivative * derivative));
    }
    (nodes, weights)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_degree_15_exactly() {
        let (x, w) = gauss_legendre(8);
        assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14);
        // ∫₋₁¹ t¹⁴ dt = 2/15.
        let i: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(14)).sum();
        assert!((i - 2.0 / 15.0).abs() < 1e-14, "{i}");
    }

    #[test]
    fn issue_6_a_subnormal_domain_keeps_max_at_inside() {
        // A domain 274 subnormal units wide: the scan step rounds up, and 31
        // steps went past the end (found by fuzzing).
        let end = 1.354e-321;
        let u = crate::KnotVector::try_new(vec![0.0, 0.0, end, end], 1, 2).unwrap();
        let c = NurbsCurve::try_new(vec![[0.0, 0.0], [3.0, 4.0]], vec![1.0, 2.0], u).unwrap();
        let d = Distance::of_curve(&c);
        assert!((0.0..=end).contains(&d.max_at), "{d:?}");
        assert_eq!(d.max, 5.0);
        assert!(d.rms > 0.0 && d.rms <= d.max, "{d:?}");
    }

    #[test]
    fn constant_offset_has_equal_max_and_rms() {
        // A curve with all control points at (3, 4) is the constant (3, 4).
        let c = NurbsCurve::try_clamped(3, vec![[3.0, 4.0]; 6], vec![1.0, 2.0, 0.5, 1.0, 3.0, 1.0])
            .unwrap();
        let d = Distance::of_curve(&c);
        assert!(
            (d.max - 5.0).abs() < 1e-14 && (d.rms - 5.0).abs() < 1e-14,
            "{d:?}"
        );
    }

    #[test]
    fn line_from_zero_has_known_max_and_rms() {
        // d(t) = 2t on [0, 1]: max 2 at t = 1, rms = √(∫ 4t² dt) = 2/√3.
        let c = NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [0.0, 2.0]], vec![1.0, 1.0]).unwrap();
        let d = Distance::of_curve(&c);
        assert_eq!((d.max, d.max_at), (2.0, 1.0));
        assert!((d.rms - 2.0 / 3f64.sqrt()).abs() < 1e-14, "{d:?}");
    }

    #[test]
    fn a_peak_next_to_the_domain_start_is_refined() {
        // y(t) = (1 − t)² + 2.02·t(1 − t) − 0.5·t²: y' = 0.02 − 3.04·t, a
        // peak of 1 + 0.02²/6.08 at t = 0.02/3.04, inside the first scan step. The scan's
        // best point was t = 0 itself, which was never bracketed: the shipped
        // example reported 0.022423 at t = 0 for a peak of 0.022439 at 0.0074.
        let c =
            NurbsCurve::try_clamped(2, vec![[0.0, 1.0], [0.0, 1.01], [0.0, -0.5]], vec![1.0; 3])
                .unwrap();
        let d = Distance::of_curve(&c);
        assert!((d.max - (1.0 + 0.0004 / 6.08)).abs() < 1e-15, "{d:?}");
        assert!((d.max_at - 0.02 / 3.04).abs() < 1e-7, "{d:?}");
    }

    #[test]
    fn two_peaks_never_fall_below_dense_sampling() {
        // Two bumps of |y| on one span, a cubic with y control values
        // (0, 1, −r, 0) and a varying weight: whichever peak is higher, the
        // maximum must not fall below dense sampling, and some shapes must
        // need the refinement.
        let mut beaten = 0;
        for i in 0..40 {
            let r = 0.5 + i as f64 * 0.025;
            let w = 1.0 + (i % 7) as f64 * 0.3;
            let c = NurbsCurve::try_clamped(
                3,
                vec![[0.0, 0.0], [0.0, 1.0], [0.0, -r], [0.0, 0.0]],
                vec![1.0, w, 1.0, 1.0],
            )
            .unwrap();
            let d = Distance::of_curve(&c);
            let y = |t: f64| c.eval(t).unwrap()[1].abs();
            let n = 400_000;
            let dense = (0..=n).map(|k| y(k as f64 / n as f64)).fold(0.0, f64::max);
            assert!(d.max >= dense - 1e-15, "r {r}, w {w}: {d:?} vs {dense}");
            assert!((y(d.max_at) - d.max).abs() < 1e-15);
            let coarse = (0..=SCAN_STEPS)
                .map(|k| y(k as f64 / SCAN_STEPS as f64))
                .fold(0.0, f64::max);
            beaten += usize::from(d.max > coarse + 1e-9);
        }
        assert!(beaten > 0, "no shape had a peak between scan points");
    }

    #[test]
    fn interior_maximum_is_refined_between_scan_points() {
        // An asymmetric rational arch whose peak lies between scan points.
        let c = NurbsCurve::try_clamped(
            2,
            vec![[0.0, 0.0], [0.0, 2.0], [0.0, 0.0]],
            vec![1.0, 3.0, 2.0],
        )
        .unwrap();
        let d = Distance::of_curve(&c);
        let y = |t: f64| c.eval(t).unwrap()[1];
        let dense = (0..=200_000)
            .map(|i| y(i as f64 / 200_000.0))
            .fold(0.0, f64::max);
        let coarse = (0..=32).map(|i| y(i as f64 / 32.0)).fold(0.0, f64::max);
        assert!(
            d.max >= dense - 1e-15 && d.max - dense < 1e-9,
            "{d:?} vs {dense}"
        );
        assert!(
            d.max - coarse > 1e-6,
            "the scan alone was already exact: {coarse}"
        );
        assert!((y(d.max_at) - d.max).abs() < 1e-15);
    }
}
