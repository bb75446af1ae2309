//! The report's limits on size: the bytes of the per-stop data and the
//! samples of the result files it carries.

use t2spline::job::Samples;

/// The most bytes the packed per-stop data may take; the grid of stops is
/// coarsened to stay within it.
pub const DATA_BUDGET: usize = 3_500_000;

/// The most samples per curve of the result files a report carries. A job
/// sampled more finely gets, at every stop that carries files, the files of
/// `t2spline run --samples 1001` instead, and the page says so: a page needs
/// no more, and the memory and size of a report then no longer grow with
/// the job's `samples` (at 30 000 samples the files of every stop took
/// 2.9 GB, at 100 000 the report ran out of memory).
pub const MAX_FILE_SAMPLES: usize = 1001;

/// The most samples per direction of a surface's result files in a report
/// (101 × 101 at most), as [`MAX_FILE_SAMPLES`] for a curve.
pub const MAX_FILE_GRID: usize = 101;

/// The samples of the result files a report of a job sampled at `samples`
/// carries: the job's, at most [`MAX_FILE_SAMPLES`] along a curve and
/// [`MAX_FILE_GRID`] in each direction of a surface.
#[must_use]
pub(crate) fn file_samples(samples: Samples) -> Samples {
    match samples {
        Samples::Along(n) => Samples::Along(n.min(MAX_FILE_SAMPLES)),
        Samples::Grid(grid) => Samples::Grid(grid.map(|n| n.min(MAX_FILE_GRID))),
    }
}
