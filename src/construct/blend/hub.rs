//! The GBS control mesh of an N-way blend: N pipes of n columns and the hub that joins their
//! ends (after Shen & Fang 2016, §2, whose formulas are lost; the ones here are designed and
//! documented in the README, "N-way pipe blends").
//!
//! The pipes are sorted counter-clockwise round the hub normal `up`. Pipe i's end ring has
//! an edge on top, TL–TR (top along `up`, right towards pipe i + 1); from TR and TL a right
//! and a left arc of s = ⌊(n − 1)/2⌋ edges run down to the bottom edge BR–BL (even n) or to
//! one bottom vertex B (odd n). The hub:
//! - top and bottom centres V0 = mean of the top (bottom) valley midpoints ± α·ρ̄·up, each
//!   split into a ring of points C_i = V0 + ⅓(M_i − V0), M_i the midpoint of TR_i and
//!   TL_{i+1} (bottom: of the arcs' lower ends). For N ≤ 4 the ring is one face (a triangle
//!   or a quad); for N ≥ 5, V0 stays a vertex (the apex) and the ring is cut into a fan of
//!   ⌊N/2⌋ quads (V0, C_{2j}, C_{2j+1}, C_{2j+2}) and, for odd N, one triangle
//!   (V0, C_{N−1}, C_0). No face has more than 5 sides and no vertex more than 5 edges, so
//!   no vertex of valence N forms at any level (a primal step turns an N-gon into a
//!   valence-N vertex, and N-fold symmetric topology would need one at the centre);
//! - a column of s + 1 valley points per valley, W_i^m = midpoint of row m of pipe i's right
//!   arc and pipe i + 1's left arc + k_α·(A − I), A − I the two pipes' mean last row minus
//!   the row behind it;
//! - faces per pipe: a quad on the ring's top edge (TL_i, TR_i, C_i, C_{i−1}); per valley a
//!   top quad (TR_i, W_i^0, TL_{i+1}, C_i) and two strips of s side quads joining the arcs
//!   through the valley column; at the bottom the mirrored quads (even n), or one pentagon
//!   per bottom vertex (W_i^s, B_i, W_{i−1}^s, Cb_{i−1}, Cb_i) (odd n).
//!
//! Valences: ring corners and bottom vertices 5, other arc vertices 4, centre points 4 (3
//! under odd rings; one more on a fan's spokes), apexes ⌈N/2⌉, valley points 3 at the ends
//! of a column and 4 inside it (and at the bottom of odd rings), pipe vertices 4 (2 or 3 on
//! the free ends).

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use glam::DVec3;

use super::input::{BlendInput, Pipe};
use crate::error::{Error, Result};
use crate::gbs::rules::circle_factor;
use crate::math::{atan2, cos, sin};
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
    /// Radius of the control rings (the limit cylinder's radius over λ_k(2π/n)).
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
    /// then the top centre points, bottom centre points, the valleys row by row, and (N ≥ 5)
    /// the top and bottom apexes.
    pub mesh: Mesh,
    /// The pipes in hub order.
    pub pipes: Vec<PlacedPipe>,
    /// The hub normal.
    pub up: DVec3,
    /// Index of the first hub (blend) vertex; every vertex from it on is a blend vertex.
    pub first_hub_vertex: usize,
    /// Valley points per valley, from the top one down.
    pub valley_rows: usize,
}

impl BlendMesh {
    /// The N top centre points, then the N bottom ones (vertex indices).
    pub fn centre_vertices(&self) -> std::ops::Range<usize> {
        self.first_hub_vertex..self.first_hub_vertex + 2 * self.pipes.len()
    }
    /// The valley points, row by row from the top (N per row; vertex indices).
    pub fn valley_vertices(&self) -> std::ops::Range<usize> {
        let n = self.pipes.len();
        self.first_hub_vertex + 2 * n..self.first_hub_vertex + (2 + self.valley_rows) * n
    }
    /// The top and bottom apexes (the centres V0 as vertices; none for N ≤ 4).
    pub fn apex_vertices(&self) -> std::ops::Range<usize> {
        let start = self.valley_vertices().end;
        start..start + if self.pipes.len() >= FAN_FROM { 2 } else { 0 }
    }
}

/// Fewest pipes whose centre ring is cut into a fan round an apex (fewer make one face of at
/// most 4 sides).
pub const FAN_FROM: usize = 5;

