//! CSV export of the sampled curves: one file per curve family, with headers.

use std::io::Write;
use std::path::{Path, PathBuf};

use t2spline::job::{Parameters, Points, RunOutput};
use t2spline::pipeline::euclidean_norm;
use t2spline::{Layer, Num};

use crate::atomic::Staged;
use crate::Error;

/// The files [`write_csv`] writes, with what each holds.
pub const CSV_FILES: [(&str, &str); 4] = [
    (
        "stage1-layers.csv",
        "the seven layer curves of the fuzzy curve",
    ),
    (
        "stage2-alpha-cut.csv",
        "the alpha-cut layer curves that exist at this alpha",
    ),
    (
        "stage3-type-reduced.csv",
        "the type-reduced left, crisp and right curves",
    ),
    (
        "stage4-defuzzified.csv",
        "the crisp and the defuzzified curve and their distance",
    ),
];

/// One named column group: a curve sampled at the result's parameters.
type Family<'a> = Vec<(String, &'a Points)>;

/// One CSV file of a result: `t` (a surface: `u, v`, one row per grid point,
/// `v` fastest), then every curve's coordinates, then an optional extra
/// column.
struct Table<'a> {
    params: &'a Parameters,
    family: Family<'a>,
    dims: usize,
    extra: Option<(&'static str, Vec<f64>)>,
}

impl Table<'_> {
    fn write(&self, out: &mut dyn Write) -> std::io::Result<()> {
        let axes = ["x", "y", "z"];
        let mut w = csv::Writer::from_writer(out);
        let mut header: Vec<String> = match self.params {
            Parameters::Along(_) => vec!["t".to_owned()],
            Parameters::Grid { .. } => vec!["u".to_owned(), "v".to_owned()],
        };
        for (name, _) in &self.family {
            header.extend(axes[..self.dims].iter().map(|a| format!("{name}_{a}")));
        }
        header.extend(self.extra.as_ref().map(|(name, _)| (*name).to_owned()));
        w.write_record(&header)?;
        let number = |x: &f64| Num(*x).to_string();
        let index: Box<dyn Iterator<Item = Vec<&f64>>> = match self.params {
            Parameters::Along(t) => Box::new(t.iter().map(|t| vec![t])),
            Parameters::Grid { u, v } => Box::new(
                u.iter()
                    .flat_map(move |a| v.iter().map(move |b| vec![a, b])),
            ),
        };
        for (i, at) in index.enumerate() {
            let mut row: Vec<String> = at.into_iter().map(number).collect();
            for (_, points) in &self.family {
                row.extend(points.coords().iter().map(|c| number(&c[i])));
            }
            row.extend(self.extra.as_ref().map(|(_, v)| number(&v[i])));
            w.write_record(&row)?;
        }
        w.flush()
    }
}

/// The tables of a result, in the order of [`CSV_FILES`], then
/// [`DERIVATIVES_CSV`] when the result has derivatives.
fn tables(result: &RunOutput) -> Vec<(&'static str, Table<'_>)> {
    let c = &result.samples;
    let layer = |l: Layer| c.layer(l);
    let stage1: Family = Layer::ALL
        .iter()
        .map(|&l| (l.name().to_owned(), layer(l)))
        .collect();
    let stage2: Family = Layer::ALL
        .iter()
        .filter_map(|&l| match c.alpha_cut.get(l) {
            Some(Some(v)) => Some((l.name().to_owned(), v)),
            Some(None) => None,
            None => Some((l.name().to_owned(), &c.crisp)),
        })
        .collect();
    let stage3: Family = vec![
        ("left".into(), &c.type_reduced.left),
        ("crisp".into(), &c.crisp),
        ("right".into(), &c.type_reduced.right),
    ];
    let stage4: Family = vec![
        ("crisp".into(), &c.crisp),
        ("defuzzified".into(), &c.defuzzified),
    ];
    // Scaled, so that a distance near 1e-170 does not underflow when squared.
    let mut d = vec![0.0; result.dimension];
    let distance: Vec<f64> = (0..c.params.count())
        .map(|i| {
            for ((d, a), b) in d
                .iter_mut()
                .zip(c.crisp.coords())
                .zip(c.defuzzified.coords())
            {
                *d = a[i] - b[i];
            }
            euclidean_norm(&d)
        })
        .collect();
    let table = |family, extra| Table {
        params: &c.params,
        family,
        dims: result.dimension,
        extra,
    };
    let mut files = vec![
        (CSV_FILES[0].0, table(stage1, None)),
        (CSV_FILES[1].0, table(stage2, None)),
        (CSV_FILES[2].0, table(stage3, None)),
        (CSV_FILES[3].0, table(stage4, Some(("distance", distance)))),
    ];
    if let Some(d) = &c.derivatives {
        // `crisp_d1_x, …, defuzzified_dK_z`: the derivatives of `--derivatives K`.
        let family: Family = [("crisp", &d.crisp), ("defuzzified", &d.defuzzified)]
            .into_iter()
            .flat_map(|(name, orders)| {
                orders
                    .iter()
                    .enumerate()
                    .map(move |(k, points)| (format!("{name}_d{}", k + 1), points))
            })
            .collect();
        files.push((DERIVATIVES_CSV, table(family, None)));
    }
    files
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
    tables(result)
        .into_iter()
        .map(|(name, table)| {
            let mut out = Vec::new();
            // Writing to a Vec cannot fail, and CSV of numbers and names is UTF-8.
            table.write(&mut out).expect("in-memory write");
            (
                name,
                String::from_utf8(out).expect("CSV of numbers is UTF-8"),
            )
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
/// together with other outputs. Returns the target paths.
///
/// # Errors
/// [`Error::Write`] if the folder cannot be created or a file cannot be
/// written.
pub fn stage_csv(
    staged: &mut Staged,
    dir: &Path,
    result: &RunOutput,
) -> Result<Vec<PathBuf>, Error> {
    std::fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: dir.to_owned(),
        source,
    })?;
    tables(result)
        .into_iter()
        .map(|(name, table)| {
            let path = dir.join(name);
            staged.add(&path, |w| table.write(w)).map(|()| path)
        })
        .collect()
}
