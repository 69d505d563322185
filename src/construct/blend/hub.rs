//! The GBS control mesh of an N-way blend: N four-column pipes and the hub that joins their
//! ends (after Shen & Fang 2016, §2, whose formulas are lost; the ones here are designed and
//! documented in the README, "N-way pipe blends").
//!
//! The pipes are sorted counter-clockwise round the hub normal `up`. Pipe i's end ring has
//! the corners TR, TL, BL, BR (top/bottom along `up`, right towards pipe i + 1). The hub:
//! - top and bottom centres V0 = mean of the ring's top (bottom) corners ± α·ρ̄·up, each
//!   split into an N-gon of points C_i = V0 + ⅓(M_i − V0), M_i the midpoint of TR_i and
//!   TL_{i+1} (BR_i, BL_{i+1}): no vertex of valence N;
//! - valley points W_i = M_i + k_α·[(A − I) at TR_i + (A − I) at TL_{i+1}]/2, A − I the pipe's
//!   last row minus the row behind it (top and bottom);
//! - faces per pipe: a top and a bottom quad on the ring's top (bottom) edge; per valley a
//!   top and a bottom quad (ring corner, valley, next ring corner, centre point) and two
//!   side quads joining the pipes' facing side edges through the top and bottom valley.
//!
//! Valences: ring corners 5, centre points 4, valley points 3, pipe vertices 4 (2 or 3 on
//! the free ends).

use glam::DVec3;

use super::input::{BlendInput, Pipe, COLUMNS};
use crate::error::{Error, Result};
use crate::gbs::rules::circle_factor;
use crate::math::atan2;
use crate::mesh::{Mesh, MeshParts};

/// Share of the way from a centre V0 to its valley midpoint at which the centre's N-gon
/// corners sit.
const CENTRE_SPLIT: f64 = 1.0 / 3.0;

/// A pipe as placed in the blend (sorted order): unit axis, frame, control radius, rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlacedPipe {
    /// Index of the pipe in [`BlendInput::pipes`].
    pub input: usize,
    /// The pipe as given.
    pub pipe: Pipe,
    /// Unit axis, away from the junction.
    pub axis: DVec3,
    /// Unit vector towards the hub's top, perpendicular to the axis.
    pub up: DVec3,
    /// Unit vector towards the next pipe, `up × axis`.
    pub side: DVec3,
    /// Radius of the control rings (the limit cylinder's radius over λ_k(π/2)).
    pub control_radius: f64,
    /// Number of segments along the pipe.
    pub segments: usize,
    /// Index of the pipe's first control vertex (its junction ring; rows follow).
    pub first_vertex: usize,
}

/// The GBS control mesh of a blend and where its parts are.
#[derive(Debug, Clone)]
pub struct BlendMesh {
    /// The control mesh: pipe vertices first (pipe by pipe, ring by ring from the junction),
    /// then the top centre points, bottom centre points, top valleys, bottom valleys.
    pub mesh: Mesh,
    /// The pipes in hub order.
    pub pipes: Vec<PlacedPipe>,
    /// The hub normal.
    pub up: DVec3,
    /// Index of the first hub (blend) vertex; every vertex from it on is a blend vertex.
    pub first_hub_vertex: usize,
}

impl BlendMesh {
    /// The N top centre points, then the N bottom ones (vertex indices).
    pub fn centre_vertices(&self) -> std::ops::Range<usize> {
        self.first_hub_vertex..self.first_hub_vertex + 2 * self.pipes.len()
    }
    /// The N top valley points, then the N bottom ones (vertex indices).
    pub fn valley_vertices(&self) -> std::ops::Range<usize> {
        let n = self.pipes.len();
        self.first_hub_vertex + 2 * n..self.first_hub_vertex + 4 * n
    }
}

/// Share of the largest axis cross product within which a pair of pipes counts as spanning
/// the hub plane as well as the best: the first such pair (in input order) gives the
/// reference normal, so that rounding noise between equally good pairs (the axes of a
/// rotated input) cannot flip it (#17 item 7).
const SEED_TIE: f64 = 1e-9;

