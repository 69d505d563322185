//! The neighbourhood of one vertex, refined exactly with stencil-valued points.
//!
//! A [`Ring`] holds a vertex, the far ends of its incident edges and the other points of its
//! incident faces, each point as a dense weight vector over a small local basis (the level-0
//! control vertices around the vertex). Refining it applies OpenSubdiv's Catmark rules
//! (`Sdc::Scheme<SCHEME_CATMARK>` masks with `Sdc::Crease` sharpness) to give the child
//! vertex's ring: the one-ring of a vertex is closed under refinement, so its limit follows
//! from the ring alone once the sharpness around it is 0 or infinite.

use crate::math;
use std::f64::consts::PI;

use crate::catmark::crease::{
    self, is_semi_sharp, is_sharp, vertex_rule, vertex_rule_from_edges, Rule,
};
use crate::catmark::masks::{
    EdgeMask, EdgeNeighbourhood, VertexMask, VertexMaskBuilder, VertexNeighbourhood,
};
use crate::error::{Error, Result};
use crate::options::{CreaseMethod, SubdivOptions};

use super::dense::stationary_left_eigenvector;

/// A point of the neighbourhood: weights on the local basis.
pub(crate) type Point = Vec<f64>;

/// `acc += w * x`.
pub(crate) fn axpy(acc: &mut [f64], w: f64, x: &[f64]) {
    for (a, b) in acc.iter_mut().zip(x) {
        *a += w * b;
    }
}

/// `x - y`.
pub(crate) fn sub(x: &[f64], y: &[f64]) -> Point {
    x.iter().zip(y).map(|(a, b)| a - b).collect()
}

fn scaled(w: f64, x: &[f64]) -> Point {
    x.iter().map(|a| w * a).collect()
}

/// The one-ring of a manifold vertex (interior: as many faces as edges; boundary: one face
/// fewer, edges 0 and n-1 on the boundary). Face `i` lies between edge `i` (leading) and
/// edge `i + 1` (trailing), as OpenSubdiv orders them counter-clockwise.
#[derive(Debug, Clone)]
pub(crate) struct Ring {
    /// The vertex.
    pub center: Point,
    /// Far end of each incident edge.
    pub ends: Vec<Point>,
    /// Sharpness of each incident edge.
    pub sharpness: Vec<f32>,
    /// Sharpness of the edges around each far end (what Chaikin creasing averages there).
    pub far_sharpness: Vec<Vec<f32>>,
    /// Points of each incident face after the vertex, in face order
    /// (first = end of the leading edge, last = end of the trailing edge).
    pub faces: Vec<Vec<Point>>,
    /// Vertex sharpness.
    pub vertex_sharpness: f32,
    /// Number of refinements applied since level 0.
    pub level: u32,
}

impl Ring {
    fn valence(&self) -> usize {
        self.ends.len()
    }

    fn is_interior(&self) -> bool {
        self.faces.len() == self.ends.len()
    }

    /// Faces on either side of edge `i`.
    fn edge_faces(&self, i: usize) -> impl Iterator<Item = usize> {
        let (n, nf) = (self.valence(), self.faces.len());
        let before = if self.is_interior() {
            Some((i + n - 1) % n)
        } else {
            i.checked_sub(1)
        };
        before.into_iter().chain((i < nf).then_some(i))
    }

    /// Sharpness is 0 or infinite everywhere around the vertex and every face is a quad:
    /// from here on the ring's subdivision matrix no longer changes.
    pub fn is_stationary(&self) -> bool {
        !is_semi_sharp(self.vertex_sharpness)
            && !self.sharpness.iter().any(|&s| is_semi_sharp(s))
            && self.faces.iter().all(|f| f.len() == 3)
    }

