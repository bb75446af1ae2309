//! numpy's `.npy` format, as far as a raster of readings needs it: a 2-D
//! array of little-endian 64- or 32-bit floats in C order.
//!
//! The format (numpy's `numpy.lib.format`): the magic `\x93NUMPY`, the
//! version's major and minor byte, the header's length (2 bytes little-endian
//! in version 1.0, 4 bytes in 2.0 and 3.0), the header (a Python dict
//! literal, Latin-1 in 1.0 and 2.0, UTF-8 in 3.0, padded with spaces and a
//! newline), then the data:
//!
//! ```text
//! {'descr': '<f8', 'fortran_order': False, 'shape': (480, 640), }
//! ```
//!
//! Anything else is refused, saying what was found and what is read: another
//! type (`'>f8'`, `'<i4'`, an object array), Fortran order, another number of
//! dimensions, data shorter or longer than the shape. The crates that read
//! the format bring a parser of Python literals (and its grammar
//! engine) along for these three keys, so the few rules are followed here.

use std::io::Read;
use std::path::Path;

use super::fields::shorten;
use super::raster::{Raster, RasterGeometry, MAX_RASTER_CELLS};
use crate::error::{Error, Problem};

/// The largest `.npy` file read: [`MAX_RASTER_CELLS`] 64-bit floats and a
/// header.
pub const MAX_NPY_BYTES: u64 = (MAX_RASTER_CELLS as u64) * 8 + (1 << 16);

/// Reads a raster from the bytes of a `.npy` file, its cells placed by
/// `geometry`; `source` names the file in messages.
///
/// # Errors
/// [`Error::Invalid`] naming what was found for a file that is not a `.npy`
/// file of a 2-D C-order array of `'<f8'` or `'<f4'`, whose data do not
/// match its shape, with more than [`MAX_RASTER_CELLS`] cells (checked before
/// they are stored), or a geometry whose values are not finite or whose
/// spacing is 0.
///
/// # Examples
/// ```
/// # use t2spline_io::{parse_npy, RasterGeometry};
/// let header = "{'descr': '<f8', 'fortran_order': False, 'shape': (1, 2), }";
/// let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
/// let padded = format!("{header:<117}\n"); // 10 + 118 bytes: a multiple of 64
/// bytes.extend((padded.len() as u16).to_le_bytes());
/// bytes.extend(padded.as_bytes());
/// bytes.extend(1.5f64.to_le_bytes());
/// bytes.extend(f64::NAN.to_le_bytes());
/// let geometry = RasterGeometry { origin: [10.0, 20.0], spacing: [2.0, -2.0] };
/// let raster = parse_npy(&bytes, "g.npy", &geometry)?;
/// assert_eq!((raster.shape, raster.x.clone(), raster.y.clone()), ([1, 2], vec![10.0, 12.0], vec![20.0]));
/// assert!(raster.values[0] == 1.5 && raster.values[1].is_nan());
/// # Ok::<(), t2spline_io::Error>(())
/// ```
pub fn parse_npy(bytes: &[u8], source: &str, geometry: &RasterGeometry) -> Result<Raster, Error> {
    let refuse = |message: String| Error::Invalid {
        file: source.to_owned(),
        problems: vec![Problem::new(message)],
    };
    let rest = bytes.strip_prefix(b"\x93NUMPY").ok_or_else(|| {
        refuse("not a .npy file: it does not start with numpy's magic `\\x93NUMPY`".into())
    })?;
    let (&[major, minor], rest) = rest
        .split_first_chunk::<2>()
        .ok_or_else(|| refuse("a .npy file cut short in its version".into()))?;
    let (length, rest) = match major {
        1 => {
            let (l, rest) = rest
                .split_first_chunk::<2>()
                .ok_or_else(|| refuse("a .npy file cut short in its header".into()))?;
            (usize::from(u16::from_le_bytes(*l)), rest)
        }
        2 | 3 => {
            let (l, rest) = rest
                .split_first_chunk::<4>()
                .ok_or_else(|| refuse("a .npy file cut short in its header".into()))?;
            (
                usize::try_from(u32::from_le_bytes(*l)).unwrap_or(usize::MAX),
                rest,
            )
        }
        _ => {
            return Err(refuse(format!(
                "a .npy file of version {major}.{minor}; versions 1.0, 2.0 and 3.0 are read"
            )))
        }
    };
    let (header, data) = rest
        .split_at_checked(length)
        .ok_or_else(|| refuse("a .npy file cut short in its header".into()))?;
    // Latin-1 (versions 1 and 2) is a byte per character; the keys and
    // values read are ASCII either way.
    let header: String = if major == 3 {
        String::from_utf8_lossy(header).into_owned()
    } else {
        header.iter().map(|&b| char::from(b)).collect()
    };
    let descr = string_value(&header, "descr").ok_or_else(|| {
        refuse(format!(
            "the header has no 'descr' string: `{}`",
            shorten(header.trim())
        ))
    })?;
    let width = match descr.as_str() {
        "<f8" => 8,
        "<f4" => 4,
        other => {
            return Err(refuse(format!(
                "an array of type '{}'; rasters are read as little-endian floats, '<f8' or '<f4' (in numpy: a.astype('<f8'))",
                shorten(other)
            )))
        }
    };
    match word_value(&header, "fortran_order").as_deref() {
        Some("False") => {}
        Some("True") => {
            return Err(refuse(
                "an array in Fortran order; rasters are read in C order (in numpy: np.save(path, np.ascontiguousarray(a)))".into(),
            ))
        }
        _ => {
            return Err(refuse(format!(
                "the header has no 'fortran_order' True or False: `{}`",
                shorten(header.trim())
            )))
        }
    }
    let shape = shape_value(&header).ok_or_else(|| {
        refuse(format!(
            "the header has no 'shape' of whole numbers: `{}`",
            shorten(header.trim())
        ))
    })?;
    let [rows, columns] = shape[..] else {
        return Err(refuse(format!(
            "an array of {} dimension(s); a raster is a 2-D array (rows, columns)",
            shape.len()
        )));
    };
    let Some(cells) = rows.checked_mul(columns).filter(|&n| n <= MAX_RASTER_CELLS) else {
        return Err(refuse(format!(
            "an array of {rows} × {columns} cells, more than the limit of {MAX_RASTER_CELLS}"
        )));
    };
    if data.len() != cells * width {
        return Err(refuse(format!(
            "{} bytes of data, but {rows} × {columns} values of {width} bytes are {}",
            data.len(),
            cells * width
        )));
    }
    let values: Vec<f64> = if width == 8 {
        data.chunks_exact(8)
            .map(|c| f64::from_le_bytes(c.try_into().unwrap_or([0; 8])))
            .collect()
    } else {
        data.chunks_exact(4)
            .map(|c| f64::from(f32::from_le_bytes(c.try_into().unwrap_or([0; 4]))))
            .collect()
    };
    if let Some((k, v)) = values
        .iter()
        .enumerate()
        .find(|(_, v)| !(v.is_nan() || (v.is_finite() && v.abs() <= t2spline::MAX_MAGNITUDE)))
    {
        return Err(refuse(format!(
            "cell ({}, {}) = {v}: a reading is a finite number within [-1e150, 1e150], or NaN for no data",
            k / columns.max(1),
            k % columns.max(1)
        )));
    }
    let RasterGeometry {
        origin: [x0, y0],
        spacing: [dx, dy],
    } = *geometry;
    let good = |v: f64| v.is_finite() && v.abs() <= t2spline::MAX_MAGNITUDE;
    if !(good(x0) && good(y0) && good(dx) && good(dy)) || dx == 0.0 || dy == 0.0 {
        return Err(refuse(
            "the origin and spacing are finite numbers within [-1e150, 1e150], the spacing not 0"
                .into(),
        ));
    }
    Ok(Raster {
        source: source.to_owned(),
        shape: [rows, columns],
        values,
        x: (0..columns).map(|j| x0 + dx * j as f64).collect(),
        y: (0..rows).map(|i| y0 + dy * i as f64).collect(),
    })
}