/// The hub normal and the pipes' order round it: the normal of the plane the axes spread
/// in (sum of consecutive cross products), the pipes sorted counter-clockwise from the
/// input's first pipe. Both depend only on the axes' relative directions, so a rotated
/// input gives the rotated mesh with the same vertex numbering.
fn hub_frame(pipes: &[Pipe]) -> Result<(DVec3, Vec<usize>)> {
    let axes: Vec<DVec3> = pipes.iter().map(|p| p.axis.normalize()).collect();
    let n = axes.len();
    let axes_ref = &axes;
    let pairs =
        || (0..n).flat_map(move |i| (i + 1..n).map(move |j| axes_ref[i].cross(axes_ref[j])));
    let largest = pairs().map(|c| c.length()).fold(0.0, f64::max);
    let seed = pairs()
        .find(|c| c.length() >= largest * (1.0 - SEED_TIE))
        .unwrap_or(DVec3::ZERO)
        .normalize();
    let e1 = seed.any_orthonormal_vector();
    let e2 = seed.cross(e1);
    let angle = |d: DVec3| atan2(d.dot(e2), d.dot(e1));
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| angle(axes[a]).total_cmp(&angle(axes[b])));
    // `e1` depends on the world frame; the cyclic order does not: start it at pipe 0.
    let first = order.iter().position(|&i| i == 0).unwrap_or(0);
    order.rotate_left(first);
    let up = (0..n)
        .map(|i| axes[order[i]].cross(axes[order[(i + 1) % n]]))
        .sum::<DVec3>()
        .normalize();
    for i in 0..n {
        let (a, b) = (axes[order[i]], axes[order[(i + 1) % n]]);
        // Gaps above half a turn leave a side of the hub without pipes.
        let gap = atan2(a.cross(b).dot(up), a.dot(b));
        if gap < -1e-9 {
            return Err(Error::invalid_argument(format!(
                "pipes {} and {} leave a gap of more than half a turn round the junction",
                order[i],
                order[(i + 1) % n]
            )));
        }
    }
    for (i, d) in axes.iter().enumerate() {
        // The hub's top and bottom fans need the pipes to spread round the normal.
        if d.dot(up).abs() > 0.5 {
            return Err(Error::invalid_argument(format!(
                "pipe {i} runs within 60° of the hub normal; the hub joins pipes that spread round it (within 30° of one plane)"
            )));
        }
    }
    Ok((up, order))
}

