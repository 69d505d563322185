//! Catmull-Clark point masks: the weights that make a face point, an edge point and a vertex
//! point from the parent neighbourhood, for any polygon and every rule, with the fractional
//! blending of two rules while a semi-sharp feature decays (`Sdc::Scheme<CATMARK>`).
//!
//! Weights are `f64`; the sharpness values that enter them stay `f32` and are widened only
//! where OpenSubdiv widens them, so that the weights are bit-identical to OpenSubdiv's.

use super::crease::{
    fractional_weight_at_vertex, sharp_edge_pair_of_crease,
    subdivide_edge_sharpnesses_around_vertex, Rule,
};
use crate::options::{CreaseMethod, TriangleSubdivision};

/// Weight of the triangle faces in the smooth edge rule with the smooth-triangle option.
const SMOOTH_TRIANGLE_EDGE_WEIGHT: f64 = 0.470;

/// Weight of each vertex of an `n`-sided face in its face point: `1/n`.
pub fn face_point_weight(n: usize) -> f64 {
    1.0 / n as f64
}

/// Weights of an edge point: on the two end vertices (in edge order) and on the face points
/// of the incident faces (in edge-face order; empty for a crease).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct EdgeMask {
    /// Weights of the two end vertices.
    pub vertices: [f64; 2],
    /// Weights of the face points of the incident faces; empty for the crease rule.
    pub faces: Vec<f64>,
}

/// What the edge rule needs to know about an edge.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeNeighbourhood {
    /// Sharpness of the edge.
    pub sharpness: f32,
    /// Number of incident faces.
    pub num_faces: usize,
    /// For an edge with two faces: whether each is a triangle (used only by the
    /// smooth-triangle option).
    pub faces_are_triangles: [bool; 2],
}

impl EdgeMask {
    fn set_smooth(&mut self, edge: &EdgeNeighbourhood, triangles: TriangleSubdivision) {
        let n = edge.num_faces;
        self.faces.clear();
        let tri = edge.faces_are_triangles;
        let use_tri = triangles == TriangleSubdivision::Smooth && n == 2 && (tri[0] || tri[1]);
        if !use_tri {
            self.vertices = [0.25, 0.25];
            if n == 2 {
                self.faces.extend_from_slice(&[0.25, 0.25]);
            } else {
                let w = 0.5 / n as f64;
                self.faces.resize(n, w);
            }
        } else {
            let f0 = if tri[0] {
                SMOOTH_TRIANGLE_EDGE_WEIGHT
            } else {
                0.25
            };
            let f1 = if tri[1] {
                SMOOTH_TRIANGLE_EDGE_WEIGHT
            } else {
                0.25
            };
            let fw = 0.5 * (f0 + f1);
            let vw = 0.5 * (1.0 - 2.0 * fw);
            self.vertices = [vw, vw];
            self.faces.extend_from_slice(&[fw, fw]);
        }
    }

    fn set_crease(&mut self) {
        self.vertices = [0.5, 0.5];
        self.faces.clear();
    }

    /// Compute the edge-point mask (`Scheme::ComputeEdgeVertexMask`).
    ///
    /// The parent rule is the crease rule when the edge is sharp. `child_rule` is the rule of
    /// the new edge vertex when known (as in refinement); `None` lets the sharpness decide.
    /// A sharp parent with a smooth child blends the crease and smooth masks with the edge
    /// sharpness as weight.
    pub fn compute(
        &mut self,
        edge: &EdgeNeighbourhood,
        child_rule: Option<Rule>,
        method: CreaseMethod,
        triangles: TriangleSubdivision,
    ) {
        if edge.sharpness <= 0.0 {
            self.set_smooth(edge, triangles);
            return;
        }
        match child_rule {
            Some(Rule::Crease) => {
                self.set_crease();
                return;
            }
            None => {
                // Parent known to be a crease (sharpness > 0): the child is a crease unless
                // its sharpness decays; a sharpness of 1 or more gives full weight anyway.
                let child_is_crease = if edge.sharpness >= 1.0 {
                    true
                } else if method == CreaseMethod::Uniform {
                    false
                } else {
                    edge.sharpness - 1.0 > 0.0
                };
                if child_is_crease {
                    self.set_crease();
                    return;
                }
            }
            Some(_) => {}
        }
        self.set_smooth(edge, triangles);
        let p = edge.sharpness as f64;
        let c = 1.0 - p;
        self.vertices[0] = p * 0.5 + c * self.vertices[0];
        self.vertices[1] = p * 0.5 + c * self.vertices[1];
        for f in &mut self.faces {
            *f *= c;
        }
    }
}

