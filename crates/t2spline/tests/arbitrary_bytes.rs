//! The curve fuzz target's checks (`tests/oracle/mod.rs`, also run by
//! `fuzz/fuzz_targets/curve.rs` under libFuzzer) on random bytes, so that every
//! `cargo test` runs a bounded share of the fuzzing: random bytes, and bytes
//! biased towards valid curves (small degree and count bytes, in-range values).

mod oracle;

use proptest::prelude::*;

proptest! {
    #![proptest_config(t2spline::strategies::cases(500, 1000))]

    #[test]
    fn arbitrary_bytes_keep_every_promise(data in proptest::collection::vec(any::<u8>(), 0..600)) {
        oracle::check_bytes(&data);
    }

    /// Mostly "small multiple of 1/8" floats (kind bytes 1 and 4), which make
    /// valid curves far more often than raw bytes do.
    #[test]
    fn mostly_valid_curves_keep_every_promise(
        head in proptest::collection::vec(any::<u8>(), 2),
        body in proptest::collection::vec((prop_oneof![Just(1u8), Just(4), any::<u8>()], any::<u8>()), 0..300),
    ) {
        let mut data = head;
        for (kind, value) in body {
            data.push(kind);
            data.push(value);
        }
        oracle::check_bytes(&data);
    }
}

/// Found by the fuzzer: degree elevation of a degree-0 curve built an invalid
/// knot vector (a panic in debug builds, an invalid curve in release builds).
#[test]
fn issue_6_elevating_a_degree_zero_curve_is_an_error() {
    let c = t2spline::NurbsCurve::try_clamped(0, vec![[0.0, 0.0], [1.0, 1.0]], vec![1.0, 1.0])
        .expect("a valid piecewise constant curve");
    let e = c.elevate_degree(1).unwrap_err();
    assert_eq!(
        e.to_string(),
        "degree of the curve to elevate = 0 is outside [1, 64]"
    );
    assert!(c.elevate_degree(0).is_ok());
}

/// Every input the fuzzer ever failed on (`fuzz/regressions/curve/`), and
/// every seed of its corpus (`fuzz/seeds/curve/`), passes every check now.
#[test]
fn fuzz_regressions_and_seeds_pass() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let mut count = 0;
    for dir in ["regressions/curve", "seeds/curve"] {
        let Ok(entries) = std::fs::read_dir(root.join(dir)) else {
            continue;
        };
        for entry in entries {
            oracle::check_bytes(&std::fs::read(entry.unwrap().path()).unwrap());
            count += 1;
        }
    }
    assert!(count >= 5, "{count} files");
}
