//! The two parameterizations OpenSubdiv users address the limit surface with.
//!
//! - [`Domain::Ptex`] (the default, see [`super::ptex`]): `face` is a Ptex face
//!   (`Far::PtexIndices`, `Far::PatchMap`); a face with `N ≠ 4` vertices is `N` consecutive
//!   faces, one per corner, each with `(u, v)` in `[0, 1]²`.
//! - [`Domain::Bfr`]: `face` is the control face (`Bfr::SurfaceFactory`'s base face) and
//!   `(u, v)` is in that face's `Bfr::Parameterization`. A quad has `[0, 1]²` as in Ptex.
//!   Under Catmull-Clark every other face, triangles included, is `QUAD_SUBFACES`: its `N`
//!   sub-faces are tiled row by row in a grid of `⌈√N⌉` columns (2 for a triangle, 3 for 5
//!   to 9 vertices, ...), sub-face `k` in the tile at column `k mod ⌈√N⌉`, row
//!   `k div ⌈√N⌉`, and fills the lower-left quarter of its unit tile:
//!   `(u, v) = (column + s/2, row + t/2)` with `(s, t)` the Ptex coordinates of sub-face `k`
//!   (`Bfr::Parameterization::ConvertNormalizedSubFaceToCoord`). A point in the gaps between
//!   those squares is outside the domain.
//!
//! Derivatives are in the domain's own units: on a sub-face, `∂/∂u` (Bfr) `= 2 ∂/∂s` (Ptex).

use super::ptex::PtexFaces;
use crate::error::{Error, Result};

/// Which parameterization a point `(face, u, v)` is given in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Domain {
    /// OpenSubdiv's Ptex faces (`Far::PtexIndices`): one parametric face per quad, `N` per
    /// `N`-gon.
    #[default]
    Ptex,
    /// Bfr's base faces with their tiled sub-face parameterization (`Bfr::Parameterization`).
    Bfr,
}

/// A point located on a Ptex face, with the factor from Ptex to the caller's derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PtexPoint {
    /// Ptex face.
    pub face: u32,
    /// Ptex coordinate u.
    pub u: f64,
    /// Ptex coordinate v.
    pub v: f64,
    /// Derivatives in the caller's domain are the Ptex ones times this (2 on a Bfr
    /// sub-face, 1 elsewhere).
    pub derivative_scale: f64,
}

/// Columns of Bfr's tiling of the sub-faces of an `n`-gon: `⌈√n⌉`.
pub fn bfr_tile_columns(n: u32) -> u32 {
    let mut c = 1;
    while c * c < n {
        c += 1;
    }
    c
}

impl PtexFaces {
    /// The Ptex face and coordinates of point `(face, u, v)` given in `domain` (see the
    /// module doc).
    ///
    /// Errors ([`Error::InvalidArgument`]): `face` out of range, `u` or `v` NaN or outside the
    /// domain (`[0, 1]` for Ptex faces and quads, the sub-face squares of Bfr's tiling).
    pub fn locate_in(&self, domain: Domain, face: u32, u: f64, v: f64) -> Result<PtexPoint> {
        let ptex = |face, u, v, derivative_scale| PtexPoint {
            face,
            u,
            v,
            derivative_scale,
        };
        if domain == Domain::Ptex {
            if face as usize >= self.len() {
                return Err(Error::invalid_argument(format!(
                    "face {face} is out of range; the mesh has {} parametric faces",
                    self.len()
                )));
            }
            check_unit(face, u, v)?;
            return Ok(ptex(face, u, v, 1.0));
        }
        let faces = self.num_control_faces();
        if face as usize >= faces {
            return Err(Error::invalid_argument(format!(
                "face {face} is out of range; the mesh has {faces} faces"
            )));
        }
        let first = self.first_of(face as usize);
        let n = self.first_of(face as usize + 1) - first;
        if n == 1 {
            check_unit(face, u, v)?;
            return Ok(ptex(first, u, v, 1.0));
        }
        // The tile Bfr assigns (u, v) to: the nearest sub-face square, then the point must
        // lie in it.
        let columns = bfr_tile_columns(n);
        let outside = || {
            Error::invalid_argument(format!(
                "(u, v) = ({u}, {v}) is outside the Bfr domain of face {face} ({n} sub-faces \
                 of side 1/2 tiled in {columns} columns)"
            ))
        };
        if !(u >= 0.0 && v >= 0.0) {
            return Err(outside());
        }
        let (col, row) = ((u + 0.25).floor(), (v + 0.25).floor());
        let (s, t) = (2.0 * (u - col), 2.0 * (v - row));
        if col >= f64::from(columns) || !(0.0..=1.0).contains(&s) || !(0.0..=1.0).contains(&t) {
            return Err(outside());
        }
        let k = row * f64::from(columns) + col;
        if k >= f64::from(n) {
            return Err(outside());
        }
        Ok(ptex(first + k as u32, s, t, 2.0))
    }

    /// The point `(face, u, v)` of Ptex face `ptex` in Bfr's domain: its control face and
    /// the coordinates of Bfr's tiling (the inverse of [`PtexFaces::locate_in`] with
    /// [`Domain::Bfr`]); `None` when `ptex` is out of range.
    pub fn to_bfr(&self, ptex: u32, u: f64, v: f64) -> Option<(u32, f64, f64)> {
        let (face, sub) = self.locate(ptex)?;
        let Some(k) = sub else {
            return Some((face, u, v));
        };
        let n = self.first_of(face as usize + 1) - self.first_of(face as usize);
        let columns = bfr_tile_columns(n);
        Some((
            face,
            f64::from(k % columns) + 0.5 * u,
            f64::from(k / columns) + 0.5 * v,
        ))
    }
}

