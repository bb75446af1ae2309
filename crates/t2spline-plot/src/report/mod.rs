//! The HTML report: one self-contained file (no network, no external scripts,
//! styles or fonts) with every figure, an alpha slider that updates the stage
//! figures and tables, tables of the control points at each stage, the distance,
//! and the job itself.
//!
//! The slider stops at alpha = 0, 0.01, …, 1 and also at every lower height h
//! and at the starting alpha. A selector switches the type reduction of
//! stages 3–4 (SPEC §10): the paper's has a frame per slider stop, each other
//! reduction one frame (it does not use alpha), all computed here. For every stop the numbers shown and the changing
//! parts of the figures are computed here, in Rust, by the same library calls
//! as `t2spline run --alpha A`, and embedded as JSON; the page's script only
//! swaps them in. Numbers are written as `run` writes them, so they agree to
//! the last digit.

mod frames;
mod reductions;
pub mod tables;

use std::fmt::Write as _;

use serde_json::{json, Value};
use t2spline::job::{Job, RunOutput, Spline};
use t2spline::{Alpha, Axis, Layer, TypeReduction};

use crate::figures::{
    number_figure, reductions_figure, stage1_figure, stage2_figure, stage3_figure, stage4_figure,
    sweep_figure, NumberChoice,
};
use crate::svg::{self, escape};
use crate::ticks::short;
use crate::{data, Error};
use frames::{frames, Strings};

/// The slider's regular step.
pub const STEP: f64 = 0.01;

/// The alphas the slider stops at: 0, 0.01, …, 1, every lower height and
/// `start`, ascending and without repeats.
///
/// # Examples
/// ```
/// let job = t2spline_io::read_job("../../examples/paper-alg-1-1.json".as_ref())?;
/// let stops = t2spline_plot::report::stops(&job, t2spline::Alpha::try_new(0.8)?);
/// assert_eq!(stops.len(), 101); // 0.6 and 0.8 are already on the grid
/// assert_eq!(stops[60], 0.6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn stops(job: &Job, start: Alpha) -> Vec<f64> {
    // i / 100 is the correctly rounded double nearest to the decimal, which is
    // what `--alpha 0.37` parses to.
    let mut v: Vec<f64> = (0..=100).map(|i| f64::from(i) / 100.0).collect();
    v.extend(job.model.heights());
    v.push(start.get());
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

