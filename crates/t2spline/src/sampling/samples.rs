//! Sampled curves as structure of arrays: one vector per coordinate.

use std::ops::Index;

use super::buffer::SampleBuffer;
use crate::fuzzy::{Alpha, Layer, Layers};
use crate::pipeline::Side;

/// One curve sampled at `len()` parameters, one vector per coordinate
/// (structure of arrays): `coord(0)[i]` is the x coordinate at the i-th
/// parameter.
///
/// # Examples
/// ```
/// # use t2spline::NurbsCurve;
/// # use t2spline::sampling::Params;
/// let c = NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [2.0, 4.0]], vec![1.0, 1.0])?;
/// let s = c.sample_soa(Params::Uniform(3))?;
/// assert_eq!(s.coord(1), &[0.0, 2.0, 4.0]);
/// assert_eq!(s.point(1), Some([1.0, 2.0]));
/// assert_eq!(s.point(3), None);
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CurveSamples<const D: usize> {
    coords: [SampleBuffer; D],
}

impl<const D: usize> CurveSamples<D> {
    /// Wraps one buffer per coordinate, all of one length.
    pub(crate) fn from_coords(coords: [SampleBuffer; D]) -> Self {
        debug_assert!(coords.iter().all(|c| c.len() == coords[0].len()));
        CurveSamples { coords }
    }

    /// The number of samples.
    #[must_use]
    pub fn len(&self) -> usize {
        self.coords.first().map_or(0, |c| c.len())
    }

    /// Whether there are no samples.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The values of one coordinate (`0` is x); empty past the last one.
    #[must_use]
    pub fn coord(&self, axis: usize) -> &[f64] {
        self.coords.get(axis).map_or(&[], |c| &**c)
    }

    /// The buffers of all coordinates (each dereferences to `[f64]`).
    #[must_use]
    pub fn coords(&self) -> &[SampleBuffer; D] {
        &self.coords
    }

    /// The buffers of all coordinates, by value.
    #[must_use]
    pub fn into_coords(self) -> [SampleBuffer; D] {
        self.coords
    }

    /// The i-th sample as a point, if `i < len()`.
    #[must_use]
    pub fn point(&self, i: usize) -> Option<[f64; D]> {
        (i < self.len()).then(|| self.at(i))
    }

    /// The i-th sample, for `i < len()`: every coordinate has `len()` values.
    fn at(&self, i: usize) -> [f64; D] {
        std::array::from_fn(|d| self.coords[d][i])
    }

    /// No samples (a buffer for the `_into` sampling functions).
    #[must_use]
    pub fn empty() -> Self {
        CurveSamples::from_coords(std::array::from_fn(|_| SampleBuffer::new()))
    }

    /// The buffers, for reuse.
    pub(crate) fn into_buffers(self) -> impl Iterator<Item = SampleBuffer> {
        self.coords.into_iter()
    }

    /// The samples as points, in order.
    pub fn points(&self) -> impl ExactSizeIterator<Item = [f64; D]> + '_ {
        (0..self.len()).map(|i| self.at(i))
    }
}

/// The seven layer curves of a fuzzy curve (stage 1, docs/method.md §6–§7), sampled at the
/// same parameters; index by [`Layer`].
///
/// At every parameter the seven values of each coordinate keep the order of
/// docs/method.md §1 exactly, as the exact curves do.
#[derive(Clone, Debug, PartialEq)]
pub struct LayerSamples<const D: usize> {
    pub(crate) layers: Layers<CurveSamples<D>>,
}

impl<const D: usize> LayerSamples<D> {
    /// No samples (a buffer for [`crate::FuzzyCurve::sample_layers_into`]).
    #[must_use]
    pub fn empty() -> Self {
        LayerSamples {
            layers: Layers::from_fn(|_| CurveSamples::empty()),
        }
    }

    pub(crate) fn into_buffers(self) -> impl Iterator<Item = SampleBuffer> {
        self.layers
            .into_array()
            .into_iter()
            .flat_map(CurveSamples::into_buffers)
    }

    /// The seven sampled curves.
    #[must_use]
    pub fn layers(&self) -> &Layers<CurveSamples<D>> {
        &self.layers
    }

    /// The number of samples.
    #[must_use]
    pub fn len(&self) -> usize {
        self.layers[Layer::Crisp].len()
    }

    /// Whether there are no samples.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

impl<const D: usize> Index<Layer> for LayerSamples<D> {
    type Output = CurveSamples<D>;
    fn index(&self, layer: Layer) -> &CurveSamples<D> {
        &self.layers[layer]
    }
}

/// The curves of stages 2–4 at one level alpha (docs/method.md §7), sampled.
///
/// The crisp curve is the same at every level and is not repeated here: it is
/// the [`Layer::Crisp`] curve of the stage-1 [`LayerSamples`].
#[derive(Clone, Debug, PartialEq)]
pub struct StageSamples<const D: usize> {
    pub(crate) alpha: Alpha,
    pub(crate) alpha_cut: Layers<Option<CurveSamples<D>>>,
    pub(crate) type_reduced: [CurveSamples<D>; 2],
    pub(crate) defuzzified: CurveSamples<D>,
}

impl<const D: usize> StageSamples<D> {
    /// The level.
    #[must_use]
    pub fn alpha(&self) -> Alpha {
        self.alpha
    }

