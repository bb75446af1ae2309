//! What the surface figures of one result share: the scene, its panels and
//! the series drawn in them.

use t2spline::job::{Parameters, Points, RunOutput};
use t2spline::Layer;

use super::bins::Bins;
use super::camera::{Camera, View, Xyz};
use super::mesh::{self, Deep, GridRef, Paint};
use super::points::xyz;
use crate::chart::paint::{Color, Fill, Stroke, BLUE, GREEN, VERMILLION};
use crate::chart::scene::{Facet, Mark, Panel, Xy};
use crate::chart::ticks::short;
use crate::figures::aspect::Aspect;
use crate::figures::style::{crisp_marker, polygon_stroke, FUNCTIONS};

/// Nets of up to this many control points get interval bars and full-size
/// markers; larger ones are drawn without bars (a note says so).
pub const FEW_NET_POINTS: usize = 144;

/// A net with more rows or columns than this is drawn thinned: every k-th row
/// and column (and the last), at most this many lines each way, with the
/// points where they cross; a note says so.
pub const MOST_NET_LINES: usize = 12;

/// The isoparametric lines on a shaded surface.
#[must_use]
pub fn iso_stroke() -> Stroke {
    Stroke::solid(Color(0x44, 0x44, 0x44), 0.5)
}

/// What the surface figures of one result share: the result, the lower
/// heights, the camera and the shapes of the grid and the net.
#[derive(Debug)]
pub struct SurfaceScene<'a> {
    /// The result drawn (sampled on [`crate::data::surface_grid`]).
    pub r: &'a RunOutput,
    /// The distinct lower heights of the job, ascending.
    pub heights: &'a [f64],
    /// The view.
    pub view: View,
    /// The camera, over the box of every layer's net and surface (the same
    /// at every alpha).
    pub camera: Camera,
    /// `[su, sv]` of the samples.
    pub grid: [usize; 2],
    /// `[nu, nv]` of the net.
    pub net: [usize; 2],
}