/// The text after `'key':` in the header, without leading spaces.
fn after_key<'h>(header: &'h str, key: &str) -> Option<&'h str> {
    let at = header
        .find(&format!("'{key}'"))
        .or_else(|| header.find(&format!("\"{key}\"")))?;
    let rest = header.get(at + key.len() + 2..)?.trim_start();
    Some(rest.strip_prefix(':')?.trim_start())
}

/// A quoted string value.
fn string_value(header: &str, key: &str) -> Option<String> {
    let rest = after_key(header, key)?;
    let quote = rest.chars().next().filter(|c| *c == '\'' || *c == '"')?;
    let body = rest.get(1..)?;
    Some(body.get(..body.find(quote)?)?.to_owned())
}

/// A bare word value (`True`, `False`).
fn word_value(header: &str, key: &str) -> Option<String> {
    let rest = after_key(header, key)?;
    Some(rest.chars().take_while(char::is_ascii_alphabetic).collect())
}

/// The `shape` tuple: whole numbers, `()`, `(n,)` or `(r, c)`.
fn shape_value(header: &str) -> Option<Vec<usize>> {
    let rest = after_key(header, "shape")?.strip_prefix('(')?;
    let body = rest.get(..rest.find(')')?)?;
    body.split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.strip_suffix('L').unwrap_or(s).parse::<usize>().ok())
        .collect()
}

/// Reads the `.npy` file at `path` (at most [`MAX_NPY_BYTES`], checked
/// before reading) as [`parse_npy`] does.
///
/// # Errors
/// [`Error::Read`] if the file cannot be read; [`Error::Invalid`] if it is
/// larger than [`MAX_NPY_BYTES`], and the errors of [`parse_npy`].
pub fn read_npy(path: &Path, geometry: &RasterGeometry) -> Result<Raster, Error> {
    let name = path.display().to_string();
    let failed = |source| Error::Read {
        path: path.to_owned(),
        source,
    };
    let file = std::fs::File::open(path).map_err(failed)?;
    let size = file.metadata().map_err(failed)?.len();
    let too_large = || {
        Error::Invalid {
        file: name.clone(),
        problems: vec![Problem::new(format!(
            "a .npy file larger than the limit of {MAX_NPY_BYTES} bytes ({MAX_RASTER_CELLS} cells of 8 bytes and a header)"
        ))],
    }
    };
    if size > MAX_NPY_BYTES {
        return Err(too_large());
    }
    let mut bytes = Vec::new();
    file.take(MAX_NPY_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(failed)?;
    if bytes.len() as u64 > MAX_NPY_BYTES {
        return Err(too_large());
    }
    parse_npy(&bytes, &name, geometry)
}
