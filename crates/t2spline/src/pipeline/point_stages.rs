//! Stages 2–4 of Algorithm 1.1 on a list of fuzzy control points, number by
//! number (docs/method.md §2–§4, §7, §9): the one place where curves ([`Solution`]) and
//! surfaces ([`SurfaceSolution`]) cut, reduce and defuzzify their points.
//!
//! Stage 2 is the alpha-cut at the level given. Stages 3 and 4 follow the
//! [`TypeReduction`] (docs/method.md §9), each number reduced by
//! [`Nt2Number::reduce`](crate::Nt2Number::reduce):
//!
//! | reduction | stage 3 left, right | stage 4 |
//! |---|---|---|
//! | `paper` | the type-reduced triangle of the cut (docs/method.md §3) | its centroid (docs/method.md §4) |
//! | `centroid` | `c_l`, `c_r` | `(c_l + c_r)/2` |
//! | `nie-tan` | the Nie–Tan value | the Nie–Tan value |
//! | `alpha-planes` | `c_l(0)`, `c_r(0)` (the widest plane) | the alpha-plane value |
//!
//! [`Solution`]: crate::Solution
//! [`SurfaceSolution`]: crate::SurfaceSolution

use crate::fuzzy::{Alpha, AlphaCut, Layer, Nt2Point};
use crate::reduction::{Reduced, TypeReduction};

/// A side of a type-reduced number `(left, crisp, right)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// The left foot.
    Left,
    /// The right foot.
    Right,
}

/// The alpha-cut, type-reduced and defuzzified values of every coordinate of
/// every control point at one level alpha and by one type reduction (docs/method.md
/// §2–§4, §9), in the order of the points given. A net of a surface is given
/// row by row.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PointStages<const D: usize> {
    alpha: Alpha,
    method: TypeReduction,
    alpha_cut: Vec<[AlphaCut; D]>,
    type_reduced: Vec<[Reduced; D]>,
    defuzzified: Vec<[f64; D]>,
}

impl<const D: usize> PointStages<D> {
    /// Runs stages 2–4 on every number of `points`: the cut at level `alpha`,
    /// the reduction by `method` (which uses `alpha` only for
    /// [`TypeReduction::Paper`]).
    pub(crate) fn new(points: &[Nt2Point<D>], alpha: Alpha, method: TypeReduction) -> Self {
        let alpha_cut: Vec<[AlphaCut; D]> = points.iter().map(|p| p.alpha_cut(alpha)).collect();
        let type_reduced: Vec<[Reduced; D]> = points
            .iter()
            .map(|p| p.coords().map(|x| x.reduce(method, alpha)))
            .collect();
        let defuzzified = type_reduced
            .iter()
            .map(|r| r.map(|r| r.defuzzified()))
            .collect();
        PointStages {
            alpha,
            method,
            alpha_cut,
            type_reduced,
            defuzzified,
        }
    }

    /// The level alpha of the cut (stage 2).
    pub(crate) fn alpha(&self) -> Alpha {
        self.alpha
    }

    /// The type reduction of stages 3–4.
    pub(crate) fn type_reduction(&self) -> TypeReduction {
        self.method
    }

    /// Stage 2: the alpha-cut of every point, per coordinate.
    pub(crate) fn alpha_cut_points(&self) -> &[[AlphaCut; D]] {
        &self.alpha_cut
    }

    /// Stage 2: the values of one alpha-cut layer; `None` for a lower layer
    /// when some number is cut above its lower height (docs/method.md §2).
    pub(crate) fn alpha_cut_layer(&self, layer: Layer) -> Option<Vec<[f64; D]>> {
        self.alpha_cut
            .iter()
            .map(|cuts| {
                let mut p = [0.0; D];
                for (x, c) in p.iter_mut().zip(cuts) {
                    *x = c.layer(layer)?;
                }
                Some(p)
            })
            .collect()
    }

    /// Stage 3: the reduced number of every point, per coordinate.
    pub(crate) fn type_reduced_points(&self) -> &[[Reduced; D]] {
        &self.type_reduced
    }

    /// Stage 3: the left or right type-reduced values.
    pub(crate) fn type_reduced_side(&self, side: Side) -> Vec<[f64; D]> {
        self.type_reduced
            .iter()
            .map(|reduced| {
                reduced.map(|t| match side {
                    Side::Left => t.left(),
                    Side::Right => t.right(),
                })
            })
            .collect()
    }

    /// Stage 4: the defuzzified points.
    pub(crate) fn defuzzified_points(&self) -> &[[f64; D]] {
        &self.defuzzified
    }

    /// The defuzzified points less the crisp points of `points` (the points
    /// the stages ran on): the control points of the difference between the
    /// defuzzified and the crisp curve or surface, which share weights and
    /// knots.
    pub(crate) fn offsets(&self, points: &[Nt2Point<D>]) -> Vec<[f64; D]> {
        self.defuzzified
            .iter()
            .zip(points)
            .map(|(d, p)| {
                let c = p.crisp();
                std::array::from_fn(|i| d[i] - c[i])
            })
            .collect()
    }
}