/// Weights of a vertex point: on the vertex itself, on the vertices opposite each incident
/// edge (in vertex-edge order), and on the face points of the incident faces (in vertex-face
/// order). Empty edge or face weights mean "none".
#[derive(Debug, Clone, Default, PartialEq)]
pub struct VertexMask {
    /// Weight of the vertex itself.
    pub vertex: f64,
    /// Weights of the vertices across the incident edges; empty if none.
    pub edges: Vec<f64>,
    /// Weights of the face points of the incident faces; empty if none.
    pub faces: Vec<f64>,
}

/// What the vertex rule needs to know about a vertex and its child.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VertexNeighbourhood<'a> {
    /// Number of incident faces.
    pub num_faces: usize,
    /// Sharpness of the vertex.
    pub sharpness: f32,
    /// Sharpness of the vertex's child (after decay).
    pub child_sharpness: f32,
    /// Sharpness of each incident edge, in vertex-edge order.
    pub edge_sharpness: &'a [f32],
}

impl VertexMask {
    fn set_smooth(&mut self, num_faces: usize) {
        let n = num_faces;
        self.vertex = (n as f64 - 2.0) / n as f64;
        let w = 1.0 / (n * n) as f64;
        self.edges.clear();
        self.edges.resize(n, w);
        self.faces.clear();
        self.faces.resize(n, w);
    }

    fn set_crease(&mut self, valence: usize, ends: [usize; 2]) {
        self.vertex = 0.75;
        self.edges.clear();
        self.edges.resize(valence, 0.0);
        self.edges[ends[0]] = 0.125;
        self.edges[ends[1]] = 0.125;
        self.faces.clear();
    }

    fn set_corner(&mut self) {
        self.vertex = 1.0;
        self.edges.clear();
        self.faces.clear();
    }

    fn set_rule(&mut self, rule: Rule, num_faces: usize, edge_sharpness: &[f32]) {
        match rule {
            Rule::Smooth | Rule::Dart => self.set_smooth(num_faces),
            Rule::Crease => match sharp_edge_pair_of_crease(edge_sharpness) {
                Some(ends) => self.set_crease(edge_sharpness.len(), ends),
                // A crease rule with no sharp edge cannot come from the classification;
                // keep the vertex in place rather than index out of range.
                None => self.set_corner(),
            },
            Rule::Corner => self.set_corner(),
        }
    }

    /// Blend: `self = parent_weight * self + child_weight * child`, where a weight set that
    /// is empty in `self` takes the child's weights scaled (`LocalMask::CombineVertexVertexMasks`).
    fn combine(&mut self, child: &VertexMask, child_weight: f64, parent_weight: f64) {
        self.vertex = parent_weight * self.vertex + child_weight * child.vertex;
        if !child.edges.is_empty() {
            if self.edges.is_empty() {
                self.edges
                    .extend(child.edges.iter().map(|&w| child_weight * w));
            } else {
                for (d, &c) in self.edges.iter_mut().zip(&child.edges) {
                    *d = parent_weight * *d + child_weight * c;
                }
            }
        }
        if !child.faces.is_empty() {
            if self.faces.is_empty() {
                self.faces
                    .extend(child.faces.iter().map(|&w| child_weight * w));
            } else {
                for (d, &c) in self.faces.iter_mut().zip(&child.faces) {
                    *d = parent_weight * *d + child_weight * c;
                }
            }
        }
    }
}

/// Reusable buffers for [`VertexMaskBuilder::compute`], so that refining a whole level does
/// not allocate per vertex.
#[derive(Debug, Clone, Default)]
pub struct VertexMaskBuilder {
    child_edges: Vec<f32>,
    child_mask: VertexMask,
}

