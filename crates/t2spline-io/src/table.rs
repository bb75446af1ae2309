//! A run's sampled curves (or surfaces) as tables of named columns, one row
//! per parameter: what the CSV files and the Parquet file hold.
//!
//! Columns borrow the result's vectors (structure of arrays, [`Points`]);
//! nothing is copied. A surface's `u` and `v` repeat over the grid (`v`
//! fastest) and the distance is taken row by row from the core
//! ([`Points::distance_at`]), so neither is stored.

use t2spline::job::{Parameters, Points, RunOutput};
use t2spline::Layer;

/// The coordinate names of columns: `crisp_x`, `crisp_y`, `crisp_z`.
const AXES: [&str; 3] = ["x", "y", "z"];

/// Where the values of a column come from.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Values<'a> {
    /// One value per row.
    Slice(&'a [f64]),
    /// A grid's `u`: row `i` has `u[i / sv]`.
    Outer(&'a [f64], usize),
    /// A grid's `v`: row `i` has `v[i % v.len()]`.
    Inner(&'a [f64]),
    /// `|crisp − defuzzified|` of each row.
    Distance(&'a Points, &'a Points),
}

impl Values<'_> {
    /// The value of row `i`.
    #[inline]
    pub(crate) fn get(&self, i: usize) -> f64 {
        match *self {
            Values::Slice(v) => v[i],
            Values::Outer(u, sv) => u[i / sv],
            Values::Inner(v) => v[i % v.len()],
            // Rows are counted from the points themselves, so `i` is in range.
            Values::Distance(a, b) => a.distance_at(b, i).unwrap_or(f64::NAN),
        }
    }

    /// The values of rows `rows`, borrowed when they are stored, else
    /// computed into `scratch`.
    #[cfg(feature = "parquet")]
    pub(crate) fn rows<'s>(
        &'s self,
        rows: std::ops::Range<usize>,
        scratch: &'s mut Vec<f64>,
    ) -> &'s [f64] {
        if let Values::Slice(v) = self {
            return &v[rows];
        }
        scratch.clear();
        scratch.extend(rows.map(|i| self.get(i)));
        scratch
    }
}

/// A named column.
#[derive(Clone, Debug)]
pub(crate) struct Column<'a> {
    /// `t`, `crisp_x`, `distance`, ...: letters, digits and `_` only.
    pub(crate) name: String,
    /// Its values.
    pub(crate) values: Values<'a>,
}

/// Columns of one length.
#[derive(Clone, Debug)]
pub(crate) struct Table<'a> {
    /// The columns, parameters first.
    pub(crate) columns: Vec<Column<'a>>,
    /// The number of rows.
    pub(crate) rows: usize,
}

/// Curves of one family: a name per curve.
type Family<'a> = Vec<(String, &'a Points)>;

/// The parameter columns: `t`, or a grid's `u` and `v` (`v` fastest).
fn parameters(params: &Parameters) -> Vec<Column<'_>> {
    let column = |name: &str, values| Column {
        name: name.to_owned(),
        values,
    };
    match params {
        Parameters::Along(t) => vec![column("t", Values::Slice(t))],
        Parameters::Grid { u, v } => vec![
            column("u", Values::Outer(u, v.len().max(1))),
            column("v", Values::Inner(v)),
        ],
    }
}

/// `name_x, name_y (, name_z)` for every curve of `family`, each name after
/// `prefix`.
fn coordinates<'a>(prefix: &str, family: &[(String, &'a Points)]) -> Vec<Column<'a>> {
    let mut columns = Vec::new();
    for (name, points) in family {
        for (c, axis) in points.coords().iter().zip(AXES) {
            columns.push(Column {
                name: format!("{prefix}{name}_{axis}"),
                values: Values::Slice(c),
            });
        }
    }
    columns
}

/// The curve families of a result: stage 1 (the seven layers), stage 2 (the
/// alpha-cut layers that exist at this alpha, the crisp curve for the crisp
/// layer), stage 3 (left, crisp, right), stage 4 (crisp, defuzzified), and
/// the derivatives if any (`crisp_d1 … defuzzified_dK`).
struct Families<'a> {
    stage1: Family<'a>,
    stage2: Family<'a>,
    stage3: Family<'a>,
    stage4: Family<'a>,
    derivatives: Option<Family<'a>>,
}

