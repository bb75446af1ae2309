//! Surfaces as depth-sorted facets (the painter's algorithm), and the 3-D box
//! with its ticks.
//!
//! Every grid cell of a sampled surface becomes a quadrilateral, and every
//! line drawn on a surface (isoparametric lines, boundaries) travels with a
//! quadrilateral or as a segment of its own; all of them, of every surface of
//! a panel, are sorted by the depth of their centre and drawn farthest first,
//! so what is nearer covers what is behind. Opaque faces are shaded by
//! [`Camera::brightness`]; translucent envelopes are not.

use crate::chart::paint::{Color, Fill, Stroke, GREY};
use crate::chart::scene::{Facet, Mark, Panel, Xy};
use crate::chart::ticks::{decimals_for, nice_ticks, tick_label};
use crate::figures::surface::camera::{cross, Camera, Xyz};

/// A facet and the depth it is sorted by.
pub type Deep = (f64, Facet);

/// A sampled surface: its grid of points `points[a·sv + b]`, `[su, sv]`.
#[derive(Clone, Copy, Debug)]
pub struct GridRef<'a> {
    /// The points, row by row.
    pub points: &'a [Xyz],
    /// `[su, sv]`.
    pub shape: [usize; 2],
}

impl GridRef<'_> {
    fn at(&self, a: usize, b: usize) -> Xyz {
        self.points[a * self.shape[1] + b]
    }
}

/// How faces are coloured.
#[derive(Clone, Copy)]
pub enum Paint<'a> {
    /// One colour, shaded by the light.
    Shaded(Color),
    /// Translucent and unshaded (an envelope).
    Translucent(&'a Fill),
    /// By a value per grid point (the mean of the cell's four corners,
    /// coloured by `colour`), shaded lightly: brightness `1 − LIGHT_SHADE·(1 − b)`.
    Values(&'a [f64], &'a dyn Fn(f64) -> Color),
}

/// How much the light darkens faces coloured by values: a quarter at most, so
/// their colours stay readable against the colour bar.
pub const VALUE_SHADE: f64 = 0.25;

/// Every `stride`-th grid line (and the last) carries an isoparametric line:
/// about eight per direction.
fn stride(n: usize) -> usize {
    (n.saturating_sub(1) / 8).max(1)
}

fn on_line(i: usize, n: usize) -> bool {
    i % stride(n) == 0 || i + 1 == n
}

fn scaled(c: Color, f: f64) -> Color {
    let m = |v: u8| (f64::from(v) * f).round().clamp(0.0, 255.0) as u8;
    Color(m(c.0), m(c.1), m(c.2))
}

/// The faces of a surface, each with the isoparametric lines along its edges
/// (`iso`, every [`stride`]-th grid line; shared edges are drawn by both
/// faces, so the nearer one draws it last).
#[must_use]
pub fn faces(cam: &Camera, g: GridRef<'_>, paint: Paint<'_>, iso: Option<&Stroke>) -> Vec<Deep> {
    let [su, sv] = g.shape;
    let mut out = Vec::with_capacity(su.saturating_sub(1) * sv.saturating_sub(1));
    for a in 0..su.saturating_sub(1) {
        for b in 0..sv.saturating_sub(1) {
            let corners = [
                g.at(a, b),
                g.at(a + 1, b),
                g.at(a + 1, b + 1),
                g.at(a, b + 1),
            ];
            let q = corners.map(|p| cam.to_box(p));
            if q.iter().flatten().any(|v| !v.is_finite()) {
                continue;
            }
            let diag = |i: usize, j: usize| std::array::from_fn(|k| q[i][k] - q[j][k]);
            let normal = cross(diag(2, 0), diag(3, 1));
            let depth = q.iter().map(|&p| cam.box_depth(p)).sum::<f64>() / 4.0;
            let fill = match paint {
                Paint::Shaded(c) => Fill {
                    color: scaled(c, cam.brightness(normal)),
                    opacity: 1.0,
                },
                Paint::Translucent(f) => f.clone(),
                Paint::Values(v, colour) => {
                    let at = |i: usize, j: usize| v[i * sv + j];
                    let mean = 0.25 * (at(a, b) + at(a + 1, b) + at(a + 1, b + 1) + at(a, b + 1));
                    let shade = 1.0 - VALUE_SHADE * (1.0 - cam.brightness(normal));
                    Fill {
                        color: scaled(colour(mean), shade),
                        opacity: 1.0,
                    }
                }
            };
            let screen = q.map(|p| cam.screen(p));
            let mut lines = Vec::new();
            if iso.is_some() {
                // Edges: a = const at a and a + 1, b = const at b and b + 1.
                if on_line(a, su) {
                    lines.push([screen[0], screen[3]]);
                }
                if on_line(a + 1, su) {
                    lines.push([screen[1], screen[2]]);
                }
                if on_line(b, sv) {
                    lines.push([screen[0], screen[1]]);
                }
                if on_line(b + 1, sv) {
                    lines.push([screen[3], screen[2]]);
                }
            }
            out.push((
                depth,
                Facet {
                    points: screen.to_vec(),
                    fill,
                    stroke: (!lines.is_empty()).then(|| iso.cloned()).flatten(),
                    lines,
                },
            ));
        }
    }
    out
}

