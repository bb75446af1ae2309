//! Figures of the shipped example, of a 3-D job and of generated jobs of 40
//! to 1000 control points: golden SVG text, layout rules (legends and labels
//! cover no data and no other text, notes say what was thinned), what the
//! legends list, and the numbers behind the new figures.
//!
//! `T2SPLINE_BLESS=1 cargo test -p t2spline-plot` rewrites the golden files in
//! `fixtures/plots/`; a reviewer reads the diff.

use std::path::{Path, PathBuf};

use t2spline::job::Job;
use t2spline::{Alpha, Axis};
use t2spline_plot::{
    all_figures, fit_layout, panel_obstacles, render_svg, Aspect, Figure, FigureOptions, Mark,
    NumberChoice, Rect, FIGURE_NAMES,
};

#[path = "../examples/many_points.rs"]
mod many_points;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// (case name, job file, alpha, number shown).
fn cases() -> Vec<(&'static str, &'static str, f64, NumberChoice)> {
    vec![
        (
            "paper-alpha-0.8",
            "examples/paper-alg-1-1.json",
            0.8,
            NumberChoice::default(),
        ),
        (
            "paper-alpha-0.5",
            "examples/paper-alg-1-1.json",
            0.5,
            NumberChoice {
                point: 2,
                axis: Axis::Y,
            },
        ),
        (
            "spiral-3d",
            "fixtures/spiral-3d.json",
            0.5,
            NumberChoice {
                point: 2,
                axis: Axis::Z,
            },
        ),
    ]
}

fn read(job: &str) -> Job {
    t2spline_io::read_job(&root().join(job)).unwrap()
}

fn figures_of(job: &Job, alpha: f64, options: FigureOptions) -> Vec<Figure> {
    all_figures(job, Alpha::try_new(alpha).unwrap(), &options).unwrap()
}

fn figures(job: &str, alpha: f64, number: NumberChoice) -> Vec<Figure> {
    figures_of(
        &read(job),
        alpha,
        FigureOptions {
            number,
            ..FigureOptions::default()
        },
    )
}

/// A generated job of `n` control points.
fn many(n: usize, dim: usize) -> Job {
    let text = many_points::job(n, dim, 1).to_string();
    t2spline_io::parse_job(&text, "generated").unwrap()
}

