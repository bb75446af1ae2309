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
//! A curve is `{"degree", "knots", "points", "weights"}`.
//!
//! Surface cases (3-D) have `"degree": [p, q]`, `"knots": [U, V]`,
//! `"points": [[[x, y, z], …], …]` (`points[i][j]`, `i` along u) and
//! `"weights"` of the same shape, and the operations
//!
//! | op | extra keys | result keys |
//! |---|---|---|
//! | `surface_derivatives` | `params` (pairs `[u, v]`), `order` | `derivatives`: per pair, `d[k][l]` for `k + l ≤ order` |
//! | `surface_insert` | `direction` (`"u"`/`"v"`), `knot`, `times` | `surface` |
//! | `surface_refine` | `direction`, `new_knots` | `surface` |
//! | `surface_elevate` | `direction`, `times` | `surface` |
//! | `surface_split` | `direction`, `t` | `pieces`: two surfaces |
//!
//! A case that fails gives `{"error": message}`. To add an operation, add an
//! arm to `run` (or `run_surface`) and a script in `peer/`.

use std::io::Read;

use serde_json::{json, Value};
use t2spline::{Direction, KnotVector, NurbsCurve, NurbsSurface};

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

fn pair(v: &Value, key: &str) -> Result<[usize; 2], String> {
    let a = v
        .as_array()
        .ok_or_else(|| format!("`{key}` is not a pair"))?;
    let get = |k: usize| a.get(k).and_then(Value::as_u64).map(|x| x as usize);
    match (a.len(), get(0), get(1)) {
        (2, Some(p), Some(q)) => Ok([p, q]),
        _ => Err(format!("`{key}` is not a pair of counts")),
    }
}

fn surface(case: &Value) -> Result<NurbsSurface<3>, String> {
    let degree = pair(field(case, "degree")?, "degree")?;
    let rows = |key: &str| -> Result<Vec<Vec<Value>>, String> {
        field(case, key)?
            .as_array()
            .ok_or_else(|| format!("`{key}` is not a list"))?
            .iter()
            .map(|r| {
                r.as_array()
                    .cloned()
                    .ok_or_else(|| format!("`{key}` holds a non-list"))
            })
            .collect()
    };
    let points = rows("points")?
        .iter()
        .map(|r| {
            r.iter()
                .map(|p| {
                    let v = numbers(p, "points[i][j]")?;
                    <[f64; 3]>::try_from(v)
                        .map_err(|_| "a point does not have 3 coordinates".to_owned())
                })
                .collect::<Result<Vec<_>, _>>()
        })
        .collect::<Result<Vec<_>, _>>()?;
    let weights = rows("weights")?
        .iter()
        .map(|r| numbers(&Value::Array(r.clone()), "weights[i]"))
        .collect::<Result<Vec<_>, _>>()?;
    let knots = field(case, "knots")?
        .as_array()
        .ok_or("`knots` is not a list")?;
    if knots.len() != 2 {
        return Err("`knots` needs two lists".to_owned());
    }
    let shape = [points.len(), points.first().map_or(0, Vec::len)];
    let make = |k: usize| {
        KnotVector::try_new(numbers(&knots[k], "knots")?, degree[k], shape[k])
            .map_err(|e| e.to_string())
    };
    NurbsSurface::try_new(points, weights, [make(0)?, make(1)?]).map_err(|e| e.to_string())
}

fn surface_json(s: &NurbsSurface<3>) -> Value {
    let [_, nv] = s.shape();
    json!({
        "degree": s.degree(),
        "knots": [s.knots(Direction::U).as_slice(), s.knots(Direction::V).as_slice()],
        "points": s.control_points().chunks(nv).map(lists).collect::<Vec<_>>(),
        "weights": s.weights().chunks(nv).collect::<Vec<_>>(),
    })
}

fn direction(case: &Value) -> Result<Direction, String> {
    match field(case, "direction")?.as_str() {
        Some("u") => Ok(Direction::U),
        Some("v") => Ok(Direction::V),
        _ => Err("`direction` is not \"u\" or \"v\"".to_owned()),
    }
}

fn run_surface(case: &Value, op: &str) -> Outcome {
    let s = surface(case)?;
    let error = |e: t2spline::Error| e.to_string();
    Ok(match op {
        "surface_derivatives" => {
            let order = usize_field(case, "order")?;
            let params = field(case, "params")?
                .as_array()
                .ok_or("`params` is not a list")?;
            let ders = params
                .iter()
                .map(|uv| {
                    let uv = numbers(uv, "params[i]")?;
                    let d = s.derivatives(uv[0], uv[1], order).map_err(error)?;
                    Ok(d.iter().map(|row| lists(row)).collect::<Vec<_>>())
                })
                .collect::<Result<Vec<_>, String>>()?;
            json!({ "derivatives": ders })
        }
        "surface_insert" => {
            let d = s
                .insert_knot(
                    direction(case)?,
                    f64_field(case, "knot")?,
                    usize_field(case, "times")?,
                )
                .map_err(error)?;
            json!({ "surface": surface_json(&d) })
        }
        "surface_refine" => {
            let new = numbers(field(case, "new_knots")?, "new_knots")?;
            json!({ "surface": surface_json(&s.refine_knots(direction(case)?, &new).map_err(error)?) })
        }
        "surface_elevate" => {
            let d = s
                .elevate_degree(direction(case)?, usize_field(case, "times")?)
                .map_err(error)?;
            json!({ "surface": surface_json(&d) })
        }
        "surface_split" => {
            let [a, b] = s
                .split_at(direction(case)?, f64_field(case, "t")?)
                .map_err(error)?;
            json!({ "pieces": [surface_json(&a), surface_json(&b)] })
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
            let op = case.get("op").and_then(Value::as_str).unwrap_or("");
            let outcome = match dimension(case) {
                _ if op.starts_with("surface_") => run_surface(case, op),
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
