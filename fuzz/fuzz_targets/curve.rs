//! libFuzzer target: rational B-spline curves and fuzzy curves with arbitrary
//! degrees, control points, weights, knots, parameters and levels, decoded from
//! the bytes. The checks are those of `crates/t2spline/tests/oracle/mod.rs`,
//! shared with the proptest run of `cargo test`.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "../../crates/t2spline/tests/oracle/mod.rs"]
mod oracle;

fuzz_target!(|data: &[u8]| {
    oracle::check_bytes(data);
});
