//! The `t2spline` command: [`t2spline_cli::main`] on the program's
//! arguments.

use std::process::ExitCode;

fn main() -> ExitCode {
    ExitCode::from(t2spline_cli::main(std::env::args_os()))
}
