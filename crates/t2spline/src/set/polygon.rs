//! Polygons with holes: the outline of a region.

use crate::Error;

/// A polygon: one exterior ring, counter-clockwise, and holes, clockwise.
/// Rings are open (the first vertex is not repeated at the end).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Polygon {
    /// The outer boundary, counter-clockwise.
    pub exterior: Vec<[f64; 2]>,
    /// The boundaries of the holes, clockwise.
    pub holes: Vec<Vec<[f64; 2]>>,
}

impl Polygon {
    /// A polygon from rings, the first the exterior: orientations are set
    /// here whatever they were. `None` without an exterior of three vertices.
    pub(crate) fn from_rings(mut rings: Vec<Vec<[f64; 2]>>) -> Option<Self> {
        for r in &mut rings {
            if r.len() > 1 && r.first() == r.last() {
                r.pop();
            }
        }
        let mut rings = rings.into_iter().filter(|r| r.len() >= 3);
        let mut exterior = rings.next()?;
        if signed_area(&exterior) < 0.0 {
            exterior.reverse();
        }
        let holes = rings
            .map(|mut h| {
                if signed_area(&h) > 0.0 {
                    h.reverse();
                }
                h
            })
            .collect();
        Some(Polygon { exterior, holes })
    }

    /// The area: the exterior's less the holes'.
    #[must_use]
    pub fn area(&self) -> f64 {
        signed_area(&self.exterior) + self.holes.iter().map(|h| signed_area(h)).sum::<f64>()
    }

    /// Whether `p` lies inside (even–odd over all rings: inside the exterior
    /// and in no hole). Points on the boundary may go either way.
    #[must_use]
    pub fn contains(&self, p: [f64; 2]) -> bool {
        std::iter::once(&self.exterior)
            .chain(&self.holes)
            .map(|r| crossings(r, p))
            .sum::<usize>()
            % 2
            == 1
    }
}

/// A region: polygons that do not overlap, and the tolerance of their outline.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Region {
    polygons: Vec<Polygon>,
    tolerance: f64,
}

impl Region {
    pub(crate) fn new(polygons: Vec<Polygon>, tolerance: f64) -> Self {
        Region {
            polygons,
            tolerance,
        }
    }

    /// A region read back from its parts (a pickle, a file), checked as a
    /// region computed here is made: a finite positive tolerance; rings of
    /// at least three vertices, open, with finite coordinates; exteriors
    /// counter-clockwise and holes clockwise (by the shoelace formula); no
    /// ring that crosses itself.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for the tolerance; [`Error::RegionPart`] naming
    /// the polygon, the ring and the rule it breaks.
    ///
    /// ```
    /// # use t2spline::set::{Polygon, Region};
    /// let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    /// let ok = Region::try_from_parts(vec![Polygon { exterior: square.clone(), holes: vec![] }], 1e-6);
    /// assert_eq!(ok.unwrap().area(), 1.0);
    /// let clockwise: Vec<[f64; 2]> = square.into_iter().rev().collect();
    /// let e = Region::try_from_parts(vec![Polygon { exterior: clockwise, holes: vec![] }], 1e-6);
    /// assert_eq!(e.unwrap_err().to_string(), "polygon 0, ring 0 (the exterior): the exterior must run counter-clockwise");
    /// // No polygon: area 0, not −0.
    /// assert!(Region::try_from_parts(vec![], 1e-6)?.area().is_sign_positive());
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_from_parts(polygons: Vec<Polygon>, tolerance: f64) -> Result<Self, Error> {
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(Error::OutOfRange {
                place: crate::error::Place::NONE,
                what: "tolerance",
                value: tolerance,
                range: "(0, inf)",
            });
        }
        for (k, polygon) in polygons.iter().enumerate() {
            for (r, ring) in std::iter::once(&polygon.exterior)
                .chain(&polygon.holes)
                .enumerate()
            {
                if let Some(rule) = ring_rule(ring, r == 0) {
                    return Err(Error::RegionPart {
                        polygon: k,
                        ring: r,
                        rule,
                    });
                }
            }
        }
        Ok(Region::new(polygons, tolerance))
    }

    /// The polygons.
    #[must_use]
    pub fn polygons(&self) -> &[Polygon] {
        &self.polygons
    }

    /// The tolerance of the outline: every point of the true region lies in
    /// the polygons, and every point of the polygons within this distance of
    /// the true region.
    #[must_use]
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The total area.
    #[must_use]
    pub fn area(&self) -> f64 {
        // A sum of floats starts at −0; `+ 0.0` makes the empty set's area 0.
        self.polygons.iter().map(Polygon::area).sum::<f64>() + 0.0
    }

    /// Whether `p` lies in one of the polygons.
    #[must_use]
    pub fn contains(&self, p: [f64; 2]) -> bool {
        self.polygons.iter().any(|g| g.contains(p))
    }

    /// The intervals of `y` where the vertical line `x = x0` meets the
    /// polygons, in increasing order.
    #[must_use]
    pub fn section(&self, x0: f64) -> Vec<[f64; 2]> {
        let mut ys: Vec<f64> = Vec::new();
        for g in &self.polygons {
            for r in std::iter::once(&g.exterior).chain(&g.holes) {
                for (a, b) in edges(r) {
                    if (a[0] <= x0) != (b[0] <= x0) {
                        ys.push(a[1] + (x0 - a[0]) * (b[1] - a[1]) / (b[0] - a[0]));
                    }
                }
            }
        }
        ys.sort_by(f64::total_cmp);
        ys.chunks_exact(2).map(|c| [c[0], c[1]]).collect()
    }
}

