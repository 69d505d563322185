//! Valid surfaces (issue #10): the fitted limit surfaces of the examples and of generated
//! spheres, ellipsoids, flat-based bottles and flat-footed goblets do not fold (the library's
//! fold check, `eval::folds`), stay close to their design surfaces between the data points
//! and are about as fair as them (`construct::design`).
// Reference geometry for tolerance checks: the platform's libm is fine here.
#![allow(clippy::disallowed_methods)]

#[path = "support/random_profile.rs"]
mod random_profile;

use std::f64::consts::PI;
use std::path::PathBuf;

use profsubd::cli::profile::read_input;
use profsubd::construct::design::SurfaceReport;
use profsubd::construct::profile::{build, shapes::ellipsoid, ProfileInput};
use profsubd::construct::sweep::revolve::RevolveInput;
use profsubd::construct::sweep::sweep::SweepInput;
use profsubd::construct::sweep::{revolve, sweep};
use random_profile::RandomProfiles;

/// Samplings from 16 × 8 to 128 × 64 (around × along).
const SAMPLINGS: [(usize, usize); 4] = [(16, 8), (32, 16), (64, 32), (128, 64)];

fn example(dir: &str, name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("examples/{dir}/{name}.json"))
}

fn assert_valid(name: &str, r: &SurfaceReport, max_distance: f64) {
    println!(
        "{name}: folded {} (worst reversal {:.1}°), design distance max {:.2e} mean {:.2e}, \
         undulation {:.3}",
        r.folded_faces,
        r.worst_reversal_deg,
        r.max_design_distance,
        r.mean_design_distance,
        r.undulation
    );
    assert_eq!(r.folded_faces, 0, "{name}: {r:?}");
    assert!(r.worst_reversal_deg < 90.0, "{name}: {r:?}");
    assert!(r.max_design_distance < max_distance, "{name}: {r:?}");
    assert!(r.mean_design_distance < 0.1 * max_distance, "{name}: {r:?}");
}

#[test]
fn examples_do_not_fold_and_follow_their_design() {
    for name in ["bottle", "vase", "mouse", "spinning_top"] {
        let model = build(&read_input(Some(&example("profiles", name))).unwrap()).unwrap();
        let r = model.surface_report().unwrap();
        assert_valid(name, r, 3e-3);
        assert!((0.9..1.1).contains(&r.undulation), "{name}: {r:?}");
    }
    let path = example("sweeps", "wine_glass");
    let text = std::fs::read_to_string(&path).unwrap();
    let glass = revolve(&RevolveInput::from_json(&text, &path).unwrap()).unwrap();
    let r = glass.surface_report().unwrap();
    assert_valid("wine_glass", r, 1e-3);
    assert!((0.9..1.1).contains(&r.undulation), "{r:?}");
    for name in ["handrail", "torus_knot_tube"] {
        let path = example("sweeps", name);
        let text = std::fs::read_to_string(&path).unwrap();
        let s = sweep(&SweepInput::from_json(&text, &path).unwrap()).unwrap();
        assert_valid(name, s.surface_report().unwrap(), 5e-3);
    }
}

#[test]
fn ellipsoids_of_several_aspect_ratios_do_not_fold() {
    for (a, b, c) in [
        (1.0, 1.0, 1.0),
        (2.0, 1.0, 1.5),
        (3.0, 2.0, 0.75),
        (1.0, 1.0, 5.0),
    ] {
        let mut previous = f64::INFINITY;
        for (around, along) in SAMPLINGS {
            let mut input = ellipsoid(a, b, c, 400);
            input.around = around as u32;
            input.along = along as u32;
            let model = build(&input).unwrap();
            let r = model.surface_report().unwrap();
            assert_valid(
                &format!("ellipsoid ({a}, {b}, {c}) {around}x{along}"),
                r,
                5e-3,
            );
            if around == 32 {
                assert!(r.max_design_distance < 1e-3, "{r:?}");
            }
            assert!(r.max_design_distance < previous, "{r:?}");
            previous = r.max_design_distance;
        }
    }
}

