//! # t2spline-py — the Python module `t2spline`
//!
//! Bindings (PyO3, numpy) of the t2spline libraries for people who model
//! uncertain data in Python: `import t2spline`, numpy arrays in and out, the
//! Rust engine underneath. Every number comes from the libraries' public API;
//! this crate converts arguments and results and computes nothing itself.
//!
//! | Python | Rust |
//! |---|---|
//! | `t2spline.run(job, alpha=, type_reduction=, samples=, derivatives=)` | `t2spline_io::parse_job` → `Job::settings` → `Job::run`, the path of `t2spline run` |
//! | `t2spline.JobError` | `t2spline_io::Error::Invalid`: the CLI's problem lines |
//! | `FuzzyNumber`, `AlphaCut` | `Nt2Number`, `AlphaCut` (docs/method.md §1–§4) |
//! | `NurbsCurve` | `NurbsCurve<2 or 3>` and its operations |
//! | `FuzzyCurve`, `Solution` | `FuzzyCurve<2 or 3>` (stage 1, sampling engine), `Solution` (stages 2–4) |
//! | `NurbsSurface` | `NurbsSurface<3 or 2>` and its operations, the grid engine |
//! | `FuzzySurface`, `SurfaceSolution` | `FuzzySurface<3 or 2>` (stage 1, grid engine), `SurfaceSolution` (stages 2–4) |
//! | `FuzzyCurve.membership`, `.region` (`Region`), `.section`, `.membership_grid`; `FuzzySurface.membership`, `.section` | `t2spline::set` (docs/method.md §10): `memberships`, `region_in`, `sections`, `membership_grid` |
//! | `fit` | `t2spline::fit::FuzzyData::fit` |
//! | `centroid` | `t2spline::reduction::discrete::SampledSet`: KM, EKM, EIASC, Nie–Tan (docs/method.md §9) |
//! | `benchmark_curve`, `benchmark_surface` | `t2spline::sampling::benchmark_curve`, `benchmark_surface` |
//! | `release_cached_memory` | `t2spline::sampling::release_cached_memory` |
//!
//! The Python package (`python/t2spline/`) adds the plotting helpers, the
//! type stubs and the documentation of every function.
//!
//! Build with maturin (`pip install .` at the repository root); the
//! `extension-module` feature, which leaves libpython to the interpreter, is
//! turned on by maturin only, so `cargo test` links libpython as a program
//! would.

// No panic reachable from input: outside tests, `unwrap`, `expect`, `panic!`
// and `unreachable!` are refused; the few sites that cannot fail carry an
// `#[allow]` with the invariant that makes them safe (ARCHITECTURE.md,
// "Decisions and reasons").
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::unreachable,
        clippy::todo,
        clippy::unimplemented
    )
)]

mod arrays;
mod capability;
mod classes;
mod closest;
mod command;
mod construct;
mod curvature;
mod curve_methods;
mod describe;
mod dict_place;
mod dim;
mod directed;
mod distance_sweep;
mod errors;
mod export;
mod fit;
mod fuzzy_curve;
mod fuzzy_methods;
mod fuzzy_surface;
mod job_dict;
mod json;
mod keyword;
mod knot_ops;
mod many;
mod measure;
mod memory;
mod net;
mod number;
mod nurbs_curve;
mod nurbs_surface;
mod pickle;
mod picture;
mod py_types;
mod readings;
mod reduction;
mod run;
mod sample;
mod set;
mod solution;
mod stage_methods;
mod surface_methods;
mod surface_solution;
mod value;
mod weight_numbers;

use pyo3::prelude::*;

/// The fuzzy curve that ``t2spline bench`` and the Rust benchmarks time:
/// degree 3, ten control points (0,0), (1,2), (2,−1), (3,3), (4,0), (5,2.5),
/// (6,−2), (7,1), (8,3), (9,0), weights 1, 0.5, 2, 1, 3, 0.7, 1, 1.5, 0.8, 1,
/// clamped uniform knots, every number with feet ``c − 0.3, c + 0.45``
/// (upper), ``c − 0.2, c + 0.3`` (primary), ``c − 0.1, c + 0.15`` (lower) and
/// height 0.6.
///
/// Examples
/// --------
/// >>> benchmark_curve()
/// FuzzyCurve(dimension=2, degree=3, order=4, control_points=(10, 2), domain=(0.0, 1.0))
#[pyfunction]
fn benchmark_curve() -> classes::PyFuzzyCurve {
    t2spline::sampling::benchmark_curve().into()
}

/// The fuzzy surface that ``t2spline bench --case surface`` and the Rust
/// benchmarks time: bicubic, an 8 × 8 net with clamped uniform knots, control
/// points ``(i, j, sin(1.1 i) cos(0.7 j) + 0.1 i j)``, weights
/// ``0.5 + ((3i + 5j) mod 7) / 4``, every number as in ``benchmark_curve``.
///
/// Examples
/// --------
/// >>> benchmark_surface().sample(3, 3)["crisp"].shape
/// (3, 3, 3)
#[pyfunction]
fn benchmark_surface() -> classes::PyFuzzySurface {
    t2spline::sampling::benchmark_surface().into()
}

/// Returns to the system the memory that large samples leave behind when
/// they are dropped: on Linux the engine keeps the huge-page mappings of
/// dropped outputs (up to 256 MiB) so that the next large output costs no
/// new memory; this unmaps them. Arrays still alive keep theirs. Does nothing
/// elsewhere.
///
/// Examples
/// --------
/// >>> layers = benchmark_curve().sample(1_000_000)   # 112 MB in mappings
/// >>> del layers                                     # kept for the next
/// >>> release_cached_memory()                        # given back
#[pyfunction]
fn release_cached_memory(py: Python<'_>) {
    py.detach(t2spline::sampling::release_cached_memory);
}

/// The extension module `t2spline._t2spline`; `t2spline/__init__.py`
/// re-exports it.
#[pymodule]
fn _t2spline(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("JobError", m.py().get_type::<errors::JobError>())?;
    m.add_class::<number::PyFuzzyNumber>()?;
    m.add_class::<number::PyAlphaCut>()?;
    m.add_class::<classes::PyNurbsCurve>()?;
    m.add_class::<classes::PyFuzzyCurve>()?;
    m.add_class::<classes::PySolution>()?;
    m.add_class::<classes::PyNurbsSurface>()?;
    m.add_class::<classes::PyFuzzySurface>()?;
    m.add_class::<classes::PySurfaceSolution>()?;
    m.add_class::<set::PyRegion>()?;
    m.add_function(wrap_pyfunction!(run::run, m)?)?;
    m.add_function(wrap_pyfunction!(command::_cli_main, m)?)?;
    m.add_function(wrap_pyfunction!(picture::_palette, m)?)?;
    m.add_function(wrap_pyfunction!(many::run_many, m)?)?;
    m.add_function(wrap_pyfunction!(many::_run_rows, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit_job, m)?)?;
    m.add_function(wrap_pyfunction!(readings::fuzzify, m)?)?;
    m.add_function(wrap_pyfunction!(export::export, m)?)?;
    m.add_function(wrap_pyfunction!(json::to_json, m)?)?;
    m.add_function(wrap_pyfunction!(reduction::centroid, m)?)?;
    m.add_function(wrap_pyfunction!(benchmark_curve, m)?)?;
    m.add_function(wrap_pyfunction!(benchmark_surface, m)?)?;
    m.add_function(wrap_pyfunction!(release_cached_memory, m)?)?;
    m.add_function(wrap_pyfunction!(errors::_panic_for_tests, m)?)?;
    Ok(())
}