/// The faces that cover the centre ring `ring` (counter-clockwise seen from outside) round
/// the apex `apex`: the ring itself for fewer than [`FAN_FROM`] points, else ⌊N/2⌋ quads
/// (apex, r_{2j}, r_{2j+1}, r_{2j+2}) and for odd N the triangle (apex, r_{N−1}, r_0).
fn centre_faces(ring: &[usize], apex: usize) -> Vec<Vec<usize>> {
    let n = ring.len();
    if n < FAN_FROM {
        return vec![ring.to_vec()];
    }
    let mut faces: Vec<Vec<usize>> = (0..n / 2)
        .map(|j| vec![apex, ring[2 * j], ring[2 * j + 1], ring[(2 * j + 2) % n]])
        .collect();
    if n % 2 == 1 {
        faces.push(vec![apex, ring[n - 1], ring[0]]);
    }
    faces
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
    let columns = input.columns;
    let lambda = circle_factor(input.order, TAU / columns as f64);
    // Ring vertex j at angle π/2 − π/n + 2πj/n from the side vector: an edge on top.
    let ring: Vec<(f64, f64)> = (0..columns)
        .map(|j| {
            let phi = FRAC_PI_2 + (2 * j) as f64 * PI / columns as f64 - PI / columns as f64;
            (cos(phi), sin(phi))
        })
        .collect();
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
        for r in 0..=segments {
            let c = pipe.end + axis * (pipe.length * r as f64 / segments as f64);
            positions.extend(
                ring.iter()
                    .map(|&(x, y)| c + (side * x + pipe_up * y) * control_radius),
            );
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
    // Each side arc runs `s` edges down from the top edge's ends; an odd ring ends both arcs
    // in one bottom vertex, an even ring in the bottom edge's ends.
    let s = (columns - 1) / 2;
    // Left arc of pipe i (down from TL), right arc (down from TR).
    let left = |i: usize, m: usize| placed[i].first_vertex + 1 + m;
    let right = |i: usize, m: usize| placed[i].first_vertex + (columns - m) % columns;
    let behind = |i: usize| placed[i].axis * (placed[i].pipe.length / placed[i].segments as f64);
    let mean_radius = placed.iter().map(|p| p.control_radius).sum::<f64>() / n as f64;
    // Midpoint of row m of valley i: right arc of pipe i with the left arc of pipe i + 1.
    let mid = |i: usize, m: usize| (positions[right(i, m)] + positions[left((i + 1) % n, m)]) / 2.0;
    let mean = |m: usize| (0..n).map(|i| mid(i, m)).sum::<DVec3>() / n as f64;
    let top = mean(0) + up * (input.alpha * mean_radius);
    let bottom = mean(s) - up * (input.alpha * mean_radius);
    let mut hub = Vec::with_capacity((s + 3) * n);
    hub.extend((0..n).map(|i| top + (mid(i, 0) - top) * CENTRE_SPLIT));
    hub.extend((0..n).map(|i| bottom + (mid(i, s) - bottom) * CENTRE_SPLIT));
    // A − I = −(axis × row spacing) at every ring vertex of a pipe.
    let push = |i: usize| -(behind(i) + behind((i + 1) % n)) / 2.0 * input.k_alpha;
    for m in 0..=s {
        hub.extend((0..n).map(|i| mid(i, m) + push(i)));
    }
    if n >= FAN_FROM {
        hub.extend([top, bottom]);
    }
    positions.extend(hub);

    let (ct, cb) = (
        |i: usize| first_hub_vertex + i,
        |i: usize| first_hub_vertex + n + i,
    );
    let w = |i: usize, m: usize| first_hub_vertex + (2 + m) * n + i;
    let mut faces: Vec<Vec<usize>> = Vec::new();
    for p in &placed {
        let v = |r: usize, j: usize| p.first_vertex + r * columns + j % columns;
        for r in 0..p.segments {
            for j in 0..columns {
                faces.push(vec![v(r, j), v(r, j + 1), v(r + 1, j + 1), v(r + 1, j)]);
            }
        }
    }
    for i in 0..n {
        let (next, prev) = ((i + 1) % n, (i + n - 1) % n);
        let (tl, tr) = (left(i, 0), right(i, 0));
        faces.push(vec![tl, tr, ct(i), ct(prev)]);
        faces.push(vec![tr, w(i, 0), left(next, 0), ct(i)]);
        for m in 0..s {
            faces.push(vec![right(i, m), right(i, m + 1), w(i, m + 1), w(i, m)]);
            faces.push(vec![w(i, m), w(i, m + 1), left(next, m + 1), left(next, m)]);
        }
        if columns % 2 == 0 {
            let (bl, br) = (left(i, s), right(i, s));
            faces.push(vec![br, bl, cb(prev), cb(i)]);
            faces.push(vec![left(next, s), w(i, s), br, cb(i)]);
        } else {
            // One bottom vertex per pipe: a pentagon round it, between the two valleys.
            faces.push(vec![w(i, s), left(i, s), w(prev, s), cb(prev), cb(i)]);
        }
    }
    let apex = first_hub_vertex + (3 + s) * n;
    faces.extend(centre_faces(&(0..n).map(ct).collect::<Vec<_>>(), apex));
    faces.extend(centre_faces(
        &(0..n).rev().map(cb).collect::<Vec<_>>(),
        apex + 1,
    ));
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
        valley_rows: s + 1,
    })
}
