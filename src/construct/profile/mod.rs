//! Hui–Lai profile construction: four planar silhouettes → an interpolating Catmull-Clark
//! quad mesh with crease and corner tags.
//!
//! Pipeline ([`build`]):
//! 1. [`silhouettes`]: splines through the points (broken at corners), end kinds (open,
//!    flat cap, pointed tip, smooth pole);
//! 2. [`param`]: the common parameter `t` of the four curves (features of equal height on
//!    one ring, height matching where the curves rise);
//! 3. [`hui_lai`]: the axis and quadrant sweeps of the paper give the data points on rings ×
//!    meridians ([`sampling`]: rings through every breakpoint);
//! 4. topology: rings joined by quads, smooth poles and flat ends closed by grid caps (all
//!    extraordinary vertices of valence 3), pointed poles by a tip fan with an infinitely
//!    sharp corner; crease edges along each corner ring where a curve of that quadrant
//!    kinks;
//! 5. [`Fitted::fit`]: control points whose exact limit surface, under the settings'
//!    subdivision options (`boundary`, `crease_method`; also written as the mesh's option
//!    tags), interpolates the data points.

pub mod hui_lai;
pub mod input;
pub mod param;
pub mod sampling;
pub mod shapes;
pub mod silhouettes;

use std::cell::RefCell;
use std::collections::HashMap;
use std::f64::consts::TAU;
use std::hash::{BuildHasherDefault, Hasher};

use glam::{DVec2, DVec3};

pub use input::{ForcedCorners, ProfileInput};
pub use silhouettes::EndKind;

use crate::construct::design::{lattice_points, quad_faces, Design, DesignCoord, DesignLattice};
use crate::construct::fitted::Fitted;
use crate::construct::grid::QuadMeshBuilder;
use crate::construct::pole_cap::{grid_cap_depth, CapVertex};
use crate::construct::settings::Settings;
use crate::error::Result;
use crate::mesh::{MeshParts, SHARPNESS_INFINITE};
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
    /// The design surface on every face's lattice ([`crate::construct::design`]).
    pub design: DesignLattice,
}

/// Steps 1–4: the cage with data points, not yet fitted (tagged with the settings' options).
pub fn build_cage(input: &ProfileInput, settings: &Settings) -> Result<ProfileCage> {
    input.check_settings(settings)?;
    let sil = Silhouettes::new(input, settings)?;
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
    // A smooth pole's cap replaces several rings, so its cells are about as large as the
    // faces around it (see `pole_cap::grid_cap_depth`).
    let rings = Rings::new(&sil, &param, input.along as usize, grid_cap_depth(n))?;
    let meridian = |q: usize| TAU * q as f64 / n as f64;
    let mut b = QuadMeshBuilder::new();
    let [bottom, top] = sil.ends;
    let offset = |e: EndKind, end: usize| match e {
        EndKind::Open | EndKind::Flat => 0,
        EndKind::Tip => 1,
        EndKind::Smooth => rings.cap_depth[end],
    };
    let design = ProfileDesign {
        sil: &sil,
        param: &param,
        rings: &rings,
        depth: [offset(bottom, 0), offset(top, 1)],
        sections: RefCell::default(),
    };
    let (lo, hi) = (design.depth[0], rings.t.len() - 1 - design.depth[1]);
    let mut coords = Vec::new();
    let mut ids: Vec<Vec<u32>> = Vec::with_capacity(hi + 1 - lo);
    for r in lo..=hi {
        let s = rings.t[r];
        let c = param.points(&sil, s);
        coords.extend((0..n).map(|q| DesignCoord::Side {
            s,
            theta: meridian(q),
        }));
        ids.push(b.add_ring((0..n).map(|q| hui_lai::surface(meridian(q), &c))));
    }
    for w in ids.windows(2) {
        b.connect_rings(&w[0], &w[1], true);
    }
    for (end, kind) in sil.ends.into_iter().enumerate() {
        let (ring, flip) = if end == 0 {
            (&ids[0], true)
        } else {
            (&ids[ids.len() - 1], false)
        };
        // Each new vertex's data point is the design surface at its cap coordinates.
        let mut place = |v: CapVertex| {
            let (rho, theta) = (v.radius, TAU * v.turn);
            coords.push(DesignCoord::Cap { end, rho, theta });
            design.cap(end, rho, theta)
        };
        match kind {
            EndKind::Open => {}
            EndKind::Flat => {
                b.flat_cap(ring, flip, place)?;
                b.crease_ring(ring, 0..n, settings.crease_sharpness);
            }
            EndKind::Tip => {
                let p = place(CapVertex {
                    radius: 0.0,
                    turn: 0.0,
                });
                b.tip(ring, p, SHARPNESS_INFINITE, flip)?;
            }
            EndKind::Smooth => b.grid_cap(ring, flip, place)?,
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
            settings.crease_sharpness,
        );
        crease_rings.push(r);
    }
    let parts = b.finish(settings.fit_options().tags());
    let (ends, size, depth) = (sil.ends, sil.size, design.depth);
    // The lattice is only needed for the surface report: computed on its first call, from
    // the curves, parameter and rings moved here.
    let faces = quad_faces(&parts);
    let points = parts.positions.clone();
    let design = DesignLattice::deferred(move |control| {
        let design = ProfileDesign {
            sil: &sil,
            param: &param,
            rings: &rings,
            depth,
            sections: RefCell::default(),
        };
        lattice_points(&faces, &coords, &points, &design, control)
    });
    Ok(ProfileCage {
        parts,
        ends,
        crease_rings,
        size,
        design,
    })
}

