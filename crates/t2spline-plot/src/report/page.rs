//! The report's HTML: a header with the job's facts and a table of contents,
//! the sticky bar (type-reduction selector, alpha slider, a number field, the
//! distance, the result download), one section per figure with its downloads and tables, the job,
//! and the packed data block with the script.

use std::fmt::Write as _;

use t2spline::job::{Parameter, RunOutput, Spline};

use super::stops::Stops;
use super::tables::{number_text, rounded};
use crate::chart::svg::escape;
use crate::chart::ticks::short;

/// A section of the report: its id, heading, figure, caption, the files
/// offered beside the figure and the tables under it.
#[derive(Debug)]
pub struct Section<'a> {
    /// Element id (also the link target).
    pub id: &'static str,
    /// Its heading.
    pub title: &'static str,
    /// The figure's SVG.
    pub svg: &'a str,
    /// The figure's file stem (for SVG and PNG downloads).
    pub figure: &'static str,
    /// What the figure shows.
    pub caption: &'a str,
    /// A CSV file of this stage, if any.
    pub csv: Option<&'static str>,
    /// Tables as HTML.
    pub tables: Vec<String>,
}

/// The page being written.
#[derive(Debug, Default)]
pub struct Page {
    /// The HTML so far.
    pub html: String,
}

/// A list of numbers for the facts line: all when few, else their count and range.
fn list(v: &[f64], what: &str) -> String {
    if v.len() <= 12 {
        let items: Vec<String> = v.iter().map(|x| short(*x, 6)).collect();
        format!("{what} ({})", items.join(", "))
    } else {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        format!(
            "{} {what} from {} to {}",
            v.len(),
            short(lo, 6),
            short(hi, 6)
        )
    }
}

/// A number shown rounded, with its exact text in `data-value`.
fn metric(id: &str, v: f64) -> String {
    format!(
        "<b id=\"{id}\" data-value=\"{}\">{}</b>",
        number_text(Some(v)),
        rounded(Some(v))
    )
}

/// Where the distance is largest: `t = …`, or `(u, v) = (…, …)` (the ids
/// of [`max_at_ids`]).
fn max_at(r: &RunOutput) -> String {
    let ids = max_at_ids(r.error.max_at);
    let values: Vec<String> = ids.iter().map(|(id, v)| metric(id, *v)).collect();
    match values.as_slice() {
        [t] => format!("t = {t}"),
        _ => format!("(u, v) = ({})", values.join(", ")),
    }
}

/// The sticky bar's ids of `max_at` with their values: `m-max-at` for `t`
/// (or `u`), `m-max-at-v` for `v`.
#[must_use]
pub fn max_at_ids(at: Parameter) -> Vec<(&'static str, f64)> {
    match at {
        Parameter::T(t) => vec![("m-max-at", t)],
        Parameter::Uv([u, v]) => vec![("m-max-at", u), ("m-max-at-v", v)],
    }
}

impl Page {
    /// The document head and the header: title, description, facts, contents.
    pub fn header(
        &mut self,
        description: Option<&str>,
        r: &RunOutput,
        heights: &[f64],
        sections: &[(&str, &str)],
    ) {
        let title = match r.spline {
            Spline::Curve { .. } => "Normal type-2 fuzzy rational B-spline curve",
            Spline::Surface { .. } => "Normal type-2 fuzzy rational B-spline surface",
        };
        let _ = write!(
            self.html,
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>t2spline report: {}</title>\n<style>\n{}</style>\n</head>\n<body>\n<header>\n<h1>{title}</h1>\n",
            escape(description.unwrap_or(title)),
            include_str!("report.css")
        );
        if let Some(d) = description {
            let _ = writeln!(self.html, "<p>{}</p>", escape(d));
        }
        let _ = writeln!(
            self.html,
            "<p class=\"facts\">{}-D, {} control points, order {} (degree {}), {}, {}, lower heights h: {}.</p>",
            r.dimension,
            r.control_points.crisp.len(),
            crate::data::curve_spline(r).order,
            crate::data::curve_spline(r).degree,
            list(crate::data::curve_spline(r).weights, "weights"),
            list(crate::data::curve_spline(r).knots, "knots"),
            heights.iter().map(|h| short(*h, 6)).collect::<Vec<_>>().join(", ")
        );
        self.html
            .push_str("<nav class=\"toc\" aria-label=\"contents\">");
        for (k, (id, name)) in sections.iter().enumerate() {
            let sep = if k > 0 { " · " } else { "" };
            let _ = write!(self.html, "{sep}<a href=\"#{id}\">{}</a>", escape(name));
        }
        self.html.push_str("</nav>\n</header>\n");
    }

