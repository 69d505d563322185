//! How a point `(face, u, v)` addresses the limit surface: OpenSubdiv's Ptex face numbering.
//!
//! Every quad of the control mesh is one parametric face with `(u, v)` in `[0, 1]²`: corner 0
//! at `(0, 0)`, corner 1 at `(1, 0)`, corner 2 at `(1, 1)`, corner 3 at `(0, 1)`. A face with
//! `N ≠ 4` vertices is split, as Catmull-Clark's first refinement splits it, into `N` quad
//! *sub-faces*, one per corner, numbered consecutively: sub-face `k` has `(0, 0)` at vertex `k`,
//! `(1, 0)` at the midpoint of edge `k → k+1`, `(1, 1)` at the face centre and `(0, 1)` at the
//! midpoint of edge `k-1 → k`. This is `Far::PtexIndices` (the face numbering of
//! `Far::PatchMap`, Osd's `PatchCoord`) and Bfr's normalized sub-face coordinates
//! (`Bfr::Parameterization::ConvertNormalizedSubFaceToCoord`). On a mesh of quads only,
//! Ptex face `i` is simply face `i`.

use crate::error::{Error, Result};
use crate::mesh::Mesh;

/// The Ptex numbering of a mesh's faces.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PtexFaces {
    /// First Ptex face of each control face, plus the total at the end.
    first: Vec<u32>,
}

impl PtexFaces {
    /// Number the parametric faces of `mesh`.
    pub fn new(mesh: &Mesh) -> Result<PtexFaces> {
        let mut first = Vec::with_capacity(mesh.num_faces() + 1);
        let mut next: u64 = 0;
        for &n in mesh.face_sizes() {
            first.push(next as u32);
            next += if n == 4 { 1 } else { u64::from(n) };
        }
        if next > u64::from(u32::MAX) {
            return Err(Error::invalid_mesh(format!(
                "the mesh has {next} parametric faces; at most {} are supported",
                u32::MAX
            )));
        }
        first.push(next as u32);
        Ok(PtexFaces { first })
    }

    /// Number of parametric (Ptex) faces.
    pub fn len(&self) -> usize {
        *self.first.last().unwrap_or(&0) as usize
    }

    /// True when there are no parametric faces (never for a valid mesh).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// First Ptex face of control face `face` (its sub-face 0); `face` = the number of control
    /// faces gives the total. Panics if out of range.
    pub fn first_of(&self, face: usize) -> u32 {
        self.first[face]
    }

    /// Number of control faces.
    pub fn num_control_faces(&self) -> usize {
        self.first.len() - 1
    }

    /// The control face of Ptex face `ptex` and, for a non-quad, its sub-face (corner) index;
    /// `None` when `ptex` is out of range.
    pub fn locate(&self, ptex: u32) -> Option<(u32, Option<u32>)> {
        if ptex as usize >= self.len() {
            return None;
        }
        // Last face whose first Ptex index is <= ptex.
        let face = self.first.partition_point(|&f| f <= ptex) - 1;
        let count = self.first[face + 1] - self.first[face];
        let sub = (count != 1).then(|| ptex - self.first[face]);
        Some((face as u32, sub))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::MeshParts;
    use glam::DVec3;

    #[test]
    fn quads_take_one_index_and_other_faces_one_per_corner() {
        // A triangle, a quad and a pentagon sharing nothing: 3 + 1 + 5 Ptex faces.
        let parts = MeshParts {
            positions: vec![DVec3::ZERO; 12],
            face_sizes: vec![3, 4, 5],
            face_indices: (0..12).collect(),
            ..Default::default()
        };
        let p = PtexFaces::new(&Mesh::from_parts(parts).unwrap()).unwrap();
        assert_eq!(p.len(), 9);
        assert_eq!(p.first_of(1), 3);
        assert_eq!(p.locate(0), Some((0, Some(0))));
        assert_eq!(p.locate(2), Some((0, Some(2))));
        assert_eq!(p.locate(3), Some((1, None)));
        assert_eq!(p.locate(4), Some((2, Some(0))));
        assert_eq!(p.locate(8), Some((2, Some(4))));
        assert_eq!(p.locate(9), None);
    }
}
