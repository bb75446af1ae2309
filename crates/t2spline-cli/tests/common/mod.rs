//! What the command's tests share: running the built `t2spline` and
//! naming paths in its arguments.

use std::path::Path;
use std::process::Command;

/// Runs the built command on `args`: its exit code, standard output and
/// standard error (UTF-8, as the command writes).
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_t2spline"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().expect("exited, not killed"),
        String::from_utf8(out.stdout).expect("UTF-8"),
        String::from_utf8(out.stderr).expect("UTF-8"),
    )
}

/// A path as an argument.
pub fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}