/// Renders the report of `job` (whose file text is `job_text`) with the
/// slider at `start`.
///
/// # Errors
/// Only if the library cannot evaluate a curve where the result says the
/// distance is largest (never for a validated job).
pub fn render(job: &Job, job_text: &str, start: Alpha) -> Result<String, Error> {
    let alphas = stops(job, start);
    let heights = job.model.heights();
    // Frames 0..alphas.len(): the paper's reduction at every stop; then one
    // frame per other reduction, which does not use alpha (stage 2 at 0).
    let reduction_frames = reductions::frames(alphas.len());
    let initial = reductions::initial_frame(&reduction_frames, job.type_reduction)
        .unwrap_or_else(|| alphas.iter().position(|&a| a == start.get()).unwrap_or(0));
    let mut results = Vec::with_capacity(alphas.len() + reduction_frames.len());
    for &a in &alphas {
        // Stops lie in [0, 1].
        let alpha = Alpha::try_new(a)?;
        let paper = Job {
            type_reduction: TypeReduction::Paper,
            ..job.clone()
        };
        results.push((alpha, data::compute(&paper, alpha)?, paper));
    }
    for frame in &reduction_frames {
        let other = Job {
            type_reduction: frame.method,
            ..job.clone()
        };
        results.push((start, data::compute(&other, start)?, other));
    }
    let choice = NumberChoice::default();
    let mut strings = Strings::default();
    let mut number = Vec::new();
    let mut stage2 = Vec::new();
    let mut stage3 = Vec::new();
    let mut stage4 = Vec::new();
    for (alpha, r, job) in &results {
        number.push(number_figure(job, *alpha, choice)?);
        stage2.push(stage2_figure(r, &heights));
        stage3.push(stage3_figure(r, &heights));
        stage4.push(stage4_figure(job, r, false)?);
    }
    let figs = [
        frames(&number, initial, "fn-", &mut strings),
        frames(&stage2, initial, "s2-", &mut strings),
        frames(&stage3, initial, "s3-", &mut strings),
        frames(&stage4, initial, "s4-", &mut strings),
    ];
    let start_result = &results[initial].1;
    let table_defs = tables::tables(start_result);
    let stops_json: Vec<Value> = results
        .iter()
        .map(|(a, r, _)| {
            let cells: serde_json::Map<String, Value> = table_defs
                .iter()
                .map(|t| (t.id.to_owned(), json!(tables::cells(t, r))))
                .collect();
            let (alpha, regime) = if r.alpha_used {
                (tables::number_text(Some(a.get())), json!(r.regime))
            } else {
                ("not used".to_owned(), json!(reductions::regime_text(r)))
            };
            json!({
                "alpha": alpha,
                "regime": regime,
                "at_h": r.alpha_used && heights.contains(&a.get()),
                "cells": cells,
            })
        })
        .collect();
    let data_block = json!({
        "initial": initial,
        "reductions": reductions::json(&reduction_frames),
        "stops": stops_json,
        "figures": figs.iter().map(|f| f.data.clone()).collect::<Vec<_>>(),
        "strings": strings.into_json(),
    });
    let stage1 = svg::render(&stage1_figure(start_result));
    let sweep = svg::render(&sweep_figure(job)?);
    let compared = svg::render(&reductions_figure(job, start)?);
    let mut page = Page::default();
    page.header(job, start_result, &heights);
    let paper_stop = alphas.iter().position(|&a| a == start.get()).unwrap_or(0);
    page.controls(
        &alphas,
        paper_stop,
        &heights,
        &reductions::selector(job.type_reduction),
    );
    page.section(
        "number",
        "One fuzzy number (paper Figs. 3.1, 4.1–4.4)",
        &figs[0].svg,
        "Coordinate x of control point 0: its upper (UMF), primary and lower (LMF) membership functions, the cut at α and the type-reduced triangle with its centroid. Other numbers: t2spline plot --point I --axis x|y|z.",
        &[],
    );
    page.section(
        "stage1",
        "Stage 1: the fuzzy control points and layer curves (Fig. 5.1)",
        &stage1,
        "Does not depend on α.",
        &[fuzzy_points_table(job, start_result)],
    );
    let table_html: Vec<String> = table_defs
        .iter()
        .map(|t| tables::html(t, start_result))
        .collect();
    page.section(
        "stage2",
        "Stage 2: alpha-cut (Fig. 5.2)",
        &figs[1].svg,
        "Cut ends of every number at α; a lower end is null above its height h.",
        &[captioned(
            "Alpha-cut control points (control_points.alpha_cut, crisp)",
            &table_html[0],
        )],
    );
    page.section(
        "stage3",
        "Stage 3: type reduction (Fig. 5.3)",
        &figs[2].svg,
        "Each control point becomes a type-1 triangle (left, crisp, right); with the centroid or alpha-planes, left and right are the centroid interval [c_l, c_r], which need not contain crisp; with Nie–Tan they are its one value.",
        &[captioned(
            "Type-reduced control points (type_reduced_left, crisp, type_reduced_right)",
            &table_html[1],
        )],
    );
    page.section(
        "stage4",
        "Stage 4: defuzzification and distance (Fig. 5.4)",
        &figs[3].svg,
        "The distance between the crisp and the defuzzified curve at equal t, over the whole domain.",
        &[
            captioned("Defuzzified control points (control_points.defuzzified)", &table_html[2]),
            captioned("Distance between the curves (error)", &table_html[3]),
        ],
    );
    page.section(
        "sweep",
        "The solution as α varies",
        &sweep,
        "Defuzzified curves of the paper's reduction for α = 0, 0.1, …, 1; does not depend on the slider.",
        &[],
    );
    page.section(
        "reductions",
        "The type reductions compared (SPEC §10)",
        &compared,
        &format!(
            "The solution curve of every type reduction and its distance to the crisp curve; the paper's at the starting α = {}. Each equals t2spline run --type-reduction NAME.",
            short(start.get(), 6)
        ),
        &[],
    );
    page.job(job_text);
    page.finish(&data_block);
    Ok(page.html)
}

fn captioned(caption: &str, table: &str) -> String {
    table.replacen(
        "<thead>",
        &format!("<caption>{}</caption><thead>", escape(caption)),
        1,
    )
}

