//! The envelope of a fuzzy surface (docs/method.md §12) as a GeoTIFF that a
//! GIS opens: one 64-bit float band per level, membership function and bound.
//!
//! The file is a baseline little-endian TIFF 6.0 with one image: `nx × ny`
//! pixels, north-up (row 0 is the greatest y), bands stored one after the
//! other (`PlanarConfiguration = 2`) in strips of about 256 KiB, no
//! compression, `SampleFormat = 3` (IEEE float), `BitsPerSample = 64`.
//! GeoTIFF 1.0 places it: `ModelPixelScale` (33550) `[dx, dy, 0]` and
//! `ModelTiepoint` (33922) the top-left corner `(0, 0, 0) ↦ (x0, y1, 0)`,
//! pixels as areas; with a CRS a `GeoKeyDirectory` (34735) whose
//! `GTModelTypeGeoKey` says projected (1) or geographic (2) and whose
//! `ProjectedCSTypeGeoKey` (3072) or `GeographicTypeGeoKey` (2048) holds the
//! EPSG code. GDAL's own tags name the bands and the missing value:
//! `GDAL_METADATA` (42112), XML with one
//! `<Item name="DESCRIPTION" sample="K" role="description">` per band
//! (`alpha=0.5 membership=upper bound=lower`), and `GDAL_NODATA` (42113),
//! `nan`.
//!
//! Written here rather than with the `tiff` crate: its encoder fixes the
//! samples of a pixel at compile time (a `ColorType` with a constant list of
//! bit depths), so an image of any number of float bands, stored plane by
//! plane, cannot be described to it; what is needed is a header, one
//! directory and the planes, about a hundred lines that the tests read back
//! with rasterio (GDAL).

use std::io::{self, Write};

use t2spline::set::{Envelope, MEMBERSHIPS};

use crate::set::envelope_table::membership_name;

/// Whether an EPSG code names a projected or a geographic CRS.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CrsKind {
    /// Planar coordinates (metres, feet): `ProjectedCSTypeGeoKey`.
    Projected,
    /// Longitude and latitude in degrees: `GeographicTypeGeoKey`.
    Geographic,
}

/// A coordinate reference system by its EPSG code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Crs {
    /// The EPSG code.
    pub code: u16,
    /// Projected or geographic.
    pub kind: CrsKind,
}

/// Geographic 2-D CRSs commonly met, which [`Crs::parse`] knows without a
/// suffix: WGS 84, ETRS89, NAD83, NAD27, GDA94, GDA2020, NAD83(CSRS),
/// NAD83(2011), SIRGAS 2000, JGD2011, CGCS2000, NZGD2000, Pulkovo 1942,
/// ED50, OSGB36.
pub const GEOGRAPHIC_CODES: [u16; 15] = [
    4326, 4258, 4269, 4267, 4283, 7844, 4617, 6318, 4674, 6668, 4490, 4167, 4284, 4230, 4277,
];

impl Crs {
    /// `EPSG:CODE`, optionally followed by `:projected` or `:geographic`.
    /// Without a suffix, the codes of [`GEOGRAPHIC_CODES`] are geographic
    /// and every other code projected (the CRS of most terrain data: UTM,
    /// national grids, Web Mercator 3857).
    ///
    /// # Errors
    /// A message saying what is expected, for any other text.
    ///
    /// # Examples
    /// ```
    /// # use t2spline_io::set::{Crs, CrsKind};
    /// assert_eq!(Crs::parse("EPSG:4326")?.kind, CrsKind::Geographic);
    /// assert_eq!(Crs::parse("epsg:32610")?, Crs { code: 32610, kind: CrsKind::Projected });
    /// assert_eq!(Crs::parse("EPSG:4490:geographic")?.kind, CrsKind::Geographic);
    /// assert!(Crs::parse("WGS84").is_err());
    /// # Ok::<(), String>(())
    /// ```
    pub fn parse(text: &str) -> Result<Crs, String> {
        let bad = || {
            format!(
                "`{}` is not EPSG:CODE (1 to 65535), optionally followed by :projected or :geographic",
                crate::printable(text)
            )
        };
        let mut parts = text.trim().split(':');
        let (Some(authority), Some(code)) = (parts.next(), parts.next()) else {
            return Err(bad());
        };
        if !authority.eq_ignore_ascii_case("epsg") {
            return Err(bad());
        }
        let code: u16 = code.parse().ok().filter(|&c| c > 0).ok_or_else(bad)?;
        let kind = match parts.next() {
            None if GEOGRAPHIC_CODES.contains(&code) => CrsKind::Geographic,
            None => CrsKind::Projected,
            Some(k) if k.eq_ignore_ascii_case("projected") => CrsKind::Projected,
            Some(k) if k.eq_ignore_ascii_case("geographic") => CrsKind::Geographic,
            Some(_) => return Err(bad()),
        };
        if parts.next().is_some() {
            return Err(bad());
        }
        Ok(Crs { code, kind })
    }
}

