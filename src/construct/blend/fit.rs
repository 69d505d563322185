//! The Catmull–Clark result of a blend: the GBS mesh refined to `gbs_level`, each vertex at
//! the GBS limit there, fitted by the shared fitter so the Catmull–Clark limit passes
//! through those points; the design lattice is the GBS limit on every face's lattice, so the
//! surface report measures the distance between the two limit surfaces.

use glam::DVec3;

use super::dual::build_dual;
use super::hub::control_mesh;
use super::input::BlendInput;
use crate::construct::design::{DesignLattice, LATTICE};
use crate::construct::{Fitted, Settings};
use crate::error::{Error, Result};
use crate::gbs::limit::limit_points;
use crate::gbs::{base_level, step, GbsLevel};
use crate::mesh::MeshParts;
use crate::refine::Refinement;
use crate::topology::Level;

/// Levels below `gbs_level` at which the lattice and the targets are taken: the lattice
/// spacing is 1/LATTICE = 1/4 of a face, two quad splits.
const LATTICE_LEVELS: u32 = 2;

/// Build the blend: its GBS mesh ([`control_mesh`]), refined `input.gbs_level` times, as a
/// fitted Catmull–Clark mesh (odd orders: [`build_dual`]). Errors: those of
/// [`control_mesh`] and [`Fitted::fit`]; [`Error::InvalidArgument`] for `gbs_level` outside
/// 1..=4 (even orders) or 1..=2 (odd orders, which refine four levels further).
pub fn build(input: &BlendInput, settings: &Settings) -> Result<Fitted> {
    let most = if input.order % 2 == 1 { 2 } else { 4 };
    if !(1..=most).contains(&input.gbs_level) {
        return Err(Error::invalid_argument(format!(
            "gbs_level {} is outside 1..={most} for order {}",
            input.gbs_level, input.order
        )));
    }
    if input.order % 2 == 1 {
        return build_dual(input, settings);
    }
    let blend = control_mesh(input)?;
    let options = input.gbs_options();
    let mut levels: Vec<GbsLevel> = vec![base_level(&blend.mesh, &options)?];
    for _ in 0..input.gbs_level + LATTICE_LEVELS {
        let next = step(levels.last().expect("level 0"), options.order)?;
        levels.push(next);
    }
    let limits = limit_points(&blend.mesh, &options, input.gbs_level + LATTICE_LEVELS)?;
    let top = &levels[input.gbs_level as usize];
    let l = &top.level;
    // Even orders number a vertex's descendants as the vertex itself (vertices first).
    let parts = MeshParts {
        positions: limits.points[..l.num_vertices()].to_vec(),
        face_sizes: vec![4; l.num_faces()],
        face_indices: (0..l.num_faces())
            .flat_map(|f| l.face_vertices(f).iter().copied())
            .collect(),
        ..Default::default()
    };
    let next = &levels[input.gbs_level as usize + 1].level;
    let finest = &levels[(input.gbs_level + LATTICE_LEVELS) as usize].level;
    let design = lattice(l, next, finest, &limits.points);
    Fitted::fit(parts, settings, DesignLattice::from_points(design))
}

/// The GBS limit on every face of `level` at `(i, j)/LATTICE`, `u` fastest, from the limit
/// points two levels down (`next` is the level between, `finest` the level of the points).
fn lattice(level: &Level, next: &Level, finest: &Level, points: &[DVec3]) -> Vec<DVec3> {
    let n = LATTICE + 1;
    let mut out = vec![DVec3::ZERO; level.num_faces() * n * n];
    for f in 0..level.num_faces() {
        for j0 in 0..4 {
            let c = Refinement::face_child_face(level, f, j0) as usize;
            for j1 in 0..4 {
                let g = Refinement::face_child_face(next, c, j1) as usize;
                // The grandchild's corners in the grandchild's own (u, v), mapped to f's.
                let fine = finest.face_vertices(g);
                for (k, local) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
                    .into_iter()
                    .enumerate()
                {
                    let (u, v) = to_parent(j0, to_parent(j1, local));
                    let (i, jj) = (
                        (u * LATTICE as f64).round() as usize,
                        (v * LATTICE as f64).round() as usize,
                    );
                    out[f * n * n + jj * n + i] = points[fine[k] as usize];
                }
            }
        }
    }
    out
}

/// A point `(u, v)` of child face `j` of a quad in the quad's `(u, v)`: the quad split keeps
/// a child quad's corner `j` at its parent's corner `j`, so the children are the quadrants
/// in the parent's orientation.
fn to_parent(j: usize, (u, v): (f64, f64)) -> (f64, f64) {
    match j {
        0 => (u / 2.0, v / 2.0),
        1 => (0.5 + u / 2.0, v / 2.0),
        2 => (0.5 + u / 2.0, 0.5 + v / 2.0),
        _ => (u / 2.0, 0.5 + v / 2.0),
    }
}
