//! The report's tonemapping-peers section: each of our operators against the engine or paper
//! operator it reproduces (three.js, Filament, bevy, and the authors' own code), under the
//! stated mapping, as the largest difference over the grid `tests/tonemap/against_peers.rs` asserts
//! on. The peers are f32 transcriptions of each source, named with repository, path and commit in
//! `tests/peers/tonemap.rs`; the cases and the grid are in `tests/peers/tonemap_cases.rs`.

#[path = "../../../tests/peers/tonemap_cases.rs"]
mod cases;
#[path = "../../../tests/peers/tonemap.rs"]
mod peers;

/// Prints the markdown table: one row per (our operator, peer operator, mapping), with the
/// largest |ours - peer| over the grid (both clamped to [0, 1]), ours in f32 and in f64 against
/// the peer in f32.
pub fn peers_table() {
    outln!("## Tonemapping against the engines and papers");
    outln!();
    outln!(
        "Grid: about 13,000 colours (greys from 0 to 1e4, dense near 0 and each operator's \
         knees; saturated colours with one or two channels 0; random colours up to 1e4). \
         Differences are after clamping both sides to [0, 1]. \"exact\" rows are held to f32 \
         rounding by `cargo test --test tonemap against_peers::`; the others document a mismatch."
    );
    outln!();
    outln!(
        "| ours | peer | mapping | exact | max diff, ours f32 | max diff, ours f64 | peer NaN |"
    );
    outln!("|---|---|---|---|---|---|---|");
    for c in cases::cases() {
        let s = cases::run(&c);
        outln!(
            "| {} | {} | {} | {} | {:.2e} | {:.2e} | {} |",
            c.ours,
            c.peer,
            c.mapping,
            if c.exact { "yes" } else { "no" },
            s.f32.max,
            s.f64.max,
            s.peer_nan
        );
    }
    let (rel, ev) = cases::bevy_exposure_max_rel();
    outln!();
    outln!(
        "bevy's camera exposure exp2(-EV100) / 1.2 against `Exposure::from_ev100`: max relative \
         difference {rel:.2e} (at EV100 {ev:.2}) over EV100 in [-20, 30]."
    );
    outln!();
}
