//! From a grid of data points to quad mesh parts: quads between rings, caps, crease tags.
//!
//! Built with the shared [`QuadMeshBuilder`] and [`crate::construct::pole_cap`], so sweeps
//! and revolutions get the same pole caps and crease tagging as the profile construction.
//! Each vertex's data point is its initial position (the fitter's input).

use std::f64::consts::TAU;

use glam::DVec3;

use crate::construct::design::DesignCoord;
use crate::construct::grid::QuadMeshBuilder;
use crate::construct::pole_cap::CapVertex;
use crate::error::{Error, Result};
use crate::mesh::{MeshParts, SHARPNESS_INFINITE};
use crate::options::PartialOptions;

/// How the first or last ring of a grid is finished.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GridEnd {
    /// Left open: boundary edges.
    Open,
    /// Closed at one tip vertex at this point, tagged as an infinitely sharp corner.
    Tip(DVec3),
    /// Closed by a grid cap through a smooth pole.
    Smooth,
    /// Closed by a flat grid cap, creased where it meets the side.
    Flat,
}

/// The data points of a sweep on a grid, with what the mesh needs to know about it.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepGrid {
    /// One ring per trajectory sample, each with one data point per profile sample.
    pub rings: Vec<Vec<DVec3>>,
    /// Whether each ring is closed (closed profile).
    pub ring_closed: bool,
    /// Whether the last ring joins the first (closed trajectory).
    pub rings_closed: bool,
    /// Rings at trajectory corners: crease rings across the sweep.
    pub crease_rings: Vec<usize>,
    /// Profile samples at profile corners: crease columns along the sweep.
    pub crease_columns: Vec<usize>,
    /// Whether faces must be reversed to face outward (a clockwise closed profile).
    pub flip: bool,
    /// How the first and the last ring are finished.
    pub ends: [GridEnd; 2],
    /// Sharpness of the crease rings and columns.
    pub crease_sharpness: f32,
}

/// Quad mesh parts of `grid`; crease edges get `grid.crease_sharpness`, tips are infinitely
/// sharp corners, flat caps are creased infinitely sharp. `cap_point(end, v)` gives the data
/// point of grid-cap vertex `v` at a smooth pole or flat end (`end` 0: first ring, 1: last).
/// Vertex ids: ring `i`'s vertex `j` is `i × ring length + j`, cap vertices follow.
///
/// Orientation: quads `(ring i, j) → (ring i, j+1) → (ring i+1, j+1) → (ring i+1, j)`, reversed
/// when `grid.flip`; caps follow (the first ring's cap faces backwards).
pub fn grid_mesh(
    grid: &SweepGrid,
    cap_point: &dyn Fn(usize, CapVertex) -> DVec3,
) -> Result<MeshParts> {
    Ok(grid_mesh_coords(grid, cap_point)?.0)
}