/// Segments of a boundary drawn as one facet: long enough for dashes to run
/// on, short enough to be hidden and shown in the right places.
const RUN: usize = 4;

/// The four boundary curves of a surface, in stretches of [`RUN`] segments,
/// each sorted by its mean depth.
#[must_use]
pub fn boundary(cam: &Camera, g: GridRef<'_>, stroke: &Stroke) -> Vec<Deep> {
    let [su, sv] = g.shape;
    let (last_a, last_b) = (su.saturating_sub(1), sv.saturating_sub(1));
    let curves: [Vec<Xyz>; 4] = [
        (0..su).map(|a| g.at(a, 0)).collect(),
        (0..su).map(|a| g.at(a, last_b)).collect(),
        (0..sv).map(|b| g.at(0, b)).collect(),
        (0..sv).map(|b| g.at(last_a, b)).collect(),
    ];
    let mut out = Vec::new();
    for c in &curves {
        let finite: Vec<Xyz> = c
            .iter()
            .copied()
            .filter(|p| p.iter().all(|v| v.is_finite()))
            .collect();
        for run in finite.windows(2).collect::<Vec<_>>().chunks(RUN) {
            let depth = run
                .iter()
                .map(|w| cam.depth(w[0]) + cam.depth(w[1]))
                .sum::<f64>()
                / (2 * run.len()) as f64;
            out.push((
                depth,
                Facet {
                    points: Vec::new(),
                    fill: Fill {
                        color: stroke.color,
                        opacity: 0.0,
                    },
                    lines: run
                        .iter()
                        .map(|w| [cam.project(w[0]), cam.project(w[1])])
                        .collect(),
                    stroke: Some(stroke.clone()),
                },
            ));
        }
    }
    out
}

/// The facets sorted farthest first (the painter's algorithm), as one mark.
#[must_use]
pub fn painted(mut facets: Vec<Deep>) -> Mark {
    facets.sort_by(|a, b| a.0.total_cmp(&b.0));
    Mark::Mesh {
        facets: facets.into_iter().map(|(_, f)| f).collect(),
    }
}

/// The length of a tick, in box units (the longest side is 1).
const TICK: f64 = 0.025;

/// The corner of the box with signs `s` (−1 or +1 per coordinate).
fn corner(cam: &Camera, s: [f64; 3]) -> Xyz {
    std::array::from_fn(|k| s[k] * cam.half[k])
}

/// The back of the box, drawn before the surfaces: the edges of the three
/// faces that look away from the viewer.
pub fn back(p: &mut Panel, cam: &Camera) {
    let mut segs = Vec::new();
    for k in 0..3 {
        // The face of the box at coordinate k = ±half whose outward normal
        // points away from the viewer.
        let mut normal = [0.0; 3];
        normal[k] = 1.0;
        let side = if cam.box_depth(normal) > 0.0 {
            -1.0
        } else {
            1.0
        };
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let mut ring = Vec::new();
        for (si, sj) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let mut s = [0.0; 3];
            (s[k], s[i], s[j]) = (side, si, sj);
            ring.push(cam.screen(corner(cam, s)));
        }
        for e in 0..4 {
            segs.push([ring[e], ring[(e + 1) % 4]]);
        }
    }
    p.push(
        "box",
        Mark::Segments {
            segments: segs,
            stroke: Stroke::solid(GREY, 0.8),
        },
    );
}

/// The edge along coordinate `k` that carries its ticks: at the bottom (the
/// top when looking from below) and on the near side for x and y; the
/// leftmost vertical edge for z. Returns the signs of the other two
/// coordinates.
fn tick_edge(cam: &Camera, k: usize) -> [f64; 3] {
    let mut best = [0.0; 3];
    let mut score = f64::NEG_INFINITY;
    for si in [-1.0, 1.0] {
        for sj in [-1.0, 1.0] {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            let mut s = [0.0; 3];
            (s[i], s[j]) = (si, sj);
            let mid = corner(cam, s);
            let value = if k == 2 {
                -cam.screen(mid)[0]
            } else {
                // Low on the screen and near the viewer.
                -cam.screen(mid)[1] + 1e-3 * cam.box_depth(mid)
            };
            if value > score {
                (score, best) = (value, s);
            }
        }
    }
    best
}

