//! Job files of surfaces (docs/method.md §8): what a surface job is, its defaults, and
//! every rule it can break reported at its line and column, all at once, as
//! for curves.

mod positions;

use positions::at;
use serde_json::{json, Value};
use t2spline::job::{Model, Samples, DEFAULT_SURFACE_SAMPLES, MAX_SAMPLES};
use t2spline::{Direction, FuzzySurface};
use t2spline_io::job::{MAX_ORDER, MAX_POINTS, MAX_SURFACE_WORK};

// ---------------------------------------------------------------------------
// Fixtures
// ---------------------------------------------------------------------------

/// A valid fuzzy number around `c` without its own height.
fn number(c: f64) -> Value {
    json!({"crisp": c, "upper": [c - 0.5, c + 1.0], "primary": [c - 0.25, c + 0.5], "lower": [c - 0.125, c + 0.25]})
}

fn point(x: f64, y: f64, z: f64) -> Value {
    json!({"x": number(x), "y": number(y), "z": number(z)})
}

/// Row `i` of a net: `columns` points along v.
fn row(i: usize, columns: usize) -> Value {
    Value::Array(
        (0..columns)
            .map(|j| point(i as f64, j as f64, (i * j) as f64))
            .collect(),
    )
}

/// A valid surface job of orders 2 × 2 on a 3 × 3 net, without weights,
/// knots or samples.
fn base() -> Value {
    json!({
        "order": [2, 2],
        "alpha": 0.5,
        "lower_height": 0.5,
        "points": [row(0, 3), row(1, 3), row(2, 3)]
    })
}

/// `base()` with `key` set to `value`.
fn with(key: &str, value: Value) -> Value {
    let mut v = base();
    v[key] = value;
    v
}

fn surface_of(v: &Value) -> FuzzySurface<3> {
    let text = serde_json::to_string_pretty(v).unwrap();
    match t2spline_io::parse_job(&text, "job.json") {
        Ok(job) => match job.model {
            Model::Surface(s) => s,
            other => panic!("not read as a surface: {other:?}"),
        },
        Err(e) => panic!("{}\n{text}", e.lines().join("\n")),
    }
}

/// The error lines of an invalid job given as text, with their positions.
fn located(text: &str) -> Vec<String> {
    match t2spline_io::parse_job(text, "job.json") {
        Ok(job) => panic!("expected problems, the job is valid: {job:?}\n{text}"),
        Err(e) => e.lines(),
    }
}

/// The error lines of an invalid job, without line and column
/// (`job.json: place: rule`); every line must have them.
fn problems(v: &Value) -> Vec<String> {
    let text = serde_json::to_string_pretty(v).unwrap();
    located(&text)
        .into_iter()
        .map(|line| {
            let parts: Vec<&str> = line.splitn(4, ':').collect();
            assert!(
                parts.len() == 4
                    && [parts[1], parts[2]]
                        .iter()
                        .all(|n| n.parse::<usize>().is_ok_and(|n| n >= 1)),
                "no line and column: {line}"
            );
            format!("{}:{}", parts[0], parts[3])
        })
        .collect()
}

#[track_caller]
fn assert_problems(v: &Value, expected: &[&str]) {
    assert_eq!(problems(v), expected, "job: {v}");
}

// ---------------------------------------------------------------------------
// What a surface job is, and its defaults
// ---------------------------------------------------------------------------

#[test]
fn rows_of_points_make_a_surface_job_with_the_defaults_of_spec_9() {
    let text = serde_json::to_string(&base()).unwrap();
    let job = t2spline_io::parse_job(&text, "job.json").unwrap();
    assert_eq!(job.samples, Samples::Grid([DEFAULT_SURFACE_SAMPLES; 2]));
    assert_eq!(job.samples, Samples::Grid([21, 21]));
    assert_eq!(
        job.model.summary(),
        "3-D surface, 3 × 3 control points, orders 2 × 2"
    );
    let Model::Surface(s) = &job.model else {
        panic!("{job:?}")
    };
    assert_eq!((s.degree(), s.shape()), ([1, 1], [3, 3]));
    assert_eq!(s.weights(), &[1.0; 9]);
    for d in Direction::BOTH {
        assert_eq!(s.knots(d).as_slice(), &[0.0, 0.0, 0.5, 1.0, 1.0]);
    }
    // points[i][j]: i along u (rows), j along v; row by row in the model.
    assert_eq!(s.points()[5].coords()[1].crisp(), 2.0);
    assert_eq!(s.points()[5].coords()[0].crisp(), 1.0);
}

