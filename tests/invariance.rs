//! Geometric invariance: the constructions and the evaluator commute with translation,
//! rotation and uniform scaling (1e-6 … 1e6) of their input, to 1e-12 of the result's
//! largest coordinate (control points and data points, vertex for vertex), for the
//! transformations each construction's input can express:
//! - sweep: any translation, rotation and scaling of the trajectory (the profile scaled too);
//! - revolve: translation along the axis and scaling (the axis is z and a partial turn
//!   starts at +x by definition, so nothing else is expressible);
//! - profile: any translation (the axis is the silhouettes' midpoint, so `c3`, `c4` are
//!   given explicitly), scaling, and the quarter turn about z (the silhouettes are the +x,
//!   +y, −x, −y views by definition, so a quarter turn is a relabelling of the four curves);
//! - sketch curves (`construct::curves`): any translation, rotation and scaling of every
//!   curve (a given projection normal rotated too);
//! - blends: any translation, rotation and scaling of the pipes (ends moved, axes turned,
//!   radii and lengths scaled);
//! - shells: any translation, rotation and scaling of the outer wall's control points, the
//!   thickness (and the crust tolerance) scaled with it;
//! - evaluator: any translation, rotation and scaling of the control points.
//!
//! And ill-conditioned fits (nearly coincident samples, a nearly degenerate profile) are
//! refused with a message, while the examples' condition estimates stay far below the bound.
//!
//! `cargo test --release --test invariance -- --nocapture` prints the worst figures.

use std::path::Path;

use glam::{DMat3, DVec3};
use profsubd::construct::blend::{self, BlendInput};
use profsubd::construct::curves::{self, Projection};
use profsubd::construct::settings::read_json;
use profsubd::construct::shell::{self, OffsetSettings, ShellInput};
use profsubd::io::obj::read_obj_file;
use profsubd::{
    profile, revolve, sweep, CurvesInput, Error, Evaluator, Fitted, Mesh, MeshParts, ProfileInput,
    RevolveInput, Settings, SweepInput,
};

const TOLERANCE: f64 = 1e-12;
const SCALES: [f64; 5] = [1e-6, 1e-3, 3.7, 1e3, 1e6];

/// Largest `|T(a_i) − b_i|` over the largest `|b_i|`.
fn relative(a: &[DVec3], b: &[DVec3], t: impl Fn(DVec3) -> DVec3) -> f64 {
    assert_eq!(a.len(), b.len());
    let size = b.iter().map(|p| p.abs().max_element()).fold(0.0, f64::max);
    let err = a
        .iter()
        .zip(b)
        .map(|(a, b)| (t(*a) - *b).length())
        .fold(0.0, f64::max);
    err / size
}

/// [`relative`] with `b` matched to `T(a)` by nearest point (for transformations that
/// renumber vertices), both ways.
fn relative_unordered(a: &[DVec3], b: &[DVec3], t: impl Fn(DVec3) -> DVec3) -> f64 {
    let ta: Vec<DVec3> = a.iter().map(|p| t(*p)).collect();
    let nearest = |p: &DVec3, set: &[DVec3]| {
        set.iter()
            .map(|q| (*p - *q).length())
            .fold(f64::INFINITY, f64::min)
    };
    let size = b.iter().map(|p| p.abs().max_element()).fold(0.0, f64::max);
    let one = ta.iter().map(|p| nearest(p, b)).fold(0.0, f64::max);
    let two = b.iter().map(|p| nearest(p, &ta)).fold(0.0, f64::max);
    one.max(two) / size
}

fn both(f: &Fitted) -> Vec<DVec3> {
    // Control points and targets: the fit and the sampling.
    f.mesh
        .positions()
        .iter()
        .chain(&f.targets)
        .copied()
        .collect()
}

fn report(what: &str, worst: f64) {
    println!("invariance {what}: worst {worst:.2e}");
    assert!(worst <= TOLERANCE, "{what}: {worst:e}");
}

