//! The one error type of the plotting crate.

/// Everything that can go wrong making figures and reports.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The number asked for belongs to a control point the job lacks.
    #[error("point {point} does not exist: the job has {count} points, 0 to {}", count.saturating_sub(1))]
    NoSuchPoint {
        /// The point asked for.
        point: usize,
        /// The job's number of control points.
        count: usize,
    },
    /// The number asked for belongs to a coordinate the job lacks.
    #[error("coordinate {axis} does not exist in a {dimension}-D job")]
    NoSuchAxis {
        /// The coordinate asked for.
        axis: t2spline::Axis,
        /// The job's dimension.
        dimension: usize,
    },
    /// A figure or computation of curves only was asked of a surface job.
    #[error("this is drawn for curve jobs only, not for surfaces")]
    Surface,
    /// A figure of plane curves only (the membership map, the section at a
    /// station) was asked of a space curve or a surface.
    #[error("this is drawn for plane curves (x, y) only")]
    Planar,
    /// A 3-D view that cannot be used.
    #[error("bad view: {0}")]
    View(String),
    /// Reading the job or writing a file failed.
    #[error(transparent)]
    Io(#[from] t2spline_io::Error),
    /// The library refused a value (never for validated jobs).
    #[error(transparent)]
    Core(#[from] t2spline::Error),
    /// The SVG could not be rasterised.
    #[error("cannot render {name}.png: {message}")]
    Png {
        /// The figure.
        name: String,
        /// Why.
        message: String,
    },
}
