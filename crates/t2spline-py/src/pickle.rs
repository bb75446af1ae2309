//! Pickling and copying (`pickle`, `copy.copy`, `copy.deepcopy`, and so
//! `multiprocessing`, joblib, Dask and Ray): every class reduces to what
//! makes it again from the values its getters give, so that the object
//! unpickled is equal (`==`) to the one pickled.
//!
//! | class | made again by |
//! |---|---|
//! | `FuzzyNumber`, `NurbsCurve`, `FuzzyCurve`, `NurbsSurface`, `FuzzySurface` | its constructor, with its getters' values in the constructor's order (floats copied bit for bit, the degree following from the knots) |
//! | `AlphaCut` | `FuzzyNumber.alpha_cut` of the number it was cut from |
//! | `Solution`, `SurfaceSolution` | `FuzzyCurve.solve` / `FuzzySurface.solve` at its alpha and type reduction (the same computation, so the same numbers) |
//! | `Region` | `Region._restore` of its polygons, tolerance, membership, alpha and plane (a region is not computed again) |
//!
//! What is pickled refers to the classes by name (`t2spline.FuzzyCurve`),
//! so unpickling needs `t2spline` importable, as in a worker process.

use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// What `__reduce__` returns: a callable and its arguments.
pub(crate) type Reduced<'py> = (Bound<'py, PyAny>, Bound<'py, PyTuple>);

/// `(type(obj), (obj.g1, obj.g2, …))` for the getters `getters`, in the
/// order of the class's constructor.
pub(crate) fn by_constructor<'py, T>(
    obj: &Bound<'py, T>,
    getters: &[&str],
) -> PyResult<Reduced<'py>> {
    let obj = obj.as_any();
    let args = getters
        .iter()
        .map(|g| obj.getattr(*g))
        .collect::<PyResult<Vec<_>>>()?;
    Ok((obj.get_type().into_any(), PyTuple::new(obj.py(), args)?))
}

/// `(type(model).solve, (model, alpha, type_reduction))` for a solution
/// whose fuzzy model is the getter `model`; alpha is `None` for a type
/// reduction that does not use it (so that solving again warns of nothing).
pub(crate) fn by_solve<'py, T>(
    obj: &Bound<'py, T>,
    model: &str,
    uses_alpha: bool,
) -> PyResult<Reduced<'py>> {
    let (py, obj) = (obj.py(), obj.as_any());
    let model = obj.getattr(model)?;
    let solve = model.get_type().getattr("solve")?;
    let alpha = if uses_alpha {
        obj.getattr("alpha")?
    } else {
        py.None().into_bound(py)
    };
    let args = PyTuple::new(py, [model, alpha, obj.getattr("type_reduction")?])?;
    Ok((solve, args))
}
