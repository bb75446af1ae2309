//! The curvature of surfaces in space as numpy arrays: `NurbsSurface.curvature`
//! and `FuzzySurface.curvatures` give a dict of `gaussian`, `mean`,
//! `principal` and `directions` at every pair of `u` and `v` (broadcast as
//! numpy does), and the refusal of quantities that need a normal on surfaces
//! in the plane.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use t2spline::{Curvature, Layers, SurfaceCurvature};

use crate::arrays::array;
use crate::dim::{ByDim, Family};
use crate::errors::compute;
use crate::py_types::{DictResult, Obj};
use crate::sample::{check_output, Pairs};

/// The numbers of one [`SurfaceCurvature`]: K, H, k₁, k₂, e₁ and e₂.
const NUMBERS: usize = 10;

/// The curvature of a surface at one pair `(u, v)`: one
/// [`SurfaceCurvature`], or the seven of a fuzzy surface's layers.
pub(crate) trait Curvatures {
    /// The axes before the quantities' own: `[]`, or `[7]` for the layers.
    const LAYERS: &'static [usize];

    /// Appends the curvatures.
    fn extend_into(self, out: &mut Vec<SurfaceCurvature>);
}

impl Curvatures for SurfaceCurvature {
    const LAYERS: &'static [usize] = &[];

    fn extend_into(self, out: &mut Vec<SurfaceCurvature>) {
        out.push(self);
    }
}

impl Curvatures for Layers<SurfaceCurvature> {
    const LAYERS: &'static [usize] = &[7];

    fn extend_into(self, out: &mut Vec<SurfaceCurvature>) {
        out.extend(self.into_array());
    }
}

/// The curvature of the surface in space inside `value` at every pair of
/// `u` and `v` (broadcast as numpy does), crisp or fuzzy, as a dict of
/// arrays: `gaussian` and `mean` of shape `broadcast(u, v).shape + layers`
/// (`layers`: `(7,)` for a fuzzy surface), `principal` that `+ (2,)`,
/// `directions` that `+ (2, 3)`. Runs with the GIL released.
///
/// # Errors
/// `ValueError` naming `what` for a surface in the plane; the errors of
/// reading `u` and `v`, shapes that do not broadcast, an output beyond the
/// size limit; the first error of the core.
pub(crate) fn surface_curvature<'py, F: Family>(
    py: Python<'py>,
    value: &ByDim<F>,
    what: &str,
    [u, v]: [&Obj<'py>; 2],
) -> DictResult<'py>
where
    F::Of<3>: Curvature<Param = [f64; 2]>,
    <F::Of<3> as Curvature>::Curvature: Curvatures,
{
    let s = spatial(value, what)?;
    let layers = <<F::Of<3> as Curvature>::Curvature as Curvatures>::LAYERS;
    let pairs = Pairs::extract(u, v)?;
    let per_pair: usize = layers.iter().product();
    check_output(pairs.u.len(), per_pair * NUMBERS, "u, v")?;
    let values = compute(py, || {
        let mut out = Vec::with_capacity(pairs.u.len() * per_pair);
        for (&u, &v) in pairs.u.iter().zip(&pairs.v) {
            s.curvature_at([u, v])?.extend_into(&mut out);
        }
        Ok(out)
    })?;
    let shape = |tail: &[usize]| -> Vec<usize> {
        pairs
            .shape
            .iter()
            .chain(layers)
            .chain(tail)
            .copied()
            .collect()
    };
    let out = PyDict::new(py);
    let gaussian = values.iter().map(|c| c.gaussian).collect();
    out.set_item("gaussian", array(py, gaussian, &shape(&[]))?)?;
    let mean = values.iter().map(|c| c.mean).collect();
    out.set_item("mean", array(py, mean, &shape(&[]))?)?;
    let principal = values.iter().flat_map(|c| c.principal).collect();
    out.set_item("principal", array(py, principal, &shape(&[2]))?)?;
    let directions = values
        .iter()
        .flat_map(|c| c.directions.into_iter().flatten())
        .collect();
    out.set_item("directions", array(py, directions, &shape(&[2, 3]))?)?;
    Ok(out)
}

/// The surface in space inside `value`.
///
/// # Errors
/// `ValueError` naming `what` for a surface in the plane, which has no
/// normal.
pub(crate) fn spatial<'a, F: Family>(value: &'a ByDim<F>, what: &str) -> PyResult<&'a F::Of<3>> {
    value.spatial_or(|| format!("{what}: a surface in the plane has none (it needs 3 coordinates)"))
}
