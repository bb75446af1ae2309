//! Our side of the peer comparison (`peer/` at the repository root): reads
//! curve cases as JSON on standard input and writes our results as JSON on
//! standard output, for the Python scripts that compare them with geomdl and
//! scipy. Not a user tool; see `peer/README.md`.
//!
//! Input: `{"cases": [case, …]}`, each case
//! `{"op": …, "degree": p, "knots": […], "points": [[…], …], "weights": […], …}`
//! with 2-D or 3-D points and, per operation:
//!
//! | op | extra keys | result keys |
//! |---|---|---|
//! | `derivatives` | `params`, `order` | `derivatives`: per parameter, `order + 1` vectors |
//! | `insert` | `knot`, `times` | `curve` |
//! | `refine` | `new_knots` | `curve` |
//! | `elevate` | `times` | `curve` |
//! | `split` | `t` | `pieces`: two curves |
//!
//! A curve is `{"degree", "knots", "points", "weights"}`. A case that fails
//! gives `{"error": message}`. To add an operation, add an arm to `run` and a
//! script in `peer/`.

use std::io::Read;

use serde_json::{json, Value};
use t2spline::{KnotVector, NurbsCurve};

type Outcome = Result<Value, String>;

fn field<'a>(case: &'a Value, key: &str) -> Result<&'a Value, String> {
    case.get(key).ok_or_else(|| format!("missing key `{key}`"))
}

fn numbers(v: &Value, key: &str) -> Result<Vec<f64>, String> {
    v.as_array()
        .ok_or_else(|| format!("`{key}` is not a list"))?
        .iter()
        .map(|x| {
            x.as_f64()
                .ok_or_else(|| format!("`{key}` holds a non-number"))
        })
        .collect()
}

fn usize_field(case: &Value, key: &str) -> Result<usize, String> {
    field(case, key)?
        .as_u64()
        .map(|x| x as usize)
        .ok_or_else(|| format!("`{key}` is not a count"))
}

fn f64_field(case: &Value, key: &str) -> Result<f64, String> {
    field(case, key)?
        .as_f64()
        .ok_or_else(|| format!("`{key}` is not a number"))
}

fn curve<const D: usize>(case: &Value) -> Result<NurbsCurve<D>, String> {
    let degree = usize_field(case, "degree")?;
    let points = field(case, "points")?
        .as_array()
        .ok_or("`points` is not a list")?
        .iter()
        .map(|p| {
            let v = numbers(p, "points[i]")?;
            <[f64; D]>::try_from(v).map_err(|_| format!("a point does not have {D} coordinates"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let weights = numbers(field(case, "weights")?, "weights")?;
    let knots = numbers(field(case, "knots")?, "knots")?;
    let knots = KnotVector::try_new(knots, degree, points.len()).map_err(|e| e.to_string())?;
    NurbsCurve::try_new(points, weights, knots).map_err(|e| e.to_string())
}

/// Points as lists (serde serializes arrays only of fixed sizes).
fn lists<const D: usize>(points: &[[f64; D]]) -> Vec<Vec<f64>> {
    points.iter().map(|p| p.to_vec()).collect()
}

fn curve_json<const D: usize>(c: &NurbsCurve<D>) -> Value {
    json!({
        "degree": c.degree(),
        "knots": c.knots().as_slice(),
        "points": lists(c.control_points()),
        "weights": c.weights(),
    })
}

fn run<const D: usize>(case: &Value) -> Outcome {
    let c = curve::<D>(case)?;
    let op = field(case, "op")?.as_str().ok_or("`op` is not text")?;
    let error = |e: t2spline::Error| e.to_string();
    Ok(match op {
        "derivatives" => {
            let order = usize_field(case, "order")?;
            let params = numbers(field(case, "params")?, "params")?;
            let ders = params
                .iter()
                .map(|&t| c.derivatives(t, order).map(|d| lists(&d)))
                .collect::<Result<Vec<_>, _>>()
                .map_err(error)?;
            json!({ "derivatives": ders })
        }
        "insert" => {
            let d = c
                .insert_knot(f64_field(case, "knot")?, usize_field(case, "times")?)
                .map_err(error)?;
            json!({ "curve": curve_json(&d) })
        }
        "refine" => {
            let new = numbers(field(case, "new_knots")?, "new_knots")?;
            json!({ "curve": curve_json(&c.refine_knots(&new).map_err(error)?) })
        }
        "elevate" => {
            let d = c
                .elevate_degree(usize_field(case, "times")?)
                .map_err(error)?;
            json!({ "curve": curve_json(&d) })
        }
        "split" => {
            let [l, r] = c.split_at(f64_field(case, "t")?).map_err(error)?;
            json!({ "pieces": [curve_json(&l), curve_json(&r)] })
        }
        other => return Err(format!("unknown op `{other}`")),
    })
}

fn dimension(case: &Value) -> Option<usize> {
    case.get("points")?.get(0)?.as_array().map(Vec::len)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut text = String::new();
    std::io::stdin().read_to_string(&mut text)?;
    let input: Value = serde_json::from_str(&text)?;
    let cases = input
        .get("cases")
        .and_then(Value::as_array)
        .ok_or("the input needs a list `cases`")?;
    let results: Vec<Value> = cases
        .iter()
        .map(|case| {
            let outcome = match dimension(case) {
                Some(2) => run::<2>(case),
                Some(3) => run::<3>(case),
                _ => Err("points must have 2 or 3 coordinates".to_owned()),
            };
            outcome.unwrap_or_else(|e| json!({ "error": e }))
        })
        .collect();
    println!("{}", json!({ "results": results }));
    Ok(())
}
