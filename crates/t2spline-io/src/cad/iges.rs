//! IGES 5.3 files of rational B-spline curves (entity 126), named by name
//! properties (entity 406, form 15).
//!
//! Five sections of 80-column records: Start (free text), Global (file
//! parameters: delimiters, precision, millimetres, dates), Directory (two
//! records of ten 8-column fields per entity), Parameter (the entity's
//! parameters in columns 1–64, its directory pointer in 66–72) and
//! Terminate (the record count of each section). Columns 73–80 hold the
//! section letter and the sequence number.
//!
//! Entity 126's parameters (IGES 5.3 §4.23):
//! ```text
//! 126, K, M, PROP1, PROP2, PROP3, PROP4,
//!      T(−M) … T(N+M),  W(0) … W(K),  X₀, Y₀, Z₀, … X_K, Y_K, Z_K,
//!      V(0), V(1), XNORM, YNORM, ZNORM
//! K = n − 1 (last control point), M = degree, N = 1 + K − M,
//! PROP1 planar, PROP2 closed, PROP3 polynomial (all weights equal), PROP4 periodic
//! ```
//! `V(0)`, `V(1)` are the domain `[U[p], U[n]]`, so unclamped knot vectors are
//! written as they are. The normal of planar (2-D) curves is `(0, 0, 1)`.
//! Surfaces are entity 128 (rational B-spline surface), named the same way.

use std::fmt::Write as _;

use t2spline::job::{Geometry, LengthUnit};
use t2spline::{Direction, NurbsCurve, NurbsSurface};

use super::meta::CadMeta;
use super::real::real;

/// The IGES text of `geometry`.
pub(super) fn render(geometry: &Geometry, meta: &CadMeta) -> String {
    let mut file = Sections::default();
    let mut start = String::from(
        "t2spline: a run's curves or surfaces as exact rational B-splines (entities 126 and 128).",
    );
    if let Some(d) = meta.description() {
        start.push(' ');
        start.push_str(d);
    }
    for line in wrap(&start.replace(['\n', '\r'], " "), 72) {
        file.start.push(line);
    }
    let global = global(meta);
    file.global = pack(&global, 72);
    let planar = geometry.dimension == 2;
    for curve in &geometry.curves {
        for (i, piece) in curve.pieces.iter().enumerate() {
            // The name property first, so that the curve can point to it.
            let name_de = file.entity(
                406,
                15,
                &format!("406,1,{};", hollerith(curve.name)),
                "NAME",
                0,
                "00010200",
            );
            let params = curve_parameters(piece, planar, name_de);
            let label: String = curve.name.chars().take(8).collect();
            file.entity(126, 0, &params, &label, i + 1, "00000000");
        }
    }
    for surface in &geometry.surfaces {
        for (i, patch) in surface.patches.iter().enumerate() {
            let name_de = file.entity(
                406,
                15,
                &format!("406,1,{};", hollerith(surface.name)),
                "NAME",
                0,
                "00010200",
            );
            let params = surface_parameters(patch, name_de);
            let label: String = surface.name.chars().take(8).collect();
            file.entity(128, 0, &params, &label, i + 1, "00000000");
        }
    }
    file.text()
}

/// The parameters of entity 128 (IGES 5.3 §4.24), ending with the pointer to
/// its name:
///
/// ```text
/// 128, K1, K2, M1, M2, PROP1 … PROP5 (closed u, closed v, polynomial, periodic u, periodic v),
///      S(−M1) … S(N1+M1), T(−M2) … T(N2+M2),
///      W(0,0), W(1,0), … W(K1,K2)            (the u index varying fastest)
///      X(0,0), Y(0,0), Z(0,0), …             (the same order)
///      U(0), U(1), V(0), V(1)
/// ```
fn surface_parameters(s: &NurbsSurface<3>, name_de: usize) -> String {
    let r = |x: f64| real(x, 'D');
    let [nu, nv] = s.shape();
    let [p, q] = s.degree();
    let w = s.weights();
    let polynomial = w.iter().all(|&x| x == w[0]);
    let mut params = vec![
        "128".to_owned(),
        (nu - 1).to_string(),
        (nv - 1).to_string(),
        p.to_string(),
        q.to_string(),
        "0".into(),
        "0".into(),
        u8::from(polynomial).to_string(),
        "0".into(),
        "0".into(),
    ];
    for direction in [Direction::U, Direction::V] {
        params.extend(s.knots(direction).as_slice().iter().map(|&u| r(u)));
    }
    // The net is stored row by row (`i·nv + j`); IGES lists it with i fastest.
    let order: Vec<usize> = (0..nv)
        .flat_map(|j| (0..nu).map(move |i| i * nv + j))
        .collect();
    params.extend(order.iter().filter_map(|&k| w.get(k)).map(|&x| r(x)));
    let points = s.control_points();
    for point in order.iter().filter_map(|&k| points.get(k)) {
        params.extend(point.iter().map(|&x| r(x)));
    }
    for direction in [Direction::U, Direction::V] {
        let d = s.domain(direction);
        params.extend([r(d.start), r(d.end)]);
    }
    params.extend(["0".into(), "1".into(), name_de.to_string()]);
    params.join(",") + ";"
}

