//! TEMP
use super::patch_topology::Neighbourhood;
use super::sample::LimitSample;
use crate::error::Result;
use crate::options::SubdivOptions;
pub fn corner_limit(_nb: &Neighbourhood, _k: usize, _o: &SubdivOptions, _scale: f64) -> Result<Option<LimitSample>> { Ok(None) }
