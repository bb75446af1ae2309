//! Stages 2–4 of Algorithm 1.1 for any [`Layered`] fuzzy object, written once
//! for curves ([`Solution`](crate::Solution)) and surfaces
//! ([`SurfaceSolution`](crate::SurfaceSolution)): the per-number values of
//! [`PointStages`] and the crisp objects through them, with the fuzzy
//! object's weights and knots (docs/method.md §7, §8).

use crate::capability::Layered;
use crate::fuzzy::{Alpha, AlphaCut, Layer, Nt2Point};
use crate::pipeline::point_stages::{PointStages, Side};
use crate::reduction::{Reduced, TypeReduction};

/// The four stages of Algorithm 1.1 of a fuzzy object `M` with `D`
/// coordinates at one level alpha: `M` itself (stage 1), and the crisp
/// objects through its alpha-cut (stage 2), type-reduced (stage 3) and
/// defuzzified (stage 4) control points. [`Solution`](crate::Solution) and
/// [`SurfaceSolution`](crate::SurfaceSolution) name it for curves and
/// surfaces and add the names of their objects (`alpha_cut_curve`,
/// `defuzzified_surface`, …) and their distance.
///
/// Stages 3–4 reduce each number by the solution's [`TypeReduction`]
/// (docs/method.md §9): with the paper's, stage 3 is the triangle
/// `(left, crisp, right)`; with the others, `[left, right]` is a centroid
/// interval, which need not contain `crisp`.
#[derive(Clone, Debug, PartialEq)]
pub struct Stages<M, const D: usize> {
    fuzzy: M,
    stages: PointStages<D>,
    /// The stages of the fuzzy weights, each cut, reduced and defuzzified
    /// as a coordinate is (docs/method.md §16); `None` with crisp weights.
    weights: Option<PointStages<1>>,
}

impl<M: Layered<D>, const D: usize> Stages<M, D> {
    pub(crate) fn new(fuzzy: M, alpha: Alpha, method: TypeReduction) -> Self {
        let stages = PointStages::new(fuzzy.fuzzy_points(), alpha, method);
        let weights = fuzzy.weight_numbers().map(|numbers| {
            let numbers: Vec<Nt2Point<1>> = numbers.iter().map(|&w| Nt2Point::new([w])).collect();
            PointStages::new(&numbers, alpha, method)
        });
        Stages {
            fuzzy,
            stages,
            weights,
        }
    }

    /// The crisp object through `points` with `weights` where the weights
    /// are fuzzy, else with the fuzzy object's.
    fn through(&self, points: Vec<[f64; D]>, weights: Option<Vec<[f64; 1]>>) -> M::Crisp {
        match weights {
            Some(w) => self
                .fuzzy
                .through_weighted(points, w.into_iter().map(|[w]| w).collect()),
            None => self.fuzzy.through(points),
        }
    }

    /// Stage 2: the weights of one alpha-cut layer where the weights are
    /// fuzzy (`Some(None)` for a lower layer when some weight is cut above
    /// its lower height); `None` with crisp weights.
    #[must_use]
    pub fn alpha_cut_weights(&self, layer: Layer) -> Option<Option<Vec<f64>>> {
        self.weights
            .as_ref()
            .map(|w| w.alpha_cut_layer(layer).map(flat))
    }

    /// Stage 3: the left or right type-reduced weights where the weights are
    /// fuzzy; `None` with crisp weights.
    #[must_use]
    pub fn type_reduced_weights(&self, side: Side) -> Option<Vec<f64>> {
        self.weights
            .as_ref()
            .map(|w| flat(w.type_reduced_side(side)))
    }

    /// Stage 4: the defuzzified weights where the weights are fuzzy; `None`
    /// with crisp weights.
    #[must_use]
    pub fn defuzzified_weights(&self) -> Option<Vec<f64>> {
        self.weights
            .as_ref()
            .map(|w| flat(w.defuzzified_points().to_vec()))
    }

    /// The per-number stages of the control points.
    pub(crate) fn stages(&self) -> &PointStages<D> {
        &self.stages
    }

