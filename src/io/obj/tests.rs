use std::path::Path;

use glam::DVec3;

use super::*;
use crate::mesh::{Corner, Crease, MeshParts};
use crate::options::{BoundaryInterpolation, CreaseMethod, PartialOptions, TriangleSubdivision};

fn parse(text: &str) -> Result<ObjRead> {
    parse_obj(text, Path::new("t.obj"))
}

fn parse_error(text: &str) -> (usize, String) {
    match parse(text) {
        Err(Error::Parse {
            path,
            line,
            message,
        }) => {
            assert_eq!(path, Path::new("t.obj"));
            (line, message)
        }
        other => panic!("expected a parse error, got {other:?}"),
    }
}

const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n";

#[test]
fn reads_every_tag_form() {
    let text = format!(
        "# two quads\n{SQUARE}vt 0 0\nvn 0 0 1\ng grp\no obj\ns off\nusemtl m\nmtllib m.mtl\n\
         f 1/1/1 2/2/2 3/3/3 4/4/4\nf 2//1 5//1 6//1 3//1\n\
         t crease 2/1/0 0 1 2.5\n\
         t crease 4/1/0 1 4 4 5 10\n\
         t crease 4/2/0 5 2 2 3 0.5 1.5\n\
         t corner 2/1/0 0 3 3.0\n\
         t corner 2/2/0 4 5 0.25 7\n\
         t hole 1/0/0 1\n\
         t interpolateboundary 1/0/0 2\n\
         t creasemethod 0/0/1 chaikin\n\
         t smoothtriangles 0/0/1 smooth\n"
    );
    let read = parse(&text).unwrap();
    assert!(read.warnings.is_empty(), "{:?}", read.warnings);
    let m = &read.mesh;
    assert_eq!(m.face_sizes(), &[4, 4]);
    assert_eq!(m.face_indices(), &[0, 1, 2, 3, 1, 4, 5, 2]);
    let creases: Vec<([u32; 2], f32)> = m
        .creases()
        .iter()
        .map(|c| (c.vertices, c.sharpness))
        .collect();
    assert_eq!(
        creases,
        vec![
            ([0, 1], 2.5),
            ([1, 4], 10.0),
            ([4, 5], 10.0),
            ([5, 2], 0.5),
            ([2, 3], 1.5)
        ]
    );
    let corners: Vec<(u32, f32)> = m
        .corners()
        .iter()
        .map(|c| (c.vertex, c.sharpness))
        .collect();
    assert_eq!(corners, vec![(0, 3.0), (3, 3.0), (4, 0.25), (5, 7.0)]);
    assert_eq!(m.holes(), &[1]);
    assert_eq!(
        m.options(),
        PartialOptions {
            boundary: Some(BoundaryInterpolation::EdgeOnly),
            crease_method: Some(CreaseMethod::Chaikin),
            triangles: Some(TriangleSubdivision::Smooth),
        }
    );
}

#[test]
fn boundary_tag_numbers_follow_renderman() {
    for (value, expected) in [
        (0, BoundaryInterpolation::None),
        (1, BoundaryInterpolation::EdgeAndCorner),
        (2, BoundaryInterpolation::EdgeOnly),
    ] {
        let text = format!("{SQUARE}f 1 2 3 4\nt interpolateboundary 1/0/0 {value}\n");
        assert_eq!(
            parse(&text).unwrap().mesh.options().boundary,
            Some(expected)
        );
    }
    let untagged = parse(&format!("{SQUARE}f 1 2 3 4\n")).unwrap();
    assert_eq!(untagged.mesh.options(), PartialOptions::default());
}

#[test]
fn negative_indices_count_back_from_the_last_vertex() {
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf 1 3 -1\n";
    let m = parse(text).unwrap().mesh;
    assert_eq!(m.face_indices(), &[0, 1, 2, 0, 2, 3]);
    let (line, message) = parse_error("v 0 0 0\nv 1 0 0\nf -1 -2 -3\n");
    assert_eq!(line, 3);
    assert!(message.contains("relative vertex index -3"), "{message}");
}

