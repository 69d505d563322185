use std::path::Path;

use super::*;
use crate::io::obj::parse_obj;

const TAGGED: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0.5\nv 2 1 0.25\n\
f 1 2 3 4\nf 2 5 6 3\n\
t crease 2/1/0 0 1 10\nt crease 2/1/0 1 4 10\nt crease 2/1/0 2 3 2.5\n\
t corner 1/1/0 5 3\nt hole 1/0/0 1\nt interpolateboundary 1/0/0 2\n";

fn tagged() -> Mesh {
    parse_obj(TAGGED, Path::new("t.obj")).unwrap().mesh
}

#[test]
fn creases_become_chains_and_read_back_in_order() {
    let mesh = tagged();
    let (text, warnings) = to_usda(&mesh, UpAxis::Z);
    assert!(warnings.is_empty());
    assert!(
        text.contains("int[] creaseIndices = [0, 1, 4, 2, 3]"),
        "{text}"
    );
    assert!(text.contains("int[] creaseLengths = [3, 2]"));
    assert!(text.contains("float[] creaseSharpnesses = [10, 2.5]"));
    assert!(text.contains("int[] cornerIndices = [5]"));
    assert!(text.contains("int[] holeIndices = [1]"));
    assert!(text.contains("uniform token interpolateBoundary = \"edgeOnly\""));
    assert!(text.contains("upAxis = \"Z\""));
    let back = parse_usda(&text, Path::new("t.usda")).unwrap();
    assert_eq!(back.positions(), mesh.positions());
    assert_eq!(back.creases(), mesh.creases());
    assert_eq!(back.corners(), mesh.corners());
    assert_eq!(back.holes(), mesh.holes());
    assert_eq!(
        back.options().boundary,
        Some(BoundaryInterpolation::EdgeOnly)
    );
    // Read -> write -> read is identical.
    let (again, _) = to_usda(&back, UpAxis::Z);
    assert_eq!(again, text);
}

#[test]
fn y_up_and_chaikin_read_back() {
    let mut parts = tagged().into_parts();
    parts.options.crease_method = Some(CreaseMethod::Chaikin);
    let mesh = Mesh::from_parts(parts).unwrap();
    let (text, warnings) = to_usda(&mesh, UpAxis::Y);
    assert_eq!(warnings.len(), 1);
    assert!(text.contains("upAxis = \"Y\""));
    assert!(
        text.contains("(2, 0.5, -0)") || text.contains("(2, 0.5, 0)"),
        "{text}"
    );
    let back = parse_usda(&text, Path::new("t.usda")).unwrap();
    assert_eq!(back.positions(), mesh.positions());
    assert_eq!(back.options().crease_method, Some(CreaseMethod::Chaikin));
}

#[test]
fn unsupported_and_malformed_files_are_parse_errors() {
    let base = to_usda(&tagged(), UpAxis::Z).0;
    for (from, to) in [
        (
            "\"catmullClark\"\n    uniform token interpolate",
            "\"loop\"\n    uniform token interpolate",
        ),
        ("\"rightHanded\"", "\"leftHanded\""),
        ("creaseLengths = [3, 2]", "creaseLengths = [3, 3]"),
        ("def Mesh", "def Xform"),
        ("[0, 1, 4, 2, 3]", "[0, 1, x, 2, 3]"),
    ] {
        let bad = base.replacen(from, to, 1);
        assert_ne!(bad, base, "{from}");
        let e = parse_usda(&bad, Path::new("bad.usda")).unwrap_err();
        assert!(matches!(e, Error::Parse { .. }), "{from}: {e}");
    }
}