fn rotation() -> DMat3 {
    DMat3::from_axis_angle(DVec3::new(0.3, -0.5, 0.8).normalize(), 0.7)
}

fn example(path: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(path)
}

/// `p ↦ scale · rotation · p + shift`.
#[derive(Debug, Clone, Copy)]
struct Similarity {
    scale: f64,
    rotation: DMat3,
    shift: DVec3,
}

impl Similarity {
    fn apply(&self, p: DVec3) -> DVec3 {
        self.rotation * p * self.scale + self.shift
    }
    fn apply3(&self, p: [f64; 3]) -> [f64; 3] {
        self.apply(DVec3::from(p)).into()
    }
}

/// A translation (by a vector of the models' size, not a power of two), the rotation and
/// the scalings: `(kind, transformation)`, kind 0, 1, 2.
fn similarities() -> Vec<(usize, Similarity)> {
    let identity = Similarity {
        scale: 1.0,
        rotation: DMat3::IDENTITY,
        shift: DVec3::ZERO,
    };
    let mut v = vec![
        (
            0,
            Similarity {
                shift: DVec3::new(0.7, -1.3, 2.9),
                ..identity
            },
        ),
        (
            1,
            Similarity {
                rotation: rotation(),
                ..identity
            },
        ),
    ];
    v.extend(SCALES.map(|scale| (2, Similarity { scale, ..identity })));
    v
}

/// The worst relative difference per kind (translation, rotation, scaling) of `build` on
/// the transformed input against the transformed `base`.
fn worst_by_kind(base: &Fitted, build: impl Fn(&Similarity) -> Result<Fitted, Error>) -> [f64; 3] {
    let mut worst = [0.0f64; 3];
    for (kind, t) in similarities() {
        let moved = build(&t).unwrap();
        worst[kind] = worst[kind].max(relative(&both(base), &both(&moved), |p| t.apply(p)));
    }
    worst
}

fn report_kinds(what: &str, worst: [f64; 3]) {
    report(&format!("{what} translation"), worst[0]);
    report(&format!("{what} rotation"), worst[1]);
    report(&format!("{what} scaling 1e-6..1e6"), worst[2]);
}

#[test]
fn sweeps_commute_with_translation_rotation_and_scaling() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/sweeps");
    let mut worst = [0.0f64; 3];
    let mut cases: Vec<(SweepInput, Settings)> = ["handrail", "torus_knot_tube"]
        .iter()
        .map(|name| read_json(&examples.join(format!("{name}.json"))).unwrap())
        .collect();
    // A polyline (every point a corner, no curvature) under the fixed frame: its sections
    // are oriented by the first corner's turn; found by this test (#17 item 7), 4.1e-4 of
    // its size under rotation before (a world axis).
    let mut polyline = cases[0].clone();
    polyline.0.trajectory = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.3, 0.1],
        [2.0, 0.2, 0.5],
        [3.0, -0.1, 0.4],
    ];
    polyline.0.frame = serde_json::from_str("\"fixed\"").unwrap();
    cases.push(polyline);
    for (input, settings) in cases {
        let base = sweep::build(&input, &settings).unwrap();
        let with = |f: &dyn Fn([f64; 3]) -> [f64; 3], s: f64| {
            let mut i = input.clone();
            i.trajectory = i.trajectory.iter().map(|p| f(*p)).collect();
            i.profile = i.profile.iter().map(|p| [p[0] * s, p[1] * s]).collect();
            if let Some(end) = &mut i.profile_end {
                *end = end.iter().map(|p| [p[0] * s, p[1] * s]).collect();
            }
            sweep::build(&i, &settings).unwrap()
        };
        let shift = DVec3::new(12.5, -7.25, 3.0);
        let moved = with(&|p| (DVec3::from(p) + shift).into(), 1.0);
        worst[0] = worst[0].max(relative(&both(&base), &both(&moved), |p| p + shift));
        let r = rotation();
        let turned = with(&|p| (r * DVec3::from(p)).into(), 1.0);
        worst[1] = worst[1].max(relative(&both(&base), &both(&turned), |p| r * p));
        for s in SCALES {
            let scaled = with(&|p| (DVec3::from(p) * s).into(), s);
            worst[2] = worst[2].max(relative(&both(&base), &both(&scaled), |p| p * s));
        }
    }
    report("sweep translation", worst[0]);
    report("sweep rotation", worst[1]);
    report("sweep scaling 1e-6..1e6", worst[2]);
}

