//! Rasterising the SVG figures to PNG (feature `png`, on by default) with
//! resvg, using only the bundled font, so PNG and SVG are the same picture and
//! text renders on a machine without fonts.

use std::sync::{Arc, OnceLock};

use resvg::tiny_skia;
use resvg::usvg::{self, fontdb};

use crate::chart::font::{FONT_BYTES, FONT_FAMILY};

/// The decoded image type, for checking PNG files.
pub use resvg::tiny_skia::Pixmap;

/// Pixels per SVG unit in PNG files: 3 gives a 640-unit figure 1920 pixels
/// wide, 300 dpi at 6.4 inches.
pub const PNG_SCALE: f32 = 3.0;

/// The resolution written into PNG files (their `pHYs` chunk), so that a
/// typesetting program places a 1920-pixel figure at 6.4 inches.
pub const PNG_DPI: f64 = 300.0;

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

/// Renders SVG text to PNG bytes at `scale` pixels per SVG unit, with a
/// `pHYs` chunk saying [`PNG_DPI`].
///
/// # Errors
/// A message if the SVG does not parse or the image would be empty or too large.
///
/// # Examples
/// ```
/// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="10" height="5"><rect width="10" height="5" fill="red"/></svg>"#;
/// let png = t2spline_plot::svg_to_png(svg, 2.0)?;
/// assert_eq!(&png[1..4], b"PNG");
/// // 300 dpi = 11811 pixels per metre, in the chunk after the header.
/// assert_eq!(&png[37..41], b"pHYs");
/// assert_eq!(u32::from_be_bytes(png[41..45].try_into().unwrap()), 11811);
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
    let png = pixmap.encode_png().map_err(|e| e.to_string())?;
    Ok(with_resolution(png, PNG_DPI))
}

/// `png` with a `pHYs` chunk of `dpi` dots per inch inserted after its
/// header (PNG specification §11.3.5.3: pixels per metre, unit 1).
fn with_resolution(mut png: Vec<u8>, dpi: f64) -> Vec<u8> {
    // Signature (8 bytes), then IHDR: length, type, 13 bytes, CRC.
    const AFTER_HEADER: usize = 8 + 4 + 4 + 13 + 4;
    if png.len() < AFTER_HEADER || &png[12..16] != b"IHDR" {
        return png;
    }
    let per_metre = (dpi / 0.0254).round() as u32;
    let mut chunk = Vec::with_capacity(21);
    chunk.extend_from_slice(&9u32.to_be_bytes());
    chunk.extend_from_slice(b"pHYs");
    chunk.extend_from_slice(&per_metre.to_be_bytes());
    chunk.extend_from_slice(&per_metre.to_be_bytes());
    chunk.push(1);
    let crc = crc32fast::hash(&chunk[4..]);
    chunk.extend_from_slice(&crc.to_be_bytes());
    png.splice(AFTER_HEADER..AFTER_HEADER, chunk);
    png
}
