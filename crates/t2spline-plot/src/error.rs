//! The one error type of the plotting crate.

/// Everything that can go wrong making figures and reports.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A plotting option breaks a rule (a point or axis the job lacks).
    #[error("{option}: {message}")]
    Option {
        /// The option, e.g. `--point`.
        option: &'static str,
        /// The rule.
        message: String,
    },
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
