//! The control mesh: OpenSubdiv's `Far::TopologyDescriptor` model.
//!
//! Vertex positions, faces as vertex counts plus a flat index array, crease edges as vertex
//! pairs with sharpness, corner vertices with sharpness, hole faces, and the subdivision
//! options the mesh's file carried. Sharpness is `f32`, as in OpenSubdiv, so that decay and
//! fractional weights round exactly as there.
//!
//! A [`Mesh`] is validated once, at construction, against what Far accepts: non-manifold
//! edges and vertices and faces that repeat a vertex are *accepted* (they occur in
//! OpenSubdiv's own shapes); what Far cannot take is rejected with [`Error::InvalidMesh`].

use glam::DVec3;

use crate::error::{Error, Result};
use crate::options::PartialOptions;

pub mod osd_hazards;
pub mod validate;
pub use osd_hazards::{osd_hazards, Hazard, HazardKind};
pub use validate::MeshReport;

/// Largest number of vertices, faces or face-vertex indices a mesh may have: OpenSubdiv
/// indexes components with a signed 32-bit `int`.
pub const MAX_COMPONENTS: usize = i32::MAX as usize;

/// Sharpness at or above which an edge or vertex is infinitely sharp (`Sdc::Crease::SHARPNESS_INFINITE`).
pub const SHARPNESS_INFINITE: f32 = 10.0;

/// A sharp edge, given by its two end vertices (either order).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crease {
    /// The two end vertices.
    pub vertices: [u32; 2],
    /// Sharpness, `0..=10`; 10 or more is infinitely sharp.
    pub sharpness: f32,
}

/// A sharp vertex.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corner {
    /// The vertex.
    pub vertex: u32,
    /// Sharpness, `0..=10`; 10 or more is infinitely sharp.
    pub sharpness: f32,
}

/// The raw parts of a mesh, before validation. All fields public so that constructions and
/// readers can fill them; [`Mesh::from_parts`] checks them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MeshParts {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Number of vertices of each face.
    pub face_sizes: Vec<u32>,
    /// Face vertex indices, face after face, 0-based.
    pub face_indices: Vec<u32>,
    /// Sharp edges.
    pub creases: Vec<Crease>,
    /// Sharp vertices.
    pub corners: Vec<Corner>,
    /// Faces that are holes (no limit surface), 0-based face indices.
    pub holes: Vec<u32>,
    /// Subdivision options carried by the mesh (file tags); unset fields take the defaults.
    pub options: PartialOptions,
}

/// A validated control mesh. Immutable; build a new one to change it.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    parts: MeshParts,
    face_offsets: Vec<u32>,
}

