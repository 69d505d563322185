//! OBJ reading and writing on OpenSubdiv's regression shapes and on generated meshes:
//! every shape loads with the counts of the shapes' `INDEX.tsv`, and write -> read gives
//! the same mesh bit for bit.

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use std::path::Path;

use glam::DVec3;
use profsubd::io::obj::{parse_obj, read_obj_file, to_obj_string};
use profsubd::options::{BoundaryInterpolation, CreaseMethod, PartialOptions};
use profsubd::{Corner, Crease, Mesh, MeshParts};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use osd_shapes::{index, shapes_dir};

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

/// A random grid of quads and triangles with random tags and awkward coordinates.
fn random_mesh(rng: &mut ChaCha8Rng) -> Mesh {
    let (nx, ny) = (rng.random_range(1..8u32), rng.random_range(1..8u32));
    let awkward = [0.0, -0.0, 1e-300, 5e-324, 1e300, 0.1, 1.0 / 3.0, -2.5e-8];
    let positions = (0..(nx + 1) * (ny + 1))
        .map(|_| {
            DVec3::from_array([0; 3].map(|_| {
                if rng.random_bool(0.2) {
                    awkward[rng.random_range(0..awkward.len())]
                } else {
                    rng.random_range(-1e3..1e3)
                }
            }))
        })
        .collect();
    let mut parts = MeshParts {
        positions,
        ..Default::default()
    };
    let id = |i: u32, j: u32| j * (nx + 1) + i;
    for j in 0..ny {
        for i in 0..nx {
            let q = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            if rng.random_bool(0.3) {
                parts.face_sizes.extend([3, 3]);
                parts
                    .face_indices
                    .extend([q[0], q[1], q[2], q[0], q[2], q[3]]);
            } else {
                parts.face_sizes.push(4);
                parts.face_indices.extend(q);
            }
            if rng.random_bool(0.3) {
                parts.creases.push(Crease {
                    vertices: [q[0], q[1]],
                    sharpness: rng.random_range(0.0..12.0f32),
                });
            }
        }
    }
    for v in 0..parts.positions.len() as u32 {
        if rng.random_bool(0.1) {
            parts.corners.push(Corner {
                vertex: v,
                sharpness: rng.random::<f32>() * 10.0,
            });
        }
    }
    let nf = parts.face_sizes.len() as u32;
    parts.holes = (0..nf).filter(|_| rng.random_bool(0.1)).collect();
    parts.options = PartialOptions {
        boundary: [
            None,
            Some(BoundaryInterpolation::None),
            Some(BoundaryInterpolation::EdgeOnly),
        ][rng.random_range(0..3)],
        crease_method: rng.random_bool(0.5).then_some(CreaseMethod::Chaikin),
        triangles: None,
    };
    Mesh::from_parts(parts).unwrap()
}

#[test]
fn generated_meshes_round_trip_bit_identically() {
    let mut rng = ChaCha8Rng::seed_from_u64(20261122);
    for k in 0..200 {
        let mesh = random_mesh(&mut rng);
        round_trip(&mesh, &format!("generated mesh {k}"));
    }
}
