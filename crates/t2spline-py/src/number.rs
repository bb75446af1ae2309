//! `FuzzyNumber` and `AlphaCut`: one normal triangular type-2 fuzzy number
//! (docs/method.md §1), its alpha-cut (§2), type reduction (§3) and defuzzification
//! (§4), and its membership functions for plotting.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use t2spline::{Alpha, AlphaCut, Membership, Nt2Number};

use crate::arrays::{array, floats};
use crate::errors::core_error;
use crate::keyword;

/// A normal triangular type-2 fuzzy number (docs/method.md §1, paper Def. 4.1).
///
/// Seven ordered values and the height ``h`` of the lower membership
/// function::
///
///     upper.left <= primary.left <= lower.left <= crisp
///                <= lower.right <= primary.right <= upper.right,   0 < h <= 1
///
/// The upper (UMF), primary and lower (LMF) membership functions are
/// triangles with the common apex ``crisp``, of heights 1, 1 and ``h``; the
/// footprint of uncertainty lies between UMF and LMF.
///
/// Parameters
/// ----------
/// crisp : float
///     The apex.
/// upper, primary, lower : pair of float
///     The ``(left, right)`` feet of each triangle.
/// lower_height : float
///     ``h``, in ``(0, 1]``.
///
/// Raises
/// ------
/// ValueError
///     For NaN or infinity, a broken order or ``h`` outside ``(0, 1]``,
///     naming the rule: ``the order upper.left <= primary.left is broken: 0.7 > 0.6``.
///
/// Examples
/// --------
/// >>> x = FuzzyNumber(1.0, upper=(0.4, 1.9), primary=(0.6, 1.6), lower=(0.8, 1.3), lower_height=0.6)
/// >>> x.alpha_cut(0.5).lower           # alpha <= h: the lower cut exists
/// (0.9666666666666667, 1.05)
/// >>> x.alpha_cut(0.8).lower is None   # alpha > h: it does not
/// True
/// >>> x.type_reduce(0.8)               # (left, crisp, right)
/// (0.9, 1.0, 1.15)
/// >>> round(x.defuzzify(0.8), 12)      # (0.9 + 1 + 1.15) / 3
/// 1.016666666667
#[pyclass(frozen, eq, module = "t2spline", name = "FuzzyNumber")]
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PyFuzzyNumber(pub(crate) Nt2Number);

/// A level alpha from Python, checked.
pub(crate) fn alpha(value: f64) -> PyResult<Alpha> {
    Alpha::try_new(value).map_err(core_error)
}

fn pair(i: t2spline::Interval) -> (f64, f64) {
    (i.left(), i.right())
}

