//! The `t2spline` command: a thin shell over `t2spline-io` and `t2spline`.
//!
//! Raw arguments ([`cli::Cli`]) become a validated plan in `cmd/`, which calls
//! the libraries; nothing is computed here. Errors are printed one line per
//! problem, `t2spline: FILE:LINE:COLUMN: PLACE: RULE`, and the exit code tells
//! their kind (see `exit.rs` and the README).

mod clash;
mod cli;
mod cmd;
mod exit;
mod output;
mod signals;

use std::io::Write;
use std::process::ExitCode;

use clap::Parser;

use crate::exit::Exit;

fn main() -> ExitCode {
    let cli = cli::Cli::parse();
    signals::remove_temporary_files_on_signals();
    match cmd::dispatch(cli) {
        Ok(()) => ExitCode::from(Exit::Ok.code()),
        Err(e) if output::is_broken_pipe(&e) => ExitCode::from(Exit::Ok.code()),
        Err(e) => {
            // `eprintln!` would panic if standard error is a closed pipe.
            let mut stderr = std::io::stderr().lock();
            for line in format!("{e:#}").lines() {
                let _ = writeln!(stderr, "t2spline: {line}");
            }
            ExitCode::from(Exit::of(&e).code())
        }
    }
}
