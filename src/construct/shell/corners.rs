//! The corner vector of every vertex of the crust's mesh: the direction and length by which
//! the offset leaves the surface at that vertex.
//!
//! - **Smooth vertex** (all its faces share one tangent plane: interior smooth vertices,
//!   extraordinary ones, darts, semi-sharp features, boundary vertices of open surfaces):
//!   `c n`, with `n` the exact unit limit normal, taken at the corner of the vertex's first
//!   face (the evaluator's exact corner limit; at extraordinary vertices its tangent plane is
//!   exact).
//! - **Crease or corner vertex** (infinitely sharp edges split its faces into sectors with
//!   different one-sided normals `n₁ … n_k`): one *mitered* vector `c m` shared by all its
//!   faces, `m` the shortest vector with `m · nᵢ = 1` for every sector (two sectors:
//!   `m = (n₁ + n₂) / (1 + n₁ · n₂)`; three or more: least squares). The offset of each side
//!   then lies at distance `c` from that side's tangent plane at the vertex, and the two
//!   sides of a crease meet on one curve (a watertight inner surface); the distance from
//!   the offset crease to the surface crease is `c |m| = c / cos(θ/2)` for a crease whose
//!   sides turn by θ. A crease turning by more than [`MAX_MITER_TURN_DEG`] is refused: the
//!   miter would be more than 4 thicknesses long.
//! - **Next to a crease** the miter is *feathered*. Relative to a side's tangent plane the
//!   miter has a sideways part `m − nᵢ` of length `tan(θ/2)`: at the crease the inner wall
//!   starts `c tan(θ/2)` sideways from the surface crease (where the true offsets of the two
//!   sides meet). Were the crease's neighbours given their plain normals, the crust would
//!   undo that shift within one face, and a face narrower than about twice the shift (a
//!   fine crust level, a thick shell) folds. So every vertex within
//!   [`FEATHER`]` · c tan(θ/2)` (along the mesh's edges) of a crease vertex `x` takes the
//!   sideways part of `x`'s miter, relative to its own normal `n`, times a weight falling
//!   linearly from 1 at `x` to 0 at that distance: `n + w (m − (m · n) n)`. Its normal part
//!   stays 1: the offset is still `c` from the vertex's tangent plane (on a flat side it is
//!   exactly the true offset, trimmed where the sides meet); only where it lies along the
//!   side spreads out, so that the crust's sideways slope stays below `1.875 / FEATHER`
//!   of the surface's.
//! - **Next to a corner** (three or more sectors) one crease's shift is not enough: on a
//!   box's wall next to a corner the inner wall must keep `c` from both other walls, and a
//!   vertex shifted away from one of them only would bring the offset back across the
//!   corner's miter within one face (the fold of fine crusts at corners, before). There
//!   the shifts of the different walls add up, and the crease vertices along each crease
//!   are feathered from the corner too (`feather`): the inner wall of a box is then
//!   exactly the inner box at every level.
//! - **No normal** (the derivatives are parallel at every face corner of the vertex: a
//!   collapsed control mesh): an error naming the vertex.

use glam::{DMat3, DVec3};

use crate::error::{Error, Result};
use crate::eval::{Evaluator, LimitSample};
use crate::math;
use crate::mesh::Mesh;
use crate::topology::Level;

/// Largest crease turning angle a miter accepts (its length is then `1 / cos(θ/2)` = 4).
pub const MAX_MITER_TURN_DEG: f64 = 151.04;

/// The feathering reach over the miter's sideways length `c tan(θ/2)` (see the module doc):
/// the crust's sideways slope next to a crease is at most `1.875 / FEATHER` (1.875: the
/// quintic blend's steepest slope over one face).
pub const FEATHER: f64 = 3.0;

/// Two unit normals closer than this (`1 − n₁ · n₂`) belong to one sector.
const SAME_SECTOR: f64 = 1e-10;

/// A corner's `|du × dv|` below this fraction of `|du| |dv|`, or a derivative shorter than
/// this fraction of the mesh's bounding-box diagonal, has no normal.
const NO_NORMAL: f64 = 1e-12;

/// The Ptex `(u, v)` of corner `k` of a quad.
pub const CORNER_UV: [(f64, f64); 4] = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];