    /// The ring of the child vertex after one level of Catmark refinement.
    pub fn refine(&self, options: &SubdivOptions) -> Ring {
        let method = options.crease_method;
        let n = self.valence();
        let face_points: Vec<Point> = self
            .faces
            .iter()
            .map(|f| {
                let w = 1.0 / (f.len() + 1) as f64;
                let mut p = scaled(w, &self.center);
                for q in f {
                    axpy(&mut p, w, q);
                }
                p
            })
            .collect();
        let mut child_sharpness = vec![0.0; n];
        crease::subdivide_edge_sharpnesses_around_vertex(
            method,
            &self.sharpness,
            &mut child_sharpness,
        );
        let far_child: Vec<f32> = (0..n)
            .map(|i| {
                crease::subdivide_edge_sharpness_at_vertex(
                    method,
                    self.sharpness[i],
                    &self.far_sharpness[i],
                )
            })
            .collect();
        let mut mask = EdgeMask::default();
        let ends: Vec<Point> = (0..n)
            .map(|i| {
                // Far's rule for the new edge vertex: from its two half edges.
                let halves = [child_sharpness[i], far_child[i]];
                let child_rule = vertex_rule(0.0, halves.iter().filter(|&&s| is_sharp(s)).count());
                let faces: Vec<usize> = self.edge_faces(i).collect();
                let tri = |k: usize| faces.get(k).is_some_and(|&f| self.faces[f].len() == 2);
                let edge = EdgeNeighbourhood {
                    sharpness: self.sharpness[i],
                    num_faces: faces.len(),
                    faces_are_triangles: [tri(0), tri(1)],
                };
                mask.compute(&edge, Some(child_rule), method, options.triangles);
                let mut p = scaled(mask.vertices[0], &self.center);
                axpy(&mut p, mask.vertices[1], &self.ends[i]);
                for (&w, &f) in mask.faces.iter().zip(&faces) {
                    axpy(&mut p, w, &face_points[f]);
                }
                p
            })
            .collect();
        let child_vertex = crease::subdivide_vertex_sharpness(self.vertex_sharpness);
        let neighbourhood = VertexNeighbourhood {
            num_faces: self.faces.len(),
            sharpness: self.vertex_sharpness,
            child_sharpness: child_vertex,
            edge_sharpness: &self.sharpness,
        };
        let mut vmask = VertexMask::default();
        VertexMaskBuilder::default().compute(
            &neighbourhood,
            vertex_rule_from_edges(self.vertex_sharpness, &self.sharpness),
            vertex_rule_from_edges(child_vertex, &child_sharpness),
            method,
            &mut vmask,
        );
        let mut center = scaled(vmask.vertex, &self.center);
        for (&w, e) in vmask.edges.iter().zip(&self.ends) {
            axpy(&mut center, w, e);
        }
        for (&w, f) in vmask.faces.iter().zip(&face_points) {
            axpy(&mut center, w, f);
        }
        let faces = (0..self.faces.len())
            .map(|i| {
                vec![
                    ends[i].clone(),
                    face_points[i].clone(),
                    ends[(i + 1) % n].clone(),
                ]
            })
            .collect();
        Ring {
            center,
            ends,
            far_sharpness: (0..n)
                .map(|i| vec![child_sharpness[i], far_child[i]])
                .collect(),
            sharpness: child_sharpness,
            faces,
            vertex_sharpness: child_vertex,
            level: self.level + 1,
        }
    }

    /// Exact limit position of the vertex of a stationary ring.
    pub fn limit(&self) -> Result<Point> {
        let n = self.valence();
        Ok(
            match vertex_rule_from_edges(self.vertex_sharpness, &self.sharpness) {
                Rule::Corner => self.center.clone(),
                Rule::Crease => {
                    let (a, b) = crease_pair(&self.sharpness);
                    let mut p = scaled(4.0 / 6.0, &self.center);
                    axpy(&mut p, 1.0 / 6.0, &self.ends[a]);
                    axpy(&mut p, 1.0 / 6.0, &self.ends[b]);
                    p
                }
                Rule::Smooth => {
                    // Left eigenvector of the all-quad smooth subdivision matrix.
                    let nn = n as f64;
                    let d = nn * (nn + 5.0);
                    let mut p = scaled(nn * nn / d, &self.center);
                    for (e, f) in self.ends.iter().zip(&self.faces) {
                        axpy(&mut p, 4.0 / d, e);
                        axpy(&mut p, 1.0 / d, &f[1]);
                    }
                    p
                }
                Rule::Dart => self.eigen_limit()?,
            },
        )
    }

    /// The limit as the left eigenvector of eigenvalue 1 of the ring's own subdivision
    /// matrix (valid for any stationary ring; the only way for darts).
    pub fn eigen_limit(&self) -> Result<Point> {
        let (n, nf) = (self.valence(), self.faces.len());
        let m = 1 + n + nf;
        let unit = |k: usize| {
            let mut p = vec![0.0; m];
            p[k] = 1.0;
            p
        };
        let basis = Ring {
            center: unit(0),
            ends: (0..n).map(|i| unit(1 + i)).collect(),
            sharpness: self.sharpness.clone(),
            far_sharpness: self.sharpness.iter().map(|&s| vec![s, s]).collect(),
            faces: (0..nf)
                .map(|i| vec![unit(1 + i), unit(1 + n + i), unit(1 + (i + 1) % n)])
                .collect(),
            vertex_sharpness: self.vertex_sharpness,
            level: 0,
        };
        let child = basis.refine(&SubdivOptions {
            crease_method: CreaseMethod::Uniform,
            ..SubdivOptions::default()
        });
        let mut s = Vec::with_capacity(m * m);
        s.extend_from_slice(&child.center);
        for e in &child.ends {
            s.extend_from_slice(e);
        }
        for f in &child.faces {
            s.extend_from_slice(&f[1]);
        }
        let l = stationary_left_eigenvector(&s, m)?;
        let mut p = scaled(l[0], &self.center);
        for i in 0..n {
            axpy(&mut p, l[1 + i], &self.ends[i]);
        }
        for i in 0..nf {
            axpy(&mut p, l[1 + n + i], &self.faces[i][1]);
        }
        Ok(p)
    }

