//! The engine behind the curve types: `sample_soa`, `sample_layers`,
//! `sample_sweep` and `sample_stages`.

use crate::error::Error;
use crate::fuzzy::{Alpha, Layer, Layers};
use crate::nurbs::NurbsCurve;
use crate::pipeline::{FuzzyCurve, Side, Solution};
use crate::sampling::{
    Bound, CurveSamples, LayerSamples, Params, Sampler, StageSamples, SweepSamples,
};

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
    /// assert!((s.point(0)[0] - c.eval(0.9)?[0]).abs() < 1e-15);
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
        let mut buffers: Vec<Vec<f64>> = std::mem::replace(out, CurveSamples::empty())
            .into_buffers()
            .collect();
        let mut coords = self
            .sampler()
            .sample_reusing(params, &mut buffers)?
            .into_iter();
        *out =
            CurveSamples::from_coords(std::array::from_fn(|_| coords.next().unwrap_or_default()));
        Ok(())
    }
}

impl<const D: usize> FuzzyCurve<D> {
    /// The seven layer curves (stage 1) at every parameter, from one power form
    /// of the rational basis shared by all of them (see [`Sampler`]). Agrees with
    /// [`FuzzyCurve::eval_layers`] to rounding, and keeps the SPEC §1 order of
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
    /// assert_eq!(s[Layer::Crisp].point(1), [1.0, 1.0]);
    /// assert_eq!(s[Layer::UpperRight].point(1), [3.0, 3.0]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_layers<'a>(
        &self,
        params: impl Into<Params<'a>>,
    ) -> Result<LayerSamples<D>, Error> {
        Ok(sweep(self, params.into(), &[], true, Vec::new())?.layers)
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
        *out = sweep(self, params.into(), &[], true, buffers)?.layers;
        Ok(())
    }

    /// Runs stages 2–4 at every level of `alphas` and samples, at `params`, the
    /// seven stage-1 layer curves and every curve of every level: the alpha-cut
    /// layers, the type-reduced left and right curves and the defuzzified curve
    /// (SPEC §7). The stages act on the control points, as
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
    /// assert!((0..101).all(|i| (solved.point(i)[1] - crisp.point(i)[1]).abs() < 1e-14));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_sweep<'a>(
        &self,
        params: impl Into<Params<'a>>,
        alphas: &[Alpha],
    ) -> Result<SweepSamples<D>, Error> {
        let solutions: Vec<Solution<D>> = alphas.iter().map(|&a| self.solve(a)).collect();
        sweep(self, params.into(), &solutions, true, Vec::new())
    }

    /// [`FuzzyCurve::sample_sweep`] into `out`, reusing its vectors: repeated
    /// sweeps then touch no fresh memory. On error `out` is left empty.
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
        *out = sweep(self, params.into(), &solutions, true, buffers)?;
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
        )?;
        let (_, levels) = sweep.into_parts();
        Ok(levels.into_iter().next().expect("one level was asked for"))
    }
}

/// The channels of a sampling job, D per curve, and the bounds that keep them
/// in order.
struct Channels<const D: usize> {
    values: Vec<Vec<f64>>,
    bounds: Vec<Bound>,
}

impl<const D: usize> Channels<D> {
    /// Adds a curve through `points`; returns the channel of its x coordinate.
    fn push(&mut self, points: &[[f64; D]]) -> usize {
        let base = self.values.len();
        for d in 0..D {
            self.values.push(points.iter().map(|p| p[d]).collect());
        }
        base
    }

    /// Bounds curve `curve` (per coordinate) from below by `at_least` and from
    /// above by `at_most`.
    fn bound(&mut self, curve: usize, at_least: Option<usize>, at_most: Option<usize>) {
        for d in 0..D {
            self.bounds.push(Bound {
                channel: curve + d,
                at_least: at_least.map(|c| c + d),
                at_most: at_most.map(|c| c + d),
            });
        }
    }

