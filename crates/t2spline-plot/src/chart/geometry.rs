//! Pixel geometry for layout: points and rectangles, and whether a segment
//! meets a rectangle.

/// A point in pixels, y downwards.
pub type Px = [f64; 2];

/// An axis-aligned rectangle in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Left edge.
    pub x: f64,
    /// Top edge.
    pub y: f64,
    /// Width.
    pub w: f64,
    /// Height.
    pub h: f64,
}

impl Rect {
    /// The right edge.
    #[must_use]
    pub fn right(&self) -> f64 {
        self.x + self.w
    }

    /// The bottom edge.
    #[must_use]
    pub fn bottom(&self) -> f64 {
        self.y + self.h
    }

    /// The rectangle grown by `m` on every side.
    #[must_use]
    pub fn grow(&self, m: f64) -> Rect {
        Rect {
            x: self.x - m,
            y: self.y - m,
            w: self.w + 2.0 * m,
            h: self.h + 2.0 * m,
        }
    }

    /// Whether the point lies inside or on the border.
    #[must_use]
    pub fn contains(&self, p: Px) -> bool {
        p[0] >= self.x && p[0] <= self.right() && p[1] >= self.y && p[1] <= self.bottom()
    }

    /// Whether `other` lies entirely inside.
    #[must_use]
    pub fn contains_rect(&self, other: &Rect) -> bool {
        other.x >= self.x - 1e-9
            && other.y >= self.y - 1e-9
            && other.right() <= self.right() + 1e-9
            && other.bottom() <= self.bottom() + 1e-9
    }

    /// Whether the two rectangles share interior points.
    #[must_use]
    pub fn overlaps(&self, other: &Rect) -> bool {
        self.x < other.right()
            && other.x < self.right()
            && self.y < other.bottom()
            && other.y < self.bottom()
    }

    /// Whether the segment `a`–`b` meets the rectangle (Liang–Barsky clipping).
    #[must_use]
    pub fn meets_segment(&self, a: Px, b: Px) -> bool {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let mut t0: f64 = 0.0;
        let mut t1: f64 = 1.0;
        for (p, q) in [
            (-dx, a[0] - self.x),
            (dx, self.right() - a[0]),
            (-dy, a[1] - self.y),
            (dy, self.bottom() - a[1]),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
                if t0 > t1 {
                    return false;
                }
            }
        }
        true
    }

    /// The point of the rectangle nearest to `p` (for a rectangle of
    /// negative width or height, its far edge).
    #[must_use]
    pub fn nearest(&self, p: Px) -> Px {
        // Not `clamp`, which panics when the bounds cross or are NaN.
        [
            p[0].max(self.x).min(self.right()),
            p[1].max(self.y).min(self.bottom()),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const R: Rect = Rect {
        x: 10.0,
        y: 10.0,
        w: 10.0,
        h: 10.0,
    };

    #[test]
    fn segments_meet_a_rectangle_only_when_they_cross_it() {
        assert!(R.meets_segment([0.0, 15.0], [30.0, 15.0]));
        assert!(R.meets_segment([12.0, 12.0], [13.0, 13.0]));
        assert!(!R.meets_segment([0.0, 0.0], [30.0, 5.0]));
        assert!(!R.meets_segment([0.0, 0.0], [9.0, 30.0]));
        assert!(R.meets_segment([0.0, 30.0], [30.0, 0.0]));
    }
}
