//! The engine behind the curve types: `sample_soa`, `sample_layers`,
//! `sample_sweep` and `sample_stages`.

use super::buffer::{Fresh, SampleBuffer};
use super::params::Params;
use super::sampler::Sampler;
use super::samples::{CurveSamples, LayerSamples, StageSamples, SweepSamples};
use crate::error::Error;
use crate::fuzzy::Alpha;
use crate::nurbs::NurbsCurve;
use crate::pipeline::point_stages::PointStages;
use crate::pipeline::{FuzzyCurve, Solution};
use crate::reduction::TypeReduction;
use crate::sampling::plan::Plan;
use crate::sampling::weighted::sweep_weighted;

impl<const D: usize> NurbsCurve<D> {
    /// A [`Sampler`] for this curve: one channel per coordinate.
    #[must_use]
    pub fn sampler(&self) -> Sampler {
        let coords: Vec<Vec<f64>> = (0..D)
            .map(|d| self.control_points().iter().map(|p| p[d]).collect())
            .collect();
        Sampler::new_unchecked(self.knots(), self.weights(), &coords)
    }

    /// `C(t)` at every parameter, as one vector per coordinate, by the sampling
    /// engine ([`Sampler`]); agrees with [`NurbsCurve::eval`] to rounding.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsCurve;
    /// # use t2spline::sampling::Params;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = NurbsCurve::try_clamped(2, vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], vec![1.0, w, 1.0])?;
    /// let s = c.sample_soa(Params::Uniform(1001))?;
    /// assert!(s.points().all(|[x, y]| (x.hypot(y) - 1.0).abs() < 1e-14));
    /// let t = [0.9, 0.1, 0.5]; // any order
    /// let s = c.sample_soa(&t)?;
    /// assert!((s.coord(0)[0] - c.eval(0.9)?[0]).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_soa<'a>(&self, params: impl Into<Params<'a>>) -> Result<CurveSamples<D>, Error> {
        let mut out = CurveSamples::empty();
        self.sample_soa_into(params, &mut out)?;
        Ok(out)
    }

    /// [`NurbsCurve::sample_soa`] into `out`, reusing its vectors: repeated
    /// sampling then touches no fresh memory. On error `out` is left empty.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    pub fn sample_soa_into<'a>(
        &self,
        params: impl Into<Params<'a>>,
        out: &mut CurveSamples<D>,
    ) -> Result<(), Error> {
        let mut buffers: Vec<SampleBuffer> = std::mem::replace(out, CurveSamples::empty())
            .into_buffers()
            .collect();
        let mut coords = self
            .sampler()
            .sample_buffers(params, &mut buffers, Fresh::HugePages)?
            .into_iter();
        *out =
            CurveSamples::from_coords(std::array::from_fn(|_| coords.next().unwrap_or_default()));
        Ok(())
    }
}

