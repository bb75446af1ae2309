//! The report's tables of control points at each stage and of the distance.
//! Every number is written exactly as `t2spline run` writes it (serde_json's
//! shortest round-trip form), so the report and the result file agree to the
//! last digit; each cell names its place in the result file (`data-key`).

use std::fmt::Write as _;

use t2spline::job::RunOutput;
use t2spline::Layer;

use crate::svg::escape;

/// A number as `t2spline run` prints it; `None` (an absent lower cut) as `null`.
#[must_use]
pub fn number_text(v: Option<f64>) -> String {
    v.map_or_else(
        || "null".to_owned(),
        |x| serde_json::Value::from(x).to_string(),
    )
}

/// One table: its id, its header and static row heads, and the keys of its
/// changing cells in order.
#[derive(Debug)]
pub struct Table {
    /// Element id.
    pub id: &'static str,
    /// Column titles.
    pub header: Vec<String>,
    /// Per row: the leading cells (point, coordinate) and the keys of the number cells.
    pub rows: Vec<(Vec<String>, Vec<String>)>,
}

const AXES: [&str; 3] = ["x", "y", "z"];

/// The tables of a result, in report order.
#[must_use]
pub fn tables(r: &RunOutput) -> Vec<Table> {
    let n = r.control_points.crisp.len();
    let d = r.dimension;
    let layers: Vec<Layer> = Layer::ALL.to_vec();
    let mut cut = Table {
        id: "table-alpha-cut",
        header: ["point", "coord."]
            .iter()
            .map(|s| (*s).to_owned())
            .chain(
                layers
                    .iter()
                    .map(|l| format!("{}′", l.name().replace('_', "."))),
            )
            .collect(),
        rows: Vec::new(),
    };
    let mut reduced = Table {
        id: "table-type-reduced",
        header: ["point", "coord.", "left", "crisp", "right"]
            .map(str::to_owned)
            .to_vec(),
        rows: Vec::new(),
    };
    let mut defuzzified = Table {
        id: "table-defuzzified",
        header: std::iter::once("point".to_owned())
            .chain(AXES[..d].iter().map(|a| (*a).to_owned()))
            .collect(),
        rows: Vec::new(),
    };
    for k in 0..n {
        for (a, axis) in AXES[..d].iter().enumerate() {
            let heads = vec![k.to_string(), (*axis).to_owned()];
            let cells = layers
                .iter()
                .map(|l| match l {
                    Layer::Crisp => format!("crisp.{k}.{a}"),
                    _ => format!("alpha_cut.{}.{k}.{a}", l.name()),
                })
                .collect();
            cut.rows.push((heads.clone(), cells));
            reduced.rows.push((
                heads,
                vec![
                    format!("type_reduced_left.{k}.{a}"),
                    format!("crisp.{k}.{a}"),
                    format!("type_reduced_right.{k}.{a}"),
                ],
            ));
        }
        defuzzified.rows.push((
            vec![k.to_string()],
            (0..d).map(|a| format!("defuzzified.{k}.{a}")).collect(),
        ));
    }
    let distance = Table {
        id: "table-distance",
        header: ["", "max", "max_at (t)", "rms"].map(str::to_owned).to_vec(),
        rows: vec![(
            vec!["distance".to_owned()],
            vec![
                "error.max".into(),
                "error.max_at".into(),
                "error.rms".into(),
            ],
        )],
    };
    vec![cut, reduced, defuzzified, distance]
}

/// The value at a cell key: `error.*` or a path into `control_points`.
#[must_use]
pub fn value(r: &RunOutput, key: &str) -> Option<f64> {
    let parts: Vec<&str> = key.split('.').collect();
    let cp = &r.control_points;
    let idx = |s: &str| s.parse::<usize>().ok();
    match parts.as_slice() {
        ["error", "max"] => Some(r.error.max),
        ["error", "max_at"] => r.error.max_at.t(),
        ["error", "rms"] => Some(r.error.rms),
        [name, k, a] => {
            let (k, a) = (idx(k)?, idx(a)?);
            let points = match *name {
                "crisp" => &cp.crisp,
                "type_reduced_left" => &cp.type_reduced_left,
                "type_reduced_right" => &cp.type_reduced_right,
                "defuzzified" => &cp.defuzzified,
                _ => return None,
            };
            points.coord(a).get(k).copied()
        }
        ["alpha_cut", layer, k, a] => {
            let l = Layer::ALL.into_iter().find(|l| l.name() == *layer)?;
            *cp.alpha_cut.get(l)?.coord(idx(a)?).get(idx(k)?)?
        }
        _ => None,
    }
}

/// The cell texts of a table for one result, in row order.
#[must_use]
pub fn cells(t: &Table, r: &RunOutput) -> Vec<String> {
    t.rows
        .iter()
        .flat_map(|(_, keys)| keys.iter().map(|k| number_text(value(r, k))))
        .collect()
}

/// The table as HTML with the texts of `r`.
#[must_use]
pub fn html(t: &Table, r: &RunOutput) -> String {
    let mut s = format!("<table id=\"{}\"><thead><tr>", t.id);
    for h in &t.header {
        let _ = write!(s, "<th>{}</th>", escape(h));
    }
    s.push_str("</tr></thead><tbody>\n");
    for (heads, keys) in &t.rows {
        s.push_str("<tr>");
        for h in heads {
            let _ = write!(s, "<th scope=\"row\">{}</th>", escape(h));
        }
        for k in keys {
            let _ = write!(s, "<td data-key=\"{k}\">{}</td>", number_text(value(r, k)));
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody></table>\n");
    s
}
