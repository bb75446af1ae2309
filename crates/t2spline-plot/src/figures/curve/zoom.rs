//! The magnified panel of stage 4: a square window around the largest
//! distance, in which the crisp and the defuzzified curve are computed anew
//! by the library on the parameters that cross the window (reusing the
//! figure's samples there would draw a few straight segments).

use t2spline::job::{Job, Points, RunOutput};
use t2spline::Alpha;

use super::largest::{largest_distance, Ends};
use super::projection::{projections, Projection};
use super::series::{line, markers};
use crate::chart::scene::{Panel, Xy};
use crate::chart::ticks::short;
use crate::data;
use crate::error::Error;
use crate::figures::style::{crisp_marker, crisp_stroke, solution_marker, solution_stroke};

/// Samples of each curve per stretch crossing the window.
const ZOOM_SAMPLES: usize = 241;
/// The most stretches of curve drawn in the window (a dense curve can cross
/// it many times; those nearest the largest distance are kept).
const MAX_STRETCHES: usize = 12;

/// The projection where the largest distance looks longest (the plane in 2-D).
fn best_projection(dimension: usize, ends: &Ends) -> Projection {
    let mut all = projections(dimension);
    all.sort_by(|a, b| {
        let len = |p: &Projection| {
            let [c, d] = ends.projected(p.axes);
            (d[0] - c[0]).hypot(d[1] - c[1])
        };
        len(b).total_cmp(&len(a))
    });
    all[0]
}

/// The square window `[x0, x1] × [y0, y1]` around the largest distance: a
/// few times its length, at least 1 % of the curve's extent.
fn window(r: &RunOutput, ends: [Xy; 2], (i, j): (usize, usize)) -> ([f64; 2], [f64; 2]) {
    let mid = [
        0.5 * (ends[0][0] + ends[1][0]),
        0.5 * (ends[0][1] + ends[1][1]),
    ];
    let extent = [i, j]
        .iter()
        .map(|&a| {
            let v = r.samples.crisp.coord(a);
            let (lo, hi) = v
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| {
                    (l.min(x), h.max(x))
                });
            hi - lo
        })
        .fold(0.0, f64::max);
    let length = (ends[1][0] - ends[0][0]).hypot(ends[1][1] - ends[0][1]);
    let half = (4.0 * length)
        .max(0.01 * extent)
        .max(1e-12 * (1.0 + mid[0].abs() + mid[1].abs()));
    (
        [mid[0] - half, mid[0] + half],
        [mid[1] - half, mid[1] + half],
    )
}

/// The parameter intervals over which the sampled crisp or defuzzified curve
/// lies in the window grown by half, each widened by one sample on both
/// sides; those nearest `t` first.
fn stretches(
    r: &RunOutput,
    win: ([f64; 2], [f64; 2]),
    (i, j): (usize, usize),
    t: f64,
) -> Vec<[f64; 2]> {
    let grow = |w: [f64; 2]| {
        let h = 0.25 * (w[1] - w[0]);
        [w[0] - h, w[1] + h]
    };
    let (wx, wy) = (grow(win.0), grow(win.1));
    let inside = |pts: &Points, k: usize| {
        let (x, y) = (pts.coord(i)[k], pts.coord(j)[k]);
        (wx[0]..=wx[1]).contains(&x) && (wy[0]..=wy[1]).contains(&y)
    };
    let params = r.samples.params.along();
    let last = params.len().saturating_sub(1);
    let mut out: Vec<[f64; 2]> = Vec::new();
    let mut start = None;
    for k in 0..=params.len() {
        let hit =
            k < params.len() && (inside(&r.samples.crisp, k) || inside(&r.samples.defuzzified, k));
        match (hit, start) {
            (true, None) => start = Some(k),
            (false, Some(s)) => {
                out.push([params[s.saturating_sub(1)], params[k.min(last)]]);
                start = None;
            }
            _ => {}
        }
    }
    let gap = |s: &[f64; 2]| (s[0] - t).max(t - s[1]).max(0.0);
    out.sort_by(|a, b| gap(a).total_cmp(&gap(b)));
    out.truncate(MAX_STRETCHES);
    out.sort_by(|a, b| a[0].total_cmp(&b[0]));
    out
}

/// The crisp and the defuzzified curve of result `r` (its alpha and type
/// reduction) on each stretch, stretches separated by a gap (a non-finite
/// point).
fn curves(
    job: &Job,
    r: &RunOutput,
    stretches: &[[f64; 2]],
    (i, j): (usize, usize),
) -> Result<[Vec<Xy>; 2], Error> {
    let alpha = Alpha::try_new(r.alpha)?;
    let mut out = [Vec::new(), Vec::new()];
    for s in stretches {
        let params: Vec<f64> = (0..ZOOM_SAMPLES)
            .map(|k| {
                let f = k as f64 / (ZOOM_SAMPLES - 1) as f64;
                // The last parameter is the stretch's end exactly.
                if k + 1 == ZOOM_SAMPLES {
                    s[1]
                } else {
                    s[0] + f * (s[1] - s[0])
                }
            })
            .collect();
        let (c, d) = data::curves_at(&job.model, alpha, r.type_reduction, &params)?;
        for (line, pts) in out.iter_mut().zip([c, d]) {
            if !line.is_empty() {
                line.push([f64::NAN, f64::NAN]);
            }
            line.extend(pts.coord(i).iter().zip(pts.coord(j)).map(|(&x, &y)| [x, y]));
        }
    }
    Ok(out)
}

/// Control points inside the window.
fn within(points: &Points, (i, j): (usize, usize), win: ([f64; 2], [f64; 2])) -> Vec<Xy> {
    points
        .coord(i)
        .iter()
        .zip(points.coord(j))
        .filter(|(x, y)| (win.0[0]..=win.0[1]).contains(*x) && (win.1[0]..=win.1[1]).contains(*y))
        .map(|(&x, &y)| [x, y])
        .collect()
}

/// The magnified panel around the largest distance of `r`.
pub(super) fn zoom_panel(job: &Job, r: &RunOutput, ends: &Ends) -> Result<Panel, Error> {
    let pr = best_projection(r.dimension, ends);
    let ij = pr.axes;
    let e = &r.error;
    let win = window(r, ends.projected(ij), ij);
    let [crisp, solution] = curves(
        job,
        r,
        &stretches(r, win, ij, data::curve_spline(r).max_at),
        ij,
    )?;
    let mut p = pr.panel(crate::figures::aspect::Aspect::Equal);
    let projection = if r.dimension > 2 {
        format!(", {} projection", pr.name())
    } else {
        String::new()
    };
    p.title = Some(format!(
        "detail around t = {}{projection}",
        short(data::curve_spline(r).max_at, 4)
    ));
    p.x_range = Some(win.0);
    p.y_range = Some(win.1);
    line(&mut p, "curve-crisp", Some(crisp), crisp_stroke());
    line(
        &mut p,
        "curve-defuzzified",
        Some(solution),
        solution_stroke(),
    );
    let cp = &r.control_points;
    markers(
        &mut p,
        "points-crisp",
        within(&cp.crisp, ij, win),
        crisp_marker(),
        true,
    );
    markers(
        &mut p,
        "points-defuzzified",
        within(&cp.defuzzified, ij, win),
        solution_marker(),
        true,
    );
    let text = if e.max > 0.0 {
        short(e.max, 4)
    } else {
        "distance 0: the curves coincide".to_owned()
    };
    largest_distance(&mut p, ends.projected(ij), Some(text));
    Ok(p)
}
