//! The constructions (profile, revolve, sweep) under every subdivision option they accept:
//! the mesh is tagged with the options, and the crate's evaluator, configured from the tags
//! read back from the written OBJ, puts the limit of every control vertex on its data point
//! (≤ 1e-10 × diagonal). Boundary *none* with an open boundary is refused, the options
//! reach the fit through JSON, the CLI and the C API, and bad values are specific errors.
// Reference geometry for tolerance checks: the platform's libm is fine here.
#![allow(clippy::disallowed_methods)]

#[path = "support/cli.rs"]
mod cli;

use std::path::Path;
use std::ptr::null_mut;

use cli::{assert_refused, example_file, profsubd, stderr, write_input};
use glam::DVec3;

use profsubd::construct::profile::shapes::double_cone;
use profsubd::eval::Evaluator;
use profsubd::ffi::construct::profsubd_options_set_crease_sharpness;
use profsubd::ffi::fitted::{profsubd_fitted, profsubd_fitted_free, profsubd_fitted_get_mesh};
use profsubd::ffi::mesh::profsubd_mesh_free;
use profsubd::ffi::mesh_io::profsubd_mesh_write_obj;
use profsubd::ffi::options::{
    profsubd_options, profsubd_options_free, profsubd_options_new, profsubd_options_set_boundary,
    profsubd_options_set_crease_method,
};
use profsubd::ffi::profile::{profsubd_profile_build, profsubd_profile_curves};
use profsubd::ffi::revolve::profsubd_revolve;
use profsubd::ffi::status::profsubd_status::{self, *};
use profsubd::io::obj::{parse_obj, read_obj_file, to_obj_string};
use profsubd::mesh::SHARPNESS_INFINITE;
use profsubd::profile::{build, ProfileInput};
use profsubd::Caps;
use profsubd::RevolveInput;
use profsubd::SweepInput;
use profsubd::{revolve, sweep, Settings};
use profsubd::{BoundaryInterpolation, CreaseMethod, Error, Mesh, SubdivOptions};

const BOUNDARIES: [BoundaryInterpolation; 2] = [
    BoundaryInterpolation::EdgeOnly,
    BoundaryInterpolation::EdgeAndCorner,
];
const METHODS: [CreaseMethod; 2] = [CreaseMethod::Uniform, CreaseMethod::Chaikin];

fn diagonal(points: &[DVec3]) -> f64 {
    let (lo, hi) = points.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    (hi - lo).length()
}

/// Limit position of every control vertex by the evaluator at a corner of its first face
/// (all-quad meshes: the Ptex face is the face).
fn vertex_limits(mesh: &Mesh, options: &SubdivOptions) -> Vec<DVec3> {
    let ev = Evaluator::new(mesh, options).unwrap();
    let mut out = vec![DVec3::NAN; mesh.num_vertices()];
    for f in 0..mesh.num_faces() {
        for (corner, &v) in mesh.face(f).iter().enumerate() {
            if out[v as usize].is_nan() {
                let (u, w) = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][corner];
                out[v as usize] = ev.evaluate(f as u32, u, w).unwrap().position;
            }
        }
    }
    out
}

fn worst(a: &[DVec3], b: &[DVec3]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(a, b)| (*a - *b).length())
        .fold(0.0, f64::max)
}

/// The mesh carries exactly `expected` as tags, and after an OBJ round trip the evaluator
/// under those tags interpolates every target to 1e-10 × diagonal. Returns the worst
/// distance over the diagonal.
fn assert_interpolates(mesh: &Mesh, targets: &[DVec3], expected: SubdivOptions, what: &str) -> f64 {
    let read = parse_obj(&to_obj_string(mesh), Path::new(what))
        .unwrap()
        .mesh;
    let tags = read.options();
    assert_eq!(
        tags.boundary,
        Some(expected.boundary),
        "{what}: boundary tag"
    );
    assert_eq!(
        tags.crease_method,
        Some(expected.crease_method),
        "{what}: crease method tag"
    );
    let diag = diagonal(targets);
    let e = worst(&vertex_limits(&read, &tags.resolve()), targets) / diag;
    assert!(e <= 1e-10, "{what}: limit vs target {e:e} x diagonal");
    e
}

