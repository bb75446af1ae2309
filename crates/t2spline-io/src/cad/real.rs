//! Floats as the CAD formats write them: shortest, exact, with a decimal point.

use t2spline::Num;

/// A float in the shortest form that reads back exactly, with a decimal
/// point in the mantissa and `exponent` (`'E'`, or `'D'` for IGES double
/// precision) before a power of ten: `3.0`, `-0.25`, `1.5E-7`.
pub(crate) fn real(x: f64, exponent: char) -> String {
    let text = Num(x).to_string();
    let (mantissa, power) = match text.split_once('e') {
        Some((m, p)) => (m.to_owned(), Some(p)),
        None => (text, None),
    };
    let mut out = mantissa;
    if !out.contains('.') {
        out.push_str(".0");
    }
    if let Some(p) = power {
        out.push(exponent);
        out.push_str(p);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_read_back_exactly_with_a_decimal_point() {
        assert_eq!(real(3.0, 'E'), "3.0");
        assert_eq!(real(-0.25, 'E'), "-0.25");
        assert_eq!(real(1.5e-7, 'E'), "1.5E-7");
        assert_eq!(real(1e300, 'D'), "1.0D300");
        assert_eq!(real(0.1 + 0.2, 'E'), "0.30000000000000004");
        for x in [
            0.1,
            1.0 / 3.0,
            2f64.sqrt() * 1e-200,
            -7.25e151,
            f64::MIN_POSITIVE,
        ] {
            let text = real(x, 'E');
            assert_eq!(text.parse::<f64>().unwrap(), x, "{text}");
            let iges = real(x, 'D').replace('D', "E");
            assert_eq!(iges.parse::<f64>().unwrap(), x, "{iges}");
        }
    }
}
