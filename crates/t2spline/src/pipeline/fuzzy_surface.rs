//! The normal type-2 fuzzy rational B-spline surface (docs/method.md §8): a net of fuzzy
//! control points, its seven layer surfaces, and the surface operations on all
//! seven layers at once.

use crate::capability::{layered, Layered};
use crate::error::{Error, Place};
use crate::fuzzy::{Alpha, Axis, Height, Layer, Layers, Nt2Number, Nt2Point};
use crate::nurbs::degree_elevation::{check_elevation, elevate};
use crate::nurbs::homogeneous::{check_rows, Row};
use crate::nurbs::knot_insertion::{insert, refine};
use crate::nurbs::surface::closest_point::check_target;
use crate::nurbs::surface::operations::{isocurve_rows, map_net, segment_net, split_net, RowNet};
use crate::nurbs::surface::{check_params, knots_in, net_shape, net_weights, TensorBasis};
use crate::nurbs::{
    BoundingBox, ClosestSurfacePoint, Direction, Domain, KnotVector, NurbsSurface, SurfaceCurvature,
};
use crate::pipeline::fuzzy_ops::{common_heights, from_stacked_rows, stacked_rows};
use crate::pipeline::weight_numbers::{crisp_only, weights_of};
use crate::pipeline::{FuzzyCurve, SurfaceSolution};
use crate::reduction::TypeReduction;

/// A rational B-spline surface whose control points are normal type-2 fuzzy
/// points (docs/method.md §8, the paper's §6 "extended for surface design by the
/// tensor product"):
///
/// ```text
/// S̃(u, v) = Σᵢ Σⱼ wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v) P̃ᵢⱼ / Σᵢ Σⱼ wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v)
/// ```
/// evaluated layer by layer: one rational B-spline surface through each of the
/// seven values of every control point, all with the same weights and knots.
/// The rational basis is non-negative and sums to 1, so the seven layer
/// surfaces keep the order of docs/method.md §1 at every `(u, v)`. `points[i][j]`: the
/// outer index runs along u, the inner along v.
///
/// # Examples
/// ```
/// # use t2spline::{FuzzySurface, Layer, Nt2Number, Nt2Point};
/// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
/// let p = |x: f64, y: f64, z: f64| Ok::<_, t2spline::Error>(Nt2Point::new([n(x)?, n(y)?, n(z)?]));
/// let net = vec![
///     vec![p(0.0, 0.0, 0.0)?, p(0.0, 1.0, 0.0)?],
///     vec![p(1.0, 0.0, 0.0)?, p(1.0, 1.0, 1.0)?],
/// ];
/// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
/// let at = s.eval_layers(0.5, 0.5)?;
/// assert_eq!(at[Layer::Crisp], [0.5, 0.5, 0.25]);
/// assert_eq!(at[Layer::UpperRight], [2.5, 2.5, 2.25]);
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct FuzzySurface<const D: usize> {
    /// Row-major: `points[i·nv + j]` is `P̃ᵢⱼ`.
    points: Vec<Nt2Point<D>>,
    /// The crisp weights, or the crisp values of the fuzzy weights; row by row.
    weights: Vec<f64>,
    /// The fuzzy weights (docs/method.md §16), row by row; `None` where they
    /// are crisp.
    weight_numbers: Option<Vec<Nt2Number>>,
    knots: [KnotVector; 2],
}

impl<const D: usize> FuzzySurface<D> {
    /// Makes a fuzzy surface of degrees `[p, q]` from a net of fuzzy points
    /// (`points[i][j]`, `i` along u), a net of weights of the same shape, and
    /// the knot values `[U, V]`; `None` selects the clamped uniform default of
    /// that direction (docs/method.md §6, §8).
    ///
    /// # Errors
    /// [`Error::NetShape`] for rows of unequal length or weights of another
    /// shape; [`Error::InDirection`] wrapping the knot errors of
    /// [`KnotVector::try_new`] (and [`Error::TooFewControlPoints`]) of a
    /// direction; [`Error::NetWeight`] for a bad weight; [`Error::Dimension`]
    /// unless `1 ≤ D ≤ 3`.
    pub fn try_new(
        degree: [usize; 2],
        points: Vec<Vec<Nt2Point<D>>>,
        weights: Vec<Vec<f64>>,
        knots: [Option<Vec<f64>>; 2],
    ) -> Result<Self, Error> {
        Axis::first::<D>()?;
        let shape = net_shape(&points, "points")?;
        let [ku, kv] = knots;
        let knots = [
            knots_in(Direction::U, ku, degree[0], shape[0])?,
            knots_in(Direction::V, kv, degree[1], shape[1])?,
        ];
        let weights = net_weights(&weights, shape)?;
        Ok(FuzzySurface {
            points: points.into_iter().flatten().collect(),
            weights,
            weight_numbers: None,
            knots,
        })
    }

