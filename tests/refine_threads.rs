//! Uniform refinement on several threads is refinement on one, bit for bit: OpenSubdiv
//! shapes (creases, corners, holes, non-manifold features, triangles, n-gons) and random
//! meshes refined until the last level's parent has enough faces, edges and vertices for
//! every thread count tried (1024 points a thread at least), at 1, 2, 3 and 7 threads and
//! all cores, in both vertex orders. Positions are compared as bits; faces and tags as
//! written. (`conformance_refine` compares the default, all cores, with Far.)

#[path = "support/osd_shapes.rs"]
#[allow(dead_code)] // the shapes folder only, not its index
mod osd_shapes;
#[path = "support/random_mesh.rs"]
mod random_mesh;

use profsubd::io::obj::read_obj_file;
use profsubd::refine::{refine_uniform_with, VertexOrder};
use profsubd::{BoundaryInterpolation, Control, Mesh, MeshParts, SubdivOptions};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use random_mesh::RandomGrid;

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

/// A `n` by `n` grid with coordinates in ±10, about a tenth of the cell pairs merged into
/// hexagons, a fifth of the quads split into triangles, creases on a fifth of the cells' left
/// edges (sharpness below 4), corners (below 3) and holes; boundary tags other than untagged.
fn random_mesh(rng: &mut ChaCha8Rng, n: u32) -> Mesh {
    RandomGrid {
        nx: n,
        ny: n,
        span: 10.0,
        awkward: 0.0,
        hexagons: 0.1,
        triangles: 0.2,
        creases: 0.2,
        crease_to: 3,
        max_crease: 4.0,
        corners: 0.05,
        max_corner: 3.0,
        holes: 0.03,
        boundaries: [
            Some(BoundaryInterpolation::None),
            Some(BoundaryInterpolation::EdgeOnly),
            Some(BoundaryInterpolation::EdgeAndCorner),
        ],
    }
    .mesh(rng)
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
