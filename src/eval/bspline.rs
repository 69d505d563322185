//! Regular bicubic B-spline patches: the exact Catmull-Clark limit surface of a quad whose
//! four corners are regular.
//!
//! A patch holds its 4×4 control points row by row: `points[4 * j + i]`, `i` along `u`,
//! `j` along `v`, the patch's own face being the inner square (points 5, 6, 10, 9 are its
//! corners 0, 1, 2, 3). Sides on an infinitely sharp edge (boundary or crease) have no points
//! beyond them; the missing row or column is the *phantom* `2·P₁ − P₂`, which makes the
//! B-spline reproduce Catmull-Clark's crease curve and corner rule exactly (the same
//! construction as Far's regular boundary patches, re-derived: the reflected point gives the
//! end-interpolating cubic B-spline of the crease rule `(1, 6, 1)/8`, `(1, 1)/2`).

use glam::DVec3;

/// Which sides of a patch lie on an infinitely sharp edge: bit 0 = `v = 0`, bit 1 = `u = 1`,
/// bit 2 = `v = 1`, bit 3 = `u = 0` (the face's edges 0, 1, 2, 3).
pub type BoundaryMask = u8;

/// Cubic uniform B-spline basis values and first derivatives at `t` in `[0, 1]`.
#[inline]
pub fn cubic_basis(t: f64) -> ([f64; 4], [f64; 4]) {
    let s = 1.0 - t;
    let t2 = t * t;
    let t3 = t2 * t;
    let b = [
        s * s * s / 6.0,
        (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0,
        (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0,
        t3 / 6.0,
    ];
    let d = [
        -0.5 * s * s,
        1.5 * t2 - 2.0 * t,
        -1.5 * t2 + t + 0.5,
        0.5 * t2,
    ];
    (b, d)
}

/// A regular bicubic B-spline patch with its phantom points already resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct BicubicPatch {
    /// The 16 control points, `points[4 * j + i]`.
    pub points: [DVec3; 16],
}

impl BicubicPatch {
    /// Build a patch from 16 points of which those beyond the sides in `boundary` are
    /// ignored and replaced by phantom points.
    pub fn with_boundary(mut points: [DVec3; 16], boundary: BoundaryMask) -> BicubicPatch {
        // Rows first (v sides), then columns (u sides): a corner phantom then comes out as
        // 4·P₁₁ − 2·P₁₂ − 2·P₂₁ + P₂₂, the tensor product of the two reflections.
        if boundary & 1 != 0 {
            for i in 4..8 {
                points[i - 4] = 2.0 * points[i] - points[i + 4];
            }
        }
        if boundary & 4 != 0 {
            for i in 8..12 {
                points[i + 4] = 2.0 * points[i] - points[i - 4];
            }
        }
        if boundary & 8 != 0 {
            for j in 0..4 {
                points[4 * j] = 2.0 * points[4 * j + 1] - points[4 * j + 2];
            }
        }
        if boundary & 2 != 0 {
            for j in 0..4 {
                points[4 * j + 3] = 2.0 * points[4 * j + 2] - points[4 * j + 1];
            }
        }
        BicubicPatch { points }
    }

    /// Position and first derivatives `(P, ∂P/∂s, ∂P/∂t)` at local `(s, t)` in `[0, 1]²`.
    #[inline]
    pub fn evaluate(&self, s: f64, t: f64) -> (DVec3, DVec3, DVec3) {
        tensor(|k| self.points[k], s, t)
    }

    /// [`BicubicPatch::evaluate`] of the patch without sharp sides whose control point `k`
    /// is `points[vertices[k]]`, read in place: the same operations, the same bits.
    #[inline]
    pub fn evaluate_indexed(
        points: &[DVec3],
        vertices: &[u32; 16],
        s: f64,
        t: f64,
    ) -> (DVec3, DVec3, DVec3) {
        tensor(|k| points[vertices[k] as usize], s, t)
    }
}

/// The tensor-product sums of [`BicubicPatch::evaluate`] over control point `point(k)`,
/// `k = 4 * j + i`.
#[inline(always)]
fn tensor(point: impl Fn(usize) -> DVec3, s: f64, t: f64) -> (DVec3, DVec3, DVec3) {
    let (bu, du) = cubic_basis(s);
    let (bv, dv) = cubic_basis(t);
    let mut pos = DVec3::ZERO;
    let mut ds = DVec3::ZERO;
    let mut dt = DVec3::ZERO;
    for j in 0..4 {
        // Four locals, not an array: `array::map` kept the row in memory.
        let (p0, p1, p2, p3) = (
            point(4 * j),
            point(4 * j + 1),
            point(4 * j + 2),
            point(4 * j + 3),
        );
        let r = p0 * bu[0] + p1 * bu[1] + p2 * bu[2] + p3 * bu[3];
        let d = p0 * du[0] + p1 * du[1] + p2 * du[2] + p3 * du[3];
        pos += r * bv[j];
        ds += d * bv[j];
        dt += r * dv[j];
    }
    (pos, ds, dt)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math;

    fn grid(f: impl Fn(f64, f64) -> DVec3) -> [DVec3; 16] {
        std::array::from_fn(|k| f((k % 4) as f64 - 1.0, (k / 4) as f64 - 1.0))
    }

    #[test]
    fn basis_is_a_partition_of_unity_with_zero_sum_derivatives() {
        for k in 0..=16 {
            let t = k as f64 / 16.0;
            let (b, d) = cubic_basis(t);
            assert!((b.iter().sum::<f64>() - 1.0).abs() < 1e-15);
            assert!(d.iter().sum::<f64>().abs() < 1e-15);
        }
        assert_eq!(cubic_basis(0.0).0, [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0]);
    }

    #[test]
    fn reproduces_bilinear_functions_exactly() {
        // B-splines reproduce linear functions: a grid of (x, y, 2x - 3y + xy) maps to itself.
        let p = BicubicPatch::with_boundary(
            grid(|x, y| DVec3::new(x, y, 2.0 * x - 3.0 * y + x * y)),
            0,
        );
        let (pos, ds, dt) = p.evaluate(0.25, 0.75);
        assert!((pos - DVec3::new(0.25, 0.75, 0.5 - 2.25 + 0.1875)).length() < 1e-15);
        assert!((ds - DVec3::new(1.0, 0.0, 2.75)).length() < 1e-15);
        assert!((dt - DVec3::new(0.0, 1.0, -2.75)).length() < 1e-15);
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let p = BicubicPatch::with_boundary(
            grid(|x, y| DVec3::new(x * x * y, math::sin(x + y), x * y * y - y * y * y)),
            0,
        );
        let h = 1e-6;
        let (_, ds, dt) = p.evaluate(0.3, 0.6);
        let fd_s = (p.evaluate(0.3 + h, 0.6).0 - p.evaluate(0.3 - h, 0.6).0) / (2.0 * h);
        let fd_t = (p.evaluate(0.3, 0.6 + h).0 - p.evaluate(0.3, 0.6 - h).0) / (2.0 * h);
        assert!((ds - fd_s).length() < 1e-8);
        assert!((dt - fd_t).length() < 1e-8);
    }

    #[test]
    fn phantom_corner_interpolates_the_corner_point() {
        // A corner patch (sides v=0 and u=0 sharp) passes through its corner control point
        // and its boundary curves are the end-interpolating B-splines of the crease rule.
        let pts = grid(|x, y| DVec3::new(x + 0.1 * y * y, y - 0.2 * x * x, x * y));
        let p = BicubicPatch::with_boundary(pts, 1 | 8);
        assert!((p.evaluate(0.0, 0.0).0 - pts[5]).length() < 1e-15);
        // Along v = 0 the curve only depends on row 1: at s = 1 it is the crease-rule limit
        // (P0 + 4 P1 + P2) / 6 of the row's points 5, 6, 7.
        let want = (pts[5] + 4.0 * pts[6] + pts[7]) / 6.0;
        assert!((p.evaluate(1.0, 0.0).0 - want).length() < 1e-15);
    }
}
