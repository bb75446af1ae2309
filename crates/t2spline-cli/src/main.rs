//! The `t2spline` command: a thin shell over `t2spline-io` and `t2spline`.
//!
//! Raw arguments ([`cli::Cli`]) become a validated plan in `cmd/`, which calls
//! the libraries; nothing is computed here.

mod cli;
mod cmd;
mod output;

use std::process::ExitCode;

use clap::Parser;

/// Exit code for success, and for a reader that closed the pipe early.
const EXIT_OK: u8 = 0;
/// Exit code for any error: bad input, bad options, a file that cannot be read
/// or written (clap uses 2 for usage errors too).
const EXIT_ERROR: u8 = 2;

fn main() -> ExitCode {
    let cli = cli::Cli::parse();
    match cmd::dispatch(cli) {
        Ok(()) => ExitCode::from(EXIT_OK),
        Err(e) if output::is_broken_pipe(&e) => ExitCode::from(EXIT_OK),
        Err(e) => {
            for line in format!("{e:#}").lines() {
                eprintln!("t2spline: {line}");
            }
            ExitCode::from(EXIT_ERROR)
        }
    }
}
