//! Known answers for one and more refinement steps: counts, Far's child order, exact
//! positions on a cube and a quad, decaying creases, and internal consistency of the child
//! topology.

use glam::DVec3;

use super::*;
use crate::mesh::{Crease, MeshParts};
use crate::options::{BoundaryInterpolation, CreaseMethod};

fn cube(creases: Vec<Crease>) -> Mesh {
    let p = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
    Mesh::from_parts(MeshParts {
        positions: vec![
            p(-0.5, -0.5, 0.5),
            p(0.5, -0.5, 0.5),
            p(-0.5, 0.5, 0.5),
            p(0.5, 0.5, 0.5),
            p(-0.5, 0.5, -0.5),
            p(0.5, 0.5, -0.5),
            p(-0.5, -0.5, -0.5),
            p(0.5, -0.5, -0.5),
        ],
        face_sizes: vec![4; 6],
        face_indices: vec![
            0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 1, 0, 1, 7, 5, 3, 6, 0, 2, 4,
        ],
        creases,
        ..Default::default()
    })
    .unwrap()
}

fn quad() -> Mesh {
    Mesh::from_parts(crate::test_support::quad()).unwrap()
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).abs().max_element() <= 1e-15
}

fn check_consistency(l: &Level) {
    if let Err(e) = l.validate() {
        panic!("level {}: {e}", l.depth());
    }
}

#[test]
fn quad_level_one_in_far_order() {
    let m = refine_uniform(&quad(), &SubdivOptions::default(), 1).unwrap();
    assert_eq!(m.num_vertices(), 9);
    assert_eq!(m.num_faces(), 4);
    // Vertices: 4 corners (kept by the corner rule), face point, 4 edge midpoints.
    let p = m.positions();
    assert_eq!(p[0], DVec3::ZERO);
    assert_eq!(p[2], DVec3::new(1.0, 1.0, 0.0));
    assert_eq!(p[4], DVec3::new(0.5, 0.5, 0.0));
    assert_eq!(p[5], DVec3::new(0.5, 0.0, 0.0));
    assert_eq!(p[8], DVec3::new(0.0, 0.5, 0.0));
    // Child quads keep their corner's position in the parent quad.
    assert_eq!(m.face(0), &[0, 5, 4, 8]);
    assert_eq!(m.face(1), &[5, 1, 6, 4]);
    assert_eq!(m.face(2), &[4, 6, 2, 7]);
    assert_eq!(m.face(3), &[8, 4, 7, 3]);
    assert!(m.creases().is_empty() && m.corners().is_empty());
    // Edge-only: the corners follow the boundary curve rule.
    let opts = SubdivOptions {
        boundary: BoundaryInterpolation::EdgeOnly,
        ..Default::default()
    };
    let m = refine_uniform(&quad(), &opts, 1).unwrap();
    assert_eq!(m.positions()[0], DVec3::new(0.125, 0.125, 0.0));
}

#[test]
fn faces_first_order_permutes_vertices() {
    let mesh = cube(vec![]);
    let o = SubdivOptions::default();
    let a = refine_uniform(&mesh, &o, 2).unwrap();
    let b = refine_uniform_ordered(&mesh, &o, 2, VertexOrder::FacesFirst).unwrap();
    assert_eq!(a.num_vertices(), b.num_vertices());
    assert_eq!(a.face_indices().len(), b.face_indices().len());
    for (fa, fb) in a.face_indices().iter().zip(b.face_indices()) {
        assert_eq!(a.positions()[*fa as usize], b.positions()[*fb as usize]);
    }
    // Level-1 faces first: the first child vertex is the face point of face 0.
    let b1 = refine_uniform_ordered(&mesh, &o, 1, VertexOrder::FacesFirst).unwrap();
    assert_eq!(b1.positions()[0], DVec3::new(0.0, 0.0, 0.5));
}

#[test]
fn cube_level_one_positions() {
    let m = refine_uniform(&cube(vec![]), &SubdivOptions::default(), 1).unwrap();
    assert_eq!((m.num_vertices(), m.num_faces()), (26, 24));
    let p = m.positions();
    // Corner (valence 3): (Q + 2R + 0 S) / 3 = 5/18 per coordinate.
    assert!(close(p[3], DVec3::splat(5.0 / 18.0)));
    // Face point of face 0, then edge point of edge 0 (vertices 0 and 1).
    assert!(close(p[8], DVec3::new(0.0, 0.0, 0.5)));
    assert!(close(p[14], DVec3::new(0.0, -0.375, 0.375)));
}