/// The worst relative difference of revolutions (full and partial turns, open and flat
/// caps) under axial translation, and under scaling.
fn revolve_figures() -> (f64, f64) {
    let profile = vec![[1.0, 0.0], [1.4, 0.8], [1.3, 2.0], [0.9, 3.0]];
    let (mut t_worst, mut s_worst) = (0.0f64, 0.0f64);
    for (angle, caps) in [(360.0, profsubd::Caps::Open), (270.0, profsubd::Caps::Flat)] {
        let mut vase = RevolveInput::new(profile.clone());
        vase.angle_deg = angle;
        let settings = Settings {
            caps,
            ..Settings::default()
        };
        let base = revolve::build(&vase, &settings).unwrap();
        let with = |f: &dyn Fn([f64; 2]) -> [f64; 2]| {
            let mut i = vase.clone();
            i.profile = i.profile.iter().map(|p| f(*p)).collect();
            revolve::build(&i, &settings).unwrap()
        };
        let moved = with(&|p| [p[0], p[1] + 4.5]);
        t_worst = t_worst.max(relative(&both(&base), &both(&moved), |p| {
            p + DVec3::Z * 4.5
        }));
        for s in SCALES {
            let scaled = with(&|p| [p[0] * s, p[1] * s]);
            s_worst = s_worst.max(relative(&both(&base), &both(&scaled), |p| p * s));
        }
    }
    (t_worst, s_worst)
}

#[test]
fn revolutions_commute_with_scaling() {
    report("revolve scaling 1e-6..1e6", revolve_figures().1);
}

#[test]
fn revolutions_commute_with_axial_translation() {
    report("revolve axial translation", revolve_figures().0);
}

#[test]
fn profiles_commute_with_translation_scaling_and_the_quarter_turn() {
    let (bottle, settings) = profile::default_model();
    let base = profile::build(&bottle, &settings).unwrap();
    let neg = |c: &[[f64; 2]]| -> Vec<[f64; 2]> { c.iter().map(|p| [-p[0], p[1]]).collect() };
    let c3 = bottle.c3.clone().unwrap_or_else(|| neg(&bottle.c1));
    let c4 = bottle.c4.clone().unwrap_or_else(|| neg(&bottle.c2));
    // `c3`, `c4` given explicitly: a translation across the axis moves the mirror axis.
    let with = |shift: DVec3, s: f64| {
        let map = |c: &[[f64; 2]], w: f64| {
            c.iter()
                .map(|p| [p[0] * s + w, p[1] * s + shift.z])
                .collect()
        };
        let i = ProfileInput {
            c1: map(&bottle.c1, shift.x),
            c2: map(&bottle.c2, shift.y),
            c3: Some(map(&c3, shift.x)),
            c4: Some(map(&c4, shift.y)),
            ..bottle.clone()
        };
        profile::build(&i, &settings).unwrap()
    };
    let mut t = 0.0f64;
    for shift in [DVec3::new(0.0, 0.0, -2.25), DVec3::new(0.7, -1.3, 2.9)] {
        let moved = with(shift, 1.0);
        t = t.max(relative(&both(&base), &both(&moved), |p| p + shift));
    }
    let mut s_worst = 0.0f64;
    for s in SCALES {
        let scaled = with(DVec3::ZERO, s);
        let e = relative(&both(&base), &both(&scaled), |p| p * s);
        println!("invariance profile scaling by {s:e}: {e:.2e}");
        s_worst = s_worst.max(e);
    }
    // A quarter turn about z, (x, y) -> (-y, x): the +x view becomes the old -y one seen
    // from +x, and so on round.
    let turned_input = ProfileInput {
        c1: neg(&c4),
        c2: bottle.c1.clone(),
        c3: Some(neg(&bottle.c2)),
        c4: Some(c3),
        ..bottle.clone()
    };
    let turned = profile::build(&turned_input, &settings).unwrap();
    let q = relative_unordered(&both(&base), &both(&turned), |p| DVec3::new(-p.y, p.x, p.z));
    report("profile quarter turn", q);
    // Found by this test (#17 item 7) and fixed: a straight stretch's rounding noise was
    // weighted as curvature (equidistribute::MIN_TURNING), and a height search ending a
    // rounding error short of a knot made a rising segment count as not rising (param.rs
    // probes): 1.5e-2 and 3.5e-2 of the model's size before.
    report("profile translation", t);
    report("profile scaling 1e-6..1e6", s_worst);
}

