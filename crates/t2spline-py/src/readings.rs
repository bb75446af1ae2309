//! `t2spline.fuzzify`: a readings file (repeated readings of stations, CSV)
//! turned into the data of a fit by the rules of ``t2spline fuzzify``
//! (`t2spline_io::fuzzify_readings`), as the dict of the data file it
//! writes.

use std::path::PathBuf;

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyString;
use t2spline_io::{data_json_text, fuzzify_readings, parse_data, ReadingsError, ReadingsOptions};

use crate::errors::{internal_error, io_error, without_gil};
use crate::json::loads;
use crate::keyword;

/// The data of a fit from a readings file, as ``t2spline fuzzify`` makes it:
/// per station and coordinate, crisp = the median, lower = the 25th–75th
/// percentiles (at ``lower_height``), primary = the 10th–90th, upper = the
/// extremes widened by ``tolerance`` (percentiles by linear interpolation,
/// type 7). The same code as the command reads the file and computes.
///
/// Parameters
/// ----------
/// readings : str or os.PathLike
///     The readings file: a header ``station,x,y`` or ``station,x,y,z`` (the
///     stations of a curve) or ``row,col,x,y,z`` (the stations of a net,
///     whose ``points`` are then rows and whose degree is a pair), then one
///     reading per row, the rows of a station in any order (comma or
///     semicolon separated).
/// tolerance : float, optional
///     The instrument's accuracy ``T`` (default 0).
/// lower_height : float, optional
///     The height of the lower membership function (default 0.5).
/// degree, order : int, optional
///     The degree (or order) of the curve to fit (default degree 3); for a
///     net, the degree in both directions.
/// alpha : float, optional
///     The level alpha to carry into the data (and so into the fitted job).
///
/// Returns
/// -------
/// dict
///     The data file's keys, in its order (``description``, ``degree`` or
///     ``order``, ``alpha`` if given, ``lower_height``, ``points``), as
///     ``t2spline fuzzify`` writes them: ``json.dumps`` of it is a data file
///     that ``t2spline fit`` takes.
///
/// Raises
/// ------
/// JobError
///     For a readings file that breaks a rule (``file:line:column: rule``).
/// ValueError
///     For an option out of its range, named: ``tolerance: …``.
/// OSError
///     For a file that cannot be read.
#[pyfunction]
#[pyo3(signature = (readings, *, tolerance=None, lower_height=None, degree=None, order=None, alpha=None))]
pub(crate) fn fuzzify<'py>(
    py: Python<'py>,
    readings: &Bound<'py, PyAny>,
    tolerance: Option<&Bound<'py, PyAny>>,
    lower_height: Option<&Bound<'py, PyAny>>,
    degree: Option<&Bound<'py, PyAny>>,
    order: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let non_negative = |v: Option<i64>, name: &str| -> PyResult<Option<u64>> {
        v.map(|n| {
            u64::try_from(n).map_err(|_| PyValueError::new_err(format!("{name}: {n} is negative")))
        })
        .transpose()
    };
    let options = ReadingsOptions {
        tolerance: keyword::opt_real(tolerance, "tolerance")?,
        lower_height: keyword::opt_real(lower_height, "lower_height")?,
        degree: non_negative(keyword::opt_int(degree, "degree")?, "degree")?,
        order: non_negative(keyword::opt_int(order, "order")?, "order")?,
        alpha: keyword::opt_real(alpha, "alpha")?,
        ..ReadingsOptions::default()
    };
    if !(readings.is_instance_of::<PyString>() || readings.hasattr("__fspath__")?) {
        return Err(PyTypeError::new_err(format!(
            "readings: expected the path of a readings file (str or os.PathLike), got {}",
            readings.get_type().name()?
        )));
    }
    let path: PathBuf = py
        .import("os")?
        .call_method1("fspath", (readings,))?
        .extract()?;
    let source = path.display().to_string();
    let json = without_gil(py, || {
        let text = t2spline_io::job::read_text(&path).map_err(ReadingsError::File)?;
        let data = fuzzify_readings(&text, &source, &options)?;
        Ok::<_, ReadingsError>(data_json_text(&data))
    })?
    .map_err(|e| match e {
        ReadingsError::File(e) => io_error(py, e),
        ReadingsError::Option { option, message } => {
            PyValueError::new_err(format!("{option}: {message}"))
        }
    })?;
    // The last guard, as the command's: what is given is a valid data file.
    parse_data(&json, "<fuzzify>")
        .map_err(|e| internal_error(&format!("the data file does not validate: {e}")))?;
    loads(py, &json)
}
