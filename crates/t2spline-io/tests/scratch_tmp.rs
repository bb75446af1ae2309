use serde_json::{json, Value};
fn number(c: f64) -> Value {
    json!({"crisp": c, "upper": [c - 0.5, c + 1.0], "primary": [c - 0.25, c + 0.5], "lower": [c - 0.125, c + 0.25]})
}
fn p3(x: f64, y: f64, z: f64) -> Value { json!({"x": number(x), "y": number(y), "z": number(z)}) }
fn show(v: &Value) {
    let text = serde_json::to_string_pretty(v).unwrap();
    match t2spline_io::parse_job(&text, "s.json") {
        Ok(j) => println!("OK {}", j.model.summary()),
        Err(e) => for l in e.lines() { println!("{l}") },
    }
    println!("--");
}
#[test]
fn scratch() {
    let row = |i: f64, n: usize| Value::Array((0..n).map(|j| p3(i, j as f64, i * j as f64)).collect());
    let base = json!({"order": [2, 2], "alpha": 0.5, "lower_height": 0.5, "points": [row(0.0,3), row(1.0,3), row(2.0,3)]});
    show(&base);
    let mut v = base.clone(); v["points"][2] = row(2.0, 2); show(&v);
    let mut v = base.clone(); v["order"] = json!(3); show(&v);
    let mut v = base.clone(); v["order"] = json!([3, 2, 1]); show(&v);
    let mut v = base.clone(); v["weights"] = json!([[1, 1, 1], [1, 0, 1]]); show(&v);
    let mut v = base.clone(); v["weights"] = json!([[1, 1, 1], [1, 1], [1, 1, 1]]); show(&v);
    let mut v = base.clone(); v["weights"] = json!([1, 1, 1]); show(&v);
    let mut v = base.clone(); v["knots"] = json!({"v": [0, 0, 1, 1, 1], "w": [1]}); show(&v);
    let mut v = base.clone(); v["knots"] = json!({"u": [0, 0, 0.5, 0.2, 1], "v": [0,0,0.5,1,1]}); show(&v);
    let mut v = base.clone(); v["knots"] = json!([0, 0, 1, 1]); show(&v);
    let mut v = base.clone(); v["points"][1][1] = json!({"x": number(1.0), "y": number(1.0)}); show(&v);
    let mut v = base.clone(); v["points"] = json!([[p3(0.0,0.0,0.0)]]); show(&v);
    let mut v = base.clone(); v["points"] = json!([row(0.0, 3)]); show(&v);
    let mut v = base.clone(); v["samples"] = json!([2000, 501]); show(&v);
    let mut v = base.clone(); v["samples"] = json!([1, 5]); show(&v);
    let mut v = base.clone(); v["samples"] = json!(7); show(&v);
    let mut v = base.clone(); v["order"] = json!([33, 0]); show(&v);
    let mut v = base.clone(); v["points"][1] = p3(1.0, 1.0, 1.0); show(&v);
    let mut v = base.clone(); v["points"] = json!([]); show(&v);
    let mut v = base.clone(); v["points"] = json!([[]]); show(&v);
    let c = json!({"order": [2, 2], "lower_height": 0.5, "samples": [3, 3], "knots": {"u": [0, 0, 1, 1]}, "points": [p3(0.0,0.0,0.0), p3(1.0,1.0,1.0)]});
    show(&c);
}
