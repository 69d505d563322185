//! Uniform refinement on several threads is refinement on one, bit for bit: OpenSubdiv
//! shapes (creases, corners, holes, non-manifold features, triangles, n-gons) and random
//! meshes refined until the last level's parent has enough faces, edges and vertices for
//! every thread count tried (1024 points a thread at least), at 1, 2, 3 and 7 threads and
//! all cores, in both vertex orders. Positions are compared as bits; faces and tags as
//! written. (`conformance_refine` compares the default, all cores, with Far.)

#[path = "support/osd_shapes.rs"]
#[allow(dead_code)] // the shapes folder only, not its index
mod osd_shapes;

use glam::DVec3;
use profsubd::io::obj::read_obj_file;
use profsubd::refine::{refine_uniform_with, VertexOrder};
use profsubd::{
    BoundaryInterpolation, Control, Corner, Crease, CreaseMethod, Mesh, MeshParts, PartialOptions,
    SubdivOptions,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Points a thread needs before the work splits (`eval::parallel`'s threshold).
const MIN_ITEMS_PER_THREAD: usize = 1024;

/// Shapes covering the rules' special cases; each is refined to about 30k faces or more.
const SHAPES: [&str; 10] = [
    "catmark_car",
    "catmark_pawn",
    "catmark_helmet",
    "catmark_hole_test4",
    "catmark_nonman_edges",
    "catmark_nonman_quadpole64",
    "catmark_smoothtris1",
    "catmark_chaikin1",
    "catmark_cubes_semisharp",
    "catmark_fvar_bound3",
];

/// Everything the refined mesh holds, positions as bits.
fn bytes(m: &Mesh) -> (Vec<[u64; 3]>, MeshParts) {
    let bits = m
        .positions()
        .iter()
        .map(|p| p.to_array().map(f64::to_bits))
        .collect();
    let parts = MeshParts {
        positions: Vec::new(),
        ..m.parts().clone()
    };
    (bits, parts)
}

/// The smallest level at which the last refinement step splits over 7 threads.
fn level_for(mesh: &Mesh) -> u32 {
    let mut faces = mesh.num_faces();
    let mut level = 1;
    while faces < 7 * MIN_ITEMS_PER_THREAD {
        faces *= 4;
        level += 1;
    }
    level
}

/// Refine `mesh` at `level` on 1, 2, 3, 7 threads and all cores; all must agree.
fn check(name: &str, mesh: &Mesh, options: &SubdivOptions, level: u32) {
    for order in [VertexOrder::VerticesFirst, VertexOrder::FacesFirst] {
        let on = |threads: usize| {
            let control = Control::NONE.with_threads(threads);
            refine_uniform_with(mesh, options, level, order, &control).unwrap()
        };
        let one = on(1);
        assert!(one.num_faces() > 0, "{name}");
        let one = bytes(&one);
        for threads in [2, 3, 7, 0] {
            assert!(
                bytes(&on(threads)) == one,
                "{name} level {level} {order:?}: {threads} threads differ from one"
            );
        }
    }
}

#[test]
fn osd_shapes_refine_the_same_on_any_number_of_threads() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    for name in SHAPES {
        let mesh = read_obj_file(&dir.join(format!("{name}.obj")))
            .unwrap()
            .mesh;
        let options = mesh.options().resolve();
        check(name, &mesh, &options, level_for(&mesh));
    }
}

/// A `n` by `n` grid with random positions, some quads split into triangles or merged into
/// hexagons, random creases, corners and holes.
fn random_mesh(rng: &mut ChaCha8Rng, n: u32) -> Mesh {
    let positions = (0..(n + 1) * (n + 1))
        .map(|_| DVec3::from_array([0; 3].map(|_| rng.random_range(-10.0..10.0))))
        .collect();
    let mut parts = MeshParts {
        positions,
        ..Default::default()
    };
    let id = |i: u32, j: u32| j * (n + 1) + i;
    for j in 0..n {
        let mut i = 0;
        while i < n {
            let q = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            if i + 1 < n && rng.random_bool(0.1) {
                let h = [q[0], q[1], id(i + 2, j), id(i + 2, j + 1), q[2], q[3]];
                parts.face_sizes.push(6);
                parts.face_indices.extend(h);
                i += 2;
                continue;
            }
            if rng.random_bool(0.2) {
                parts.face_sizes.extend([3, 3]);
                parts
                    .face_indices
                    .extend([q[0], q[1], q[2], q[0], q[2], q[3]]);
            } else {
                parts.face_sizes.push(4);
                parts.face_indices.extend(q);
            }
            if rng.random_bool(0.2) {
                parts.creases.push(Crease {
                    vertices: [q[0], q[3]],
                    sharpness: rng.random_range(0.0..4.0f32),
                });
            }
            i += 1;
        }
    }
    for v in 0..parts.positions.len() as u32 {
        if rng.random_bool(0.05) {
            parts.corners.push(Corner {
                vertex: v,
                sharpness: rng.random::<f32>() * 3.0,
            });
        }
    }
    let nf = parts.face_sizes.len() as u32;
    parts.holes = (0..nf).filter(|_| rng.random_bool(0.03)).collect();
    parts.options = PartialOptions {
        boundary: Some(
            [
                BoundaryInterpolation::None,
                BoundaryInterpolation::EdgeOnly,
                BoundaryInterpolation::EdgeAndCorner,
            ][rng.random_range(0..3)],
        ),
        crease_method: rng.random_bool(0.5).then_some(CreaseMethod::Chaikin),
        triangles: None,
    };
    Mesh::from_parts(parts).unwrap()
}

#[test]
fn random_meshes_refine_the_same_on_any_number_of_threads() {
    let mut rng = ChaCha8Rng::seed_from_u64(18);
    for k in 0..3 {
        let mesh = random_mesh(&mut rng, 30);
        let options = mesh.options().resolve();
        check(
            &format!("random mesh {k}"),
            &mesh,
            &options,
            level_for(&mesh),
        );
    }
}
