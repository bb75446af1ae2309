//! The distance between the crisp and the defuzzified curve (or surface) of
//! the paper's type reduction at many levels alpha, sampled: what a figure of
//! the distance against alpha draws (docs/method.md §7, stage 4).
//!
//! A run computes `error.max` and `error.rms` exactly, independent of
//! sampling ([`crate::Distance`], [`crate::SurfaceDistance`]); a figure needs
//! them at a hundred levels and more, for curves of a hundred thousand
//! control points, where the exact searches would take seconds. Here the
//! distance `d = ‖D − C‖` is sampled at uniform parameters by the sampling
//! engine (the crisp control points and the defuzzified ones of several
//! levels in one [`Sampler`](crate::sampling::Sampler) pass), and summarised
//! by one rule for curves and surfaces alike ([`DistanceSweep::summary`]):
//!
//! ```text
//! max ≈ maxᵢ d(tᵢ),   rms ≈ √( Σᵢ ωᵢ d(tᵢ)² / Σᵢ ωᵢ )
//! ```
//! the trapezoidal rule, `ω = ½` at both ends of each direction and 1 inside
//! (on a grid the product of the two directions' weights). At the figures'
//! sampling both are within a fraction of a per cent of the exact values.

use super::params::Params;
use super::sampler::Sampler;
use crate::error::Error;
use crate::fuzzy::Alpha;
use crate::nurbs::NurbsSurface;
use crate::pipeline::{FuzzyCurve, FuzzySurface};
use crate::vector::euclidean_norm;

/// Levels sampled together: bounds the memory of a sweep over many alphas
/// (one array per coordinate and level).
const LEVELS_PER_PASS: usize = 8;

/// The sampled distance between the crisp and the defuzzified curve or
/// surface at each of several levels.
#[derive(Clone, Debug, PartialEq)]
pub struct DistanceSweep {
    /// The sample shape `[1, n]` for a curve, `[su, sv]` for a surface's grid
    /// (`v` fastest).
    shape: [usize; 2],
    /// One list of `su·sv` distances per level, in the order of the levels.
    levels: Vec<Vec<f64>>,
}

impl DistanceSweep {
    /// The distances at level `k` (in the order the levels were given), one
    /// per sample: along the curve, or row by row on the grid.
    #[must_use]
    pub fn distances(&self, k: usize) -> Option<&[f64]> {
        self.levels.get(k).map(Vec::as_slice)
    }

    /// The number of levels.
    #[must_use]
    pub fn len(&self) -> usize {
        self.levels.len()
    }

    /// Whether no level was given.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.levels.is_empty()
    }

    /// `[max, rms]` of each level by the trapezoidal rule of the module
    /// docs; `[0, 0]` where the distance is zero everywhere. The squares are
    /// taken of `d / max`, so that neither a distance near 1e-170 underflows
    /// nor one near 1e300 overflows.
    #[must_use]
    pub fn summary(&self) -> Vec<[f64; 2]> {
        let [su, sv] = self.shape;
        let end = |i: usize, n: usize| if i == 0 || i + 1 == n { 0.5 } else { 1.0 };
        self.levels
            .iter()
            .map(|d| {
                let max = d.iter().copied().fold(0.0, f64::max);
                if max <= 0.0 {
                    return [0.0, 0.0];
                }
                let (mut sum, mut weight) = (0.0, 0.0);
                for (i, &v) in d.iter().enumerate() {
                    let w = end(i / sv, su) * end(i % sv, sv);
                    let s = v / max;
                    sum += w * s * s;
                    weight += w;
                }
                [max, max * (sum / weight).sqrt()]
            })
            .collect()
    }
}

impl<const D: usize> FuzzyCurve<D> {
    /// The distance between the crisp curve and the defuzzified curve of
    /// the paper's type reduction at each of `alphas`, at `samples` uniform
    /// parameters (the module docs say how it is summarised).
    ///
    /// # Errors
    /// [`Error::Memory`] if the samples cannot be allocated; the sampling
    /// engine's errors (never for a validated curve).
    ///
    /// # Examples
    /// A curve whose every number is shifted by its spread: the distance is
    /// the same at every parameter.
    /// ```
    /// # use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c, c], [c, c], 1.0);
    /// let points = vec![Nt2Point::new([n(0.0)?]), Nt2Point::new([n(1.0)?])];
    /// let c = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let sweep = c.distance_sweep(&[Alpha::ZERO], 11)?;
    /// let [max, rms] = sweep.summary()[0];
    /// // left = (−1 + 0 + 0)/3, right = (2 + 0 + 0)/3: defuzzified = c + 1/9.
    /// assert!((max - 1.0 / 9.0).abs() < 1e-15 && (rms - 1.0 / 9.0).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn distance_sweep(&self, alphas: &[Alpha], samples: usize) -> Result<DistanceSweep, Error> {
        if self.weight_numbers().is_some() {
            return self.distance_sweep_weighted(alphas, samples);
        }
        let column = |pts: &[[f64; D]], d: usize| pts.iter().map(|p| p[d]).collect::<Vec<f64>>();
        let crisp: Vec<[f64; D]> = self.points().iter().map(|p| p.crisp()).collect();
        let mut levels = Vec::with_capacity(alphas.len());
        for pass in alphas.chunks(LEVELS_PER_PASS) {
            let mut channels: Vec<Vec<f64>> = (0..D).map(|k| column(&crisp, k)).collect();
            for &a in pass {
                let s = self.solve(a);
                channels.extend((0..D).map(|k| column(s.defuzzified_points(), k)));
            }
            let sampler = Sampler::try_new(self.knots(), self.weights(), &channels)?;
            let values = sampler.sample(Params::Uniform(samples))?;
            for l in 0..pass.len() {
                let d = (0..samples)
                    .map(|i| {
                        let diff: [f64; D] =
                            std::array::from_fn(|k| values[D * (l + 1) + k][i] - values[k][i]);
                        euclidean_norm(&diff)
                    })
                    .collect();
                levels.push(d);
            }
        }
        Ok(DistanceSweep {
            shape: [1, samples],
            levels,
        })
    }
}

