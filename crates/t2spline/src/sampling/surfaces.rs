//! The grid engine behind the surface types: `sample_grid`, `sample_layers`,
//! `sample_sweep` and `sample_stages` of surfaces.

use super::buffer::{Fresh, SampleBuffer};
use super::params::Params;
use super::samples::{CurveSamples, Grid, LayerSamples, StageSamples, SweepSamples};
use crate::error::Error;
use crate::fuzzy::Alpha;
use crate::nurbs::{Direction, NurbsSurface};
use crate::pipeline::point_stages::PointStages;
use crate::pipeline::{FuzzySurface, SurfaceSolution};
use crate::reduction::TypeReduction;
use crate::sampling::plan::Plan;
use crate::sampling::weighted::grid_sweep_weighted;
use crate::sampling::GridSampler;

impl<const D: usize> NurbsSurface<D> {
    /// A [`GridSampler`] for this surface: one channel per coordinate.
    #[must_use]
    pub fn grid_sampler(&self) -> GridSampler {
        let coords: Vec<Vec<f64>> = (0..D)
            .map(|d| self.control_points().iter().map(|p| p[d]).collect())
            .collect();
        GridSampler::new_unchecked(&self.knots_pair(), self.weights(), &coords)
    }

    /// Both knot vectors.
    fn knots_pair(&self) -> [crate::KnotVector; 2] {
        Direction::BOTH.map(|d| self.knots(d).clone())
    }

    /// `S(u_a, v_b)` on the grid `u × v`, as one vector per coordinate, by the
    /// grid engine ([`GridSampler`]); agrees with [`NurbsSurface::eval`] to
    /// rounding.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] for the first
    /// parameter outside its domain.
    ///
    /// # Examples
    /// The quarter cylinder of radius 1 on a 101 × 11 grid:
    /// ```
    /// # use t2spline::NurbsSurface;
    /// # use t2spline::sampling::Params;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let net = vec![
    ///     vec![[1.0, 0.0, 0.0], [1.0, 0.0, 2.0]],
    ///     vec![[1.0, 1.0, 0.0], [1.0, 1.0, 2.0]],
    ///     vec![[0.0, 1.0, 0.0], [0.0, 1.0, 2.0]],
    /// ];
    /// let s = NurbsSurface::try_clamped([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]])?;
    /// let g = s.sample_grid(Params::Uniform(101), Params::Uniform(11))?;
    /// assert!(g.samples().points().all(|[x, y, _]| (x.hypot(y) - 1.0).abs() < 1e-15));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_grid<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
    ) -> Result<Grid<CurveSamples<D>>, Error> {
        let mut out = Grid::buffer(CurveSamples::empty());
        self.sample_grid_into(u, v, &mut out)?;
        Ok(out)
    }

    /// [`NurbsSurface::sample_grid`] into `out`, reusing its vectors. On error
    /// `out` is left empty.
    ///
    /// # Errors
    /// As [`NurbsSurface::sample_grid`].
    pub fn sample_grid_into<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
        out: &mut Grid<CurveSamples<D>>,
    ) -> Result<(), Error> {
        let (u, v) = (u.into(), v.into());
        let old = std::mem::replace(out, Grid::buffer(CurveSamples::empty()));
        let mut buffers: Vec<SampleBuffer> = old.samples.into_buffers().collect();
        let mut coords = self
            .grid_sampler()
            .sample_buffers(u, v, &mut buffers, Fresh::HugePages)?
            .into_iter();
        *out = Grid {
            shape: [u.len(), v.len()],
            samples: CurveSamples::from_coords(std::array::from_fn(|_| {
                coords.next().unwrap_or_default()
            })),
        };
        Ok(())
    }
}