/// Bytes of a strip at most (whole rows; at least one row).
const STRIP_BYTES: usize = 1 << 18;

/// TIFF field types.
const ASCII: u16 = 2;
const SHORT: u16 = 3;
const LONG: u16 = 4;
const DOUBLE: u16 = 12;

/// One directory entry: tag, type, count and the value's bytes.
struct Entry {
    tag: u16,
    kind: u16,
    count: u32,
    bytes: Vec<u8>,
}

fn shorts(tag: u16, values: &[u16]) -> Entry {
    Entry {
        tag,
        kind: SHORT,
        count: values.len() as u32,
        bytes: values.iter().flat_map(|v| v.to_le_bytes()).collect(),
    }
}

fn longs(tag: u16, values: &[u32]) -> Entry {
    Entry {
        tag,
        kind: LONG,
        count: values.len() as u32,
        bytes: values.iter().flat_map(|v| v.to_le_bytes()).collect(),
    }
}

fn doubles(tag: u16, values: &[f64]) -> Entry {
    Entry {
        tag,
        kind: DOUBLE,
        count: values.len() as u32,
        bytes: values.iter().flat_map(|v| v.to_le_bytes()).collect(),
    }
}

fn ascii(tag: u16, text: &str) -> Entry {
    let mut bytes = text.as_bytes().to_vec();
    bytes.push(0);
    Entry {
        tag,
        kind: ASCII,
        count: bytes.len() as u32,
        bytes,
    }
}

/// The bands in file order: description and values (row by row from the
/// least y, as the envelope stores them).
fn bands(e: &Envelope) -> Vec<(String, &[f64])> {
    let mut out = Vec::new();
    for level in &e.levels {
        for m in MEMBERSHIPS {
            if let Some(b) = level.get(m) {
                for (bound, values) in [("lower", &b.least), ("upper", &b.greatest)] {
                    let mut alpha = Vec::new();
                    // Writing to a Vec cannot fail.
                    let _ = crate::number::csv(&mut alpha, level.alpha);
                    let alpha = String::from_utf8_lossy(&alpha).into_owned();
                    out.push((
                        format!(
                            "alpha={alpha} membership={} bound={bound}",
                            membership_name(m)
                        ),
                        values.as_slice(),
                    ));
                }
            }
        }
    }
    out
}

