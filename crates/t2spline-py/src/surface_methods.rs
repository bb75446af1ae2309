//! The methods that `NurbsSurface` and `FuzzySurface` share, written once:
//! the core's `NurbsSurface<D>` and `FuzzySurface<D>` have the same
//! accessors and the same operations in one direction (a fuzzy surface
//! applies them to its seven layers at once), so one body serves both
//! classes, as `curve_methods!` does for curves.

/// `surface_methods!(Class, Curve { methods })`: the `#[pymethods]` block of
/// `Class` (a wrapper of a `ByDim` of surfaces whose isocurves are `Curve`s)
/// with its own `methods` and the shared ones: `dimension`, `degree` (and
/// the deprecated `degree_u`, `degree_v`), `order`, `shape`, `weights`, `knots_u`, `knots_v`, `domain`,
/// `uniform_params`, `bounding_box`, `isocurve`, `insert_knot`, `refine_knots`,
/// `elevate_degree`, `split_at`, `segment`.
macro_rules! surface_methods {
    ($class:ident, $curve:ident { $($own:tt)* }) => {
        #[pyo3::pymethods]
        impl $class {
            $($own)*

            /// The number of coordinates of a point: 3 or 2.
            #[getter]
            fn dimension(&self) -> usize {
                self.0.dimension()
            }

            /// The degrees ``(p, q)`` in u and in v.
            #[getter]
            fn degree(&self) -> (usize, usize) {
                let [p, q] = $crate::dim::by_dim!(&self.0, |s| s.degree());
                (p, q)
            }

            /// The degree ``p`` in u. Deprecated: use ``degree[0]``.
            #[getter]
            fn degree_u(&self, py: Python<'_>) -> PyResult<usize> {
                $crate::directed::deprecated(py, "degree_u", "degree[0]")?;
                Ok(self.degree().0)
            }

            /// The degree ``q`` in v. Deprecated: use ``degree[1]``.
            #[getter]
            fn degree_v(&self, py: Python<'_>) -> PyResult<usize> {
                $crate::directed::deprecated(py, "degree_v", "degree[1]")?;
                Ok(self.degree().1)
            }

            /// The orders ``(p + 1, q + 1)``.
            #[getter]
            fn order(&self) -> (usize, usize) {
                let [p, q] = $crate::dim::by_dim!(&self.0, |s| s.degree());
                (p + 1, q + 1)
            }

            /// The shape of the control net ``(nu, nv)``: rows along u,
            /// columns along v.
            #[getter]
            fn shape(&self) -> (usize, usize) {
                let [nu, nv] = $crate::dim::by_dim!(&self.0, |s| s.shape());
                (nu, nv)
            }

            /// The weights, shape ``(nu, nv)``.
            #[getter]
            fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                $crate::dim::by_dim!(&self.0, |s| {
                    let net = $crate::net::Net::net(s);
                    $crate::arrays::array(py, s.weights().to_vec(), &net)
                })
            }

            /// The knot vector in u, shape ``(nu + p + 1,)`` (the default made
            /// explicit).
            #[getter]
            fn knots_u<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                self.knots_in(py, t2spline::Direction::U)
            }

            /// The knot vector in v, shape ``(nv + q + 1,)``.
            #[getter]
            fn knots_v<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                self.knots_in(py, t2spline::Direction::V)
            }

            /// The parameter domain ``((U[p], U[nu]), (V[q], V[nv]))``.
            #[getter]
            fn domain(&self) -> ((f64, f64), (f64, f64)) {
                let [u, v] = self.domains();
                ((u.start, u.end), (v.start, v.end))
            }

            /// ``count_u`` and ``count_v`` uniform parameters over the domain
            /// in u and in v (docs/jobs.md), the parameters of
            /// ``sample(count_u, count_v)``.
            fn uniform_params<'py>(
                &self,
                py: Python<'py>,
                count_u: &Bound<'py, PyAny>,
                count_v: &Bound<'py, PyAny>,
            ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
                let [u, v] = self.domains();
                Ok((
                    $crate::curve_methods::uniform_params(py, u, count_u, "count_u")?,
                    $crate::curve_methods::uniform_params(py, v, count_v, "count_v")?,
                ))
            }

            /// The tight axis-aligned box of the surface ``(min, max)``, each
            /// of shape ``(dimension,)`` (per knot-span patch: the box of its
            /// control points as a bound, refined by the extrema of each
            /// coordinate); for a fuzzy surface the box of all seven layer
            /// surfaces.
            fn bounding_box<'py>(
                &self,
                py: Python<'py>,
            ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
                $crate::dim::by_dim!(&self.0, |s| $crate::capability::bounding_box(py, s))
            }

            /// The isoparametric curve at ``t`` in ``direction``: for ``"u"``
            /// the curve ``v ↦ S(t, v)``, for ``"v"`` the curve
            /// ``u ↦ S(u, t)`` (The NURBS Book §4.5), exactly; a fuzzy
            /// surface gives a fuzzy curve, every layer the isocurve of its
            /// layer surface.
            ///
            /// Examples
            /// --------
            /// >>> s = NurbsSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], degree=1)
            /// >>> s.isocurve(0.25, direction="u").eval(0.6).tolist()     # S(0.25, 0.6) = (u, v, u·v)
            /// [0.25, 0.6, 0.15]
            #[pyo3(signature = (*args, t=None, direction=None), text_signature = "($self, t, *, direction)")]
            fn isocurve(
                &self,
                py: Python<'_>,
                args: &Bound<'_, pyo3::types::PyTuple>,
                t: Option<&Bound<'_, PyAny>>,
                direction: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<$curve> {
                let class = stringify!($class);
                let (direction, [t]) =
                    $crate::directed::directed(class, "isocurve", ["t"], args, [t], direction)?;
                let t = $crate::keyword::real(&$crate::directed::required(t, "isocurve", "t")?, "t")?;
                $crate::dim::by_dim!(&self.0, |s| $crate::errors::compute(py, || Ok(s
                    .isocurve(direction, t)?
                    .into())))
            }

            /// The same surface with the knot ``t`` inserted ``times`` times in
            /// ``direction`` (``"u"`` or ``"v"``; The NURBS Book A5.1 on every
            /// line of the net). A fuzzy surface inserts it into all seven
            /// layers at once; their order holds exactly.
            ///
            /// Raises
            /// ------
            /// ValueError
            ///     If ``t`` is outside the domain of ``direction`` or would
            ///     repeat more than its order; for a fuzzy surface, when a
            ///     coordinate mixes lower heights.
            #[pyo3(signature = (*args, t=None, times=None, direction=None), text_signature = "($self, t, times=1, *, direction)")]
            fn insert_knot(
                &self,
                py: Python<'_>,
                args: &Bound<'_, pyo3::types::PyTuple>,
                t: Option<&Bound<'_, PyAny>>,
                times: Option<&Bound<'_, PyAny>>,
                direction: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<Self> {
                let class = stringify!($class);
                let (direction, [t, times]) = $crate::directed::directed(
                    class, "insert_knot", ["t", "times"], args, [t, times], direction,
                )?;
                let t = $crate::keyword::real(&$crate::directed::required(t, "insert_knot", "t")?, "t")?;
                let times = $crate::keyword::times(times.as_ref())?;
                let op = $crate::knot_ops::KnotOp::Insert(t, times);
                let [s] = $crate::knot_ops::apply(py, &self.0, direction, op)?;
                Ok(Self(s))
            }

            /// The same surface with all of ``knots`` inserted in
            /// ``direction`` (knot refinement, A5.4 on every line of the net).
            #[pyo3(signature = (*args, knots=None, direction=None), text_signature = "($self, knots, *, direction)")]
            fn refine_knots(
                &self,
                py: Python<'_>,
                args: &Bound<'_, pyo3::types::PyTuple>,
                knots: Option<&Bound<'_, PyAny>>,
                direction: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<Self> {
                let class = stringify!($class);
                let (direction, [knots]) = $crate::directed::directed(
                    class, "refine_knots", ["knots"], args, [knots], direction,
                )?;
                let knots = $crate::directed::required(knots, "refine_knots", "knots")?;
                let new = $crate::arrays::optional_vector(Some(&knots), "knots")?
                    .unwrap_or_default();
                let op = $crate::knot_ops::KnotOp::Refine(&new);
                let [s] = $crate::knot_ops::apply(py, &self.0, direction, op)?;
                Ok(Self(s))
            }

            /// The same surface with its degree in ``direction`` raised by
            /// ``times`` (A5.9 on every line of the net; an unclamped
            /// direction is first cut to its domain).
            #[pyo3(signature = (*args, times=None, direction=None), text_signature = "($self, times=1, *, direction)")]
            fn elevate_degree(
                &self,
                py: Python<'_>,
                args: &Bound<'_, pyo3::types::PyTuple>,
                times: Option<&Bound<'_, PyAny>>,
                direction: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<Self> {
                let class = stringify!($class);
                let (direction, [times]) = $crate::directed::directed(
                    class, "elevate_degree", ["times"], args, [times], direction,
                )?;
                let times = $crate::keyword::times(times.as_ref())?;
                let op = $crate::knot_ops::KnotOp::Elevate(times);
                let [s] = $crate::knot_ops::apply(py, &self.0, direction, op)?;
                Ok(Self(s))
            }

            /// The two surfaces on either side of ``t`` in ``direction``,
            /// strictly inside its domain: for ``"u"`` the pieces over
            /// ``[a, t] × [c, d]`` and ``[t, b] × [c, d]``.
            #[pyo3(signature = (*args, t=None, direction=None), text_signature = "($self, t, *, direction)")]
            fn split_at(
                &self,
                py: Python<'_>,
                args: &Bound<'_, pyo3::types::PyTuple>,
                t: Option<&Bound<'_, PyAny>>,
                direction: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<(Self, Self)> {
                let class = stringify!($class);
                let (direction, [t]) =
                    $crate::directed::directed(class, "split_at", ["t"], args, [t], direction)?;
                let t = $crate::keyword::real(&$crate::directed::required(t, "split_at", "t")?, "t")?;
                let op = $crate::knot_ops::KnotOp::Split(t);
                let [a, b] = $crate::knot_ops::apply(py, &self.0, direction, op)?;
                Ok((Self(a), Self(b)))
            }

            /// The piece of the surface over the rectangle ``u × v`` of its
            /// domain (``u = (u0, u1)``, ``v = (v0, v1)``), as a surface of
            /// its own, clamped in both directions.
            fn segment(
                &self,
                py: Python<'_>,
                u: &Bound<'_, PyAny>,
                v: &Bound<'_, PyAny>,
            ) -> PyResult<Self> {
                let (u, v) = ($crate::keyword::real_pair(u, "u")?, $crate::keyword::real_pair(v, "v")?);
                $crate::dim::by_dim!(&self.0, |s| $crate::errors::compute(py, || Ok(s
                    .segment([u.0, u.1], [v.0, v.1])?
                    .into())))
            }
        }

        impl $class {
            /// What its descriptions say (`__repr__`, `_repr_html_`).
            fn facts(&self) -> $crate::describe::SurfaceFacts {
                let (dimension, domain) = (self.0.dimension(), self.domain());
                $crate::dim::by_dim!(&self.0, |s| $crate::describe::SurfaceFacts {
                    dimension,
                    degree: s.degree(),
                    net: s.shape(),
                    domain,
                })
            }

            /// The domains in u and in v.
            fn domains(&self) -> [t2spline::Domain; 2] {
                $crate::dim::by_dim!(&self.0, |s| t2spline::Direction::BOTH.map(|d| s.domain(d)))
            }

            /// The knot vector of one direction as an array.
            fn knots_in<'py>(
                &self,
                py: Python<'py>,
                direction: t2spline::Direction,
            ) -> PyResult<Bound<'py, PyAny>> {
                let k = $crate::dim::by_dim!(&self.0, |s| s.knots(direction).as_slice().to_vec());
                let n = k.len();
                $crate::arrays::array(py, k, &[n])
            }
        }
    };
}

pub(crate) use surface_methods;