#[test]
fn ignored_tags_and_clamps_are_reported_with_file_and_line() {
    let text = format!(
        "{SQUARE}f 1 2 3 4\n\
         t facevaryinginterpolateboundary 1/0/0 1\n\
         t vertexedit 1/0/0 0\n\
         t faceedit 4/0/1 1 2 3 4 hole\n\
         t wobble 0/0/0\n\
         l 1 2\n\
         t crease 2/1/0 0 1 -2\n\
         t corner 1/1/0 2 -0.5\n\
         t interpolateboundary 1/0/0 1\n\
         t interpolateboundary 1/0/0 0\n"
    );
    let read = parse(&text).unwrap();
    let expected = [
        "t.obj:8: ignored face-varying tag `facevaryinginterpolateboundary`",
        "t.obj:9: ignored hierarchical edit `vertexedit`",
        "t.obj:10: ignored hierarchical edit `faceedit`",
        "t.obj:11: ignored unknown tag `wobble`",
        "t.obj:12: ignored unknown statement `l`",
        "t.obj:13: negative sharpness -2 in tag `crease` clamped to 0",
        "t.obj:14: negative sharpness -0.5 in tag `corner` clamped to 0",
        "t.obj:16: `interpolateboundary` tag overrides the one on line 15",
    ];
    assert_eq!(read.warnings.len(), expected.len(), "{:?}", read.warnings);
    for (w, e) in read.warnings.iter().zip(expected) {
        assert!(w.starts_with(e), "{w} does not start with {e}");
    }
    assert_eq!(read.mesh.creases()[0].sharpness.to_bits(), 0f32.to_bits());
    assert_eq!(read.mesh.corners()[0].sharpness.to_bits(), 0f32.to_bits());
    assert_eq!(
        read.mesh.options().boundary,
        Some(BoundaryInterpolation::None)
    );
}

#[test]
fn malformed_lines_give_file_line_and_expectation() {
    let cases: [(&str, usize, &str); 15] = [
        ("v 0 0\n", 1, "expected `v x y z`"),
        (
            "v 0 0 zero\n",
            1,
            "expected a finite vertex coordinate, found `zero`",
        ),
        ("v 0 0 inf\n", 1, "found `inf`"),
        (
            "v 0 0 0\nv 1 0 0\nf 1 2\n",
            3,
            "at least 3 vertex indices, found 2",
        ),
        ("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 0 2\n", 4, "found `0`"),
        (
            "v 0 0 0\nv 1 0 0\nv 1 1 0\n\nf 1 2 9\n",
            5,
            "vertex 9 but the file has 3",
        ),
        ("t crease 2/1\n", 1, "expected argument counts"),
        (
            "t crease 2/1/0 0 1\n",
            1,
            "announces 2/1/0 arguments but has 2 values",
        ),
        ("t crease 3/1/0 0 1 2 1.0\n", 1, "expected `t crease 2/1/0"),
        (
            "t crease 2/1/0 0 -1 1.0\n",
            1,
            "0-based index in tag `crease`, found `-1`",
        ),
        (
            "t corner 2/1/0 0 1 nan\n",
            1,
            "sharpness number in tag `corner`, found `nan`",
        ),
        ("t interpolateboundary 1/0/0 3\n", 1, "B = 0 (none)"),
        ("t creasemethod 0/0/1 uniform\n", 1, "normal|chaikin"),
        ("t smoothtriangles 1/0/0 1\n", 1, "catmark|smooth"),
        ("t\n", 1, "expected a tag name"),
    ];
    for (text, line, expected) in cases {
        let (l, message) = parse_error(text);
        assert_eq!(l, line, "{text:?}: {message}");
        assert!(message.contains(expected), "{text:?}: {message}");
    }
}

#[test]
fn tags_referring_to_missing_components_name_their_line() {
    let base = format!("{SQUARE}f 1 2 3 4\n");
    let cases = [
        ("t crease 2/1/0 0 2 1\n", "no face joins by an edge"),
        (
            "t crease 2/1/0 0 6 1\n",
            "crease on vertices 0 6 (0-based) but the file has 6",
        ),
        (
            "t corner 1/1/0 6 1\n",
            "corner on vertex 6 (0-based) but the file has 6",
        ),
        (
            "t hole 1/0/0 1\n",
            "hole on face 1 (0-based) but the file has 1 faces",
        ),
    ];
    for (tag, expected) in cases {
        let (line, message) = parse_error(&format!("{base}# comment\n{tag}"));
        assert_eq!(line, 9, "{tag}");
        assert!(message.contains(expected), "{tag}: {message}");
    }
    let empty = parse("v 0 0 0\n");
    assert!(
        matches!(&empty, Err(Error::InvalidMesh(m)) if m == "t.obj: mesh has no faces"),
        "{empty:?}"
    );
}