/// Writes the envelope as a GeoTIFF (module docs), with the CRS if given.
///
/// # Errors
/// The errors of `w`; [`io::ErrorKind::InvalidInput`] for an envelope with
/// no band or past the 4 GiB of a classic TIFF.
pub fn write_envelope_geotiff<W: Write + ?Sized>(
    w: &mut W,
    e: &Envelope,
    crs: Option<Crs>,
) -> io::Result<()> {
    let invalid = |m: &str| io::Error::new(io::ErrorKind::InvalidInput, m.to_owned());
    let bands = bands(e);
    let [nx, ny] = e.grid.shape();
    let row = nx * 8;
    let plane = row * ny;
    let data = plane as u64 * bands.len() as u64;
    if bands.is_empty() {
        return Err(invalid("the envelope has no band"));
    }
    if data + (1 << 20) > u64::from(u32::MAX) {
        return Err(invalid(
            "the envelope is larger than the 4 GiB of a TIFF file",
        ));
    }
    let rows_per_strip = (STRIP_BYTES / row).clamp(1, ny);
    let strips = ny.div_ceil(rows_per_strip);
    let mut offsets = Vec::with_capacity(strips * bands.len());
    let mut counts = Vec::with_capacity(strips * bands.len());
    for b in 0..bands.len() {
        for s in 0..strips {
            let rows = rows_per_strip.min(ny - s * rows_per_strip);
            offsets.push((8 + b * plane + s * rows_per_strip * row) as u32);
            counts.push((rows * row) as u32);
        }
    }
    let spp = bands.len() as u16;
    let [x0, _, _, y1] = e.grid.extent();
    let [dx, dy] = e.grid.cell_size();
    let mut xml = String::from("<GDALMetadata>\n");
    for (k, (description, _)) in bands.iter().enumerate() {
        xml.push_str(&format!(
            "  <Item name=\"DESCRIPTION\" sample=\"{k}\" role=\"description\">{description}</Item>\n"
        ));
    }
    xml.push_str(&format!(
        "  <Item name=\"EXACT\">{}</Item>\n</GDALMetadata>",
        e.exact
    ));
    let mut entries = vec![
        longs(256, &[nx as u32]),
        longs(257, &[ny as u32]),
        shorts(258, &vec![64; bands.len()]),
        shorts(259, &[1]),
        shorts(262, &[1]),
        longs(273, &offsets),
        shorts(277, &[spp]),
        longs(278, &[rows_per_strip as u32]),
        longs(279, &counts),
        shorts(284, &[if spp > 1 { 2 } else { 1 }]),
    ];
    if spp > 1 {
        entries.push(shorts(338, &vec![0; bands.len() - 1]));
    }
    entries.push(shorts(339, &vec![3; bands.len()]));
    entries.push(doubles(33550, &[dx, dy, 0.0]));
    entries.push(doubles(33922, &[0.0, 0.0, 0.0, x0, y1, 0.0]));
    if let Some(crs) = crs {
        let (model, key) = match crs.kind {
            CrsKind::Projected => (1, 3072),
            CrsKind::Geographic => (2, 2048),
        };
        // Version 1.1.0, three keys: model type, raster type (pixel is
        // area), and the CRS, sorted by key.
        entries.push(shorts(
            34735,
            &[
                1, 1, 0, 3, 1024, 0, 1, model, 1025, 0, 1, 1, key, 0, 1, crs.code,
            ],
        ));
    }
    entries.push(ascii(42112, &xml));
    entries.push(ascii(42113, "nan"));
    // Header, the planes, then the directory and the values that do not fit
    // in an entry.
    let ifd = 8 + data as usize;
    w.write_all(b"II")?;
    w.write_all(&42u16.to_le_bytes())?;
    w.write_all(&(ifd as u32).to_le_bytes())?;
    let mut buffer = Vec::with_capacity(row);
    for (_, values) in &bands {
        for j in (0..ny).rev() {
            buffer.clear();
            for v in &values[j * nx..(j + 1) * nx] {
                buffer.extend_from_slice(&v.to_le_bytes());
            }
            w.write_all(&buffer)?;
        }
    }
    let mut extra = ifd + 2 + 12 * entries.len() + 4;
    let mut tail: Vec<u8> = Vec::new();
    w.write_all(&(entries.len() as u16).to_le_bytes())?;
    for entry in &entries {
        w.write_all(&entry.tag.to_le_bytes())?;
        w.write_all(&entry.kind.to_le_bytes())?;
        w.write_all(&entry.count.to_le_bytes())?;
        if entry.bytes.len() <= 4 {
            let mut inline = [0u8; 4];
            inline[..entry.bytes.len()].copy_from_slice(&entry.bytes);
            w.write_all(&inline)?;
        } else {
            w.write_all(&(extra as u32).to_le_bytes())?;
            tail.extend_from_slice(&entry.bytes);
            extra += entry.bytes.len();
            // Values start on a word boundary.
            if extra % 2 == 1 {
                tail.push(0);
                extra += 1;
            }
        }
    }
    w.write_all(&0u32.to_le_bytes())?;
    w.write_all(&tail)
}