#[pymethods]
impl PyFuzzyNumber {
    #[new]
    #[pyo3(signature = (crisp, upper=None, primary=None, lower=None, lower_height=None))]
    fn new(
        crisp: &Bound<'_, PyAny>,
        upper: Option<&Bound<'_, PyAny>>,
        primary: Option<&Bound<'_, PyAny>>,
        lower: Option<&Bound<'_, PyAny>>,
        lower_height: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let crisp = keyword::real(crisp, "crisp")?;
        // Not given: a crisp number's feet `(crisp, crisp)` and height 1.
        let lower_height = keyword::opt_real(lower_height, "lower_height")?.unwrap_or(1.0);
        let feet = |arg: Option<&Bound<'_, PyAny>>, name| -> PyResult<[f64; 2]> {
            let Some(arg) = arg else {
                return Ok([crisp; 2]);
            };
            let f = floats(arg, name)?;
            f.expect_shape(name, &[2], ": (left, right)")?;
            Ok([f.data[0], f.data[1]])
        };
        let (upper, primary, lower) = (
            feet(upper, "upper")?,
            feet(primary, "primary")?,
            feet(lower, "lower")?,
        );
        Nt2Number::try_new(crisp, upper, primary, lower, lower_height)
            .map(PyFuzzyNumber)
            .map_err(core_error)
    }

    /// The apex ``crisp`` (the paper's P).
    #[getter]
    fn crisp(&self) -> f64 {
        self.0.crisp()
    }

    /// Pickling and copying: the constructor with ``(crisp, upper, primary,
    /// lower, lower_height)``, an equal object.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::pickle::Reduced<'py>> {
        crate::pickle::by_constructor(slf, &["crisp", "upper", "primary", "lower", "lower_height"])
    }

    /// The feet ``(left, right)`` of the upper membership function.
    #[getter]
    fn upper(&self) -> (f64, f64) {
        pair(self.0.upper())
    }

    /// The feet ``(left, right)`` of the primary membership function.
    #[getter]
    fn primary(&self) -> (f64, f64) {
        pair(self.0.primary())
    }

    /// The feet ``(left, right)`` of the lower membership function.
    #[getter]
    fn lower(&self) -> (f64, f64) {
        pair(self.0.lower())
    }

    /// The height ``h`` of the lower membership function.
    #[getter]
    fn lower_height(&self) -> f64 {
        self.0.height().get()
    }

    /// The alpha-cut at level ``alpha`` (docs/method.md §2, paper Eqs. 4.1–4.2).
    ///
    /// Every end point moves towards ``crisp``::
    ///
    ///     cut(e) = e + s·(crisp − e),  s = alpha for upper and primary ends,
    ///                                  s = alpha/h for lower ends
    ///
    /// Above the lower height (``alpha > h``) the lower cut is absent
    /// (``AlphaCut.lower`` is ``None``); at ``alpha = h`` it is the single
    /// value ``crisp``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     If ``alpha`` is NaN or outside ``[0, 1]``.
    ///
    /// Examples
    /// --------
    /// >>> x = FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)
    /// >>> x.alpha_cut(0.5)
    /// AlphaCut(alpha=0.5, crisp=1.0, upper=(0.7, 1.45), primary=(0.8, 1.3), lower=(0.9666666666666667, 1.05))
    /// >>> x.alpha_cut(0.6).lower     # at alpha = h: the single value crisp
    /// (1.0, 1.0)
    fn alpha_cut(&self, alpha: &Bound<'_, PyAny>) -> PyResult<PyAlphaCut> {
        let a = self::alpha(keyword::real(alpha, "alpha")?)?;
        Ok(PyAlphaCut {
            alpha: a.get(),
            cut: self.0.alpha_cut(a),
            number: self.0,
        })
    }

    /// The type-reduced triangle ``(left, crisp, right)`` at level ``alpha``
    /// (docs/method.md §3, paper Def. 4.3)::
    ///
    ///     alpha <= h:  left  = (upper.left' + primary.left' + lower.left') / 3
    ///                  right = (lower.right' + primary.right' + upper.right') / 3
    ///     alpha >  h:  left  = (upper.left' + primary.left') / 2
    ///                  right = (primary.right' + upper.right') / 2
    ///
    /// (primes: the alpha-cut values). The result jumps at ``alpha = h``; this
    /// is the paper's method.
    ///
    /// Examples
    /// --------
    /// >>> x = FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)
    /// >>> [round(v, 12) for v in x.type_reduce(0.6)]   # at h: three-term means
    /// [0.866666666667, 1.0, 1.2]
    fn type_reduce(&self, alpha: &Bound<'_, PyAny>) -> PyResult<(f64, f64, f64)> {
        Ok(self.alpha_cut(alpha)?.type_reduce())
    }

    /// The defuzzified value at level ``alpha``: the centroid of the
    /// type-reduced triangle, ``(left + crisp + right) / 3`` (docs/method.md §4, paper
    /// Def. 4.4).
    ///
    /// Examples
    /// --------
    /// >>> FuzzyNumber(2.0, (1.0, 3.0), (1.5, 2.5), (1.8, 2.2), 0.5).defuzzify(0.3)  # symmetric
    /// 2.0
    fn defuzzify(&self, alpha: &Bound<'_, PyAny>) -> PyResult<f64> {
        Ok(self
            .0
            .alpha_cut(self::alpha(keyword::real(alpha, "alpha")?)?)
            .type_reduce()
            .defuzzify())
    }

    /// One membership function at every value of ``x`` (docs/method.md §1), for
    /// plotting::
    ///
    ///     UMF     = T(x; upper.left, crisp, upper.right, 1)
    ///     primary = T(x; primary.left, crisp, primary.right, 1)
    ///     LMF     = T(x; lower.left, crisp, lower.right, h)
    ///
    /// where ``T(x; a, c, b, top)`` is the triangle with feet ``a``, ``b``,
    /// apex ``c`` and height ``top`` (a side of zero width is a vertical edge).
    ///
    /// Parameters
    /// ----------
    /// x : array_like
    ///     Where to evaluate; any shape.
    /// which : {'upper', 'primary', 'lower'}
    ///     The membership function.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     ``float64``, the shape of ``x``.
    ///
    /// Examples
    /// --------
    /// >>> x = FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)
    /// >>> x.membership([0.9, 1.0, 1.3], which="lower").round(12).tolist()
    /// [0.3, 0.6, 0.0]
    #[pyo3(signature = (x, which = None), text_signature = "($self, x, which='upper')")]
    fn membership<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        which: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let which = keyword::opt_text(which, "which")?;
        let which = match which.as_deref().unwrap_or("upper") {
            "upper" => Membership::Upper,
            "primary" => Membership::Primary,
            "lower" => Membership::Lower,
            other => {
                return Err(PyValueError::new_err(format!(
                    "which: expected 'upper', 'primary' or 'lower', got {other:?}"
                )))
            }
        };
        let x = floats(x, "x")?;
        let values = x
            .data
            .iter()
            .map(|&v| self.0.membership(which, v))
            .collect();
        array(py, values, &x.shape)
    }

    /// The picture in a notebook: the number figure of ``t2spline plot``
    /// (the three membership functions, the cut at ``alpha = h/2``, the type
    /// reductions) as inline SVG under a table of the number's values.
    fn _repr_html_(&self) -> PyResult<String> {
        crate::picture::number_page(&self.0)
    }

    fn __repr__(&self) -> String {
        format!(
            "FuzzyNumber(crisp={:?}, upper={:?}, primary={:?}, lower={:?}, lower_height={:?})",
            self.crisp(),
            self.upper(),
            self.primary(),
            self.lower(),
            self.lower_height()
        )
    }
}

