//! Stages 2–4 of Algorithm 1.1 on the control net of a fuzzy surface (docs/method.md
//! §7, §8), and the surfaces through their results.

use crate::fuzzy::{Alpha, AlphaCut, Layer};
use crate::nurbs::NurbsSurface;
use crate::pipeline::point_stages::{PointStages, Side};
use crate::pipeline::{FuzzySurface, SurfaceDistance};
use crate::reduction::{Reduced, TypeReduction};

/// The four stages of Algorithm 1.1 for a fuzzy surface at one level alpha
/// (docs/method.md §7, §8), computed number by number on the control net exactly as for
/// curves ([`Solution`](crate::Solution) shares the same per-number code):
///
/// 1. the fuzzy surface and its seven layer surfaces;
/// 2. alpha-cut control points and their surfaces;
/// 3. type-reduced control points `(left, crisp, right)` and the left and right
///    surfaces;
/// 4. defuzzified control points and the crisp solution surface, compared with
///    the crisp surface by [`SurfaceSolution::distance`].
///
/// Point lists are row by row (`[i·nv + j]`), as
/// [`FuzzySurface::points`].
///
/// # Examples
/// ```
/// # use t2spline::{Alpha, FuzzySurface, Nt2Number, Nt2Point, Side};
/// // Every number has left spreads (0.6, 0.4) and right spreads (0.9, 0.6):
/// // the defuzzified net is the crisp one moved by 0.05/3 in x, y and z.
/// let n = |c: f64| Nt2Number::try_new(c, [c - 0.6, c + 0.9], [c - 0.4, c + 0.6], [c - 0.2, c + 0.3], 0.6);
/// let p = |x: f64, y: f64, z: f64| Ok::<_, t2spline::Error>(Nt2Point::new([n(x)?, n(y)?, n(z)?]));
/// let net = vec![
///     vec![p(0.0, 0.0, 0.0)?, p(0.0, 1.0, 0.5)?],
///     vec![p(1.0, 0.0, 0.2)?, p(1.0, 1.0, 1.0)?],
/// ];
/// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0, 2.0], vec![1.0, 1.0]], [None, None])?;
/// let solution = s.solve(Alpha::try_new(0.8)?);
/// let left = solution.type_reduced_surface(Side::Left);
/// assert!(left.eval(0.5, 0.5)?[0] <= solution.defuzzified_surface().eval(0.5, 0.5)?[0]);
/// let d = solution.distance();
/// let offset = 0.05 / 3.0 * 3f64.sqrt();
/// assert!((d.max - offset).abs() < 1e-12 && (d.rms - offset).abs() < 1e-12);
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceSolution<const D: usize> {
    surface: FuzzySurface<D>,
    stages: PointStages<D>,
}

impl<const D: usize> SurfaceSolution<D> {
    pub(crate) fn new(surface: FuzzySurface<D>, alpha: Alpha, method: TypeReduction) -> Self {
        let stages = PointStages::new(surface.points(), alpha, method);
        SurfaceSolution { surface, stages }
    }

    /// The per-number stages of the control net.
    pub(crate) fn stages(&self) -> &PointStages<D> {
        &self.stages
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

    /// Stage 1: the fuzzy surface.
    #[must_use]
    pub fn fuzzy_surface(&self) -> &FuzzySurface<D> {
        &self.surface
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

    /// Stage 2: the surface through one alpha-cut layer, when that layer
    /// exists for every control point.
    #[must_use]
    pub fn alpha_cut_surface(&self, layer: Layer) -> Option<NurbsSurface<D>> {
        self.alpha_cut_layer(layer)
            .map(|points| self.surface.with_control_points(points))
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

    /// Stage 3: the surface through the left or right type-reduced points.
    #[must_use]
    pub fn type_reduced_surface(&self, side: Side) -> NurbsSurface<D> {
        self.surface
            .with_control_points(self.stages.type_reduced_side(side))
    }

    /// Stage 4: the defuzzified control points.
    #[must_use]
    pub fn defuzzified_points(&self) -> &[[f64; D]] {
        self.stages.defuzzified_points()
    }

    /// Stage 4: the crisp type-2 solution surface through the defuzzified
    /// points.
    #[must_use]
    pub fn defuzzified_surface(&self) -> NurbsSurface<D> {
        self.surface
            .with_control_points(self.stages.defuzzified_points().to_vec())
    }

    /// The crisp surface through the crisp control points.
    #[must_use]
    pub fn crisp_surface(&self) -> NurbsSurface<D> {
        self.surface.crisp_surface()
    }

    /// The distance between the crisp and the defuzzified surface at equal
    /// `(u, v)` over the whole domain (docs/method.md §8); see [`SurfaceDistance`].
    #[must_use]
    pub fn distance(&self) -> SurfaceDistance {
        let offsets = self.stages.offsets(self.surface.points());
        SurfaceDistance::of_surface(&self.surface.with_control_points(offsets))
    }
}
