//! Filament's DFG layout: `dfg::table_filament` holds the B and E of `dfg::table` bit for bit,
//! and `dfg::specular_filament` (mix(x, y, F0)) equals `dfg::specular` with F90 = 1 on them,
//! to the rounding of the two forms; both keep the crate's rules at the edges.
#![cfg(feature = "ibl")]

use brdf::V3;
use brdf::ibl::dfg;
use brdf::wide::f32x8;

const N_NOV: usize = 8;
const N_R: usize = 6;
const SAMPLES: u32 = 256;

#[test]
fn filament_table_holds_b_and_e_of_the_table() {
    let mut abe = vec![[0.0f32; 3]; N_NOV * N_R];
    let mut be = vec![[0.0f32; 2]; N_NOV * N_R];
    dfg::table(&mut abe, N_NOV, N_R, SAMPLES).expect("valid dimensions");
    dfg::table_filament(&mut be, N_NOV, N_R, SAMPLES).expect("valid dimensions");
    for (full, two) in abe.iter().zip(&be) {
        assert_eq!([full[1], full[2]], *two);
    }
    // Its errors are the table's.
    assert!(dfg::table_filament(&mut be, N_NOV + 1, N_R, SAMPLES).is_err());
    assert!(dfg::table_filament(&mut be, N_NOV, N_R, 0).is_err());
    assert!(dfg::table_filament(&mut be, 0, N_R, SAMPLES).is_err());
}

#[test]
fn filament_mix_equals_the_split_sum_with_f90_one() {
    let mut abe = vec![[0.0f32; 3]; N_NOV * N_R];
    dfg::table(&mut abe, N_NOV, N_R, SAMPLES).expect("valid dimensions");
    let light = V3::new(0.7f32, 1.3, 2.9);
    let mut worst = 0.0f64;
    for [a, b, e] in &abe {
        for f0 in [0.0f32, 0.02, 0.04, 0.3, 0.77, 0.95, 1.0] {
            let f0v = V3::new(f0, f0 * 0.5, 1.0 - f0);
            let ours = dfg::specular_filament(light, f0v, *b, *e);
            let split = dfg::specular(light, f0v, 1.0, *a, *b);
            for (x, y) in [(ours.x, split.x), (ours.y, split.y), (ours.z, split.z)] {
                // x + F0 (y - x) against F0 A + B: E = A + B holds to the f32 rounding of the
                // three table entries, so the two differ by a few roundings of values <= 3.
                let d = (f64::from(x) - f64::from(y)).abs();
                worst = worst.max(d);
                assert!(d <= 4.0 * 3.0 * f64::from(f32::EPSILON), "{x} vs {y}");
            }
        }
    }
    println!("specular_filament against specular(F90 = 1): max abs difference {worst:.2e}");
    // The f32x8 lanes equal the scalar results bit for bit.
    let (b, e) = (abe[5][1], abe[5][2]);
    let f0s = [0.0f32, 0.1, 0.2, 0.4, 0.6, 0.8, 0.9, 1.0];
    let lanes = dfg::specular_filament(
        V3::new(f32x8::splat(1.5), f32x8::splat(0.5), f32x8::splat(2.0)),
        V3::new(f32x8::from(f0s), f32x8::from(f0s), f32x8::from(f0s)),
        f32x8::splat(b),
        f32x8::splat(e),
    );
    let xs = lanes.x.to_array();
    for (i, f0) in f0s.iter().enumerate() {
        let s = dfg::specular_filament(V3::new(1.5f32, 0.5, 2.0), V3::new(*f0, *f0, *f0), b, e);
        assert_eq!(xs[i].to_bits(), s.x.to_bits());
    }
}

#[test]
fn filament_mix_keeps_the_rules_at_the_edges() {
    let m = f32::MAX;
    // Finite in, finite out: channels near MAX are capped.
    let out = dfg::specular_filament(V3::new(m, m, m), V3::new(0.0, 0.5, 1.0), -m, m);
    for v in [out.x, out.y, out.z] {
        assert!(v.is_finite(), "{v}");
    }
    // A zero radiance stays 0 where the mix overflows.
    let out = dfg::specular_filament(V3::new(0.0f32, 0.0, 0.0), V3::new(1.0, 1.0, 1.0), m, m);
    assert_eq!([out.x, out.y, out.z], [0.0; 3]);
    // NaN and infinite channels, f0 outside [0, 1], a negative radiance: NaN where stated.
    let ok = V3::new(1.0f64, 1.0, 1.0);
    let f0 = V3::new(0.04, 0.5, 0.9);
    for (x, y) in [
        (f64::NAN, 1.0),
        (0.1, f64::NAN),
        (f64::INFINITY, 1.0),
        (0.1, -f64::INFINITY),
    ] {
        let out = dfg::specular_filament(ok, f0, x, y);
        assert!(out.x.is_nan() && out.y.is_nan() && out.z.is_nan());
    }
    let out = dfg::specular_filament(ok, V3::new(1.5, 0.5, -0.1), 0.1, 0.9);
    assert!(out.x.is_nan() && out.y.is_finite() && out.z.is_nan());
    let out = dfg::specular_filament(V3::new(-1.0, f64::INFINITY, 2.0), f0, 0.1, 0.9);
    assert!(out.x.is_nan() && out.y.is_nan() && out.z.is_finite());
}
