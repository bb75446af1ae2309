//! The report's tables of control points at each stage and of the distance.
//!
//! Each cell shows its number rounded to four significant digits, where it is
//! read, and carries the exact text in `data-value`, written as
//! `t2spline run` writes it (serde_json's shortest round-trip form), so the
//! report and the result file agree to the last digit; `data-key` names its
//! place in the result file. Jobs of many control points show the first
//! [`MAX_TABLE_POINTS`] points; the downloads have all.

use std::fmt::Write as _;

use t2spline::job::{ControlPoints, Parameter, RunOutput};
use t2spline::Layer;

use crate::chart::svg::escape;
use crate::chart::ticks::significant;

/// The most control points a table lists.
pub const MAX_TABLE_POINTS: usize = 12;

/// A number as `t2spline run` prints it; `None` (an absent lower cut) as `null`.
#[must_use]
pub fn number_text(v: Option<f64>) -> String {
    v.map_or_else(
        || "null".to_owned(),
        |x| serde_json::Value::from(x).to_string(),
    )
}

/// A number rounded for reading: four significant digits, trailing zeros
/// dropped (`0.84`, `-1.235`, `1.2e-7`); `null` for an absent value.
#[must_use]
pub fn rounded(v: Option<f64>) -> String {
    let Some(x) = v else {
        return "null".to_owned();
    };
    let mag = if x == 0.0 || !x.is_finite() {
        0
    } else {
        x.abs().log10().floor() as i32
    };
    if !(-4..=6).contains(&mag) {
        let s = format!("{x:.3e}");
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = m.trim_end_matches('0').trim_end_matches('.');
        return format!("{m}e{e}");
    }
    significant(x, 4)
}

/// One table: its id, its caption, its header and static row heads, and the
/// keys of its changing cells in order.
#[derive(Debug)]
pub struct Table {
    /// Element id.
    pub id: &'static str,
    /// What it holds.
    pub caption: &'static str,
    /// Column titles.
    pub header: Vec<String>,
    /// Per row: the leading cells (point, coordinate) and the keys of the number cells.
    pub rows: Vec<(Vec<String>, Vec<String>)>,
    /// Control points not listed.
    pub left_out: usize,
}

const AXES: [&str; 3] = ["x", "y", "z"];

fn table(id: &'static str, caption: &'static str, header: &[&str]) -> Table {
    Table {
        id,
        caption,
        header: header.iter().map(|s| (*s).to_owned()).collect(),
        rows: Vec::new(),
        left_out: 0,
    }
}

/// The tables of a result, in report order.
#[must_use]
pub fn tables(r: &RunOutput) -> Vec<Table> {
    let n = r.control_points.crisp.len();
    let shown = n.min(MAX_TABLE_POINTS);
    let d = r.dimension;
    let mut cut = table(
        "table-alpha-cut",
        "Alpha-cut control points (control_points.alpha_cut, crisp)",
        &["point", "coord."],
    );
    cut.header.extend(
        Layer::ALL
            .iter()
            .map(|l| format!("{}′", l.name().replace('_', "."))),
    );
    let mut reduced = table(
        "table-type-reduced",
        "Type-reduced control points (type_reduced_left, crisp, type_reduced_right)",
        &["point", "coord.", "left", "crisp", "right"],
    );
    let mut defuzzified = table(
        "table-defuzzified",
        "Defuzzified control points (control_points.defuzzified)",
        &["point"],
    );
    defuzzified
        .header
        .extend(AXES[..d].iter().map(|a| (*a).to_owned()));
    // A surface's points are `[row][column]` in the result file.
    let net = r.control_points.crisp.grid();
    let point = |k: usize| match net {
        Some([_, nv]) => (
            format!("{}.{}", k / nv, k % nv),
            format!("({}, {})", k / nv, k % nv),
        ),
        None => (k.to_string(), k.to_string()),
    };
    for k in 0..shown {
        let (path, name) = point(k);
        let k = path;
        for (a, axis) in AXES[..d].iter().enumerate() {
            let heads = vec![name.clone(), (*axis).to_owned()];
            let cells = Layer::ALL
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
            vec![name],
            (0..d).map(|a| format!("defuzzified.{k}.{a}")).collect(),
        ));
    }
    for t in [&mut cut, &mut reduced, &mut defuzzified] {
        t.left_out = n - shown;
    }
    let (header, at): (&[&str], Vec<String>) = match r.error.max_at {
        Parameter::T(_) => (
            &["", "max", "max_at (t)", "rms"],
            vec!["error.max_at".into()],
        ),
        Parameter::Uv(_) => (
            &["", "max", "max_at (u)", "max_at (v)", "rms"],
            vec!["error.max_at.0".into(), "error.max_at.1".into()],
        ),
    };
    let mut distance = table("table-distance", "Distance (error)", header);
    let mut keys = vec!["error.max".to_owned()];
    keys.extend(at);
    keys.push("error.rms".into());
    distance.rows.push((vec!["distance".to_owned()], keys));
    vec![cut, reduced, defuzzified, distance]
}