/// The parameters of entity 126, ending with the pointer to its name.
fn curve_parameters(c: &NurbsCurve<3>, planar: bool, name_de: usize) -> String {
    let r = |x: f64| real(x, 'D');
    let w = c.weights();
    let polynomial = w.iter().all(|&x| x == w[0]);
    let d = c.domain();
    let mut p = vec![
        "126".to_owned(),
        (c.control_points().len() - 1).to_string(),
        c.degree().to_string(),
        u8::from(planar).to_string(),
        "0".into(),
        u8::from(polynomial).to_string(),
        "0".into(),
    ];
    p.extend(c.knots().as_slice().iter().map(|&u| r(u)));
    p.extend(w.iter().map(|&x| r(x)));
    for q in c.control_points() {
        p.extend(q.iter().map(|&x| r(x)));
    }
    p.extend([r(d.start), r(d.end)]);
    let normal = if planar { [0.0, 0.0, 1.0] } else { [0.0; 3] };
    p.extend(normal.iter().map(|&x| r(x)));
    // No associativities; one property: the name.
    p.extend(["0".into(), "1".into(), name_de.to_string()]);
    p.join(",") + ";"
}

/// The global section's parameters (IGES 5.3 §2.2.4.3), one string.
/// The IGES 5.3 unit flag (global parameter 14) of `units`.
fn unit_flag(units: LengthUnit) -> &'static str {
    match units {
        LengthUnit::Inch => "1",
        LengthUnit::Millimetre => "2",
        LengthUnit::Foot => "4",
        LengthUnit::Metre => "6",
        LengthUnit::Centimetre => "10",
    }
}

/// The IGES 5.3 unit name (global parameter 15) of `units`.
fn unit_name(units: LengthUnit) -> &'static str {
    match units {
        LengthUnit::Inch => "INCH",
        LengthUnit::Millimetre => "MM",
        LengthUnit::Foot => "FT",
        LengthUnit::Metre => "M",
        LengthUnit::Centimetre => "CM",
    }
}

fn global(meta: &CadMeta) -> String {
    let date = meta.timestamp().replace(['-', ':'], "").replace('T', ".");
    let version = concat!("t2spline ", env!("CARGO_PKG_VERSION"));
    [
        hollerith(","),
        hollerith(";"),
        hollerith("t2spline"),
        hollerith(meta.name()),
        hollerith(version),
        hollerith(version),
        "32".into(),
        "38".into(),
        "6".into(),
        "308".into(),
        "17".into(),
        hollerith("t2spline"),
        "1.0".into(),
        unit_flag(meta.units()).into(),
        hollerith(unit_name(meta.units())),
        "1".into(),
        "1.0".into(),
        hollerith(&date),
        "1.0D-10".into(),
        "0.0".into(),
        hollerith(""),
        hollerith(""),
        "11".into(),
        "0".into(),
        hollerith(&date),
    ]
    .join(",")
        + ";"
}

/// An IGES string: its length in characters, `H`, the text (ASCII; other
/// characters become `?`); an empty string is the parameter's default (an
/// empty field), as `0H` is not read by every program.
fn hollerith(text: &str) -> String {
    if text.is_empty() {
        return String::new();
    }
    let ascii: String = text
        .chars()
        .map(|c| if (' '..='~').contains(&c) { c } else { '?' })
        .collect();
    format!("{}H{ascii}", ascii.len())
}

/// The records of the five sections, before sequence numbers.
#[derive(Default)]
struct Sections {
    start: Vec<String>,
    global: Vec<String>,
    directory: Vec<String>,
    parameters: Vec<String>,
}

impl Sections {
    /// Adds an entity (two directory records and its parameter records);
    /// returns its directory pointer (the sequence number of its first
    /// directory record).
    fn entity(
        &mut self,
        kind: u32,
        form: u32,
        params: &str,
        label: &str,
        subscript: usize,
        status: &str,
    ) -> usize {
        let de = self.directory.len() + 1;
        let first = self.parameters.len() + 1;
        let lines = pack(params, 64);
        for line in &lines {
            self.parameters.push(format!("{line:<64} {de:>7}"));
        }
        self.directory.push(format!(
            "{kind:>8}{first:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{status:>8}",
            0, 1, 0, 0, 0, 0
        ));
        self.directory.push(format!(
            "{kind:>8}{:>8}{:>8}{:>8}{form:>8}{:>8}{:>8}{label:>8}{subscript:>8}",
            0,
            0,
            lines.len(),
            "",
            ""
        ));
        de
    }