impl<const D: usize> FuzzySurface<D> {
    /// The seven layer surfaces (stage 1) on the grid `u × v`, sharing one
    /// basis evaluation per grid row and column (see [`GridSampler`]); the
    /// seven values keep the docs/method.md §1 order exactly at every grid point.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] for the first
    /// parameter outside its domain.
    pub fn sample_layers<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
    ) -> Result<Grid<LayerSamples<D>>, Error> {
        let g = grid_sweep(
            self,
            u.into(),
            v.into(),
            &[],
            true,
            Vec::new(),
            Fresh::HugePages,
        )?;
        Ok(Grid {
            shape: g.shape,
            samples: g.samples.layers,
        })
    }

    /// [`FuzzySurface::sample_layers`] into `out`, reusing its vectors.
    ///
    /// # Errors
    /// As [`FuzzySurface::sample_layers`].
    pub fn sample_layers_into<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
        out: &mut Grid<LayerSamples<D>>,
    ) -> Result<(), Error> {
        let old = std::mem::replace(out, Grid::buffer(LayerSamples::empty()));
        let buffers = old.samples.into_buffers().collect();
        let g = grid_sweep(
            self,
            u.into(),
            v.into(),
            &[],
            true,
            buffers,
            Fresh::HugePages,
        )?;
        *out = Grid {
            shape: g.shape,
            samples: g.samples.layers,
        };
        Ok(())
    }

    /// [`FuzzySurface::sample_layers`] into memory the caller owns: `out`
    /// holds `7·D` slices of `u.len()·v.len()` values, and `out[k·D + d]`
    /// receives coordinate `d` of the layer
    /// [`Layer::ALL`](crate::Layer::ALL)`[k]` (the order of docs/method.md
    /// §1), `[a·sv + b]` at `(u_a, v_b)`. Front ends that keep their own
    /// arrays (the Python bindings) get the engine's output without a copy;
    /// the values are those of `sample_layers`, bit for bit.
    ///
    /// # Errors
    /// [`Error::Length`] if `out` has the wrong number or length of slices;
    /// as [`FuzzySurface::sample_layers`] otherwise.
    pub fn sample_layers_into_slices<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
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
            let grid = self.sample_layers(u, v)?;
            for (k, layer) in crate::Layer::ALL.into_iter().enumerate() {
                for (d, from) in grid.samples()[layer].coords().iter().enumerate() {
                    let to = out.get_mut(k * D + d).map(|s| &mut **s);
                    match to {
                        Some(to) if to.len() == from.len() => to.copy_from_slice(from),
                        _ => {
                            return Err(Error::Length {
                                what: "an output slice (one value per grid point)",
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
        // The same sampler as `sample_layers`, so that both agree bit for bit.
        let knots = Direction::BOTH.map(|d| self.knots(d).clone());
        GridSampler::new_unchecked(&knots, self.weights(), plan.values()).sample_into(
            u,
            v,
            &mut ordered,
        )
    }

    /// Stages 2–4 at every level of `alphas` on the control net, and every
    /// surface of stage 1 and of every level on the grid `u × v` (docs/method.md §7, §8),
    /// as [`FuzzyCurve::sample_sweep`](crate::FuzzyCurve::sample_sweep) does
    /// for curves.
    ///
    /// # Errors
    /// As [`FuzzySurface::sample_layers`].
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, FuzzySurface, Layer, Nt2Number, Nt2Point};
    /// # use t2spline::sampling::Params;
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
    /// let p = |x: f64, y: f64, z: f64| Ok::<_, t2spline::Error>(Nt2Point::new([n(x)?, n(y)?, n(z)?]));
    /// let net = vec![vec![p(0.0, 0.0, 0.0)?, p(0.0, 1.0, 0.0)?], vec![p(1.0, 0.0, 0.0)?, p(1.0, 1.0, 1.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0, 2.0], vec![1.0, 1.0]], [None, None])?;
    /// let alphas = [Alpha::try_new(0.3)?, Alpha::try_new(1.0)?];
    /// let g = s.sample_sweep(Params::Uniform(21), Params::Uniform(11), &alphas)?;
    /// let crisp = &g.samples().layers()[Layer::Crisp];
    /// let top = g.samples().levels()[1].defuzzified(); // alpha = 1: the crisp surface
    /// assert!((0..21 * 11).all(|k| (top.coord(2)[k] - crisp.coord(2)[k]).abs() < 1e-15));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn sample_sweep<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
        alphas: &[Alpha],
    ) -> Result<Grid<SweepSamples<D>>, Error> {
        self.sample_sweep_with(u, v, alphas, TypeReduction::Paper)
    }

    /// [`FuzzySurface::sample_sweep`] with the type reduction `method` (docs/method.md
    /// §9): every level's stages as
    /// [`FuzzySurface::solve_with`] computes them.
    ///
    /// # Errors
    /// As [`FuzzySurface::sample_layers`].
    pub fn sample_sweep_with<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
        alphas: &[Alpha],
        method: TypeReduction,
    ) -> Result<Grid<SweepSamples<D>>, Error> {
        let solutions: Vec<SurfaceSolution<D>> =
            alphas.iter().map(|&a| self.solve_with(a, method)).collect();
        grid_sweep(
            self,
            u.into(),
            v.into(),
            &solutions,
            true,
            Vec::new(),
            Fresh::HugePages,
        )
    }

    /// [`FuzzySurface::sample_sweep`] into `out`, reusing its vectors (the
    /// paper's type reduction).
    ///
    /// # Errors
    /// As [`FuzzySurface::sample_layers`].
    pub fn sample_sweep_into<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
        alphas: &[Alpha],
        out: &mut Grid<SweepSamples<D>>,
    ) -> Result<(), Error> {
        let old = std::mem::replace(out, Grid::buffer(SweepSamples::empty()));
        let buffers = old.samples.into_buffers();
        let solutions: Vec<SurfaceSolution<D>> = alphas.iter().map(|&a| self.solve(a)).collect();
        *out = grid_sweep(
            self,
            u.into(),
            v.into(),
            &solutions,
            true,
            buffers,
            Fresh::HugePages,
        )?;
        Ok(())
    }
}

