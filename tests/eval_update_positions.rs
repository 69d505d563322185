//! `Evaluator::set_positions` against fresh builds: on every OpenSubdiv regression shape
//! (extraordinary vertices, semi-sharp creases and corners, boundaries, non-manifold
//! vertices, faces that repeat a vertex), under both crease methods, with and without hole
//! tags, an evaluator given new positions evaluates bit for bit as one built with them,
//! everywhere: inside faces, at their corners (exact vertex limits below the cache depth)
//! and at the control vertices.
#![allow(clippy::disallowed_methods)] // test data only, not compared across machines

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use glam::DVec3;
use profsubd::eval::Evaluator;
use profsubd::io::obj::read_obj_file;
use profsubd::{CreaseMethod, Error, Mesh, MeshParts, SubdivOptions};

/// A deterministic displacement of every vertex, large enough to change every patch.
fn moved(parts: &MeshParts, seed: f64) -> Vec<DVec3> {
    let diag = parts
        .positions
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    let scale = 0.05 * (diag.1 - diag.0).length();
    parts
        .positions
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let k = i as f64 + seed;
            *p + scale * DVec3::new((1.3 * k).sin(), (2.1 * k).cos(), (0.7 * k).sin())
        })
        .collect()
}

/// Every result of `ev` at a set of points on each parametric face, and at the control
/// vertices, as bits (errors as their messages).
fn fingerprint(ev: &Evaluator) -> Vec<String> {
    // A corner (the exact vertex limit where the quadtree never ends), an inner point and
    // one next to the far corner (deep in the quadtree there).
    let params = [0.0, 1.0 / 3.0, 0.999];
    let mut out = Vec::new();
    for face in 0..ev.num_parametric_faces() as u32 {
        for &u in &params {
            for &v in &params {
                out.push(match ev.evaluate(face, u, v) {
                    Ok(s) => format!(
                        "{:?}",
                        [s.position, s.du, s.dv].map(|p| p.to_array().map(f64::to_bits))
                    ),
                    Err(e) => e.to_string(),
                });
            }
        }
    }
    out.push(match ev.limit_vertices() {
        Ok(s) => format!(
            "{:?}",
            s.iter()
                .map(|s| [s.position, s.du, s.dv].map(|p| p.to_array().map(f64::to_bits)))
                .collect::<Vec<_>>()
        ),
        Err(e) => e.to_string(),
    });
    out
}

/// Shapes whose checks together cover every feature of the full sweep (see
/// [`covers_every_feature`]): semi-sharp creases under both methods, corner tags, every
/// boundary rule, darts, non-quads and smooth triangles, non-manifold edges and vertices,
/// faces that repeat a vertex, isolated vertices, hole tags of the shape's own and those
/// every shape is also checked with, extraordinary vertices of valence 2 to 8.
const CI_SHAPES: &[&str] = &[
    "catmark_chaikin1",
    "catmark_cube_corner3",
    "catmark_cubes_semisharp",
    "catmark_dart_edgecorner",
    "catmark_edgenone",
    "catmark_edgeonly",
    "catmark_hole_test2",
    "catmark_nonman_bareverts",
    "catmark_nonman_edges",
    "catmark_nonquads",
    "catmark_pole8",
    "catmark_smoothtris1",
    "catmark_val2_interior",
    "catmark_xord_boundary",
];

/// The features of `rows` the update must handle, as the INDEX's columns name them.
fn features(rows: &[&osd_shapes::IndexRow]) -> Vec<String> {
    let mut f: Vec<String> = Vec::new();
    for r in rows {
        let mut add = |s: &str| {
            if !f.iter().any(|x| x == s) {
                f.push(s.to_string());
            }
        };
        if r.has_creases {
            add("creases");
        }
        if r.has_corners {
            add("corners");
        }
        add(&format!("boundary {}", r.boundary));
        for key in [
            "chaikin",
            "face sizes",
            "smoothtriangles",
            "non-manifold",
            "repeated vertices",
            "inconsistent orientation",
            "edges with >2 faces",
            "isolated vertices",
            "boundary edges",
            "holes",
        ] {
            if r.notes.contains(key) {
                add(key);
            }
        }
        if r.name.contains("dart") {
            add("dart");
        }
    }
    f.sort();
    f
}

