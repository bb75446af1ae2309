//! The report's data block: what the page's script swaps in at each frame
//! (the changing parts of the figures, the numbers of the bar and the
//! tables, the downloads), gathered into one JSON value that the page
//! embeds packed ([`super::pack`]).

use serde_json::{json, Value};
use t2spline::job::{Job, RunOutput};
use t2spline::Alpha;

use super::computed::Computed;
use super::file_stops::FileStops;
use super::frames::{frames, Frames, Strings};
use super::stops::Stops;
use super::tables::{self, number_text, rounded};
use super::terrain_frames::TerrainFrames;
use super::{downloads, page, reductions};
use crate::chart::scene::Figure;
use crate::error::Error;
use crate::figures::curve::distance_figure;

/// The data block and what the page's sections show of it at the start.
pub(super) struct DataBlock {
    /// The JSON the page embeds.
    pub json: Value,
    /// The changing figures (number, stages 2–4, distance against alpha;
    /// a terrain's width map and shoreline), each with its starting SVG.
    pub figures: Vec<Frames>,
    /// The tables of stages 2–4.
    pub tables: Vec<tables::Table>,
}

impl DataBlock {
    /// The data block of `job`'s report from its computed frames `c`.
    pub(super) fn build(
        job: &Job,
        start: Alpha,
        stops: &Stops,
        with_files: &FileStops,
        c: &Computed,
        terrain: &TerrainFrames,
    ) -> Result<DataBlock, Error> {
        let heights = job.model.heights();
        // The distance against alpha is the paper's: a frame per slider stop,
        // shown at the slider's stop whatever the reduction.
        let distance = distance_figure(job, start.get())?;
        let distances: Vec<Figure> = stops
            .alphas
            .iter()
            .map(|&a| with_alpha_rule(&distance, a))
            .collect();
        let probes = stops.probes(&heights);
        let mut all_probes = probes.clone();
        all_probes.extend(c.others.iter().map(|f| f.frame));
        let mut strings = Strings::default();
        let mut figs: Vec<Frames> = c
            .kinds
            .iter()
            .zip(["fn-", "s2-", "s3-", "s4-"])
            .map(|(list, prefix)| frames(list, c.initial, &all_probes, prefix, &mut strings))
            .collect();
        let mut da = frames(&distances, stops.initial, &probes, "da-", &mut strings);
        da.data["paper"] = json!(true);
        figs.push(da);
        // A terrain's width map and shoreline: a frame per slider stop,
        // shown at the slider's stop whatever the reduction (they do not
        // depend on it).
        if let TerrainFrames::Drawn {
            widths, shorelines, ..
        } = terrain
        {
            for (list, prefix) in [(widths, "ew-"), (shorelines, "sh-")] {
                let mut f = frames(list, stops.initial, &probes, prefix, &mut strings);
                f.data["paper"] = json!(true);
                figs.push(f);
            }
        }
        let table_defs = tables::tables(c.start_run()?);
        let stops_json: Vec<Value> = c
            .shown
            .iter()
            .zip(&c.runs)
            .map(|((a, _), r)| stop_json(a.get(), r, &heights, &table_defs))
            .collect();
        let json = json!({
            "initial": c.initial,
            "step": stops.step_text(),
            "reductions": reductions::json(&c.others),
            "stops": stops_json,
            "figures": figs.iter().map(|f| f.data.clone()).collect::<Vec<_>>(),
            "strings": strings.into_json(),
            "downloads": downloads::pack(&c.files),
            "files_at": with_files.index_json(&c.shown),
            "files_note": with_files.note(job),
        });
        Ok(DataBlock {
            json,
            figures: figs,
            tables: table_defs,
        })
    }
}

/// The distance figure with its alpha line at `alpha`.
fn with_alpha_rule(fig: &Figure, alpha: f64) -> Figure {
    let mut f = fig.clone();
    for p in &mut f.panels {
        for item in &mut p.items {
            if item.key == "alpha" {
                item.mark = crate::figures::curve::alpha_rule(alpha);
            }
        }
    }
    f
}

/// One frame's numbers: alpha (null when the reduction does not use it),
/// the reduction, regime, the distance, the table cells.
fn stop_json(a: f64, r: &RunOutput, heights: &[f64], defs: &[tables::Table]) -> Value {
    let pair = |v: f64| json!([number_text(Some(v)), rounded(Some(v))]);
    let cells: serde_json::Map<String, Value> = defs
        .iter()
        .map(|t| (t.id.to_owned(), json!(tables::cells(t, r))))
        .collect();
    let mut bar = serde_json::Map::new();
    bar.insert("m-max".into(), pair(r.error.max));
    for (id, v) in page::max_at_ids(r.error.max_at) {
        bar.insert(id.into(), pair(v));
    }
    bar.insert("m-rms".into(), pair(r.error.rms));
    let (alpha, shown) = if r.alpha_used {
        (json!(number_text(Some(a))), json!(rounded(Some(a))))
    } else {
        (Value::Null, json!("not used"))
    };
    json!({
        "alpha": alpha,
        "shown": shown,
        "reduction": r.type_reduction.name(),
        "regime": reductions::regime_text(r),
        "at_h": r.alpha_used && heights.contains(&a),
        "bar": bar,
        "cells": cells,
    })
}