#[test]
fn degree_pairs_and_explicit_weights_and_knots_are_read() {
    let mut v = with("degree", json!([2, 1]));
    v.as_object_mut().unwrap().remove("order");
    v["weights"] = json!([[1, 2, 1], [1, 0.5, 1], [3, 1, 1]]);
    v["knots"] = json!({"u": [0, 0, 0, 2, 2, 2], "v": [-1, -1, 0.25, 1, 1]});
    let s = surface_of(&v);
    assert_eq!(s.degree(), [2, 1]);
    assert_eq!(s.weights(), &[1.0, 2.0, 1.0, 1.0, 0.5, 1.0, 3.0, 1.0, 1.0]);
    assert_eq!(
        s.knots(Direction::U).as_slice(),
        &[0.0, 0.0, 0.0, 2.0, 2.0, 2.0]
    );
    assert_eq!(
        s.knots(Direction::V).as_slice(),
        &[-1.0, -1.0, 0.25, 1.0, 1.0]
    );
}

#[test]
fn a_knot_vector_left_out_takes_its_default() {
    let s = surface_of(&with("knots", json!({"v": [0, 0, 0.75, 1, 1]})));
    assert_eq!(s.knots(Direction::U).as_slice(), &[0.0, 0.0, 0.5, 1.0, 1.0]);
    assert_eq!(
        s.knots(Direction::V).as_slice(),
        &[0.0, 0.0, 0.75, 1.0, 1.0]
    );
    let s = surface_of(&with("knots", json!({})));
    assert_eq!(s.knots(Direction::V).as_slice(), &[0.0, 0.0, 0.5, 1.0, 1.0]);
}

#[test]
fn samples_are_a_pair_or_one_number_for_both_directions() {
    let samples = |value: Value| {
        let text = with("samples", value).to_string();
        t2spline_io::parse_job(&text, "job.json").unwrap().samples
    };
    assert_eq!(samples(json!([41, 3])), Samples::Grid([41, 3]));
    assert_eq!(samples(json!(7)), Samples::Grid([7, 7]));
    assert_eq!(samples(json!(7.0)), Samples::Grid([7, 7]));
    assert_eq!(samples(json!([1000, 1000])), Samples::Grid([1000, 1000]));
}

#[test]
fn the_kind_of_job_follows_most_entries_of_points() {
    // One stray array in a curve job keeps the curve's messages.
    let mut v = json!({"order": 2, "lower_height": 0.5,
                       "points": [point(0.0, 0.0, 0.0), point(1.0, 1.0, 1.0), point(2.0, 0.0, 1.0)]});
    v["points"][0] = json!([1, 2]);
    assert_problems(
        &v,
        &["job.json: points[0]: expected a point (a JSON object), got an array"],
    );
    // One stray point in a surface job keeps the surface's messages.
    let mut v = base();
    v["points"][1] = point(1.0, 1.0, 1.0);
    assert_problems(
        &v,
        &["job.json: points[1]: expected a row of points (an array), got an object"],
    );
    // No points to tell: the order decides.
    assert_problems(
        &with("points", json!([])),
        &[
            "job.json: points: a surface of order 2 in u needs at least 2 control points along u, got 0",
            "job.json: points: a surface of order 2 in v needs at least 2 control points along v, got 0",
        ],
    );
}

// ---------------------------------------------------------------------------
// Every rule of a surface job
// ---------------------------------------------------------------------------

#[test]
fn ragged_rows_name_their_lengths() {
    let mut v = base();
    v["points"][2] = row(2, 2);
    v["points"].as_array_mut().unwrap().push(row(3, 4));
    assert_problems(
        &v,
        &[
            "job.json: points[2]: 2 columns, row 0 has 3: every row of the net needs as many points",
            "job.json: points[3]: 4 columns, row 0 has 3: every row of the net needs as many points",
        ],
    );
}