#[test]
fn semi_sharp_crease_blends_and_decays() {
    // Edge 0 (vertices 0, 1) with sharpness 0.5: half crease, half smooth.
    let crease = |s| {
        vec![Crease {
            vertices: [0, 1],
            sharpness: s,
        }]
    };
    let o = SubdivOptions::default();
    let (l, p) = refine_levels(&cube(crease(0.5)), &o, 1, VertexOrder::VerticesFirst).unwrap();
    let smooth = DVec3::new(0.0, -0.375, 0.375);
    let mid = DVec3::new(0.0, -0.5, 0.5);
    assert!(close(p[14], 0.5 * mid + 0.5 * smooth));
    assert_eq!(l.edge_sharpness(l.num_edges() - 24), 0.0);
    // Sharpness 2.5: full crease, children 1.5.
    let (l, p) = refine_levels(&cube(crease(2.5)), &o, 1, VertexOrder::VerticesFirst).unwrap();
    assert_eq!(p[14], mid);
    let first_edge_child = 24;
    assert_eq!(l.edge_sharpness(first_edge_child), 1.5);
    assert_eq!(l.edge_sharpness(first_edge_child + 1), 1.5);
    let m = refine_uniform(&cube(crease(2.5)), &o, 2).unwrap();
    assert_eq!(m.creases().len(), 4);
    assert!(m.creases().iter().all(|c| c.sharpness == 0.5));
    // Chaikin on an isolated crease decays like uniform.
    let ch = SubdivOptions {
        crease_method: CreaseMethod::Chaikin,
        ..o
    };
    let (l, _) = refine_levels(&cube(crease(2.5)), &ch, 1, VertexOrder::VerticesFirst).unwrap();
    assert_eq!(l.edge_sharpness(first_edge_child), 1.5);
}

#[test]
fn child_topology_is_consistent() {
    let o = SubdivOptions::default();
    let mesh = Mesh::from_parts(MeshParts {
        positions: (0..7).map(|i| DVec3::new(i as f64, 0.0, 0.0)).collect(),
        // A quad, a triangle and a pentagon sharing edges, plus a non-manifold fin.
        face_sizes: vec![4, 3, 5, 3],
        face_indices: vec![0, 1, 2, 3, 1, 4, 2, 2, 4, 5, 6, 3, 1, 2, 6],
        ..Default::default()
    })
    .unwrap();
    for m in [cube(vec![]), mesh] {
        let mut l = Level::from_mesh_with_options(&m, &o);
        check_consistency(&l);
        for _ in 0..3 {
            for order in [VertexOrder::VerticesFirst, VertexOrder::FacesFirst] {
                check_consistency(&refine(&l, order).child);
            }
            l = refine(&l, VertexOrder::VerticesFirst).child;
        }
    }
}

#[test]
fn stencils_reproduce_positions() {
    let mesh = cube(vec![Crease {
        vertices: [0, 1],
        sharpness: 1.7,
    }]);
    let o = SubdivOptions::default();
    let mut l = Level::from_mesh_with_options(&mesh, &o);
    let mut pos = mesh.positions().to_vec();
    let mut st: Vec<SparseStencil> = (0..8).map(SparseStencil::unit).collect();
    for _ in 0..3 {
        let r = refine(&l, VertexOrder::VerticesFirst);
        pos = interpolate(&l, &r, &pos);
        st = interpolate(&l, &r, &st);
        l = r.child;
    }
    for (p, s) in pos.iter().zip(&st) {
        let sum: f64 = s.entries.iter().map(|e| e.1).sum();
        assert!((sum - 1.0).abs() < 1e-14);
        assert!((s.apply(mesh.positions()) - *p).length() < 1e-15);
    }
}

#[test]
fn rejects_too_deep() {
    let e = refine_uniform(&quad(), &SubdivOptions::default(), MAX_LEVEL + 1);
    assert!(matches!(e, Err(Error::InvalidArgument(_))));
}
