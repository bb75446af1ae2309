//! One module per subcommand: validate the raw arguments into a plan, then call
//! the libraries.

mod batch;
mod bench;
mod contour;
mod envelope;
mod export;
mod fit;
mod fuzzify;
mod levels;
mod measure;
pub mod membership;
mod model_kind;
mod plot;
pub mod prepare;
pub mod region;
mod report;
mod results;
mod run;
mod section;
mod serve;
mod validate;

use crate::cli::{Cli, Command};

/// Runs the chosen subcommand.
pub fn dispatch(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Command::Run(args) => run::run(args),
        Command::Validate(args) => validate::validate(&args),
        Command::Plot(args) => plot::plot(&args),
        Command::Report(args) => report::report(&args),
        Command::Fit(args) => fit::fit(args),
        Command::Fuzzify(args) => fuzzify::fuzzify(args),
        Command::Export(args) => export::export(&args),
        Command::Measure(args) => measure::measure(&args),
        Command::Membership(args) => membership::membership(&args),
        Command::Region(args) => region::region(&args),
        Command::Section(args) => section::section(&args),
        Command::Envelope(args) => envelope::envelope(&args),
        Command::Contour(args) => contour::contour(&args),
        Command::Bench(args) => bench::bench(&args),
        Command::Serve(args) => serve::serve(&args),
    }
}