#[test]
fn weights_of_another_shape_are_named_by_row_and_bad_weights_by_row_and_column() {
    assert_problems(
        &with("weights", json!([[1, 1, 1], [1, 0, 1]])),
        &[
            "job.json: weights: 2 rows, points has 3",
            "job.json: weights[1][1] = 0 must be finite and greater than 0",
        ],
    );
    assert_problems(
        &with("weights", json!([[1, 1, 1], [1, 1], [1, 1, 1e200, 1]])),
        &[
            "job.json: weights[1]: 2 columns, points[1] has 3",
            "job.json: weights[2]: 4 columns, points[2] has 3",
            "job.json: weights[2][2] = 1e200 is outside [1e-150, 1e150]",
        ],
    );
    assert_problems(
        &with("weights", json!([[1, 1, 1], [1, "2", 1], 5])),
        &[
            "job.json: weights[1][1]: expected a number, got a string",
            "job.json: weights[2]: expected an array of numbers, got a number",
        ],
    );
    assert_problems(
        &with("weights", json!([1, 1, 1])),
        &["job.json: weights: expected rows of numbers, the shape of points, got a list of numbers (the weights of a curve)"],
    );
    assert_problems(
        &with("weights", json!({"u": 1})),
        &["job.json: weights: expected rows of numbers, the shape of points, got an object"],
    );
}

#[test]
fn points_of_a_surface_need_three_coordinates() {
    let mut v = base();
    v["points"][1][2] = json!({"x": number(1.0), "y": number(1.0)});
    v["points"][2][0] = json!({"x": number(2.0), "y": number(0.0), "w": number(0.0)});
    assert_problems(
        &v,
        &[
            "job.json: points[1][2]: has coordinates [x, y]; the points of a surface need x, y and z",
            "job.json: points[2][0].w: unknown key (known keys: x, y, z)",
            "job.json: points[2][0]: has coordinates [x, y]; the points of a surface need x, y and z",
        ],
    );
}

#[test]
fn numbers_in_the_net_are_named_by_row_column_and_coordinate() {
    let mut v = base();
    v["points"][2][1]["y"]["lower"] = json!([1.5, 0.9]);
    v["points"][0][2]["z"]["crisp"] = json!("0");
    v["points"][1][0]["x"]["lower_height"] = json!(0);
    assert_problems(
        &v,
        &[
            "job.json: points[0][2].z.crisp: expected a number, got a string",
            "job.json: points[1][0].x: lower_height = 0 is outside (0, 1]",
            "job.json: points[2][1].y: the order lower.left <= crisp is broken: 1.5 > 1",
            "job.json: points[2][1].y: the order crisp <= lower.right is broken: 1 > 0.9",
        ],
    );
}

#[test]
fn knot_vectors_of_the_wrong_length_name_direction_and_count() {
    assert_problems(
        &with(
            "knots",
            json!({"u": [0, 0, 1, 1], "v": [0, 0, 0.5, 1, 1, 1]}),
        ),
        &[
            "job.json: knots.u: expected 5 values (rows + order in u), got 4",
            "job.json: knots.v: expected 5 values (columns + order in v), got 6",
        ],
    );
    assert_problems(
        &with(
            "knots",
            json!({"u": [0, 0, 0.7, 0.5, 1], "v": [0, 0, 1, 1, 1]}),
        ),
        &[
            "job.json: knots.u[3] = 0.5 is less than knots.u[2] = 0.7: knots.u must not decrease",
            "job.json: knots.v[2..5]: the value 1 repeats 3 times, more than the order 2",
        ],
    );
    assert_problems(
        &with("knots", json!({"v": [0, 0, 1, 1, 1e151]})),
        &["job.json: knots.v[4] = 1e151 is outside [-1e150, 1e150]"],
    );
    let mut v = with("order", json!([3, 2]));
    v["knots"] = json!({"u": [0, 0.5, 0.5, 0.5, 1, 1]});
    assert_problems(
        &v,
        &["job.json: knots.u: the domain [knots.u[2], knots.u[3]] = [0.5, 0.5] is empty; it needs knots.u[2] < knots.u[3]"],
    );
}

