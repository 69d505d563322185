//! Where the data points sit in the unit square, and the quad mesh joining them.
//!
//! **4 sides.** An `nu × nv` grid of quads on the nodes `(i/nu, j/nv)`. So that the mesh
//! interpolates the interior curves too, nodes are moved onto their pre-images: wherever a
//! pre-image crosses an inner grid line `U = i/nu` at `v*` (or `V = j/nv` at `u*`), the
//! nearest inner node of that line is moved along the line to the crossing, where the blend
//! is exactly the curve point (`d = 0`). Crossings are taken most transversal first; a node
//! moves once, and only if it stays more than a quarter of a cell from its neighbours along
//! the line, so the grid keeps its order. Before them, a pre-image's end inside the square
//! takes the nearest inner node (both coordinates), under the same quarter-cell rule, so a
//! curve ending inside the patch is interpolated to its end. The grid's corners are tagged
//! as infinitely sharp corners.
//!
//! **3 sides.** The square with its top side collapsed is a triangle `A = (0, 0)`,
//! `B = (1, 0)`, apex `C` (`v = 1`); it is split from its centroid to its edge midpoints into
//! three quads of `k × k` faces each (`k = ⌈max(nu, nv) / 2⌉`, so each side has `2k`
//! intervals): all quads, one interior valence-3 vertex at the centroid, the triangle's three
//! corners tagged. A node with barycentric coordinates `(a, b, c)` (weights of `A, B, C`) has
//! square coordinates `u = b / (a + b)`, `v = c` (the apex any `u`: its point is the
//! collapsed side's). Interior curves are interpolated here too: an inner node whose lines
//! `U = u` or `V = v` (rays from the apex, lines parallel to the base) cross a pre-image near
//! it is moved along that line to the nearest crossing, if the move is shorter than 0.3 of
//! its shortest edge in the triangle (so no cell turns over); nodes are taken in order, each
//! once. Before them, a pre-image's end inside the triangle takes its nearest inner node
//! (distance in the triangle) if every quad around that node stays convex, so a stroke
//! ending inside the patch is interpolated to its end.

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use super::blend::Blend;
use super::preimage::crossings;
use crate::control::Control;
use crate::error::Result;
use crate::mesh::{Corner, MeshParts, SHARPNESS_INFINITE};
use crate::options::PartialOptions;

/// The nodes of the mesh in the unit square and its quads.
#[derive(Debug, Clone, PartialEq)]
pub struct SquareGrid {
    /// Square coordinates of every vertex.
    pub uv: Vec<DVec2>,
    /// Quads, counter-clockwise in the square.
    pub faces: Vec<[u32; 4]>,
    /// Vertices tagged as corners.
    pub corners: Vec<u32>,
}

