//! CSV export of the sampled curves: one file per curve family, with headers.

use std::path::{Path, PathBuf};

use t2spline::Layer;

use crate::atomic::write_all_atomic;
use crate::result::{Point, RunResult};
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
type Family<'a> = Vec<(String, &'a [Point])>;

/// Renders the four CSV files of a result, as `(file name, contents)`, and
/// [`DERIVATIVES_CSV`] when the result has derivatives.
///
/// Every file starts with the column `t`; a curve `name` contributes columns
/// `name_x`, `name_y` (and `name_z`). Numbers are written in the shortest form
/// that reads back to the same `f64`.
#[must_use]
pub fn render_csv(result: &RunResult) -> Vec<(&'static str, String)> {
    let c = &result.curves;
    let layer = |l: Layer| -> &[Point] {
        match c.layers.get(l) {
            Some(v) => v,
            None => &c.crisp,
        }
    };
    let stage1: Family = Layer::ALL
        .iter()
        .map(|&l| (l.name().to_owned(), layer(l)))
        .collect();
    let stage2: Family = Layer::ALL
        .iter()
        .filter_map(|&l| match c.alpha_cut.get(l) {
            Some(Some(v)) => Some((l.name().to_owned(), v.as_slice())),
            Some(None) => None,
            None => Some((l.name().to_owned(), c.crisp.as_slice())),
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
    let distance: Vec<f64> = c
        .crisp
        .iter()
        .zip(&c.defuzzified)
        .map(|(a, b)| {
            a.iter()
                .zip(b)
                .map(|(x, y)| (x - y) * (x - y))
                .sum::<f64>()
                .sqrt()
        })
        .collect();
    let dims = result.dimension;
    let mut files = vec![
        (CSV_FILES[0].0, table(&c.params, &stage1, dims, None)),
        (CSV_FILES[1].0, table(&c.params, &stage2, dims, None)),
        (CSV_FILES[2].0, table(&c.params, &stage3, dims, None)),
        (
            CSV_FILES[3].0,
            table(&c.params, &stage4, dims, Some(("distance", &distance))),
        ),
    ];
    if let Some(d) = &c.derivatives {
        // `crisp_d1_x, …, defuzzified_dK_z`: the derivatives of `--derivatives K`.
        let family: Family = [("crisp", &d.crisp), ("defuzzified", &d.defuzzified)]
            .into_iter()
            .flat_map(|(name, orders)| {
                orders
                    .iter()
                    .enumerate()
                    .map(move |(k, points)| (format!("{name}_d{}", k + 1), points.as_slice()))
            })
            .collect();
        files.push((DERIVATIVES_CSV, table(&c.params, &family, dims, None)));
    }
    files
}

/// The extra file [`write_csv`] writes for a result with derivatives
/// (`t2spline run --derivatives K --csv DIR`): columns `crisp_d1_x, …,
/// defuzzified_dK_y` after `t`.
pub const DERIVATIVES_CSV: &str = "derivatives.csv";

fn table(params: &[f64], family: &Family, dims: usize, extra: Option<(&str, &[f64])>) -> String {
    let axes = ["x", "y", "z"];
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["t".to_owned()];
    for (name, _) in family {
        header.extend(axes[..dims].iter().map(|a| format!("{name}_{a}")));
    }
    header.extend(extra.map(|(name, _)| name.to_owned()));
    // Writing to a Vec cannot fail.
    w.write_record(&header).expect("in-memory write");
    for (i, t) in params.iter().enumerate() {
        let mut row = vec![t.to_string()];
        for (_, points) in family {
            row.extend(points[i].iter().map(f64::to_string));
        }
        row.extend(extra.map(|(_, v)| v[i].to_string()));
        w.write_record(&row).expect("in-memory write");
    }
    String::from_utf8(w.into_inner().expect("in-memory write")).expect("CSV of numbers is UTF-8")
}

/// Writes the four CSV files of [`render_csv`] into `dir`, creating it if
/// needed; the files are written all or nothing ([`write_all_atomic`]). Returns
/// the paths written.
///
/// # Errors
/// [`Error::Write`] if the folder cannot be created or a file cannot be written.
pub fn write_csv(dir: &Path, result: &RunResult) -> Result<Vec<PathBuf>, Error> {
    let files: Vec<(PathBuf, String)> = render_csv(result)
        .into_iter()
        .map(|(name, text)| (dir.join(name), text))
        .collect();
    std::fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: dir.to_owned(),
        source,
    })?;
    let refs: Vec<(&Path, &[u8])> = files
        .iter()
        .map(|(p, t)| (p.as_path(), t.as_bytes()))
        .collect();
    write_all_atomic(&refs)?;
    Ok(files.into_iter().map(|(p, _)| p).collect())
}
