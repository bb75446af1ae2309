//! The command `t2spline` from the Python package: the console script
//! `t2spline` (`python/t2spline/_cli.py`) calls [`_cli_main`], which is the
//! command-line tool itself ([`t2spline_cli::main`]), so that `pip install
//! t2spline` gives the same command as `cargo install`. Figures are SVG:
//! the package carries no PNG renderer.

use std::ffi::OsString;

use pyo3::prelude::*;

use crate::errors::without_gil;

/// Runs the command ``t2spline`` on ``args`` (the program's name first) and
/// returns its exit code; the GIL is released while it runs. Help, the
/// version and a malformed command line end the process, as the command
/// does.
#[pyfunction]
pub(crate) fn _cli_main(py: Python<'_>, args: Vec<OsString>) -> PyResult<u8> {
    without_gil(py, || t2spline_cli::main(args))
}