fn check_unit(face: u32, u: f64, v: f64) -> Result<()> {
    if !(0.0..=1.0).contains(&u) || !(0.0..=1.0).contains(&v) {
        return Err(Error::invalid_argument(format!(
            "(u, v) = ({u}, {v}) on face {face} is outside [0, 1]"
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::mesh::{Mesh, MeshParts};

    /// A triangle, a quad, a pentagon and a decagon sharing nothing: Ptex faces 0-2, 3, 4-8,
    /// 9-18.
    fn faces() -> PtexFaces {
        let sizes = vec![3, 4, 5, 10];
        let total: u32 = sizes.iter().sum();
        let parts = MeshParts {
            positions: vec![DVec3::ZERO; total as usize],
            face_sizes: sizes,
            face_indices: (0..total).collect(),
            ..Default::default()
        };
        PtexFaces::new(&Mesh::from_parts(parts).unwrap()).unwrap()
    }

    #[test]
    fn tiles_have_ceil_sqrt_columns_as_bfr() {
        let got: Vec<u32> = (3..=17).map(bfr_tile_columns).collect();
        assert_eq!(got, [2, 2, 3, 3, 3, 3, 3, 4, 4, 4, 4, 4, 4, 4, 5]);
    }

    #[test]
    fn bfr_points_map_to_sub_faces_and_back() {
        let p = faces();
        // Triangle: sub-faces at tiles (0,0), (1,0), (0,1).
        let at = |f, u, v| p.locate_in(Domain::Bfr, f, u, v).unwrap();
        assert_eq!(
            at(0, 0.25, 0.5),
            PtexPoint {
                face: 0,
                u: 0.5,
                v: 1.0,
                derivative_scale: 2.0
            }
        );
        assert_eq!(
            at(0, 1.5, 0.0),
            PtexPoint {
                face: 1,
                u: 1.0,
                v: 0.0,
                derivative_scale: 2.0
            }
        );
        assert_eq!(
            at(0, 0.0, 1.25),
            PtexPoint {
                face: 2,
                u: 0.0,
                v: 0.5,
                derivative_scale: 2.0
            }
        );
        // The quad is its own Ptex face.
        assert_eq!(
            at(1, 0.3, 0.7),
            PtexPoint {
                face: 3,
                u: 0.3,
                v: 0.7,
                derivative_scale: 1.0
            }
        );
        // Pentagon: 3 columns, sub-face 4 at tile (1, 1).
        assert_eq!(
            at(2, 1.5, 1.5),
            PtexPoint {
                face: 8,
                u: 1.0,
                v: 1.0,
                derivative_scale: 2.0
            }
        );
        // Decagon: 4 columns, sub-face 9 at tile (1, 2).
        assert_eq!(
            at(3, 1.125, 2.0),
            PtexPoint {
                face: 18,
                u: 0.25,
                v: 0.0,
                derivative_scale: 2.0
            }
        );
        // Ptex -> Bfr -> Ptex is the identity on every sub-face, corners included.
        for ptex in 0..19u32 {
            for (u, v) in [(0.0, 0.0), (1.0, 1.0), (0.25, 0.75), (1.0, 0.0), (0.5, 1.0)] {
                let (f, bu, bv) = p.to_bfr(ptex, u, v).unwrap();
                let back = p.locate_in(Domain::Bfr, f, bu, bv).unwrap();
                assert_eq!(
                    (back.face, back.u, back.v),
                    (ptex, u, v),
                    "{ptex} ({u}, {v})"
                );
            }
        }
        assert_eq!(p.to_bfr(19, 0.0, 0.0), None);
    }

    #[test]
    fn points_outside_either_domain_are_refused() {
        let p = faces();
        let bad = |d, f, u, v| match p.locate_in(d, f, u, v) {
            Err(Error::InvalidArgument(m)) => m,
            other => panic!("{d:?} {f} ({u}, {v}): {other:?}"),
        };
        assert!(bad(Domain::Ptex, 19, 0.5, 0.5).contains("19 parametric faces"));
        assert!(bad(Domain::Bfr, 4, 0.5, 0.5).contains("the mesh has 4 faces"));
        assert!(bad(Domain::Ptex, 0, 1.5, 0.5).contains("outside [0, 1]"));
        assert!(bad(Domain::Bfr, 1, 0.5, -0.1).contains("outside [0, 1]"));
        // In a gap between sub-face squares, past the last column, in the empty tile of a
        // triangle's grid, negative, NaN.
        for (u, v) in [
            (0.6, 0.2),
            (0.2, 0.7),
            (2.1, 0.0),
            (1.25, 1.25),
            (-0.1, 0.0),
            (f64::NAN, 0.0),
        ] {
            let m = bad(Domain::Bfr, 0, u, v);
            assert!(
                m.contains("outside the Bfr domain of face 0 (3 sub-faces"),
                "{m}"
            );
        }
        assert!(bad(Domain::Bfr, 2, 2.25, 1.25).contains("5 sub-faces"));
    }
}
