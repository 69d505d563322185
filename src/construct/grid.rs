//! Building quad meshes ring by ring, with their data points and sharpness tags.
//!
//! Swept constructions sample a surface on rings (one per profile parameter) × meridians
//! (one per sweep parameter). [`QuadMeshBuilder`] collects the data point of every vertex,
//! the quads joining consecutive rings, the caps from [`crate::construct::pole_cap`], and
//! crease edges along rings; [`QuadMeshBuilder::finish`] turns it into validated mesh parts.
//! Each vertex's data point is also its initial position, ready for the fitter.

use glam::DVec3;

use crate::construct::pole_cap::{self, CapVertex};
use crate::error::Result;
use crate::mesh::{Corner, Crease, MeshParts};
use crate::options::PartialOptions;

/// Collects vertices (data points), quads and tags.
#[derive(Debug, Clone, Default)]
pub struct QuadMeshBuilder {
    points: Vec<DVec3>,
    faces: Vec<[u32; 4]>,
    creases: Vec<Crease>,
    corners: Vec<Corner>,
}

impl QuadMeshBuilder {
    /// An empty builder.
    pub fn new() -> Self {
        Self::default()
    }

    /// Number of vertices so far.
    pub fn num_vertices(&self) -> u32 {
        self.points.len() as u32
    }

    /// Add one vertex with its data point; returns its id.
    pub fn add_vertex(&mut self, p: DVec3) -> u32 {
        self.points.push(p);
        self.points.len() as u32 - 1
    }

    /// Add a ring of vertices; returns their ids in order.
    pub fn add_ring(&mut self, points: impl IntoIterator<Item = DVec3>) -> Vec<u32> {
        points.into_iter().map(|p| self.add_vertex(p)).collect()
    }

    /// Join two rings of equal length with quads `(a[j], a[j+1], b[j+1], b[j])`: outward
    /// when `a → a[j+1]` and `a → b` form a right-handed pair with the outward normal.
    /// `closed` joins the last vertex back to the first.
    pub fn connect_rings(&mut self, a: &[u32], b: &[u32], closed: bool) {
        let n = a.len();
        let spans = if closed { n } else { n.saturating_sub(1) };
        for j in 0..spans {
            let k = (j + 1) % n;
            self.faces.push([a[j], a[k], b[k], b[j]]);
        }
    }

    /// Close `ring` (4k ids, counter-clockwise seen from the cap's outside unless `flip`)
    /// with a grid cap, placing each new vertex with `place`.
    pub fn grid_cap(
        &mut self,
        ring: &[u32],
        flip: bool,
        mut place: impl FnMut(CapVertex) -> DVec3,
    ) -> Result<()> {
        let cap = pole_cap::grid_cap(ring, self.num_vertices(), flip)?;
        for v in cap.vertices {
            let p = place(v);
            self.add_vertex(p);
        }
        self.faces.extend(cap.faces);
        Ok(())
    }

    /// Close a crease `ring` (4k ids, oriented as for [`QuadMeshBuilder::grid_cap`]) with a
    /// flat cap: one ring of quads to an inner ring at relative radius
    /// [`flat_cap_inner_radius`], then a grid cap inside that. `place` gets each new vertex's
    /// position relative to the outer ring (radius 1 on it). The inner ring keeps every
    /// vertex of the crease ring regular (two faces on the cap side): a grid cap's corner
    /// placed on the crease would have one face spanning a straight angle, where the limit's
    /// two tangents along the crease are parallel and the surface folds in its plane.
    pub fn flat_cap(
        &mut self,
        ring: &[u32],
        flip: bool,
        mut place: impl FnMut(CapVertex) -> DVec3,
    ) -> Result<()> {
        let n = ring.len();
        let inner_radius = flat_cap_inner_radius(n);
        let inner = self.add_ring((0..n).map(|p| {
            place(CapVertex {
                radius: inner_radius,
                turn: p as f64 / n as f64,
            })
        }));
        if flip {
            self.connect_rings(&inner, ring, true);
        } else {
            self.connect_rings(ring, &inner, true);
        }
        self.grid_cap(&inner, flip, |v| {
            place(CapVertex {
                radius: v.radius * inner_radius,
                turn: v.turn,
            })
        })
    }

    /// Close `ring` at a new tip vertex at `p`, tagged as a corner of `sharpness`.
    pub fn tip(&mut self, ring: &[u32], p: DVec3, sharpness: f32, flip: bool) -> Result<u32> {
        let tip = self.add_vertex(p);
        self.faces.extend(pole_cap::tip_fan(ring, tip, flip)?);
        self.corners.push(Corner {
            vertex: tip,
            sharpness,
        });
        Ok(tip)
    }

    /// Tag ring edges `(ring[j], ring[j+1])` (indices wrapping) for each `j` in `edges`.
    pub fn crease_ring(
        &mut self,
        ring: &[u32],
        edges: impl IntoIterator<Item = usize>,
        sharpness: f32,
    ) {
        let n = ring.len();
        for j in edges {
            self.creases.push(Crease {
                vertices: [ring[j % n], ring[(j + 1) % n]],
                sharpness,
            });
        }
    }

    /// The mesh parts, carrying `options` as its tags.
    pub fn finish(self, options: PartialOptions) -> MeshParts {
        MeshParts {
            positions: self.points,
            face_sizes: vec![4; self.faces.len()],
            face_indices: self.faces.into_iter().flatten().collect(),
            creases: self.creases,
            corners: self.corners,
            holes: Vec::new(),
            options,
        }
    }
}

/// Relative radius of a flat cap's inner ring around a ring of `n = 4k` vertices:
/// `k / (k + 2)`, so that the cap's `k / 2` concentric squares and the one ring of quads
/// outside them step inwards equally.
pub fn flat_cap_inner_radius(n: usize) -> f64 {
    let k = (n / 4) as f64;
    k / (k + 2.0)
}
