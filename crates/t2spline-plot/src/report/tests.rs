use super::budget::file_samples;
use super::downloads::{files_of, unpack};
use super::*;
use base64::Engine as _;
use serde_json::{json, Value};
use t2spline::job::RunOutput;
use t2spline::job::Samples;
use t2spline::TypeReduction;

use crate::data;

fn example() -> (Job, String) {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json");
    let text = std::fs::read_to_string(&path).unwrap();
    (t2spline_io::parse_job(&text, "example").unwrap(), text)
}

/// The report of `job` with the slider starting at 0.37.
fn render_at_037(job: &Job, text: &str) -> String {
    render(
        job,
        text,
        Alpha::try_new(0.37).unwrap(),
        &FigureOptions::default(),
    )
    .unwrap()
}

/// The report's data block, unpacked.
fn data_block(html: &str) -> Value {
    let start = html.find("id=\"report-data\">").unwrap() + 17;
    let end = html[start..].find("</script>").unwrap() + start;
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(html[start..end].trim())
        .unwrap();
    let json = miniz_oxide::inflate::decompress_to_vec_zlib(&bytes).unwrap();
    serde_json::from_slice(&json).unwrap()
}

/// The result of `t2spline run --alpha A --type-reduction M` on `job`,
/// through the core's settings (not the report's own path).
fn run(job: &Job, alpha: f64, method: TypeReduction) -> RunOutput {
    let settings = job
        .settings(&t2spline::job::Overrides {
            alpha: Some(alpha),
            type_reduction: Some(method),
            ..Default::default()
        })
        .unwrap();
    job.run(&settings).unwrap()
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
fn table_cells_are_the_run_result_at_the_job_sampling() {
    let (job, _) = example();
    for a in Stops::new(&job, Alpha::try_new(0.8).unwrap(), 100).alphas {
        let alpha = Alpha::try_new(a).unwrap();
        let figure_result = data::compute(&job, alpha).unwrap();
        let run_result = run(&job, a, TypeReduction::Paper);
        assert_same_tables(&figure_result, &run_result, &format!("alpha {a}"));
    }
}

#[test]
fn every_reduction_is_the_run_result() {
    let (job, _) = example();
    let alpha = Alpha::try_new(0.8).unwrap();
    for method in TypeReduction::ALL {
        let figure_result = data::compute_with(&job, alpha, method).unwrap();
        let run_result = run(&job, 0.8, method);
        assert_eq!(figure_result.type_reduction, method);
        assert_same_tables(&figure_result, &run_result, method.name());
    }
}

/// A stop whose files the report leaves out shows the numbers of the run its
/// figures were drawn from: for surfaces too they are those of the run at
/// the job's own samples.
#[test]
fn surface_stops_show_the_run_result_at_the_job_sampling() {
    for name in ["fuzzy-terrain.json", "fuzzy-cylinder.json"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples")
            .join(name);
        let text = std::fs::read_to_string(&path).unwrap();
        let job = t2spline_io::parse_job(&text, name).unwrap();
        for a in [0.0, 0.35, 1.0] {
            let alpha = Alpha::try_new(a).unwrap();
            for method in TypeReduction::ALL {
                let figure_result =
                    data::compute_within(&job, alpha, method, data::REPORT_SURFACE_GRID).unwrap();
                let run_result = run(&job, a, method);
                assert_ne!(
                    figure_result.samples.crisp.len(),
                    run_result.samples.crisp.len(),
                    "{name}: the figures are sampled otherwise than the job"
                );
                assert_same_tables(
                    &figure_result,
                    &run_result,
                    &format!("{name} {a} {method:?}"),
                );
            }
        }
    }
}

#[test]
fn the_report_marks_h_starts_at_the_given_alpha_and_carries_run_s_files() {
    let (job, text) = example();
    let html = render_at_037(&job, &text);
    assert!(html.contains("α = h = 0.6"));
    assert!(html.contains("data-value=\"0.37\" data-stamp=\"alpha-0.37\">0.37</output>"));
    assert!(html.contains("value=\"37\""), "0.37 is stop 37");
    let data = data_block(&html);
    let stops = data["stops"].as_array().unwrap();
    // 101 slider stops of the paper's reduction, one frame for each other.
    assert_eq!(stops.len(), 104, "a small job gets every 0.01");
    assert_eq!(stops[60]["at_h"], json!(true));
    assert_eq!(stops[60]["regime"], json!("alpha <= h"));
    assert_eq!(stops[61]["regime"], json!("alpha > h"));
    assert_eq!(stops[101]["alpha"], Value::Null);
    assert_eq!(stops[101]["shown"], json!("not used"));
    assert_eq!(stops[101]["reduction"], json!("centroid"));
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
    let figures = data["figures"].as_array().unwrap();
    assert_eq!(figures.len(), 5);
    for f in &figures[..4] {
        assert_eq!(
            f["frames"].as_array().unwrap().len(),
            104,
            "{}",
            f["prefix"]
        );
    }
    // The distance against alpha is the paper's: a frame per slider stop.
    assert_eq!(figures[4]["frames"].as_array().unwrap().len(), 101);
    assert_eq!(figures[4]["paper"], json!(true));
    assert!(html.contains("<option value=\"paper\" selected>"));
    // Every download at every frame is the bytes run writes.
    let downloads = &data["downloads"];
    let frames = [
        (0, 0.0, TypeReduction::Paper),
        (37, 0.37, TypeReduction::Paper),
        (60, 0.6, TypeReduction::Paper),
        (61, 0.61, TypeReduction::Paper),
        (100, 1.0, TypeReduction::Paper),
        (101, 0.37, TypeReduction::Centroid),
        (102, 0.37, TypeReduction::NieTan),
        (103, 0.37, TypeReduction::AlphaPlanes),
    ];
    for (k, a, method) in frames {
        if method == TypeReduction::Paper {
            let shown: f64 = stops[k]["alpha"].as_str().unwrap().parse().unwrap();
            assert_eq!(shown, a, "stop {k}");
        }
        let files = files_of(&run(&job, a, method)).unwrap();
        assert_eq!(files.len(), downloads["files"].as_array().unwrap().len());
        for (name, text) in &files {
            assert_eq!(
                unpack(downloads, name, k).as_deref(),
                Some(text.as_str()),
                "frame {k}: {name}"
            );
        }
    }
}

#[test]
fn a_job_of_another_reduction_opens_on_its_frame() {
    let (job, text) = example();
    let job = Job {
        type_reduction: TypeReduction::NieTan,
        ..job
    };
    let html = render_at_037(&job, &text);
    assert!(html.contains("<option value=\"nie-tan\" selected>"));
    assert!(html.contains("data-stamp=\"nie-tan\">not used</output>"));
    assert!(
        html.contains("value=\"37\""),
        "the slider rests at the start"
    );
    let data = data_block(&html);
    assert_eq!(data["initial"], json!(102));
    assert_eq!(data["stops"][102]["reduction"], json!("nie-tan"));
}

/// The downloads of frame `k` (null where the frame carries none).
fn frame_file(data: &Value, name: &str, k: usize) -> Option<String> {
    let at = data["files_at"][k].as_u64()?;
    unpack(&data["downloads"], name, usize::try_from(at).unwrap())
}

#[test]
fn a_finely_sampled_curve_carries_thinned_files_and_says_so() {
    // At 30 000 samples the files of every stop took 2.9 GB, and at 100 000
    // the report ran out of memory. The report never runs the job at its own
    // samples now: this one, at the most `validate` accepts, costs what a
    // job of 1001 samples costs.
    let (job, text) = example();
    let job = Job {
        samples: Samples::Along(1_000_000),
        ..job
    };
    let html = render_at_037(&job, &text);
    assert!(html.len() < 2 * DATA_BUDGET, "{} bytes", html.len());
    assert!(html.contains(
        "<p class=\"note\" id=\"files-note\">The job samples 1000000; to keep the report small its result files (JSON, CSV) are sampled at 1001, the most a report carries: they are the bytes of <code>t2spline run JOB --samples 1001 --alpha A</code>. <code>t2spline run JOB</code> gives the full result at the job's samples."
    ));
    let data = data_block(&html);
    let initial = usize::try_from(data["initial"].as_u64().unwrap()).unwrap();
    let thinned = Job {
        samples: Samples::Along(MAX_FILE_SAMPLES),
        ..job.clone()
    };
    for (name, file) in files_of(&run(&thinned, 0.37, TypeReduction::Paper)).unwrap() {
        assert_eq!(
            frame_file(&data, &name, initial).as_deref(),
            Some(file.as_str()),
            "{name}"
        );
    }
    let result: Value =
        serde_json::from_str(&frame_file(&data, "result.json", initial).unwrap()).unwrap();
    assert_eq!(result["curves"]["params"].as_array().unwrap().len(), 1001);
}

#[test]
fn a_job_within_the_limit_carries_its_own_samples_without_a_note() {
    let (job, text) = example();
    let job = Job {
        samples: Samples::Along(MAX_FILE_SAMPLES),
        ..job
    };
    assert_eq!(file_samples(job.samples), job.samples);
    let html = render_at_037(&job, &text);
    assert!(!html.contains("files-note"));
    let data = data_block(&html);
    let initial = usize::try_from(data["initial"].as_u64().unwrap()).unwrap();
    let result: Value =
        serde_json::from_str(&frame_file(&data, "result.json", initial).unwrap()).unwrap();
    assert_eq!(result["curves"]["params"].as_array().unwrap().len(), 1001);
}

#[test]
fn a_finely_sampled_surface_is_bounded_and_says_so() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fuzzy-terrain.json");
    let text = std::fs::read_to_string(&path).unwrap();
    let job = t2spline_io::parse_job(&text, "terrain").unwrap();
    assert_eq!(
        file_samples(Samples::Grid([1000, 40])),
        Samples::Grid([101, 40])
    );
    let job = Job {
        samples: Samples::Grid([1000, 1000]),
        ..job
    };
    let html = render_at_037(&job, &text);
    assert!(html.len() < 2 * DATA_BUDGET, "{} bytes", html.len());
    assert!(html.contains(
        "The job samples 1000 × 1000; to keep the report small its result files (JSON, CSV) are sampled at 101 × 101, the most a report carries: they are the bytes of <code>t2spline run JOB --samples 101,101 --alpha A</code>."
    ));
    let data = data_block(&html);
    // One stop's files at 101 × 101 would take most of the budget: left
    // out, and the note says at which samples.
    let note = data["files_note"].as_str().unwrap();
    assert!(
        note.starts_with("The result files are left out of this report: even at 101 × 101 samples they would take "),
        "{note}"
    );
    assert!(data["files_at"]
        .as_array()
        .unwrap()
        .iter()
        .all(Value::is_null));
}

