//! Numbers as text, the shortest decimal that reads back to the same `f64`,
//! written straight into an output buffer without allocating.
//!
//! Both forms start from the digits of `zmij` (Schubfach's shortest
//! round-trip digits; the crate `serde_json` formats with), so JSON and CSV
//! agree digit for digit and only the notation differs:
//!
//! | value | JSON ([`json`], serde_json's form) | CSV ([`csv`], [`t2spline::Num`]'s form) |
//! |---|---|---|
//! | `1.0`, `-0.0` | `1.0`, `-0.0` | `1`, `-0` |
//! | `0.1`, `2.5` | `0.1`, `2.5` | `0.1`, `2.5` |
//! | `1.5e-6` | `1.5e-6` | `0.0000015` |
//! | `1.5e-7` | `1.5e-7` | `1.5e-7` |
//! | `1e16`, `1e300` | `1e+16`, `1e+300` | `1e16`, `1e300` |
//!
//! JSON writes plain decimals for `1e-5 ≤ |x| < 1e16`, CSV (as Rust's `{}` and
//! `{:e}` do in [`t2spline::Num`]) for `1e-6 ≤ |x| < 1e16`.
//!
//! The digits are the shortest that read back exactly; where two such
//! strings are equally close to the value (its binary value ends in a 5 just
//! past the 17th digit, as `1245506687333402.25`), zmij picks the even last
//! digit and Rust's formatter the higher one, so CSV may differ from
//! [`t2spline::Num`] there by one in the last digit (`…402.2`, not `…402.3`),
//! and agrees with JSON.

use std::io::{self, Write};

/// Writes `x` as serde_json writes it (finite `x`; the caller checks).
///
/// # Errors
/// The errors of `w`.
#[inline]
pub(crate) fn json<W: Write + ?Sized>(w: &mut W, x: f64) -> io::Result<()> {
    w.write_all(zmij::Buffer::new().format_finite(x).as_bytes())
}

