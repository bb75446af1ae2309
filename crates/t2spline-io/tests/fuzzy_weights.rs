//! Jobs with fuzzy weights (docs/jobs.md, docs/method.md §16): read as a
//! coordinate's number is, written back, run, and with crisp weights nothing
//! changes.

use t2spline::job::{Model, Overrides};
use t2spline::{Alpha, Layer, Side};

fn example() -> String {
    std::fs::read_to_string("../../examples/fuzzy-weights.json").unwrap()
}

fn result_json(text: &str) -> serde_json::Value {
    let job = t2spline_io::parse_job(text, "job.json").unwrap();
    let settings = job.settings(&Overrides::default()).unwrap();
    serde_json::to_value(job.run(&settings).unwrap()).unwrap()
}

#[test]
fn a_fuzzy_weight_is_read_as_a_coordinates_number_with_the_jobs_height() {
    let job = t2spline_io::parse_job(&example(), "fuzzy-weights.json").unwrap();
    let Model::Planar(c) = &job.model else {
        panic!("a plane curve")
    };
    let w = c.weight_numbers().unwrap();
    assert_eq!(w.len(), 4);
    assert_eq!(c.weights(), &[1.0, 1.0, 3.0, 1.0]);
    assert_eq!(w[2].layer(Layer::UpperLeft), 2.0);
    assert_eq!(w[2].layer(Layer::UpperRight), 4.5);
    assert_eq!(w[2].height().get(), 0.6);
    // A bare number among them is crisp.
    assert!(Layer::ALL.iter().all(|&l| w[0].layer(l) == 1.0));
    // Its own lower_height wins over the job's.
    let own = example().replace(
        "\"lower\": [\n        2.7,\n        3.5\n      ]",
        "\"lower\": [\n        2.7,\n        3.5\n      ],\n      \"lower_height\": 0.9",
    );
    assert_ne!(own, example());
    let job = t2spline_io::parse_job(&own, "own.json").unwrap();
    let Model::Planar(c) = &job.model else {
        panic!("a plane curve")
    };
    assert_eq!(c.weight_numbers().unwrap()[2].height().get(), 0.9);
}

#[test]
fn the_canonical_job_gives_the_job_back() {
    let job = t2spline_io::parse_job(&example(), "fuzzy-weights.json").unwrap();
    let json = t2spline_io::job_json(&job);
    assert!(json["weights"][2].is_object());
    let again = t2spline_io::parse_job(&json.to_string(), "again.json").unwrap();
    assert_eq!(again, job);
}

#[test]
fn the_result_holds_the_weights_of_every_stage() {
    let job = t2spline_io::parse_job(&example(), "fuzzy-weights.json").unwrap();
    let Model::Planar(c) = &job.model else {
        panic!("a plane curve")
    };
    let r = result_json(&example());
    let stages = &r["weight_stages"];
    let s = c.solve(Alpha::try_new(0.8).unwrap());
    let list = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    assert_eq!(list(&stages["crisp"]), c.weights());
    assert_eq!(
        list(&stages["defuzzified"]),
        s.defuzzified_weights().unwrap()
    );
    assert_eq!(
        list(&stages["type_reduced_left"]),
        s.type_reduced_weights(Side::Left).unwrap()
    );
    assert_eq!(
        list(&stages["alpha_cut"]["upper_right"]),
        s.alpha_cut_weights(Layer::UpperRight).unwrap().unwrap()
    );
    // Alpha 0.8 lies above the lower height 0.6: no lower cut.
    assert!(stages["alpha_cut"]["lower_left"][2].is_null());
    assert_eq!(list(&stages["layers"]["upper_left"]), [1.0, 1.0, 2.0, 1.0]);
    // The sampled solution is the curve through the defuzzified points with
    // the defuzzified weights.
    let solved = s.defuzzified_curve();
    let ts = list(&r["curves"]["params"]);
    let xy = r["curves"]["defuzzified"].as_array().unwrap();
    for (t, p) in ts.iter().zip(xy) {
        let q = solved.eval(*t).unwrap();
        assert!((p[0].as_f64().unwrap() - q[0]).abs() < 1e-12);
        assert!((p[1].as_f64().unwrap() - q[1]).abs() < 1e-12);
    }
}

#[test]
fn crisp_weights_written_as_numbers_give_the_same_result_to_the_byte() {
    let plain = std::fs::read_to_string("../../examples/paper-alg-1-1.json").unwrap();
    let as_numbers = plain.replace(
        "\"weights\": [1, 1, 3, 1]",
        "\"weights\": [1, {\"crisp\": 1, \"upper\": [1, 1], \"primary\": [1, 1], \"lower\": [1, 1]}, 3, 1]",
    );
    assert_ne!(plain, as_numbers);
    let (a, b) = (result_json(&plain), result_json(&as_numbers));
    assert!(a.get("weight_stages").is_none());
    assert_eq!(
        t2spline_io::to_json_pretty(&a),
        t2spline_io::to_json_pretty(&b)
    );
}