fn options(boundary: BoundaryInterpolation, crease_method: CreaseMethod) -> SubdivOptions {
    SubdivOptions {
        boundary,
        crease_method,
        ..Default::default()
    }
}

fn vase() -> (ProfileInput, Settings) {
    ProfileInput::from_json(
        &std::fs::read_to_string(example_file("profiles", "vase", "json")).unwrap(),
        Path::new("vase.json"),
    )
    .unwrap()
}

/// Open at the top (vase), closed with semi-sharp creases (double cone, flat-capped
/// cylinder-like body): every boundary rule that has a surface and both crease methods.
#[test]
fn profiles_interpolate_under_every_option() {
    let mut cone = (double_cone(1.0, 1.0, 8), Settings::default());
    cone.1.crease_sharpness = 2.5;
    let mut capped = (
        ProfileInput::new(
            vec![[0.8, 0.0], [1.0, 0.5], [0.9, 1.0], [0.5, 1.5], [0.6, 2.0]],
            vec![[0.6, 0.0], [0.7, 0.5], [0.7, 1.0], [0.4, 1.5], [0.5, 2.0]],
        ),
        Settings::default(),
    );
    capped.1.caps = Caps::Flat;
    capped.1.crease_sharpness = 1.5;
    capped.0.corners.c1 = vec![2];
    for (name, base) in [
        ("vase", vase()),
        ("cone 2.5", cone),
        ("flat caps 1.5", capped),
    ] {
        for boundary in BOUNDARIES {
            for crease_method in METHODS {
                let (input, mut settings) = base.clone();
                settings.boundary = boundary;
                settings.crease_method = crease_method;
                let m = build(&input, &settings).unwrap();
                let what = format!("{name} {boundary:?} {crease_method:?}");
                assert_interpolates(&m.mesh, &m.targets, options(boundary, crease_method), &what);
            }
        }
    }
}

/// A closed model has no boundary: boundary *none* fits, to the same mesh as the other
/// rules; with an open end it is refused, naming a vertex of the open ring.
#[test]
fn boundary_none_fits_closed_models_and_refuses_open_ends() {
    let cone = double_cone(1.0, 1.0, 8);
    let mut settings = Settings {
        crease_sharpness: 2.5,
        ..Settings::default()
    };
    let reference = build(&cone, &settings).unwrap();
    settings.boundary = BoundaryInterpolation::None;
    let m = build(&cone, &settings).unwrap();
    let none = options(BoundaryInterpolation::None, CreaseMethod::Uniform);
    assert_interpolates(&m.mesh, &m.targets, none, "cone none");
    assert_eq!(m.mesh.positions(), reference.mesh.positions());

    let mut open = vase();
    open.1.boundary = BoundaryInterpolation::None;
    let e = build(&open.0, &open.1).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidArgument(m) if m.contains("16 vertices")
            && m.contains("boundary interpolation none")
            && m.contains("(1, 0, 4.1)")),
        "{e}"
    );
    let rev = RevolveInput::new(vec![[1.0, 0.0], [1.2, 1.0]]);
    let none = Settings {
        boundary: BoundaryInterpolation::None,
        ..Settings::default()
    };
    assert!(
        matches!(revolve::build(&rev, &none), Err(Error::InvalidArgument(m)) if m.contains("boundary"))
    );
    // A full turn with two poles is closed.
    let sphere = RevolveInput::new(
        (0..=12)
            .map(|i| {
                let t = std::f64::consts::PI * (i as f64 / 12.0 - 0.5);
                [if i % 12 == 0 { 0.0 } else { t.cos() }, t.sin()]
            })
            .collect(),
    );
    let s = revolve::build(&sphere, &none).unwrap();
    assert_interpolates(
        &s.mesh,
        &s.targets,
        options(BoundaryInterpolation::None, CreaseMethod::Uniform),
        "sphere none",
    );
}

