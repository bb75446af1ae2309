//! The `t2spline` command: a thin shell over `t2spline-io` and `t2spline`.
//!
//! Raw arguments (`cli::Cli`) become a validated plan in `cmd/`, which calls
//! the libraries; nothing is computed here. Errors are printed one line per
//! problem, `t2spline: FILE:LINE:COLUMN: PLACE: RULE`, and the exit code tells
//! their kind (see `exit.rs` and the README).
//!
//! The command is this library's [`main`]: the binary `t2spline` calls it,
//! and so does the Python package's console script of the same name.

mod clash;
mod cli;
mod cmd;
mod exit;
mod output;
mod signals;

use std::ffi::OsString;
use std::io::Write;

use clap::Parser;

use crate::exit::Exit;

/// Runs the command on `args` (the program's name first, as
/// `std::env::args_os` gives them) and returns its exit code. Help, the
/// version and a malformed command line are printed by clap, which ends the
/// process with its own code.
pub fn main<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = cli::Cli::parse_from(args);
    signals::remove_temporary_files_on_signals();
    match cmd::dispatch(cli) {
        Ok(()) => Exit::Ok.code(),
        Err(e) if output::is_broken_pipe(&e) => Exit::Ok.code(),
        Err(e) => {
            // `eprintln!` would panic if standard error is a closed pipe.
            let mut stderr = std::io::stderr().lock();
            for line in format!("{e:#}").lines() {
                let _ = writeln!(stderr, "t2spline: {line}");
            }
            Exit::of(&e).code()
        }
    }
}