/// The unit normal of limit sample `s` at a face corner, `None` where the derivatives are
/// parallel or vanish (relative to `diag`, the mesh's bounding-box diagonal).
fn corner_normal(s: &LimitSample, diag: f64) -> Option<DVec3> {
    let cross = s.du.cross(s.dv);
    let (a, b) = (s.du.length(), s.dv.length());
    let tiny = NO_NORMAL * diag;
    (a > tiny && b > tiny && cross.length() > NO_NORMAL * a * b).then(|| cross / cross.length())
}

/// The corner direction `m` (before scaling by the thickness; `m · n = 1` for the vertex's
/// normal `n`, and for every sector's at a crease) of every vertex of `ev`'s quad mesh, in
/// vertex order, feathered next to creases for thickness `thickness` (see the module doc);
/// a vertex in no face with surface gets the zero vector. `name` names a vertex in messages.
///
/// With them, for every vertex, the crease vertex whose miter it carries or is feathered
/// from (itself at a crease; `None` away from creases): what a fold message names.
///
/// Errors ([`Error::InvalidArgument`]): a vertex with faces but no normal; a crease turning
/// by more than [`MAX_MITER_TURN_DEG`].
pub fn corner_directions(
    ev: &Evaluator,
    thickness: f64,
    name: &dyn Fn(usize) -> String,
) -> Result<(Vec<DVec3>, Vec<Option<u32>>)> {
    let mesh: &Mesh = ev.mesh();
    let n = mesh.num_vertices();
    let diag = mesh.bounding_box_diagonal();
    // Per vertex: whether it has a face with surface, its limit position, and its distinct
    // sector normals.
    let mut has_face = vec![false; n];
    let mut position = vec![DVec3::ZERO; n];
    let mut sectors: Vec<Vec<DVec3>> = vec![Vec::new(); n];
    for f in 0..mesh.num_faces() {
        let face = mesh.face(f);
        for (k, &vertex) in face.iter().enumerate() {
            let v = vertex as usize;
            if !ev.has_surface(f as u32) {
                continue;
            }
            has_face[v] = true;
            let (u, w) = CORNER_UV[k];
            let sample = ev.evaluate(f as u32, u, w)?;
            position[v] = sample.position;
            if let Some(normal) = corner_normal(&sample, diag) {
                if !sectors[v].iter().any(|s| 1.0 - s.dot(normal) < SAME_SECTOR) {
                    sectors[v].push(normal);
                }
            }
        }
    }
    let mut directions = (0..n)
        .map(|v| match sectors[v].as_slice() {
            [] if has_face[v] => Err(Error::invalid_argument(format!(
                "{} has no normal: the limit surface's derivatives are parallel at every face \
                 corner there (a collapsed control mesh); move its control points apart",
                name(v)
            ))),
            [] => Ok(DVec3::ZERO),
            [normal] => Ok(*normal),
            normals => miter(normals, || name(v)),
        })
        .collect::<Result<Vec<DVec3>>>()?;
    let from = feather(ev, &position, &sectors, thickness, &mut directions);
    Ok((directions, from))
}

/// Two source normals closer than this (cosine) are one wall: the nearer source's
/// constraint stands for both.
const SAME_WALL: f64 = 0.94;

/// A second wall's normal must leave the span of the normals already constrained by this
/// much (sine) to be feathered in too (see [`feather`]).
const INDEPENDENT: f64 = 0.05;