/// Every shape of `rows` for which `keep` holds, under both crease methods, with and without
/// hole tags: an evaluator updated to new positions evaluates as one built with them, and
/// back. Returns the number of results compared.
fn check_updates(rows: &[&osd_shapes::IndexRow]) -> usize {
    let mut compared = 0usize;
    for row in rows {
        let mesh = read_obj_file(&row.path).unwrap().mesh;
        let nf = mesh.num_faces() as u32;
        for holes in [vec![], (0..nf).step_by(7).skip(1).collect::<Vec<u32>>()] {
            let mut parts = mesh.clone().into_parts();
            parts.holes = holes.clone();
            let original = Mesh::from_parts(parts.clone()).unwrap();
            parts.positions = moved(&parts, 0.5);
            let target = Mesh::from_parts(parts).unwrap();
            for crease_method in [CreaseMethod::Uniform, CreaseMethod::Chaikin] {
                let options = SubdivOptions {
                    crease_method,
                    ..mesh.options().resolve()
                };
                let what = format!("{} holes {holes:?} {crease_method:?}", row.name);
                let mut updated = Evaluator::new(&original, &options).unwrap();
                let before = fingerprint(&updated);
                updated.set_positions(target.positions()).unwrap();
                let fresh = Evaluator::new(&target, &options).unwrap();
                let got = fingerprint(&updated);
                assert_eq!(got, fingerprint(&fresh), "{what}");
                assert_ne!(got, before, "{what}: the update changed nothing");
                assert_eq!(updated.mesh(), fresh.mesh(), "{what}");
                // And back: the original positions give the original evaluator.
                updated.set_positions(original.positions()).unwrap();
                assert_eq!(fingerprint(&updated), before, "{what}");
                compared += got.len();
            }
        }
    }
    compared
}

#[test]
fn covers_every_feature() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let rows = osd_shapes::index(&dir);
    let all: Vec<&osd_shapes::IndexRow> = rows.iter().collect();
    let ci: Vec<&osd_shapes::IndexRow> = rows
        .iter()
        .filter(|r| CI_SHAPES.contains(&r.name.as_str()))
        .collect();
    assert_eq!(
        ci.len(),
        CI_SHAPES.len(),
        "a CI shape is missing from the INDEX"
    );
    assert_eq!(features(&ci), features(&all));
}

#[test]
fn new_positions_give_the_evaluator_built_with_them_on_representative_shapes() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let rows = osd_shapes::index(&dir);
    let ci: Vec<&osd_shapes::IndexRow> = rows
        .iter()
        .filter(|r| CI_SHAPES.contains(&r.name.as_str()))
        .collect();
    eprintln!("compared {} results", check_updates(&ci));
}

/// The full sweep (about two and a half minutes in release mode): `cargo test --release
/// --test eval_update_positions -- --ignored`.
#[test]
#[ignore]
fn new_positions_give_the_evaluator_built_with_them_on_every_shape() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let rows = osd_shapes::index(&dir);
    assert_eq!(rows.len(), 87);
    let all: Vec<&osd_shapes::IndexRow> = rows.iter().collect();
    eprintln!("compared {} results", check_updates(&all));
}

#[test]
fn bad_positions_are_refused_and_leave_the_evaluator_unchanged() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mesh = read_obj_file(&dir.join("catmark_car.obj")).unwrap().mesh;
    let mut ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
    let before = fingerprint(&ev);
    let nv = mesh.num_vertices();
    let mut nan = mesh.positions().to_vec();
    nan[3].y = f64::NAN;
    let mut inf = mesh.positions().to_vec();
    inf[nv - 1].z = f64::INFINITY;
    let cases: [(&[DVec3], String); 4] = [
        (
            &mesh.positions()[1..],
            format!("{} positions given for a mesh of {nv} vertices", nv - 1),
        ),
        (
            &[],
            format!("0 positions given for a mesh of {nv} vertices"),
        ),
        (&nan, "position 3 has a non-finite coordinate".to_string()),
        (
            &inf,
            format!("position {} has a non-finite coordinate", nv - 1),
        ),
    ];
    for (positions, message) in cases {
        match ev.set_positions(positions) {
            Err(Error::InvalidArgument(m)) => assert!(m.contains(&message), "{m}"),
            other => panic!("{message}: {other:?}"),
        }
        assert_eq!(fingerprint(&ev), before);
    }
}

#[test]
fn the_build_on_several_threads_is_the_build_on_one() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    // The car refined once (6,300 quads with semi-sharp creases): ranges of faces for up to
    // seven threads. Each range refines its own faces, so points next to a range's ends may
    // be computed by two ranges: the same bits, not the same number of points.
    let car = read_obj_file(&dir.join("catmark_car.obj")).unwrap().mesh;
    let options = car.options().resolve();
    let mesh = profsubd::refine::refine_uniform(&car, &options, 1).unwrap();
    let one = Evaluator::with_threads(&mesh, &options, 1).unwrap();
    let want = fingerprint(&one);
    for threads in [2, 3, 7] {
        let many = Evaluator::with_threads(&mesh, &options, threads).unwrap();
        assert_eq!(fingerprint(&many), want, "{threads} threads");
    }
}
