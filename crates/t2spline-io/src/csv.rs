//! CSV export of the sampled curves: one file per curve family, with headers.
//!
//! Each number's shortest round-trip digits (zmij's, the ones serde_json
//! writes, `number.rs`) go straight into a 64 KiB buffer of a concrete type, so
//! a number costs its formatting and a copy: no `String` per number or row and
//! no call through `dyn Write` per separator (the writer before this built a
//! string per number and went through the `csv` crate). Only the notation
//! differs from the JSON file's (`1` for `1.0`, `1e300`, plain decimals down
//! to 1e-6), so the digits of the CSV and JSON files of one run are the same.
//! The tables themselves, borrowing the result's vectors, are `table.rs`'s.

use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use t2spline::job::RunOutput;

use crate::atomic::Staged;
use crate::error::Error;
use crate::number;
use crate::table::{stage_tables, Table};

/// The file of stage 1: the seven layer curves.
pub const STAGE1_CSV: &str = "stage1-layers.csv";
/// The file of stage 2: the alpha-cut layer curves.
pub const STAGE2_CSV: &str = "stage2-alpha-cut.csv";
/// The file of stage 3: the type-reduced curves.
pub const STAGE3_CSV: &str = "stage3-type-reduced.csv";
/// The file of stage 4: the crisp and the defuzzified curve.
pub const STAGE4_CSV: &str = "stage4-defuzzified.csv";

/// The files [`write_csv`] writes, with what each holds, in the order of the
/// stages.
pub const CSV_FILES: [(&str, &str); 4] = [
    (STAGE1_CSV, "the seven layer curves of the fuzzy curve"),
    (
        STAGE2_CSV,
        "the alpha-cut layer curves that exist at this alpha",
    ),
    (STAGE3_CSV, "the type-reduced left, crisp and right curves"),
    (
        STAGE4_CSV,
        "the crisp and the defuzzified curve and their distance",
    ),
];

/// The CSV files' tables by file name: the four stages, then
/// [`DERIVATIVES_CSV`] when the result has derivatives.
fn csv_tables(result: &RunOutput) -> Vec<(&'static str, Table<'_>)> {
    let (stages, derivatives) = stage_tables(result);
    let names = [STAGE1_CSV, STAGE2_CSV, STAGE3_CSV, STAGE4_CSV];
    let mut tables: Vec<_> = names.into_iter().zip(stages).collect();
    tables.extend(derivatives.map(|d| (DERIVATIVES_CSV, d)));
    tables
}

/// Writes one table as CSV: a header of column names, then one line per
/// row, numbers in [`number::csv`]'s form, `\n` line ends (no quoting: names
/// and numbers hold no commas or quotes).
///
/// Numbers go straight into a buffer of 64 KiB: no string per number or row.
fn write_table<W: Write>(table: &Table<'_>, out: W) -> io::Result<()> {
    let mut w = BufWriter::with_capacity(1 << 16, out);
    for (k, column) in table.columns.iter().enumerate() {
        if k > 0 {
            w.write_all(b",")?;
        }
        w.write_all(column.name.as_bytes())?;
    }
    w.write_all(b"\n")?;
    for i in 0..table.rows {
        let mut columns = table.columns.iter();
        if let Some(first) = columns.next() {
            number::csv(&mut w, first.values.get(i))?;
        }
        for column in columns {
            w.write_all(b",")?;
            number::csv(&mut w, column.values.get(i))?;
        }
        w.write_all(b"\n")?;
    }
    w.flush()
}

/// The extra file [`write_csv`] writes for a result with derivatives
/// (`t2spline run --derivatives K --csv DIR`): columns `crisp_d1_x, …,
/// defuzzified_dK_y` after `t`.
pub const DERIVATIVES_CSV: &str = "derivatives.csv";

/// Renders the four CSV files of a result, as `(file name, contents)`, and
/// [`DERIVATIVES_CSV`] when the result has derivatives.
///
/// Every file starts with the column `t`; a curve `name` contributes columns
/// `name_x`, `name_y` (and `name_z`). Numbers are written in the shortest form
/// that reads back to the same `f64`, in exponent form beyond 1e16 and below
/// 1e-6 (`1e300`, not 301 digits).
#[must_use]
pub fn render_csv(result: &RunOutput) -> Vec<(&'static str, String)> {
    csv_tables(result)
        .into_iter()
        .map(|(name, table)| {
            let mut out = Vec::new();
            // Writing to a Vec cannot fail, and CSV of numbers and names is
            // UTF-8, so the lossy conversion changes nothing.
            #[allow(clippy::expect_used)]
            write_table(&table, &mut out).expect("in-memory write");
            (name, String::from_utf8_lossy(&out).into_owned())
        })
        .collect()
}

/// Writes the CSV files of [`render_csv`] into `dir`, creating it if
/// needed, all or nothing: each is written completely to a temporary file
/// first, and only then are the four renamed into place. Returns the paths
/// written.
///
/// # Errors
/// [`Error::Write`] if the folder cannot be created or a file cannot be
/// written; then no file in `dir` has changed.
pub fn write_csv(dir: &Path, result: &RunOutput) -> Result<Vec<PathBuf>, Error> {
    let mut staged = Staged::default();
    let paths = stage_csv(&mut staged, dir, result)?;
    staged.commit()?;
    Ok(paths)
}

/// Writes the CSV files of a result into temporary files beside their
/// targets in `dir` (created if needed), to be renamed by [`Staged::commit`]
/// together with other outputs. Returns the target paths. A
/// [`DERIVATIVES_CSV`] of an earlier run is removed at the commit when this
/// result has no derivatives, so that the folder holds this result's files
/// (other files in it are left alone).
///
/// # Errors
/// [`Error::Write`] if the folder cannot be created or a file cannot be
/// written.
pub fn stage_csv<'a>(
    staged: &mut Staged<'a>,
    dir: &Path,
    result: &'a RunOutput,
) -> Result<Vec<PathBuf>, Error> {
    std::fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: dir.to_owned(),
        source,
    })?;
    let tables = csv_tables(result);
    if !tables.iter().any(|(name, _)| *name == DERIVATIVES_CSV) {
        staged.remove_stale(&dir.join(DERIVATIVES_CSV));
    }
    tables
        .into_iter()
        .map(|(name, table)| {
            let path = dir.join(name);
            staged
                .add(&path, move |w| write_table(&table, w))
                .map(|()| path)
        })
        .collect()
}
