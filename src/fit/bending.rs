//! The bending energy of a control net: the fairness term of the fit.
//!
//! `E(x) = Σ_v |(L x)_v|²` over every vertex `v`, with `L` the umbrella operator
//! `(L x)_v = mean of x over v's edge neighbours − x_v` (a discrete Laplacian, so `E` is a
//! discrete thin-plate energy of the control net: zero for a net whose every vertex is the
//! centroid of its neighbours, a plane's regular grid say, and large where the net bends
//! sharply). Where the data leave a control point free, the fit puts it where `E` is
//! stationary with respect to it (Halstead, Kass & DeRose 1993 add the same kind of term to
//! an interpolating Catmull-Clark fit): the row `∂E/∂x_i / 2 = Σ_v L_{v,i} (L x)_v = 0` of
//! [`Umbrella::energy_row`]. It is linear in the control points, sums to 0 (a translation
//! of the net keeps it) and uses only the mesh's edges, not its positions, so it commutes
//! with translation, rotation and scaling.

use std::collections::BTreeMap;

use crate::mesh::Mesh;

/// The umbrella operator of a mesh: each vertex's edge neighbours.
#[derive(Debug, Clone)]
pub struct Umbrella {
    neighbours: Vec<Vec<u32>>,
}

impl Umbrella {
    /// The edge neighbours of every vertex of `mesh` (sorted, each once).
    pub fn new(mesh: &Mesh) -> Umbrella {
        let mut neighbours = vec![Vec::new(); mesh.num_vertices()];
        let mut start = 0;
        for &size in mesh.face_sizes() {
            let face = &mesh.face_indices()[start..start + size as usize];
            for (k, &a) in face.iter().enumerate() {
                let b = face[(k + 1) % face.len()];
                neighbours[a as usize].push(b);
                neighbours[b as usize].push(a);
            }
            start += size as usize;
        }
        for n in &mut neighbours {
            n.sort_unstable();
            n.dedup();
        }
        Umbrella { neighbours }
    }

    /// Row `v` of `L`: `(column, weight)` pairs by column.
    pub fn laplacian_row(&self, v: usize) -> Vec<(u32, f64)> {
        let n = &self.neighbours[v];
        let w = 1.0 / n.len().max(1) as f64;
        let mut row: BTreeMap<u32, f64> = n.iter().map(|&u| (u, w)).collect();
        *row.entry(v as u32).or_insert(0.0) -= 1.0;
        row.into_iter().collect()
    }

    /// Row `i` of `Lᵀ L`, half the gradient of the energy with respect to control point `i`:
    /// `(column, weight)` pairs by column (a fixed order, so sums are deterministic).
    pub fn energy_row(&self, i: usize) -> Vec<(u32, f64)> {
        let mut row = BTreeMap::new();
        // L_{v,i} is non-zero for v = i (−1) and for each neighbour v of i (1 / |N(v)|).
        let terms = std::iter::once((i, -1.0)).chain(
            self.neighbours[i]
                .iter()
                .map(|&v| (v as usize, 1.0 / self.neighbours[v as usize].len() as f64)),
        );
        for (v, l_vi) in terms {
            for (u, l_vu) in self.laplacian_row(v) {
                *row.entry(u).or_insert(0.0) += l_vi * l_vu;
            }
        }
        row.into_iter().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::MeshParts;
    use glam::DVec3;

    /// A `n × n` grid of quads in the plane z = 0, vertex `(i, j)` at index `i (n + 1) + j`.
    fn grid(n: usize) -> Mesh {
        let mut parts = MeshParts::default();
        for i in 0..=n {
            for j in 0..=n {
                parts.positions.push(DVec3::new(j as f64, i as f64, 0.0));
            }
        }
        let id = |i: usize, j: usize| (i * (n + 1) + j) as u32;
        for i in 0..n {
            for j in 0..n {
                parts.face_sizes.push(4);
                parts
                    .face_indices
                    .extend([id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)]);
            }
        }
        Mesh::from_parts(parts).unwrap()
    }

    fn apply(row: &[(u32, f64)], x: &[f64]) -> f64 {
        row.iter().map(|&(j, w)| w * x[j as usize]).sum()
    }

    #[test]
    fn rows_vanish_on_linear_nets_and_match_the_energy_gradient() {
        let mesh = grid(4);
        let u = Umbrella::new(&mesh);
        let centre = 2 * 5 + 2;
        // An interior vertex of a regular grid: the 13-point biharmonic stencil's shape
        // (centre 1 + 4/16, edge neighbours −2/4, diagonal 2/16, two apart 1/16).
        let row: BTreeMap<u32, f64> = u.energy_row(centre).into_iter().collect();
        assert_eq!(row.len(), 13);
        assert!((row[&(centre as u32)] - 1.25).abs() < 1e-15);
        assert!((row[&(centre as u32 + 1)] + 0.5).abs() < 1e-15);
        assert!((row[&(centre as u32 + 6)] - 0.125).abs() < 1e-15);
        assert!((row[&(centre as u32 + 2)] - 0.0625).abs() < 1e-15);
        // Every row sums to 0 and vanishes on an affine function of the interior's positions.
        for i in [centre, 0, 3, 7] {
            let r = u.energy_row(i);
            assert!(r.iter().map(|p| p.1).sum::<f64>().abs() < 1e-15);
        }
        let affine: Vec<f64> = mesh
            .positions()
            .iter()
            .map(|p| 2.0 * p.x - 3.0 * p.y + 1.0)
            .collect();
        assert!(apply(&u.energy_row(centre), &affine).abs() < 1e-13);
        // Against the energy's finite-difference gradient on a curved net.
        let x: Vec<f64> = mesh
            .positions()
            .iter()
            .map(|p| crate::math::sin(p.x * 0.7) * p.y + 0.1 * p.x * p.x)
            .collect();
        let energy = |x: &[f64]| -> f64 {
            (0..x.len())
                .map(|v| apply(&u.laplacian_row(v), x).powi(2))
                .sum()
        };
        for i in [centre, 1, 12, 24] {
            let h = 1e-5;
            let (mut up, mut down) = (x.clone(), x.clone());
            up[i] += h;
            down[i] -= h;
            let fd = (energy(&up) - energy(&down)) / (2.0 * h) / 2.0;
            assert!((fd - apply(&u.energy_row(i), &x)).abs() < 1e-8, "{i}");
        }
    }
}
