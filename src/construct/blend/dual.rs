//! The Catmull–Clark result of an odd-order (dual) blend. Odd orders refine on the
//! Doo–Sabin split, so no vertex survives a step; instead every face, edge and vertex of
//! level L has one face of level L + 1 centred on it (a face keeps its index at every level;
//! the GBS refinement numbers the others). The Catmull–Clark mesh is the quad split of level L
//! (vertex, next edge, face, previous edge per face corner): each of its vertices targets the
//! GBS limit at the centre of the level-(L + 1) face on its element, taken as the centroid of
//! that face's descendant at level L + 3 + [`EXTRA_LEVELS`] (for k = 3 a regular quad's
//! centroid is on the limit surface at every level: the tensor product of the curve's edge
//! midpoints; elsewhere it approaches the limit about 4× per level). Quads at a level-L
//! boundary vertex or edge are left out: an odd-order boundary is free and has no face there.
//!
//! Lattice points: the quad of corner `j` of face `g` holds the level-(L + 1) vertex of that
//! corner at its centre and the four level-(L + 1) faces round it in its quadrants (the
//! vertex's face at (0, 0), the next edge's at (1, 0), `g` at (1, 1), the previous edge's at
//! (0, 1)); each quadrant is the quad of that face's corner at the centre, so a lattice point
//! at spacing 1/4 is a corner of a quad two levels down.

use super::hub::control_mesh;
use super::input::BlendInput;
use crate::construct::design::{DesignLattice, LATTICE};
use crate::construct::{Fitted, Settings};
use crate::error::{Error, Result};
use crate::gbs::rules::centroid;
use crate::gbs::{base_level, dual_faces, step, DualFaces, GbsLevel};
use crate::mesh::MeshParts;

/// Levels below the lattice's finest faces (level L + 3) at which the centroids are taken.
pub const EXTRA_LEVELS: usize = 1;

/// Levels L..=L + 2 and the faces their steps make.
struct Chain<'a> {
    levels: &'a [GbsLevel],
    dual: Vec<DualFaces>,
}

impl Chain<'_> {
    /// The face of level `m + 1` centred on point `(s, t)` of the quad of corner `j` of face
    /// `g` at level `m` (dyadic `s`, `t` of the lattice; `None` at a free boundary).
    fn locate(&self, m: usize, g: usize, j: usize, (s, t): (f64, f64)) -> Option<u32> {
        let level = &self.levels[m].level;
        let d = &self.dual[m];
        let (fv, fe) = (level.face_vertices(g), level.face_edges(g));
        let n = fv.len();
        let (next, prev) = (fe[j] as usize, fe[(j + n - 1) % n] as usize);
        let quadrant = |u: bool, v: bool| match (u, v) {
            (false, false) => d.vertex[fv[j] as usize],
            (true, false) => d.edge[next],
            (true, true) => Some(g as u32),
            (false, true) => d.edge[prev],
        };
        if (s == 0.0 || s == 1.0) && (t == 0.0 || t == 1.0) {
            return quadrant(s == 1.0, t == 1.0);
        }
        // Descend into the quadrant's quad round the corner's child vertex q.
        let q = level.face_offset(g) + j;
        let (du, dv) = (s - 0.5, t - 0.5);
        let want = quadrant(du >= 0.0, dv >= 0.0)?;
        let child = &self.levels[m + 1].level;
        let k = child.vertex_faces(q).iter().position(|&x| x == want)?;
        let local = child.vertex_face_local_indices(q)[k] as usize;
        // The child face's next edge at q runs along u where the quadrant's signs agree
        // (both faces turn the same way round q), along v otherwise.
        let (a, b) = (2.0 * du.abs(), 2.0 * dv.abs());
        let st = if (du >= 0.0) == (dv >= 0.0) {
            (a, b)
        } else {
            (b, a)
        };
        self.locate(m + 1, want as usize, local, st)
    }
}

/// Build the odd-order blend's Catmull–Clark result (see the module documentation).
/// Errors: those of the GBS refinement and of [`Fitted::fit`].
pub fn build_dual(input: &BlendInput, settings: &Settings) -> Result<Fitted> {
    let blend = control_mesh(input)?;
    let options = input.gbs_options();
    let top = input.gbs_level as usize;
    let mut levels: Vec<GbsLevel> = vec![base_level(&blend.mesh, &options)?];
    for _ in 0..top + 3 + EXTRA_LEVELS {
        let next = step(levels.last().expect("level 0"), options.order)?;
        levels.push(next);
    }
    let finest = levels.last().expect("levels");
    let estimate = |face: u32| {
        let fv = finest.level.face_vertices(face as usize);
        centroid(fv.iter().map(|&i| finest.positions[i as usize]))
    };
    let chain = Chain {
        levels: &levels,
        dual: levels.iter().map(|l| dual_faces(&l.level)).collect(),
    };
    let level = &levels[top].level;
    let d = &chain.dual[top];
    // Catmull–Clark vertices: level-L vertices, then edges, then faces, those used.
    let (nv, ne) = (level.num_vertices(), level.num_edges());
    let mut index: Vec<Option<u32>> = vec![None; nv + ne + level.num_faces()];
    let mut positions = Vec::new();
    let mut use_slot = |slot: usize, face: u32| {
        *index[slot].get_or_insert_with(|| {
            positions.push(estimate(face));
            positions.len() as u32 - 1
        })
    };
    let (mut indices, mut design) = (Vec::new(), Vec::new());
    let n = LATTICE + 1;
    for g in 0..level.num_faces() {
        let (fv, fe) = (level.face_vertices(g), level.face_edges(g));
        let k = fv.len();
        for j in 0..k {
            let (v, next, prev) = (fv[j] as usize, fe[j] as usize, fe[(j + k - 1) % k] as usize);
            let (Some(vf), Some(nf), Some(pf)) = (d.vertex[v], d.edge[next], d.edge[prev]) else {
                continue;
            };
            indices.extend([
                use_slot(v, vf),
                use_slot(nv + next, nf),
                use_slot(nv + ne + g, g as u32),
                use_slot(nv + prev, pf),
            ]);
            for b in 0..n {
                for a in 0..n {
                    let st = (a as f64 / LATTICE as f64, b as f64 / LATTICE as f64);
                    let face = chain.locate(top, g, j, st).ok_or_else(|| {
                        Error::NumericalFailure(format!(
                            "blend: no level-{} face under corner {j} of face {g}",
                            top + 2
                        ))
                    })?;
                    design.push(estimate(face));
                }
            }
        }
    }
    let parts = MeshParts {
        positions,
        face_sizes: vec![4; indices.len() / 4],
        face_indices: indices,
        ..Default::default()
    };
    Fitted::fit(parts, settings, DesignLattice::from_points(design))
}
