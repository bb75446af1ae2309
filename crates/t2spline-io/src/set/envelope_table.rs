//! The envelope of a fuzzy surface as a long table (docs/method.md §12):
//! the columns `x, y, alpha, membership, lower, upper`, one row per cell with
//! data, level and membership function (levels in the order asked, then
//! upper, primary, lower, then the cells row by row from the least y, x
//! fastest). NODATA cells have no row. CSV here, Parquet (feature `parquet`)
//! by the crate's column writers.

use std::io::{self, Write};

use t2spline::set::{Envelope, MEMBERSHIPS};
use t2spline::Membership;

use crate::number::csv as num;

/// The table's columns.
pub const ENVELOPE_COLUMNS: [&str; 6] = ["x", "y", "alpha", "membership", "lower", "upper"];

/// The name of a membership function in tables and band descriptions.
#[must_use]
pub fn membership_name(m: Membership) -> &'static str {
    match m {
        Membership::Upper => "upper",
        Membership::Primary => "primary",
        Membership::Lower => "lower",
    }
}

/// One row of the table.
pub(crate) struct Row {
    pub(crate) x: f64,
    pub(crate) y: f64,
    pub(crate) alpha: f64,
    pub(crate) membership: &'static str,
    pub(crate) lower: f64,
    pub(crate) upper: f64,
}

/// The rows of the table, in its order.
pub(crate) fn rows(e: &Envelope) -> impl Iterator<Item = Row> + '_ {
    let (xs, ys) = (e.grid.xs(), e.grid.ys());
    let nx = xs.len();
    e.levels.iter().flat_map(move |level| {
        let (xs, ys) = (xs.clone(), ys.clone());
        MEMBERSHIPS.into_iter().flat_map(move |m| {
            let (xs, ys) = (xs.clone(), ys.clone());
            level.get(m).into_iter().flat_map(move |b| {
                let (xs, ys) = (xs.clone(), ys.clone());
                b.least
                    .iter()
                    .zip(&b.greatest)
                    .enumerate()
                    .filter(|(_, (lo, hi))| !lo.is_nan() && !hi.is_nan())
                    .map(move |(k, (&lower, &upper))| Row {
                        x: xs[k % nx],
                        y: ys[k / nx],
                        alpha: level.alpha,
                        membership: membership_name(m),
                        lower,
                        upper,
                    })
            })
        })
    })
}

/// Writes the envelope as CSV with the header
/// `x,y,alpha,membership,lower,upper`.
///
/// # Errors
/// The errors of `w`.
///
/// # Examples
/// ```
/// # use t2spline::{Alpha, FuzzySurface, Nt2Number, Nt2Point};
/// # use t2spline::set::PlanGrid;
/// let c = |x: f64| Nt2Number::try_crisp(x);
/// let z = Nt2Number::try_new(0.0, [-1.0, 1.0], [-0.5, 0.5], [-0.25, 0.25], 0.5)?;
/// let p = |x: f64, y: f64| Ok::<_, t2spline::Error>(Nt2Point::new([c(x)?, c(y)?, z]));
/// let net = vec![vec![p(0.0, 0.0)?, p(0.0, 2.0)?], vec![p(2.0, 0.0)?, p(2.0, 2.0)?]];
/// let s = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
/// let e = s.envelope(&PlanGrid::try_new(s.plan_extent(), [1, 1])?, &[Alpha::ZERO])?;
/// let mut out = Vec::new();
/// t2spline_io::set::write_envelope_csv(&mut out, &e)?;
/// assert_eq!(
///     String::from_utf8(out)?,
///     "x,y,alpha,membership,lower,upper\n1,1,0,upper,-1,1\n1,1,0,primary,-0.5,0.5\n1,1,0,lower,-0.25,0.25\n"
/// );
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_envelope_csv<W: Write + ?Sized>(w: &mut W, e: &Envelope) -> io::Result<()> {
    writeln!(w, "{}", ENVELOPE_COLUMNS.join(","))?;
    for r in rows(e) {
        for v in [r.x, r.y, r.alpha] {
            num(w, v)?;
            w.write_all(b",")?;
        }
        w.write_all(r.membership.as_bytes())?;
        w.write_all(b",")?;
        num(w, r.lower)?;
        w.write_all(b",")?;
        num(w, r.upper)?;
        w.write_all(b"\n")?;
    }
    Ok(())
}

/// Writes the envelope as one Parquet table: `x, y, alpha, lower, upper`
/// required `DOUBLE`, `membership` required UTF-8 text; the grid (`extent`
/// `[x0, y0, x1, y1]`, `shape` `[nx, ny]`) and whether the bounds are exact
/// as key-value metadata (JSON text).
///
/// # Errors
/// The errors of `writer`.
#[cfg(feature = "parquet")]
pub fn write_envelope_parquet<W: Write + Send>(writer: W, e: &Envelope) -> io::Result<()> {
    parquet_table::write(writer, e).map_err(crate::parquet::io_error)
}

#[cfg(feature = "parquet")]
mod parquet_table {
    use std::io::Write;

    use parquet::basic::Repetition;
    use parquet::data_type::{ByteArray, ByteArrayType, DoubleType};
    use parquet::errors::ParquetError;
    use parquet::file::metadata::KeyValue;
    use parquet::file::writer::SerializedFileWriter;
    use t2spline::set::Envelope;

    use super::{rows, ENVELOPE_COLUMNS};
    use crate::parquet::{double, next, properties, schema, text, ROW_GROUP};

    pub(super) fn write<W: Write + Send>(writer: W, e: &Envelope) -> Result<(), ParquetError> {
        let [x, y, alpha, membership, lower, upper] = ENVELOPE_COLUMNS;
        let fields = vec![
            double(x)?,
            double(y)?,
            double(alpha)?,
            text(membership, Repetition::REQUIRED)?,
            double(lower)?,
            double(upper)?,
        ];
        let json = |v: serde_json::Value| v.to_string();
        let metadata = vec![
            KeyValue::new(
                "extent".to_owned(),
                json(serde_json::json!(e.grid.extent())),
            ),
            KeyValue::new("shape".to_owned(), json(serde_json::json!(e.grid.shape()))),
            KeyValue::new("exact".to_owned(), json(serde_json::json!(e.exact))),
        ];
        let mut out =
            SerializedFileWriter::new(writer, schema(fields)?, properties(metadata, false))?;
        let mut all = rows(e).peekable();
        while all.peek().is_some() {
            let mut columns: [Vec<f64>; 5] = Default::default();
            let mut names: Vec<ByteArray> = Vec::new();
            for r in all.by_ref().take(ROW_GROUP) {
                for (c, v) in columns
                    .iter_mut()
                    .zip([r.x, r.y, r.alpha, r.lower, r.upper])
                {
                    c.push(v);
                }
                names.push(ByteArray::from(r.membership));
            }
            let mut group = out.next_row_group()?;
            let [xs, ys, alphas, lows, highs] = &columns;
            for values in [xs, ys, alphas] {
                let mut c = next(&mut group)?;
                c.typed::<DoubleType>().write_batch(values, None, None)?;
                c.close()?;
            }
            let mut c = next(&mut group)?;
            c.typed::<ByteArrayType>().write_batch(&names, None, None)?;
            c.close()?;
            for values in [lows, highs] {
                let mut c = next(&mut group)?;
                c.typed::<DoubleType>().write_batch(values, None, None)?;
                c.close()?;
            }
            group.close()?;
        }
        out.close()?;
        Ok(())
    }
}
