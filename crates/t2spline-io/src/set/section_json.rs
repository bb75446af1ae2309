//! Station sections as JSON: `{"x": X0, "levels": [{"alpha": a, "upper":
//! [[y0, y1], …], "primary": […], "lower": […]}, …]}` (`"x"` and `"y"` with
//! `"z"` intervals for a surface). A function with no cut at a level has
//! `null`.

use std::io::{self, Write};

use t2spline::set::SectionLevel;

use crate::number::json as num;

/// Where the section is taken.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Station {
    /// A plane curve's vertical line `x = x0`; the intervals are of y.
    X(f64),
    /// A surface's vertical line `(x0, y0)`; the intervals are of z.
    Xy(f64, f64),
}

/// Writes the sections.
///
/// # Errors
/// The errors of `w`.
///
/// # Examples
/// ```
/// use t2spline::set::SectionLevel;
/// use t2spline_io::set::{write_section_json, Station};
/// let level = SectionLevel { alpha: 0.5, upper: Some(vec![[1.0, 2.0]]), primary: Some(vec![]), lower: None };
/// let mut out = Vec::new();
/// write_section_json(&mut out, Station::X(3.0), &[level])?;
/// assert_eq!(String::from_utf8(out)?, concat!(
///     "{\"x\": 3.0, \"levels\": [\n",
///     "  {\"alpha\": 0.5, \"upper\": [[1.0, 2.0]], \"primary\": [], \"lower\": null}\n",
///     "]}\n"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_section_json<W: Write + ?Sized>(
    w: &mut W,
    station: Station,
    levels: &[SectionLevel],
) -> io::Result<()> {
    match station {
        Station::X(x) => {
            w.write_all(b"{\"x\": ")?;
            num(w, x)?;
        }
        Station::Xy(x, y) => {
            w.write_all(b"{\"x\": ")?;
            num(w, x)?;
            w.write_all(b", \"y\": ")?;
            num(w, y)?;
        }
    }
    w.write_all(b", \"levels\": [")?;
    for (k, level) in levels.iter().enumerate() {
        w.write_all(if k > 0 { b",\n  " } else { b"\n  " })?;
        w.write_all(b"{\"alpha\": ")?;
        num(w, level.alpha)?;
        for (name, intervals) in [
            ("upper", &level.upper),
            ("primary", &level.primary),
            ("lower", &level.lower),
        ] {
            write!(w, ", \"{name}\": ")?;
            match intervals {
                None => w.write_all(b"null")?,
                Some(list) => {
                    w.write_all(b"[")?;
                    for (i, iv) in list.iter().enumerate() {
                        if i > 0 {
                            w.write_all(b", ")?;
                        }
                        w.write_all(b"[")?;
                        num(w, iv[0])?;
                        w.write_all(b", ")?;
                        num(w, iv[1])?;
                        w.write_all(b"]")?;
                    }
                    w.write_all(b"]")?;
                }
            }
        }
        w.write_all(b"}")?;
    }
    w.write_all(b"\n]}\n")
}