impl SquareGrid {
    /// The `nu × nv` grid with its nodes moved onto the interior pre-images of `blend`.
    pub fn four_sided(nu: usize, nv: usize, blend: &Blend) -> SquareGrid {
        let id = |i: usize, j: usize| (j * (nu + 1) + i) as u32;
        let mut uv: Vec<DVec2> = (0..=nv)
            .flat_map(|j| {
                (0..=nu).map(move |i| DVec2::new(i as f64 / nu as f64, j as f64 / nv as f64))
            })
            .collect();
        snap(&mut uv, nu, nv, blend);
        let faces = (0..nv)
            .flat_map(|j| {
                (0..nu).map(move |i| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
            })
            .collect();
        SquareGrid {
            uv,
            faces,
            corners: vec![id(0, 0), id(nu, 0), id(nu, nv), id(0, nv)],
        }
    }

    /// The triangle split into three `k × k` quad grids, nodes moved onto the interior
    /// pre-images of `blend`.
    pub fn three_sided(k: usize, blend: &Blend) -> SquareGrid {
        let (a, b, c) = (DVec3::X, DVec3::Y, DVec3::Z);
        let (ab, bc, ca) = ((a + b) * 0.5, (b + c) * 0.5, (c + a) * 0.5);
        let g = (a + b + c) / 3.0;
        let quads = [[a, ab, g, ca], [b, bc, g, ab], [c, ca, g, bc]];
        let scale = (6 * k * k) as f64;
        let mut ids: HashMap<[i64; 2], u32> = HashMap::new();
        let mut uv = Vec::new();
        let mut node = |p: DVec3| -> u32 {
            let key = [(p.x * scale).round() as i64, (p.y * scale).round() as i64];
            *ids.entry(key).or_insert_with(|| {
                let s = p.x + p.y;
                uv.push(if s > 1e-12 {
                    DVec2::new(p.y / s, p.z)
                } else {
                    DVec2::new(0.5, 1.0)
                });
                (uv.len() - 1) as u32
            })
        };
        let mut faces = Vec::with_capacity(3 * k * k);
        let mut corners = Vec::new();
        for q in &quads {
            let at = |p: usize, r: usize| {
                let (s, t) = (p as f64 / k as f64, r as f64 / k as f64);
                q[0] * ((1.0 - s) * (1.0 - t))
                    + q[1] * (s * (1.0 - t))
                    + q[2] * (s * t)
                    + q[3] * ((1.0 - s) * t)
            };
            let grid: Vec<Vec<u32>> = (0..=k)
                .map(|r| (0..=k).map(|p| node(at(p, r))).collect())
                .collect();
            corners.push(grid[0][0]);
            for r in 0..k {
                for p in 0..k {
                    faces.push([
                        grid[r][p],
                        grid[r][p + 1],
                        grid[r + 1][p + 1],
                        grid[r + 1][p],
                    ]);
                }
            }
        }
        snap_three_sided(&mut uv, &faces, blend);
        SquareGrid { uv, faces, corners }
    }

    /// Mesh parts with every vertex at its blended point, corners tagged infinitely sharp.
    /// `control` is polled once per vertex at fraction 0 (the blend precedes the fit).
    /// Errors: [`crate::Error::Cancelled`] from `control`.
    pub fn parts(&self, blend: &Blend, control: &Control) -> Result<MeshParts> {
        let poll = control.stage(0.0, 0.0);
        let n = self.uv.len();
        let mut positions = Vec::with_capacity(n);
        for (i, &p) in self.uv.iter().enumerate() {
            poll.step(i, n)?;
            positions.push(blend.point(p));
        }
        Ok(MeshParts {
            positions,
            face_sizes: vec![4; self.faces.len()],
            face_indices: self.faces.iter().flatten().copied().collect(),
            creases: Vec::new(),
            corners: self
                .corners
                .iter()
                .map(|&vertex| Corner {
                    vertex,
                    sharpness: SHARPNESS_INFINITE,
                })
                .collect(),
            holes: Vec::new(),
            options: PartialOptions::default(),
        })
    }
}

/// A candidate move of a node onto a pre-image crossing.
struct Move {
    /// How transversal the crossing is (sine of the angle between the line and the curve).
    quality: f64,
    /// 0: the node moves along `v` (on the line `U = u_i`); 1: along `u`.
    axis: usize,
    /// Node column and row.
    node: [usize; 2],
    /// The crossing's coordinate along the line.
    at: f64,
}

/// Move nodes of the `nu × nv` grid `uv` onto the interior pre-images (module documentation).
fn snap(uv: &mut [DVec2], nu: usize, nv: usize, blend: &Blend) {
    let mut moves = Vec::new();
    let mut found = Vec::new();
    for c in &blend.interior {
        for piece in &c.pieces {
            // Lines U = i/nu: the node moves in v; lines V = j/nv: in u.
            for (axis, lines, along) in [(0, nu, nv), (1, nv, nu)] {
                for line in 1..lines {
                    let value = line as f64 / lines as f64;
                    found.clear();
                    crossings(piece, axis, value, &mut found);
                    for &(at, _, dir) in &found {
                        let nearest = (at * along as f64).round() as usize;
                        if nearest == 0 || nearest >= along {
                            continue;
                        }
                        moves.push(Move {
                            quality: dir[axis].abs() / dir.length(),
                            axis,
                            node: if axis == 0 {
                                [line, nearest]
                            } else {
                                [nearest, line]
                            },
                            at,
                        });
                    }
                }
            }
        }
    }
    moves.sort_by(|a, b| {
        b.quality
            .total_cmp(&a.quality)
            .then(a.axis.cmp(&b.axis))
            .then(a.node.cmp(&b.node))
            .then(a.at.total_cmp(&b.at))
    });
    let id = |i: usize, j: usize| j * (nu + 1) + i;
    let mut moved = vec![false; uv.len()];
    // A curve's ends inside the square first: the nearest inner node moves onto the end
    // (both coordinates), if it keeps a quarter cell from its four neighbours.
    let (cu, cv) = (1.0 / nu as f64, 1.0 / nv as f64);
    for c in &blend.interior {
        for piece in &c.pieces {
            for end in [piece[0].uv, piece[piece.len() - 1].uv] {
                let (i, j) = (
                    (end.x * nu as f64).round() as usize,
                    (end.y * nv as f64).round() as usize,
                );
                if i == 0
                    || j == 0
                    || i >= nu
                    || j >= nv
                    || end.x <= 0.0
                    || end.y <= 0.0
                    || end.x >= 1.0
                    || end.y >= 1.0
                {
                    continue;
                }
                let k = id(i, j);
                let clear = uv[id(i - 1, j)].x + 0.25 * cu < end.x
                    && end.x < uv[id(i + 1, j)].x - 0.25 * cu
                    && uv[id(i, j - 1)].y + 0.25 * cv < end.y
                    && end.y < uv[id(i, j + 1)].y - 0.25 * cv;
                if !moved[k] && clear {
                    uv[k] = end;
                    moved[k] = true;
                }
            }
        }
    }
    for m in moves {
        let [i, j] = m.node;
        let k = id(i, j);
        if moved[k] {
            continue;
        }
        // Neighbours along the direction of motion, and the coordinate that moves.
        let (before, after, coord, cell) = if m.axis == 0 {
            (id(i, j - 1), id(i, j + 1), 1, 1.0 / nv as f64)
        } else {
            (id(i - 1, j), id(i + 1, j), 0, 1.0 / nu as f64)
        };
        let margin = 0.25 * cell;
        if m.at > uv[before][coord] + margin && m.at < uv[after][coord] - margin {
            uv[k][coord] = m.at;
            moved[k] = true;
        }
    }
}

/// A point of the square in the 3-sided layout's equilateral triangle `A = (0, 0)`,
/// `B = (1, 0)`, `C = (1/2, √3/2)` (barycentric `a = (1 − u)(1 − v)`, `b = u (1 − v)`, `c = v`).
fn in_triangle(p: DVec2) -> DVec2 {
    let (b, c) = (p.x * (1.0 - p.y), p.y);
    DVec2::new(b + 0.5 * c, c * 0.75f64.sqrt())
}

/// Move inner nodes of the 3-sided layout onto the interior pre-images (module documentation).
fn snap_three_sided(uv: &mut [DVec2], faces: &[[u32; 4]], blend: &Blend) {
    if blend.interior.is_empty() {
        return;
    }
    snap_ends_three_sided(uv, faces, blend);
    let mut shortest = vec![f64::INFINITY; uv.len()];
    for f in faces {
        for k in 0..4 {
            let (a, b) = (f[k] as usize, f[(k + 1) % 4] as usize);
            let d = in_triangle(uv[a]).distance(in_triangle(uv[b]));
            shortest[a] = shortest[a].min(d);
            shortest[b] = shortest[b].min(d);
        }
    }
    let mut found = Vec::new();
    for (node, p) in uv.iter_mut().enumerate() {
        if blend.on_curve(*p) {
            continue; // the boundary, or a curve's end
        }
        let here = in_triangle(*p);
        let mut best: Option<(f64, DVec2)> = None;
        for c in &blend.interior {
            for piece in &c.pieces {
                for axis in [0, 1] {
                    found.clear();
                    crossings(piece, axis, p[axis], &mut found);
                    for &(at, _, _) in &found {
                        let mut q = *p;
                        q[1 - axis] = at;
                        let d = in_triangle(q).distance(here);
                        if d < 0.3 * shortest[node] && best.map_or(true, |b| d < b.0) {
                            best = Some((d, q));
                        }
                    }
                }
            }
        }
        if let Some((_, q)) = best {
            *p = q;
        }
    }
}

/// Each interior pre-image's end inside the 3-sided layout takes its nearest inner node
/// (distance in the triangle), if that node is off every curve and moving it keeps every
/// quad around it strictly convex in the triangle (so no cell turns over).
fn snap_ends_three_sided(uv: &mut [DVec2], faces: &[[u32; 4]], blend: &Blend) {
    let mut around: Vec<Vec<usize>> = vec![Vec::new(); uv.len()];
    for (f, q) in faces.iter().enumerate() {
        for &v in q {
            around[v as usize].push(f);
        }
    }
    // +1 or -1 if the quad is strictly convex in the triangle (its turning sense), else 0.
    let turn = |uv: &[DVec2], f: usize| {
        let c = faces[f].map(|v| in_triangle(uv[v as usize]));
        let t: Vec<f64> = (0..4)
            .map(|k| (c[(k + 1) % 4] - c[k]).perp_dot(c[(k + 2) % 4] - c[(k + 1) % 4]))
            .collect();
        if t.iter().all(|&x| x > 0.0) {
            1
        } else if t.iter().all(|&x| x < 0.0) {
            -1
        } else {
            0
        }
    };
    for c in &blend.interior {
        for piece in &c.pieces {
            for end in [piece[0].uv, piece[piece.len() - 1].uv] {
                if end.min_element() <= 0.0 || end.max_element() >= 1.0 {
                    continue; // clipped at the boundary: already on it
                }
                let at = in_triangle(end);
                let nearest = (0..uv.len())
                    .filter(|&k| !around[k].is_empty())
                    .min_by(|&a, &b| {
                        in_triangle(uv[a])
                            .distance_squared(at)
                            .total_cmp(&in_triangle(uv[b]).distance_squared(at))
                    });
                let Some(k) = nearest else { continue };
                if blend.on_curve(uv[k]) {
                    continue; // the boundary, or already on a curve
                }
                let before: Vec<i32> = around[k].iter().map(|&f| turn(uv, f)).collect();
                let old = uv[k];
                uv[k] = end;
                if around[k]
                    .iter()
                    .zip(&before)
                    .any(|(&f, &t)| turn(uv, f) != t)
                {
                    uv[k] = old;
                }
            }
        }
    }
}
