//! Uniform Catmull-Clark refinement in OpenSubdiv Far's component order.
//!
//! [`refine_uniform`] refines a [`Mesh`] `n` times and returns the refined mesh: positions
//! equal to `Far::TopologyRefiner::RefineUniform` + `Far::PrimvarRefinerReal<double>::Interpolate`
//! index by index (same arithmetic, same order of operations, sharpness in `f32`), faces in
//! Far's order, and the decayed crease and corner sharpness as tags.
//!
//! The step API underneath serves the evaluators: [`step::refine`] refines a
//! [`Level`] once (topology, sharpness, rules), and [`primvar::interpolate`] carries any
//! [`Primvar`] through that step — positions ([`glam::DVec3`]) or [`SparseStencil`]s, so that
//! a local neighbourhood can be refined as weights on the base vertices.

mod output;
pub mod primvar;
mod ranges;
pub(crate) mod step;
#[cfg(test)]
mod tests;

use glam::DVec3;

pub(crate) use output::{corners_of, creases_of_child};
use primvar::interpolate_polled;
pub use primvar::{interpolate, Primvar, SparseStencil};
pub use step::{refine, Refinement, VertexOrder};

use crate::control::Control;
use crate::error::{Error, Result};
use crate::mesh::Mesh;
use crate::options::SubdivOptions;
use crate::topology::Level;

/// Highest refinement level accepted: each level multiplies the face count by about 4, so
/// level 8 turns a single quad into 65,536 faces and a 10k-face mesh into 655 million.
pub const MAX_LEVEL: u32 = 8;

/// Largest number of face-vertex indices a refined mesh may have (2^26, about 16.7 million
/// quads, a few GB of topology and positions): a bound on memory rather than on levels.
pub const MAX_REFINED_FACE_INDICES: usize = 1 << 26;

/// Refine `mesh` uniformly `level` times under `options`, child vertices in Far's default
/// order (children of vertices, then of faces, then of edges), on all cores (the result does
/// not depend on the thread count: [`refine_uniform_with`]).
///
/// Level 0 returns the mesh with the options attached. Errors: [`Error::InvalidArgument`]
/// if `level` exceeds [`MAX_LEVEL`] or the refined mesh would exceed
/// [`MAX_REFINED_FACE_INDICES`] face-vertex indices.
pub fn refine_uniform(mesh: &Mesh, options: &SubdivOptions, level: u32) -> Result<Mesh> {
    refine_uniform_ordered(mesh, options, level, VertexOrder::VerticesFirst)
}

/// [`refine_uniform`] with a choice of child vertex order.
pub fn refine_uniform_ordered(
    mesh: &Mesh,
    options: &SubdivOptions,
    level: u32,
    order: VertexOrder,
) -> Result<Mesh> {
    refine_uniform_with(mesh, options, level, order, &Control::NONE)
}

/// [`refine_uniform_ordered`] with progress, cancellation and a memory budget: `control` is
/// polled through the base level's topology (at fraction 0) and each level's topology and
/// positions (every thousandth face, edge or vertex of each pass; the work of level `k`
/// counted as `4^k`), and the refinement refused before allocating when [`refined_bytes`] is
/// above the budget. Each level's positions are computed on `control`'s threads
/// ([`Control::threads`], 0: all cores), the same bit for bit for every count; its topology
/// on the calling thread.
///
/// Errors: those of [`refine_uniform`]; [`Error::Cancelled`] and [`Error::LimitExceeded`]
/// from `control`.
pub fn refine_uniform_with(
    mesh: &Mesh,
    options: &SubdivOptions,
    level: u32,
    order: VertexOrder,
    control: &Control,
) -> Result<Mesh> {
    control.report(0.0)?;
    check_level(mesh, level)?;
    control.check_memory(
        &format!("refining {} faces {level} times", mesh.num_faces()),
        refined_bytes(mesh, level),
    )?;
    // The base level's topology: polled, though counted as no work (level 0 costs 4^0 of
    // the 4^k the fractions below count).
    let base = Level::from_mesh_polled(mesh, options, &control.stage(0.0, 0.0))?;
    let refined = refine_base(mesh, base, options, level, order, control)?;
    control.report(1.0)?;
    Ok(refined)
}