    /// This surface with fuzzy weights (docs/method.md §16): one normal
    /// type-2 fuzzy number per net point, row by row (`numbers[i·nv + j]`
    /// is the weight of `P̃ᵢⱼ`), every value of each (its upper cut's feet
    /// included) a valid weight. The crisp values become
    /// [`FuzzySurface::weights`]. Numbers that are all crisp (every value
    /// equal) leave the surface with crisp weights.
    ///
    /// # Errors
    /// [`Error::WeightCount`] unless there is one number per net point;
    /// [`Error::Weight`] or [`Error::WeightOutOfRange`] for the first value
    /// (the least first) that is not a valid weight, its index counted row
    /// by row.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzySurface, Layer, Nt2Number, Nt2Point};
    /// let c = |x: f64| Nt2Number::try_crisp(x);
    /// let p = |x: f64, y: f64, z: f64| Ok::<_, t2spline::Error>(Nt2Point::new([c(x)?, c(y)?, c(z)?]));
    /// let net = vec![vec![p(0.0, 0.0, 0.0)?, p(0.0, 1.0, 0.0)?], vec![p(1.0, 0.0, 0.0)?, p(1.0, 1.0, 1.0)?]];
    /// let w = Nt2Number::try_new(1.0, [0.5, 3.0], [0.75, 2.0], [1.0, 1.0], 1.0)?;
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?
    ///     .with_weight_numbers(vec![c(1.0)?, c(1.0)?, c(1.0)?, w])?;
    /// // The upper right layer weighs the corner (1, 1, 1) by 3: at the centre
    /// // z = 3/(1 + 1 + 1 + 3).
    /// let at = s.eval_layers(0.5, 0.5)?;
    /// assert!((at[Layer::UpperRight][2] - 0.5).abs() < 1e-15);
    /// assert!((at[Layer::Crisp][2] - 0.25).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn with_weight_numbers(self, numbers: Vec<Nt2Number>) -> Result<Self, Error> {
        let (weights, weight_numbers) = weights_of(numbers, self.points.len())?;
        Ok(FuzzySurface {
            weights,
            weight_numbers,
            ..self
        })
    }

    /// The fuzzy weights (docs/method.md §16), row by row, or `None` where
    /// the weights are crisp.
    #[must_use]
    pub fn weight_numbers(&self) -> Option<&[Nt2Number]> {
        self.weight_numbers.as_deref()
    }

    /// `Err(`[`Error::FuzzyWeights`]`)` naming `what` where the weights are
    /// fuzzy: the guard of the operations that take crisp weights only.
    pub(crate) fn crisp_weights_for(&self, what: &'static str) -> Result<(), Error> {
        crisp_only(self.weight_numbers(), what)
    }

    /// A fuzzy surface from parts an exact algorithm derived from a valid one.
    pub(crate) fn from_parts_unchecked(
        points: Vec<Nt2Point<D>>,
        weights: Vec<f64>,
        knots: [KnotVector; 2],
    ) -> Self {
        debug_assert_eq!(points.len(), knots[0].count() * knots[1].count());
        debug_assert_eq!(weights.len(), points.len());
        FuzzySurface {
            points,
            weights,
            weight_numbers: None,
            knots,
        }
    }

    /// The fuzzy control points, row by row (`points()[i·nv + j]` is `P̃ᵢⱼ`).
    #[must_use]
    pub fn points(&self) -> &[Nt2Point<D>] {
        &self.points
    }

    /// The weights, row by row: with fuzzy weights, their crisp values.
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The knot vector of one direction.
    #[must_use]
    pub fn knots(&self, direction: Direction) -> &KnotVector {
        &self.knots[direction.index()]
    }

    /// The degrees `[p, q]`.
    #[must_use]
    pub fn degree(&self) -> [usize; 2] {
        self.knots.each_ref().map(KnotVector::degree)
    }

    /// The shape of the net `[nu, nv]`.
    #[must_use]
    pub fn shape(&self) -> [usize; 2] {
        self.knots.each_ref().map(KnotVector::count)
    }

    /// The parameter domain of one direction.
    #[must_use]
    pub fn domain(&self, direction: Direction) -> Domain {
        self.knots(direction).domain()
    }

    /// Checks `(u, v)` against the domain.
    pub(crate) fn check(&self, u: f64, v: f64) -> Result<(), Error> {
        check_params(&self.knots, u, v)
    }

    /// A crisp surface with this surface's weights and knots through
    /// `control_points` (one per fuzzy control point, row by row).
    pub(crate) fn with_control_points(&self, control_points: Vec<[f64; D]>) -> NurbsSurface<D> {
        NurbsSurface::from_parts_unchecked(control_points, self.weights.clone(), self.knots.clone())
    }

    /// The layer surface through one value of every control point (docs/method.md §8).
    #[must_use]
    pub fn layer_surface(&self, layer: Layer) -> NurbsSurface<D> {
        Layered::layer(self, layer)
    }

    /// The surface through the crisp values: the crisp rational B-spline surface.
    #[must_use]
    pub fn crisp_surface(&self) -> NurbsSurface<D> {
        self.layer_surface(Layer::Crisp)
    }

    /// The seven layer surfaces at `(u, v)`, from one evaluation of the
    /// rational basis; their values keep the docs/method.md §1 order exactly.
    /// With fuzzy weights each layer surface has weights of its own
    /// (docs/method.md §16), is evaluated by itself, and the values need not
    /// be ordered.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `u` or `v` is
    /// NaN or outside its domain.
    pub fn eval_layers(&self, u: f64, v: f64) -> Result<Layers<[f64; D]>, Error> {
        check_params(&self.knots, u, v)?;
        if self.weight_numbers.is_some() {
            return Layers::try_from_fn(|layer| self.layer_surface(layer).eval(u, v));
        }
        let basis = TensorBasis::new(&self.knots, &self.weights, u, v);
        let mut out = Layers::from_fn(|_| [0.0; D]);
        basis.for_each(self.shape()[1], |k, r| {
            let p = &self.points[k];
            for layer in Layer::ALL {
                for (o, x) in out[layer].iter_mut().zip(p.layer(layer)) {
                    *o += r * x;
                }
            }
        });
        Ok(out)
    }

    /// The lower height shared by every number of each coordinate, or `None`
    /// if some coordinate mixes heights.
    #[must_use]
    pub fn coordinate_heights(&self) -> Option<[Height; D]> {
        common_heights(&self.points, |_, _| Place::NONE).ok()
    }

    /// The fuzzy surface at `(u, v)` as a fuzzy point when each coordinate has
    /// one lower height for all control points and the weights are crisp;
    /// `Ok(None)` otherwise (docs/method.md §6; layers with weights of their
    /// own need not be ordered, docs/method.md §16).
    ///
    /// # Errors
    /// As [`FuzzySurface::eval_layers`].
    pub fn eval(&self, u: f64, v: f64) -> Result<Option<Nt2Point<D>>, Error> {
        let layers = self.eval_layers(u, v)?;
        if self.weight_numbers.is_some() {
            return Ok(None);
        }
        Ok(self.coordinate_heights().map(|heights| {
            Nt2Point::new(std::array::from_fn(|d| {
                Nt2Number::from_layers_unchecked(&layers.map(|p| p[d]), heights[d])
            }))
        }))
    }

    /// The point of every layer surface closest to `target` (see
    /// [`NurbsSurface::closest_point`]). Other per-layer quantities come from
    /// [`FuzzySurface::layer_surface`].
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::OutOfRange`] naming the axis if a
    /// coordinate of `target` is not finite or of magnitude above
    /// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE).
    pub fn closest_points(
        &self,
        target: [f64; D],
    ) -> Result<Layers<ClosestSurfacePoint<D>>, Error> {
        check_target(&target)?;
        layered::closest(self, target)
    }

    /// The derivatives of every layer surface at `(u, v)` up to `order` (see
    /// [`NurbsSurface::derivatives`]): `[layer][k][l]` = `∂ᵏ⁺ˡS/∂uᵏ∂vˡ`.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `u` or `v` is
    /// NaN or outside its domain; [`Error::OutOfRange`] for an order above
    /// [`MAX_DERIVATIVE_ORDER`](crate::nurbs::MAX_DERIVATIVE_ORDER).
    pub fn derivatives(
        &self,
        u: f64,
        v: f64,
        order: usize,
    ) -> Result<Layers<Vec<Vec<[f64; D]>>>, Error> {
        layered::derivatives(self, [u, v], order)
    }

    /// The bounding box of all seven layer surfaces (see
    /// [`NurbsSurface::bounding_box`]): the region the fuzzy surface can
    /// occupy. Since the layers are ordered at every `(u, v)`, its lower
    /// corner comes from the `upper_left` surface and its upper corner from
    /// the `upper_right` surface. With fuzzy weights the box is that of
    /// the control points' upper cuts at level 0, which holds every surface
    /// with its weights inside their cuts (see
    /// [`layered::bounding_box`](crate::capability::layered::bounding_box)).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzySurface, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c, c], [c, c], 1.0);
    /// let p = |x: f64, y: f64| Ok::<_, t2spline::Error>(Nt2Point::new([n(x)?, n(y)?, n(x + y)?]));
    /// let net = vec![vec![p(0.0, 0.0)?, p(0.0, 1.0)?], vec![p(1.0, 0.0)?, p(1.0, 1.0)?]];
    /// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let b = s.bounding_box();
    /// let want = [[-1.0, -1.0, -1.0], [3.0, 3.0, 4.0]];
    /// for (got, want) in [b.min, b.max].iter().flatten().zip(want.iter().flatten()) {
    ///     assert!((got - want).abs() < 1e-15);
    /// }
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn bounding_box(&self) -> BoundingBox<D> {
        layered::bounding_box(self)
    }

    /// Runs stages 2–4 of Algorithm 1.1 on the control net at level `alpha`
    /// with the paper's type reduction (docs/method.md §7, §8); the same as
    /// `self.solve_with(alpha, TypeReduction::Paper)`.
    #[must_use]
    pub fn solve(&self, alpha: Alpha) -> SurfaceSolution<D> {
        self.solve_with(alpha, TypeReduction::Paper)
    }

    /// Runs stages 2–4 on the control net with the type reduction `method`
    /// (docs/method.md §8, §9), number by number exactly as
    /// [`FuzzyCurve::solve_with`](crate::FuzzyCurve::solve_with) does.
    #[must_use]
    pub fn solve_with(&self, alpha: Alpha, method: TypeReduction) -> SurfaceSolution<D> {
        SurfaceSolution::new(self.clone(), alpha, method)
    }

    /// The place `points[i][j].axis` of the `k`-th point of the net.
    fn place(&self, k: usize, axis: crate::fuzzy::Axis) -> Place {
        let nv = self.shape()[1];
        Place::in_net(k / nv, k % nv, axis)
    }

    /// The lower height of each coordinate, shared by every point.
    fn common_heights(&self) -> Result<[Height; D], Error> {
        common_heights(&self.points, |k, axis| self.place(k, axis))
    }

    /// Runs a curve operation in `direction` on the seven stacked layers of
    /// the net (see `nurbs/surface/operations.rs`) and rebuilds the fuzzy
    /// surface; also returns the largest order repair made (see
    /// `pipeline/fuzzy_ops.rs`).
    pub(crate) fn map_rows(
        &self,
        direction: Direction,
        op: impl FnOnce(&KnotVector, &[Row]) -> Result<(KnotVector, Vec<Row>), Error>,
    ) -> Result<(Self, f64), Error> {
        self.crisp_weights_for("a knot operation")?;
        let heights = self.common_heights()?;
        let rows = stacked_rows(&self.points, &self.weights);
        rebuild(map_net((&self.knots, &rows), direction, op)?, heights)
    }

    /// The fuzzy isoparametric curve at `t` in `direction` (see
    /// [`NurbsSurface::isocurve`]): every layer of it is the isocurve of the
    /// layer surface.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`];
    /// [`Error::MixedHeights`] if a coordinate mixes lower heights; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
    pub fn isocurve(&self, direction: Direction, t: f64) -> Result<FuzzyCurve<D>, Error> {
        self.domain(direction)
            .check(t)
            .map_err(|e| e.in_direction(direction))?;
        self.crisp_weights_for("an isocurve")?;
        let heights = self.common_heights()?;
        let rows = isocurve_rows(
            (&self.knots, &stacked_rows(&self.points, &self.weights)),
            direction,
            t,
        );
        let (points, weights, _) = from_stacked_rows(&rows, heights);
        let knots = self.knots(direction.other()).clone();
        Ok(FuzzyCurve::from_parts_unchecked(points, weights, knots))
    }

    /// The same fuzzy surface with the knot `t` inserted `times` times in
    /// `direction`, in every layer (see [`NurbsSurface::insert_knot`]); the
    /// layer surfaces are unchanged, and so are the surfaces of every stage.
    ///
    /// # Errors
    /// Those of `NurbsSurface::insert_knot`, and [`Error::MixedHeights`] if a
    /// coordinate mixes lower heights; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
    pub fn insert_knot(&self, direction: Direction, t: f64, times: usize) -> Result<Self, Error> {
        self.crisp_weights_for("knot insertion")?;
        Ok(self.map_rows(direction, |k, r| insert(k, r, t, times))?.0)
    }

    /// The same fuzzy surface with all knots of `new` inserted in `direction`,
    /// in every layer (see [`NurbsSurface::refine_knots`]).
    ///
    /// # Errors
    /// As [`FuzzySurface::insert_knot`].
    pub fn refine_knots(&self, direction: Direction, new: &[f64]) -> Result<Self, Error> {
        self.crisp_weights_for("knot refinement")?;
        Ok(self.map_rows(direction, |k, r| refine(k, r, new))?.0)
    }

    /// The same fuzzy surface with the degree in `direction` raised by
    /// `times`, in every layer (see [`NurbsSurface::elevate_degree`]).
    ///
    /// # Errors
    /// As `NurbsSurface::elevate_degree`, and [`Error::MixedHeights`]; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
    pub fn elevate_degree(&self, direction: Direction, times: usize) -> Result<Self, Error> {
        self.crisp_weights_for("degree elevation")?;
        check_elevation(self.degree()[direction.index()], times)
            .map_err(|e| e.in_direction(direction))?;
        Ok(self.map_rows(direction, |k, r| Ok(elevate(k, r, times)))?.0)
    }

    /// The two fuzzy surfaces on either side of `t` in `direction`, every
    /// layer split there (see [`NurbsSurface::split_at`]).
    ///
    /// # Errors
    /// As `NurbsSurface::split_at`, and [`Error::MixedHeights`]; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Direction, FuzzySurface, Layer, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
    /// let p = |x: f64, y: f64, z: f64| Ok::<_, t2spline::Error>(Nt2Point::new([n(x)?, n(y)?, n(z)?]));
    /// let net = vec![
    ///     vec![p(0.0, 0.0, 0.0)?, p(0.0, 1.0, 0.0)?, p(0.0, 2.0, 1.0)?],
    ///     vec![p(1.0, 0.0, 0.0)?, p(1.0, 1.0, 1.0)?, p(1.0, 2.0, 0.0)?],
    /// ];
    /// let s = FuzzySurface::try_new([1, 2], net, vec![vec![1.0, 2.0, 1.0]; 2], [None, None])?;
    /// let [low, high] = s.split_at(Direction::V, 0.3)?;
    /// let (a, b) = (s.eval_layers(0.4, 0.2)?, low.eval_layers(0.4, 0.2)?);
    /// assert!((a[Layer::UpperLeft][2] - b[Layer::UpperLeft][2]).abs() < 1e-15);
    /// assert_eq!(high.domain(Direction::V).start, 0.3);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn split_at(&self, direction: Direction, t: f64) -> Result<[Self; 2], Error> {
        self.crisp_weights_for("splitting")?;
        let heights = self.common_heights()?;
        let rows = stacked_rows(&self.points, &self.weights);
        let [a, b] = split_net((&self.knots, &rows), direction, t)?;
        Ok([rebuild(a, heights)?.0, rebuild(b, heights)?.0])
    }

    /// The fuzzy surface over the rectangle `[u₀, u₁] × [v₀, v₁]`, clamped in
    /// both directions (see [`NurbsSurface::segment`]).
    ///
    /// # Errors
    /// As `NurbsSurface::segment`, and [`Error::MixedHeights`]; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
    pub fn segment(&self, u: [f64; 2], v: [f64; 2]) -> Result<Self, Error> {
        self.crisp_weights_for("a segment")?;
        let heights = self.common_heights()?;
        let rows = stacked_rows(&self.points, &self.weights);
        let net = segment_net((&self.knots, &rows), u, v)?;
        Ok(rebuild(net, heights)?.0)
    }
}