impl<const D: usize> FuzzyCurve<D> {
    /// [`FuzzyCurve::distance_sweep`] with fuzzy weights (docs/method.md
    /// §16): the crisp and each defuzzified curve have weights of their own,
    /// so each is sampled by its own sampler.
    fn distance_sweep_weighted(
        &self,
        alphas: &[Alpha],
        samples: usize,
    ) -> Result<DistanceSweep, Error> {
        let crisp = self.crisp_curve().sample_soa(Params::Uniform(samples))?;
        let levels = alphas
            .iter()
            .map(|&a| {
                let solved = self
                    .solve(a)
                    .defuzzified_curve()
                    .sample_soa(Params::Uniform(samples))?;
                Ok((0..samples)
                    .map(|i| {
                        let diff: [f64; D] =
                            std::array::from_fn(|k| solved.coord(k)[i] - crisp.coord(k)[i]);
                        euclidean_norm(&diff)
                    })
                    .collect())
            })
            .collect::<Result<Vec<Vec<f64>>, Error>>()?;
        Ok(DistanceSweep {
            shape: [1, samples],
            levels,
        })
    }
}

impl<const D: usize> FuzzySurface<D> {
    /// The distance between the crisp surface and the defuzzified surface of
    /// the paper's type reduction at each of `alphas`, on the grid of `su × sv`
    /// uniform parameters `(u, v)` (the module docs say how it is
    /// summarised).
    ///
    /// # Errors
    /// [`Error::Memory`] if the grid cannot be allocated; the grid engine's
    /// errors (never for a validated surface).
    pub fn distance_sweep(
        &self,
        alphas: &[Alpha],
        [su, sv]: [usize; 2],
    ) -> Result<DistanceSweep, Error> {
        let grid = |x: &NurbsSurface<D>| {
            x.sample_grid(Params::Uniform(su), Params::Uniform(sv))
                .map(crate::sampling::Grid::into_samples)
        };
        let crisp = grid(&self.crisp_surface())?;
        let levels = alphas
            .iter()
            .map(|&a| {
                let d = grid(&self.solve(a).defuzzified_surface())?;
                Ok(d.points()
                    .zip(crisp.points())
                    .map(|(p, q)| {
                        euclidean_norm(&std::array::from_fn::<f64, D, _>(|k| p[k] - q[k]))
                    })
                    .collect())
            })
            .collect::<Result<Vec<Vec<f64>>, Error>>()?;
        Ok(DistanceSweep {
            shape: [su, sv],
            levels,
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::fuzzy::{Alpha, Nt2Number, Nt2Point};
    use crate::pipeline::FuzzyCurve;

    /// A line whose first number is shifted by its spread and whose second is
    /// crisp: `d(t) = (1 − t)/9` on `[0, 1]`.
    fn wedge() -> FuzzyCurve<1> {
        let a = Nt2Number::try_new(0.0, [-1.0, 2.0], [0.0, 0.0], [0.0, 0.0], 1.0).unwrap();
        let b = Nt2Number::try_crisp(1.0).unwrap();
        FuzzyCurve::try_new(
            1,
            vec![Nt2Point::new([a]), Nt2Point::new([b])],
            vec![1.0; 2],
            None,
        )
        .unwrap()
    }

    #[test]
    fn the_trapezoidal_rms_of_a_linear_distance_converges_to_the_integral() {
        // rms = √(∫₀¹ ((1 − t)/9)² dt) = 1/(9√3); the trapezoidal rule errs by
        // O(1/n²), 1/(6n²) of the mean square here.
        let exact = 1.0 / (9.0 * 3.0_f64.sqrt());
        for n in [11, 101, 1001] {
            let sweep = wedge().distance_sweep(&[Alpha::ZERO], n).unwrap();
            let [max, rms] = sweep.summary()[0];
            assert!((max - 1.0 / 9.0).abs() < 1e-15);
            let h = 1.0 / (n - 1) as f64;
            assert!(
                (rms / exact - 1.0).abs() <= 0.5 * h * h + 1e-12,
                "{n}: {rms}"
            );
        }
    }

    #[test]
    fn each_level_is_its_own_and_a_crisp_level_has_no_distance() {
        let levels: Vec<Alpha> = (0..=20)
            .map(|k| Alpha::try_new(k as f64 / 20.0).unwrap())
            .collect();
        let sweep = wedge().distance_sweep(&levels, 5).unwrap();
        assert_eq!(sweep.len(), 21);
        for (k, a) in levels.iter().enumerate() {
            let d = sweep.distances(k).unwrap();
            // At alpha the first number's cut is [−(1 − α), 2(1 − α)].
            let expected = (1.0 - a.get()) / 9.0;
            assert!((d[0] - expected).abs() < 1e-15, "{k}: {}", d[0]);
            assert_eq!(d[4], 0.0);
        }
        assert_eq!(sweep.summary()[20], [0.0, 0.0]);
        assert!(sweep.distances(21).is_none());
    }
}