/// A three-quarter revolution and an open ribbon sweep have one-face corner vertices, where
/// edge-only and edge-and-corner differ: each fit interpolates under its own rule, and
/// evaluating it under the other rule misses the corner targets.
#[test]
fn partial_revolutions_and_open_sweeps_honour_the_boundary_rule() {
    let mut rev = RevolveInput::new(vec![[1.0, 0.0], [1.3, 0.6], [1.0, 1.2], [0.6, 1.5]]);
    rev.angle_deg = 270.0;
    rev.samples_around = 12;
    rev.samples_profile = 8;
    rev.corners = vec![2];
    let mut rev_settings = Settings {
        crease_sharpness: 2.0,
        ..Settings::default()
    };
    let mut ribbon = SweepInput::new(
        vec![[-0.3, 0.0], [0.0, 0.1], [0.3, 0.0]],
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.5, 1.0, 0.0],
            [1.5, 2.0, 0.5],
        ],
    );
    ribbon.samples_profile = 6;
    ribbon.samples_trajectory = 12;
    ribbon.corners.profile = vec![1];
    ribbon.corners.trajectory = vec![1];
    let mut ribbon_settings = Settings {
        crease_sharpness: 1.5,
        ..Settings::default()
    };
    for crease_method in METHODS {
        let mut fitted = Vec::new();
        for boundary in BOUNDARIES {
            rev_settings.boundary = boundary;
            rev_settings.crease_method = crease_method;
            ribbon_settings.boundary = boundary;
            ribbon_settings.crease_method = crease_method;
            let o = options(boundary, crease_method);
            let r = revolve::build(&rev, &rev_settings).unwrap();
            assert!(r.mesh.creases().iter().all(|c| c.sharpness == 2.0));
            assert!(!r.mesh.creases().is_empty());
            assert_interpolates(&r.mesh, &r.targets, o, &format!("270° revolve {o:?}"));
            let s = sweep::build(&ribbon, &ribbon_settings).unwrap();
            assert!(s.mesh.creases().iter().all(|c| c.sharpness == 1.5));
            assert_interpolates(&s.mesh, &s.targets, o, &format!("ribbon sweep {o:?}"));
            fitted.push((r, s));
        }
        // The edge-only fit evaluated with edge-and-corner rules (and the reverse) is off.
        for (k, (r, s)) in fitted.iter().enumerate() {
            let other = options(BOUNDARIES[1 - k], crease_method);
            for (mesh, targets) in [(&r.mesh, &r.targets), (&s.mesh, &s.targets)] {
                let e = worst(&vertex_limits(mesh, &other), targets) / diagonal(targets);
                assert!(
                    e > 1e-3,
                    "{other:?}: the rule should matter at corners ({e:e})"
                );
            }
        }
    }
}

