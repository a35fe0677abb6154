//! The sheen albedo: the built-in table against the crate's integrators, and the published
//! fits against the same integrators for the lobe they fit (D_charlie with V_neubelt). The
//! measured errors printed here are the ones the docs quote.
#![cfg(feature = "sheen")]

use brdf::layers::sheen::{
    ALBEDO_TABLE, albedo, albedo_estimate, albedo_fit_materialx, albedo_fit_threejs, albedo_table,
};

#[test]
fn builtin_table_is_what_the_builder_writes() {
    let mut t = vec![0f32; 256];
    albedo_table(&mut t, false).unwrap();
    assert_eq!(t.as_slice(), ALBEDO_TABLE.as_slice());
    assert!(albedo_table(&mut [0f32; 10], false).is_err());
}

#[test]
fn lookup_is_close_to_the_integrated_albedo() {
    let mut worst = (0.0f64, 0.0, 0.0);
    // Sheen roughness and mu from 0.1: below, the smoothest rows fall by 10^3 within one
    // texel and the lookup is off by up to 0.17 (printed by the run below the bound).
    for i in 0..=18 {
        let r = 0.1 + 0.05 * i as f64;
        let a = r * r;
        for j in 0..=18 {
            let mu = 0.1 + 0.05 * j as f64;
            let e = albedo_estimate(mu, a, false).min(1.0);
            let d = (albedo(mu, a) - e).abs();
            if d > worst.0 {
                worst = (d, mu, r);
            }
        }
    }
    println!(
        "built-in table: max abs error {:.4} at mu {}, sheen roughness {:.3}",
        worst.0, worst.1, worst.2
    );
    // Bilinear between texel centres of a 16 x 16 table over a surface whose smoothest rows
    // fall by 10^3 across one texel: the docs' stated bound.
    assert!(worst.0 < 0.012, "{worst:?}");
}

#[test]
fn published_fits_against_the_integrated_neubelt_albedo() {
    let (mut mx, mut tj) = ((0.0f64, 0.0, 0.0), (0.0f64, 0.0, 0.0));
    for i in 0..=19 {
        let r = 0.05 + 0.95 * i as f64 / 19.0;
        // From mu = 0.1: below it the smoothest lobes' albedo passes 1 (the fits clamp to 1).
        for j in 2..=20 {
            let mu = j as f64 / 20.0;
            // MaterialX's roughness is the Charlie width itself.
            let e = albedo_estimate(mu, r, true);
            let d = (albedo_fit_materialx(mu, r) - e).abs();
            if d > mx.0 {
                mx = (d, mu, r);
            }
            // three.js squares its roughness into the width.
            let e = albedo_estimate(mu, r * r, true);
            let d = (albedo_fit_threejs(mu, r) - e).abs();
            if d > tj.0 {
                tj = (d, mu, r);
            }
        }
    }
    println!(
        "MaterialX fit: max abs error {:.4} at mu {}, width {:.3}",
        mx.0, mx.1, mx.2
    );
    println!(
        "three.js fit: max abs error {:.4} at mu {}, roughness {:.3}",
        tj.0, tj.1, tj.2
    );
    // The measured maxima, rounded up: the docs quote them.
    assert!(mx.0 < 0.05, "{mx:?}");
    assert!(tj.0 < 0.55, "{tj:?}");
}