#[test]
fn spheres_and_goblets_by_revolution_do_not_fold() {
    let semicircle: Vec<[f64; 2]> = (0..=48)
        .map(|i| {
            let t = -PI / 2.0 + PI * i as f64 / 48.0;
            [if i == 0 || i == 48 { 0.0 } else { t.cos() }, t.sin()]
        })
        .collect();
    // A goblet with a wide flat foot (a smooth pole at its centre), a thin stem and a bowl.
    let goblet = vec![
        [0.0, 0.0],
        [3.0, 0.0],
        [3.05, 0.08],
        [0.4, 0.25],
        [0.12, 0.6],
        [0.1, 2.5],
        [0.3, 3.2],
        [1.4, 3.8],
        [2.0, 5.0],
        [2.1, 6.0],
        [0.0, 5.9],
    ];
    for (name, profile) in [("sphere", semicircle), ("goblet", goblet)] {
        for (around, along) in SAMPLINGS {
            let mut input = RevolveInput::new(profile.clone());
            input.samples_around = around;
            input.samples_profile = along * if name == "goblet" { 2 } else { 1 };
            let s = revolve(&input).unwrap();
            let r = s.surface_report().unwrap();
            assert_valid(&format!("{name} {around}x{along}"), r, 5e-3);
        }
    }
}

#[test]
fn bottles_with_flat_bases_do_not_fold() {
    let input = read_input(Some(&example("profiles", "bottle"))).unwrap();
    for (around, along) in SAMPLINGS {
        let mut bottle: ProfileInput = input.clone();
        bottle.around = around as u32;
        bottle.along = along as u32 + 8;
        let model = build(&bottle).unwrap();
        assert_valid(
            &format!("bottle {around}x{}", along + 8),
            model.surface_report().unwrap(),
            5e-3,
        );
    }
}

#[test]
fn random_full_turn_revolutions_do_not_fold() {
    // The generator of `sweep_wedge`'s random-profile test, full turns only, fitted: every
    // profile that is accepted gives a limit surface without folds.
    let mut random = RandomProfiles::new();
    let mut built = 0;
    for _ in 0..60 {
        let pts = random.profile();
        let mut input = RevolveInput::new(pts);
        if random.next() < 0.5 {
            input.caps = profsubd::construct::profile::Caps::Flat;
        }
        input.samples_around = 4 * (2 + (random.next() * 6.0) as usize);
        input.samples_profile = 4 + (random.next() * 28.0) as usize;
        let Ok(s) = revolve(&input) else { continue };
        let r = s.surface_report().unwrap();
        assert_eq!(r.folded_faces, 0, "{input:?}: {r:?}");
        built += 1;
    }
    assert!(built > 30, "{built}");
}

#[test]
fn partial_vase_revolutions_with_flat_caps_do_not_fold() {
    // Flat ends (sectors), two flat meridian caps and a neck: a crease ring where the
    // profile turns towards the axis, whose meridian-cap corner spans a reflex angle.
    let path = example("sweeps", "vase_cutaway");
    let text = std::fs::read_to_string(&path).unwrap();
    let input = RevolveInput::from_json(&text, &path).unwrap();
    let r = revolve(&input).unwrap().surface_report().unwrap().clone();
    println!(
        "vase_cutaway: folded {}, design distance max {:.2e} mean {:.2e}",
        r.folded_faces, r.max_design_distance, r.mean_design_distance
    );
    assert_eq!(r.folded_faces, 0, "{r:?}");
    for angle in [90.0, 180.0, 270.0] {
        for (around, along) in [(16, 16), (32, 32)] {
            let mut vase = input.clone();
            (vase.angle_deg, vase.samples_around, vase.samples_profile) = (angle, around, along);
            let r = revolve(&vase).unwrap().surface_report().unwrap().clone();
            println!("vase {angle}° {around}x{along}: folded {}", r.folded_faces);
            assert_eq!(r.folded_faces, 0, "{angle} {around}x{along}: {r:?}");
            assert!(r.worst_reversal_deg < 90.0, "{r:?}");
        }
    }
}

#[test]
fn wine_glass_cutaway_folds_less() {
    // Not yet fold-free: the first face of each pole sector half at the two apexes (4) folds,
    // where the apex's 270° span between its two creases cannot be filled by the corner rule
    // (a flat sector's bisector is creased to the arc; a pole's has no crease to end at).
    // 244 before the pole sectors were deepened, the meridian caps' layout chosen by shape
    // and their reflex corners split.
    let path = example("sweeps", "wine_glass_cutaway");
    let text = std::fs::read_to_string(&path).unwrap();
    let s = revolve(&RevolveInput::from_json(&text, &path).unwrap()).unwrap();
    let r = s.surface_report().unwrap();
    println!(
        "wine_glass_cutaway: folded {}, design distance max {:.2e} mean {:.2e}",
        r.folded_faces, r.max_design_distance, r.mean_design_distance
    );
    assert!(r.folded_faces <= 4, "{r:?}");
}