/// Sweeps and revolutions take `crease_sharpness` like the profile construction: semi-sharp
/// crease loops and rings are fitted with the true limit. Every crease edge of a construction
/// has the same sharpness, and Chaikin's rule differs from uniform decay only where semi-sharp
/// edges of different sharpness meet, so both methods give the same control points here.
#[test]
fn semi_sharp_sweeps_and_revolutions_interpolate() {
    let square = vec![[-0.2, -0.2], [0.2, -0.2], [0.2, 0.2], [-0.2, 0.2]];
    let wavy: Vec<[f64; 3]> = (0..24)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 24.0;
            [2.0 * t.cos(), 2.0 * t.sin(), 0.2 * (2.0 * t).sin()]
        })
        .collect();
    let mut tube = SweepInput::new(square.clone(), wavy);
    tube.closed_profile = true;
    tube.closed_trajectory = true;
    tube.samples_profile = 8;
    let mut rail = SweepInput::new(
        square,
        vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0]],
    );
    rail.closed_profile = true;
    rail.samples_profile = 8;
    rail.samples_trajectory = 16;
    let mut goblet = RevolveInput::new(vec![
        [0.0, 0.0],
        [1.0, 0.0],
        [0.3, 0.4],
        [0.3, 1.2],
        [1.0, 2.0],
    ]);
    goblet.corners = vec![1];
    for sharpness in [0.5f32, 1.5, 3.0] {
        for crease_method in METHODS {
            let mut settings = Settings {
                crease_sharpness: sharpness,
                ..Settings::default()
            };
            for (name, input) in [("tube", &tube), ("rail", &rail)] {
                settings.crease_method = crease_method;
                let s = sweep::build(input, &settings).unwrap();
                let uniform = Settings {
                    crease_method: CreaseMethod::Uniform,
                    ..settings.clone()
                };
                let u = sweep::build(input, &uniform).unwrap();
                assert_eq!(s.mesh.positions(), u.mesh.positions());
                assert!(!s.mesh.creases().is_empty());
                assert!(s.mesh.creases().iter().all(|c| c.sharpness == sharpness));
                let o = options(BoundaryInterpolation::EdgeAndCorner, crease_method);
                assert_interpolates(&s.mesh, &s.targets, o, &format!("{name} {sharpness} {o:?}"));
            }
            settings.crease_method = crease_method;
            let g = revolve::build(&goblet, &settings).unwrap();
            assert!(g.mesh.creases().iter().all(|c| c.sharpness == sharpness));
            // The bottom is a pointed pole: its tip stays infinitely sharp.
            assert!(g
                .mesh
                .corners()
                .iter()
                .all(|c| c.sharpness == SHARPNESS_INFINITE));
            let o = options(BoundaryInterpolation::EdgeAndCorner, crease_method);
            assert_interpolates(&g.mesh, &g.targets, o, &format!("goblet {sharpness} {o:?}"));
        }
    }
}

