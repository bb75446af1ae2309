//! The channels of a sampling job over a fuzzy curve or surface: which
//! control values each sampled curve (or surface) goes through, the bounds
//! that keep their order, and the assembly of the sampled vectors into
//! [`SweepSamples`]. Shared by the curve engine (`curves.rs`) and the grid
//! engine (`surfaces.rs`), so both sample exactly the same stages.

use super::buffer::SampleBuffer;
use super::sampler::Bound;
use super::samples::{CurveSamples, LayerSamples, StageSamples, SweepSamples};
use crate::fuzzy::{Layer, Layers, Nt2Point};
use crate::pipeline::point_stages::{PointStages, Side};
use crate::reduction::TypeReduction;

/// Where the channels of one level's stages are: the alpha-cut layers (none
/// for the crisp layer and for absent lower cuts), the type-reduced left and
/// right, the defuzzified; each the channel of its first coordinate.
type LevelChannels = (
    crate::fuzzy::Alpha,
    Layers<Option<usize>>,
    usize,
    usize,
    usize,
);

/// The channels of a sweep (`D` per curve), their order bounds, and where
/// each curve's channels are.
#[derive(Debug)]
pub(crate) struct Plan<const D: usize> {
    values: Vec<Vec<f64>>,
    bounds: Vec<Bound>,
    stage1: Layers<Option<usize>>,
    levels: Vec<LevelChannels>,
}

impl<const D: usize> Plan<D> {
    /// Plans the crisp curve of `points`, the six other layers if `layers`,
    /// and the stage 2–4 curves of every level in `stages` (computed on the
    /// same points, each by its own type reduction). The bounds are the
    /// orders the exact curves obey: the layers' of docs/method.md §1, `left ≤
    /// defuzzified ≤ right` for every reduction, and `left ≤ crisp ≤ right`
    /// for the paper's only.
    pub(crate) fn new(points: &[Nt2Point<D>], stages: &[&PointStages<D>], layers: bool) -> Self {
        let mut plan = Plan {
            values: Vec::new(),
            bounds: Vec::new(),
            stage1: Layers::from_fn(|_| None),
            levels: Vec::with_capacity(stages.len()),
        };
        let layer_of = |l: Layer| points.iter().map(|p| p.layer(l)).collect::<Vec<_>>();
        let crisp = plan.push(&layer_of(Layer::Crisp));
        plan.stage1 = Layers::from_fn(|l| match l {
            Layer::Crisp => Some(crisp),
            _ if layers => Some(plan.push(&layer_of(l))),
            _ => None,
        });
        let stage1 = plan.stage1;
        plan.bound_layers(&stage1, crisp);
        for s in stages {
            let cut: Layers<Option<usize>> = Layers::from_fn(|l| match l {
                Layer::Crisp => None,
                _ => s.alpha_cut_layer(l).map(|points| plan.push(&points)),
            });
            plan.bound_layers(&cut, crisp);
            let left = plan.push(&s.type_reduced_side(Side::Left));
            let right = plan.push(&s.type_reduced_side(Side::Right));
            let defuzzified = plan.push(s.defuzzified_points());
            if s.type_reduction() == TypeReduction::Paper {
                // The paper's triangle has its apex at crisp (docs/method.md §3).
                plan.bound(left, None, Some(crisp));
                plan.bound(right, Some(crisp), None);
            } else {
                // A centroid need not enclose crisp (docs/method.md §9): both ends
                // may lie on one side of it. Only left ≤ right holds.
                plan.bound(right, Some(left), None);
            }
            plan.bound(defuzzified, Some(left), Some(right));
            plan.levels.push((s.alpha(), cut, left, right, defuzzified));
        }
        plan
    }

    /// Slices given by layer, `out[k·D + d]` for coordinate `d` of
    /// [`Layer::ALL`]`[k]`, in the plan's order of channels (every layer
    /// planned, and `7·D` slices: the callers check both).
    pub(crate) fn by_layer<'o>(&self, out: &'o mut [&mut [f64]]) -> Vec<&'o mut [f64]> {
        let channels = Layer::ALL.into_iter().flat_map(|layer| {
            let first = self.stage1[layer].unwrap_or(0);
            (0..D).map(move |d| first + d)
        });
        let mut by_channel: Vec<(usize, &mut [f64])> =
            channels.zip(out.iter_mut().map(|o| &mut **o)).collect();
        by_channel.sort_by_key(|(channel, _)| *channel);
        by_channel.into_iter().map(|(_, o)| o).collect()
    }

    /// Every channel's control values.
    pub(crate) fn values(&self) -> &[Vec<f64>] {
        &self.values
    }

    /// The bounds that keep the sampled curves in the order of their exact
    /// counterparts.
    pub(crate) fn bounds(&self) -> &[Bound] {
        &self.bounds
    }

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
    /// neighbour (docs/method.md §1 order). `curves[layer]` is `None` for a missing layer.
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

    /// The sampled channels (one vector per channel, in plan order) as
    /// stage-1 layers and one [`StageSamples`] per level. Layers that were not
    /// planned stay empty.
    pub(crate) fn assemble(self, out: Vec<SampleBuffer>) -> SweepSamples<D> {
        let mut out: Vec<Option<SampleBuffer>> = out.into_iter().map(Some).collect();
        let mut take = |base: usize| {
            CurveSamples::from_coords(std::array::from_fn(|d| {
                // The plan made these channels, and each is taken once.
                #[allow(clippy::expect_used)]
                out[base + d].take().expect("each channel is taken once")
            }))
        };
        let layers = LayerSamples {
            layers: Layers::from_fn(|l| {
                self.stage1[l].map_or_else(
                    || CurveSamples::from_coords(std::array::from_fn(|_| SampleBuffer::new())),
                    &mut take,
                )
            }),
        };
        let levels = self
            .levels
            .into_iter()
            .map(|(alpha, cut, left, right, defuzzified)| StageSamples {
                alpha,
                alpha_cut: cut.map(|c| c.map(&mut take)),
                type_reduced: [take(left), take(right)],
                defuzzified: take(defuzzified),
            })
            .collect();
        SweepSamples { layers, levels }
    }
}
