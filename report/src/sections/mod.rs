//! The report's sections on the crate's checks (carried over from the first report).

pub mod checks;
pub mod gpu;
pub mod ibl;
pub mod layers;
pub mod lobes;
pub mod tonemap;
pub mod transmission;
