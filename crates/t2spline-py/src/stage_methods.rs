//! The methods that `Solution` and `SurfaceSolution` share, written once:
//! the core's `Solution<D>` and `SurfaceSolution<D>` hold the same
//! per-number stages of their control points (`PointStages`), so the level,
//! the type reduction and the control points of stages 2–4 read the same,
//! as arrays of the net's shape.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use t2spline::{Layer, Side};

/// The six non-crisp layers, in the order of docs/method.md §1: the alpha-cut ends.
pub(crate) fn six_layers() -> impl Iterator<Item = Layer> {
    Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp)
}

/// The sampled stages 2–4 as `Solution.sample` and `SurfaceSolution.sample`
/// give them, into `out`: `"alpha_cut"` (a dict of the six layers, `None`
/// for an absent lower layer), `"type_reduced"` (a dict of `"left"` and
/// `"right"`) and `"defuzzified"`, each of shape `samples + (d,)`: the keys of
/// the result file's `curves`.
pub(crate) fn stage_samples<const D: usize>(
    out: &Bound<'_, PyDict>,
    stages: &t2spline::sampling::StageSamples<D>,
    samples: &[usize],
) -> PyResult<()> {
    let py = out.py();
    let cuts = PyDict::new(py);
    for l in six_layers() {
        match stages.alpha_cut(l) {
            Some(c) => cuts.set_item(
                l.name(),
                crate::arrays::columns_array(py, c.coords(), samples)?,
            )?,
            None => cuts.set_item(l.name(), py.None())?,
        }
    }
    out.set_item("alpha_cut", cuts)?;
    let reduced = PyDict::new(py);
    for (side, name) in [(Side::Left, "left"), (Side::Right, "right")] {
        let curve = stages.type_reduced(side);
        reduced.set_item(
            name,
            crate::arrays::columns_array(py, curve.coords(), samples)?,
        )?;
    }
    out.set_item("type_reduced", reduced)?;
    out.set_item(
        "defuzzified",
        crate::arrays::columns_array(py, stages.defuzzified().coords(), samples)?,
    )?;
    Ok(())
}

/// `samples` as the dict that `sample` returns: a `t2spline._samples.SampledStages`,
/// which still answers the flat keys of earlier releases
/// (`type_reduced_left`), with a `DeprecationWarning`.
pub(crate) fn stage_samples_dict<'py>(samples: Bound<'py, PyDict>) -> PyResult<Bound<'py, PyAny>> {
    samples
        .py()
        .import("t2spline._samples")?
        .getattr("SampledStages")?
        .call1((samples,))
}

/// `stage_methods!(Class, model, "net" { methods })`: the `#[pymethods]`
/// block of `Class` (a wrapper of a `ByDim` of solutions whose fuzzy model
/// the core gives by the method `model`, with control points in a net of
/// shape `(net)`) with its own `methods` and the shared ones:
/// `alpha`, `type_reduction`, `crisp`, `alpha_cut`, `type_reduced_left`,
/// `type_reduced_right`, `defuzzified`.
macro_rules! stage_methods {
    ($class:ident, $model:ident, $net:literal { $($own:tt)* }) => {
        #[pyo3::pymethods]
        impl $class {
            $($own)*

            /// The level alpha of the cut (stage 2); 0 with a type reduction
            /// that does not use alpha.
            #[getter]
            fn alpha(&self) -> f64 {
                $crate::dim::by_dim!(&self.0, |s| s.alpha().get())
            }

            /// The type reduction of stages 3–4 (docs/method.md §9): ``"paper"``,
            /// ``"centroid"``, ``"nie-tan"`` or ``"alpha-planes"``.
            #[getter]
            fn type_reduction(&self) -> &'static str {
                $crate::dim::by_dim!(&self.0, |s| s.type_reduction().name())
            }

            #[doc = concat!("The crisp control points, shape ``(", $net, ", d)``.")]
            #[getter]
            fn crisp<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                $crate::dim::by_dim!(&self.0, |s| self.net_array(
                    py,
                    s.$model().points().iter().map(|p| p.crisp()).collect()
                ))
            }

            /// Stage 2: the alpha-cut ends of every control point, a dict of the
            #[doc = concat!("six non-crisp layer names to arrays of shape ``(", $net, ", d)``. A")]
            /// lower end is NaN where alpha is above that number's lower height
            /// (the cut is absent, docs/method.md §2).
            #[getter]
            fn alpha_cut<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
                let out = pyo3::types::PyDict::new(py);
                for l in $crate::stage_methods::six_layers() {
                    // An absent lower cut (alpha above that number's height) is NaN.
                    let values = $crate::dim::by_dim!(&self.0, |s| s
                        .alpha_cut_points()
                        .iter()
                        .flat_map(|cuts| cuts.iter().map(|c| c.layer(l).unwrap_or(f64::NAN)))
                        .collect::<Vec<_>>());
                    let shape = $crate::dim::by_dim!(&self.0, |s| $crate::net::shape(
                        &$crate::net::Net::net(s),
                        &[self.0.dimension()]
                    ));
                    out.set_item(l.name(), $crate::arrays::array(py, values, &shape)?)?;
                }
                Ok(out)
            }

            #[doc = concat!("Stage 3: the left type-reduced control points, shape ``(", $net, ", d)``.")]
            #[getter]
            fn type_reduced_left<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                $crate::dim::by_dim!(&self.0, |s| self.net_array(
                    py,
                    s.type_reduced_side(t2spline::Side::Left)
                ))
            }

            #[doc = concat!("Stage 3: the right type-reduced control points, shape ``(", $net, ", d)``.")]
            #[getter]
            fn type_reduced_right<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                $crate::dim::by_dim!(&self.0, |s| self.net_array(
                    py,
                    s.type_reduced_side(t2spline::Side::Right)
                ))
            }

            #[doc = concat!("Stage 4: the defuzzified control points, shape ``(", $net, ", d)``.")]
            #[getter]
            fn defuzzified<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                $crate::dim::by_dim!(&self.0, |s| self.net_array(
                    py,
                    s.defuzzified_points().to_vec()
                ))
            }
        }

        impl $class {
            /// Points, one per control point, as an array of the net's shape.
            fn net_array<'py, const D: usize>(
                &self,
                py: Python<'py>,
                points: Vec<[f64; D]>,
            ) -> PyResult<Bound<'py, PyAny>> {
                let net = $crate::dim::by_dim!(&self.0, |s| $crate::net::Net::net(s));
                $crate::net::points_array(py, points, &net)
            }
        }
    };
}

pub(crate) use stage_methods;
