//! Gauss–Legendre rules and adaptive tensor-product cubature on rectangles,
//! used for the mean square distance between two surfaces
//! ([`crate::SurfaceDistance`]).

/// Nodes and weights of `n`-point Gauss–Legendre quadrature on `[−1, 1]`, by
/// Newton's method on the Legendre polynomial `Pₙ` from Tricomi's initial
/// guesses (Abramowitz and Stegun 22.16.6; three-term recurrence 22.7.10):
///
/// ```text
/// P_k(x) = ((2k − 1)·x·P_{k−1}(x) − (k − 1)·P_{k−2}(x)) / k,   Pₙ'(x) = n·(x·Pₙ − P_{n−1}) / (x² − 1)
/// wᵢ = 2 / ((1 − xᵢ²)·Pₙ'(xᵢ)²)
/// ```
/// The rule is exact for polynomials of degree up to `2n − 1`.
pub(crate) fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let legendre = |x: f64| {
        let (mut p, mut previous) = (x, 1.0);
        for k in 2..=n {
            let k = k as f64;
            (p, previous) = (((2.0 * k - 1.0) * x * p - (k - 1.0) * previous) / k, p);
        }
        (p, n as f64 * (x * p - previous) / (x * x - 1.0))
    };
    (1..=n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 - 0.25) / (n as f64 + 0.5)).cos();
            for _ in 0..100 {
                let (p, dp) = legendre(x);
                let dx = p / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            let dp = legendre(x).1;
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .unzip()
}

/// Points per direction of the tensor rule: exact for polynomials of degree
/// 15 in each variable, so a polynomial patch of degrees up to 7 gives its
/// squared distance exactly.
const POINTS: usize = 8;

/// The deepest subdivision (cells of `4⁻¹²` of the rectangle).
const MAX_DEPTH: u32 = 12;

/// The mean of `f` over the unit square `[0, 1]²`, adaptively: a cell's
/// tensor Gauss–Legendre value is compared with the sum over its four
/// quarters; where they differ by more than the cell's share of
/// `tolerance`, each quarter is treated the same way. Each accepted cell
/// keeps the sum over its quarters, so the result's error is about the
/// sum of the accepted differences, at most `tolerance` (plus rounding)
/// unless `budget` subdivisions or the depth [`MAX_DEPTH`] run out first.
pub(crate) struct Cubature {
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl Cubature {
    pub(crate) fn new() -> Self {
        let (x, w) = gauss_legendre(POINTS);
        // On [0, 1]: nodes (1 + x)/2, weights w/2.
        Cubature {
            nodes: x.iter().map(|x| (1.0 + x) / 2.0).collect(),
            weights: w.iter().map(|w| w / 2.0).collect(),
        }
    }

    /// The mean of `f` over the cell `[u₀, u₀ + h] × [v₀, v₀ + h]` of the unit
    /// square, times the cell's area `h²`.
    fn cell(&self, f: &impl Fn(f64, f64) -> f64, [u, v]: [f64; 2], h: f64) -> f64 {
        let mut sum = 0.0;
        for (x, wx) in self.nodes.iter().zip(&self.weights) {
            for (y, wy) in self.nodes.iter().zip(&self.weights) {
                sum += wx * wy * f(u + h * x, v + h * y);
            }
        }
        sum * h * h
    }

    /// The mean of `f` over `[0, 1]²` to about `tolerance` (absolute), using
    /// at most `budget` subdivisions (decremented).
    pub(crate) fn mean(
        &self,
        f: &impl Fn(f64, f64) -> f64,
        tolerance: f64,
        budget: &mut usize,
    ) -> f64 {
        let whole = self.cell(f, [0.0, 0.0], 1.0);
        self.refine(f, [0.0, 0.0], 1.0, whole, tolerance, budget, 0)
    }

    #[allow(clippy::too_many_arguments)]
    fn refine(
        &self,
        f: &impl Fn(f64, f64) -> f64,
        at: [f64; 2],
        h: f64,
        whole: f64,
        tolerance: f64,
        budget: &mut usize,
        depth: u32,
    ) -> f64 {
        let half = h / 2.0;
        let corners = [
            at,
            [at[0] + half, at[1]],
            [at[0], at[1] + half],
            [at[0] + half, at[1] + half],
        ];
        let parts = corners.map(|c| self.cell(f, c, half));
        let sum: f64 = parts.iter().sum();
        if (sum - whole).abs() <= tolerance || *budget == 0 || depth >= MAX_DEPTH {
            return sum;
        }
        *budget -= 1;
        corners
            .iter()
            .zip(parts)
            .map(|(&c, part)| self.refine(f, c, half, part, tolerance / 4.0, budget, depth + 1))
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_degree_15_exactly() {
        let (x, w) = gauss_legendre(8);
        assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14);
        let i: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(14)).sum();
        assert!((i - 2.0 / 15.0).abs() < 1e-14, "{i}");
    }

    #[test]
    fn mean_of_smooth_and_peaked_functions() {
        let c = Cubature::new();
        let mut budget = 10_000;
        // A polynomial of degree 15 in each variable: exact at once.
        let m = c.mean(&|u, v| u.powi(15) * v.powi(14), 1e-15, &mut budget);
        assert!((m - 1.0 / 16.0 / 15.0).abs() < 1e-16, "{m}");
        // A narrow rational peak: 1/(1 + 400·((u − 0.3)² + (v − 0.6)²)), whose
        // mean over the square is close to π/400·ln(…); compared with a much
        // tighter run.
        let f = |u: f64, v: f64| 1.0 / (1.0 + 400.0 * ((u - 0.3).powi(2) + (v - 0.6).powi(2)));
        let loose = c.mean(&f, 1e-13, &mut budget);
        let mut more = 100_000;
        let tight = c.mean(&f, 1e-16, &mut more);
        assert!((loose - tight).abs() < 2e-13, "{loose} {tight}");
        assert!(budget < 10_000, "the peak needed subdivision");
    }
}