/// The alpha-cut of a fuzzy number at one level (docs/method.md §2): the cut ends of
/// the upper, primary and lower membership functions; ``lower`` is ``None``
/// above the number's lower height. Made by ``FuzzyNumber.alpha_cut``.
///
/// Examples
/// --------
/// >>> cut = FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6).alpha_cut(0.5)
/// >>> cut.upper, cut.primary
/// ((0.7, 1.45), (0.8, 1.3))
/// >>> cut.type_reduce()[1]
/// 1.0
#[pyclass(frozen, eq, module = "t2spline", name = "AlphaCut")]
#[derive(Clone, Debug)]
pub(crate) struct PyAlphaCut {
    alpha: f64,
    cut: AlphaCut,
    /// The number cut, which pickling keeps.
    number: Nt2Number,
}

/// Two cuts are equal when their levels and ends are, whatever numbers
/// they were cut from.
impl PartialEq for PyAlphaCut {
    fn eq(&self, other: &Self) -> bool {
        self.alpha == other.alpha && self.cut == other.cut
    }
}

#[pymethods]
impl PyAlphaCut {
    /// The level alpha.
    #[getter]
    fn alpha(&self) -> f64 {
        self.alpha
    }

    /// Pickling and copying: ``FuzzyNumber.alpha_cut`` of the number cut, at
    /// the same level, an equal object.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<crate::pickle::Reduced<'py>> {
        let cut = py.get_type::<PyFuzzyNumber>().getattr("alpha_cut")?;
        let number = Bound::new(py, PyFuzzyNumber(self.number))?.into_any();
        let args =
            pyo3::types::PyTuple::new(py, [number, self.alpha.into_pyobject(py)?.into_any()])?;
        Ok((cut, args))
    }

    /// The apex, which every cut contains.
    #[getter]
    fn crisp(&self) -> f64 {
        self.cut.crisp()
    }

    /// The cut of the upper membership function, ``(left, right)``.
    #[getter]
    fn upper(&self) -> (f64, f64) {
        pair(self.cut.upper())
    }

    /// The cut of the primary membership function, ``(left, right)``.
    #[getter]
    fn primary(&self) -> (f64, f64) {
        pair(self.cut.primary())
    }

    /// The cut of the lower membership function, ``(left, right)``; ``None``
    /// when alpha is above the lower height.
    #[getter]
    fn lower(&self) -> Option<(f64, f64)> {
        self.cut.lower().map(pair)
    }

    /// The type-reduced triangle ``(left, crisp, right)`` of this cut (docs/method.md §3;
    /// see ``FuzzyNumber.type_reduce``).
    fn type_reduce(&self) -> (f64, f64, f64) {
        let t = self.cut.type_reduce();
        (t.left(), t.crisp(), t.right())
    }

    fn __repr__(&self) -> String {
        format!(
            "AlphaCut(alpha={:?}, crisp={:?}, upper={:?}, primary={:?}, lower={})",
            self.alpha,
            self.crisp(),
            self.upper(),
            self.primary(),
            self.lower().map_or("None".to_owned(), |l| format!("{l:?}"))
        )
    }
}