#[test]
fn knots_of_a_surface_are_an_object_of_u_and_v() {
    assert_problems(
        &with(
            "knots",
            json!({"u": [0, 0, 0.5, 1, 1], "w": [0, 1], "V": []}),
        ),
        &[
            "job.json: knots.w: unknown key (known keys: u, v)",
            "job.json: knots.V: unknown key (known keys: u, v)",
        ],
    );
    assert_problems(
        &with("knots", json!([0, 0, 0.5, 1, 1])),
        &["job.json: knots: a surface has a knot vector per direction: expected an object with `u` and/or `v`, got an array"],
    );
    assert_problems(
        &with("knots", json!({"u": 3})),
        &["job.json: knots.u: expected an array of numbers, got a number"],
    );
}

#[test]
fn a_grid_of_one_point_or_one_row_is_too_small_for_orders_above_one() {
    assert_problems(
        &with("points", json!([[point(0.0, 0.0, 0.0)]])),
        &[
            "job.json: points: a surface of order 2 in u needs at least 2 control points along u, got 1",
            "job.json: points: a surface of order 2 in v needs at least 2 control points along v, got 1",
        ],
    );
    assert_problems(
        &with("points", json!([row(0, 3)])),
        &["job.json: points: a surface of order 2 in u needs at least 2 control points along u, got 1"],
    );
    assert_problems(
        &with("points", json!([[], []])),
        &["job.json: points: a surface of order 2 in v needs at least 2 control points along v, got 0"],
    );
    // Order 1 is allowed in either direction, as for curves: one row is then
    // a surface constant in u.
    let mut v = with("order", json!([1, 2]));
    v["points"] = json!([row(0, 3)]);
    assert_eq!(surface_of(&v).shape(), [1, 3]);
}

#[test]
fn a_pair_where_a_number_is_wanted_and_a_number_where_a_pair_is() {
    // In a surface job.
    assert_problems(
        &with("order", json!(3)),
        &["job.json: order: a surface (points given as rows of a net) has one order per direction: give a pair [u, v], got 3"],
    );
    assert_problems(
        &with("order", json!([3, 2, 1])),
        &["job.json: order: expected a pair [u, v], one order per direction, got an array of 3 values"],
    );
    assert_problems(
        &with("order", json!([0, 33])),
        &[
            "job.json: order[0]: order = 0: the order must be at least 1",
            &format!(
                "job.json: order[1]: order = 33 is more than the limit {MAX_ORDER} (degree 31)"
            ),
        ],
    );
    assert_problems(
        &with("samples", json!([3, 3, 3])),
        &["job.json: samples: expected a pair [u, v] of numbers of samples, or one number for both directions, got an array of 3 values"],
    );
    assert_problems(
        &with("samples", json!([1, 2.5])),
        &[
            "job.json: samples[0]: samples = 1: at least 2 are needed (both ends of the domain)",
            "job.json: samples[1]: expected a whole number >= 0, got 2.5",
        ],
    );
    // In a curve job.
    let curve = json!({"order": [2, 2], "lower_height": 0.5, "samples": [3, 3],
                       "knots": {"u": [0, 0, 1, 1]},
                       "points": [point(0.0, 0.0, 0.0), point(1.0, 1.0, 1.0)]});
    assert_problems(
        &curve,
        &[
            "job.json: order: a pair [u, v] is for a surface, whose points are rows of a net; a curve has one order",
            "job.json: samples: a pair [u, v] is for a surface, whose points are rows of a net; a curve takes one number of samples",
            "job.json: knots: an object of knot vectors (u, v) is for a surface, whose points are rows of a net; a curve's knots are one array of numbers",
        ],
    );
}

#[test]
fn grids_beyond_the_limit_of_samples_are_refused() {
    assert_problems(
        &with("samples", json!([2000, 501])),
        &[&format!(
            "job.json: samples: samples = 2000 × 501 = 1002000 grid points is more than the limit {MAX_SAMPLES}"
        )],
    );
    assert_problems(
        &with("samples", json!(1001)),
        &["job.json: samples: samples = 1001 × 1001 = 1002001 grid points is more than the limit 1000000"],
    );
}

/// The net's size is counted from the rows' lengths before any point is read:
/// a net of placeholders past the limit gives one problem, not one per entry.
#[test]
fn a_net_beyond_the_limit_is_refused_before_its_points_are_read() {
    let side = 317; // 317² = 100 489 > MAX_POINTS
    assert!(side * side > MAX_POINTS && (side - 1) * (side - 1) <= MAX_POINTS);
    let row = format!("[{}]", vec!["0"; side].join(","));
    let text = format!(
        r#"{{"order": [2, 2], "lower_height": 0.5, "points": [{}]}}"#,
        vec![row; side].join(",")
    );
    assert_eq!(
        located(&text),
        [format!(
            "job.json:{}: points: a net of {} control points is more than the limit {MAX_POINTS}",
            at(&text, "\"points\"", 0),
            side * side
        )]
    );
}

