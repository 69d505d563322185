//! Hui–Lai profile construction: four planar silhouettes → an interpolating Catmull-Clark
//! quad mesh with crease and corner tags.
//!
//! Pipeline ([`build`]):
//! 1. [`silhouettes`]: splines through the points (broken at corners), end kinds (open,
//!    flat cap, pointed tip, smooth pole);
//! 2. [`param`]: the common parameter `t` of the four curves (features of equal height on
//!    one ring, height matching where the curves rise);
//! 3. [`sweep`]: the axis and quadrant sweeps of the paper give the data points on rings ×
//!    meridians ([`sampling`]: rings through every breakpoint);
//! 4. topology: rings joined by quads, smooth poles and flat ends closed by grid caps (all
//!    extraordinary vertices of valence 3), pointed poles by a tip fan with an infinitely
//!    sharp corner; crease edges along each corner ring where a curve of that quadrant
//!    kinks;
//! 5. [`crate::fit::fit_cage`]: control points whose exact limit surface, under the input's
//!    subdivision options (`boundary`, `crease_method`; also written as the mesh's option
//!    tags), interpolates the data points.

pub mod input;
pub mod param;
pub mod sampling;
pub mod shapes;
pub mod silhouettes;
pub mod sweep;

use std::f64::consts::TAU;

use glam::DVec3;

pub use input::{Caps, ForcedCorners, ProfileInput};
pub use silhouettes::EndKind;

use crate::construct::grid::QuadMeshBuilder;
use crate::error::Result;
use crate::fit::{fit_cage, FitReport, FittedCage};
use crate::mesh::{Mesh, MeshParts, SHARPNESS_INFINITE};
use param::CommonParam;
use sampling::Rings;
use silhouettes::Silhouettes;

/// The control cage before fitting: topology, tags, and the data point of every vertex
/// (also its position).
#[derive(Debug, Clone)]
pub struct ProfileCage {
    /// Mesh parts whose positions are the data points.
    pub parts: MeshParts,
    /// Bottom and top end kinds.
    pub ends: [EndKind; 2],
    /// Ring index (0 = bottom) of each ring that carries crease edges.
    pub crease_rings: Vec<usize>,
    /// Bounding-box diagonal of the input points.
    pub size: f64,
}

/// Steps 1–4: the cage with data points, not yet fitted (tagged with the input's options).
pub fn build_cage(input: &ProfileInput) -> Result<ProfileCage> {
    input.check_settings()?;
    let sil = Silhouettes::new(input)?;
    let param = CommonParam::new(&sil)?;
    let n = input.around as usize;
    if n < 8 && sil.ends.contains(&EndKind::Tip) {
        return Err(crate::error::Error::invalid_argument(format!(
            "around = {n} would give a pointed pole (tip) valence {}: an interior vertex of \
             valence 2; use around >= 8",
            n / 2
        )));
    }
    let k = n / 4;
    // The cap fills the ring next to the pole, whose distance shrinks like h² with the
    // graded rings (see `crate::construct::grading`).
    let cap_rings = 1;
    let rings = Rings::new(&sil, &param, input.along as usize, cap_rings)?;
    let meridian = |q: usize| TAU * q as f64 / n as f64;
    let curve_at = |t: f64| param.points(&sil, t);
    let mut b = QuadMeshBuilder::new();
    let [bottom, top] = sil.ends;
    let offset = |e: EndKind| match e {
        EndKind::Open | EndKind::Flat => 0,
        EndKind::Tip => 1,
        EndKind::Smooth => cap_rings,
    };
    let (lo, hi) = (offset(bottom), rings.t.len() - 1 - offset(top));
    let mut ids: Vec<Vec<u32>> = Vec::with_capacity(hi + 1 - lo);
    for r in lo..=hi {
        let c = curve_at(rings.t[r]);
        ids.push(b.add_ring((0..n).map(|q| sweep::surface(meridian(q), &c))));
    }
    for w in ids.windows(2) {
        b.connect_rings(&w[0], &w[1], true);
    }
    for (e, kind) in sil.ends.into_iter().enumerate() {
        let (ring, flip, t_end) = if e == 0 {
            (&ids[0], true, rings.t[0])
        } else {
            (&ids[ids.len() - 1], false, rings.t[rings.t.len() - 1])
        };
        match kind {
            EndKind::Open => {}
            EndKind::Flat => {
                let c = curve_at(t_end);
                let centre = sweep::axis(&c);
                b.grid_cap(ring, flip, |v| {
                    centre + (sweep::surface(TAU * v.turn, &c) - centre) * v.radius
                })?;
                b.crease_ring(ring, 0..n, input.crease_sharpness);
            }
            EndKind::Tip => {
                let p = sweep::surface(0.0, &curve_at(t_end));
                b.tip(ring, p, SHARPNESS_INFINITE, flip)?;
            }
            EndKind::Smooth => {
                b.grid_cap(ring, flip, |v| {
                    let depth = v.radius * cap_rings as f64;
                    let t = rings.cap_t(e, depth);
                    sweep::surface(TAU * v.turn, &curve_at(t))
                })?;
            }
        }
    }
    let mut crease_rings = Vec::new();
    for (j, sharp) in param.sharp.iter().enumerate() {
        let kinked: Vec<usize> = (0..4).filter(|&q| sharp[q] || sharp[(q + 1) % 4]).collect();
        if kinked.is_empty() {
            continue;
        }
        let r = rings.ring_of_break[j];
        let ring = &ids[r - lo];
        b.crease_ring(
            ring,
            kinked.iter().flat_map(|&q| q * k..(q + 1) * k),
            input.crease_sharpness,
        );
        crease_rings.push(r);
    }
    Ok(ProfileCage {
        parts: b.finish(input.fit_options().tags()),
        ends: sil.ends,
        crease_rings,
        size: sil.size,
    })
}

/// The data point of every vertex of `cage` (its positions), as 3-D points.
pub fn targets(cage: &ProfileCage) -> &[DVec3] {
    &cage.parts.positions
}

/// A fitted profile model: the control mesh and what it interpolates.
#[derive(Debug, Clone)]
pub struct ProfileModel {
    /// The control mesh (fitted positions, crease and corner tags, option tags).
    pub mesh: Mesh,
    /// The data point each control vertex's limit position interpolates, in vertex order.
    pub targets: Vec<DVec3>,
    /// The achieved fit residual and its tolerance.
    pub fit: FitReport,
    /// Bottom and top end kinds.
    pub ends: [EndKind; 2],
    /// Ring index (0 = bottom) of each ring that carries crease edges.
    pub crease_rings: Vec<usize>,
}

/// The whole pipeline: silhouettes → data points → cage → control points whose exact limit
/// surface passes through every data point.
///
/// Errors: [`crate::Error::InvalidArgument`] for bad input (each check says what and where;
/// also boundary interpolation *none* with an open end, whose data points no limit surface
/// reaches), [`crate::Error::NumericalFailure`] if the fit misses its tolerance.
pub fn build(input: &ProfileInput) -> Result<ProfileModel> {
    let cage = build_cage(input)?;
    let FittedCage { mesh, targets, fit } = fit_cage(cage.parts, input.fit_options())?;
    Ok(ProfileModel {
        mesh,
        targets,
        fit,
        ends: cage.ends,
        crease_rings: cage.crease_rings,
    })
}

#[cfg(test)]
mod tests;