    /// Limit derivatives of a stationary ring along the leading and trailing edges of face
    /// `j`, per unit of the ring's own edge parameter (see the module doc of
    /// [`super::vertex_limit`] for where they are exact).
    pub fn tangents(&self, j: usize) -> (Point, Point) {
        let n = self.valence();
        let (lead, trail) = (j, (j + 1) % n);
        match vertex_rule_from_edges(self.vertex_sharpness, &self.sharpness) {
            Rule::Smooth | Rule::Dart if n >= 3 => {
                (self.smooth_tangent(lead), self.smooth_tangent(trail))
            }
            Rule::Crease => self.crease_tangents(j),
            _ => (
                sub(&self.ends[lead], &self.center),
                sub(&self.ends[trail], &self.center),
            ),
        }
    }

    /// OpenSubdiv's smooth limit tangent mask rotated to edge `i`, scaled by 1/12 so that
    /// it is the derivative of the bicubic patch at a regular vertex.
    fn smooth_tangent(&self, i: usize) -> Point {
        let n = self.valence();
        let mut t = vec![0.0; self.center.len()];
        if n == 4 {
            let ew = [4.0, 0.0, -4.0, 0.0];
            let fw = [1.0, -1.0, -1.0, 1.0];
            for k in 0..4 {
                axpy(&mut t, ew[k] / 12.0, &self.ends[(i + k) % 4]);
                axpy(&mut t, fw[k] / 12.0, &self.faces[(i + k) % 4][1]);
            }
            return t;
        }
        let theta = 2.0 * PI / n as f64;
        let lambda = 5.0 / 16.0
            + (math::cos(theta) + math::cos(0.5 * theta) * (2.0 * (9.0 + math::cos(theta))).sqrt())
                / 16.0;
        let fscale = 1.0 / (4.0 * lambda - 1.0);
        for k in 0..n {
            let (c0, c1) = (
                math::cos(k as f64 * theta),
                math::cos((k + 1) as f64 * theta),
            );
            axpy(&mut t, 4.0 * c0 / 12.0, &self.ends[(i + k) % n]);
            axpy(
                &mut t,
                fscale * (c0 + c1) / 12.0,
                &self.faces[(i + k) % n][1],
            );
        }
        t
    }

    /// Tangents in the crease sector that holds face `j`: along the crease
    /// (`(E_lead - E_trail)/2`), across it (OpenSubdiv's crease tangent mask: the uniform
    /// B-spline cross derivative when the sector has two faces), and in between as the
    /// sector's characteristic map spreads the edges (angle `π p / k`).
    fn crease_tangents(&self, j: usize) -> (Point, Point) {
        let n = self.valence();
        let sharp = |i: usize| is_sharp(self.sharpness[i % n]);
        let mut a = j;
        while !sharp(a) {
            a = (a + n - 1) % n;
        }
        let mut k = 1;
        while !sharp(a + k) {
            k += 1;
        }
        let b = (a + k) % n;
        let opp = |i: usize| &self.faces[(a + i) % n][1];
        let along = {
            let mut t = scaled(0.5, &self.ends[a]);
            axpy(&mut t, -0.5, &self.ends[b]);
            t
        };
        let mut across = vec![0.0; self.center.len()];
        match k {
            1 => {
                axpy(&mut across, -6.0, &self.center);
                axpy(&mut across, 3.0, &self.ends[a]);
                axpy(&mut across, 3.0, &self.ends[b]);
            }
            2 => {
                axpy(&mut across, -4.0 / 6.0, &self.center);
                axpy(&mut across, -1.0 / 6.0, &self.ends[a]);
                axpy(&mut across, 4.0 / 6.0, &self.ends[(a + 1) % n]);
                axpy(&mut across, -1.0 / 6.0, &self.ends[b]);
                axpy(&mut across, 1.0 / 6.0, opp(0));
                axpy(&mut across, 1.0 / 6.0, opp(1));
            }
            _ => {
                let kf = k as f64;
                let theta = PI / kf;
                let (c, s) = (math::cos(theta), math::sin(theta));
                let denom = 1.0 / (kf * (3.0 + c));
                let r = (c + 1.0) / s;
                axpy(&mut across, 4.0 * r * (c - 1.0) * denom, &self.center);
                axpy(&mut across, -r * (1.0 + 2.0 * c) * denom, &self.ends[a]);
                axpy(&mut across, -r * (1.0 + 2.0 * c) * denom, &self.ends[b]);
                axpy(&mut across, s * denom, opp(0));
                for i in 1..k {
                    let (si, si1) = (
                        math::sin(i as f64 * theta),
                        math::sin((i + 1) as f64 * theta),
                    );
                    axpy(&mut across, 4.0 * si * denom, &self.ends[(a + i) % n]);
                    axpy(&mut across, (si + si1) * denom, opp(i));
                }
            }
        }
        let at = |p: usize| -> Point {
            if p == 0 {
                along.clone()
            } else if p == k {
                scaled(-1.0, &along)
            } else if 2 * p == k {
                across.clone()
            } else {
                let phi = PI * p as f64 / k as f64;
                let mut t = scaled(math::cos(phi), &along);
                axpy(&mut t, math::sin(phi), &across);
                t
            }
        };
        let p = (j + n - a) % n;
        (at(p), at(p + 1))
    }
}