/// The time of a run grows with the span rectangles times the basis terms
/// of each: a net past that limit is refused, naming the figures.
#[test]
fn a_surface_beyond_the_limit_of_work_is_refused() {
    let net = |n: usize| Value::Array((0..n).map(|i| row(i, n)).collect());
    let mut v = with("order", json!([4, 4]));
    v["points"] = net(204);
    assert_problems(
        &v,
        &[&format!(
            "job.json: points: a surface of 204 × 204 control points and orders 4 × 4 has up to 40401 span rectangles of 16 basis terms each, 646416 in all, more than the limit {MAX_SURFACE_WORK}: the distance of the solution is measured on every rectangle; use fewer control points or lower orders"
        )],
    );
    v["points"] = net(203);
    assert_eq!(surface_of(&v).shape(), [203, 203]);
}

/// One file with a problem of every surface kind; each line names the file,
/// the line and column of the key or element concerned (for a missing key:
/// of the object that lacks it), the place and the rule — all at once.
#[test]
fn every_problem_of_a_surface_file_is_listed_with_line_and_column() {
    let p = |x: f64, y: f64, z: f64| point(x, y, z).to_string();
    let text = format!(
        r#"{{
  "order": [3, 2],
  "alpha": 0.5,
  "lower_height": 0.5,
  "samples": [1, 4],
  "weights": [[1, 1], [1, -1]],
  "knots": {{"u": [0, 0, 0, 1, 1, 1], "v": [0, 0, 1, 1, 1], "w": []}},
  "points": [
    [{}, {}],
    [{}, {}, {}],
    [{}, {{"x": {}, "y": {}}}]
  ]
}}"#,
        p(0.0, 0.0, 0.0),
        p(0.0, 1.0, 0.0),
        p(1.0, 0.0, 1.0),
        p(1.0, 1.0, 1.0),
        p(1.0, 2.0, 1.0),
        p(2.0, 0.0, 0.0),
        number(2.0),
        number(1.0),
    );
    let expected = [
        format!(
            "{}: samples[0]: samples = 1: at least 2 are needed (both ends of the domain)",
            at(&text, "1, 4]", 0)
        ),
        format!(
            "{}: points[1]: 3 columns, row 0 has 2: every row of the net needs as many points",
            at(&text, "[{", 1)
        ),
        format!(
            "{}: points[2][1]: has coordinates [x, y]; the points of a surface need x, y and z",
            at(&text, "{\"x\"", 6)
        ),
        format!(
            "{}: weights: 2 rows, points has 3",
            at(&text, "\"weights\"", 0)
        ),
        format!(
            "{}: weights[1]: 2 columns, points[1] has 3",
            at(&text, "[1, -1]", 0)
        ),
        format!(
            "{}: weights[1][1] = -1 must be finite and greater than 0",
            at(&text, "-1]]", 0)
        ),
        format!(
            "{}: knots.w: unknown key (known keys: u, v)",
            at(&text, "\"w\"", 0)
        ),
    ];
    let got: Vec<String> = located(&text)
        .iter()
        .map(|l| {
            l.strip_prefix("job.json:")
                .expect("names the file")
                .to_owned()
        })
        .collect();
    assert_eq!(got, expected, "\n{}\n{text}", got.join("\n"));
}

/// With a regular net, the rules of each direction are checked even when
/// other parts of the file are broken.
#[test]
fn direction_rules_are_checked_even_when_other_parts_are_broken() {
    let mut v = with("knots", json!({"u": [0, 0, 1, 1], "v": [0, 0, 0.5, 1, 1]}));
    v["points"][0][0]["x"]["crisp"] = json!(null);
    v["alpha"] = json!(2);
    assert_problems(
        &v,
        &[
            "job.json: alpha = 2 is outside [0, 1]",
            "job.json: points[0][0].x.crisp: expected a number, got null",
            "job.json: knots.u: expected 5 values (rows + order in u), got 4",
        ],
    );
}
