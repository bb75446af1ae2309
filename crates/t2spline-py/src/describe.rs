//! The short descriptions of curves and surfaces, crisp or fuzzy, written
//! once for the four classes: the `__repr__` line and the rows of the table
//! under a notebook picture (`_repr_html_`).

/// The rows of a table under a picture: a name and its value.
pub(crate) type Rows = Vec<(&'static str, String)>;

/// What a curve's description says: its degree `p` (the order is `p + 1`),
/// its control points and its domain.
pub(crate) struct CurveFacts {
    /// The number of coordinates: 2 or 3.
    pub(crate) dimension: usize,
    /// The degree `p`.
    pub(crate) degree: usize,
    /// The number of control points.
    pub(crate) points: usize,
    /// The parameter domain `(a, b)`.
    pub(crate) domain: (f64, f64),
}

impl CurveFacts {
    /// The rows: dimension, degree (order), control points, domain.
    pub(crate) fn rows(&self) -> Rows {
        let (a, b) = self.domain;
        vec![
            ("dimension", self.dimension.to_string()),
            (
                "degree (order)",
                format!("{} ({})", self.degree, self.degree + 1),
            ),
            ("control points", self.points.to_string()),
            ("domain", format!("[{a:?}, {b:?}]")),
        ]
    }

    /// `Class(dimension=…, degree=…, order=…, control_points=(n, d), …,
    /// domain=(a, b))`, with `knots=(len,)` before the domain where given.
    pub(crate) fn repr(&self, class: &str, knots: Option<usize>) -> String {
        let (d, p, (a, b)) = (self.dimension, self.degree, self.domain);
        let knots = knots.map(|k| format!("knots=({k},), ")).unwrap_or_default();
        format!(
            "{class}(dimension={d}, degree={p}, order={}, control_points=({}, {d}), {knots}domain=({a:?}, {b:?}))",
            p + 1,
            self.points,
        )
    }
}

/// What a surface's description says: its degrees `(p, q)` (the orders are
/// `(p + 1, q + 1)`), the shape of its control net and its domain.
pub(crate) struct SurfaceFacts {
    /// The number of coordinates: 2 or 3.
    pub(crate) dimension: usize,
    /// The degrees `[p, q]` in u and in v.
    pub(crate) degree: [usize; 2],
    /// The shape `[nu, nv]` of the control net.
    pub(crate) net: [usize; 2],
    /// The parameter domain `((a, b), (c, e))`.
    pub(crate) domain: ((f64, f64), (f64, f64)),
}

impl SurfaceFacts {
    /// The rows: dimension, degree (u, v), control net.
    pub(crate) fn rows(&self) -> Rows {
        let ([p, q], [nu, nv]) = (self.degree, self.net);
        vec![
            ("dimension", self.dimension.to_string()),
            ("degree (u, v)", format!("({p}, {q})")),
            ("control net", format!("{nu} × {nv}")),
        ]
    }

    /// `Class(dimension=…, degree=(p, q), order=(…), control_points=(nu, nv,
    /// d), …, domain=((a, b), (c, e)))`, with `knots=(len_u, len_v)` before
    /// the domain where given.
    pub(crate) fn repr(&self, class: &str, knots: Option<[usize; 2]>) -> String {
        let (d, [p, q], [nu, nv]) = (self.dimension, self.degree, self.net);
        let ((a, b), (c, e)) = self.domain;
        let knots = knots
            .map(|[ku, kv]| format!("knots=({ku}, {kv}), "))
            .unwrap_or_default();
        format!(
            "{class}(dimension={d}, degree=({p}, {q}), order=({}, {}), control_points=({nu}, {nv}, {d}), {knots}domain=(({a:?}, {b:?}), ({c:?}, {e:?})))",
            p + 1,
            q + 1,
        )
    }
}
