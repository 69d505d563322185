//! The plane the sketch curves are projected on: the best-fit plane of all their points
//! (`"projection": "auto"`) or the plane through their centroid with a given normal.

use glam::{DVec2, DVec3};

use crate::construct::sweep::frames::any_perpendicular;
use crate::error::{Error, Result};

/// A plane with an orthonormal in-plane frame: a point `p` projects to
/// `((p − origin)·e1, (p − origin)·e2)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    /// A point of the plane (the centroid of the curve points).
    pub origin: DVec3,
    /// First in-plane axis.
    pub e1: DVec3,
    /// Second in-plane axis; `e1 × e2` is the plane's normal.
    pub e2: DVec3,
}

/// Smallest ratio of the middle to the largest principal variance for the points to span a
/// plane (below it they lie on one line, up to rounding: a width under 1e-6 of the length).
const LINE_RATIO: f64 = 1e-12;

impl Plane {
    /// 2-D coordinates of `p` in the plane.
    pub fn project(&self, p: DVec3) -> DVec2 {
        let d = p - self.origin;
        DVec2::new(d.dot(self.e1), d.dot(self.e2))
    }

    /// 2-D components of a direction `d`.
    pub fn project_dir(&self, d: DVec3) -> DVec2 {
        DVec2::new(d.dot(self.e1), d.dot(self.e2))
    }

    /// The plane's unit normal, `e1 × e2`.
    pub fn normal(&self) -> DVec3 {
        self.e1.cross(self.e2)
    }

    /// The same plane seen from the other side (`e2` reversed, so the normal is too).
    pub fn flipped(self) -> Plane {
        Plane {
            e2: -self.e2,
            ..self
        }
    }

    /// The best-fit (least-squares) plane of `points`: through their centroid, normal along
    /// the covariance matrix's eigenvector of least eigenvalue, `e1` along the largest.
    ///
    /// Errors ([`Error::InvalidArgument`]): fewer than 3 points, or all of them on one line
    /// (or at one point), so that no plane exists.
    pub fn best_fit(points: &[DVec3]) -> Result<Plane> {
        let no_plane = || {
            Error::invalid_argument(
                "projection \"auto\": all curve points lie on one line, so no plane fits \
                 them; give the curves some width or a projection normal",
            )
        };
        if points.len() < 3 {
            return Err(no_plane());
        }
        let origin = points.iter().copied().sum::<DVec3>() / points.len() as f64;
        let mut c = [[0.0f64; 3]; 3];
        for p in points {
            let d = (*p - origin).to_array();
            for (i, row) in c.iter_mut().enumerate() {
                for (j, x) in row.iter_mut().enumerate() {
                    *x += d[i] * d[j];
                }
            }
        }
        let (values, vectors) = symmetric_eigen(c);
        // Ascending order of the eigenvalues.
        let mut order = [0usize, 1, 2];
        order.sort_by(|&a, &b| values[a].total_cmp(&values[b]));
        let (middle, largest) = (values[order[1]], values[order[2]]);
        if largest.is_nan() || largest <= 0.0 || middle <= LINE_RATIO * largest {
            return Err(no_plane());
        }
        let column = |k: usize| DVec3::new(vectors[0][k], vectors[1][k], vectors[2][k]);
        let normal = column(order[0]).normalize();
        let e1 = column(order[2]).normalize();
        Ok(Plane {
            origin,
            e1,
            e2: normal.cross(e1),
        })
    }

    /// The plane through the centroid of `points` with unit normal along `normal`; `e1` is
    /// the coordinate axis least aligned with the normal, made perpendicular to it.
    ///
    /// Errors ([`Error::InvalidArgument`]): a normal that is not finite or is zero.
    pub fn with_normal(points: &[DVec3], normal: [f64; 3]) -> Result<Plane> {
        let n = DVec3::from(normal);
        if !n.is_finite() || n.length() == 0.0 {
            return Err(Error::invalid_argument(format!(
                "projection normal ({}, {}, {}) must be finite and non-zero",
                n.x, n.y, n.z
            )));
        }
        let n = n.normalize();
        let e1 = any_perpendicular(n);
        let origin = points.iter().copied().sum::<DVec3>() / points.len().max(1) as f64;
        Ok(Plane {
            origin,
            e1,
            e2: n.cross(e1),
        })
    }
}

/// Eigenvalues and eigenvectors (the columns of the matrix) of a symmetric 3 × 3 matrix by
/// cyclic Jacobi rotations, in a fixed order (deterministic bits).
fn symmetric_eigen(mut a: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _sweep in 0..32 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        let diag = a[0][0].abs() + a[1][1].abs() + a[2][2].abs();
        if off <= 1e-300 || off <= 1e-18 * diag {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            for row in a.iter_mut() {
                let (kp, kq) = (row[p], row[q]);
                row[p] = c * kp - s * kq;
                row[q] = s * kp + c * kq;
            }
            let (row_p, row_q) = (a[p], a[q]);
            for k in 0..3 {
                a[p][k] = c * row_p[k] - s * row_q[k];
                a[q][k] = s * row_p[k] + c * row_q[k];
            }
            for row in v.iter_mut() {
                let (kp, kq) = (row[p], row[q]);
                row[p] = c * kp - s * kq;
                row[q] = s * kp + c * kq;
            }
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn best_fit_plane_of_a_tilted_square_and_no_plane_for_a_line() {
        let n = DVec3::new(1.0, 2.0, 2.0) / 3.0;
        let e1 = DVec3::new(2.0, -1.0, 0.0).normalize();
        let e2 = n.cross(e1);
        let pts: Vec<DVec3> = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0), (1.0, 0.3)]
            .iter()
            .map(|&(a, b)| DVec3::new(1.0, 2.0, 3.0) + e1 * a + e2 * b)
            .collect();
        let p = Plane::best_fit(&pts).unwrap();
        assert!(p.normal().cross(n).length() < 1e-12, "{}", p.normal());
        for q in &pts {
            assert!((*q - p.origin).dot(p.normal()).abs() < 1e-12);
        }
        let line: Vec<DVec3> = (0..5)
            .map(|i| DVec3::new(1.0, 2.0, 3.0) * i as f64)
            .collect();
        let e = Plane::best_fit(&line).unwrap_err().to_string();
        assert!(e.contains("one line"), "{e}");
        assert!(Plane::with_normal(&pts, [0.0, 0.0, 0.0]).is_err());
        assert!(Plane::with_normal(&pts, [f64::NAN, 0.0, 1.0]).is_err());
        let p = Plane::with_normal(&pts, [0.0, 0.0, 2.0]).unwrap();
        assert!((p.normal() - DVec3::Z).length() < 1e-15);
    }
}
