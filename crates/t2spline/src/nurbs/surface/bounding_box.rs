//! The axis-aligned bounding box of a surface.

use super::tensor_product::NurbsSurface;
use crate::nurbs::surface::patches::{patch_min, Patch, HULL_SLACK};
use crate::nurbs::BoundingBox;

/// Where each face of a box is reached: `at[0][d]` for `min[d]`, `at[1][d]`
/// for `max[d]`, as parameters `[u, v]`.
pub(crate) type FaceParams<const D: usize> = [[[f64; 2]; D]; 2];

impl<const D: usize> NurbsSurface<D> {
    /// The tight axis-aligned bounding box of the surface over its domain
    /// (not the box of the control points, which only contains it).
    ///
    /// The box starts as the box of the corners of every span rectangle
    /// (patch). Each patch is a convex combination of the control points
    /// acting on it, so their smallest coordinate `x_d` bounds the patch's
    /// from below; for each coordinate and side, patches are searched from
    /// the most extreme bound on, and the search stops at the first patch
    /// whose bound cannot move the face. A searched patch is scanned on a
    /// 17 × 17 grid and every local extremum of the scan refined by
    /// Nelder–Mead inside the patch (borders and corners included), as for
    /// the largest distance between two surfaces ([`crate::SurfaceDistance`]).
    /// Each face is a value of the surface; an extremum of a smooth patch
    /// found so is within about `10⁻¹⁶` of the true one relative to the
    /// patch's size (the error is quadratic in the position). An extremum
    /// narrower than a scan cell that is not extreme at the scan points can
    /// in principle be missed. Along a knot of full multiplicity both
    /// one-sided limits count.
    ///
    /// # Examples
    /// The quarter cylinder of radius 1 and height 2 lies in
    /// `[0, 1] × [0, 1] × [0, 2]`; its control point (1, 1, z) is outside:
    /// ```
    /// # use t2spline::NurbsSurface;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let net = vec![
    ///     vec![[1.0, 0.0, 0.0], [1.0, 0.0, 2.0]],
    ///     vec![[1.0, 1.0, 0.0], [1.0, 1.0, 2.0]],
    ///     vec![[0.0, 1.0, 0.0], [0.0, 1.0, 2.0]],
    /// ];
    /// let s = NurbsSurface::try_clamped([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]])?;
    /// let b = s.bounding_box();
    /// // Values of the surface, so up to the rounding of an evaluation:
    /// let want = [[0.0, 0.0, 0.0], [1.0, 1.0, 2.0]];
    /// for (got, want) in [b.min, b.max].iter().flatten().zip(want.iter().flatten()) {
    ///     assert!((got - want).abs() < 1e-15);
    /// }
    /// // A bump: z peaks at 1/4 inside, though the middle control point has z = 1.
    /// let row = |x: f64, z: f64| vec![[x, 0.0, 0.0], [x, 1.0, z], [x, 2.0, 0.0]];
    /// let bump = NurbsSurface::try_clamped([2, 2], vec![row(0.0, 0.0), row(1.0, 1.0), row(2.0, 0.0)], vec![vec![1.0; 3]; 3])?;
    /// assert!((bump.bounding_box().max[2] - 0.25).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn bounding_box(&self) -> BoundingBox<D> {
        self.bounding_box_reached(true).0
    }

    /// The bounding box and where each face is reached, with the patches
    /// pruned by their bounds or (for the tests) every patch searched.
    pub(crate) fn bounding_box_reached(&self, prune: bool) -> (BoundingBox<D>, FaceParams<D>) {
        let patches = self.patches();
        let corner = |&(spans, [[a0, b0], [a1, b1]]): &Patch| {
            [[a0, a1], [a0, b1], [b0, a1], [b0, b1]]
                .map(|x| (x, self.eval_in_spans(spans, x[0], x[1])))
        };
        // faces[side][d] = (the smallest of ±x_d, where), ± by side.
        let first = (patches[0].1[0][0], patches[0].1[1][0]);
        let start = self.eval_in_spans(patches[0].0, first.0, first.1);
        let mut faces: [[(f64, [f64; 2]); D]; 2] = [
            std::array::from_fn(|d| (start[d], [first.0, first.1])),
            std::array::from_fn(|d| (-start[d], [first.0, first.1])),
        ];
        for patch in &patches {
            for (x, p) in corner(patch) {
                for d in 0..D {
                    for (side, sign) in [(0, 1.0), (1, -1.0)] {
                        if sign * p[d] < faces[side][d].0 {
                            faces[side][d] = (sign * p[d], x);
                        }
                    }
                }
            }
        }
        let boxes: Vec<BoundingBox<D>> = patches.iter().map(|p| self.patch_box(p)).collect();
        // `d` picks the coordinate of the faces, the boxes and the surface.
        #[allow(clippy::needless_range_loop)]
        for d in 0..D {
            for (side, sign) in [(0, 1.0), (1, -1.0)] {
                // The smallest of ±x_d over the points acting on each patch.
                let bounds: Vec<f64> = boxes
                    .iter()
                    .map(|b| {
                        let lo = if side == 0 { b.min[d] } else { -b.max[d] };
                        lo - HULL_SLACK * b.min[d].abs().max(b.max[d].abs())
                    })
                    .collect();
                let mut order: Vec<usize> = (0..patches.len()).collect();
                order.sort_by(|&a, &b| bounds[a].total_cmp(&bounds[b]));
                for k in order {
                    if prune && bounds[k] >= faces[side][d].0 {
                        break;
                    }
                    let patch = &patches[k];
                    let f = |[u, v]: [f64; 2]| sign * self.eval_in_spans(patch.0, u, v)[d];
                    let found = patch_min(patch, f, |_| true);
                    if found.0 < faces[side][d].0 {
                        faces[side][d] = found;
                    }
                }
            }
        }
        let b = BoundingBox {
            min: std::array::from_fn(|d| faces[0][d].0),
            max: std::array::from_fn(|d| -faces[1][d].0),
        };
        (b, faces.map(|side| side.map(|(_, x)| x)))
    }
}