/// The value at a cell key: `error.*` or a path into `control_points`.
#[must_use]
pub fn value(r: &RunOutput, key: &str) -> Option<f64> {
    let parts: Vec<&str> = key.split('.').collect();
    let cp = &r.control_points;
    let idx = |s: &str| s.parse::<usize>().ok();
    let net = cp.crisp.grid();
    let net_index = |i: &str, j: &str| Some(idx(i)? * net?[1] + idx(j)?);
    let at = |name: &str, k, a| point_value(cp, name, k, a);
    let cut = |layer: &str, k, a| cut_value(cp, layer, k, a);
    match parts.as_slice() {
        ["error", "max"] => Some(r.error.max),
        ["error", "max_at"] => r.error.max_at.t(),
        ["error", "max_at", c] => match r.error.max_at {
            Parameter::Uv(uv) => uv.get(idx(c)?).copied(),
            Parameter::T(_) => None,
        },
        ["error", "rms"] => Some(r.error.rms),
        [name, i, j, a] if net.is_some() => at(name, net_index(i, j)?, idx(a)?),
        ["alpha_cut", layer, i, j, a] => cut(layer, net_index(i, j)?, idx(a)?),
        [name, k, a] => at(name, idx(k)?, idx(a)?),
        ["alpha_cut", layer, k, a] => cut(layer, idx(k)?, idx(a)?),
        _ => None,
    }
}

/// Looks up `points.k.a` in `control_points` for [`value`].
fn point_value(cp: &ControlPoints, name: &str, k: usize, a: usize) -> Option<f64> {
    let points = match name {
        "crisp" => &cp.crisp,
        "type_reduced_left" => &cp.type_reduced_left,
        "type_reduced_right" => &cp.type_reduced_right,
        "defuzzified" => &cp.defuzzified,
        _ => return None,
    };
    points.coord(a).get(k).copied()
}

/// Looks up `alpha_cut.layer.k.a` in `control_points` for [`value`].
fn cut_value(cp: &ControlPoints, layer: &str, k: usize, a: usize) -> Option<f64> {
    let l = Layer::ALL.into_iter().find(|l| l.name() == layer)?;
    *cp.alpha_cut.get(l)?.coord(a).get(k)?
}

/// The exact and the rounded texts of a table's cells for one result, in
/// row order.
#[must_use]
pub fn cells(t: &Table, r: &RunOutput) -> (Vec<String>, Vec<String>) {
    t.rows
        .iter()
        .flat_map(|(_, keys)| keys.iter().map(|k| value(r, k)))
        .map(|v| (number_text(v), rounded(v)))
        .unzip()
}

/// The table as HTML with the texts of `r`, folded under its caption
/// (`open` when it lists every point of a small job).
#[must_use]
pub fn html(t: &Table, r: &RunOutput) -> String {
    let rows = t.rows.len();
    let open = if t.left_out == 0 && rows <= 3 * MAX_TABLE_POINTS {
        " open"
    } else {
        ""
    };
    let mut s = format!(
        "<details class=\"table\"{open}><summary>{}</summary>\n<div class=\"scroll\"><table id=\"{}\"><thead><tr>",
        escape(t.caption),
        t.id
    );
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
            let v = value(r, k);
            let absent = if v.is_none() { " class=\"absent\"" } else { "" };
            let _ = write!(
                s,
                "<td data-key=\"{k}\" data-value=\"{}\"{absent}>{}</td>",
                number_text(v),
                rounded(v)
            );
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody></table></div>\n");
    if t.left_out > 0 {
        let _ = writeln!(
            s,
            "<p class=\"note\">The first {MAX_TABLE_POINTS} control points; the other {} are in the downloads (result JSON).</p>",
            t.left_out
        );
    }
    s.push_str("</details>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_rounded_for_reading() {
        assert_eq!(rounded(Some(0.840_000_000_000_000_1)), "0.84");
        assert_eq!(rounded(Some(-1.234_56)), "-1.235");
        assert_eq!(rounded(Some(4.0)), "4");
        assert_eq!(rounded(Some(1234.567)), "1235");
        assert_eq!(rounded(Some(0.007_398_2)), "0.007398");
        assert_eq!(rounded(Some(1.2e-7)), "1.2e-7");
        assert_eq!(rounded(Some(3.0e12)), "3e12");
        assert_eq!(rounded(None), "null");
        assert_eq!(
            number_text(Some(0.840_000_000_000_000_1)),
            "0.8400000000000001"
        );
    }
}