impl<'a> SurfaceScene<'a> {
    /// The scene of surface result `r`.
    #[must_use]
    pub fn new(
        r: &'a RunOutput,
        heights: &'a [f64],
        view: View,
        aspect: Aspect,
    ) -> SurfaceScene<'a> {
        let (s, cp) = (&r.samples, &r.control_points);
        let mut bounds = [[f64::INFINITY, f64::NEG_INFINITY]; 3];
        let mut add = |p: &Points| {
            for (k, b) in bounds.iter_mut().enumerate() {
                for &v in p.coord(k).iter().filter(|v| v.is_finite()) {
                    *b = [b[0].min(v), b[1].max(v)];
                }
            }
        };
        for l in Layer::ALL {
            add(s.layer(l));
            add(cp.layers.get(l).unwrap_or(&cp.crisp));
        }
        let bounds = bounds.map(|[lo, hi]| if lo <= hi { [lo, hi] } else { [0.0, 1.0] });
        let len = |p: &Points| p.grid().unwrap_or([p.len(), 1]);
        SurfaceScene {
            r,
            heights,
            view,
            camera: Camera::new(view, bounds, aspect),
            grid: len(&s.crisp),
            net: len(&cp.crisp),
        }
    }

    /// A sampled surface of the result as a grid.
    #[must_use]
    pub fn grid_of<'p>(&self, points: &'p [Xyz]) -> GridRef<'p> {
        GridRef {
            points,
            shape: self.grid,
        }
    }

    /// Whether the net is small enough for interval bars.
    #[must_use]
    pub fn bars_shown(&self) -> bool {
        self.net[0] * self.net[1] <= FEW_NET_POINTS
    }

    /// The 3-D panel: the box's back, the depth-sorted `facets`, then what
    /// `overlay` adds (nets, bars, markers: drawn over the surfaces), then the
    /// ticks.
    pub fn view_panel(&self, facets: Vec<Deep>, overlay: impl FnOnce(&mut Panel)) -> Panel {
        let mut p = Panel::view();
        p.title = Some(format!(
            "view from azimuth {}°, elevation {}°",
            short(self.view.azimuth, 4),
            short(self.view.elevation, 4)
        ));
        mesh::back(&mut p, &self.camera);
        p.push("surfaces", mesh::painted(facets));
        overlay(&mut p);
        mesh::ticks(&mut p, &self.camera, ["x", "y", "z"]);
        p
    }

    /// The map over `(u, v)`: each grid cell coloured by `bins` at the mean of
    /// `values` (one per grid point) at its corners.
    #[must_use]
    pub fn map_panel(&self, title: &str, values: &[f64], bins: &Bins) -> Panel {
        let (u, v) = match &self.r.samples.params {
            Parameters::Grid { u, v } => (u.as_slice(), v.as_slice()),
            Parameters::Along(_) => (&[][..], &[][..]),
        };
        let mut p = Panel::graph("u", "v");
        p.title = Some(title.to_owned());
        let sv = v.len();
        let mut facets = Vec::new();
        for a in 0..u.len().saturating_sub(1) {
            for b in 0..sv.saturating_sub(1) {
                let at = |i: usize, j: usize| values.get(i * sv + j).copied().unwrap_or(0.0);
                let mean = 0.25 * (at(a, b) + at(a + 1, b) + at(a + 1, b + 1) + at(a, b + 1));
                facets.push(Facet {
                    points: vec![
                        [u[a], v[b]],
                        [u[a + 1], v[b]],
                        [u[a + 1], v[b + 1]],
                        [u[a], v[b + 1]],
                    ],
                    fill: Fill {
                        color: bins.colour(mean),
                        opacity: 1.0,
                    },
                    lines: Vec::new(),
                    stroke: None,
                });
            }
        }
        p.push("cells", Mark::Mesh { facets });
        p
    }

    /// Every how many rows and columns of the net are drawn: 1 up to
    /// [`MOST_NET_LINES`] lines each way, else the least step that keeps
    /// within it.
    #[must_use]
    pub fn net_step(&self) -> usize {
        let most = self.net[0].max(self.net[1]);
        if most <= MOST_NET_LINES {
            1
        } else {
            // Lines 0, k, 2k, … and the last: ⌈(n − 1) / k⌉ + 1 ≤ MOST_NET_LINES.
            (most - 1).div_ceil(MOST_NET_LINES - 1)
        }
    }

    /// The drawn lines among `n`: every [`Self::net_step`]-th and the last.
    fn drawn(&self, n: usize) -> impl Iterator<Item = usize> {
        let step = self.net_step();
        (0..n).filter(move |&i| i % step == 0 || i + 1 == n)
    }

    /// The control net through `points`, projected: its rows and columns
    /// (every [`Self::net_step`]-th on a large net), each through all its
    /// points.
    #[must_use]
    pub fn net_segments(&self, points: &Points) -> Vec<[Xy; 2]> {
        let p: Vec<Xy> = xyz(points)
            .into_iter()
            .map(|q| self.camera.project(q))
            .collect();
        let [nu, nv] = self.net;
        let mut segs = Vec::new();
        for a in self.drawn(nu) {
            segs.extend((1..nv).map(|b| [p[a * nv + b - 1], p[a * nv + b]]));
        }
        for b in self.drawn(nv) {
            segs.extend((1..nu).map(|a| [p[(a - 1) * nv + b], p[a * nv + b]]));
        }
        segs
    }

    /// The net's points, projected: where the drawn rows and columns cross.
    #[must_use]
    pub fn projected(&self, points: &Points) -> Vec<Xy> {
        let [nu, nv] = self.net;
        let p = xyz(points);
        self.drawn(nu)
            .flat_map(|a| self.drawn(nv).map(move |b| a * nv + b))
            .filter_map(|k| p.get(k).map(|&q| self.camera.project(q)))
            .collect()
    }

    /// The notes: thinning, and a coordinate stretched to fit the box.
    #[must_use]
    pub fn notes(&self) -> Vec<String> {
        let mut notes = Vec::new();
        let stretched: Vec<String> = (0..3)
            .filter(|&k| self.camera.stretch(k) > 1.0 + 1e-9)
            .map(|k| {
                format!(
                    "{} ×{}",
                    ["x", "y", "z"][k],
                    short(self.camera.stretch(k), 3)
                )
            })
            .collect();
        if !stretched.is_empty() {
            notes.push(format!(
                "3-D box not to scale: {} against the other coordinates.",
                stretched.join(", ")
            ));
        }
        if !self.bars_shown() {
            notes.push(format!(
                "{} × {} control points: interval bars left out (shown up to {FEW_NET_POINTS} points).",
                self.net[0], self.net[1]
            ));
        }
        let step = self.net_step();
        if step > 1 {
            notes.push(format!(
                "{} × {} control points: one row and column in {step} of the net drawn (and the last), with the points where they cross.",
                self.net[0], self.net[1]
            ));
        }
        notes.push(format!(
            "Surfaces drawn on a {} × {} grid; the control net is drawn over them.",
            self.grid[0], self.grid[1]
        ));
        notes
    }

    /// The crisp control net and points, drawn over the surfaces.
    pub fn crisp_net(&self, p: &mut Panel) {
        let cp = &self.r.control_points;
        p.push(
            "net",
            Mark::Segments {
                segments: self.net_segments(&cp.crisp),
                stroke: polygon_stroke(),
            },
        );
        let mut marker = crisp_marker();
        if !self.bars_shown() {
            marker.size = 3.0;
        }
        p.push(
            "points-crisp",
            Mark::Markers {
                points: self.projected(&cp.crisp),
                marker,
            },
        );
    }

    /// Through each crisp control point, a bar per function and coordinate
    /// from the left to the right value given by `ends(layer)` (a coordinate
    /// of a point absent where the value is), when the net is small enough.
    pub fn bars(&self, p: &mut Panel, ends: impl Fn(Layer) -> Vec<Vec<Option<f64>>>) {
        if !self.bars_shown() {
            return;
        }
        let crisp = xyz(&self.r.control_points.crisp);
        for ((left, right, name), stroke) in FUNCTIONS.iter().zip(bar_strokes()) {
            let (lo, hi) = (ends(*left), ends(*right));
            let mut segments = Vec::new();
            for (i, c) in crisp.iter().enumerate() {
                for k in 0..3 {
                    let end =
                        |e: &[Vec<Option<f64>>]| e.get(k).and_then(|v| v.get(i).copied().flatten());
                    if let (Some(a), Some(b)) = (end(&lo), end(&hi)) {
                        let (mut pa, mut pb) = (*c, *c);
                        (pa[k], pb[k]) = (a, b);
                        segments.push([self.camera.project(pa), self.camera.project(pb)]);
                    }
                }
            }
            p.push(format!("bars-{name}"), Mark::Segments { segments, stroke });
        }
    }

    /// The shaded crisp surface with its isoparametric lines.
    #[must_use]
    pub fn crisp_faces(&self, paint: Paint<'_>) -> Vec<Deep> {
        let crisp = xyz(&self.r.samples.crisp);
        mesh::faces(
            &self.camera,
            self.grid_of(&crisp),
            paint,
            Some(&iso_stroke()),
        )
    }

    /// Two surfaces as translucent envelopes in `fill`, with their boundaries.
    #[must_use]
    pub fn envelopes(&self, surfaces: [(&Points, Stroke); 2], fill: &Fill) -> Vec<Deep> {
        let mut out = Vec::new();
        for (s, stroke) in surfaces {
            let pts = xyz(s);
            out.extend(mesh::faces(
                &self.camera,
                self.grid_of(&pts),
                Paint::Translucent(fill),
                None,
            ));
            out.extend(mesh::boundary(&self.camera, self.grid_of(&pts), &stroke));
        }
        out
    }

    /// The boundary curves of a surface.
    #[must_use]
    pub fn outline(&self, s: &Points, stroke: &Stroke) -> Vec<Deep> {
        let pts = xyz(s);
        mesh::boundary(&self.camera, self.grid_of(&pts), stroke)
    }
}