#[test]
fn json_keys_parse_and_bad_values_are_specific_errors() {
    let c = r#""c1": [[0,0],[1,1],[0,2]], "c2": [[0,0],[1,1],[0,2]]"#;
    let (_, p) = ProfileInput::from_json(
        &format!(r#"{{{c}, "boundary": "edge-only", "crease_method": "chaikin"}}"#),
        Path::new("p.json"),
    )
    .unwrap();
    assert_eq!(p.boundary, BoundaryInterpolation::EdgeOnly);
    assert_eq!(p.crease_method, CreaseMethod::Chaikin);
    let (_, p) = ProfileInput::from_json(&format!("{{{c}}}"), Path::new("p.json")).unwrap();
    assert_eq!(p.boundary, BoundaryInterpolation::EdgeAndCorner);
    assert_eq!(p.crease_method, CreaseMethod::Uniform);
    let parse_error = |e: Error| match e {
        Error::Parse { message, .. } => message,
        other => panic!("expected a parse error, got {other}"),
    };
    let e = ProfileInput::from_json(&format!(r#"{{{c}, "boundary": "edge"}}"#), Path::new("p"));
    let m = parse_error(e.unwrap_err());
    assert!(
        m.contains("unknown variant `edge`") && m.contains("edge-only"),
        "{m}"
    );
    let e = ProfileInput::from_json(
        &format!(r#"{{{c}, "crease_method": "normal"}}"#),
        Path::new("p"),
    );
    assert!(parse_error(e.unwrap_err()).contains("chaikin"));
    let e = ProfileInput::from_json(
        &format!(r#"{{{c}, "creasemethod": "chaikin"}}"#),
        Path::new("p"),
    );
    assert!(parse_error(e.unwrap_err()).contains("unknown field `creasemethod`"));

    let (_, r) = RevolveInput::from_json(
        r#"{"profile": [[1,0],[1,1]], "crease_sharpness": 2.5, "boundary": "edge-only",
            "crease_method": "chaikin"}"#,
        Path::new("r.json"),
    )
    .unwrap();
    assert_eq!(
        (r.crease_sharpness, r.boundary, r.crease_method),
        (2.5, BoundaryInterpolation::EdgeOnly, CreaseMethod::Chaikin)
    );
    let (_, r) = RevolveInput::from_json(r#"{"profile": [[1,0],[1,1]]}"#, Path::new("r")).unwrap();
    assert_eq!(r.crease_sharpness, SHARPNESS_INFINITE);
    let (_, s) = SweepInput::from_json(
        r#"{"profile": [[0,0],[1,0]], "trajectory": [[0,0,0],[0,0,1]],
            "crease_sharpness": "infinite", "boundary": "none"}"#,
        Path::new("s.json"),
    )
    .unwrap();
    assert_eq!(s.crease_sharpness, SHARPNESS_INFINITE);
    assert_eq!(s.boundary, BoundaryInterpolation::None);
    let e = SweepInput::from_json(
        r#"{"profile": [[0,0],[1,0]], "trajectory": [[0,0,0],[0,0,1]], "crease_sharpness": "big"}"#,
        Path::new("s"),
    );
    assert!(parse_error(e.unwrap_err()).contains("\"infinite\" or a number"));
    let bad = RevolveInput::new(vec![[1.0, 0.0], [1.0, 1.0]]);
    let negative = Settings {
        crease_sharpness: -1.0,
        ..Settings::default()
    };
    assert!(
        matches!(revolve::build(&bad, &negative), Err(Error::InvalidArgument(m)) if m.contains("crease_sharpness = -1"))
    );
    let bad = SweepInput::new(
        vec![[0.0, 0.0], [1.0, 0.0]],
        vec![[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
    );
    let nan = Settings {
        crease_sharpness: f32::NAN,
        ..Settings::default()
    };
    assert!(
        matches!(sweep::build(&bad, &nan), Err(Error::InvalidArgument(m)) if m.contains("crease_sharpness"))
    );
}

/// CLI flags override the JSON; a refused fit or a bad flag writes nothing.
#[test]
fn cli_flags_override_the_json_and_errors_write_nothing() {
    let dir = std::env::temp_dir().join(format!("profsubd_fit_options_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let json = write_input(
        &dir,
        "rail.json",
        r#"{"profile": [[-0.2,-0.2],[0.2,-0.2],[0.2,0.2],[-0.2,0.2]], "closed_profile": true,
            "trajectory": [[0,0,0],[2,0,0],[2,2,0]], "samples_profile": 8,
            "samples_trajectory": 8, "crease_sharpness": 3, "crease_method": "chaikin",
            "boundary": "edge-only"}"#,
    );
    let out = dir.join("rail.obj");
    let (j, o) = (json.to_str().unwrap(), out.to_str().unwrap());
    let run = profsubd(&["sweep", j, "-o", o]);
    assert!(run.status.success(), "{}", stderr(&run));
    let m = read_obj_file(&out).unwrap().mesh;
    assert_eq!(m.options().boundary, Some(BoundaryInterpolation::EdgeOnly));
    assert_eq!(m.options().crease_method, Some(CreaseMethod::Chaikin));
    assert!(m.creases().iter().all(|c| c.sharpness == 3.0));
    let run = profsubd(&[
        "sweep",
        j,
        "-o",
        o,
        "--boundary",
        "edge-and-corner",
        "--crease",
        "uniform",
        "--crease-sharpness",
        "1.25",
    ]);
    assert!(run.status.success());
    let m = read_obj_file(&out).unwrap().mesh;
    assert_eq!(
        m.options().boundary,
        Some(BoundaryInterpolation::EdgeAndCorner)
    );
    assert_eq!(m.options().crease_method, Some(CreaseMethod::Uniform));
    assert!(m.creases().iter().all(|c| c.sharpness == 1.25));
    std::fs::remove_file(&out).unwrap();

    let vase = example_file("profiles", "vase", "json");
    let run = profsubd(&[
        "profile",
        vase.to_str().unwrap(),
        "-o",
        o,
        "--boundary",
        "none",
    ]);
    assert_refused(
        &run,
        "boundary interpolation none",
        &[&out],
        "boundary none",
    );
    for bad in [
        ["--boundary", "edge"],
        ["--crease", "normal"],
        ["--crease-sharpness", "-2"],
    ] {
        let run = profsubd(&["profile", "-o", o, bad[0], bad[1]]);
        assert_refused(&run, bad[1], &[&out], &format!("{bad:?}"));
    }
    let run = profsubd(&[
        "profile",
        "-o",
        o,
        "--boundary",
        "edge-only",
        "--crease",
        "chaikin",
    ]);
    assert!(run.status.success());
    let m = read_obj_file(&out).unwrap().mesh;
    assert_eq!(m.options().boundary, Some(BoundaryInterpolation::EdgeOnly));
    assert_eq!(m.options().crease_method, Some(CreaseMethod::Chaikin));
    std::fs::remove_dir_all(&dir).unwrap();
}

struct Options(*mut profsubd_options);

impl Options {
    fn new() -> Options {
        let mut o = null_mut();
        assert_eq!(unsafe { profsubd_options_new(&mut o) }, PROFSUBD_OK);
        Options(o)
    }
}

impl Drop for Options {
    fn drop(&mut self) {
        unsafe { profsubd_options_free(self.0) }
    }
}

fn build_profile(curve: &[f64], options: &Options) -> (profsubd_status, *mut profsubd_fitted) {
    let mut curves: profsubd_profile_curves = unsafe { std::mem::zeroed() };
    curves.struct_size = std::mem::size_of::<profsubd_profile_curves>();
    curves.c1 = curve.as_ptr();
    curves.c1_points = curve.len() / 2;
    curves.c2 = curve.as_ptr();
    curves.c2_points = curve.len() / 2;
    let mut out = null_mut();
    let st = unsafe { profsubd_profile_build(&curves, options.0, &mut out) };
    (st, out)
}

/// The C API's options object carries the boundary rule and crease method to the profile
/// and revolve constructions; boundary none on an open model fails with no output.
#[test]
fn c_api_passes_the_options_to_the_fit() {
    let vase: Vec<f64> = vase().0.c1.iter().flatten().copied().collect();
    let o = Options::new();
    unsafe {
        assert_eq!(profsubd_options_set_boundary(o.0, 1), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_crease_method(o.0, 1), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_crease_sharpness(o.0, 2.0), PROFSUBD_OK);
        assert_eq!(
            profsubd_options_set_boundary(o.0, 3),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_crease_method(o.0, -1),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
    }
    let (st, p) = build_profile(&vase, &o);
    assert_eq!(st, PROFSUBD_OK);
    let mut mesh = null_mut();
    unsafe {
        assert_eq!(profsubd_fitted_get_mesh(p, &mut mesh), PROFSUBD_OK);
        profsubd_fitted_free(p);
        let path =
            std::env::temp_dir().join(format!("profsubd_fit_options_{}.obj", std::process::id()));
        let c_path = std::ffi::CString::new(path.to_str().unwrap()).unwrap();
        assert_eq!(profsubd_mesh_write_obj(mesh, c_path.as_ptr()), PROFSUBD_OK);
        profsubd_mesh_free(mesh);
        let m = read_obj_file(&path).unwrap().mesh;
        std::fs::remove_file(&path).unwrap();
        assert_eq!(m.options().boundary, Some(BoundaryInterpolation::EdgeOnly));
        assert_eq!(m.options().crease_method, Some(CreaseMethod::Chaikin));
        assert!(m.creases().iter().all(|c| c.sharpness == 2.0));
        assert_eq!(profsubd_options_set_boundary(o.0, 0), PROFSUBD_OK);
    }
    let (st, p) = build_profile(&vase, &o);
    assert_eq!(st, PROFSUBD_ERROR_INVALID_ARGUMENT);
    assert!(p.is_null());
    let profile = [1.0, 0.0, 1.2, 1.0];
    let mut s: *mut profsubd_fitted = null_mut();
    let st = unsafe { profsubd_revolve(profile.as_ptr(), 2, o.0, &mut s) };
    assert_eq!(st, PROFSUBD_ERROR_INVALID_ARGUMENT);
    assert!(s.is_null());
    unsafe {
        assert_eq!(profsubd_options_set_boundary(o.0, 1), PROFSUBD_OK);
        assert_eq!(
            profsubd_revolve(profile.as_ptr(), 2, o.0, &mut s),
            PROFSUBD_OK
        );
        profsubd_fitted_free(s);
    }
}