impl VertexMaskBuilder {
    /// Compute the vertex-point mask into `out` (`Scheme::ComputeVertexVertexMask`).
    ///
    /// `parent_rule` and `child_rule` are the rules of the vertex and of its child. When they
    /// differ, the masks of both rules are blended with the fractional weight of the features
    /// that decay.
    pub fn compute(
        &mut self,
        vertex: &VertexNeighbourhood<'_>,
        parent_rule: Rule,
        child_rule: Rule,
        method: CreaseMethod,
        out: &mut VertexMask,
    ) {
        out.set_rule(parent_rule, vertex.num_faces, vertex.edge_sharpness);
        if matches!(parent_rule, Rule::Smooth | Rule::Dart) || child_rule == parent_rule {
            return;
        }
        let parent_edges = vertex.edge_sharpness;
        self.child_edges.clear();
        self.child_edges.resize(parent_edges.len(), 0.0);
        subdivide_edge_sharpnesses_around_vertex(method, parent_edges, &mut self.child_edges);
        self.child_mask
            .set_rule(child_rule, vertex.num_faces, &self.child_edges);
        let p = fractional_weight_at_vertex(
            method,
            vertex.sharpness,
            vertex.child_sharpness,
            parent_edges,
            &self.child_edges,
        ) as f64;
        let c = 1.0 - p;
        out.combine(&self.child_mask, c, p);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use CreaseMethod::Uniform;
    use TriangleSubdivision::{Catmark, Smooth};

    fn edge(sharpness: f32, num_faces: usize) -> EdgeNeighbourhood {
        EdgeNeighbourhood {
            sharpness,
            num_faces,
            faces_are_triangles: [false, false],
        }
    }

    #[test]
    fn face_weights() {
        assert_eq!(face_point_weight(4), 0.25);
        assert_eq!(face_point_weight(3), 1.0 / 3.0);
    }

    #[test]
    fn edge_masks() {
        let mut m = EdgeMask::default();
        m.compute(&edge(0.0, 2), Some(Rule::Smooth), Uniform, Catmark);
        assert_eq!(m.vertices, [0.25, 0.25]);
        assert_eq!(m.faces, vec![0.25, 0.25]);
        m.compute(&edge(0.0, 3), Some(Rule::Smooth), Uniform, Catmark);
        assert_eq!(m.faces, vec![0.5 / 3.0; 3]);
        m.compute(&edge(2.0, 2), Some(Rule::Crease), Uniform, Catmark);
        assert_eq!(m.vertices, [0.5, 0.5]);
        assert!(m.faces.is_empty());
        // Sharpness 0.25 decaying to smooth: 0.25 * crease + 0.75 * smooth.
        m.compute(&edge(0.25, 2), Some(Rule::Smooth), Uniform, Catmark);
        assert_eq!(m.vertices, [0.125 + 0.75 * 0.25; 2]);
        assert_eq!(m.faces, vec![0.1875, 0.1875]);
        m.compute(&edge(0.25, 2), None, Uniform, Catmark);
        assert_eq!(m.vertices, [0.3125; 2]);
        m.compute(&edge(1.5, 2), None, Uniform, Catmark);
        assert_eq!(m.vertices, [0.5; 2]);
        // Smooth triangles: one triangle.
        let mut e = edge(0.0, 2);
        e.faces_are_triangles = [true, false];
        m.compute(&e, Some(Rule::Smooth), Uniform, Smooth);
        let fw = 0.5 * (0.47 + 0.25);
        assert_eq!(m.faces, vec![fw, fw]);
        assert_eq!(m.vertices, [0.5 * (1.0 - 2.0 * fw); 2]);
    }

    #[test]
    fn vertex_masks() {
        let mut b = VertexMaskBuilder::default();
        let mut m = VertexMask::default();
        let sharp = [0.0f32; 5];
        let v = VertexNeighbourhood {
            num_faces: 5,
            sharpness: 0.0,
            child_sharpness: 0.0,
            edge_sharpness: &sharp,
        };
        b.compute(&v, Rule::Smooth, Rule::Smooth, Uniform, &mut m);
        assert_eq!(m.vertex, 0.6);
        assert_eq!(m.edges, vec![1.0 / 25.0; 5]);
        assert_eq!(m.faces, vec![1.0 / 25.0; 5]);

        let sharp = [10.0f32, 0.0, 10.0];
        let v = VertexNeighbourhood {
            num_faces: 2,
            sharpness: 0.0,
            child_sharpness: 0.0,
            edge_sharpness: &sharp,
        };
        b.compute(&v, Rule::Crease, Rule::Crease, Uniform, &mut m);
        assert_eq!(m.vertex, 0.75);
        assert_eq!(m.edges, vec![0.125, 0.0, 0.125]);
        assert!(m.faces.is_empty());

        // A corner of sharpness 0.5 on a regular interior vertex decays to smooth:
        // 0.5 * corner + 0.5 * smooth.
        let sharp = [0.0f32; 4];
        let v = VertexNeighbourhood {
            num_faces: 4,
            sharpness: 0.5,
            child_sharpness: 0.0,
            edge_sharpness: &sharp,
        };
        b.compute(&v, Rule::Corner, Rule::Smooth, Uniform, &mut m);
        assert_eq!(m.vertex, 0.5 + 0.5 * 0.5);
        assert_eq!(m.edges, vec![0.5 / 16.0; 4]);
        assert_eq!(m.faces, vec![0.5 / 16.0; 4]);
    }
}
