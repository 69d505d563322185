//! Every construction on arbitrary JSON: the first byte picks profile, revolve or sweep, the
//! rest is the JSON input (construction keys and settings keys, as the command line reads
//! it). Sample counts are capped at 48 × 48 so that one input stays fast. Any panic is a
//! finding, and so is a result that breaks the contract: a fit residual above its
//! tolerance, a non-finite control point, a target count that is not the vertex count, a
//! condition estimate above the refused bound. Seeds: `fuzz/corpus/construction/` (the
//! examples' JSON, prefixed with their kind byte).
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;
use profsubd::{profile, revolve, sweep, Fitted, ProfileInput, RevolveInput, SweepInput};

/// Largest sample interval count per direction the target builds.
const CAP: u32 = 48;

fn check(result: profsubd::Result<Fitted>) {
    let Ok(f) = result else { return };
    assert_eq!(f.targets.len(), f.mesh.num_vertices(), "one target per vertex");
    assert!(
        f.fit.residual <= f.fit.tolerance,
        "residual {} above tolerance {}",
        f.fit.residual,
        f.fit.tolerance
    );
    assert!(f.mesh.positions().iter().all(|p| p.is_finite()), "non-finite control point");
    assert!(f.fit.condition <= profsubd::MAX_FIT_CONDITION, "condition {}", f.fit.condition);
}

fuzz_target!(|data: &[u8]| {
    let Some((&kind, rest)) = data.split_first() else { return };
    let Ok(text) = std::str::from_utf8(rest) else { return };
    let path = Path::new("fuzz.json");
    match kind % 3 {
        0 => {
            if let Ok((mut i, s)) = ProfileInput::from_json(text, path) {
                (i.along, i.around) = (i.along.min(CAP), i.around.min(CAP));
                check(profile::build(&i, &s));
            }
        }
        1 => {
            if let Ok((mut i, s)) = RevolveInput::from_json(text, path) {
                i.samples_profile = i.samples_profile.min(CAP as usize);
                i.samples_around = i.samples_around.min(CAP as usize);
                check(revolve::build(&i, &s));
            }
        }
        _ => {
            if let Ok((mut i, s)) = SweepInput::from_json(text, path) {
                i.samples_profile = i.samples_profile.min(CAP as usize);
                i.samples_trajectory = i.samples_trajectory.min(CAP as usize);
                check(sweep::build(&i, &s));
            }
        }
    }
});