    /// Stage 2: the curve through one alpha-cut layer; `None` for
    /// [`Layer::Crisp`] (it is the stage-1 crisp curve) and for a lower layer
    /// that does not exist at this level (docs/method.md §2).
    #[must_use]
    pub fn alpha_cut(&self, layer: Layer) -> Option<&CurveSamples<D>> {
        self.alpha_cut[layer].as_ref()
    }

    /// Stage 3: the type-reduced left or right curve.
    #[must_use]
    pub fn type_reduced(&self, side: Side) -> &CurveSamples<D> {
        match side {
            Side::Left => &self.type_reduced[0],
            Side::Right => &self.type_reduced[1],
        }
    }

    /// Stage 4: the crisp type-2 solution curve.
    #[must_use]
    pub fn defuzzified(&self) -> &CurveSamples<D> {
        &self.defuzzified
    }
}

/// Stage 1 and stages 2–4 at several levels, all sampled at the same parameters
/// from one power form (see [`crate::FuzzyCurve::sample_sweep`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SweepSamples<const D: usize> {
    pub(crate) layers: LayerSamples<D>,
    pub(crate) levels: Vec<StageSamples<D>>,
}

impl<const D: usize> SweepSamples<D> {
    /// No samples (a buffer for [`crate::FuzzyCurve::sample_sweep_into`]).
    #[must_use]
    pub fn empty() -> Self {
        SweepSamples {
            layers: LayerSamples::empty(),
            levels: Vec::new(),
        }
    }

    pub(crate) fn into_buffers(self) -> Vec<SampleBuffer> {
        let mut out: Vec<SampleBuffer> = self.layers.into_buffers().collect();
        for level in self.levels {
            for curve in level.alpha_cut.into_array().into_iter().flatten() {
                out.extend(curve.into_buffers());
            }
            let [left, right] = level.type_reduced;
            out.extend(left.into_buffers());
            out.extend(right.into_buffers());
            out.extend(level.defuzzified.into_buffers());
        }
        out
    }

    /// Stage 1: the seven layer curves (the crisp curve among them).
    #[must_use]
    pub fn layers(&self) -> &LayerSamples<D> {
        &self.layers
    }

    /// Stages 2–4, one entry per level, in the order the levels were given.
    #[must_use]
    pub fn levels(&self) -> &[StageSamples<D>] {
        &self.levels
    }

    /// The parts, by value.
    #[must_use]
    pub fn into_parts(self) -> (LayerSamples<D>, Vec<StageSamples<D>>) {
        (self.layers, self.levels)
    }
}

/// Samples on a grid `u_a × v_b` of a surface (docs/method.md §8): `T` holds one vector
/// per coordinate of each sampled surface, as for curves ([`CurveSamples`],
/// [`LayerSamples`], [`StageSamples`], [`SweepSamples`]), with the grid point
/// `(u_a, v_b)` at index [`Grid::index`]`(a, b) = a·sv + b` (`a` along u).
///
/// # Examples
/// ```
/// # use t2spline::NurbsSurface;
/// # use t2spline::sampling::Params;
/// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
/// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0; 2]; 2])?;
/// let g = s.sample_grid(Params::Uniform(3), Params::Uniform(5))?;
/// assert_eq!(g.shape(), [3, 5]);
/// assert_eq!(g.samples().point(g.index(1, 2)?), Some([0.5, 0.5, 0.25]));
/// assert!(g.index(3, 0).is_err());
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Grid<T> {
    pub(crate) shape: [usize; 2],
    pub(crate) samples: T,
}

impl<T> Grid<T> {
    /// An empty grid around `samples` (a buffer for the `_into` sampling
    /// functions, e.g. `Grid::buffer(LayerSamples::empty())`).
    #[must_use]
    pub fn buffer(samples: T) -> Self {
        Grid {
            shape: [0, 0],
            samples,
        }
    }

    /// `[su, sv]`: parameters along u and along v.
    #[must_use]
    pub fn shape(&self) -> [usize; 2] {
        self.shape
    }

    /// The index of the grid point `(u_a, v_b)` in every sample vector.
    ///
    /// # Errors
    /// [`Error::Index`](crate::Error::Index) naming the `u` or `v` index if
    /// `a ≥ su` or `b ≥ sv`.
    pub fn index(&self, a: usize, b: usize) -> Result<usize, crate::Error> {
        let [su, sv] = self.shape;
        let a = crate::Error::check_index("u parameter", a, su)?;
        let b = crate::Error::check_index("v parameter", b, sv)?;
        Ok(a * sv + b)
    }

    /// The samples.
    #[must_use]
    pub fn samples(&self) -> &T {
        &self.samples
    }

    /// The samples, by value.
    #[must_use]
    pub fn into_samples(self) -> T {
        self.samples
    }
}
