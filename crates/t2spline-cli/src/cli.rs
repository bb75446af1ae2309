//! Command-line arguments, as given (clap derive); validation happens in `cmd/`.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

/// Normal type-2 fuzzy rational B-spline curves: model uncertain control points,
/// cut, type-reduce and defuzzify them (Algorithm 1.1 of Zakaria, Wahab and
/// Gobithaasan), and measure how far the crisp type-2 solution moves.
#[derive(Debug, Parser)]
#[command(name = "t2spline", version, propagate_version = true)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run the four stages on a job file and write the result as JSON.
    Run(RunArgs),
    /// Check a job file and report every problem in it.
    Validate(ValidateArgs),
}

/// Arguments of `t2spline run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    /// The job file (JSON, see SPEC §8); `-` reads standard input.
    pub job: PathBuf,
    /// Write the result here instead of standard output (`-` is standard output).
    #[arg(short, long, value_name = "OUT.json")]
    pub output: Option<PathBuf>,
    /// The level alpha in [0, 1]; overrides the job file.
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    pub alpha: Option<f64>,
    /// Number of uniform parameters to sample the curves at (at least 2);
    /// overrides the job file.
    #[arg(long, value_name = "N")]
    pub samples: Option<u64>,
    /// Also write the sampled curves as CSV files (one per curve family) into
    /// this folder, creating it if needed.
    #[arg(long, value_name = "DIR")]
    pub csv: Option<PathBuf>,
    /// Also compute the derivatives of orders 1 to K of the crisp and the
    /// defuzzified curve at the sample parameters, and their arc lengths
    /// (result keys `curves.derivatives`, `curves.arc_length`); K from 1 to 16.
    #[arg(long, value_name = "K", allow_negative_numbers = true)]
    pub derivatives: Option<i64>,
}

/// Arguments of `t2spline validate`.
#[derive(Debug, Args)]
pub struct ValidateArgs {
    /// The job file; `-` reads standard input.
    pub job: PathBuf,
}