#[test]
fn byte_order_mark_crlf_and_stray_bytes_are_tolerated() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bom.obj");
    let mut bytes = "\u{feff}# caf".as_bytes().to_vec();
    bytes.push(0xe9); // latin-1 in a comment
    bytes.extend_from_slice(b"\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
    std::fs::write(&path, bytes).unwrap();
    let read = read_obj_file(&path).unwrap();
    assert!(read.warnings.is_empty(), "{:?}", read.warnings);
    assert_eq!(read.mesh.face_indices(), &[0, 1, 2]);
}

#[test]
fn reading_a_missing_file_is_an_io_error() {
    let e = read_obj_file(Path::new("/nonexistent/x.obj")).unwrap_err();
    assert!(matches!(e, Error::Io { ref path, .. } if path == Path::new("/nonexistent/x.obj")));
}

fn tagged_mesh() -> Mesh {
    Mesh::from_parts(MeshParts {
        positions: vec![
            DVec3::new(0.1, -0.0, 1e-7),
            DVec3::new(1.0 / 3.0, 2.5e300, -7.0),
            DVec3::new(f64::MIN_POSITIVE / 8.0, 123456789.125, 0.30000000000000004),
            DVec3::new(-1e17, 5e-324, 1.0),
        ],
        face_sizes: vec![3, 3],
        face_indices: vec![0, 1, 2, 0, 2, 3],
        creases: vec![Crease {
            vertices: [2, 0],
            sharpness: 0.1,
        }],
        corners: vec![Corner {
            vertex: 3,
            sharpness: 1.0 / 3.0,
        }],
        holes: vec![1],
        options: PartialOptions {
            boundary: Some(BoundaryInterpolation::EdgeAndCorner),
            crease_method: Some(CreaseMethod::Uniform),
            triangles: Some(TriangleSubdivision::Catmark),
        },
    })
    .unwrap()
}

#[test]
fn writes_shortest_round_trip_numbers_and_tags() {
    let text = to_obj_string(&tagged_mesh());
    let expected = "# written by profsubd; tags as OpenSubdiv's regression shapes\n\
        v 0.1 -0 1e-7\n\
        v 0.3333333333333333 2.5e300 -7\n\
        v 2.781342323134e-309 123456789.125 0.30000000000000004\n\
        v -1e17 5e-324 1\n\
        f 1 2 3\n\
        f 1 3 4\n\
        t interpolateboundary 1/0/0 1\n\
        t creasemethod 0/0/1 normal\n\
        t smoothtriangles 0/0/1 catmark\n\
        t crease 2/1/0 2 0 0.1\n\
        t corner 1/1/0 3 0.33333334\n\
        t hole 1/0/0 1\n";
    assert_eq!(text, expected);
}

#[test]
fn write_then_read_is_bit_identical() {
    let mesh = tagged_mesh();
    let back = parse(&to_obj_string(&mesh)).unwrap();
    assert!(back.warnings.is_empty());
    let bits = |m: &Mesh| -> Vec<u64> {
        m.positions()
            .iter()
            .flat_map(|p| p.to_array().map(f64::to_bits))
            .collect()
    };
    assert_eq!(bits(&back.mesh), bits(&mesh));
    assert_eq!(back.mesh, mesh);
    assert_eq!(
        back.mesh.corners()[0].sharpness.to_bits(),
        (1.0f32 / 3.0).to_bits()
    );
}

#[test]
fn files_round_trip_through_disk() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("m.obj");
    let mesh = tagged_mesh();
    write_obj_file(&mesh, &path).unwrap();
    assert_eq!(read_obj_file(&path).unwrap().mesh, mesh);
    let e = write_obj_file(&mesh, &dir.path().join("no/such/dir.obj")).unwrap_err();
    assert!(matches!(e, Error::Io { .. }));
}