/// The Hui–Lai design surface of a profile model, in [`DesignCoord`]s: the side at ring
/// parameter `s = t` and angle `θ` is the blended quadrant sweep [`hui_lai::surface`]; a
/// smooth pole's cap at relative radius `ρ` is the sweep at the parameter `ρ` of the way
/// (linearly by ring) from the pole to the ring it closes, a tip's fan likewise over its one
/// ring interval, and a flat cap is the end's section scaled by `ρ` about the axis point.
struct ProfileDesign<'a> {
    sil: &'a Silhouettes,
    param: &'a CommonParam,
    rings: &'a Rings,
    /// Ring intervals each end's cap or tip replaces.
    depth: [usize; 2],
    /// The four curves' points at each parameter `s` asked for (by its bits): the lattice
    /// asks for the same few `s` on every face of a ring strip, and each costs bisections.
    sections: RefCell<HashMap<u64, [DVec2; 4], BuildHasherDefault<BitsHasher>>>,
}

/// A multiplicative hash of one `u64` (a parameter's bits): SipHash, the default, cost as
/// much as the lookup saved.
#[derive(Default)]
struct BitsHasher(u64);

impl Hasher for BitsHasher {
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0 ^ x ^ (x >> 29)).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    }

    fn finish(&self) -> u64 {
        self.0 ^ (self.0 >> 32)
    }
}

impl ProfileDesign<'_> {
    /// [`CommonParam::points`] at `s`, computed once per `s`.
    fn points(&self, s: f64) -> [DVec2; 4] {
        *self
            .sections
            .borrow_mut()
            .entry(s.to_bits())
            .or_insert_with(|| self.param.points(self.sil, s))
    }
}

impl Design for ProfileDesign<'_> {
    fn side(&self, s: f64, theta: f64) -> DVec3 {
        hui_lai::surface(theta, &self.points(s))
    }

    fn angle(&self, theta: f64) -> f64 {
        theta
    }

    fn cap(&self, end: usize, rho: f64, theta: f64) -> DVec3 {
        if self.sil.ends[end] == EndKind::Flat {
            let t_end = self.rings.t[if end == 0 { 0 } else { self.rings.t.len() - 1 }];
            let c = self.points(t_end);
            let centre = hui_lai::axis(&c);
            return centre + (hui_lai::surface(theta, &c) - centre) * rho;
        }
        let t = self.rings.cap_t(end, rho * self.depth[end] as f64);
        self.side(t, theta)
    }

    fn periods(&self) -> [Option<f64>; 2] {
        [None, Some(TAU)]
    }
}

/// The data point of every vertex of `cage` (its positions), as 3-D points.
pub fn targets(cage: &ProfileCage) -> &[DVec3] {
    &cage.parts.positions
}

/// The built-in model, a bottle (`examples/profiles/bottle.json`), in its JSON form.
pub const DEFAULT_MODEL_JSON: &str = include_str!("../../../examples/profiles/bottle.json");

/// The built-in model ([`DEFAULT_MODEL_JSON`]): its curves and settings.
pub fn default_model() -> (ProfileInput, Settings) {
    // The bundled text is parsed by the unit tests; it cannot fail.
    ProfileInput::from_json(
        DEFAULT_MODEL_JSON,
        std::path::Path::new("<built-in bottle>"),
    )
    .expect("the built-in model parses")
}

/// The whole pipeline: silhouettes → data points → cage → control points whose exact limit
/// surface passes through every data point.
///
/// Errors: [`crate::Error::InvalidArgument`] for bad input or settings (each check says what
/// and where; also boundary interpolation *none* with an open end, whose data points no limit
/// surface reaches), [`crate::Error::NumericalFailure`] if the fit misses its tolerance.
pub fn build(input: &ProfileInput, settings: &Settings) -> Result<Fitted> {
    let cage = build_cage(input, settings)?;
    Fitted::fit(cage.parts, settings, cage.design)
}

#[cfg(test)]
mod tests;