impl<const D: usize> FuzzyCurve<D> {
    /// The seven layer curves (stage 1) at every parameter, from one power form
    /// of the rational basis shared by all of them (see [`Sampler`]). Agrees with
    /// [`FuzzyCurve::eval_layers`] to rounding, and keeps the docs/method.md §1 order of
    /// the seven values exactly at every parameter.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzyCurve, Layer, Nt2Number, Nt2Point};
    /// # use t2spline::sampling::Params;
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
    /// let points = vec![
    ///     Nt2Point::new([n(0.0)?, n(0.0)?]),
    ///     Nt2Point::new([n(1.0)?, n(2.0)?]),
    ///     Nt2Point::new([n(2.0)?, n(0.0)?]),
    /// ];
    /// let c = FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 1.0], None)?;
    /// let s = c.sample_layers(Params::Uniform(3))?;
    /// assert_eq!(s[Layer::Crisp].point(1), Some([1.0, 1.0]));
    /// assert_eq!(s[Layer::UpperRight].point(1), Some([3.0, 3.0]));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_layers<'a>(
        &self,
        params: impl Into<Params<'a>>,
    ) -> Result<LayerSamples<D>, Error> {
        Ok(sweep(self, params.into(), &[], true, Vec::new(), Fresh::HugePages)?.layers)
    }

    /// [`FuzzyCurve::sample_layers`] into `out`, reusing its vectors: repeated
    /// sampling then touches no fresh memory. On error `out` is left empty.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    pub fn sample_layers_into<'a>(
        &self,
        params: impl Into<Params<'a>>,
        out: &mut LayerSamples<D>,
    ) -> Result<(), Error> {
        let buffers = std::mem::replace(out, LayerSamples::empty())
            .into_buffers()
            .collect();
        *out = sweep(self, params.into(), &[], true, buffers, Fresh::HugePages)?.layers;
        Ok(())
    }

    /// [`FuzzyCurve::sample_layers`] into memory the caller owns: `out` holds
    /// `7·D` slices, each as long as `params`, and `out[k·D + d]` receives
    /// coordinate `d` of the layer [`Layer::ALL`](crate::Layer::ALL)`[k]`
    /// (the order of docs/method.md §1, from `upper_left` to `upper_right`).
    /// Front ends that keep their own arrays (the Python bindings write into
    /// one buffer that numpy then owns) get the engine's output without a
    /// copy. The values are those of `sample_layers`, bit
    /// for bit.
    ///
    /// # Errors
    /// [`Error::Length`] if `out` has the wrong number or length of slices;
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzyCurve, Layer, Nt2Number, Nt2Point};
    /// # use t2spline::sampling::Params;
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(2.0)?, n(4.0)?])];
    /// let c = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let mut buffer = vec![0.0; 7 * 2 * 3]; // layer, coordinate, parameter
    /// let mut out: Vec<&mut [f64]> = buffer.chunks_mut(3).collect();
    /// c.sample_layers_into_slices(Params::Uniform(3), &mut out)?;
    /// let k = Layer::UpperRight.index();
    /// assert_eq!(&buffer[(k * 2 + 1) * 3..][..3], [2.0, 4.0, 6.0]); // y of upper_right
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_layers_into_slices<'a>(
        &self,
        params: impl Into<Params<'a>>,
        out: &mut [&mut [f64]],
    ) -> Result<(), Error> {
        if out.len() != 7 * D {
            return Err(Error::Length {
                what: "output slices (one per coordinate of each layer)",
                expected: 7 * D,
                found: out.len(),
            });
        }
        if self.weight_numbers().is_some() {
            let samples = self.sample_layers(params)?;
            for (k, layer) in crate::Layer::ALL.into_iter().enumerate() {
                for (d, from) in samples[layer].coords().iter().enumerate() {
                    let to = out.get_mut(k * D + d).map(|s| &mut **s);
                    match to {
                        Some(to) if to.len() == from.len() => to.copy_from_slice(from),
                        _ => {
                            return Err(Error::Length {
                                what: "an output slice (one value per parameter)",
                                expected: from.len(),
                                found: to.map_or(0, |s| s.len()),
                            })
                        }
                    }
                }
            }
            return Ok(());
        }
        let plan = Plan::new(self.points(), &[], true);
        // The plan orders its channels its own way.
        let mut ordered = plan.by_layer(out);
        let params = params.into();
        // The same sampler as `sample_layers`, so that both agree bit for bit.
        Sampler::for_count_unchecked(self.knots(), self.weights(), plan.values(), params.len())
            .with_bounds(plan.bounds())?
            .sample_into(params, &mut ordered)
    }

    /// Runs stages 2–4 at every level of `alphas` and samples, at `params`, the
    /// seven stage-1 layer curves and every curve of every level: the alpha-cut
    /// layers, the type-reduced left and right curves and the defuzzified curve
    /// (docs/method.md §7). The stages act on the control points, as
    /// [`FuzzyCurve::solve`] does, so mixed lower heights are handled too; all
    /// curves share one power form of the rational basis, so each further level
    /// costs one Horner evaluation per coordinate of each of its curves.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, FuzzyCurve, Layer, Nt2Number, Nt2Point, Side};
    /// # use t2spline::sampling::Params;
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1.0)?, n(2.0)?]), Nt2Point::new([n(2.0)?, n(0.0)?])];
    /// let c = FuzzyCurve::try_new(2, points, vec![1.0, 2.0, 1.0], None)?;
    /// let alphas: Vec<Alpha> = (0..=10).map(|k| Alpha::try_new(k as f64 / 10.0)).collect::<Result<_, _>>()?;
    /// let sweep = c.sample_sweep(Params::Uniform(101), &alphas)?;
    /// let top = &sweep.levels()[10]; // alpha = 1: everything collapses onto the crisp curve
    /// assert!(top.alpha_cut(Layer::LowerLeft).is_none()); // 1 > h = 0.5
    /// let crisp = &sweep.layers()[Layer::Crisp];
    /// let solved = top.defuzzified();
    /// assert!((0..101).all(|i| (solved.coord(1)[i] - crisp.coord(1)[i]).abs() < 1e-14));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_sweep<'a>(
        &self,
        params: impl Into<Params<'a>>,
        alphas: &[Alpha],
    ) -> Result<SweepSamples<D>, Error> {
        self.sample_sweep_with(params, alphas, TypeReduction::Paper)
    }

    /// [`FuzzyCurve::sample_sweep`] with the type reduction `method` (docs/method.md
    /// §9): every level's stages as [`FuzzyCurve::solve_with`] computes
    /// them. Only the paper's reduction depends on alpha; with the others,
    /// the levels differ in their alpha-cut curves only.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point, Side, TypeReduction};
    /// # use t2spline::sampling::Params;
    /// // Long right sides: the centroid lies right of crisp, both ends of it.
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 0.1, c + 3.0], [c - 0.05, c + 2.0], [c, c + 1.0], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(2.0)?, n(1.0)?])];
    /// let c = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let sweep = c.sample_sweep_with(Params::Uniform(5), &[Alpha::try_new(0.0)?], TypeReduction::Centroid)?;
    /// let (crisp, level) = (&sweep.layers()[t2spline::Layer::Crisp], &sweep.levels()[0]);
    /// let left = level.type_reduced(Side::Left);
    /// assert!((0..5).all(|i| matches!((left.point(i), crisp.point(i)), (Some(l), Some(c)) if l[0] > c[0])));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_sweep_with<'a>(
        &self,
        params: impl Into<Params<'a>>,
        alphas: &[Alpha],
        method: TypeReduction,
    ) -> Result<SweepSamples<D>, Error> {
        let solutions: Vec<Solution<D>> =
            alphas.iter().map(|&a| self.solve_with(a, method)).collect();
        sweep(
            self,
            params.into(),
            &solutions,
            true,
            Vec::new(),
            Fresh::HugePages,
        )
    }

    /// [`FuzzyCurve::sample_sweep`] into `out`, reusing its vectors: repeated
    /// sweeps then touch no fresh memory. On error `out` is left empty. The
    /// paper's type reduction.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    pub fn sample_sweep_into<'a>(
        &self,
        params: impl Into<Params<'a>>,
        alphas: &[Alpha],
        out: &mut SweepSamples<D>,
    ) -> Result<(), Error> {
        let buffers = std::mem::replace(out, SweepSamples::empty()).into_buffers();
        let solutions: Vec<Solution<D>> = alphas.iter().map(|&a| self.solve(a)).collect();
        *out = sweep(
            self,
            params.into(),
            &solutions,
            true,
            buffers,
            Fresh::HugePages,
        )?;
        Ok(())
    }
}

