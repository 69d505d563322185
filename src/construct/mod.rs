//! (module under construction)

pub mod sweep;