#[test]
fn sketch_curves_commute_with_translation_rotation_and_scaling() {
    let mut worst = [0.0f64; 3];
    // Interior curves and the best-fit plane; a given projection normal; three sides.
    for name in ["bonnet", "open_corners", "three_sided"] {
        let (input, settings): (CurvesInput, Settings) =
            read_json(&example(&format!("curves/{name}.json"))).unwrap();
        let base = curves::build(&input, &settings).unwrap();
        let w = worst_by_kind(&base, |t| {
            let map = |c: &Vec<Vec<[f64; 3]>>| -> Vec<Vec<[f64; 3]>> {
                c.iter()
                    .map(|c| c.iter().map(|p| t.apply3(*p)).collect())
                    .collect()
            };
            let mut i = input.clone();
            i.boundary = map(&input.boundary);
            i.interior = map(&input.interior);
            if let Projection::Normal(n) = input.projection {
                i.projection = Projection::Normal((t.rotation * DVec3::from(n)).into());
            }
            curves::build(&i, &settings)
        });
        worst = [0, 1, 2].map(|k| worst[k].max(w[k]));
    }
    report_kinds("sketch curves", worst);
}

#[test]
fn blends_commute_with_translation_rotation_and_scaling() {
    let mut worst = [0.0f64; 3];
    // The four-way blend's axes are pairwise perpendicular: equally good hub normals, one
    // of which rounding used to pick, and a world-dependent first pipe; found by this test
    // (#17 item 7), 1.55 of the model's size (renumbered vertices) before.
    for name in ["tee", "four_way", "six_way"] {
        let (input, settings): (BlendInput, Settings) =
            read_json(&example(&format!("blends/{name}.json"))).unwrap();
        let base = blend::build(&input, &settings).unwrap();
        let w = worst_by_kind(&base, |t| {
            let mut i = input.clone();
            for p in &mut i.pipes {
                p.end = t.apply(p.end);
                p.axis = t.rotation * p.axis;
                p.radius *= t.scale;
                p.length *= t.scale;
            }
            blend::build(&i, &settings)
        });
        worst = [0, 1, 2].map(|k| worst[k].max(w[k]));
    }
    report_kinds("blend", worst);
}

#[test]
fn shells_commute_with_translation_rotation_and_scaling() {
    let mesh = read_obj_file(&example("profiles/vase.obj")).unwrap().mesh;
    let c = 0.01 * mesh.bounding_box_diagonal();
    let mut worst = [0.0f64; 3];
    // At the given crust level, and at the level a tolerance (scaled too) chooses.
    for tolerance in [None, Some(0.05 * c)] {
        let input = ShellInput {
            mesh: mesh.clone(),
            offset: OffsetSettings::new(c),
            tolerance,
        };
        let base = shell::build(&input, &Settings::default()).unwrap();
        let w = worst_by_kind(&base, |t| {
            let moved = Mesh::from_parts(MeshParts {
                positions: mesh.positions().iter().map(|p| t.apply(*p)).collect(),
                ..mesh.parts().clone()
            })
            .unwrap();
            let i = ShellInput {
                mesh: moved,
                offset: OffsetSettings::new(c * t.scale),
                tolerance: tolerance.map(|x| x * t.scale),
            };
            shell::build(&i, &Settings::default())
        });
        worst = [0, 1, 2].map(|k| worst[k].max(w[k]));
    }
    report_kinds("shell", worst);
}