#[cfg(test)]
mod tests {
    use t2spline::set::PlanGrid;
    use t2spline::{Alpha, FuzzySurface, Nt2Number, Nt2Point};

    use super::*;

    /// Reads the directory back: `(tag, type, count, value bytes)`.
    fn entries(file: &[u8]) -> Vec<(u16, u16, u32, Vec<u8>)> {
        let u16_at = |o: usize| u16::from_le_bytes([file[o], file[o + 1]]);
        let u32_at =
            |o: usize| u32::from_le_bytes([file[o], file[o + 1], file[o + 2], file[o + 3]]);
        let ifd = u32_at(4) as usize;
        (0..usize::from(u16_at(ifd)))
            .map(|k| {
                let o = ifd + 2 + 12 * k;
                let (tag, kind, count) = (u16_at(o), u16_at(o + 2), u32_at(o + 4));
                let size =
                    count as usize * [0, 1, 1, 2, 4, 8, 1, 1, 2, 4, 8, 4, 8][usize::from(kind)];
                let at = if size <= 4 {
                    o + 8
                } else {
                    u32_at(o + 8) as usize
                };
                (tag, kind, count, file[at..at + size].to_vec())
            })
            .collect()
    }

    #[test]
    fn a_small_envelope_reads_back() {
        let c = |x: f64| Nt2Number::try_crisp(x).expect("finite");
        let z = |h: f64| {
            Nt2Number::try_new(h, [h - 1.0, h + 1.0], [h - 0.5, h + 0.5], [h, h], 1.0)
                .expect("valid")
        };
        let p = |x: f64, y: f64| Nt2Point::new([c(x), c(y), z(x)]);
        let net = vec![
            vec![p(0.0, 0.0), p(0.0, 2.0)],
            vec![p(4.0, 0.0), p(4.0, 2.0)],
        ];
        let s =
            FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).expect("valid");
        let e = s
            .envelope(
                &PlanGrid::try_new(s.plan_extent(), [4, 2]).expect("grid"),
                &[Alpha::ZERO],
            )
            .expect("small");
        let mut file = Vec::new();
        write_envelope_geotiff(
            &mut file,
            &e,
            Some(Crs::parse("EPSG:32610").expect("a code")),
        )
        .expect("written");
        assert_eq!(&file[..4], b"II*\0");
        let d = entries(&file);
        let tags: Vec<u16> = d.iter().map(|e| e.0).collect();
        let mut sorted = tags.clone();
        sorted.sort_unstable();
        assert_eq!(tags, sorted, "entries sorted by tag");
        let find = |tag: u16| d.iter().find(|e| e.0 == tag).expect("present").3.clone();
        assert_eq!(find(277), 6u16.to_le_bytes());
        let xml = String::from_utf8(find(42112)).expect("text");
        assert!(xml.contains(r#"<Item name="DESCRIPTION" sample="5" role="description">alpha=0 membership=lower bound=upper</Item>"#), "{xml}");
        assert_eq!(find(42113), b"nan\0");
        let key: Vec<u16> = find(34735)
            .chunks(2)
            .map(|b| u16::from_le_bytes([b[0], b[1]]))
            .collect();
        assert_eq!(&key[12..], &[3072, 0, 1, 32610]);
        // Band 0 (upper, least), row 0 = the greatest y: z = x − 1 at x = 0.5.
        let first = u32::from_le_bytes(find(273)[..4].try_into().expect("four bytes")) as usize;
        let v = f64::from_le_bytes(file[first..first + 8].try_into().expect("eight bytes"));
        assert!((v - (0.5 - 1.0)).abs() < 1e-12, "{v}");
    }
}
