//! The f32x8 lane exp (`Real::exp`) is `wide::f32x8::exp`'s algorithm without its
//! data-dependent branches: bit-identical to it on every f32 input. Checked here on every
//! 127th bit pattern (33.8 million values, both signs, NaN, infinities, subnormals), with
//! lanes mixing ordinary and far-negative arguments as a Beckmann D's tail does (the case
//! the branches were slow on). `cargo test --test lane_exp -- --nocapture` prints the count.

use brdf::Real;
use brdf::wide::f32x8;

fn same(a: f32, b: f32) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

#[test]
fn lane_exp_is_bit_identical_to_wides_on_every_127th_bit_pattern() {
    let mut checked = 0u64;
    let mut bits: u64 = 0;
    while bits <= u64::from(u32::MAX) {
        // Eight patterns per vector, the last lane a far-negative argument so that vectors
        // mix a subnormal or zero result with the others.
        let mut lanes = [0.0f32; 8];
        for (l, v) in lanes.iter_mut().enumerate().take(7) {
            *v = f32::from_bits(((bits + 127 * l as u64) & 0xFFFF_FFFF) as u32);
        }
        lanes[7] = -95.0 - (bits % 13) as f32;
        let x = f32x8::new(lanes);
        let ours = Real::exp(x).to_array();
        let theirs = x.exp().to_array();
        for l in 0..8 {
            assert!(
                same(ours[l], theirs[l]),
                "exp({:e}) = {:e}, wide {:e}",
                lanes[l],
                ours[l],
                theirs[l]
            );
        }
        checked += 8;
        bits += 127 * 7;
    }
    println!("{checked} values checked");
    assert!(checked > 30_000_000);
}