/// Feather the miters of the crease and corner vertices (two or more sectors) into the
/// vertices around them (see the module doc). Each such *source* `x` reaches the vertices
/// within [`FEATHER`]` · c tan(θ/2)` of it along the mesh's edges (limit positions
/// `position`), `|m|² = 1 + tan²(θ/2)`, with weight `w` falling linearly from 1 at `x` to 0
/// there; it feathers vertices of fewer sectors (smooth vertices from creases and corners,
/// crease vertices from corners along their crease).
///
/// At a vertex `v` with own normals `N_v` and direction `d₀` (its normal or miter), each
/// normal `n` of a source other than those on `v`'s own sides (for each own normal, the
/// source's closest) is a constraint `d · n ≥ d₀ · n + w (1 − d₀ · n)`: at the source
/// (`w = 1`) the offset is `c` from that wall's plane, as the miter puts it, and the
/// constraint fades to nothing at the reach. `d` is the shortest correction of `d₀`
/// orthogonal to `N_v` meeting them (`d · n = 1` for the own normals stays). With one
/// source this is exactly the old rule: the miter's sideways part times `w`. Constraints
/// are taken by decreasing weight; a normal within [`SAME_WALL`] of one taken is the same
/// wall seen from a farther source and is skipped. Within reach of a corner (three or more
/// sectors) the constraints of different walls add up (a second wall must leave the span
/// of those taken by [`INDEPENDENT`]): next to a box corner the wall vertex `(a, b)` gets
/// `n + w_x(a) e_x + w_y(b) e_y`, the crease vertex on the edge `(1, 1, w)`, and the inner
/// wall is exactly the trimmed offset. Elsewhere only the nearest source counts (what two
/// creases far from any corner would make of each other is not a corner's trimming).
///
/// Returns the source each vertex carries the feathering of (the nearest reaching it;
/// itself at a crease or corner; `None` elsewhere).
fn feather(
    ev: &Evaluator,
    position: &[DVec3],
    sectors: &[Vec<DVec3>],
    c: f64,
    dirs: &mut [DVec3],
) -> Vec<Option<u32>> {
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;
    let level = Level::from_mesh_with_options(ev.mesh(), ev.options());
    let n = position.len();
    let count = |v: usize| sectors[v].len();
    // The reach of each source's miter: FEATHER c tan(θ/2), |m|² = 1 + tan²(θ/2).
    let reach: Vec<f64> = (0..n)
        .map(|x| match count(x) {
            0 | 1 => 0.0,
            _ => FEATHER * c * (dirs[x].length_squared() - 1.0).max(0.0).sqrt(),
        })
        .collect();
    // Per vertex: the sources reaching it, with their weights.
    let mut reached: Vec<Vec<(f64, u32)>> = vec![Vec::new(); n];
    let mut dist = vec![f64::INFINITY; n];
    let mut touched = Vec::new();
    let mut heap = BinaryHeap::new();
    for x in (0..n).filter(|&x| reach[x] > 0.0) {
        // Dijkstra from x within its reach, through vertices of fewer sectors than x.
        dist[x] = 0.0;
        touched.push(x);
        heap.push(Reverse((Ordered(0.0), x)));
        while let Some(Reverse((Ordered(d), v))) = heap.pop() {
            if d > dist[v] || (v != x && count(v) >= count(x)) {
                continue;
            }
            for &e in level.vertex_edges(v) {
                let [a, b] = level.edge_vertices(e as usize);
                let w = (if a as usize == v { b } else { a }) as usize;
                let dw = d + (position[w] - position[v]).length();
                if dw >= reach[x] || dw >= dist[w] {
                    continue;
                }
                if dist[w].is_infinite() {
                    touched.push(w);
                }
                dist[w] = dw;
                heap.push(Reverse((Ordered(dw), w)));
            }
        }
        for &v in &touched {
            if v != x && (1..count(x)).contains(&count(v)) {
                reached[v].push((1.0 - dist[v] / reach[x], x as u32));
            }
            dist[v] = f64::INFINITY;
        }
        touched.clear();
    }
    let mut from: Vec<Option<u32>> = (0..n).map(|v| (count(v) > 1).then_some(v as u32)).collect();
    for (v, sources) in reached.iter_mut().enumerate() {
        if sources.is_empty() {
            continue;
        }
        // By decreasing weight, ties by source index: deterministic.
        sources.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        if count(v) == 1 {
            from[v] = Some(sources[0].1);
        }
        let corner_near = sources.iter().any(|&(_, x)| count(x as usize) > 2);
        let used = if corner_near { sources.len() } else { 1 };
        dirs[v] = feathered(dirs[v], &sectors[v], &sources[..used], sectors);
    }
    from
}