impl<const D: usize> Solution<D> {
    /// The curves of stages 2–4 at this level, sampled at `params` (see
    /// [`FuzzyCurve::sample_sweep`] for many levels at once).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first parameter outside the domain.
    pub fn sample_stages<'a>(
        &self,
        params: impl Into<Params<'a>>,
    ) -> Result<StageSamples<D>, Error> {
        let sweep = sweep(
            self.fuzzy_curve(),
            params.into(),
            std::slice::from_ref(self),
            false,
            Vec::new(),
            Fresh::HugePages,
        )?;
        let (_, levels) = sweep.into_parts();
        // One solution was sampled, so there is one level.
        #[allow(clippy::expect_used)]
        Ok(levels.into_iter().next().expect("one level was asked for"))
    }

    /// The seven stage-1 layer curves and this solution's curves of stages
    /// 2–4, from one sampler (what a run samples), in ordinary vectors: a
    /// run's output takes them as `Vec<f64>` without a copy.
    pub(crate) fn sample_with_layers(&self, params: Params<'_>) -> Result<SweepSamples<D>, Error> {
        sweep(
            self.fuzzy_curve(),
            params,
            std::slice::from_ref(self),
            true,
            Vec::new(),
            Fresh::Vectors,
        )
    }
}

/// Samples the crisp curve, the six other layers if `layers`, and the curves of
/// stages 2–4 of every solution, with one sampler (with fuzzy weights, one
/// per curve: `weighted.rs`), into buffers taken from
/// `buffers` where it has them and new ones from `fresh`.
fn sweep<const D: usize>(
    curve: &FuzzyCurve<D>,
    params: Params<'_>,
    solutions: &[Solution<D>],
    layers: bool,
    mut buffers: Vec<SampleBuffer>,
    fresh: Fresh,
) -> Result<SweepSamples<D>, Error> {
    if curve.weight_numbers().is_some() {
        return sweep_weighted(curve, params, solutions, layers, buffers, fresh);
    }
    let stages: Vec<&PointStages<D>> = solutions.iter().map(Solution::stages).collect();
    let plan = Plan::new(curve.points(), &stages, layers);
    let sampler =
        Sampler::for_count_unchecked(curve.knots(), curve.weights(), plan.values(), params.len())
            .with_bounds(plan.bounds())?;
    let out = sampler.sample_buffers(params, &mut buffers, fresh)?;
    Ok(plan.assemble(out))
}