/// Writes finite `x` as [`t2spline::Num`] displays it: Rust's `{}` for
/// `1e-6 ≤ |x| < 1e16` and zero, `{:e}` otherwise.
///
/// # Errors
/// The errors of `w`.
#[inline]
pub(crate) fn csv<W: Write + ?Sized>(w: &mut W, x: f64) -> io::Result<()> {
    let mut buffer = zmij::Buffer::new();
    let text = buffer.format_finite(x).as_bytes();
    // zmij writes plain decimals exactly for these (module docs).
    let plain = x == 0.0 || (1e-5..1e16).contains(&x.abs());
    let exponent = if plain {
        None
    } else {
        text.iter().position(|&b| b == b'e')
    };
    match exponent {
        // `12.5`, `1.0`: a whole number loses its `.0`.
        None => w.write_all(text.strip_suffix(b".0").unwrap_or(text)),
        Some(e) => {
            let (mantissa, exponent) = (&text[..e], &text[e + 1..]);
            if exponent == b"-6" {
                // `-1.25e-6` → `-0.00000125`: plain in CSV, not in JSON.
                let (sign, digits) = match mantissa.strip_prefix(b"-") {
                    Some(rest) => (&b"-"[..], rest),
                    None => (&b""[..], mantissa),
                };
                w.write_all(sign)?;
                w.write_all(b"0.00000")?;
                w.write_all(&digits[..1])?;
                w.write_all(digits.get(2..).unwrap_or_default())
            } else {
                // `1e+300` → `1e300`.
                w.write_all(mantissa)?;
                w.write_all(b"e")?;
                w.write_all(exponent.strip_prefix(b"+").unwrap_or(exponent))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use t2spline::Num;

    fn as_csv(x: f64) -> String {
        let mut out = Vec::new();
        csv(&mut out, x).unwrap();
        String::from_utf8(out).unwrap()
    }

    fn as_json(x: f64) -> String {
        let mut out = Vec::new();
        json(&mut out, x).unwrap();
        String::from_utf8(out).unwrap()
    }

    /// Values at every boundary of both notations, and the extremes.
    fn edges() -> Vec<f64> {
        let mut v = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            2.5,
            1e-6,
            1e-5,
            1e15,
            1e16,
            1e17,
            1.5e-6,
            9.999999999999999e-6,
            9.999999999999998e15,
            123456789012345680.0,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            1e300,
            2.5e-300,
            0.8799999999999999,
        ];
        for k in -320..=308 {
            let p: f64 = format!("1e{k}").parse().unwrap();
            // The neighbours of the power, one ulp either side.
            let (up, down) = (
                f64::from_bits(p.to_bits() + 1),
                f64::from_bits(p.to_bits() - 1),
            );
            v.extend([p, -p, up, down, 1.5 * p, 7.0 / 3.0 * p]);
        }
        v.into_iter().filter(|x| x.is_finite()).collect()
    }

    /// `Num`'s text, or (in an exact tie of two shortest strings, see the
    /// module docs) the same string but a last digit one lower.
    fn agrees_with_num(text: &str, x: f64) -> bool {
        let num = Num(x).to_string();
        if text == num {
            return true;
        }
        let last = |s: &str| s.bytes().last().map(|b| b as i32);
        text.len() == num.len()
            && text[..text.len() - 1] == num[..num.len() - 1]
            && last(&num).zip(last(text)).is_some_and(|(a, b)| a - b == 1)
            && text.parse::<f64>().ok() == Some(x)
    }

    #[test]
    fn csv_is_nums_text_at_every_edge() {
        for x in edges() {
            let text = as_csv(x);
            assert!(
                agrees_with_num(&text, x),
                "{x:e}: {text} against {}",
                Num(x)
            );
        }
    }

    #[test]
    // The value is exact (floats 0.25 apart there): its tie is the point.
    #[allow(clippy::excessive_precision)]
    fn a_tie_takes_the_even_digit_as_json_does() {
        let x = -1245506687333402.25;
        assert_eq!(Num(x).to_string(), "-1245506687333402.3");
        assert_eq!(as_csv(x), "-1245506687333402.2");
        assert_eq!(as_json(x), "-1245506687333402.2");
        assert_eq!(as_csv(x).parse::<f64>().unwrap(), x);
    }

    #[test]
    fn json_is_serde_jsons_text_at_every_edge() {
        for x in edges() {
            assert_eq!(as_json(x), serde_json::to_string(&x).unwrap(), "{x:e}");
        }
    }

    #[test]
    fn the_table_of_the_module_docs() {
        let rows = [
            (1.0, "1.0", "1"),
            (-0.0, "-0.0", "-0"),
            (1.5e-6, "1.5e-6", "0.0000015"),
            (1.5e-7, "1.5e-7", "1.5e-7"),
            (1e16, "1e+16", "1e16"),
            (1e300, "1e+300", "1e300"),
        ];
        for (x, j, c) in rows {
            assert_eq!((as_json(x), as_csv(x)), (j.to_owned(), c.to_owned()));
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]
        /// Any finite bit pattern: the text is `Num`'s and reads back exactly.
        #[test]
        fn csv_is_nums_text_for_any_float(bits in any::<u64>()) {
            let x = f64::from_bits(bits);
            prop_assume!(x.is_finite());
            let text = as_csv(x);
            prop_assert!(agrees_with_num(&text, x), "{} against {}", text, Num(x));
            prop_assert_eq!(text.parse::<f64>().unwrap().to_bits(), bits);
        }

        /// Values of ordinary size, where most output lies.
        #[test]
        fn csv_is_nums_text_for_ordinary_values(x in -1e7..1e7f64, k in -8..18i32) {
            let x = x * 10f64.powi(k - 7);
            prop_assert!(agrees_with_num(&as_csv(x), x), "{} against {}", as_csv(x), Num(x));
            prop_assert_eq!(as_json(x), serde_json::to_string(&x).unwrap());
        }
    }
}