/// The feathered direction of a vertex with direction `d0` and own normals `own` under the
/// constraints of `sources` (weight, vertex; by decreasing weight): see [`feather`].
fn feathered(d0: DVec3, own: &[DVec3], sources: &[(f64, u32)], sectors: &[Vec<DVec3>]) -> DVec3 {
    // An orthonormal basis of the normals constrained so far (the own ones first).
    let mut basis: Vec<DVec3> = Vec::with_capacity(3);
    let orthogonal = |basis: &[DVec3], n: DVec3| basis.iter().fold(n, |r, b| r - *b * b.dot(r));
    for &o in own {
        let r = orthogonal(&basis, o);
        if r.length() > 1e-9 {
            basis.push(r / r.length());
        }
    }
    let mut taken: Vec<DVec3> = Vec::new();
    let mut d = d0;
    for &(w, x) in sources {
        let normals = &sectors[x as usize];
        // The source's normal on each of the vertex's own sides.
        let own_side: Vec<usize> = own
            .iter()
            .filter_map(|o| {
                (0..normals.len())
                    .max_by(|&a, &b| normals[a].dot(*o).total_cmp(&normals[b].dot(*o)))
            })
            .collect();
        for (k, &nj) in normals.iter().enumerate() {
            if own_side.contains(&k) || taken.iter().any(|t| t.dot(nj) > SAME_WALL) {
                continue;
            }
            let base = d0.dot(nj);
            if base >= 1.0 {
                continue;
            }
            let target = base + w * (1.0 - base);
            let have = d.dot(nj);
            if have >= target {
                taken.push(nj);
                continue;
            }
            let r = orthogonal(&basis, nj);
            let len = r.length();
            // The first wall may be nearly the own side's (a shallow crease: the correction
            // is then w tan(θ/2), small); a second must be a different direction.
            let needed = if taken.is_empty() { 1e-9 } else { INDEPENDENT };
            if len < needed {
                continue;
            }
            let rhat = r / len;
            d += rhat * ((target - have) / len);
            basis.push(rhat);
            taken.push(nj);
        }
    }
    d
}

/// A distance ordered for the heap (never NaN: sums of lengths of finite positions).
#[derive(Debug, Clone, Copy)]
struct Ordered(f64);

impl PartialEq for Ordered {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other).is_eq()
    }
}

impl Eq for Ordered {}

impl PartialOrd for Ordered {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Ordered {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// The shortest `m` with `m · nᵢ = 1` for the unit normals `normals` (least squares when
/// they disagree), refused past [`MAX_MITER_TURN_DEG`].
fn miter(normals: &[DVec3], name: impl Fn() -> String) -> Result<DVec3> {
    let m = if let [a, b] = normals {
        (*a + *b) / (1.0 + a.dot(*b))
    } else {
        // Normal equations (Nᵀ N) m = Nᵀ 1, with a tiny ridge so that coplanar normals give
        // the shortest solution.
        let mut ntn = DMat3::ZERO;
        let mut rhs = DVec3::ZERO;
        for &n in normals {
            ntn += DMat3::from_cols(n * n.x, n * n.y, n * n.z);
            rhs += n;
        }
        let ridge = 1e-12 * (ntn.x_axis.x + ntn.y_axis.y + ntn.z_axis.z);
        (ntn + DMat3::from_diagonal(DVec3::splat(ridge))).inverse() * rhs
    };
    let limit = 1.0 / math::cos(MAX_MITER_TURN_DEG.to_radians() / 2.0);
    if m.is_finite() && m.length() <= limit {
        Ok(m)
    } else {
        Err(Error::invalid_argument(format!(
            "the sides meeting at {} turn by more than {MAX_MITER_TURN_DEG}°: their offsets \
             would meet more than {limit:.3} thicknesses away (|miter| = {:.3}); soften the \
             crease or lower the thickness",
            name(),
            m.length()
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn miters_are_at_unit_distance_from_every_sector_plane() {
        let name = || "vertex 0".to_string();
        // A right-angled crease: m = (1, 1, 0), |m| = √2.
        let m = miter(&[DVec3::X, DVec3::Y], name).unwrap();
        assert!((m - DVec3::new(1.0, 1.0, 0.0)).length() < 1e-15);
        // A cube corner: (1, 1, 1).
        let m = miter(&[DVec3::X, DVec3::Y, DVec3::Z], name).unwrap();
        assert!((m - DVec3::ONE).length() < 1e-9, "{m}");
        // A 30° crease.
        let (sin, cos) = math::sin_cos(std::f64::consts::FRAC_PI_6);
        let b = DVec3::new(cos, sin, 0.0);
        let m = miter(&[DVec3::X, b], name).unwrap();
        assert!((m.dot(DVec3::X) - 1.0).abs() < 1e-15 && (m.dot(b) - 1.0).abs() < 1e-15);
        // A knife edge (turning by 170°) is refused, naming the vertex.
        let t = 170f64.to_radians();
        let e = miter(
            &[DVec3::X, DVec3::new(math::cos(t), math::sin(t), 0.0)],
            name,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("vertex 0") && e.contains("151.04"), "{e}");
    }
}
