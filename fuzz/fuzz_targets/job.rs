//! libFuzzer target: arbitrary bytes as a job file, through reading,
//! validation, the four stages, JSON and CSV. The checks are those of
//! `crates/t2spline-io/tests/oracle/mod.rs`, shared with the proptest run of
//! `cargo test`.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "../../crates/t2spline-io/tests/oracle/mod.rs"]
mod oracle;

fuzz_target!(|data: &[u8]| {
    oracle::check_job_bytes(data);
});