#[test]
fn svg_files_match_the_golden_files() {
    let bless = std::env::var("T2SPLINE_BLESS").as_deref() == Ok("1");
    let mut failures = Vec::new();
    for (case, job, alpha, choice) in cases() {
        let dir = root().join("fixtures/plots").join(case);
        for fig in figures(job, alpha, choice) {
            let text = render_svg(&fig);
            let path = dir.join(format!("{}.svg", fig.name));
            if bless {
                std::fs::create_dir_all(&dir).unwrap();
                std::fs::write(&path, &text).unwrap();
                continue;
            }
            let golden = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e} (run with T2SPLINE_BLESS=1)", path.display()));
            if golden != text {
                let line = golden
                    .lines()
                    .zip(text.lines())
                    .position(|(a, b)| a != b)
                    .map_or(golden.lines().count().min(text.lines().count()), |i| i)
                    + 1;
                failures.push(format!("{} differs from line {line}", path.display()));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{failures:#?}\nrerun with T2SPLINE_BLESS=1 and review the diff"
    );
}

#[test]
fn every_figure_has_title_axes_labels_and_a_legend() {
    for (case, job, alpha, choice) in cases() {
        let figs = figures(job, alpha, choice);
        let names: Vec<&str> = figs.iter().map(|f| f.name).collect();
        // The figures of the plane are drawn for plane curves only.
        let expected = if case.contains("3d") {
            &FIGURE_NAMES[..9]
        } else {
            &FIGURE_NAMES[..]
        };
        assert_eq!(names, expected, "{case}");
        for fig in &figs {
            let text = render_svg(fig);
            assert!(
                text.contains(&format!("<title>{}</title>", escape(&fig.title))),
                "{case}/{}",
                fig.name
            );
            for p in &fig.panels {
                for label in [&p.x_label, &p.y_label] {
                    assert!(
                        text.contains(&format!(">{}</text>", escape(label))),
                        "{case}/{}: axis label {label}",
                        fig.name
                    );
                }
            }
            assert!(!fig.legend.is_empty(), "{case}/{}: legend", fig.name);
            let three_d = case.contains("3d");
            let panels = match fig.name {
                "number" | "alpha-sweep" | "distance-alpha" | "section" => 1,
                "membership" => 2,
                // The length, and the area of a plane curve.
                "measures" => {
                    if three_d {
                        1
                    } else {
                        2
                    }
                }
                // The projections and the magnified panel, or the distance
                // along the curve.
                "stage4-defuzzified" | "reductions" => {
                    if three_d {
                        4
                    } else {
                        2
                    }
                }
                _ => {
                    if three_d {
                        3
                    } else {
                        1
                    }
                }
            };
            assert_eq!(
                fig.panels.len(),
                panels,
                "{case}/{}: projections (and detail)",
                fig.name
            );
        }
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The layout rules every figure keeps: equal aspect where asked, ticks,
/// the legend on no data, every annotation placed, texts inside their panel
/// and on no other text or the legend, the subtitle within the page.
fn check_layout(case: &str, fig: &Figure) {
    let l = fit_layout(&[fig]);
    let legend = l.legend.as_ref().expect("legend");
    for (i, (p, pl)) in fig.panels.iter().zip(&l.panels).enumerate() {
        if p.equal_aspect {
            let sx = pl.plot.w / (pl.x.range[1] - pl.x.range[0]);
            let sy = pl.plot.h / (pl.y.range[1] - pl.y.range[0]);
            assert!(
                (sx / sy - 1.0).abs() < 1e-9,
                "{case}/{}: aspect {sx} vs {sy}",
                fig.name
            );
        }
        assert!(
            pl.x.ticks.len() >= 2 && pl.y.ticks.len() >= 2,
            "{case}/{}: ticks",
            fig.name
        );
        let o = panel_obstacles(p, pl);
        if legend.panel == Some(i) {
            assert_eq!(
                o.hits(&legend.rect),
                0,
                "{case}/{}: legend covers data",
                fig.name
            );
        }
        let placed: Vec<(usize, Rect)> = l.labels[i]
            .iter()
            .enumerate()
            .filter_map(|(k, p)| Some((k, p.clone()??.rect)))
            .collect();
        for (k, item) in p.items.iter().enumerate() {
            let always = match &item.mark {
                Mark::Label { priority, .. } => *priority == t2spline_plot::Priority::Always,
                Mark::HRule { label, .. } | Mark::VRule { label, .. } => !label.is_empty(),
                _ => false,
            };
            if always {
                assert!(
                    placed.iter().any(|(j, _)| *j == k),
                    "{case}/{}: {} not placed",
                    fig.name,
                    item.key
                );
            }
        }
        for (n, (_, a)) in placed.iter().enumerate() {
            assert!(
                pl.plot.contains_rect(a),
                "{case}/{}: label outside",
                fig.name
            );
            if legend.panel == Some(i) {
                assert!(
                    !a.overlaps(&legend.rect),
                    "{case}/{}: label under the legend",
                    fig.name
                );
            }
            for (_, b) in &placed[n + 1..] {
                assert!(
                    !a.overlaps(b),
                    "{case}/{}: labels overlap: {a:?} {b:?}",
                    fig.name
                );
            }
        }
    }
}

#[test]
fn curves_have_equal_aspect_and_legends_and_labels_cover_no_data() {
    for (case, job, alpha, choice) in cases() {
        for fig in figures(job, alpha, choice) {
            check_layout(case, &fig);
        }
    }
}

#[test]
fn every_point_of_a_small_job_is_named() {
    for fig in figures("examples/paper-alg-1-1.json", 0.8, NumberChoice::default())[1..4].iter() {
        let l = fit_layout(&[fig]);
        let named = fig.panels[0]
            .items
            .iter()
            .zip(&l.labels[0])
            .filter(|(it, p)| it.key.starts_with("name-") && matches!(p, Some(Some(_))))
            .count();
        assert_eq!(named, 4, "{}: names placed", fig.name);
    }
}

#[test]
fn jobs_of_40_to_1000_points_stay_readable() {
    for (n, dim) in [(40, 2), (200, 2), (200, 3), (1000, 2)] {
        let job = many(n, dim);
        let figs = figures_of(&job, 0.8, FigureOptions::default());
        let case = format!("{n} points, {dim}-D");
        for fig in &figs {
            check_layout(&case, fig);
            // No subtitle lists hundreds of weights.
            assert!(
                fig.subtitle.chars().count() < 140,
                "{case}/{}: {}",
                fig.name,
                fig.subtitle
            );
            if fig.name.starts_with("stage") {
                let names = fig.panels[0]
                    .items
                    .iter()
                    .filter(|it| it.key.starts_with("name-"))
                    .count();
                assert!(names <= 60, "{case}/{}: {names} names tried", fig.name);
            }
        }
        let stage2 = &figs[2];
        if n >= 200 {
            assert!(
                stage2
                    .notes
                    .iter()
                    .any(|s| s.contains(&format!("{n} control points"))),
                "{case}: the thinning is noted: {:?}",
                stage2.notes
            );
        }
        if n >= 1000 {
            assert!(
                stage2
                    .notes
                    .iter()
                    .any(|s| s.contains("cut ends not marked")),
                "{case}: {:?}",
                stage2.notes
            );
            assert!(stage2.panels[0]
                .items
                .iter()
                .all(|it| !it.key.starts_with("points-upper") || it.mark == Mark::Empty));
        }
    }
}

/// Every stroke, marker and fill a legend shows is drawn somewhere in the
/// figure.
fn legend_lists_only_what_is_drawn(fig: &Figure) {
    let marks: Vec<&Mark> = fig
        .panels
        .iter()
        .flat_map(|p| p.items.iter().map(|it| &it.mark))
        .collect();
    for e in &fig.legend {
        if let Some(s) = &e.line {
            let drawn = marks.iter().any(|m| match m {
                Mark::Line { stroke, .. } | Mark::Segments { stroke, .. } => stroke == s,
                _ => false,
            });
            assert!(
                drawn,
                "{}: legend line '{}' is not drawn",
                fig.name, e.label
            );
        }
        if let Some(f) = &e.fill {
            let drawn = marks.iter().any(
                |m| matches!(m, Mark::Area { fill, .. } | Mark::Region { fill, .. } if fill == f),
            );
            assert!(
                drawn,
                "{}: legend area '{}' is not drawn",
                fig.name, e.label
            );
        }
        if let Some(mk) = &e.marker {
            let drawn = marks.iter().any(|m| matches!(m, Mark::Markers { marker, .. } if marker.shape == mk.shape && marker.stroke == mk.stroke));
            assert!(
                drawn,
                "{}: legend marker '{}' is not drawn",
                fig.name, e.label
            );
        }
    }
    // Every area drawn is in the legend.
    for m in &marks {
        if let Mark::Area { fill, .. } | Mark::Region { fill, .. } = m {
            assert!(
                fig.legend.iter().any(|e| e.fill.as_ref() == Some(fill)),
                "{}: an unlabelled band",
                fig.name
            );
        }
    }
}

#[test]
fn legends_list_what_is_drawn_and_nothing_else() {
    let job = read("examples/paper-alg-1-1.json");
    for alpha in [0.3, 0.6, 0.8, 1.0] {
        let figs = figures_of(&job, alpha, FigureOptions::default());
        for fig in figs.iter().filter(|f| f.name != "number") {
            legend_lists_only_what_is_drawn(fig);
        }
        let lower = figs[2]
            .legend
            .iter()
            .any(|e| e.label.starts_with("lower cuts"));
        assert_eq!(
            lower,
            alpha <= 0.6,
            "alpha {alpha}: lower cuts listed only where drawn"
        );
    }
    for fig in figures_of(&many(200, 3), 0.5, FigureOptions::default())
        .iter()
        .filter(|f| f.name != "number")
    {
        legend_lists_only_what_is_drawn(fig);
    }
}

#[test]
fn stage3_left_and_right_curves_differ_in_colour_and_dash() {
    let figs = figures("examples/paper-alg-1-1.json", 0.8, NumberChoice::default());
    let stroke = |key: &str| {
        figs[3].panels[0]
            .items
            .iter()
            .find_map(|it| match (&it.mark, it.key == key) {
                (Mark::Line { stroke, .. }, true) => Some(stroke.clone()),
                _ => None,
            })
            .unwrap()
    };
    let (l, r) = (stroke("curve-left"), stroke("curve-right"));
    assert_ne!(l.color, r.color);
    assert_ne!(l.dash, r.dash);
}

#[test]
fn the_magnified_panel_resamples_its_stretch_of_curve() {
    // In the magnified panel of stage 4 neighbouring vertices lie a few
    // pixels apart: the curves are computed anew there, not taken from the
    // figure's samples, which would be tens of pixels apart at this zoom.
    for job in [
        read("examples/paper-alg-1-1.json"),
        many(40, 2),
        many(40, 3),
    ] {
        let fig = figures_of(&job, 0.8, FigureOptions::default()).swap_remove(4);
        let l = fit_layout(&[&fig]);
        let (zoom, pl) = (fig.panels.last().unwrap(), l.panels.last().unwrap());
        assert!(zoom.x_range.is_some(), "a magnified panel");
        for it in zoom.items.iter().filter(|it| it.key.starts_with("curve-")) {
            let Mark::Line { points, .. } = &it.mark else {
                panic!("a line")
            };
            let px: Vec<_> = points.iter().map(|&p| pl.to_px(p)).collect();
            let inside = px.iter().filter(|p| pl.plot.contains(**p)).count();
            assert!(inside > 50, "{}: {inside} vertices in the window", it.key);
            let longest = px
                .windows(2)
                .filter(|w| pl.plot.contains(w[0]) && pl.plot.contains(w[1]))
                .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
                .fold(0.0, f64::max);
            assert!(
                longest < 8.0,
                "{}: a straight stretch of {longest} px",
                it.key
            );
        }
    }
}

#[test]
fn the_distance_figure_shows_both_sides_of_the_jump_at_h() {
    let job = read("examples/paper-alg-1-1.json");
    let fig = figures_of(&job, 0.8, FigureOptions::default()).swap_remove(6);
    let markers = |key: &str| {
        fig.panels[0]
            .items
            .iter()
            .find_map(|it| match (&it.mark, it.key == key) {
                (Mark::Markers { points, .. }, true) => Some(points.clone()),
                _ => None,
            })
            .unwrap()
    };
    let (at, above) = (markers("max-at-h"), markers("max-above-h"));
    // No line bridges the jump: the curve breaks at h, and is drawn in two
    // stretches.
    let svg = render_svg(&fig);
    let line = svg
        .lines()
        .find(|l| l.contains("stroke=\"#000000\" stroke-width=\"1.8\""))
        .expect("the max line");
    assert!(
        line.starts_with("<path d=\"M") && line.matches('M').count() == 2,
        "{line}"
    );
    assert_eq!((at.len(), above.len()), (1, 1));
    assert_eq!(at[0][0], 0.6);
    // The paper's type reduction jumps at h: averaging three cut ends (the
    // lower one at the crisp value) or two.
    assert!(
        (above[0][1] - at[0][1]).abs() > 0.1 * at[0][1],
        "{at:?} {above:?}"
    );
    // The sampled maximum agrees with the run's exact error.max.
    let exact = |a: f64| {
        job.run(
            &job.settings(&t2spline::job::Overrides {
                alpha: Some(a),
                type_reduction: Some(t2spline::TypeReduction::Paper),
                samples: Some(vec![2]),
                derivatives: None,
            })
            .unwrap(),
        )
        .unwrap()
        .error
    };
    let e = exact(0.6);
    assert!(
        (at[0][1] - e.max).abs() <= 1e-3 * e.max,
        "sampled {} vs exact {}",
        at[0][1],
        e.max
    );
}

#[test]
fn aspect_auto_fits_each_axis_and_says_so() {
    let job = read("examples/paper-alg-1-1.json");
    let figs = figures_of(
        &job,
        0.8,
        FigureOptions {
            aspect: Aspect::Auto,
            ..FigureOptions::default()
        },
    );
    for fig in &figs[1..5] {
        assert!(
            fig.panels.iter().take(1).all(|p| !p.equal_aspect),
            "{}",
            fig.name
        );
        assert!(
            fig.notes.iter().any(|n| n.contains("not to scale")),
            "{}",
            fig.name
        );
    }
}

#[cfg(feature = "png")]
mod png {
    use super::*;
    use t2spline_plot::Pixmap;

    /// Pixels close to `rgb` (within 40 per channel).
    fn count(p: &Pixmap, rgb: [u8; 3]) -> usize {
        p.pixels()
            .iter()
            .filter(|c| {
                let c = c.demultiply();
                [c.red(), c.green(), c.blue()]
                    .iter()
                    .zip(rgb)
                    .all(|(a, b)| (i32::from(*a) - i32::from(b)).abs() <= 40)
            })
            .count()
    }

    #[test]
    fn png_files_are_three_times_the_svg_at_300_dpi_with_text_and_series() {
        let figs = figures("examples/paper-alg-1-1.json", 0.8, NumberChoice::default());
        let files = t2spline_plot::render_files(&figs, t2spline_plot::Format::Png).unwrap();
        assert_eq!(files.len(), FIGURE_NAMES.len());
        for (fig, (name, bytes)) in figs.iter().zip(&files) {
            assert_eq!(name, &format!("{}.png", fig.name));
            // pHYs after the header: 11811 pixels per metre both ways, unit metre.
            assert_eq!(&bytes[37..41], b"pHYs", "{name}");
            assert_eq!(
                &bytes[41..49],
                &[0, 0, 0x2e, 0x23, 0, 0, 0x2e, 0x23],
                "{name}"
            );
            assert_eq!(bytes[49], 1, "{name}");
            let pixmap = Pixmap::decode_png(bytes).unwrap();
            let l = fit_layout(&[fig]);
            assert_eq!(pixmap.width(), (l.width * 3.0).round() as u32, "{name}");
            assert_eq!(pixmap.height(), (l.height * 3.0).round() as u32, "{name}");
            let total = (pixmap.width() * pixmap.height()) as usize;
            let white = count(&pixmap, [255, 255, 255]);
            assert!(
                white > total / 3 && white < total,
                "{name}: {white} of {total} white"
            );
            // The title is text in the bundled font: dark pixels in its band.
            let band_top = ((l.title_baseline - 14.0) * 3.0) as u32;
            let band_bottom = ((l.title_baseline + 3.0) * 3.0) as u32;
            let dark = (band_top..band_bottom)
                .flat_map(|y| (0..pixmap.width()).map(move |x| (x, y)))
                .filter(|&(x, y)| {
                    let c = pixmap.pixel(x, y).unwrap().demultiply();
                    u32::from(c.red()) + u32::from(c.green()) + u32::from(c.blue()) < 200
                })
                .count();
            assert!(
                dark > 500,
                "{name}: title text rendered ({dark} dark pixels)"
            );
        }
        // Series colours: the upper layers (blue) and lower layers (vermillion)
        // of stage 1; the right type-reduced curve (orange) of stage 3.
        let stage1 = Pixmap::decode_png(&files[1].1).unwrap();
        assert!(
            count(&stage1, [0x00, 0x72, 0xb2]) > 5_000,
            "blue upper layers"
        );
        assert!(
            count(&stage1, [0xd5, 0x5e, 0x00]) > 5_000,
            "vermillion lower layers"
        );
        let stage3 = Pixmap::decode_png(&files[3].1).unwrap();
        assert!(
            count(&stage3, [0xe6, 0x9f, 0x00]) > 2_000,
            "orange right curve"
        );
    }
}
