use super::*;
use base64::Engine as _;

fn example() -> (Job, String) {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json");
    let text = std::fs::read_to_string(&path).unwrap();
    (t2spline_io::parse_job(&text, "example").unwrap(), text)
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

#[test]
fn table_cells_are_the_run_result_at_the_job_sampling() {
    let (job, _) = example();
    for a in Stops::new(&job, Alpha::try_new(0.8).unwrap(), 100).alphas {
        let alpha = Alpha::try_new(a).unwrap();
        let figure_result = data::compute(&job, alpha).unwrap();
        let run_result = data::run_job(&job, alpha).unwrap();
        for t in tables::tables(&run_result) {
            assert_eq!(
                tables::cells(&t, &figure_result),
                tables::cells(&t, &run_result),
                "alpha {a}, {}",
                t.id
            );
        }
    }
}

#[test]
fn the_report_marks_h_starts_at_the_given_alpha_and_carries_run_s_files() {
    let (job, text) = example();
    let html = render(
        &job,
        &text,
        Alpha::try_new(0.37).unwrap(),
        &FigureOptions::default(),
    )
    .unwrap();
    assert!(html.contains("α = h = 0.6"));
    assert!(html.contains("data-value=\"0.37\">0.37</output>"));
    assert!(html.contains("value=\"37\""), "0.37 is stop 37");
    let data = data_block(&html);
    let stops = data["stops"].as_array().unwrap();
    assert_eq!(stops.len(), 101, "a small job gets every 0.01");
    assert_eq!(stops[60]["at_h"], json!(true));
    assert_eq!(stops[60]["regime"], json!("alpha <= h"));
    assert_eq!(stops[61]["regime"], json!("alpha > h"));
    assert_eq!(data["figures"].as_array().unwrap().len(), 5);
    // Every download at every stop is the bytes run writes.
    let downloads = &data["downloads"];
    for k in [0, 37, 60, 61, 100] {
        let alpha = Alpha::try_new(stops[k]["alpha"].as_str().unwrap().parse().unwrap()).unwrap();
        let files = files_of(&data::run_job(&job, alpha).unwrap()).unwrap();
        assert_eq!(files.len(), downloads["files"].as_array().unwrap().len());
        for (name, text) in &files {
            assert_eq!(
                unpack(downloads, name, k).as_deref(),
                Some(text.as_str()),
                "stop {k}: {name}"
            );
        }
    }
}