    /// The sticky bar: the type-reduction selector, slider at the start's
    /// stop, number field, regime, jumps to each h, the distance of the
    /// starting result `r` and the result's download.
    pub fn controls(
        &mut self,
        stops: &Stops,
        heights: &[f64],
        r: &RunOutput,
        selector: &str,
        files_note: Option<&str>,
    ) {
        let (alphas, initial) = (&stops.alphas, stops.initial);
        let a = number_text(Some(alphas[initial]));
        // A reduction that does not use alpha starts on its own frame.
        let (shown, stamp) = if r.alpha_used {
            (rounded(Some(alphas[initial])), format!("alpha-{a}"))
        } else {
            ("not used".to_owned(), r.type_reduction.name().to_owned())
        };
        let _ = write!(
            self.html,
            "<div id=\"controls\" role=\"region\" aria-label=\"type reduction and alpha\">\n<div class=\"row\">\n{selector}<label for=\"alpha\">α</label>\n<input type=\"range\" id=\"alpha\" min=\"0\" max=\"{}\" step=\"1\" value=\"{initial}\" disabled>\n<input type=\"number\" id=\"alpha-field\" min=\"0\" max=\"1\" step=\"any\" value=\"{a}\" aria-label=\"alpha value\" disabled>\n<output id=\"alpha-value\" for=\"alpha\" data-value=\"{a}\" data-stamp=\"{stamp}\">{shown}</output>\n<span id=\"regime\">{}</span>\n",
            alphas.len() - 1,
            escape(&super::reductions::regime_text(r))
        );
        for h in heights.iter().take(6) {
            if let Some(k) = alphas.iter().position(|a| a == h) {
                let _ = writeln!(
                    self.html,
                    "<button type=\"button\" data-stop=\"{k}\">α = h = {}</button>",
                    short(*h, 6)
                );
            }
        }
        let e = &r.error;
        let _ = write!(
            self.html,
            "</div>\n<div class=\"row\">\n<span class=\"metrics\">max distance {} at {}, rms {}</span>\n<span class=\"downloads\">result shown: <button type=\"button\" class=\"dl\" data-file=\"result.json\">JSON</button></span>\n</div>\n<p class=\"note\" id=\"alpha-note\" aria-live=\"polite\">Stops at α = 0, {}, …, 1 and at every h. At α = h type reduction switches from averaging three cut ends to two (docs/method.md §3), so the solution jumps just above h; that is the paper's method. Every number equals <code>t2spline run --alpha A</code> at the shown α (rounded where shown; exact in the downloads). Only the paper's type reduction uses α: with another one selected the slider rests, stage 2 is cut at α = 0 (the whole footprint) and every number equals <code>t2spline run --type-reduction NAME</code>.</p>\n",
            metric("m-max", e.max),
            max_at(r),
            metric("m-rms", e.rms),
            stops.step_text(),
        );
        if let Some(note) = files_note {
            let _ = writeln!(self.html, "<p class=\"note\" id=\"files-note\">{note}</p>");
        }
        self.html.push_str("</div>\n<main>\n");
    }

    /// A section with its figure, downloads and tables.
    pub fn section(&mut self, s: &Section<'_>) {
        let _ = write!(
            self.html,
            "<section id=\"{}\">\n<h2>{}</h2>\n<figure data-name=\"{}\">\n{}<figcaption>{} <span class=\"downloads\">Download: <button type=\"button\" class=\"dl\" data-svg=\"{}\">SVG</button> <button type=\"button\" class=\"dl\" data-png=\"{}\">PNG</button>",
            s.id,
            escape(s.title),
            s.figure,
            s.svg,
            escape(s.caption),
            s.figure,
            s.figure
        );
        if let Some(csv) = s.csv {
            let _ = write!(
                self.html,
                " <button type=\"button\" class=\"dl\" data-file=\"{csv}\">CSV</button>"
            );
        }
        self.html.push_str("</span></figcaption>\n</figure>\n");
        if !s.tables.is_empty() {
            self.html.push_str("<div class=\"tables\">\n");
            for t in &s.tables {
                self.html.push_str(t);
            }
            self.html.push_str("</div>\n");
        }
        self.html.push_str("</section>\n");
    }

    /// A section without a figure: its heading and a note saying why.
    pub fn note_section(&mut self, id: &str, title: &str, note: &str) {
        let _ = write!(
            self.html,
            "<section id=\"{id}\">\n<h2>{}</h2>\n<p class=\"note\">{}</p>\n</section>\n",
            escape(title),
            escape(note)
        );
    }

    /// The job file's text (its first `MAX_JOB_TEXT` bytes).
    pub fn job(&mut self, text: &str) {
        const MAX_JOB_TEXT: usize = 200_000;
        let shown = if text.len() > MAX_JOB_TEXT {
            let mut end = MAX_JOB_TEXT;
            while !text.is_char_boundary(end) {
                end -= 1;
            }
            format!("{}\n… ({} more bytes)", &text[..end], text.len() - end)
        } else {
            text.to_owned()
        };
        let open = if text.lines().count() <= 60 {
            " open"
        } else {
            ""
        };
        let _ = write!(
            self.html,
            "<section id=\"job\">\n<h2>The job</h2>\n<details{open}><summary>The job file ({} bytes)</summary>\n<pre>{}</pre>\n</details>\n</section>\n</main>\n",
            text.len(),
            escape(&shown)
        );
    }

    /// The footer, the packed data block and the script.
    pub fn finish(&mut self, packed: &str) {
        let _ = write!(
            self.html,
            "<footer>Made by t2spline {}. Self-contained: no network, scripts or fonts are loaded.</footer>\n<script type=\"application/octet-stream\" id=\"report-data\">{packed}</script>\n<script>\n{}</script>\n</body>\n</html>\n",
            env!("CARGO_PKG_VERSION"),
            include_str!("report.js")
        );
    }
}
