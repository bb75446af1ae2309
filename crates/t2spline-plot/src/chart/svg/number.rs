//! Numbers as the SVG writer puts them into files: coordinates in pixels with
//! two decimals, so that the files are stable text and golden files compare
//! as text.

/// A coordinate for an SVG file: two decimals, trailing zeros dropped, no `-0`,
/// so that files are stable text.
#[must_use]
pub fn coord(v: f64) -> String {
    let s = format!("{v:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::coord;

    #[test]
    fn coordinates_have_two_decimals_and_no_negative_zero() {
        assert_eq!(coord(-0.004), "0");
        assert_eq!(coord(12.3456), "12.35");
        assert_eq!(coord(3.0), "3");
        assert_eq!(coord(10.10), "10.1");
    }
}
