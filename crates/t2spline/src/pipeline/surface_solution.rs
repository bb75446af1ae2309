//! Stages 2–4 of Algorithm 1.1 on the control net of a fuzzy surface (docs/method.md
//! §7, §8), and the surfaces through their results.

use crate::fuzzy::Layer;
use crate::nurbs::NurbsSurface;
use crate::pipeline::point_stages::Side;
use crate::pipeline::stages::Stages;
use crate::pipeline::{FuzzySurface, SurfaceDistance};

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
/// The accessors of every stage are those of [`Stages`], written once for
/// curves and surfaces; this type adds the names of the surfaces.
pub type SurfaceSolution<const D: usize> = Stages<FuzzySurface<D>, D>;

impl<const D: usize> SurfaceSolution<D> {
    /// Stage 1: the fuzzy surface.
    #[must_use]
    pub fn fuzzy_surface(&self) -> &FuzzySurface<D> {
        self.fuzzy()
    }

    /// Stage 2: the surface through one alpha-cut layer, when that layer
    /// exists for every control point.
    #[must_use]
    pub fn alpha_cut_surface(&self, layer: Layer) -> Option<NurbsSurface<D>> {
        self.alpha_cut(layer)
    }

    /// Stage 3: the surface through the left or right type-reduced points.
    #[must_use]
    pub fn type_reduced_surface(&self, side: Side) -> NurbsSurface<D> {
        self.type_reduced(side)
    }

    /// Stage 4: the crisp type-2 solution surface through the defuzzified
    /// points.
    #[must_use]
    pub fn defuzzified_surface(&self) -> NurbsSurface<D> {
        self.defuzzified()
    }

    /// The crisp surface through the crisp control points.
    #[must_use]
    pub fn crisp_surface(&self) -> NurbsSurface<D> {
        self.crisp()
    }

    /// The distance between the crisp and the defuzzified surface at equal
    /// `(u, v)` over the whole domain (docs/method.md §8); see [`SurfaceDistance`].
    #[must_use]
    pub fn distance(&self) -> SurfaceDistance {
        if self.fuzzy_surface().weight_numbers().is_some() {
            // The two surfaces have weights of their own (docs/method.md §16).
            return SurfaceDistance::between(&self.defuzzified_surface(), &self.crisp_surface());
        }
        SurfaceDistance::of_surface(&self.offsets())
    }
}