/// The edges of an open ring, the closing one included.
fn edges(r: &[[f64; 2]]) -> impl Iterator<Item = (&[f64; 2], &[f64; 2])> {
    r.iter().zip(r.iter().cycle().skip(1))
}

/// The shoelace formula `½ Σ (xᵢ yᵢ₊₁ − xᵢ₊₁ yᵢ)`, positive
/// counter-clockwise.
pub(crate) fn signed_area(r: &[[f64; 2]]) -> f64 {
    0.5 * edges(r)
        .map(|(a, b)| a[0] * b[1] - b[0] * a[1])
        .sum::<f64>()
}

/// How many edges of the ring a ray from `p` towards +x crosses.
fn crossings(r: &[[f64; 2]], p: [f64; 2]) -> usize {
    edges(r)
        .filter(|(a, b)| {
            (a[1] > p[1]) != (b[1] > p[1])
                && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        })
        .count()
}

/// The first rule `ring` breaks, if any; `exterior`: it must run
/// counter-clockwise, else clockwise.
fn ring_rule(ring: &[[f64; 2]], exterior: bool) -> Option<&'static str> {
    if ring.len() < 3 {
        return Some("a ring needs at least three vertices");
    }
    if ring.iter().flatten().any(|x| !x.is_finite()) {
        return Some("every coordinate must be a finite number");
    }
    if ring.first() == ring.last() {
        return Some("rings are stored open: the first vertex is not repeated at the end");
    }
    let area = signed_area(ring);
    if exterior && area <= 0.0 {
        return Some("the exterior must run counter-clockwise");
    }
    if !exterior && area >= 0.0 {
        return Some("a hole must run clockwise");
    }
    if crosses_itself(ring) {
        return Some("the ring crosses itself");
    }
    None
}

/// Whether two edges of the ring that are not neighbours meet: a sweep
/// along x over the edges sorted by their least x, so that only edges whose
/// x ranges overlap are compared.
fn crosses_itself(ring: &[[f64; 2]]) -> bool {
    let n = ring.len();
    let edge = |i: usize| (ring[i], ring[(i + 1) % n]);
    let mut order: Vec<usize> = (0..n).collect();
    let low = |i: usize| ring[i][0].min(ring[(i + 1) % n][0]);
    order.sort_by(|&a, &b| low(a).total_cmp(&low(b)));
    for (k, &i) in order.iter().enumerate() {
        let (a, b) = edge(i);
        let high = a[0].max(b[0]);
        for &j in &order[k + 1..] {
            if low(j) > high {
                break;
            }
            let neighbours = (i + 1) % n == j || (j + 1) % n == i;
            if !neighbours {
                let (c, d) = edge(j);
                if segments_meet(a, b, c, d) {
                    return true;
                }
            }
        }
    }
    false
}

/// Whether the closed segments ab and cd share a point (orientation tests).
fn segments_meet(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let orient = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
        let v = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
        if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        }
    };
    let within = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
        r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    let (o1, o2, o3, o4) = (
        orient(a, b, c),
        orient(a, b, d),
        orient(c, d, a),
        orient(c, d, b),
    );
    (o1 != o2 && o3 != o4)
        || (o1 == 0 && within(a, b, c))
        || (o2 == 0 && within(a, b, d))
        || (o3 == 0 && within(c, d, a))
        || (o4 == 0 && within(c, d, b))
}