impl Mesh {
    /// Validate `parts` and build a mesh.
    ///
    /// Errors ([`Error::InvalidMesh`]): no faces, a face with fewer than 3 vertices, a vertex
    /// index out of range, face indices not matching the face sizes, a non-finite
    /// coordinate, a NaN or negative sharpness, a crease on a vertex pair that is not an
    /// edge, a corner or hole index out of range, more than [`MAX_COMPONENTS`] components.
    pub fn from_parts(parts: MeshParts) -> Result<Mesh> {
        let nv = parts.positions.len();
        let nf = parts.face_sizes.len();
        if nv > MAX_COMPONENTS || nf > MAX_COMPONENTS || parts.face_indices.len() > MAX_COMPONENTS {
            return Err(Error::invalid_mesh(format!(
                "too many components (limit {MAX_COMPONENTS} vertices, faces or face indices)"
            )));
        }
        if nf == 0 {
            return Err(Error::invalid_mesh("mesh has no faces"));
        }
        if let Some((i, p)) = parts
            .positions
            .iter()
            .enumerate()
            .find(|(_, p)| !p.is_finite())
        {
            return Err(Error::invalid_mesh(format!(
                "vertex {i} has a non-finite coordinate ({} {} {})",
                p.x, p.y, p.z
            )));
        }
        let mut face_offsets = Vec::with_capacity(nf + 1);
        let mut total: usize = 0;
        face_offsets.push(0u32);
        for (f, &n) in parts.face_sizes.iter().enumerate() {
            if n < 3 {
                return Err(Error::invalid_mesh(format!(
                    "face {f} has {n} vertices; a face needs at least 3"
                )));
            }
            total += n as usize;
            if total > parts.face_indices.len() {
                return Err(Error::invalid_mesh(format!(
                    "face sizes add up to more than the {} face indices given",
                    parts.face_indices.len()
                )));
            }
            face_offsets.push(total as u32);
        }
        if total != parts.face_indices.len() {
            return Err(Error::invalid_mesh(format!(
                "face sizes add up to {total} but {} face indices were given",
                parts.face_indices.len()
            )));
        }
        for f in 0..nf {
            let (a, b) = (face_offsets[f] as usize, face_offsets[f + 1] as usize);
            if let Some(&v) = parts.face_indices[a..b].iter().find(|&&v| v as usize >= nv) {
                return Err(Error::invalid_mesh(format!(
                    "face {f} refers to vertex {v}, but the mesh has {nv} vertices"
                )));
            }
        }
        check_creases(&parts, &face_offsets)?;
        for (i, c) in parts.corners.iter().enumerate() {
            if c.vertex as usize >= nv {
                return Err(Error::invalid_mesh(format!(
                    "corner {i} is on vertex {}, but the mesh has {nv} vertices",
                    c.vertex
                )));
            }
            check_sharpness(c.sharpness, || format!("corner {i} (vertex {})", c.vertex))?;
        }
        if let Some(&h) = parts.holes.iter().find(|&&h| h as usize >= nf) {
            return Err(Error::invalid_mesh(format!(
                "hole face {h} is out of range; the mesh has {nf} faces"
            )));
        }
        Ok(Mesh {
            parts,
            face_offsets,
        })
    }

    /// A mesh from parts the crate built itself and knows to satisfy every check of
    /// [`Mesh::from_parts`] (a refined level: faces, creases and corners derived from a valid
    /// mesh), with `face_offsets` already known. Skips the validation, which costs more than
    /// the refinement itself; `from_parts` on the same parts must succeed (tested).
    pub(crate) fn from_trusted_parts(parts: MeshParts, face_offsets: Vec<u32>) -> Mesh {
        debug_assert_eq!(face_offsets.len(), parts.face_sizes.len() + 1);
        debug_assert_eq!(
            face_offsets.last().map(|&n| n as usize),
            Some(parts.face_indices.len())
        );
        Mesh {
            parts,
            face_offsets,
        }
    }

