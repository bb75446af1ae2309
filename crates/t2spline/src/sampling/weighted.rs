//! Sampling a fuzzy curve or surface whose weights are fuzzy too
//! (docs/method.md §16).
//!
//! Each layer and each stage object then has weights of its own, so no
//! rational basis is shared and the layers need not keep the order of
//! docs/method.md §1: every object is sampled by a sampler of its own, with
//! no order bounds, into the same [`SweepSamples`] the shared-basis engines
//! fill. The walk over the objects is written once ([`sweep_each`]); curves
//! and surfaces give it their own sampler.

use super::buffer::{Fresh, SampleBuffer};
use super::params::Params;
use super::samples::{CurveSamples, Grid, LayerSamples, StageSamples, SweepSamples};
use crate::capability::Layered;
use crate::error::Error;
use crate::fuzzy::{Layer, Layers};
use crate::nurbs::{NurbsCurve, NurbsSurface};
use crate::pipeline::{FuzzyCurve, FuzzySurface, Side, Solution, Stages, SurfaceSolution};

/// Samples the crisp layer object of `fuzzy`, the six other layers if
/// `layers`, and the stage 2–4 objects of every solution, each by `sample`.
fn sweep_each<M: Layered<D>, const D: usize>(
    fuzzy: &M,
    solutions: &[Stages<M, D>],
    layers: bool,
    mut sample: impl FnMut(&M::Crisp) -> Result<CurveSamples<D>, Error>,
) -> Result<SweepSamples<D>, Error> {
    let layers = LayerSamples {
        layers: Layers::try_from_fn(|l| {
            if layers || l == Layer::Crisp {
                sample(&fuzzy.layer(l))
            } else {
                Ok(CurveSamples::from_coords(std::array::from_fn(|_| {
                    SampleBuffer::new()
                })))
            }
        })?,
    };
    let levels = solutions
        .iter()
        .map(|s| {
            Ok(StageSamples {
                alpha: s.alpha(),
                alpha_cut: Layers::try_from_fn(|l| match l {
                    Layer::Crisp => Ok(None),
                    _ => s.alpha_cut(l).map(|c| sample(&c)).transpose(),
                })?,
                type_reduced: [
                    sample(&s.type_reduced(Side::Left))?,
                    sample(&s.type_reduced(Side::Right))?,
                ],
                defuzzified: sample(&s.defuzzified())?,
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(SweepSamples { layers, levels })
}

/// One buffer per coordinate as samples.
fn samples_of<const D: usize>(coords: Vec<SampleBuffer>) -> CurveSamples<D> {
    let mut coords = coords.into_iter();
    CurveSamples::from_coords(std::array::from_fn(|_| coords.next().unwrap_or_default()))
}

/// Samples the crisp layer curve of `curve`, the six other layers if
/// `layers`, and the stage 2–4 curves of every solution, each with its own
/// weights, into buffers taken from `buffers` where it has them and new
/// ones from `fresh`.
pub(super) fn sweep_weighted<const D: usize>(
    curve: &FuzzyCurve<D>,
    params: Params<'_>,
    solutions: &[Solution<D>],
    layers: bool,
    mut buffers: Vec<SampleBuffer>,
    fresh: Fresh,
) -> Result<SweepSamples<D>, Error> {
    sweep_each(curve, solutions, layers, |c: &NurbsCurve<D>| {
        Ok(samples_of(c.sampler().sample_buffers(
            params,
            &mut buffers,
            fresh,
        )?))
    })
}

/// As [`sweep_weighted`], for a surface on the grid `u × v`, each surface
/// by a grid sampler of its own.
pub(super) fn grid_sweep_weighted<const D: usize>(
    surface: &FuzzySurface<D>,
    [u, v]: [Params<'_>; 2],
    solutions: &[SurfaceSolution<D>],
    layers: bool,
    mut buffers: Vec<SampleBuffer>,
    fresh: Fresh,
) -> Result<Grid<SweepSamples<D>>, Error> {
    let samples = sweep_each(surface, solutions, layers, |s: &NurbsSurface<D>| {
        Ok(samples_of(s.grid_sampler().sample_buffers(
            u,
            v,
            &mut buffers,
            fresh,
        )?))
    })?;
    Ok(Grid {
        shape: [u.len(), v.len()],
        samples,
    })
}