    /// Bounds a chain of layer curves outwards from the crisp one: each left
    /// layer at most its inner neighbour, each right layer at least its inner
    /// neighbour (SPEC §1 order). `curves[layer]` is `None` for a missing layer.
    fn bound_layers(&mut self, curves: &Layers<Option<usize>>, crisp: usize) {
        let mut inner = crisp;
        for layer in [Layer::LowerLeft, Layer::PrimaryLeft, Layer::UpperLeft] {
            if let Some(c) = curves[layer] {
                self.bound(c, None, Some(inner));
                inner = c;
            }
        }
        inner = crisp;
        for layer in [Layer::LowerRight, Layer::PrimaryRight, Layer::UpperRight] {
            if let Some(c) = curves[layer] {
                self.bound(c, Some(inner), None);
                inner = c;
            }
        }
    }
}

/// Samples the crisp curve, the six other layers if `layers`, and the curves of
/// stages 2–4 of every solution, with one sampler, into vectors taken from
/// `buffers` where it has them.
fn sweep<const D: usize>(
    curve: &FuzzyCurve<D>,
    params: Params<'_>,
    solutions: &[Solution<D>],
    layers: bool,
    mut buffers: Vec<Vec<f64>>,
) -> Result<SweepSamples<D>, Error> {
    let mut ch = Channels::<D> {
        values: Vec::new(),
        bounds: Vec::new(),
    };
    let layer_of = |l: Layer| {
        curve
            .points()
            .iter()
            .map(|p| p.layer(l))
            .collect::<Vec<_>>()
    };
    let crisp = ch.push(&layer_of(Layer::Crisp));
    let stage1: Layers<Option<usize>> = Layers::from_fn(|l| match l {
        Layer::Crisp => Some(crisp),
        _ if layers => Some(ch.push(&layer_of(l))),
        _ => None,
    });
    ch.bound_layers(&stage1, crisp);
    let mut level_channels = Vec::with_capacity(solutions.len());
    for s in solutions {
        let cut: Layers<Option<usize>> = Layers::from_fn(|l| match l {
            Layer::Crisp => None,
            _ => s.alpha_cut_layer(l).map(|points| ch.push(&points)),
        });
        ch.bound_layers(&cut, crisp);
        let left = ch.push(&s.type_reduced_side(Side::Left));
        let right = ch.push(&s.type_reduced_side(Side::Right));
        let defuzzified = ch.push(s.defuzzified_points());
        ch.bound(left, None, Some(crisp));
        ch.bound(right, Some(crisp), None);
        ch.bound(defuzzified, Some(left), Some(right));
        level_channels.push((s.alpha(), cut, left, right, defuzzified));
    }
    let sampler =
        Sampler::for_count_unchecked(curve.knots(), curve.weights(), &ch.values, params.len())
            .with_bounds(&ch.bounds)
            .expect("the bounds name channels just made");
    let mut out: Vec<Option<Vec<f64>>> = sampler
        .sample_reusing(params, &mut buffers)?
        .into_iter()
        .map(Some)
        .collect();
    let mut take = |base: usize| {
        CurveSamples::from_coords(std::array::from_fn(|d| {
            out[base + d].take().expect("each channel is taken once")
        }))
    };
    let layers = LayerSamples {
        layers: Layers::from_fn(|l| {
            // Without `layers`, only the crisp curve was sampled; the others stay
            // empty and are dropped by `Solution::sample_stages`.
            stage1[l].map_or_else(
                || CurveSamples::from_coords(std::array::from_fn(|_| Vec::new())),
                &mut take,
            )
        }),
    };
    let levels = level_channels
        .into_iter()
        .map(|(alpha, cut, left, right, defuzzified)| StageSamples {
            alpha,
            alpha_cut: cut.map(|c| c.map(&mut take)),
            type_reduced: [take(left), take(right)],
            defuzzified: take(defuzzified),
        })
        .collect();
    Ok(SweepSamples { layers, levels })
}