    /// Vertex positions.
    pub fn positions(&self) -> &[DVec3] {
        &self.parts.positions
    }
    /// Number of vertices of each face.
    pub fn face_sizes(&self) -> &[u32] {
        &self.parts.face_sizes
    }
    /// All face vertex indices, face after face.
    pub fn face_indices(&self) -> &[u32] {
        &self.parts.face_indices
    }
    /// The vertices of face `f`, in order. Panics if `f` is out of range.
    pub fn face(&self, f: usize) -> &[u32] {
        let (a, b) = (
            self.face_offsets[f] as usize,
            self.face_offsets[f + 1] as usize,
        );
        &self.parts.face_indices[a..b]
    }
    /// Offset of each face's first index in [`Mesh::face_indices`], plus the total at the end.
    pub fn face_offsets(&self) -> &[u32] {
        &self.face_offsets
    }
    /// Number of vertices.
    pub fn num_vertices(&self) -> usize {
        self.parts.positions.len()
    }
    /// Number of faces.
    pub fn num_faces(&self) -> usize {
        self.parts.face_sizes.len()
    }
    /// Sharp edges.
    pub fn creases(&self) -> &[Crease] {
        &self.parts.creases
    }
    /// Sharp vertices.
    pub fn corners(&self) -> &[Corner] {
        &self.parts.corners
    }
    /// Hole faces.
    pub fn holes(&self) -> &[u32] {
        &self.parts.holes
    }
    /// Options carried by the mesh (file tags).
    pub fn options(&self) -> PartialOptions {
        self.parts.options
    }
    /// The parts this mesh was built from.
    pub fn parts(&self) -> &MeshParts {
        &self.parts
    }
    /// This mesh's faces, tags and options with `positions` as its vertices (as many, all
    /// finite: the caller checks). The topology was validated with this mesh; the positions
    /// are moved in, not copied.
    pub(crate) fn with_positions(&self, positions: Vec<DVec3>) -> Mesh {
        debug_assert!(positions.len() == self.num_vertices());
        let p = &self.parts;
        Mesh {
            parts: MeshParts {
                positions,
                face_sizes: p.face_sizes.clone(),
                face_indices: p.face_indices.clone(),
                creases: p.creases.clone(),
                corners: p.corners.clone(),
                holes: p.holes.clone(),
                options: p.options,
            },
            face_offsets: self.face_offsets.clone(),
        }
    }
    /// Replace the vertex positions by `positions` (as many, all finite: the caller checks).
    pub(crate) fn set_positions(&mut self, positions: &[DVec3]) {
        debug_assert!(positions.len() == self.num_vertices());
        self.parts.positions.copy_from_slice(positions);
    }
    /// Consume the mesh and return its parts, to modify and validate again.
    pub fn into_parts(self) -> MeshParts {
        self.parts
    }
    /// Axis-aligned bounding box `(min, max)` of the vertex positions.
    pub fn bounding_box(&self) -> (DVec3, DVec3) {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for p in &self.parts.positions {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        (lo, hi)
    }
    /// Length of the bounding-box diagonal: the scale that tolerances are relative to.
    pub fn bounding_box_diagonal(&self) -> f64 {
        let (lo, hi) = self.bounding_box();
        if self.parts.positions.is_empty() {
            0.0
        } else {
            (hi - lo).length()
        }
    }
}

fn check_sharpness(s: f32, what: impl Fn() -> String) -> Result<()> {
    if s.is_nan() || s < 0.0 {
        return Err(Error::invalid_mesh(format!(
            "{} has sharpness {s}; sharpness must be a number >= 0",
            what()
        )));
    }
    Ok(())
}

fn check_creases(parts: &MeshParts, face_offsets: &[u32]) -> Result<()> {
    if parts.creases.is_empty() {
        return Ok(());
    }
    let nv = parts.positions.len();
    // The creased vertex pairs, sorted, and whether a face edge joins each: a look-up per
    // edge in the (usually few) creases instead of a set of every edge (a 256 × 512
    // revolution's cage: 0.5 M edges for 512 creases).
    let key = |[a, b]: [u32; 2]| (a.min(b), a.max(b));
    let mut creased: Vec<(u32, u32)> = parts.creases.iter().map(|c| key(c.vertices)).collect();
    creased.sort_unstable();
    creased.dedup();
    let mut joined = vec![false; creased.len()];
    // Only edges between two creased vertices are looked up.
    let mut on_crease = vec![false; nv];
    for &(a, b) in &creased {
        for v in [a, b] {
            if let Some(c) = on_crease.get_mut(v as usize) {
                *c = true;
            }
        }
    }
    for w in face_offsets.windows(2) {
        let face = &parts.face_indices[w[0] as usize..w[1] as usize];
        for (i, &a) in face.iter().enumerate() {
            let b = face[(i + 1) % face.len()];
            if !(on_crease[a as usize] && on_crease[b as usize]) {
                continue;
            }
            if let Ok(k) = creased.binary_search(&key([a, b])) {
                joined[k] = true;
            }
        }
    }
    for (i, c) in parts.creases.iter().enumerate() {
        let [a, b] = c.vertices;
        if a as usize >= nv || b as usize >= nv {
            return Err(Error::invalid_mesh(format!(
                "crease {i} ({a} {b}) refers to a vertex out of range; the mesh has {nv} vertices"
            )));
        }
        if !creased.binary_search(&key([a, b])).is_ok_and(|k| joined[k]) {
            return Err(Error::invalid_mesh(format!(
                "crease {i} is on vertices {a} {b}, which are not joined by an edge"
            )));
        }
        check_sharpness(c.sharpness, || format!("crease {i} ({a} {b})"))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::quad;

    #[test]
    fn accepts_a_quad_and_reports_counts() {
        let m = Mesh::from_parts(quad()).unwrap();
        assert_eq!(m.num_vertices(), 4);
        assert_eq!(m.face(0), &[0, 1, 2, 3]);
        assert_eq!(m.bounding_box_diagonal(), 2f64.sqrt());
    }

    #[test]
    fn rejects_what_far_cannot_take() {
        let mut p = quad();
        p.face_indices[2] = 7;
        assert!(
            matches!(Mesh::from_parts(p), Err(Error::InvalidMesh(m)) if m.contains("vertex 7"))
        );
        let mut p = quad();
        p.face_sizes = vec![2, 2];
        assert!(
            matches!(Mesh::from_parts(p), Err(Error::InvalidMesh(m)) if m.contains("at least 3"))
        );
        let mut p = quad();
        p.positions[1].y = f64::NAN;
        assert!(Mesh::from_parts(p).is_err());
        let mut p = quad();
        p.creases.push(Crease {
            vertices: [0, 2],
            sharpness: 1.0,
        });
        assert!(
            matches!(Mesh::from_parts(p), Err(Error::InvalidMesh(m)) if m.contains("not joined"))
        );
        let mut p = quad();
        p.creases.push(Crease {
            vertices: [0, 1],
            sharpness: -1.0,
        });
        assert!(Mesh::from_parts(p).is_err());
        let mut p = quad();
        p.corners.push(Corner {
            vertex: 2,
            sharpness: f32::NAN,
        });
        assert!(Mesh::from_parts(p).is_err());
        let mut p = quad();
        p.holes.push(1);
        assert!(Mesh::from_parts(p).is_err());
    }

    /// New positions on a mesh give the mesh `from_parts` builds from them and the old
    /// faces, tags and options (face offsets included).
    #[test]
    fn with_positions_is_from_parts_with_the_new_positions() {
        let mut p = quad();
        p.creases.push(Crease {
            vertices: [1, 0],
            sharpness: 2.5,
        });
        p.corners.push(Corner {
            vertex: 2,
            sharpness: 10.0,
        });
        p.holes.push(0);
        p.options.crease_method = Some(crate::options::CreaseMethod::Chaikin);
        let m = Mesh::from_parts(p.clone()).unwrap();
        p.positions = m.positions().iter().map(|q| *q * 2.0 + DVec3::Z).collect();
        let moved = m.with_positions(p.positions.clone());
        assert_eq!(moved, Mesh::from_parts(p).unwrap());
        assert_ne!(moved.positions(), m.positions());
    }

    /// Creases on edges in either direction (repeated too) pass; the first crease that is
    /// not an edge is the one named.
    #[test]
    fn names_the_first_crease_off_the_edges() {
        let crease = |a, b| Crease {
            vertices: [a, b],
            sharpness: 2.0,
        };
        let mut p = quad();
        p.creases = vec![crease(1, 0), crease(2, 3), crease(0, 1), crease(3, 0)];
        assert_eq!(Mesh::from_parts(p.clone()).unwrap().creases().len(), 4);
        p.creases.extend([crease(2, 0), crease(1, 3)]);
        match Mesh::from_parts(p) {
            Err(Error::InvalidMesh(m)) => assert_eq!(
                m,
                "crease 4 is on vertices 2 0, which are not joined by an edge"
            ),
            other => panic!("{other:?}"),
        }
    }
}