#[test]
fn the_slider_shows_the_region_at_each_stop() {
    let (job, text) = example();
    let html = render_at_037(&job, &text);
    let data = data_block(&html);
    let strings = data["strings"].as_array().unwrap();
    // Stage 2 is the second figure kind; each stop lists its changing parts.
    let s2 = &data["figures"][1];
    assert_eq!(s2["prefix"], json!("s2-"));
    let frames = s2["frames"].as_array().unwrap();
    let regions_at = |k: usize| -> Vec<String> {
        frames[k]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| {
                strings[i.as_u64().unwrap() as usize]
                    .as_str()
                    .unwrap()
                    .to_owned()
            })
            .filter(|s| s.contains("fill-rule=\"evenodd\""))
            .collect()
    };
    let stops = data["stops"].as_array().unwrap();
    let at = |a: &str| {
        stops
            .iter()
            .position(|s| s["alpha"].as_str() == Some(a))
            .unwrap()
    };
    // Upper and lower regions at 0.3, the upper alone above h = 0.6, and
    // they differ from stop to stop.
    let (low, high) = (regions_at(at("0.3")), regions_at(at("0.8")));
    assert_eq!(low.len(), 2, "upper and lower at 0.3");
    assert_eq!(high.len(), 1, "upper alone at 0.8");
    assert_ne!(low, regions_at(at("0.31")));
    // The figures of the plane are sections of the page.
    for id in ["membership", "section"] {
        assert!(html.contains(&format!("<section id=\"{id}\">")), "{id}");
    }
}