/// Build the blend's GBS control mesh. Errors: [`BlendInput::validate`]'s, and pipes that do
/// not spread round one hub normal ([`Error::InvalidArgument`]).
pub fn control_mesh(input: &BlendInput) -> Result<BlendMesh> {
    input.validate()?;
    let (up, order) = hub_frame(&input.pipes)?;
    let lambda = circle_factor(input.order, std::f64::consts::FRAC_PI_2);
    let mut positions = Vec::new();
    let mut placed = Vec::new();
    for &i in &order {
        let pipe = input.pipes[i];
        let axis = pipe.axis.normalize();
        let pipe_up = (up - axis * up.dot(axis)).normalize();
        let side = pipe_up.cross(axis);
        let control_radius = pipe.radius / lambda;
        let segments = ((pipe.length / pipe.radius).ceil() as usize).clamp(3, 64);
        let first_vertex = positions.len();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let corners = [
            (side + pipe_up) * s,
            (pipe_up - side) * s,
            (-side - pipe_up) * s,
            (side - pipe_up) * s,
        ];
        for r in 0..=segments {
            let c = pipe.end + axis * (pipe.length * r as f64 / segments as f64);
            positions.extend(corners.iter().map(|&k| c + k * control_radius));
        }
        placed.push(PlacedPipe {
            input: i,
            pipe,
            axis,
            up: pipe_up,
            side,
            control_radius,
            segments,
            first_vertex,
        });
    }
    let n = placed.len();
    let first_hub_vertex = positions.len();
    // Ring corner `j` (0 TR, 1 TL, 2 BL, 3 BR) of pipe `i` and its row-1 neighbour's offset.
    let corner = |i: usize, j: usize| placed[i].first_vertex + j;
    let behind = |i: usize| placed[i].axis * (placed[i].pipe.length / placed[i].segments as f64);
    let mean_radius = placed.iter().map(|p| p.control_radius).sum::<f64>() / n as f64;
    let mean = |j0: usize, j1: usize| {
        (0..n)
            .map(|i| positions[corner(i, j0)] + positions[corner(i, j1)])
            .sum::<DVec3>()
            / (2 * n) as f64
    };
    let top = mean(0, 1) + up * (input.alpha * mean_radius);
    let bottom = mean(2, 3) - up * (input.alpha * mean_radius);
    // Valley midpoints: TR_i with TL_{i+1} (top), BR_i with BL_{i+1} (bottom).
    let mid = |i: usize, j: usize, k: usize| {
        (positions[corner(i, j)] + positions[corner((i + 1) % n, k)]) / 2.0
    };
    let mut hub = Vec::with_capacity(4 * n);
    hub.extend((0..n).map(|i| top + (mid(i, 0, 1) - top) * CENTRE_SPLIT));
    hub.extend((0..n).map(|i| bottom + (mid(i, 3, 2) - bottom) * CENTRE_SPLIT));
    // A − I = −(axis × row spacing) at every ring corner of a pipe.
    let push = |i: usize| -(behind(i) + behind((i + 1) % n)) / 2.0 * input.k_alpha;
    hub.extend((0..n).map(|i| mid(i, 0, 1) + push(i)));
    hub.extend((0..n).map(|i| mid(i, 3, 2) + push(i)));
    positions.extend(hub);

    let (ct, cb) = (
        |i: usize| first_hub_vertex + i,
        |i: usize| first_hub_vertex + n + i,
    );
    let (wt, wb) = (
        |i: usize| first_hub_vertex + 2 * n + i,
        |i: usize| first_hub_vertex + 3 * n + i,
    );
    let mut faces: Vec<Vec<usize>> = Vec::new();
    for p in &placed {
        let v = |r: usize, j: usize| p.first_vertex + r * COLUMNS + j % COLUMNS;
        for r in 0..p.segments {
            for j in 0..COLUMNS {
                faces.push(vec![v(r, j), v(r, j + 1), v(r + 1, j + 1), v(r + 1, j)]);
            }
        }
    }
    let (tr, tl, bl, br) = (
        |i: usize| corner(i, 0),
        |i: usize| corner(i, 1),
        |i: usize| corner(i, 2),
        |i: usize| corner(i, 3),
    );
    for i in 0..n {
        let (next, prev) = ((i + 1) % n, (i + n - 1) % n);
        faces.push(vec![tl(i), tr(i), ct(i), ct(prev)]);
        faces.push(vec![tr(i), wt(i), tl(next), ct(i)]);
        faces.push(vec![tr(i), br(i), wb(i), wt(i)]);
        faces.push(vec![wt(i), wb(i), bl(next), tl(next)]);
        faces.push(vec![br(i), bl(i), cb(prev), cb(i)]);
        faces.push(vec![bl(next), wb(i), br(i), cb(i)]);
    }
    faces.push((0..n).map(ct).collect());
    faces.push((0..n).rev().map(cb).collect());
    let mesh = Mesh::from_parts(MeshParts {
        positions,
        face_sizes: faces.iter().map(|f| f.len() as u32).collect(),
        face_indices: faces.iter().flatten().map(|&i| i as u32).collect(),
        ..Default::default()
    })?;
    Ok(BlendMesh {
        mesh,
        pipes: placed,
        up,
        first_hub_vertex,
    })
}
