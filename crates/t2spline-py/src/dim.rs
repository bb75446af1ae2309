//! One dispatch over the dimension: Python sees one `NurbsCurve`, one
//! `NurbsSurface`, one `FuzzyCurve`, … class, while the core's types carry
//! their dimension `D` (2 or 3) in the type. [`ByDim`] holds either, and the two
//! macros are the only places that tell them apart: code written once for
//! any `D` runs on both.

use pyo3::exceptions::PyValueError;
use pyo3::PyResult;
use t2spline::job::Model;
use t2spline::{
    FuzzyCurve, FuzzySurface, Nt2Point, NurbsCurve, NurbsSurface, Solution, SurfaceSolution,
};

/// A family of core types indexed by dimension.
pub(crate) trait Family {
    /// The type of dimension `D`.
    type Of<const D: usize>: Clone + std::fmt::Debug + PartialEq + Send + Sync;
}

/// A value of dimension 2 (`x`, `y`) or 3 (`x`, `y`, `z`).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ByDim<F: Family> {
    /// In the plane.
    Planar(F::Of<2>),
    /// In space.
    Spatial(F::Of<3>),
}

/// `families! { Family: Type<D>; … }`: a marker type per family of core
/// types, each with its doc comment.
macro_rules! families {
    ($($(#[$doc:meta])* $family:ident: $ty:ty;)*) => {$(
        $(#[$doc])*
        #[derive(Clone, Debug, PartialEq)]
        pub(crate) struct $family;
        impl Family for $family {
            type Of<const D: usize> = $ty;
        }
    )*};
}

families! {
    /// [`NurbsCurve`]s.
    Nurbs: NurbsCurve<D>;
    /// [`FuzzyCurve`]s.
    Fuzzy: FuzzyCurve<D>;
    /// Lists of fuzzy points.
    PointList: Vec<Nt2Point<D>>;
    /// [`Solution`]s.
    Solved: Solution<D>;
    /// [`NurbsSurface`]s.
    NurbsNet: NurbsSurface<D>;
    /// [`FuzzySurface`]s.
    FuzzyNet: FuzzySurface<D>;
    /// [`SurfaceSolution`]s.
    SolvedNet: SurfaceSolution<D>;
}

/// `by_dim!(value, |c| body)`: `body` with `c` bound to the value inside a
/// [`ByDim`] of either dimension. The body is compiled once per dimension, so
/// inside it `c` has a concrete type (`NurbsCurve<2>`, then `NurbsCurve<3>`)
/// and `ByDim::from` wraps results of that dimension.
macro_rules! by_dim {
    ($value:expr, |$c:ident| $body:expr) => {
        match $value {
            $crate::dim::ByDim::Planar($c) => $body,
            $crate::dim::ByDim::Spatial($c) => $body,
        }
    };
}

pub(crate) use by_dim;

/// `ByDim::from` for each family's type of either dimension.
macro_rules! from_dims {
    ($($family:ident: $ty:ident),*) => {
        $(
            impl From<$ty<2>> for ByDim<$family> {
                fn from(value: $ty<2>) -> Self {
                    ByDim::Planar(value)
                }
            }
            impl From<$ty<3>> for ByDim<$family> {
                fn from(value: $ty<3>) -> Self {
                    ByDim::Spatial(value)
                }
            }
        )*
    };
}

from_dims!(
    Nurbs: NurbsCurve,
    Fuzzy: FuzzyCurve,
    Solved: Solution,
    NurbsNet: NurbsSurface,
    FuzzyNet: FuzzySurface,
    SolvedNet: SurfaceSolution
);

impl<F: Family> ByDim<F> {
    /// The number of coordinates: 2 or 3.
    pub(crate) fn dimension(&self) -> usize {
        match self {
            ByDim::Planar(_) => 2,
            ByDim::Spatial(_) => 3,
        }
    }

    /// The value in the plane.
    ///
    /// # Errors
    /// `ValueError` with the message `refusal()` for one in space.
    pub(crate) fn planar_or(&self, refusal: impl FnOnce() -> String) -> PyResult<&F::Of<2>> {
        match self {
            ByDim::Planar(c) => Ok(c),
            ByDim::Spatial(_) => Err(PyValueError::new_err(refusal())),
        }
    }

    /// The value in space.
    ///
    /// # Errors
    /// `ValueError` with the message `refusal()` for one in the plane.
    pub(crate) fn spatial_or(&self, refusal: impl FnOnce() -> String) -> PyResult<&F::Of<3>> {
        match self {
            ByDim::Spatial(c) => Ok(c),
            ByDim::Planar(_) => Err(PyValueError::new_err(refusal())),
        }
    }
}

/// A value taken from a job's model.
pub(crate) trait FromModel: Sized {
    /// The value of `model`; `None` for a model of another kind.
    fn from_model(model: Model) -> Option<Self>;
}

impl FromModel for ByDim<Fuzzy> {
    /// The fuzzy curve of a job's model; `None` for a model that is not a
    /// curve.
    fn from_model(model: Model) -> Option<Self> {
        match model {
            Model::Planar(c) => Some(ByDim::Planar(c)),
            Model::Spatial(c) => Some(ByDim::Spatial(c)),
            _ => None,
        }
    }
}

impl FromModel for ByDim<FuzzyNet> {
    /// The fuzzy surface of a job's model; `None` for a model that is not a
    /// surface.
    fn from_model(model: Model) -> Option<Self> {
        match model {
            Model::Surface(s) => Some(ByDim::Spatial(s)),
            _ => None,
        }
    }
}

/// A value written back as a job's model.
pub(crate) trait ToModel {
    /// The model of a job of this value.
    ///
    /// # Errors
    /// `ValueError` for what no job holds (a surface in the plane).
    fn to_model(&self) -> pyo3::PyResult<Model>;
}

impl ToModel for ByDim<Fuzzy> {
    fn to_model(&self) -> pyo3::PyResult<Model> {
        Ok(match self {
            ByDim::Planar(c) => Model::Planar(c.clone()),
            ByDim::Spatial(c) => Model::Spatial(c.clone()),
        })
    }
}

impl ToModel for ByDim<FuzzyNet> {
    fn to_model(&self) -> pyo3::PyResult<Model> {
        match self {
            ByDim::Spatial(s) => Ok(Model::Surface(s.clone())),
            ByDim::Planar(_) => Err(pyo3::exceptions::PyValueError::new_err(
                "a surface job has points with x, y and z (docs/method.md §8); this surface is in the plane",
            )),
        }
    }
}
