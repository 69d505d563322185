//! Whether a tessellation is a closed, manifold, consistently oriented surface.

use std::collections::HashMap;

use super::Tessellation;

/// Edge counts of a polygon mesh, for checking that a tessellation is watertight.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EdgeReport {
    /// Vertices used by a polygon.
    pub vertices: usize,
    /// Undirected edges.
    pub edges: usize,
    /// Polygons.
    pub faces: usize,
    /// Edges with one polygon.
    pub boundary_edges: usize,
    /// Edges with three or more polygons.
    pub non_manifold_edges: usize,
    /// Edges with two polygons that run it the same way.
    pub misoriented_edges: usize,
}

impl EdgeReport {
    /// Count the edges of `faces` (sizes and vertex lists).
    pub fn new(face_sizes: &[u32], face_vertices: &[u32]) -> EdgeReport {
        // Per undirected edge: number of uses along (low → high) and against.
        let mut uses: HashMap<(u32, u32), [usize; 2]> = HashMap::new();
        let mut used = std::collections::HashSet::new();
        let mut start = 0;
        for &size in face_sizes {
            let c = &face_vertices[start..start + size as usize];
            for i in 0..c.len() {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                used.insert(a);
                let e = uses.entry((a.min(b), a.max(b))).or_default();
                e[usize::from(a > b)] += 1;
            }
            start += size as usize;
        }
        let mut r = EdgeReport {
            vertices: used.len(),
            edges: uses.len(),
            faces: face_sizes.len(),
            ..EdgeReport::default()
        };
        for [along, against] in uses.values() {
            match along + against {
                1 => r.boundary_edges += 1,
                2 if *along != 1 => r.misoriented_edges += 1,
                2 => {}
                _ => r.non_manifold_edges += 1,
            }
        }
        r
    }

    /// Euler characteristic `V - E + F`.
    pub fn euler_characteristic(&self) -> i64 {
        self.vertices as i64 - self.edges as i64 + self.faces as i64
    }

    /// Every edge has exactly two polygons, running it in opposite directions.
    pub fn is_closed_oriented_manifold(&self) -> bool {
        self.boundary_edges == 0 && self.non_manifold_edges == 0 && self.misoriented_edges == 0
    }
}

impl Tessellation {
    /// The edge counts of the polygons.
    pub fn edge_report(&self) -> EdgeReport {
        EdgeReport::new(&self.face_sizes, &self.face_vertices)
    }
}
