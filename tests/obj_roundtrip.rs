//! OBJ reading and writing on OpenSubdiv's regression shapes and on generated meshes:
//! every shape loads with the counts of the shapes' `INDEX.tsv`, and write -> read gives
//! the same mesh bit for bit.

#[path = "support/osd_shapes.rs"]
mod osd_shapes;
#[path = "support/random_mesh.rs"]
mod random_mesh;

use std::path::Path;

use profsubd::io::obj::{parse_obj, read_obj_file, to_obj_string};
use profsubd::options::{BoundaryInterpolation, CreaseMethod};
use profsubd::Mesh;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use osd_shapes::{index, shapes_dir};
use random_mesh::RandomGrid;

/// Every bit of a mesh: positions and sharpness as raw bits, the rest as is.
fn assert_bit_identical(a: &Mesh, b: &Mesh, what: &str) {
    let bits = |m: &Mesh| -> Vec<u64> {
        m.positions()
            .iter()
            .flat_map(|p| p.to_array().map(f64::to_bits))
            .collect()
    };
    let crease_bits = |m: &Mesh| -> Vec<(u32, u32, u32)> {
        m.creases()
            .iter()
            .map(|c| (c.vertices[0], c.vertices[1], c.sharpness.to_bits()))
            .collect()
    };
    let corner_bits = |m: &Mesh| -> Vec<(u32, u32)> {
        m.corners()
            .iter()
            .map(|c| (c.vertex, c.sharpness.to_bits()))
            .collect()
    };
    assert_eq!(bits(a), bits(b), "{what}: positions differ");
    assert_eq!(crease_bits(a), crease_bits(b), "{what}: creases differ");
    assert_eq!(corner_bits(a), corner_bits(b), "{what}: corners differ");
    assert_eq!(a.face_sizes(), b.face_sizes(), "{what}: face sizes differ");
    assert_eq!(a.face_indices(), b.face_indices(), "{what}: faces differ");
    assert_eq!(a.holes(), b.holes(), "{what}: holes differ");
    assert_eq!(a.options(), b.options(), "{what}: options differ");
}

fn round_trip(mesh: &Mesh, what: &str) {
    let text = to_obj_string(mesh);
    let back = parse_obj(&text, Path::new(what)).unwrap_or_else(|e| panic!("{what}: {e}"));
    assert!(back.warnings.is_empty(), "{what}: {:?}", back.warnings);
    assert_bit_identical(mesh, &back.mesh, what);
}

#[test]
fn every_osd_shape_loads_with_index_counts_and_round_trips() {
    let Some(dir) = shapes_dir() else { return };
    let rows = index(&dir);
    for row in &rows {
        let name = row.name.as_str();
        let read = read_obj_file(&row.path).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(read.mesh.num_vertices(), row.verts, "{name}: vertices");
        assert_eq!(read.mesh.num_faces(), row.faces, "{name}: faces");
        let boundary = match read.mesh.options().boundary {
            None => "untagged",
            Some(BoundaryInterpolation::None) => "none",
            Some(BoundaryInterpolation::EdgeOnly) => "edge",
            Some(BoundaryInterpolation::EdgeAndCorner) => "edgeandcorner",
        };
        assert_eq!(boundary, row.boundary, "{name}: boundary tag");
        assert_eq!(
            !read.mesh.creases().is_empty(),
            row.has_creases,
            "{name}: creases"
        );
        assert_eq!(
            !read.mesh.corners().is_empty(),
            row.has_corners,
            "{name}: corners"
        );
        round_trip(&read.mesh, name);
    }
    let objs = std::fs::read_dir(&dir)
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .path()
                .extension()
                .is_some_and(|x| x == "obj")
        })
        .count();
    assert_eq!(
        rows.len(),
        objs,
        "INDEX.tsv must list every .obj of the folder"
    );
    assert_eq!(rows.len(), 87);
}

#[test]
fn osd_shapes_report_exactly_their_ignored_tags() {
    let Some(dir) = shapes_dir() else { return };
    let hedit = read_obj_file(&dir.join("catmark_square_hedit1.obj")).unwrap();
    assert_eq!(hedit.warnings.len(), 2, "{:?}", hedit.warnings);
    for (w, line) in hedit.warnings.iter().zip([46, 47]) {
        let at =
            format!("catmark_square_hedit1.obj:{line}: ignored hierarchical edit `vertexedit`");
        assert!(w.contains(&at), "{w}");
    }
    let fvar = read_obj_file(&dir.join("catmark_cubes_semisharp.obj")).unwrap();
    assert_eq!(fvar.warnings.len(), 1, "{:?}", fvar.warnings);
    assert!(fvar.warnings[0].contains(
        "catmark_cubes_semisharp.obj:164: ignored face-varying tag `facevaryinginterpolateboundary`"
    ));
    let cube = read_obj_file(&dir.join("catmark_cube.obj")).unwrap();
    assert!(cube.warnings.is_empty(), "{:?}", cube.warnings);
    let chaikin = read_obj_file(&dir.join("catmark_chaikin1.obj")).unwrap();
    assert_eq!(
        chaikin.mesh.options().crease_method,
        Some(CreaseMethod::Chaikin)
    );
}

/// A random grid of at most 7 by 7 quads and triangles with coordinates in ±1000, a fifth of
/// them awkward ([`random_mesh::AWKWARD`]), and many tags: creases on the cells' bottom edges
/// (sharpness up to 12), corners (up to 10), holes, boundary untagged, none or edge.
fn random_mesh(rng: &mut ChaCha8Rng) -> Mesh {
    RandomGrid {
        nx: rng.random_range(1..8),
        ny: rng.random_range(1..8),
        span: 1e3,
        awkward: 0.2,
        hexagons: 0.0,
        triangles: 0.3,
        creases: 0.3,
        crease_to: 1,
        max_crease: 12.0,
        corners: 0.1,
        max_corner: 10.0,
        holes: 0.1,
        boundaries: [
            None,
            Some(BoundaryInterpolation::None),
            Some(BoundaryInterpolation::EdgeOnly),
        ],
    }
    .mesh(rng)
}

#[test]
fn generated_meshes_round_trip_bit_identically() {
    let mut rng = ChaCha8Rng::seed_from_u64(20261122);
    for k in 0..200 {
        let mesh = random_mesh(&mut rng);
        round_trip(&mesh, &format!("generated mesh {k}"));
    }
}
