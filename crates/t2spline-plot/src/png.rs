//! Rasterising the SVG figures to PNG (feature `png`, on by default) with
//! resvg, using only the bundled font, so PNG and SVG are the same picture and
//! text renders on a machine without fonts.

use std::sync::{Arc, OnceLock};

use resvg::tiny_skia;
use resvg::usvg::{self, fontdb};

use crate::font::{FONT_BYTES, FONT_FAMILY};

/// The decoded image type, for checking PNG files.
pub use resvg::tiny_skia::Pixmap;

/// Pixels per SVG unit in PNG files: 3 gives a 640-unit figure 1920 pixels
/// wide, 300 dpi at 6.4 inches.
pub const PNG_SCALE: f32 = 3.0;

fn fonts() -> Arc<fontdb::Database> {
    static DB: OnceLock<Arc<fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = fontdb::Database::new();
        db.load_font_data(FONT_BYTES.to_vec());
        db.set_sans_serif_family(FONT_FAMILY);
        db.set_serif_family(FONT_FAMILY);
        Arc::new(db)
    })
    .clone()
}

/// Renders SVG text to PNG bytes at `scale` pixels per SVG unit.
///
/// # Errors
/// A message if the SVG does not parse or the image would be empty or too large.
///
/// # Examples
/// ```
/// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="10" height="5"><rect width="10" height="5" fill="red"/></svg>"#;
/// let png = t2spline_plot::png::svg_to_png(svg, 2.0)?;
/// assert_eq!(&png[1..4], b"PNG");
/// # Ok::<(), String>(())
/// ```
pub fn svg_to_png(svg: &str, scale: f32) -> Result<Vec<u8>, String> {
    let options = usvg::Options {
        font_family: FONT_FAMILY.to_owned(),
        fontdb: fonts(),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &options).map_err(|e| e.to_string())?;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(scale)
        .ok_or("the scaled image has no pixels")?;
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or("the image is empty or too large")?;
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap.encode_png().map_err(|e| e.to_string())
}
