//! Figures of the shipped example and of a 3-D job: golden SVG text, decoded
//! PNG content, and layout rules (legends and labels cover no data).
//!
//! `T2SPLINE_BLESS=1 cargo test -p t2spline-plot` rewrites the golden files in
//! `fixtures/plots/`; a reviewer reads the diff.

use std::path::{Path, PathBuf};

use t2spline::{Alpha, Axis};
use t2spline_plot::geometry::Rect;
use t2spline_plot::scene::{Figure, Mark};
use t2spline_plot::{all_figures, layout, svg, NumberChoice, FIGURE_NAMES};

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

fn figures(job: &str, alpha: f64, choice: NumberChoice) -> Vec<Figure> {
    let job = t2spline_io::read_job(&root().join(job)).unwrap();
    all_figures(&job, Alpha::try_new(alpha).unwrap(), choice).unwrap()
}

#[test]
fn svg_files_match_the_golden_files() {
    let bless = std::env::var("T2SPLINE_BLESS").as_deref() == Ok("1");
    let mut failures = Vec::new();
    for (case, job, alpha, choice) in cases() {
        let dir = root().join("fixtures/plots").join(case);
        for fig in figures(job, alpha, choice) {
            let text = svg::render(&fig);
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
fn every_figure_has_title_axes_labels_and_a_legend_or_colour_bar() {
    for (case, job, alpha, choice) in cases() {
        let figs = figures(job, alpha, choice);
        let names: Vec<&str> = figs.iter().map(|f| f.name).collect();
        assert_eq!(names, FIGURE_NAMES, "{case}");
        for fig in &figs {
            let text = svg::render(fig);
            assert!(
                text.contains(&format!("<title>{}</title>", svg::escape(&fig.title))),
                "{case}/{}",
                fig.name
            );
            for p in &fig.panels {
                assert!(
                    text.contains(&format!(">{}</text>", svg::escape(&p.x_label))),
                    "{case}/{}: x label",
                    fig.name
                );
                assert!(
                    text.contains(&format!(">{}</text>", svg::escape(&p.y_label))),
                    "{case}/{}: y label",
                    fig.name
                );
            }
            assert!(!fig.legend.is_empty(), "{case}/{}: legend", fig.name);
            let panels = if case.contains("3d") && fig.name != "number" {
                3
            } else {
                1
            };
            let panels = match fig.name {
                "stage4-defuzzified" if panels == 1 => 2,
                // The projections and the distance along the curve.
                "reductions" => panels + 1,
                _ => panels,
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

#[test]
fn curves_have_equal_aspect_and_legends_and_labels_cover_no_data() {
    for (case, job, alpha, choice) in cases() {
        for fig in figures(job, alpha, choice) {
            let l = layout::fit(&[&fig]);
            for (p, pl) in fig.panels.iter().zip(&l.panels) {
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
            }
            let legend = l.legend.as_ref().expect("legend");
            for (i, (p, pl)) in fig.panels.iter().zip(&l.panels).enumerate() {
                let o = layout::panel_obstacles(p, pl);
                if legend.panel == Some(i) {
                    assert_eq!(
                        o.hits(&legend.rect),
                        0,
                        "{case}/{}: legend covers data",
                        fig.name
                    );
                }
                let forbidden: Vec<Rect> = legend
                    .panel
                    .filter(|&j| j == i)
                    .map(|_| legend.rect)
                    .into_iter()
                    .collect();
                let placed: Vec<_> = t2spline_plot::labels::place(p, pl, &o, &forbidden)
                    .into_iter()
                    .flatten()
                    .collect();
                let wanted = p
                    .items
                    .iter()
                    .filter(|it| matches!(it.mark, Mark::Label { .. } | Mark::HRule { .. }))
                    .count();
                assert_eq!(
                    placed.len(),
                    wanted,
                    "{case}/{}: every label placed",
                    fig.name
                );
                for (k, a) in placed.iter().enumerate() {
                    assert!(
                        pl.plot.contains_rect(&a.rect),
                        "{case}/{}: label outside",
                        fig.name
                    );
                    for f in &forbidden {
                        assert!(
                            !a.rect.overlaps(f),
                            "{case}/{}: label under the legend",
                            fig.name
                        );
                    }
                    for b in &placed[k + 1..] {
                        assert!(
                            !a.rect.overlaps(&b.rect),
                            "{case}/{}: labels overlap",
                            fig.name
                        );
                    }
                }
            }
        }
    }
}

#[cfg(feature = "png")]
mod png {
    use super::*;
    use resvg_tiny_skia::Pixmap;

    mod resvg_tiny_skia {
        pub use t2spline_plot::png::Pixmap;
    }

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
    fn png_files_decode_to_the_svg_size_times_three_with_text_and_series() {
        let figs = figures("examples/paper-alg-1-1.json", 0.8, NumberChoice::default());
        let files = t2spline_plot::render_files(&figs, t2spline_plot::Format::Png).unwrap();
        assert_eq!(files.len(), 7);
        for (fig, (name, bytes)) in figs.iter().zip(&files) {
            assert_eq!(name, &format!("{}.png", fig.name));
            let pixmap = Pixmap::decode_png(bytes).unwrap();
            let l = layout::fit(&[fig]);
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
        // Series colours: the upper layers (blue) and lower layers (vermillion) of stage 1.
        let stage1 = Pixmap::decode_png(&files[1].1).unwrap();
        assert!(
            count(&stage1, [0x00, 0x72, 0xb2]) > 5_000,
            "blue upper layers"
        );
        assert!(
            count(&stage1, [0xd5, 0x5e, 0x00]) > 5_000,
            "vermillion lower layers"
        );
        // The sweep has the viridis ends in its colour bar.
        let sweep = Pixmap::decode_png(&files[5].1).unwrap();
        assert!(
            count(&sweep, [0x44, 0x01, 0x54]) > 1_000,
            "dark purple (α = 0)"
        );
        assert!(count(&sweep, [0xfd, 0xe7, 0x25]) > 1_000, "yellow (α = 1)");
    }
}