    /// The file: every record padded to 72 columns, then the section letter
    /// and the sequence number.
    fn text(&self) -> String {
        let mut out = String::new();
        for (letter, records) in [
            ('S', &self.start),
            ('G', &self.global),
            ('D', &self.directory),
            ('P', &self.parameters),
        ] {
            for (i, record) in records.iter().enumerate() {
                let _ = writeln!(out, "{record:<72}{letter}{:>7}", i + 1);
            }
        }
        let counts = format!(
            "S{:>7}G{:>7}D{:>7}P{:>7}",
            self.start.len(),
            self.global.len(),
            self.directory.len(),
            self.parameters.len()
        );
        let _ = writeln!(out, "{counts:<72}T{:>7}", 1);
        out
    }
}

/// Parameters (separated by `,`, ended by `;`) in records of at most `width`
/// columns, never splitting a parameter (a Hollerith string longer than a
/// record is split, as IGES allows).
fn pack(params: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    let mut rest = params;
    while !rest.is_empty() {
        // The next parameter with its delimiter; Hollerith strings may hold
        // delimiters, so they are measured by their count.
        let len = token_len(rest);
        let token = &rest[..len];
        rest = &rest[len..];
        if line.len() + token.len() > width && !line.is_empty() {
            lines.push(std::mem::take(&mut line));
        }
        if token.len() > width {
            let mut chunk = token;
            while chunk.len() > width {
                lines.push(chunk[..width].to_owned());
                chunk = &chunk[width..];
            }
            line.push_str(chunk);
        } else {
            line.push_str(token);
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// The length of the first parameter of `text` with its delimiter.
fn token_len(text: &str) -> usize {
    let digits = text.bytes().take_while(u8::is_ascii_digit).count();
    if digits > 0 && text.as_bytes().get(digits) == Some(&b'H') {
        let count: usize = text[..digits].parse().unwrap_or(0);
        // The string, then its delimiter.
        return (digits + 1 + count + 1).min(text.len());
    }
    text.find([',', ';']).map_or(text.len(), |i| i + 1)
}

/// Free text in lines of at most `width` characters, broken at spaces;
/// characters outside printable ASCII (control characters such as an
/// escape, and every non-ASCII one) become `?`, as in Hollerith strings.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let word: String = word
            .chars()
            .map(|c| if (' '..='~').contains(&c) { c } else { '?' })
            .collect();
        for piece in word.as_bytes().chunks(width.max(1)) {
            let piece = String::from_utf8_lossy(piece);
            if line.is_empty() {
                line.push_str(&piece);
            } else if line.len() + 1 + piece.len() <= width {
                line.push(' ');
                line.push_str(&piece);
            } else {
                lines.push(std::mem::replace(&mut line, piece.into_owned()));
            }
        }
    }
    lines.push(line);
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_are_packed_without_splitting_numbers() {
        let p = "126,1,1,0,0,1,0,0.0,0.0,1.0,1.0,1.0,1.0,0.0,0.0,0.0,1.0,2.0,3.0;";
        let lines = pack(p, 16);
        assert!(lines.iter().all(|l| l.len() <= 16), "{lines:?}");
        assert_eq!(lines.concat(), p);
        assert!(lines.iter().all(|l| l.ends_with([',', ';'])), "{lines:?}");
    }

    #[test]
    fn hollerith_strings_keep_their_delimiters_inside() {
        assert_eq!(hollerith("a,b"), "3Ha,b");
        assert_eq!(token_len("3Ha,b,7,"), 6);
        assert_eq!(pack("1H,,1H;,5Habcde;", 8), ["1H,,1H;,", "5Habcde;"]);
    }

    #[test]
    fn records_are_80_columns() {
        let mut s = Sections::default();
        s.start.push("x".into());
        s.global = pack(
            &global(
                &CadMeta::new(
                    "a.igs".into(),
                    None,
                    "2026-01-02T03:04:05",
                    Default::default(),
                )
                .unwrap(),
            ),
            72,
        );
        s.entity(406, 15, "406,1,5Hcrisp;", "NAME", 0, "00010200");
        let text = s.text();
        assert!(text.lines().all(|l| l.len() == 80), "{text}");
        assert!(text.contains("15H20260102.030405"), "{text}");
        let count = |letter: u8| text.lines().filter(|l| l.as_bytes()[72] == letter).count();
        let terminate = format!(
            "S{:>7}G{:>7}D{:>7}P{:>7}",
            count(b'S'),
            count(b'G'),
            count(b'D'),
            count(b'P')
        );
        assert_eq!((count(b'S'), count(b'D'), count(b'P')), (1, 2, 1));
        assert!(
            text.lines().last().unwrap().starts_with(&terminate),
            "{text}"
        );
    }
}
