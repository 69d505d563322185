//! Known-answer tests of the base level: edge numbering, order around vertices, non-manifold
//! detection and Far's sharpening.

use glam::DVec3;

use super::Level;
use crate::catmark::Rule;
use crate::mesh::{Corner, Crease, Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, SubdivOptions};

fn mesh(positions: usize, faces: &[&[u32]]) -> MeshParts {
    MeshParts {
        positions: (0..positions)
            .map(|i| DVec3::new(i as f64, (i * i) as f64, 0.0))
            .collect(),
        face_sizes: faces.iter().map(|f| f.len() as u32).collect(),
        face_indices: faces.iter().flat_map(|f| f.iter().copied()).collect(),
        ..Default::default()
    }
}

fn level(parts: MeshParts) -> Level {
    Level::from_mesh(&Mesh::from_parts(parts).unwrap())
}

fn with_boundary(parts: MeshParts, boundary: BoundaryInterpolation) -> Level {
    let opts = SubdivOptions {
        boundary,
        ..Default::default()
    };
    Level::from_mesh_with_options(&Mesh::from_parts(parts).unwrap(), &opts)
}

/// 2x1 grid of quads: v0 v1 v2 on y=0, v3 v4 v5 on y=1.
fn grid_2x1() -> MeshParts {
    mesh(6, &[&[0, 1, 4, 3], &[1, 2, 5, 4]])
}

fn cube() -> MeshParts {
    mesh(
        8,
        &[
            &[0, 1, 3, 2],
            &[2, 3, 5, 4],
            &[4, 5, 7, 6],
            &[6, 7, 1, 0],
            &[1, 7, 5, 3],
            &[6, 0, 2, 4],
        ],
    )
}

#[test]
fn grid_edges_numbered_as_vtr() {
    let l = level(grid_2x1());
    assert_eq!(l.num_edges(), 7);
    let expect = [[0, 1], [1, 4], [4, 3], [3, 0], [1, 2], [2, 5], [5, 4]];
    for (e, ev) in expect.iter().enumerate() {
        assert_eq!(l.edge_vertices(e), *ev, "edge {e}");
    }
    assert_eq!(l.face_edges(0), &[0, 1, 2, 3]);
    assert_eq!(l.face_edges(1), &[4, 5, 6, 1]);
    assert_eq!(l.edge_faces(1), &[0, 1]);
    assert_eq!(l.edge_face_local_indices(1), &[1, 3]);
    assert_eq!(l.find_edge(4, 1), Some(1));
    assert_eq!(l.find_edge(0, 4), None);
}

#[test]
fn grid_vertex_order_is_counter_clockwise_from_the_leading_boundary_edge() {
    let l = level(grid_2x1());
    // Bottom middle: +x edge, +y edge, -x edge.
    assert_eq!(l.vertex_faces(1), &[1, 0]);
    assert_eq!(l.vertex_edges(1), &[4, 1, 0]);
    assert_eq!(l.vertex_face_local_indices(1), &[0, 1]);
    assert_eq!(l.vertex_edge_local_indices(1), &[0, 0, 1]);
    // Top middle: -x edge, -y edge, +x edge.
    assert_eq!(l.vertex_faces(4), &[0, 1]);
    assert_eq!(l.vertex_edges(4), &[2, 1, 6]);
    assert_eq!(l.vertex_edge_local_indices(4), &[0, 1, 1]);
    assert_eq!(l.valence(4), 3);
    assert!(l.is_vertex_boundary(4));
    assert!(!l.is_edge_boundary(1));
    assert!(l.is_edge_boundary(0));
    // Corners sharpened under the default edge-and-corner rule, boundary edges infinite.
    assert_eq!(l.vertex_sharpness(0), 10.0);
    assert_eq!(l.vertex_rule(0), Rule::Corner);
    assert_eq!(l.vertex_sharpness(1), 0.0);
    assert_eq!(l.vertex_rule(1), Rule::Crease);
    assert_eq!(l.edge_sharpness(0), 10.0);
    assert_eq!(l.edge_sharpness(1), 0.0);
    let l = with_boundary(grid_2x1(), BoundaryInterpolation::EdgeOnly);
    assert_eq!(l.vertex_sharpness(0), 0.0);
    assert_eq!(l.vertex_rule(0), Rule::Crease);
    assert!(!(0..2).any(|f| l.is_face_hole(f)));
    let l = with_boundary(grid_2x1(), BoundaryInterpolation::None);
    assert!(l.is_face_hole(0) && l.is_face_hole(1));
}

#[test]
fn cube_is_closed_and_ordered() {
    let l = level(cube());
    assert_eq!((l.num_vertices(), l.num_edges(), l.num_faces()), (8, 12, 6));
    for v in 0..8 {
        assert_eq!(l.valence(v), 3);
        assert!(!l.is_vertex_boundary(v) && !l.is_vertex_non_manifold(v));
        assert_eq!(l.vertex_rule(v), Rule::Smooth);
        let (faces, edges, locals) = (
            l.vertex_faces(v),
            l.vertex_edges(v),
            l.vertex_face_local_indices(v),
        );
        // Face i leads with edge i and trails with edge i+1 (counter-clockwise).
        for i in 0..3 {
            let fe = l.face_edges(faces[i] as usize);
            let k = locals[i] as usize;
            assert_eq!(l.face_vertices(faces[i] as usize)[k] as usize, v);
            assert_eq!(fe[k], edges[i]);
            assert_eq!(fe[(k + 3) % 4], edges[(i + 1) % 3]);
        }
    }
    for e in 0..12 {
        assert_eq!(l.edge_faces(e).len(), 2);
        assert!(!l.is_edge_non_manifold(e));
    }
    // Vertex 0's first face is the first face it was met in (face 0).
    assert_eq!(l.vertex_faces(0)[0], 0);
}