#[test]
fn the_evaluator_commutes_with_translation_rotation_and_scaling() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/profiles/mouse.obj");
    let mesh = read_obj_file(&path).unwrap().mesh;
    let options = mesh.options().resolve();
    let points: Vec<(u32, f64, f64)> = (0..mesh.num_faces() as u32)
        .flat_map(|f| [(f, 0.0, 0.0), (f, 0.25, 0.5), (f, 0.9, 0.1), (f, 1.0, 1.0)])
        .collect();
    let eval = |positions: Vec<DVec3>| -> (Vec<DVec3>, Vec<DVec3>) {
        let moved = Mesh::from_parts(MeshParts {
            positions,
            ..mesh.parts().clone()
        })
        .unwrap();
        let ev = Evaluator::new(&moved, &options).unwrap();
        let s: Vec<_> = points
            .iter()
            .map(|&(f, u, v)| ev.evaluate(f, u, v).unwrap())
            .collect();
        (
            s.iter().map(|s| s.position).collect(),
            s.iter().map(|s| s.du).collect(),
        )
    };
    let (p0, d0) = eval(mesh.positions().to_vec());
    let mut worst = [0.0f64; 3];
    let shift = DVec3::new(-3.5, 100.25, 7.0);
    let (p, _) = eval(mesh.positions().iter().map(|p| *p + shift).collect());
    worst[0] = relative(&p0, &p, |p| p + shift);
    let r = rotation();
    let (p, d) = eval(mesh.positions().iter().map(|p| r * *p).collect());
    worst[1] = relative(&p0, &p, |p| r * p).max(relative(&d0, &d, |d| r * d));
    for s in SCALES {
        let (p, d) = eval(mesh.positions().iter().map(|p| *p * s).collect());
        worst[2] = worst[2]
            .max(relative(&p0, &p, |p| p * s))
            .max(relative(&d0, &d, |d| d * s));
    }
    report("evaluator translation", worst[0]);
    report("evaluator rotation", worst[1]);
    report("evaluator scaling 1e-6..1e6", worst[2]);
}

#[test]
fn ill_conditioned_fits_are_refused_and_the_estimate_is_reported() {
    let refused = |r: Result<Fitted, Error>| match r {
        Err(Error::NumericalFailure(m)) => {
            assert!(m.contains("ill-conditioned fit"), "{m}");
            m
        }
        other => panic!("{:?}", other.map(|f| f.fit)),
    };
    // Two profile points 1e-10 apart: rings 1e-10 apart.
    let mut close = RevolveInput::new(vec![[1.0, 0.0], [1.0, 1e-10], [1.2, 1.0], [1.0, 2.0]]);
    close.corners = vec![1];
    let m = refused(revolve::build(&close, &Settings::default()));
    println!("coincident: {m}");
    // A nearly degenerate profile: a tube of radius 1e-9 and length 1.
    let thin = RevolveInput::new(vec![[1e-9, 0.0], [1e-9, 1.0]]);
    let m = refused(revolve::build(&thin, &Settings::default()));
    println!("degenerate: {m}");
    // A thin but honest tube (radius 1e-3) is accepted, and the estimate is reported.
    let tube = revolve::build(
        &RevolveInput::new(vec![[1e-3, 0.0], [1e-3, 1.0]]),
        &Settings::default(),
    )
    .unwrap();
    assert!(tube.fit.condition > 1.0 && tube.fit.condition < profsubd::MAX_FIT_CONDITION);
    // The examples: far below the bound.
    let (bottle, settings) = profile::default_model();
    let c = profile::build(&bottle, &settings).unwrap().fit.condition;
    println!(
        "condition: thin tube {:.3e}, bottle {c:.3e}",
        tube.fit.condition
    );
    assert!((1.0..1e4).contains(&c), "{c}");
}
