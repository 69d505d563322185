//! Generalized B-spline (GBS) subdivision (Fang, Ma & Wang 2014; Shen & Fang 2016): a
//! scheme of its own beside the Catmark rules, of order k = 3..8 with a tension v₀ > −1.
//!
//! On a regular grid its limit is the tensor product of generalized B-splines of order k,
//! piecewise in span{1, t, …, t^{k−3}, cos ωt, sin ωt} (v₀ = cos(ωΔ/2) for knot spacing Δ;
//! cosh for v₀ > 1; polynomials for v₀ = 1): circles, cylinders, tori and other surfaces of
//! revolution come out exact. The tension of level l + 1 is `√((1 + v_l)/2)`.
//!
//! - Even k (primal): per level, midpoint insertion and one tension smoothing on the
//!   Catmull–Clark quad split, then (k − 4)/2 averaging passes. At k = 4, v = 1 this is
//!   Catmull–Clark (OpenSubdiv's Catmark, boundary edge-only, infinitely sharp creases).
//! - Odd k (dual): per level, one point per face corner on the Doo–Sabin split, then
//!   (k − 3)/2 averaging passes.
//! - Boundaries and infinitely sharp creases follow the curve rule (even k); odd-order
//!   boundaries are free (Doo–Sabin's), and odd orders take no crease tags.
//!
//! [`rules`] holds the pure masks; [`refine_gbs`] refines a [`Mesh`]; [`limit`] evaluates
//! limit positions.

pub mod limit;
mod refine;
pub mod rules;
#[cfg(test)]
mod tests;

use glam::DVec3;

use crate::error::{Error, Result};
use crate::mesh::{Mesh, MeshParts};
use crate::refine::MAX_LEVEL;
use crate::topology::Level;
pub(crate) use refine::{dual_faces, DualFaces};
use rules::{next_tension, MAX_ORDER, MIN_ORDER};

/// Order and level-0 tension of a GBS scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GbsOptions {
    /// Order k (degree k − 1), [`rules::MIN_ORDER`]..=[`rules::MAX_ORDER`].
    pub order: u32,
    /// Tension v₀ of the first step, > −1: cos(θ/2) reproduces circles of n = 2π/θ control
    /// points, 1 polynomials, cosh for hyperbolas.
    pub tension: f64,
}

impl GbsOptions {
    /// Errors ([`Error::InvalidArgument`]): order outside 3..=8, tension not finite or ≤ −1.
    pub fn validate(&self) -> Result<()> {
        if !(MIN_ORDER..=MAX_ORDER).contains(&self.order) {
            return Err(Error::invalid_argument(format!(
                "GBS order {} is outside {MIN_ORDER}..={MAX_ORDER}",
                self.order
            )));
        }
        if !self.tension.is_finite() || self.tension <= -1.0 {
            return Err(Error::invalid_argument(format!(
                "GBS tension {} must be a finite number above -1",
                self.tension
            )));
        }
        Ok(())
    }
}

/// A refined GBS level: the topology, the positions and the tension its next step uses.
#[derive(Debug, Clone)]
pub struct GbsLevel {
    /// The level's topology (Far's component order for even orders).
    pub level: Level,
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Tension of the next step.
    pub tension: f64,
}

impl GbsLevel {
    /// The level as a plain mesh (faces and positions, no tags).
    pub fn to_mesh(&self) -> Result<Mesh> {
        let l = &self.level;
        Mesh::from_parts(MeshParts {
            positions: self.positions.clone(),
            face_sizes: (0..l.num_faces())
                .map(|f| l.face_vertices(f).len() as u32)
                .collect(),
            face_indices: (0..l.num_faces())
                .flat_map(|f| l.face_vertices(f).iter().copied())
                .collect(),
            ..Default::default()
        })
    }
}

/// The base level of `mesh` for GBS of order `order`, checked.
pub fn base_level(mesh: &Mesh, options: &GbsOptions) -> Result<GbsLevel> {
    options.validate()?;
    let level = Level::from_mesh_with_options(mesh, &refine::level_options());
    refine::check_level(&level, options.order)?;
    Ok(GbsLevel {
        level,
        positions: mesh.positions().to_vec(),
        tension: options.tension,
    })
}

/// Refine `level` once with order `order` (its own tension), giving the next level.
pub fn step(level: &GbsLevel, order: u32) -> Result<GbsLevel> {
    let v = level.tension;
    let (child, mut p) = if order % 2 == 0 {
        refine::even_step(&level.level, &level.positions, v)
    } else {
        refine::odd_step(&level.level, &level.positions, v)?
    };
    for _ in 0..(order - 3) / 2 {
        p = refine::average(&child, &p);
    }
    Ok(GbsLevel {
        level: child,
        positions: p,
        tension: next_tension(v),
    })
}

/// Refine `mesh` `levels` times with GBS `options`.
///
/// Errors: [`Error::InvalidArgument`] for bad options or `levels` above
/// [`crate::refine::MAX_LEVEL`]; [`Error::InvalidMesh`] for a non-manifold mesh, holes,
/// semi-sharp tags, tags at odd orders, inconsistent orientation (odd orders), or a face
/// count above the refinement limit.
pub fn refine_gbs(mesh: &Mesh, options: &GbsOptions, levels: u32) -> Result<GbsLevel> {
    if levels > MAX_LEVEL {
        return Err(Error::invalid_argument(format!(
            "refinement level {levels} is above the maximum {MAX_LEVEL}"
        )));
    }
    let indices = mesh.face_indices().len() as f64 * 4f64.powi(levels as i32);
    if indices > crate::refine::MAX_REFINED_FACE_INDICES as f64 {
        return Err(Error::invalid_argument(format!(
            "refining {} face indices {levels} times is above the limit",
            mesh.face_indices().len()
        )));
    }
    let mut current = base_level(mesh, options)?;
    for _ in 0..levels {
        current = step(&current, options.order)?;
    }
    Ok(current)
}
