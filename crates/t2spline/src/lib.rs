//! # t2spline — normal type-2 fuzzy rational B-spline curves
//!
//! Models uncertain data with rational B-spline curves whose control points are
//! *normal triangular type-2 fuzzy numbers* (NT2TFN), following Zakaria, Wahab
//! and Gobithaasan, "Normal Type-2 Fuzzy Rational B-spline Curve", as made
//! precise in docs/method.md (section numbers below refer to it).
//!
//! The crate has no I/O: job and result files live in `t2spline-io`, the
//! command-line tool in `t2spline-cli`.
//!
//! ## The method in one example (Algorithm 1.1)
//! ```
//! use t2spline::{Alpha, FuzzyCurve, Layer, Nt2Number, Nt2Point, Side};
//!
//! // Stage 1: fuzzy control points (crisp value, upper, primary, lower feet, h).
//! let x = |c: f64| Nt2Number::try_new(c, [c - 0.6, c + 0.9], [c - 0.4, c + 0.6], [c - 0.2, c + 0.3], 0.6);
//! let points = vec![
//!     Nt2Point::new([x(1.0)?, x(1.0)?]),
//!     Nt2Point::new([x(2.0)?, x(4.0)?]),
//!     Nt2Point::new([x(5.0)?, x(4.5)?]),
//!     Nt2Point::new([x(6.0)?, x(1.0)?]),
//! ];
//! let curve = FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 3.0, 1.0], None)?;
//! let layers = curve.eval_layers(0.25)?;            // seven ordered layer points
//! assert!(layers[Layer::UpperLeft][0] <= layers[Layer::Crisp][0]);
//!
//! // Stages 2–4 at alpha = 0.8 (above h = 0.6: the lower cut is absent).
//! let solution = curve.solve(Alpha::try_new(0.8)?);
//! assert!(solution.alpha_cut_curve(Layer::LowerLeft).is_none());
//! let left = solution.type_reduced_curve(Side::Left);
//! let solved = solution.defuzzified_curve();         // the crisp type-2 solution
//! assert!(left.eval(0.5)?[0] <= solved.eval(0.5)?[0]);
//!
//! // Unequal left and right spreads move the solution off the crisp curve. Here
//! // every number has left spreads (0.6, 0.4) and right spreads (0.9, 0.6), so
//! // left = c − 0.1, right = c + 0.15 and every defuzzified point is the crisp
//! // one moved by 0.05/3 in x and y: the distance is that constant.
//! let d = solution.distance();
//! let offset = 0.05 / 3.0 * 2f64.sqrt();
//! assert!((d.max - offset).abs() < 1e-12 && (d.rms - offset).abs() < 1e-12);
//! # Ok::<(), t2spline::Error>(())
//! ```
//!
//! ## Contents
//! - [`fuzzy`]: [`Nt2Number`] (docs/method.md §1), [`Alpha`] and [`AlphaCut`] (§2), type
//!   reduction to a [`Tfn`] (§3), defuzzification (§4), [`Nt2Point`] (§5), and the
//!   seven [`Layer`]s.
//! - [`reduction`]: the type-2 literature's reductions of one number, exact
//!   (§9): the interval type-2 [`Nt2Number::centroid`] (Karnik–Mendel),
//!   [`Nt2Number::nie_tan`], the general type-2 [`Nt2Number::alpha_planes`],
//!   and [`Nt2Number::reduce`] by any [`TypeReduction`]; the discrete KM, EKM,
//!   EIASC and Nie–Tan algorithms on sampled sets ([`reduction::discrete`]).
//! - [`nurbs`]: [`KnotVector`], basis functions and [`NurbsCurve`] of any order
//!   (§6), with the curve operations of The NURBS Book: derivatives of any
//!   order, tangent, curvature, knot insertion and refinement, degree
//!   elevation, splitting, arc length and its inverse, closest point,
//!   [`BoundingBox`]. [`FuzzyCurve`] applies them to all seven layers with
//!   shared knots and weights, so the result is again a fuzzy curve.
//! - [`FuzzyCurve`] and [`FuzzySurface`] (stage 1), [`Solution`] and
//!   [`SurfaceSolution`] (stages 2–4, both [`Stages`]) and the [`Distance`]
//!   between the crisp and the defuzzified curve (§7).
//! - [`interval_weights`]: curves whose weights are uncertain too (§15): at one
//!   parameter and level, the envelope of each coordinate by Karnik–Mendel,
//!   the support function, membership of a point and sections of the convex
//!   set the curve reaches, exact.
//! - [`capability`]: the operations curves and surfaces share, as traits;
//!   [`prelude`]: the common types and traits in one import.
//! - [`fit`]: curves through data or approximating them (interpolation and
//!   least squares, The NURBS Book §9.2.1 and §9.4.1), crisp and fuzzy.
//! - [`sampling`]: the fast sampling engine — one power form of the rational
//!   basis per span for all layers and alpha levels, structure-of-arrays output,
//!   multi-threaded for large jobs ([`NurbsCurve::sample_soa`],
//!   [`FuzzyCurve::sample_layers`], [`FuzzyCurve::sample_sweep`]).
//! - [`MAX_MAGNITUDE`], [`MIN_WEIGHT`], [`MAX_WEIGHT`]: the range of inputs,
//!   chosen so that every result is finite; constructors refuse values outside.
//! - Features: `parallel` (default: large sampling jobs run on rayon's threads),
//!   `serde` (Serialize for the data types), `proptest` (generators in
//!   `strategies`).

// No panic reachable from input: outside tests, `unwrap`, `expect`, `panic!`
// and `unreachable!` are refused; the few sites that cannot fail carry an
// `#[allow]` with the invariant that makes them safe (ARCHITECTURE.md,
// "Decisions and reasons").
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::unreachable,
        clippy::todo,
        clippy::unimplemented
    )
)]

mod brent;
pub mod capability;
mod cubature;
mod error;
pub mod fit;
pub mod fuzzy;
mod golden_section;
mod heap_key;
pub mod interval_weights;
pub mod job;
mod limits;
pub mod measure;
mod nelder_mead;
pub mod nurbs;
mod pipeline;
mod place;
pub mod prelude;
mod quadrature;
pub mod reduction;
pub mod sampling;
pub mod set;
pub mod vector;
// Generators for property tests: a value they cannot build is a failing
// test, so they may `expect`.
#[cfg(any(test, feature = "proptest"))]
#[allow(clippy::expect_used, clippy::unwrap_used)]
pub mod strategies;

#[doc(no_inline)]
pub use capability::{
    Bounded, Closest, Curvature, Differentiable, KnotOperations, Layered, Parametric,
};
pub use error::{Error, Num};
#[doc(no_inline)]
pub use fuzzy::{
    Alpha, AlphaCut, Axis, Height, Interval, Layer, Layers, Membership, Nt2Number, Nt2Point,
    Nt2Point2, Nt2Point3, Tfn,
};
pub use limits::{MAX_MAGNITUDE, MAX_WEIGHT, MIN_WEIGHT};
#[doc(no_inline)]
pub use nurbs::{
    BoundingBox, ClosestPoint, ClosestSurfacePoint, Direction, Domain, KnotVector, NurbsCurve,
    NurbsSurface, SurfaceCurvature,
};
pub use pipeline::{
    Distance, FuzzyCurve, FuzzySurface, Side, Solution, Stages, SurfaceDistance, SurfaceSolution,
};
pub use place::Place;
#[doc(no_inline)]
pub use reduction::{AlphaPlanes, Reduced, TypeReduction};