#[test]
fn a_terrain_report_has_its_width_map_and_shoreline_at_every_stop() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fuzzy-terrain.json");
    let text = std::fs::read_to_string(&path).unwrap();
    let job = t2spline_io::parse_job(&text, "terrain").unwrap();
    let html = render_at_037(&job, &text);
    for figure in ["envelope-width", "shoreline", "terrain-measures"] {
        assert!(
            html.contains(&format!("data-name=\"{figure}\"")),
            "{figure}"
        );
    }
    let data = data_block(&html);
    let stops = data["stops"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| !s["alpha"].is_null())
        .count();
    for prefix in ["ew-", "sh-"] {
        let f = data["figures"]
            .as_array()
            .unwrap()
            .iter()
            .find(|f| f["prefix"] == prefix)
            .unwrap_or_else(|| panic!("{prefix}"));
        assert_eq!(f["paper"], json!(true), "{prefix} follows the slider");
        assert_eq!(f["frames"].as_array().unwrap().len(), stops, "{prefix}");
        assert!(
            !f["parts"].as_array().unwrap().is_empty(),
            "{prefix} changes"
        );
    }
    // The slider's stops are within the budget with the terrain's frames.
    assert!(html.len() < 5_000_000, "{}", html.len());
}

#[test]
fn a_surface_that_is_not_a_terrain_has_a_note_instead() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fuzzy-cylinder.json");
    let text = std::fs::read_to_string(&path).unwrap();
    let job = t2spline_io::parse_job(&text, "cylinder").unwrap();
    let html = render_at_037(&job, &text);
    assert!(html.contains("they are left out here"));
    assert!(!html.contains("data-name=\"envelope-width\""));
    let data = data_block(&html);
    assert!(data["figures"]
        .as_array()
        .unwrap()
        .iter()
        .all(|f| f["prefix"] != "ew-" && f["prefix"] != "sh-"));
}