impl<'a> Families<'a> {
    fn of(result: &'a RunOutput) -> Self {
        let c = &result.samples;
        let named = |name: &str, points| (name.to_owned(), points);
        Families {
            stage1: Layer::ALL
                .iter()
                .map(|&l| named(l.name(), c.layer(l)))
                .collect(),
            stage2: Layer::ALL
                .iter()
                .filter_map(|&l| match c.alpha_cut.get(l) {
                    Some(Some(v)) => Some(named(l.name(), v)),
                    Some(None) => None,
                    None => Some(named(l.name(), &c.crisp)),
                })
                .collect(),
            stage3: vec![
                named("left", &c.type_reduced.left),
                named("crisp", &c.crisp),
                named("right", &c.type_reduced.right),
            ],
            stage4: vec![
                named("crisp", &c.crisp),
                named("defuzzified", &c.defuzzified),
            ],
            derivatives: c.derivatives.as_ref().map(|d| {
                [("crisp", &d.crisp), ("defuzzified", &d.defuzzified)]
                    .into_iter()
                    .flat_map(|(name, orders)| {
                        orders
                            .iter()
                            .enumerate()
                            .map(move |(k, points)| (format!("{name}_d{}", k + 1), points))
                    })
                    .collect()
            }),
        }
    }
}

/// The `distance` column: `|crisp − defuzzified|` per row.
fn distance(result: &RunOutput) -> Column<'_> {
    Column {
        name: "distance".to_owned(),
        values: Values::Distance(&result.samples.crisp, &result.samples.defuzzified),
    }
}

/// The tables of the four stages, in order (stage 4 with the `distance`
/// column), and the derivatives' table when the result has them: one CSV file
/// each.
pub(crate) fn stage_tables<'r>(result: &'r RunOutput) -> ([Table<'r>; 4], Option<Table<'r>>) {
    let f = Families::of(result);
    let rows = result.samples.params.count();
    let table = |family: &[(String, &'r Points)], extra: Option<Column<'r>>| {
        let mut columns = parameters(&result.samples.params);
        columns.extend(coordinates("", family));
        columns.extend(extra);
        Table { columns, rows }
    };
    let stages = [
        table(&f.stage1, None),
        table(&f.stage2, None),
        table(&f.stage3, None),
        table(&f.stage4, Some(distance(result))),
    ];
    (stages, f.derivatives.as_deref().map(|d| table(d, None)))
}

/// Every sampled column of a result in one table, each curve once, with
/// the names of the CSV columns: the parameters, stage 1 (`upper_left_x`,
/// …, `crisp_x`, …), the alpha-cut layers that exist (`alpha_cut_upper_left_x`:
/// prefixed, as the stage-2 file's names repeat stage 1's), `left_*`,
/// `right_*`, `defuzzified_*`, `distance`, and the derivatives
/// (`crisp_d1_x`, …).
pub(crate) fn one_table(result: &RunOutput) -> Table<'_> {
    let f = Families::of(result);
    let mut columns = parameters(&result.samples.params);
    columns.extend(coordinates("", &f.stage1));
    // Stage 2 without the crisp curve, which stage 1 has.
    let cuts: Family<'_> = f
        .stage2
        .iter()
        .filter(|(name, _)| name != Layer::Crisp.name())
        .cloned()
        .collect();
    columns.extend(coordinates("alpha_cut_", &cuts));
    let c = &result.samples;
    let rest: Family<'_> = vec![
        ("left".to_owned(), &c.type_reduced.left),
        ("right".to_owned(), &c.type_reduced.right),
        ("defuzzified".to_owned(), &c.defuzzified),
    ];
    columns.extend(coordinates("", &rest));
    columns.push(distance(result));
    if let Some(d) = &f.derivatives {
        columns.extend(coordinates("", d));
    }
    Table {
        columns,
        rows: result.samples.params.count(),
    }
}

/// One column of a result's samples table ([`sample_columns`]): its name
/// and its values, borrowed from the result or computed row by row.
#[derive(Clone, Debug)]
pub struct SampleColumn<'a>(Column<'a>);

impl SampleColumn<'_> {
    /// `t`, `crisp_x`, `alpha_cut_upper_left_y`, `distance`, …
    #[must_use]
    pub fn name(&self) -> &str {
        &self.0.name
    }

    /// Appends the values of the first `rows` rows to `out`.
    pub fn extend_into(&self, rows: usize, out: &mut Vec<f64>) {
        if let Values::Slice(v) = self.0.values {
            out.extend_from_slice(&v[..rows.min(v.len())]);
        } else {
            out.extend((0..rows).map(|i| self.0.values.get(i)));
        }
    }
}

