//! The grades of query points as CSV: `x,y[,z],upper,primary,lower`, one row
//! per point in input order.

use std::io::{self, Write};

use t2spline::set::Grades;

use crate::number::csv as num;

/// Writes the header and one row per point with its grades.
///
/// # Errors
/// The errors of `w`.
///
/// # Examples
/// ```
/// use t2spline::set::Grades;
/// let mut out = Vec::new();
/// let g = Grades { upper: 0.5, primary: 0.25, lower: 0.0 };
/// t2spline_io::set::write_membership_csv(&mut out, &[[1.0, 2.0]], &[g])?;
/// assert_eq!(String::from_utf8(out)?, "x,y,upper,primary,lower\n1,2,0.5,0.25,0\n");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_membership_csv<W: Write + ?Sized, const D: usize>(
    w: &mut W,
    points: &[[f64; D]],
    grades: &[Grades],
) -> io::Result<()> {
    let axes = ["x", "y", "z"];
    writeln!(w, "{},upper,primary,lower", axes[..D].join(","))?;
    for (p, g) in points.iter().zip(grades) {
        for x in p {
            num(w, *x)?;
            w.write_all(b",")?;
        }
        num(w, g.upper)?;
        w.write_all(b",")?;
        num(w, g.primary)?;
        w.write_all(b",")?;
        num(w, g.lower)?;
        w.write_all(b"\n")?;
    }
    Ok(())
}
