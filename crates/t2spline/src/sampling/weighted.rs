//! Sampling a fuzzy curve whose weights are fuzzy too (docs/method.md §16).
//!
//! Each layer and each stage curve then has weights of its own, so no
//! rational basis is shared and the layers need not keep the order of
//! docs/method.md §1: every curve is sampled by a sampler of its own, with
//! no order bounds, into the same [`SweepSamples`] the shared-basis engine
//! fills.

use super::buffer::{Fresh, SampleBuffer};
use super::params::Params;
use super::samples::{CurveSamples, LayerSamples, StageSamples, SweepSamples};
use crate::error::Error;
use crate::fuzzy::{Layer, Layers};
use crate::nurbs::NurbsCurve;
use crate::pipeline::{FuzzyCurve, Side, Solution};

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
    let mut sample = |c: &NurbsCurve<D>| -> Result<CurveSamples<D>, Error> {
        let mut coords = c
            .sampler()
            .sample_buffers(params, &mut buffers, fresh)?
            .into_iter();
        Ok(CurveSamples::from_coords(std::array::from_fn(|_| {
            coords.next().unwrap_or_default()
        })))
    };
    let layers = LayerSamples {
        layers: Layers::try_from_fn(|l| {
            if layers || l == Layer::Crisp {
                sample(&curve.layer_curve(l))
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
                    _ => s.alpha_cut_curve(l).map(|c| sample(&c)).transpose(),
                })?,
                type_reduced: [
                    sample(&s.type_reduced_curve(Side::Left))?,
                    sample(&s.type_reduced_curve(Side::Right))?,
                ],
                defuzzified: sample(&s.defuzzified_curve())?,
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(SweepSamples { layers, levels })
}
