//! The types and traits most programs use, in one import:
//!
//! ```
//! use t2spline::prelude::*;
//! let c = NurbsCurve::try_clamped(1, vec![[0.0, 0.0], [3.0, 4.0]], vec![1.0, 1.0])?;
//! assert_eq!(c.bounding_box().max, [3.0, 4.0]);
//! // The capabilities are in scope: generic code runs on any curve or surface.
//! fn middle<T: Parametric<Param = f64>>(x: &T) -> Result<T::Point, Error> {
//!     x.point_at(0.5)
//! }
//! assert_eq!(middle(&c)?, [1.5, 2.0]);
//! # Ok::<(), t2spline::Error>(())
//! ```

pub use crate::capability::{
    Bounded, Closest, Curvature, Differentiable, KnotOperations, Layered, Parametric,
};
pub use crate::error::Error;
pub use crate::fuzzy::{Alpha, Layer, Layers, Nt2Number, Nt2Point};
pub use crate::job::Job;
pub use crate::nurbs::{Direction, NurbsCurve, NurbsSurface};
pub use crate::pipeline::{FuzzyCurve, FuzzySurface, Side, Solution, SurfaceSolution};
pub use crate::reduction::TypeReduction;
