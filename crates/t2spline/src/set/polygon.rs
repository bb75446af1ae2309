//! Polygons with holes: the outline of a region.

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

    /// A region as stored: polygons and the tolerance of their outline,
    /// taken as they are (from [`Region::polygons`] and [`Region::tolerance`]
    /// of a region computed before, as a front end reads one back).
    #[must_use]
    pub fn from_parts(polygons: Vec<Polygon>, tolerance: f64) -> Self {
        Region::new(polygons, tolerance)
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
        self.polygons.iter().map(Polygon::area).sum()
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