/// The strokes of the upper, primary and lower bars (thinner for wider
/// intervals, so all show), as the curve figures draw them.
#[must_use]
pub fn bar_strokes() -> [Stroke; 3] {
    [
        Stroke::solid(BLUE, 1.2),
        Stroke::solid(GREEN, 2.6),
        Stroke::solid(VERMILLION, 4.4),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figures::surface::stage4_figure;
    use t2spline::Alpha;

    #[test]
    fn the_largest_distance_starts_at_the_projection_of_max_at() {
        // The terrain's distance is largest at its corner (u, v) = (1, 1),
        // whose crisp point is the last sample of the grid.
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/fuzzy-terrain.json"
        );
        let job = t2spline_io::read_job(std::path::Path::new(path)).unwrap();
        let alpha = Alpha::try_new(0.5).unwrap();
        let r = crate::data::compute(&job, alpha).unwrap();
        assert_eq!(r.error.max_at, t2spline::job::Parameter::Uv([1.0, 1.0]));
        let heights = job.model.heights();
        let scene = SurfaceScene::new(&r, &heights, View::DEFAULT, Aspect::Equal);
        let fig = stage4_figure(&job, &scene).unwrap();
        let ends = fig.panels[0]
            .items
            .iter()
            .find(|i| i.key == "distance-ends")
            .unwrap();
        let Mark::Markers { points, .. } = &ends.mark else {
            panic!()
        };
        let corner = xyz(&r.samples.crisp).last().copied().unwrap();
        let want = scene.camera.project(corner);
        assert!((points[0][0] - want[0]).abs() < 1e-9 && (points[0][1] - want[1]).abs() < 1e-9);
        let solution = xyz(&r.samples.defuzzified).last().copied().unwrap();
        let d = (0..3)
            .map(|k| (solution[k] - corner[k]).powi(2))
            .sum::<f64>()
            .sqrt();
        assert!(
            (d - r.error.max).abs() < 1e-9 * r.error.max.max(1.0),
            "{d} {}",
            r.error.max
        );
    }
}
