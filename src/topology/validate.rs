//! Internal consistency of a [`Level`] (`Vtr::Level::validateTopology`): what refinement and
//! interpolation rely on, checkable on any level.

use super::Level;

impl Level {
    /// Check the level's relations against each other: every face edge joins the face's
    /// consecutive vertices, every local index points back at its component, and around every
    /// manifold interior vertex face `i` leads with edge `i` and trails with edge `i + 1`
    /// (counter-clockwise order). Returns the first violation found.
    pub fn validate(&self) -> Result<(), String> {
        for f in 0..self.num_faces() {
            let (fv, fe) = (self.face_vertices(f), self.face_edges(f));
            for i in 0..fv.len() {
                let [a, b] = self.edge_vertices(fe[i] as usize);
                let (p, q) = (fv[i], fv[(i + 1) % fv.len()]);
                if (a, b) != (p, q) && (a, b) != (q, p) {
                    return Err(format!("face {f}: edge {i} does not join vertices {p} {q}"));
                }
            }
        }
        for e in 0..self.num_edges() {
            for (&f, &k) in self
                .edge_faces(e)
                .iter()
                .zip(self.edge_face_local_indices(e))
            {
                if self.face_edges(f as usize).get(k as usize) != Some(&(e as u32)) {
                    return Err(format!("edge {e}: local index {k} in face {f} is wrong"));
                }
            }
        }
        for v in 0..self.num_vertices() {
            let (faces, edges) = (self.vertex_faces(v), self.vertex_edges(v));
            let face_locals = self.vertex_face_local_indices(v);
            for (&f, &k) in faces.iter().zip(face_locals) {
                if self.face_vertices(f as usize).get(k as usize) != Some(&(v as u32)) {
                    return Err(format!("vertex {v}: local index {k} in face {f} is wrong"));
                }
            }
            for (&e, &k) in edges.iter().zip(self.vertex_edge_local_indices(v)) {
                if self.edge_vertices(e as usize).get(k as usize) != Some(&(v as u32)) {
                    return Err(format!("vertex {v}: local index {k} in edge {e} is wrong"));
                }
            }
            if self.is_vertex_non_manifold(v) || self.is_vertex_boundary(v) {
                continue;
            }
            let n = faces.len();
            if edges.len() != n {
                return Err(format!(
                    "interior vertex {v}: {n} faces but {} edges",
                    edges.len()
                ));
            }
            for i in 0..n {
                let fe = self.face_edges(faces[i] as usize);
                let k = face_locals[i] as usize;
                if fe[k] != edges[i] || fe[(k + fe.len() - 1) % fe.len()] != edges[(i + 1) % n] {
                    return Err(format!(
                        "vertex {v}: face {i} is not between edges {i} and {}",
                        (i + 1) % n
                    ));
                }
            }
        }
        Ok(())
    }
}