/// Estimated bytes of refining `mesh` `level` times (what [`refine_uniform_with`] checks
/// against the memory budget): about 64 bytes per face-vertex index of the refined mesh
/// (its topology, edges and positions, and the parent level alive beside it).
pub fn refined_bytes(mesh: &Mesh, level: u32) -> u64 {
    let indices = mesh.face_indices().len() as f64 * 4f64.powi(level.min(MAX_LEVEL) as i32);
    (64.0 * indices).min(u64::MAX as f64) as u64
}

/// Refine `base`, the base level of `mesh`, `level` times.
fn refine_base(
    mesh: &Mesh,
    base: Level,
    options: &SubdivOptions,
    level: u32,
    order: VertexOrder,
    control: &Control,
) -> Result<Mesh> {
    if level == 0 {
        let sharpened = |v: usize| base.vertex_topology(v).is_sharpened(options.boundary);
        let corners = output::corners_of(&base, sharpened);
        let creases = output::creases_of(&base);
        let positions = mesh.positions().to_vec();
        return Ok(output::to_mesh(base, positions, corners, creases));
    }
    let mut current = base;
    let mut positions = mesh.positions().to_vec();
    // Level k (1-based) costs about 4^k: it is done at (4^(k+1) - 4) / (4^(level+1) - 4).
    let total = 4f64.powi(level as i32 + 1) - 4.0;
    let done = |k: u32| (4f64.powi(k as i32 + 1) - 4.0) / total;
    // Topology takes about half a level's time, positions the other half.
    let half = |k: u32| (done(k) + done(k + 1)) / 2.0;
    for k in 1..level {
        let r = step::refine_polled(
            &current,
            order,
            true,
            &control.stage(done(k - 1), half(k - 1)),
        )?;
        control.report(half(k - 1))?;
        positions = interpolate_polled(
            &current,
            &r,
            &positions,
            &control.stage(half(k - 1), done(k)),
        )?;
        current = r.child;
        control.report(done(k))?;
    }
    // The last level needs no neighbourhoods (Far's minimal topology): its creases and the
    // vertices Far sharpens from topology are read off the parent (a child vertex has its
    // parent's topology, a child edge its parent's boundary and non-manifold status).
    let topology = control.stage(done(level - 1), half(level - 1));
    let r = step::refine_polled(&current, order, false, &topology)?;
    control.report(half(level - 1))?;
    let last = control.stage(half(level - 1), done(level));
    positions = interpolate_polled(&current, &r, &positions, &last)?;
    // Only the children of vertices can be sharpened from topology, as their parent was.
    let sharpened = |cv: usize| {
        r.child_vertex_parent_vertex(cv)
            .is_some_and(|v| current.vertex_topology(v).is_sharpened(options.boundary))
    };
    let corners = output::corners_of(&r.child, sharpened);
    let creases = output::creases_of_child(&current, &r);
    Ok(output::to_mesh(r.child, positions, corners, creases))
}

/// Refine `mesh` `level` times and return the last level with its vertex positions.
///
/// Errors as [`refine_uniform`].
pub fn refine_levels(
    mesh: &Mesh,
    options: &SubdivOptions,
    level: u32,
    order: VertexOrder,
) -> Result<(Level, Vec<DVec3>)> {
    check_level(mesh, level)?;
    let mut current = Level::from_mesh_with_options(mesh, options);
    let mut positions = mesh.positions().to_vec();
    for _ in 0..level {
        let r = refine(&current, order);
        positions = interpolate(&current, &r, &positions);
        current = r.child;
    }
    Ok((current, positions))
}

fn check_level(mesh: &Mesh, level: u32) -> Result<()> {
    if level > MAX_LEVEL {
        return Err(Error::invalid_argument(format!(
            "refinement level {level} is above the maximum {MAX_LEVEL}"
        )));
    }
    // Each level makes 4 face-vertex indices per parent face-vertex.
    let indices = mesh.face_indices().len() as f64 * 4f64.powi(level as i32);
    if indices > MAX_REFINED_FACE_INDICES as f64 {
        return Err(Error::invalid_argument(format!(
            "refining {} face indices {level} times would give {indices:.0}, above the limit {MAX_REFINED_FACE_INDICES}",
            mesh.face_indices().len()
        )));
    }
    Ok(())
}
