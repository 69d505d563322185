use glam::DVec3;

use super::*;
use crate::mesh::MeshParts;

fn mesh(nv: usize, faces: &[&[u32]]) -> Mesh {
    Mesh::from_parts(MeshParts {
        positions: (0..nv)
            .map(|i| DVec3::new(i as f64, (i * i) as f64, 0.0))
            .collect(),
        face_sizes: faces.iter().map(|f| f.len() as u32).collect(),
        face_indices: faces.concat(),
        ..Default::default()
    })
    .unwrap()
}

const CUBE: [&[u32]; 6] = [
    &[0, 3, 2, 1],
    &[4, 5, 6, 7],
    &[0, 1, 5, 4],
    &[1, 2, 6, 5],
    &[2, 3, 7, 6],
    &[3, 0, 4, 7],
];

/// An `nx` by `ny` grid of quads, optionally closed into a torus.
fn grid(nx: u32, ny: u32, torus: bool) -> Mesh {
    let (cols, rows) = if torus { (nx, ny) } else { (nx + 1, ny + 1) };
    let id = |i: u32, j: u32| (j % rows) * cols + i % cols;
    let faces: Vec<Vec<u32>> = (0..ny)
        .flat_map(|j| {
            (0..nx).map(move |i| vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
        })
        .collect();
    let refs: Vec<&[u32]> = faces.iter().map(Vec::as_slice).collect();
    mesh((cols * rows) as usize, &refs)
}

#[test]
fn cube_is_a_closed_oriented_sphere() {
    let r = mesh(8, &CUBE).check();
    assert_eq!((r.num_vertices, r.num_edges, r.num_faces), (8, 12, 6));
    assert_eq!(r.euler_characteristic, 2);
    assert!(r.is_closed() && r.is_manifold() && r.is_consistently_oriented());
    assert_eq!((r.num_boundary_loops, r.num_components), (0, 1));
    assert_eq!(r.valences, BTreeMap::from([(3, 8)]));
    assert_eq!(r.face_sizes, BTreeMap::from([(4, 6)]));
}

#[test]
fn open_grid_has_one_boundary_loop() {
    let r = grid(3, 2, false).check();
    assert_eq!((r.num_vertices, r.num_edges, r.num_faces), (12, 17, 6));
    assert_eq!(r.euler_characteristic, 1);
    assert_eq!(r.boundary_edges.len(), 10);
    assert_eq!(r.num_boundary_loops, 1);
    assert!(r.is_manifold() && r.is_consistently_oriented() && !r.is_closed());
    assert_eq!(r.valences, BTreeMap::from([(2, 4), (3, 6), (4, 2)]));
}

#[test]
fn torus_has_euler_characteristic_zero() {
    let r = grid(4, 3, true).check();
    assert_eq!((r.num_vertices, r.num_edges, r.num_faces), (12, 24, 12));
    assert_eq!(r.euler_characteristic, 0);
    assert!(r.is_closed() && r.is_manifold() && r.is_consistently_oriented());
    assert_eq!(r.valences, BTreeMap::from([(4, 12)]));
}

#[test]
fn bow_tie_vertex_is_non_manifold() {
    let r = mesh(5, &[&[0, 1, 2], &[0, 3, 4]]).check();
    assert_eq!(r.non_manifold_vertices, vec![0]);
    assert!(r.non_manifold_edges.is_empty());
    assert_eq!(r.boundary_edges.len(), 6);
    // The two boundary triangles touch at vertex 0: one connected boundary.
    assert_eq!((r.num_boundary_loops, r.num_components), (1, 1));
    assert_eq!(r.euler_characteristic, 1);
    assert!(!r.is_manifold());
}

#[test]
fn edge_with_three_faces_is_non_manifold() {
    let r = mesh(5, &[&[0, 1, 2], &[1, 0, 3], &[0, 1, 4]]).check();
    // Edge 0 is (0, 1), the first edge of the first face.
    assert_eq!(r.non_manifold_edges, vec![[0, 1]]);
    assert_eq!(r.non_manifold_vertices, vec![0, 1]);
    assert_eq!((r.num_edges, r.euler_characteristic), (7, 1));
    assert_eq!(r.boundary_edges.len(), 6);
    assert!(!r.is_manifold());
}

#[test]
fn flipped_face_is_inconsistent_and_non_manifold_as_in_opensubdiv() {
    let mut faces = CUBE;
    faces[1] = &[7, 6, 5, 4];
    let r = mesh(8, &faces).check();
    // Face 1's edges are OpenSubdiv's edges 4..8, first met in that face's direction;
    // each side face uses the pair it shares with face 1 in the same direction.
    assert_eq!(r.inconsistent_edges, vec![[7, 6], [6, 5], [5, 4], [4, 7]]);
    assert_eq!(r.non_manifold_vertices, vec![4, 5, 6, 7]);
    assert!(r.non_manifold_edges.is_empty() && r.is_closed());
    assert!(!r.is_consistently_oriented() && !r.is_manifold());
    assert_eq!((r.num_edges, r.euler_characteristic), (12, 2));
    let two = mesh(6, &[&[0, 1, 4, 3], &[1, 4, 5, 2]]).check();
    assert_eq!(two.inconsistent_edges, vec![[1, 4]]);
    assert_eq!(two.num_boundary_loops, 1);
}

#[test]
fn repeated_face_vertex_and_isolated_vertex() {
    // Like OpenSubdiv's `f 4 3 5 5`: a degenerate edge (2, 2), used once.
    let r = mesh(5, &[&[0, 1, 2, 2], &[0, 3, 1]]).check();
    assert_eq!(r.faces_with_repeated_vertices, vec![0]);
    assert!(r.non_manifold_edges.is_empty());
    assert_eq!(
        r.boundary_edges,
        vec![[1, 2], [2, 2], [2, 0], [0, 3], [3, 1]]
    );
    assert_eq!(r.non_manifold_vertices, vec![2, 4]);
    assert_eq!(r.isolated_vertices, vec![4]);
    assert_eq!(r.num_components, 1);
    assert!(!r.is_manifold());
    // A vertex met twice, not in a row: no degenerate edge, still not a manifold.
    let r = mesh(5, &[&[0, 1, 2, 0, 3, 4]]).check();
    assert_eq!(r.faces_with_repeated_vertices, vec![0]);
    assert!(r.non_manifold_edges.is_empty());
    assert_eq!(r.non_manifold_vertices, vec![0]);
}

#[test]
fn separate_pieces_are_counted() {
    let r = mesh(8, &[&[0, 1, 2, 3], &[4, 5, 6, 7]]).check();
    assert_eq!((r.num_components, r.num_boundary_loops), (2, 2));
    assert_eq!(r.euler_characteristic, 2);
    assert!(r.is_manifold());
}
