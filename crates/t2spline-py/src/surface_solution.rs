//! `SurfaceSolution`: stages 2–4 of Algorithm 1.1 at one level alpha on the
//! control net of a fuzzy surface (docs/method.md §7, §8) — the control nets of the
//! stages (shared with `Solution`, `stage_methods.rs`), their surfaces, their
//! grids and the distance between the crisp and the defuzzified surface.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::classes::{PyFuzzySurface, PyNurbsSurface, PySurfaceSolution};
use crate::construct::{layer, side};
use crate::dim::by_dim;
use crate::errors::compute;
use crate::sample::GridArg;
use crate::stage_methods::{stage_methods, stage_samples, stage_samples_dict};

stage_methods!(PySurfaceSolution, fuzzy_surface, "nu, nv" {

    /// Pickling and copying: ``FuzzySurface.solve`` again at this alpha and type
    /// reduction, the same computation and so an equal object.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::pickle::Reduced<'py>> {
        let uses_alpha = by_dim!(&slf.get().0, |s| s.type_reduction().uses_alpha());
        crate::pickle::by_solve(slf, "fuzzy_surface", uses_alpha)
    }
    /// The fuzzy surface (stage 1) this solves.
    #[getter]
    fn fuzzy_surface(&self) -> PyFuzzySurface {
        by_dim!(&self.0, |s| s.fuzzy_surface().clone().into())
    }

    /// The surface through one alpha-cut layer; ``None`` for a lower layer
    /// when some number has no lower cut at this level.
    fn alpha_cut_surface(&self, layer: &Bound<'_, PyAny>) -> PyResult<Option<PyNurbsSurface>> {
        let l = self::layer(layer, "layer")?;
        Ok(by_dim!(&self.0, |s| s.alpha_cut_surface(l).map(Into::into)))
    }

    /// The surface through the left or the right type-reduced values.
    fn type_reduced_surface(&self, side: &Bound<'_, PyAny>) -> PyResult<PyNurbsSurface> {
        let side = self::side(side)?;
        Ok(by_dim!(&self.0, |s| s.type_reduced_surface(side).into()))
    }

    /// The crisp type-2 solution: the surface through the defuzzified
    /// control net.
    fn defuzzified_surface(&self) -> PyNurbsSurface {
        by_dim!(&self.0, |s| s.defuzzified_surface().into())
    }

    /// The crisp surface, through the crisp control net.
    fn crisp_surface(&self) -> PyNurbsSurface {
        by_dim!(&self.0, |s| s.crisp_surface().into())
    }

    /// The distance ``d(u, v) = |D(u, v) − C(u, v)|`` between the
    /// defuzzified surface ``D`` and the crisp surface ``C`` at equal
    /// parameters over the whole domain ``[a, b] × [c, d]`` (docs/method.md §8)::
    ///
    ///     max = max d(u, v)   (at (u, v) = max_at),
    ///     rms = sqrt( 1/((b − a)(d − c)) ∫∫ d(u, v)² du dv )
    ///
    /// properties of the surfaces, not of a sampling: a 17 × 17 scan of
    /// every span rectangle refined by Nelder–Mead, and adaptive
    /// Gauss–Legendre cubature. Zero for symmetric spreads. The numbers of
    /// ``run``'s ``error`` for the same job, level and type reduction, bit
    /// for bit.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"max"`` (float), ``"max_at"`` (a pair ``(u, v)``), ``"rms"``
    ///     (float).
    fn distance<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = by_dim!(&self.0, |s| compute(py, || Ok(s.distance())))?;
        let out = PyDict::new(py);
        out.set_item("max", d.max)?;
        out.set_item("max_at", (d.max_at[0], d.max_at[1]))?;
        out.set_item("rms", d.rms)?;
        Ok(out)
    }

    /// The surfaces of stages 2–4 on the grid ``u × v`` by the grid engine.
    ///
    /// Parameters
    /// ----------
    /// u, v : int or array_like
    ///     Each a count of uniform parameters over its domain, or a 1-D array
    ///     of parameters.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"u"``, ``"v"`` (shapes ``(su,)``, ``(sv,)``); ``"alpha_cut"``:
    ///     the six alpha-cut layer surfaces (shape ``(su, sv, d)``, ``None``
    ///     for an absent lower layer); ``"type_reduced"``: ``"left"`` and
    ///     ``"right"``; and ``"defuzzified"`` (shape ``(su, sv, d)``). The
    ///     flat keys of earlier releases (``"type_reduced_left"``) still
    ///     answer, with a ``DeprecationWarning``.
    fn sample<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let grid = GridArg::extract(u, v)?;
        grid.check_output(9 * self.0.dimension())?;
        let out = PyDict::new(py);
        let domains = by_dim!(&self.0, |s| t2spline::Direction::BOTH
            .map(|d| s.fuzzy_surface().domain(d)));
        let [u, v] = grid.arrays(py, domains)?;
        out.set_item("u", u)?;
        out.set_item("v", v)?;
        by_dim!(&self.0, |s| {
            let stages = compute(py, || s.sample_stages(grid.u.params(), grid.v.params()))?;
            stage_samples(&out, stages.samples(), &grid.shape())
        })?;
        stage_samples_dict(out)
    }

    /// The picture in a notebook: the four stages on the surface, drawn by
    /// the figure code of ``t2spline plot``, as inline SVG under a table of
    /// alpha and the type reduction; ``None`` (no picture) for a surface in
    /// the plane.
    fn _repr_html_(&self) -> PyResult<Option<String>> {
        use crate::dim::ToModel as _;
        let (fuzzy, alpha, method): (crate::dim::ByDim<crate::dim::FuzzyNet>, _, _) =
            by_dim!(&self.0, |s| (
                s.fuzzy_surface().clone().into(),
                s.alpha(),
                s.type_reduction()
            ));
        let Ok(model) = fuzzy.to_model() else {
            return Ok(None);
        };
        let figures =
            crate::picture::stage_figures(model, alpha, method, t2spline_plot::Stages::All)?;
        let rows = [
            ("alpha", format!("{:?}", alpha.get())),
            ("type reduction", method.name().to_owned()),
        ];
        Ok(Some(crate::picture::page(&figures, &rows)))
    }

    fn __repr__(&self) -> String {
        by_dim!(&self.0, |s| {
            let surface = s.fuzzy_surface();
            let ([p, q], [nu, nv]) = (surface.degree(), surface.shape());
            format!(
                "SurfaceSolution(alpha={:?}, type_reduction='{}', control_points=({nu}, {nv}, {}), degree=({p}, {q}))",
                s.alpha().get(),
                s.type_reduction().name(),
                self.0.dimension(),
            )
        })
    }
});