    /// The per-number stages of the fuzzy weights; `None` with crisp weights.
    pub(crate) fn weight_stages(&self) -> Option<&PointStages<1>> {
        self.weights.as_ref()
    }

    /// Stage 1: the fuzzy object.
    #[must_use]
    pub fn fuzzy(&self) -> &M {
        &self.fuzzy
    }

    /// The level alpha of the cut (stage 2); stages 3–4 use it only with
    /// [`TypeReduction::Paper`].
    #[must_use]
    pub fn alpha(&self) -> Alpha {
        self.stages.alpha()
    }

    /// The type reduction of stages 3–4 (docs/method.md §9).
    #[must_use]
    pub fn type_reduction(&self) -> TypeReduction {
        self.stages.type_reduction()
    }

    /// Stage 2: the alpha-cut of every control point, per coordinate.
    #[must_use]
    pub fn alpha_cut_points(&self) -> &[[AlphaCut; D]] {
        self.stages.alpha_cut_points()
    }

    /// Stage 2: the control points of one alpha-cut layer; `None` for a lower
    /// layer when some number is cut above its lower height (docs/method.md §2).
    #[must_use]
    pub fn alpha_cut_layer(&self, layer: Layer) -> Option<Vec<[f64; D]>> {
        self.stages.alpha_cut_layer(layer)
    }

    /// Stage 2: the crisp object through one alpha-cut layer, when that
    /// layer exists for every control point.
    #[must_use]
    pub fn alpha_cut(&self, layer: Layer) -> Option<M::Crisp> {
        let points = self.alpha_cut_layer(layer)?;
        let weights = match &self.weights {
            Some(w) => Some(w.alpha_cut_layer(layer)?),
            None => None,
        };
        Some(self.through(points, weights))
    }

    /// Stage 3: every coordinate of every control point reduced by the
    /// solution's [`TypeReduction`] ([`Nt2Number::reduce`](crate::Nt2Number::reduce)):
    /// for the paper's, the feet of the type-reduced triangle and its
    /// centroid; for the others, `left`/`right` need not enclose `crisp`.
    #[must_use]
    pub fn type_reduced_points(&self) -> &[[Reduced; D]] {
        self.stages.type_reduced_points()
    }

    /// Stage 3: the left or right type-reduced control points.
    #[must_use]
    pub fn type_reduced_side(&self, side: Side) -> Vec<[f64; D]> {
        self.stages.type_reduced_side(side)
    }

    /// Stage 3: the crisp object through the left or right type-reduced
    /// control points.
    #[must_use]
    pub fn type_reduced(&self, side: Side) -> M::Crisp {
        let weights = self.weights.as_ref().map(|w| w.type_reduced_side(side));
        self.through(self.type_reduced_side(side), weights)
    }

    /// Stage 4: the defuzzified control points.
    #[must_use]
    pub fn defuzzified_points(&self) -> &[[f64; D]] {
        self.stages.defuzzified_points()
    }

    /// Stage 4: the crisp type-2 solution through the defuzzified points.
    #[must_use]
    pub fn defuzzified(&self) -> M::Crisp {
        let weights = self
            .weights
            .as_ref()
            .map(|w| w.defuzzified_points().to_vec());
        self.through(self.stages.defuzzified_points().to_vec(), weights)
    }

    /// The crisp object through the crisp control points.
    #[must_use]
    pub fn crisp(&self) -> M::Crisp {
        self.fuzzy.layer(Layer::Crisp)
    }

    /// The crisp object through the offsets `defuzzified − crisp` of the
    /// control points, whose norm over the domain is the distance between
    /// the crisp and the defuzzified object at equal parameters where the
    /// weights are crisp. With fuzzy weights the two objects have weights of
    /// their own and their difference is no rational B-spline with either's.
    pub(crate) fn offsets(&self) -> M::Crisp {
        self.fuzzy
            .through(self.stages.offsets(self.fuzzy.fuzzy_points()))
    }
}

/// One value per point from one-coordinate points.
fn flat(values: Vec<[f64; 1]>) -> Vec<f64> {
    values.into_iter().map(|[w]| w).collect()
}