#[test]
fn creases_and_corners_from_tags() {
    let mut p = cube();
    p.creases.push(Crease {
        vertices: [3, 1],
        sharpness: 2.5,
    });
    p.creases.push(Crease {
        vertices: [1, 0],
        sharpness: 1.0,
    });
    p.corners.push(Corner {
        vertex: 5,
        sharpness: 0.5,
    });
    let l = level(p);
    let e = l.find_edge(1, 3).unwrap() as usize;
    assert_eq!(l.edge_sharpness(e), 2.5);
    assert_eq!(l.edge_sharpness(0), 1.0);
    assert_eq!(l.vertex_rule(1), Rule::Crease);
    assert_eq!(l.vertex_rule(3), Rule::Dart);
    assert_eq!(l.vertex_rule(5), Rule::Corner);
    assert_eq!(l.vertex_sharpness(5), 0.5);
}

#[test]
fn non_manifold_fin_edge() {
    // Three quads sharing edge (0,1).
    let l = level(mesh(8, &[&[0, 1, 2, 3], &[1, 0, 4, 5], &[0, 1, 6, 7]]));
    let e = l.find_edge(0, 1).unwrap() as usize;
    assert_eq!(e, 0);
    assert_eq!(l.edge_faces(e), &[0, 1, 2]);
    assert!(l.is_edge_non_manifold(e));
    assert!(l.is_vertex_non_manifold(0) && l.is_vertex_non_manifold(1));
    assert!(!l.is_vertex_non_manifold(2));
    assert_eq!(l.edge_sharpness(e), 10.0);
    assert_eq!(l.vertex_sharpness(0), 10.0);
    // Non-manifold vertices keep the order faces were met in.
    assert_eq!(l.vertex_faces(0), &[0, 1, 2]);
    assert_eq!(l.vertex_edges(0), &[0, 3, 4, 9]);
}

#[test]
fn opposite_winding_is_non_manifold() {
    // Second face uses edge (0,1) in the same direction as the first.
    let l = level(mesh(6, &[&[0, 1, 2, 3], &[0, 1, 4, 5]]));
    assert!(l.is_edge_non_manifold(0));
    assert_eq!(l.edge_faces(0), &[0, 1]);
    assert_eq!(l.edge_sharpness(0), 10.0);
}

#[test]
fn bowtie_vertex_is_non_manifold() {
    let l = level(mesh(5, &[&[0, 1, 2], &[0, 3, 4]]));
    assert!(l.is_vertex_non_manifold(0));
    assert!(!(0..l.num_edges()).any(|e| l.is_edge_non_manifold(e)));
    assert_eq!(l.vertex_sharpness(0), 10.0);
    assert_eq!(l.vertex_faces(0), &[0, 1]);
}

#[test]
fn repeated_vertex_makes_degenerate_edge() {
    // As catmark_nonman_quadpole: a quad 0 1 2 2.
    let l = level(mesh(4, &[&[0, 1, 2, 2], &[0, 2, 3]]));
    // Edges: (0,1) (1,2) (2,2) (2,0) | (0,2)->found as e3 (2,0) (2,3) (3,0)
    assert_eq!(l.num_edges(), 6);
    assert_eq!(l.edge_vertices(2), [2, 2]);
    assert!(l.is_edge_non_manifold(2));
    assert_eq!(l.face_edges(0), &[0, 1, 2, 3]);
    assert_eq!(l.face_edges(1), &[3, 4, 5]);
    assert!(l.is_vertex_non_manifold(2));
    // Vertex 2 is met twice in face 0 (positions 2 and 3) and has the degenerate edge twice.
    assert_eq!(l.vertex_faces(2), &[0, 0, 1]);
    assert_eq!(l.vertex_face_local_indices(2), &[2, 3, 1]);
    assert_eq!(l.vertex_edges(2), &[1, 2, 2, 3, 4]);
    assert_eq!(l.vertex_edge_local_indices(2), &[1, 0, 1, 0, 0]);
    assert_eq!(l.find_edge(2, 2), Some(2));
}

#[test]
fn edge_repeated_in_one_face_gets_a_new_instance() {
    // Face 0 1 0 2 uses edge (0,1) then (1,0): the second is a new edge.
    let l = level(mesh(3, &[&[0, 1, 0, 2]]));
    assert_eq!(l.edge_vertices(0), [0, 1]);
    assert_eq!(l.edge_vertices(1), [1, 0]);
    assert!(l.is_edge_non_manifold(0) && l.is_edge_non_manifold(1));
    assert_eq!(l.face_edges(0), &[0, 1, 2, 3]);
}

#[test]
fn isolated_vertex_is_non_manifold_corner() {
    let l = level(mesh(5, &[&[0, 1, 2, 3]]));
    assert!(l.is_vertex_non_manifold(4));
    assert_eq!(l.vertex_sharpness(4), 10.0);
    assert_eq!(l.vertex_rule(4), Rule::Corner);
    assert_eq!(l.valence(4), 0);
}