/// [`grid_mesh`] and the design coordinates of its vertices: ring `i`'s vertex `j` at
/// `Side { s: i, theta: j }` (indices), a cap's vertices at their relative radius and angle
/// (a tip at radius 0).
pub fn grid_mesh_coords(
    grid: &SweepGrid,
    cap_point: &dyn Fn(usize, CapVertex) -> DVec3,
) -> Result<(MeshParts, Vec<DesignCoord>)> {
    let rows = grid.rings.len();
    if rows == 0 || grid.rings.iter().any(|r| r.len() != grid.rings[0].len()) {
        return Err(Error::invalid_argument(
            "a sweep grid needs rings of one length",
        ));
    }
    let mut b = QuadMeshBuilder::new();
    let ids: Vec<Vec<u32>> = grid
        .rings
        .iter()
        .map(|r| b.add_ring(r.iter().copied()))
        .collect();
    let mut coords: Vec<DesignCoord> = (0..rows)
        .flat_map(|i| {
            (0..grid.rings[i].len()).map(move |j| DesignCoord::Side {
                s: i as f64,
                theta: j as f64,
            })
        })
        .collect();
    let ring_spans = if grid.ring_closed {
        ids[0].len()
    } else {
        ids[0].len() - 1
    };
    let row_spans = if grid.rings_closed { rows } else { rows - 1 };
    for i in 0..row_spans {
        let (a, c) = (&ids[i], &ids[(i + 1) % rows]);
        if grid.flip {
            b.connect_rings(c, a, grid.ring_closed);
        } else {
            b.connect_rings(a, c, grid.ring_closed);
        }
    }
    for (end, kind) in grid.ends.iter().enumerate() {
        let ring = if end == 0 { &ids[0] } else { &ids[rows - 1] };
        let flip = (end == 0) != grid.flip;
        let mut place = |v: CapVertex| {
            coords.push(DesignCoord::Cap {
                end,
                rho: v.radius,
                theta: TAU * v.turn,
            });
            cap_point(end, v)
        };
        match *kind {
            GridEnd::Open => {}
            GridEnd::Tip(p) => {
                coords.push(DesignCoord::Cap {
                    end,
                    rho: 0.0,
                    theta: 0.0,
                });
                b.tip(ring, p, SHARPNESS_INFINITE, flip)?;
            }
            GridEnd::Smooth => b.grid_cap(ring, flip, place)?,
            GridEnd::Flat => {
                b.flat_cap(ring, flip, &mut place)?;
                b.crease_ring(ring, 0..ring_spans, SHARPNESS_INFINITE);
            }
        }
    }
    for &i in &grid.crease_rings {
        b.crease_ring(&ids[i], 0..ring_spans, grid.crease_sharpness);
    }
    for &j in &grid.crease_columns {
        let column: Vec<u32> = ids.iter().map(|r| r[j]).collect();
        b.crease_ring(&column, 0..row_spans, grid.crease_sharpness);
    }
    Ok((b.finish(PartialOptions::default()), coords))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::revolve::RevolveInput;
    use crate::construct::settings::Settings;
    use crate::construct::sweep::SweepInput;
    use crate::mesh::validate::check;
    use crate::mesh::Mesh;
    use crate::test_support::circle2;
    use std::f64::consts::TAU;

    fn revolve_mesh(input: &RevolveInput) -> Mesh {
        Mesh::from_parts(input.mesh_parts(&Settings::default()).unwrap()).unwrap()
    }

    #[test]
    fn torus_is_closed_genus_one_and_all_regular() {
        let mut input = SweepInput::new(
            circle2(16, 0.5),
            circle2(16, 2.0)
                .into_iter()
                .map(|[x, y]| [x, y, 0.0])
                .collect(),
        );
        input.closed_profile = true;
        input.closed_trajectory = true;
        let m = Mesh::from_parts(
            grid_mesh(&input.grid(&Settings::default()).unwrap(), &|_, _| {
                DVec3::ZERO
            })
            .unwrap(),
        )
        .unwrap();
        let r = check(&m);
        assert_eq!((r.num_vertices, r.num_faces, r.num_edges), (512, 512, 1024));
        assert_eq!(r.euler_characteristic, 0);
        assert!(r.is_manifold() && r.is_closed() && r.is_consistently_oriented());
        assert_eq!(r.valences.keys().copied().collect::<Vec<_>>(), vec![4]);
        // Outward: the first face's normal points away from the tube's centre line.
        let f = m.face(0);
        let p: Vec<DVec3> = f.iter().map(|&v| m.positions()[v as usize]).collect();
        let n = (p[1] - p[0]).cross(p[3] - p[0]);
        let centre = p[0].truncate().normalize().extend(0.0) * 2.0;
        assert!(n.dot(p[0] - centre) > 0.0);
    }

    #[test]
    fn sphere_has_two_grid_caps_with_valence_3_and_5_only() {
        let pts: Vec<[f64; 2]> = (0..=12)
            .map(|i| {
                let t = -TAU / 4.0 + TAU / 2.0 * i as f64 / 12.0;
                [
                    if i == 0 || i == 12 {
                        0.0
                    } else {
                        crate::math::cos(t)
                    },
                    crate::math::sin(t),
                ]
            })
            .collect();
        let m = revolve_mesh(&RevolveInput::new(pts));
        let r = check(&m);
        assert_eq!(r.euler_characteristic, 2);
        assert!(r.is_manifold() && r.is_closed() && r.is_consistently_oriented());
        assert_eq!(r.valences.keys().copied().collect::<Vec<_>>(), vec![3, 4]);
        assert!(m.corners().is_empty() && m.creases().is_empty());
        // Every data point, cap vertices included, lies on the unit sphere (up to the spline).
        let worst = m
            .positions()
            .iter()
            .map(|p| (p.length() - 1.0).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-4, "{worst}");
        // The cap centres are the poles.
        let poles = m
            .positions()
            .iter()
            .filter(|p| p.truncate().length() < 1e-12)
            .count();
        assert_eq!(poles, 2);
        // Outward: the top cap's faces point up.
        let top = m.num_faces() - 1;
        let p: Vec<DVec3> = m
            .face(top)
            .iter()
            .map(|&v| m.positions()[v as usize])
            .collect();
        assert!((p[1] - p[0]).cross(p[3] - p[0]).z > 0.0);
    }

    #[test]
    fn cone_tip_is_a_tagged_corner() {
        let m = revolve_mesh(&RevolveInput::new(vec![[1.0, 0.0], [0.0, 2.0]]));
        let r = check(&m);
        assert_eq!(r.num_boundary_loops, 1);
        assert!(r.is_manifold() && r.is_consistently_oriented());
        assert_eq!(m.corners().len(), 1);
        let tip = m.corners()[0];
        assert_eq!(
            m.positions()[tip.vertex as usize],
            DVec3::new(0.0, 0.0, 2.0)
        );
        assert_eq!(tip.sharpness, SHARPNESS_INFINITE);
    }

    #[test]
    fn square_tube_keeps_four_crease_loops_and_l_keeps_a_ring() {
        let sq = vec![[-0.2, -0.2], [0.2, -0.2], [0.2, 0.2], [-0.2, 0.2]];
        // A closed, non-planar curve (a circle with a wave in z).
        let loop3: Vec<[f64; 3]> = (0..24)
            .map(|i| {
                let t = TAU * i as f64 / 24.0;
                [
                    3.0 * crate::math::cos(t),
                    3.0 * crate::math::sin(t),
                    0.3 * crate::math::sin(2.0 * t),
                ]
            })
            .collect();
        let mut input = SweepInput::new(sq.clone(), loop3);
        input.closed_profile = true;
        input.closed_trajectory = true;
        input.samples_profile = 8;
        let m = Mesh::from_parts(
            grid_mesh(&input.grid(&Settings::default()).unwrap(), &|_, _| {
                DVec3::ZERO
            })
            .unwrap(),
        )
        .unwrap();
        // 4 columns × 32 edges, forming 4 closed loops: each crease vertex has 2 crease edges.
        assert_eq!(m.creases().len(), 4 * 32);
        let mut count = std::collections::HashMap::new();
        for c in m.creases() {
            for v in c.vertices {
                *count.entry(v).or_insert(0) += 1;
            }
        }
        assert_eq!(count.len(), 4 * 32);
        assert!(count.values().all(|&k| k == 2));
        assert!(check(&m).is_closed());

        let mut l = SweepInput::new(sq, vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0]]);
        l.closed_profile = true;
        l.samples_profile = 8;
        l.samples_trajectory = 8;
        let g = l.grid(&Settings::default()).unwrap();
        let m = Mesh::from_parts(grid_mesh(&g, &|_, _| DVec3::ZERO).unwrap()).unwrap();
        // 4 profile-corner columns × 8 + one ring of 8 at the corner.
        assert_eq!(m.creases().len(), 4 * 8 + 8);
        let ring: Vec<u32> = (0..8).map(|j| (4 * 8 + j) as u32).collect();
        let on_ring = m
            .creases()
            .iter()
            .filter(|c| c.vertices.iter().all(|v| ring.contains(v)))
            .count();
        assert_eq!(on_ring, 8);
        let r = check(&m);
        assert_eq!(r.num_boundary_loops, 2);
        assert!(r.is_consistently_oriented());
    }
}