/// The stage-1 table: every number's seven values and height.
fn fuzzy_points_table(job: &Job, r: &RunOutput) -> String {
    let mut s = String::from("<table id=\"table-fuzzy\"><caption>Fuzzy control points (the job)</caption><thead><tr><th>point</th><th>coord.</th><th>weight</th>");
    for l in Layer::ALL {
        let _ = write!(s, "<th>{}</th>", l.name().replace('_', "."));
    }
    s.push_str("<th>h</th></tr></thead><tbody>\n");
    for k in 0..r.control_points.crisp.len() {
        for (a, axis) in Axis::first::<3>().iter().take(r.dimension).enumerate() {
            let _ = write!(
                s,
                "<tr><th scope=\"row\">{k}</th><th scope=\"row\">{}</th><td>{}</td>",
                axis.name(),
                tables::number_text(r.spline.weights().get(k).copied())
            );
            for l in Layer::ALL {
                let points = r
                    .control_points
                    .layers
                    .get(l)
                    .unwrap_or(&r.control_points.crisp);
                let _ = write!(
                    s,
                    "<td>{}</td>",
                    tables::number_text(points.coord(a).get(k).copied())
                );
            }
            let h = data::number(&job.model, k, *axis)
                .ok()
                .map(|x| x.height().get());
            let _ = writeln!(s, "<td>{}</td></tr>", tables::number_text(h));
        }
    }
    s.push_str("</tbody></table>\n");
    s
}

/// The page being written.
#[derive(Debug, Default)]
struct Page {
    html: String,
}

impl Page {
    fn header(&mut self, job: &Job, r: &RunOutput, heights: &[f64]) {
        let title = "Normal type-2 fuzzy rational B-spline curve";
        let curve = match &r.spline {
            Spline::Curve {
                order,
                degree,
                knots,
                ..
            } => (*order, *degree, knots.as_slice()),
            Spline::Surface { .. } => (0, 0, &[][..]),
        };
        let _ = write!(
            self.html,
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>t2spline report: {}</title>\n<style>\n{}</style>\n</head>\n<body>\n<header>\n<h1>{title}</h1>\n",
            escape(job.description.as_deref().unwrap_or(title)),
            include_str!("report.css")
        );
        if let Some(d) = &job.description {
            let _ = writeln!(self.html, "<p>{}</p>", escape(d));
        }
        let _ = writeln!(
            self.html,
            "<p class=\"facts\">{}-D, {} control points, order {} (degree {}), weights ({}), knots ({}), lower heights h: {}.</p>\n</header>",
            r.dimension,
            r.control_points.crisp.len(),
            curve.0,
            curve.1,
            join(&r.spline.weights()),
            join(curve.2),
            join(heights)
        );
    }

    fn controls(&mut self, alphas: &[f64], initial: usize, heights: &[f64], selector: &str) {
        let _ = write!(
            self.html,
            "<nav id=\"controls\" aria-label=\"type reduction and alpha\">\n<div class=\"row\">\n{selector}<label for=\"alpha\">α</label>\n<input type=\"range\" id=\"alpha\" min=\"0\" max=\"{}\" step=\"1\" value=\"{initial}\">\n<output id=\"alpha-value\" for=\"alpha\">{}</output>\n<span id=\"regime\"></span>\n",
            alphas.len() - 1,
            tables::number_text(Some(alphas[initial]))
        );
        for h in heights {
            if let Some(k) = alphas.iter().position(|a| a == h) {
                let _ = writeln!(
                    self.html,
                    "<button type=\"button\" data-stop=\"{k}\">go to α = h = {}</button>",
                    short(*h, 6)
                );
            }
        }
        let _ = writeln!(
            self.html,
            "</div>\n<p class=\"note\">Stops at α = 0, 0.01, …, 1 and at every h. At α = h type reduction switches from averaging three cut ends to two (SPEC §3), so the solution jumps between α = h and the next stop; that is the paper's method. Every number shown equals <code>t2spline run --alpha A</code> at the shown α. Only the paper's type reduction uses α: with another one selected the slider rests, stage 2 is cut at α = 0 (the whole footprint) and every number equals <code>t2spline run --type-reduction NAME</code>.</p>\n</nav>\n<main>"
        );
    }

    fn section(&mut self, id: &str, title: &str, svg: &str, caption: &str, tables: &[String]) {
        let _ = write!(
            self.html,
            "<section id=\"{id}\">\n<h2>{}</h2>\n<figure>\n{svg}<figcaption>{}</figcaption>\n</figure>\n",
            escape(title),
            escape(caption)
        );
        if !tables.is_empty() {
            self.html.push_str("<div class=\"tables\">\n");
            for t in tables {
                self.html.push_str(t);
            }
            self.html.push_str("</div>\n");
        }
        self.html.push_str("</section>\n");
    }

    fn job(&mut self, text: &str) {
        let _ = write!(
            self.html,
            "<section id=\"job\">\n<h2>The job</h2>\n<pre>{}</pre>\n</section>\n</main>\n",
            escape(text)
        );
    }