/// First and last sharp edge (`Crease::GetSharpEdgePairOfCrease`); only called for the
/// crease rule, which has two.
fn crease_pair(sharpness: &[f32]) -> (usize, usize) {
    let [a, b] = crease::sharp_edge_pair_of_crease(sharpness).unwrap_or([0, 0]);
    (a, b)
}

/// The vertex of a non-manifold crease: only the vertex and the far ends of its two
/// infinitely sharp edges take part in its (crease or corner) rule.
#[derive(Debug, Clone)]
pub(crate) struct CreaseLine {
    /// The vertex.
    pub center: Point,
    /// Far ends of the two infinitely sharp edges.
    pub ends: [Point; 2],
    /// Sharpness of every incident edge, in OpenSubdiv's order.
    pub sharpness: Vec<f32>,
    /// Vertex sharpness.
    pub vertex_sharpness: f32,
}

impl CreaseLine {
    /// Refine until the sharpness has decayed, then apply the crease limit mask.
    pub fn limit(mut self, method: CreaseMethod) -> Result<Point> {
        for _ in 0..MAX_LEVELS {
            let rule = vertex_rule_from_edges(self.vertex_sharpness, &self.sharpness);
            let stationary = !is_semi_sharp(self.vertex_sharpness)
                && !self.sharpness.iter().any(|&s| is_semi_sharp(s));
            if stationary {
                if rule == Rule::Crease {
                    let mut p = scaled(4.0 / 6.0, &self.center);
                    axpy(&mut p, 1.0 / 6.0, &self.ends[0]);
                    axpy(&mut p, 1.0 / 6.0, &self.ends[1]);
                    return Ok(p);
                }
                return Ok(self.center);
            }
            let mut child = vec![0.0; self.sharpness.len()];
            crease::subdivide_edge_sharpnesses_around_vertex(method, &self.sharpness, &mut child);
            let child_vertex = crease::subdivide_vertex_sharpness(self.vertex_sharpness);
            let child_rule = vertex_rule_from_edges(child_vertex, &child);
            let mask = |r: Rule| -> Point {
                if r == Rule::Crease {
                    let mut p = scaled(0.75, &self.center);
                    axpy(&mut p, 0.125, &self.ends[0]);
                    axpy(&mut p, 0.125, &self.ends[1]);
                    p
                } else {
                    self.center.clone()
                }
            };
            let mut center = mask(rule);
            if child_rule != rule {
                let pw = crease::fractional_weight_at_vertex(
                    method,
                    self.vertex_sharpness,
                    child_vertex,
                    &self.sharpness,
                    &child,
                ) as f64;
                center = scaled(pw, &center);
                axpy(&mut center, 1.0 - pw, &mask(child_rule));
            }
            let half = |e: &Point| {
                let mut p = scaled(0.5, &self.center);
                axpy(&mut p, 0.5, e);
                p
            };
            self.ends = [half(&self.ends[0]), half(&self.ends[1])];
            self.center = center;
            self.sharpness = child;
            self.vertex_sharpness = child_vertex;
        }
        Err(too_deep())
    }
}

/// More levels than any sharpness below the infinite value can need.
pub(crate) const MAX_LEVELS: u32 = 16;

/// The error for a neighbourhood whose sharpness does not decay (cannot happen with
/// OpenSubdiv's rules; kept as an error rather than a panic).
pub(crate) fn too_deep() -> Error {
    Error::NumericalFailure(format!(
        "vertex sharpness did not decay within {MAX_LEVELS} levels"
    ))
}
