//! Adaptive Gauss–Kronrod quadrature (7-point Gauss, 15-point Kronrod;
//! Piessens et al., QUADPACK, QK15) with a bounded amount of work.
//!
//! ```text
//! ∫ₐᵇ f ≈ K₁₅,  error estimate |K₁₅ − G₇|
//! ```
//! An interval whose estimate exceeds its share `tol·(b − a)` of the tolerance
//! is bisected. The estimate bounds the error of the Gauss rule; the Kronrod
//! value that is kept is far more accurate for smooth integrands. The work is
//! bounded twice: by a depth (2⁻⁴⁰ of the interval) and by a count of
//! bisections the caller grants, so that an integrand made noisy by rounding,
//! whose estimate never meets the tolerance, still ends in bounded time (pieces
//! left when the budget runs out keep their Kronrod value).

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
/// Bisections allowed below one interval given to [`integrate`].
const MAX_DEPTH: u32 = 40;

/// `(K₁₅, |K₁₅ − G₇|)` for `∫ₐᵇ f`.
pub(crate) fn gauss_kronrod(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let (centre, half) = ((a + b) / 2.0, (b - a) / 2.0);
    let mut kronrod = 0.0;
    let mut gauss = 0.0;
    for (j, (x, w)) in XGK.iter().zip(WGK).enumerate() {
        let sum = if *x == 0.0 {
            f(centre)
        } else {
            f(centre - half * x) + f(centre + half * x)
        };
        kronrod += w * sum;
        if j % 2 == 1 {
            gauss += WG[j / 2] * sum;
        }
    }
    (kronrod * half, ((kronrod - gauss) * half).abs())
}

/// `∫ₐᵇ f` to the absolute tolerance `tol` per unit of the variable: every
/// piece is bisected until `err ≤ tol·width`, using at most `budget`
/// bisections (which it counts down).
pub(crate) fn integrate(
    f: &impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    tol: f64,
    budget: &mut usize,
) -> f64 {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kronrod_is_exact_for_polynomials_of_degree_22() {
        // ∫₀¹ x²² dx = 1/23.
        let (k, _) = gauss_kronrod(&|x: f64| x.powi(22), 0.0, 1.0);
        assert!((k - 1.0 / 23.0).abs() < 1e-16, "{k}");
    }

    #[test]
    fn adaptive_meets_its_tolerance_on_a_peak() {
        // ∫₀¹ 1/(1e-4 + (x − 0.3)²) dx = 100·(atan(70) + atan(30)).
        let exact = 100.0 * (70f64.atan() + 30f64.atan());
        let mut budget = 1000;
        let f = |x: f64| 1.0 / (1e-4 + (x - 0.3) * (x - 0.3));
        let v = integrate(&f, 0.0, 1.0, 1e-10, &mut budget);
        assert!((v - exact).abs() < 1e-10, "{v} vs {exact}");
        assert!(budget < 1000, "no bisection was needed?");
    }

    #[test]
    fn an_exhausted_budget_stops_the_work() {
        let mut budget = 3;
        let noisy = |x: f64| if (x * 1e9).fract() < 0.5 { 0.0 } else { 1.0 };
        let v = integrate(&noisy, 0.0, 1.0, 0.0, &mut budget);
        assert_eq!(budget, 0);
        assert!(v.is_finite());
    }
}
