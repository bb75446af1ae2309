//! Surface jobs with fuzzy weights (docs/jobs.md, docs/method.md §16): the
//! rows of `weights` may hold fuzzy numbers, read as a curve's are, written
//! back, and run with the weights of every stage in the result.

use t2spline::job::{Model, Overrides};
use t2spline::{Alpha, Direction, Layer, Side};

const FIXTURE: &str = "../../fixtures/fuzzy-weights-surface.json";

fn fixture() -> String {
    std::fs::read_to_string(FIXTURE).unwrap()
}

fn surface(text: &str) -> t2spline::FuzzySurface<3> {
    let job = t2spline_io::parse_job(text, "fuzzy-weights-surface.json").unwrap();
    let Model::Surface(s) = job.model else {
        panic!("a surface")
    };
    s
}

fn list(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

#[test]
fn fuzzy_weights_in_the_rows_are_read_with_the_jobs_height() {
    let s = surface(&fixture());
    let w = s.weight_numbers().unwrap();
    // Row by row: weights[1][1] is the fifth, weights[1][2] the sixth.
    assert_eq!(w.len(), 9);
    assert_eq!(s.weights(), &[1.0, 1.0, 1.0, 1.0, 2.0, 1.0, 1.0, 1.0, 1.0]);
    assert_eq!(w[4].layer(Layer::UpperLeft), 1.0);
    assert_eq!(w[4].layer(Layer::UpperRight), 4.0);
    assert_eq!(w[4].height().get(), 0.5);
    assert_eq!(w[5].layer(Layer::LowerLeft), 0.9);
    // A bare number, in a fuzzy row or a crisp one, is crisp.
    for k in [0, 3, 8] {
        assert!(Layer::ALL.iter().all(|&l| w[k].layer(l) == 1.0));
    }
}

#[test]
fn the_canonical_job_gives_the_job_back() {
    let job = t2spline_io::parse_job(&fixture(), "fuzzy-weights-surface.json").unwrap();
    let json = t2spline_io::job_json(&job);
    assert!(json["weights"][1][1].is_object());
    assert_eq!(json["weights"].as_array().unwrap().len(), 3);
    let again = t2spline_io::parse_job(&json.to_string(), "again.json").unwrap();
    assert_eq!(again, job);
}

#[test]
fn a_bad_foot_is_reported_at_its_place() {
    let bad = fixture().replace(
        "\"upper\": [\n          1,\n          4\n        ]",
        "\"upper\": [\n          0,\n          4\n        ]",
    );
    assert_ne!(bad, fixture());
    let e = t2spline_io::parse_job(&bad, "bad.json")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("weights[1][1].upper[0]: 0 must be finite and greater than 0: every value of a fuzzy weight is a weight"),
        "{e}"
    );
}

#[test]
fn the_result_holds_the_weights_of_every_stage_row_by_row() {
    let text = fixture();
    let s = surface(&text);
    let job = t2spline_io::parse_job(&text, "job.json").unwrap();
    let settings = job.settings(&Overrides::default()).unwrap();
    let r = serde_json::to_value(job.run(&settings).unwrap()).unwrap();
    let stages = &r["weight_stages"];
    let solution = s.solve(Alpha::try_new(0.5).unwrap());
    assert_eq!(list(&stages["crisp"]), s.weights());
    assert_eq!(
        list(&stages["defuzzified"]),
        solution.defuzzified_weights().unwrap()
    );
    assert_eq!(
        list(&stages["type_reduced_right"]),
        solution.type_reduced_weights(Side::Right).unwrap()
    );
    assert_eq!(
        list(&stages["alpha_cut"]["upper_left"]),
        solution
            .alpha_cut_weights(Layer::UpperLeft)
            .unwrap()
            .unwrap()
    );
    // The sampled solution is the surface through the defuzzified points
    // with the defuzzified weights, and the error measures it.
    let solved = solution.defuzzified_surface();
    let surfaces = &r["surfaces"];
    let (us, vs) = (
        list(&surfaces["params"]["u"]),
        list(&surfaces["params"]["v"]),
    );
    let grid = surfaces["defuzzified"].as_array().unwrap();
    // Rows of points along u, each along v.
    for (a, &u) in us.iter().enumerate() {
        for (b, &v) in vs.iter().enumerate() {
            let p = list(&grid[a][b]);
            let q = solved.eval(u, v).unwrap();
            assert!((0..3).all(|d| (p[d] - q[d]).abs() < 1e-12), "{p:?} {q:?}");
        }
    }
    let d = solution.distance();
    assert_eq!(r["error"]["max"].as_f64().unwrap(), d.max);
    assert!(d.max > 0.0);
    assert_eq!(s.domain(Direction::U).start, us[0]);
}
