//! `t2spline.export`: a job's exact curves (or surfaces) as a CAD file, by
//! the path of ``t2spline export`` (`Prepared::cad`) and written all or
//! nothing (`t2spline_io::write_atomic`).

use std::path::{Path, PathBuf};

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyString;
use t2spline::job::{LengthUnit, Overrides};
use t2spline_io::{write_atomic, CadFormat};

use crate::errors::{io_error, without_gil};
use crate::keyword;
use crate::reduction;
use crate::run::{job_text, prepare, run_error, warn_alpha};

/// Writes a job's exact curves as ``t2spline export`` does: the crisp and
/// the defuzzified curve and the six layer curves (a surface job's eight
/// surfaces) as rational B-splines, never polylines, into a DXF, STEP,
/// IGES or OBJ file, the same bytes as the command's (the header's time is
/// the clock's, or ``SOURCE_DATE_EPOCH``'s). The file is complete or
/// untouched: it is written to a temporary file and renamed.
///
/// Parameters
/// ----------
/// job : dict or str or os.PathLike
///     A job, as ``run`` takes it.
/// path : str or os.PathLike
///     The file to write.
/// format : {"dxf", "step", "iges", "obj"}, optional
///     The format; by default the one the extension of ``path`` names
///     (``.dxf``, ``.step``/``.stp``, ``.iges``/``.igs``, ``.obj``).
/// alpha : float, optional
///     The level alpha of the defuzzified curve, in place of the job's.
/// type_reduction : {"paper", "centroid", "nie-tan", "alpha-planes"}, optional
///     The type reduction of the defuzzified curve, in place of the job's.
/// units : {"mm", "cm", "m", "in", "ft"}, optional
///     The unit of the coordinates that the file records (the numbers are
///     written as they are); by default the job's ``units``, else ``"mm"``.
///
/// Raises
/// ------
/// JobError
///     For a job that breaks the rules, or curves the format cannot hold
///     (degree 0; a surface in DXF).
/// ValueError
///     For an unknown ``format`` or ``units``, or a path whose extension
///     names none.
/// OSError
///     For a file that cannot be read or written.
#[pyfunction]
#[pyo3(signature = (job, path, format=None, alpha=None, type_reduction=None, *, units=None))]
pub(crate) fn export<'py>(
    py: Python<'py>,
    job: &Bound<'py, PyAny>,
    path: &Bound<'py, PyAny>,
    format: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
    type_reduction: Option<&Bound<'py, PyAny>>,
    units: Option<&Bound<'py, PyAny>>,
) -> PyResult<()> {
    let units = match keyword::opt_text(units, "units")? {
        Some(name) => Some(LengthUnit::named(&name).ok_or_else(|| {
            PyValueError::new_err(format!(
                "units: unknown unit {name:?} (known: {})",
                LengthUnit::names()
            ))
        })?),
        None => None,
    };
    if !(path.is_instance_of::<PyString>() || path.hasattr("__fspath__")?) {
        return Err(PyTypeError::new_err(format!(
            "path: expected a str or os.PathLike, got {}",
            path.get_type().name()?
        )));
    }
    let path: PathBuf = py
        .import("os")?
        .call_method1("fspath", (path,))?
        .extract()?;
    let format = match keyword::opt_text(format, "format")? {
        Some(name) => CadFormat::named(&name).ok_or_else(|| {
            PyValueError::new_err(format!(
                "format: unknown format {name:?} (known: dxf, step, iges, obj)"
            ))
        })?,
        None => CadFormat::from_extension(&path).ok_or_else(|| {
            PyValueError::new_err(format!(
                "format: missing: the extension of {} names no format (.dxf, .step, .stp, .iges, .igs, .obj); give format=\"dxf\"|\"step\"|\"iges\"|\"obj\"",
                path.display()
            ))
        })?,
    };
    let type_reduction = keyword::opt_text(type_reduction, "type_reduction")?;
    let overrides = Overrides {
        alpha: keyword::opt_real(alpha, "alpha")?,
        type_reduction: reduction::type_reduction(type_reduction.as_deref())?,
        ..Overrides::default()
    };
    let (text, source) = job_text(job)?;
    let prepared =
        without_gil(py, || prepare(&text, &source, &overrides))?.map_err(|e| run_error(py, e))?;
    warn_alpha(py, prepared.settings(), overrides.alpha.is_some(), "")?;
    let name = file_name(&path);
    without_gil(py, || {
        let text = prepared
            .cad(format, name, &source, units)
            .map_err(Failure::Run)?;
        write_atomic(&path, text.as_bytes()).map_err(Failure::Write)
    })?
    .map_err(|e| match e {
        Failure::Run(e) => run_error(py, e),
        Failure::Write(e) => match e {
            t2spline_io::Error::Write { ref source, .. } => match source.raw_os_error() {
                Some(errno) => pyo3::exceptions::PyOSError::new_err((
                    errno,
                    source.to_string(),
                    path.display().to_string(),
                )),
                None => pyo3::exceptions::PyOSError::new_err(e.to_string()),
            },
            other => io_error(py, other),
        },
    })
}

/// Why an export wrote nothing.
enum Failure {
    Run(t2spline_io::RunError),
    Write(t2spline_io::Error),
}

/// The name a CAD file gives itself: its file name.
fn file_name(path: &Path) -> String {
    path.file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}
