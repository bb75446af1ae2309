//! The check of the no-panic tests, shared by the core's, the I/O crate's
//! and the plot crate's `tests/no_panic.rs` (the latter two include this file
//! by path).

use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `f`, failing the test with `what` and the panic's message if it
/// panics; else gives what `f` returned (a value or an error).
pub fn returns<T>(what: &str, f: impl FnOnce() -> T) -> T {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(value) => value,
        Err(payload) => {
            let message = payload
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| payload.downcast_ref::<&str>().copied())
                .unwrap_or("(no message)");
            panic!("{what} panicked: {message}");
        }
    }
}