impl<const D: usize> SurfaceSolution<D> {
    /// The surfaces of stages 2–4 at this level on the grid `u × v`.
    ///
    /// # Errors
    /// As [`FuzzySurface::sample_layers`].
    pub fn sample_stages<'a, 'b>(
        &self,
        u: impl Into<Params<'a>>,
        v: impl Into<Params<'b>>,
    ) -> Result<Grid<StageSamples<D>>, Error> {
        let g = grid_sweep(
            self.fuzzy_surface(),
            u.into(),
            v.into(),
            std::slice::from_ref(self),
            false,
            Vec::new(),
            Fresh::HugePages,
        )?;
        let (_, levels) = g.samples.into_parts();
        // One solution was sampled, so there is one level.
        #[allow(clippy::expect_used)]
        Ok(Grid {
            shape: g.shape,
            samples: levels.into_iter().next().expect("one level was asked for"),
        })
    }

    /// The seven stage-1 layer surfaces and this solution's surfaces of
    /// stages 2–4 on the grid `u × v`, from one grid sampler (what a run
    /// samples), in ordinary vectors, which a run's output takes without a
    /// copy.
    pub(crate) fn sample_with_layers(
        &self,
        u: Params<'_>,
        v: Params<'_>,
    ) -> Result<Grid<SweepSamples<D>>, Error> {
        grid_sweep(
            self.fuzzy_surface(),
            u,
            v,
            std::slice::from_ref(self),
            true,
            Vec::new(),
            Fresh::Vectors,
        )
    }
}

/// Samples the crisp surface, the six other layers if `layers`, and the
/// surfaces of stages 2–4 of every solution with one grid sampler (with
/// fuzzy weights, one per surface: `weighted.rs`). The grid engine keeps
/// every order exactly, so the plan's bounds are not needed.
fn grid_sweep<const D: usize>(
    surface: &FuzzySurface<D>,
    u: Params<'_>,
    v: Params<'_>,
    solutions: &[SurfaceSolution<D>],
    layers: bool,
    mut buffers: Vec<SampleBuffer>,
    fresh: Fresh,
) -> Result<Grid<SweepSamples<D>>, Error> {
    if surface.weight_numbers().is_some() {
        return grid_sweep_weighted(surface, [u, v], solutions, layers, buffers, fresh);
    }
    let stages: Vec<&PointStages<D>> = solutions.iter().map(SurfaceSolution::stages).collect();
    let plan = Plan::new(surface.points(), &stages, layers);
    let knots = Direction::BOTH.map(|d| surface.knots(d).clone());
    let sampler = GridSampler::new_unchecked(&knots, surface.weights(), plan.values());
    let out = sampler.sample_buffers(u, v, &mut buffers, fresh)?;
    Ok(Grid {
        shape: [u.len(), v.len()],
        samples: plan.assemble(out),
    })
}
