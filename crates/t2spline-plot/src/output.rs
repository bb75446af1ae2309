//! Turning figures into file contents, all rendered in memory before a caller
//! writes any of them (the CLI writes them all or nothing).

use crate::chart::scene::Figure;
use crate::chart::svg;
use crate::error::Error;

/// Which files `plot` writes per figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Format {
    /// `NAME.svg` only.
    Svg,
    /// `NAME.png` only.
    Png,
    /// Both.
    #[default]
    Both,
}

impl Format {
    fn svg(self) -> bool {
        matches!(self, Format::Svg | Format::Both)
    }

    fn png(self) -> bool {
        matches!(self, Format::Png | Format::Both)
    }
}

/// The files of `figures` in `format`, as `(file name, bytes)`, in figure order.
///
/// # Errors
/// [`Error::Png`] if rasterising fails, or if PNG is asked for and the crate
/// was built without the `png` feature.
pub fn render_files(figures: &[Figure], format: Format) -> Result<Vec<(String, Vec<u8>)>, Error> {
    let mut files = Vec::new();
    for fig in figures {
        let text = svg::render(fig);
        if format.png() {
            files.push((format!("{}.png", fig.name), png_bytes(fig.name, &text)?));
        }
        if format.svg() {
            files.push((format!("{}.svg", fig.name), text.into_bytes()));
        }
    }
    Ok(files)
}

#[cfg(feature = "png")]
fn png_bytes(name: &str, svg: &str) -> Result<Vec<u8>, Error> {
    crate::chart::png::svg_to_png(svg, crate::chart::png::PNG_SCALE).map_err(|message| Error::Png {
        name: name.to_owned(),
        message,
    })
}

#[cfg(not(feature = "png"))]
fn png_bytes(name: &str, _svg: &str) -> Result<Vec<u8>, Error> {
    Err(Error::Png {
        name: name.to_owned(),
        message: "this build has no PNG support (feature `png`); use --format svg".into(),
    })
}