    fn finish(&mut self, data: &Value) {
        // "</" may not appear inside a script element; "<\/" is the same JSON.
        let json = data.to_string().replace("</", "<\\/");
        let _ = write!(
            self.html,
            "<footer>Made by t2spline {}. Self-contained: no network, scripts or fonts are loaded.</footer>\n<script type=\"application/json\" id=\"report-data\">{json}</script>\n<script>\n{}</script>\n</body>\n</html>\n",
            env!("CARGO_PKG_VERSION"),
            include_str!("report.js")
        );
    }
}

fn join(v: &[f64]) -> String {
    v.iter()
        .map(|x| short(*x, 6))
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> (Job, String) {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/paper-alg-1-1.json");
        let text = std::fs::read_to_string(&path).unwrap();
        (t2spline_io::parse_job(&text, "example").unwrap(), text)
    }

    #[test]
    fn table_cells_are_the_run_result_at_the_job_sampling() {
        let (job, _) = example();
        for a in stops(&job, Alpha::try_new(0.8).unwrap()) {
            let alpha = Alpha::try_new(a).unwrap();
            let figure_result = data::compute(&job, alpha).unwrap();
            let run_result = job
                .run(&t2spline::job::Settings {
                    alpha,
                    type_reduction: t2spline::TypeReduction::Paper,
                    unused_alpha: None,
                    samples: job.samples,
                    derivatives: None,
                })
                .unwrap();
            assert_same_tables(&figure_result, &run_result, &format!("alpha {a}"));
        }
    }

    /// The report's table cells of `shown` are those of `run`.
    fn assert_same_tables(shown: &RunOutput, run: &RunOutput, what: &str) {
        for t in tables::tables(run) {
            assert_eq!(
                tables::cells(&t, shown),
                tables::cells(&t, run),
                "{what}, {}",
                t.id
            );
        }
    }

    #[test]
    fn the_report_marks_h_and_starts_at_the_given_alpha() {
        let (job, text) = example();
        let html = render(&job, &text, Alpha::try_new(0.37).unwrap()).unwrap();
        assert!(html.contains("go to α = h = 0.6"));
        assert!(html.contains("<output id=\"alpha-value\" for=\"alpha\">0.37</output>"));
        assert!(html.contains("value=\"37\""), "0.37 is stop 37");
        let start = html.find("id=\"report-data\">").unwrap();
        let end = html[start..].find("</script>").unwrap() + start;
        let data: Value =
            serde_json::from_str(&html[start + 17..end].replace("<\\/", "</")).unwrap();
        let stops = data["stops"].as_array().unwrap();
        // 101 slider stops of the paper's reduction, one frame for each other.
        assert_eq!(stops.len(), 104);
        assert_eq!(stops[60]["at_h"], json!(true));
        assert_eq!(stops[60]["regime"], json!("alpha <= h"));
        assert_eq!(stops[61]["regime"], json!("alpha > h"));
        assert_eq!(stops[101]["alpha"], json!("not used"));
        assert_eq!(
            data["reductions"],
            json!([
                {"name": "paper", "frame": null},
                {"name": "centroid", "frame": 101},
                {"name": "nie-tan", "frame": 102},
                {"name": "alpha-planes", "frame": 103},
            ])
        );
        assert_eq!(data["initial"], json!(37));
        for f in data["figures"].as_array().unwrap() {
            assert_eq!(f["frames"].as_array().unwrap().len(), 104);
        }
        assert_eq!(data["figures"].as_array().unwrap().len(), 4);
        assert!(html.contains("<option value=\"paper\" selected>"));
        // A job of another reduction opens on its frame.
        let job = Job {
            type_reduction: TypeReduction::NieTan,
            ..job
        };
        let html = render(&job, &text, Alpha::try_new(0.37).unwrap()).unwrap();
        assert!(html.contains("<option value=\"nie-tan\" selected>"));
        assert!(html.contains("\"initial\":102"));
    }

    #[test]
    fn every_reduction_is_the_run_result() {
        let (job, _) = example();
        let alpha = Alpha::try_new(0.8).unwrap();
        for method in TypeReduction::ALL {
            let job = Job {
                type_reduction: method,
                ..job.clone()
            };
            let figure_result = data::compute(&job, alpha).unwrap();
            let settings = job
                .settings(&t2spline::job::Overrides {
                    alpha: Some(0.8),
                    ..Default::default()
                })
                .unwrap();
            let run_result = job.run(&settings).unwrap();
            assert_eq!(figure_result.type_reduction, method);
            assert_same_tables(&figure_result, &run_result, method.name());
        }
    }
}
