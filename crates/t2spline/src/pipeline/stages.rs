//! Stages 2–4 of Algorithm 1.1 for any [`Layered`] fuzzy object, written once
//! for curves ([`Solution`](crate::Solution)) and surfaces
//! ([`SurfaceSolution`](crate::SurfaceSolution)): the per-number values of
//! [`PointStages`] and the crisp objects through them, with the fuzzy
//! object's weights and knots (docs/method.md §7, §8).

use crate::capability::Layered;
use crate::fuzzy::{Alpha, AlphaCut, Layer};
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
}

impl<M: Layered<D>, const D: usize> Stages<M, D> {
    pub(crate) fn new(fuzzy: M, alpha: Alpha, method: TypeReduction) -> Self {
        let stages = PointStages::new(fuzzy.fuzzy_points(), alpha, method);
        Stages { fuzzy, stages }
    }

    /// The per-number stages of the control points.
    pub(crate) fn stages(&self) -> &PointStages<D> {
        &self.stages
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
        self.alpha_cut_layer(layer)
            .map(|points| self.fuzzy.through(points))
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
        self.fuzzy.through(self.type_reduced_side(side))
    }

    /// Stage 4: the defuzzified control points.
    #[must_use]
    pub fn defuzzified_points(&self) -> &[[f64; D]] {
        self.stages.defuzzified_points()
    }

    /// Stage 4: the crisp type-2 solution through the defuzzified points.
    #[must_use]
    pub fn defuzzified(&self) -> M::Crisp {
        self.fuzzy
            .through(self.stages.defuzzified_points().to_vec())
    }

    /// The crisp object through the crisp control points.
    #[must_use]
    pub fn crisp(&self) -> M::Crisp {
        self.fuzzy.layer(Layer::Crisp)
    }

    /// The crisp object through the offsets `defuzzified − crisp` of the
    /// control points, whose norm over the domain is the distance between
    /// the crisp and the defuzzified object at equal parameters.
    pub(crate) fn offsets(&self) -> M::Crisp {
        self.fuzzy
            .through(self.stages.offsets(self.fuzzy.fuzzy_points()))
    }
}