/// The fuzzy surface from a net of stacked homogeneous rows, with the order
/// repaired; also the largest repair made.
///
/// # Errors
/// [`Error::IllConditioned`] if the rows are outside the input ranges.
fn rebuild<const D: usize>(
    (knots, rows): RowNet,
    heights: [Height; D],
) -> Result<(FuzzySurface<D>, f64), Error> {
    check_rows(&rows, "the operation on the fuzzy surface")?;
    let (points, weights, worst) = from_stacked_rows(&rows, heights);
    Ok((
        FuzzySurface::from_parts_unchecked(points, weights, knots),
        worst,
    ))
}

impl FuzzySurface<3> {
    /// The curvature of every layer surface at `(u, v)` (see
    /// [`NurbsSurface::curvature`]): Gaussian, mean and principal curvatures
    /// and principal directions, each layer with its own normal. Unlike the
    /// points, the curvatures of the layers are not ordered.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `u` or `v` is
    /// NaN or outside its domain; [`Error::InLayer`] naming the first layer
    /// (in the order of docs/method.md §1) whose curvature is undefined, wrapping its
    /// [`Error::SingularNormal`] or [`Error::IllConditioned`].
    ///
    /// # Examples
    /// A fuzzy quarter cylinder whose radius is the fuzzy number
    /// `(1, [0.5, 2], [0.7, 1.5], [0.9, 1.2])`: each layer is a cylinder of
    /// radius `r` and curvatures `[0, −1/r]`.
    /// ```
    /// # use t2spline::{FuzzySurface, Layer, Nt2Number, Nt2Point};
    /// let r = Nt2Number::try_new(1.0, [0.5, 2.0], [0.7, 1.5], [0.9, 1.2], 0.5)?;
    /// let zero = Nt2Number::try_new(0.0, [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], 0.5)?;
    /// let z = |h: f64| Nt2Number::try_new(h, [h, h], [h, h], [h, h], 0.5);
    /// let p = |x: &Nt2Number, y: &Nt2Number, h: f64| Ok::<_, t2spline::Error>(Nt2Point::new([x.clone(), y.clone(), z(h)?]));
    /// let net = vec![
    ///     vec![p(&r, &zero, 0.0)?, p(&r, &zero, 1.0)?],
    ///     vec![p(&r, &r, 0.0)?, p(&r, &r, 1.0)?],
    ///     vec![p(&zero, &r, 0.0)?, p(&zero, &r, 1.0)?],
    /// ];
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let s = FuzzySurface::try_new([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]], [None, None])?;
    /// let c = s.curvatures(0.4, 0.5)?;
    /// assert!((c[Layer::Crisp].principal[1] + 1.0).abs() < 1e-14);
    /// assert!((c[Layer::UpperLeft].principal[1] + 2.0).abs() < 1e-14); // r = 0.5
    /// assert!((c[Layer::UpperRight].mean + 0.25).abs() < 1e-14); // r = 2
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn curvatures(&self, u: f64, v: f64) -> Result<Layers<SurfaceCurvature>, Error> {
        layered::curvatures(self, [u, v])
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::nurbs::split::segment;
    use crate::strategies;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Insertion and splitting keep the seven values ordered bit for bit
        /// (nothing to repair); elevation repairs at most rounding (the bound
        /// of `strategies::elevation_tolerance`), as for curves.
        #[test]
        fn the_order_needs_no_repair_beyond_rounding(
            s in strategies::fuzzy_surface_common_height::<3>(), d in 0usize..2, at in 0.05..0.95f64,
        ) {
            let direction = Direction::BOTH[d];
            let k = s.knots(direction).clone();
            let t = k.domain().lerp(at);
            let room = k.degree() + 1 - k.multiplicity(t);
            let (_, worst) = s.map_rows(direction, |k, r| insert(k, r, t, room.min(2))).unwrap();
            prop_assert_eq!(worst, 0.0);
            let (a, b) = (k.domain().start, k.domain().end);
            let (_, worst) = s.map_rows(direction, |k, r| segment(k, r, a, t.max(a + (b - a) / 4.0))).unwrap();
            prop_assert_eq!(worst, 0.0);
            let scale = s
                .points()
                .iter()
                .flat_map(|p| Layer::ALL.map(|l| p.layer(l)))
                .flatten()
                .fold(1.0, |m: f64, x| m.max(x.abs()));
            let (_, worst) = s.map_rows(direction, |k, r| Ok(elevate(k, r, 1))).unwrap();
            prop_assert!(worst <= strategies::elevation_tolerance(&k, s.weights(), scale), "{}", worst);
        }
    }

    proptest! {
        #![proptest_config(strategies::cases(4, 8))]

        /// The layer-wise closest points are those of the layer surfaces; the
        /// box is the union of the layer surfaces' boxes, spanned by the two
        /// outer layers, and holds every layer's samples.
        #[test]
        fn closest_points_and_the_box_are_those_of_the_layers(
            s in strategies::fuzzy_surface_common_height::<3>(),
            target in prop::array::uniform3(-5.0f64..5.0),
        ) {
            let near = s.closest_points(target).unwrap();
            let b = s.bounding_box();
            let outer = s.layer_surface(Layer::UpperLeft).bounding_box();
            let upper = s.layer_surface(Layer::UpperRight).bounding_box();
            prop_assert_eq!(b.min, outer.min);
            prop_assert_eq!(b.max, upper.max);
            for l in Layer::ALL {
                let layer = s.layer_surface(l);
                prop_assert_eq!(near[l], layer.closest_point(target).unwrap());
                let lb = layer.bounding_box();
                prop_assert!(b.contains(&lb.min, 0.0) && b.contains(&lb.max, 0.0));
            }
            let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
            for u in du.uniform(21).unwrap() {
                for v in dv.uniform(21).unwrap() {
                    let layers = s.eval_layers(u, v).unwrap();
                    for l in Layer::ALL {
                        prop_assert!(b.contains(&layers[l], 1e-12));
                    }
                }
            }
        }
    }

    #[test]
    fn a_target_that_is_not_finite_is_an_error() {
        let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c, c], [c, c], 1.0).unwrap();
        let p = |x: f64, y: f64| Nt2Point::new([n(x), n(y)]);
        let net = vec![
            vec![p(0.0, 0.0), p(0.0, 1.0)],
            vec![p(1.0, 0.0), p(1.0, 1.0)],
        ];
        let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).unwrap();
        assert!(matches!(
            s.closest_points([0.0, f64::NEG_INFINITY]),
            Err(Error::NotFinite { .. })
        ));
        let near = s.closest_points([0.5, 3.0]).unwrap();
        assert_eq!(near[Layer::Crisp].point, [0.5, 1.0]);
        // The upper right layer spans [1, 2]²: its nearest point is a corner.
        assert_eq!(near[Layer::UpperRight].point, [1.0, 2.0]);
    }
}
