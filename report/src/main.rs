//! The main job: `cargo run --release -p brdf-report [-- --quick] [-- --out DIR]` (the library
//! holds it, see its docs).

fn main() -> Result<(), Box<dyn std::error::Error>> {
    brdf_report::run()
}
