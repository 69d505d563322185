//! The bench model shared by the benches: the bundled bottle example (extraordinary vertices
//! of valence 3 at its pole caps, a crease ring at its shoulder, a flat-capped base) at a
//! chosen sampling.

use std::path::Path;

use profsubd::construct::settings::read_json;
use profsubd::profile::{build, ProfileInput};
use profsubd::Fitted;

/// The bottle of `examples/profiles/bottle.json` sampled `around × along`.
pub fn bottle(around: u32, along: u32) -> Fitted {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/profiles/bottle.json");
    let (mut input, settings) = read_json::<ProfileInput>(&path).expect("bottle input");
    input.around = around;
    input.along = along;
    build(&input, &settings).expect("bottle model")
}