/// A result's samples as one table, the Parquet file's: its columns (the
/// parameters, stage 1, the alpha-cut layers that exist, `left_*`,
/// `right_*`, `defuzzified_*`, `distance`, the derivatives) and the number
/// of rows.
#[must_use]
pub fn sample_columns(result: &RunOutput) -> (Vec<SampleColumn<'_>>, usize) {
    let table = one_table(result);
    (
        table.columns.into_iter().map(SampleColumn).collect(),
        table.rows,
    )
}

/// Every column that [`sample_columns`] gives a result without derivatives,
/// whatever the model and the regime, in the table's order: `t`, `u`, `v`,
/// then the columns of a 3-D result at an alpha where every lower cut
/// exists (`upper_left_x`, …, `alpha_cut_upper_left_x`, …, `distance`).
/// One schema for the samples of many jobs: each result fills its own
/// columns, the others are absent.
#[must_use]
pub fn sample_column_names() -> Vec<String> {
    let mut names: Vec<String> = ["t", "u", "v"].map(str::to_owned).to_vec();
    let mut xyz = |prefix: &str, name: &str| {
        names.extend(AXES.iter().map(|a| format!("{prefix}{name}_{a}")));
    };
    for l in Layer::ALL {
        xyz("", l.name());
    }
    for l in Layer::ALL.iter().filter(|&&l| l != Layer::Crisp) {
        xyz("alpha_cut_", l.name());
    }
    for name in ["left", "right", "defuzzified"] {
        xyz("", name);
    }
    names.push("distance".to_owned());
    names
}

/// The highest order of a result's derivatives (0 without).
pub(crate) fn derivative_order(result: &RunOutput) -> usize {
    result
        .samples
        .derivatives
        .as_ref()
        .map_or(0, |d| d.crisp.len())
}

/// The sample columns of many runs' one table, after `job` and `alpha`:
/// [`sample_column_names`], then the derivative columns of orders 1 to
/// `derivatives` in a result's order (`crisp_d1_x`, `crisp_d1_y`,
/// `crisp_d1_z`, `crisp_d2_x`, …, `defuzzified_d1_x`, …). A column a job
/// lacks is null in its rows.
pub(crate) fn jobs_column_names(derivatives: usize) -> Vec<String> {
    let mut names = sample_column_names();
    for curve in ["crisp", "defuzzified"] {
        for k in 1..=derivatives {
            names.extend(AXES.iter().map(|a| format!("{curve}_d{k}_{a}")));
        }
    }
    names
}

#[cfg(test)]
mod tests {
    use t2spline::job::Overrides;

    use super::{sample_column_names, sample_columns};
    use crate::{MissingAlpha, Prepared};

    /// The names of a run's sample columns: the example job at `alpha`.
    fn names(file: &str, alpha: f64) -> Vec<String> {
        let path = format!("{}/../../examples/{file}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap();
        let overrides = Overrides {
            alpha: Some(alpha),
            samples: Some(if file.contains("paper") {
                vec![5]
            } else {
                vec![3, 4]
            }),
            ..Overrides::default()
        };
        let refuse = MissingAlpha::Refuse { advice: "" };
        let result = Prepared::from_text(&text, &path, &overrides, refuse)
            .unwrap()
            .run()
            .unwrap();
        let (columns, rows) = sample_columns(&result);
        assert_eq!(rows, result.samples.params.count());
        columns.iter().map(|c| c.name().to_owned()).collect()
    }

    #[test]
    fn every_result_s_columns_are_in_the_one_schema_in_its_order() {
        let all = sample_column_names();
        for (file, alpha) in [
            ("paper-alg-1-1.json", 0.3),
            ("paper-alg-1-1.json", 0.9),
            ("fuzzy-terrain.json", 0.2),
            ("fuzzy-terrain.json", 1.0),
        ] {
            let got = names(file, alpha);
            let mut at = all.iter();
            for name in &got {
                assert!(
                    at.any(|n| n == name),
                    "{file} at {alpha}: {name} out of the schema or its order"
                );
            }
        }
        // Below h every lower cut exists: a 3-D surface fills every column but t.
        let terrain = names("fuzzy-terrain.json", 0.0);
        assert_eq!(terrain.len(), all.len() - 1, "{terrain:?}");
    }
}