/// The ticks, tick labels and axis names of the box, on one edge per
/// coordinate, pointing away from the box's centre.
pub fn ticks(p: &mut Panel, cam: &Camera, names: [&str; 3]) {
    let mut segs = Vec::new();
    let mut texts: Vec<(Xy, String)> = Vec::new();
    for (k, name) in names.iter().enumerate() {
        let s = tick_edge(cam, k);
        let mid = cam.screen(corner(cam, s));
        let len = mid[0].hypot(mid[1]);
        let out = if len > 0.0 {
            [mid[0] / len, mid[1] / len]
        } else {
            [0.0, -1.0]
        };
        let [lo, hi] = cam.bounds[k];
        let (values, step) = nice_ticks(lo, hi, 5);
        let decimals = decimals_for(step);
        for v in values.into_iter().filter(|v| (lo..=hi).contains(v)) {
            let mut d = cam.bounds.map(|[lo, hi]| 0.5 * (lo + hi));
            d[k] = v;
            let mut q = cam.to_box(d);
            for c in (0..3).filter(|&c| c != k) {
                q[c] = s[c] * cam.half[c];
            }
            let at = cam.screen(q);
            let end = [at[0] + TICK * out[0], at[1] + TICK * out[1]];
            segs.push([at, end]);
            texts.push((
                [at[0] + 3.2 * TICK * out[0], at[1] + 3.2 * TICK * out[1]],
                tick_label(v, decimals).replace('-', "−"),
            ));
        }
        texts.push((
            [mid[0] + 7.5 * TICK * out[0], mid[1] + 7.5 * TICK * out[1]],
            (*name).to_owned(),
        ));
    }
    p.push(
        "ticks",
        Mark::Segments {
            segments: segs,
            stroke: Stroke::solid(GREY, 1.0),
        },
    );
    for (n, (at, text)) in texts.into_iter().enumerate() {
        p.push(format!("tick-{n}"), Mark::Text { at, text });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figures::aspect::Aspect;
    use crate::figures::surface::camera::View;

    fn plane(z: f64) -> Vec<Xyz> {
        let mut v = Vec::new();
        for a in 0..3 {
            for b in 0..3 {
                v.push([f64::from(a), f64::from(b), z]);
            }
        }
        v
    }

    #[test]
    fn the_nearer_of_two_parallel_planes_is_drawn_last() {
        let bounds = [[0.0, 2.0], [0.0, 2.0], [0.0, 1.0]];
        // Looking down, up and obliquely from above and below.
        for (view, top_nearer) in [
            ((0.0, 90.0), true),
            ((0.0, -90.0), false),
            ((-60.0, 30.0), true),
            ((20.0, -40.0), false),
        ] {
            let cam = Camera::new(
                View::try_new(view.0, view.1).unwrap(),
                bounds,
                Aspect::Equal,
            );
            let (low, high) = (plane(0.0), plane(1.0));
            let mut all = faces(
                &cam,
                GridRef {
                    points: &low,
                    shape: [3, 3],
                },
                Paint::Shaded(GREY),
                None,
            );
            // The top plane's colour is dark whatever the light (a shade of (1, 2, 3)).
            all.extend(faces(
                &cam,
                GridRef {
                    points: &high,
                    shape: [3, 3],
                },
                Paint::Shaded(Color(1, 2, 3)),
                None,
            ));
            all.reverse(); // the order built must not matter
            let Mark::Mesh { facets } = painted(all) else {
                unreachable!()
            };
            assert_eq!(facets.len(), 8);
            let top = |f: &Facet| f.fill.color.2 <= 3;
            let position = |p: Xyz| {
                let is_top = p[2] > 0.5;
                facets
                    .iter()
                    .position(|f| f.points[0] == cam.project(p) && top(f) == is_top)
                    .unwrap()
            };
            // Each face of one plane and the face straight above or below it
            // overlap on the screen: the nearer is drawn after the other.
            for a in 0..2 {
                for b in 0..2 {
                    let (x, y) = (f64::from(a), f64::from(b));
                    let (lo, hi) = (position([x, y, 0.0]), position([x, y, 1.0]));
                    assert_eq!(hi > lo, top_nearer, "{view:?} face ({a}, {b})");
                }
            }
            if view.1.abs() == 90.0 {
                // Straight on, depth is height alone: one plane after the other.
                assert!(facets[..4].iter().all(|f| top(f) != top_nearer), "{view:?}");
            }
        }
    }
}
