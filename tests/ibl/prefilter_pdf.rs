//! The prefilter directions are drawn from the pdf they report: D(h) / 4 integrates to 1
//! over the sphere (adaptive cubature), the directions pass a chi-square test against it,
//! and the returned pdf equals `prefilter::pdf` at the returned direction.
#![cfg(all(feature = "ibl", feature = "integrate"))]

use brdf::V3;
use brdf::ibl::prefilter;
use brdf::integrate::{Config, hemisphere};
use glam::DVec3;

use crate::common;
use common::{assert_fits, chi_square};

/// The sphere folded onto the upper hemisphere by z -> (1 + z) / 2 (same azimuth): the map
/// halves every solid angle, so a density p on the sphere becomes 2 p, and the hemisphere
/// chi-square of tests/common sees the whole distribution, below-horizon samples included.
fn fold(w: DVec3) -> DVec3 {
    let z = 0.5 * (1.0 + w.z);
    let phi = w.y.atan2(w.x);
    let r = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

fn unfold(w: DVec3) -> DVec3 {
    let z = 2.0 * w.z - 1.0;
    let phi = w.y.atan2(w.x);
    let r = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

#[test]
fn prefilter_pdf_integrates_to_one_over_the_sphere() {
    for alpha in [0.05, 0.25, 0.5, 1.0] {
        let upper = hemisphere(
            |w| prefilter::pdf(w, alpha),
            &[V3::unit_z()],
            &Config::default(),
        );
        let lower = hemisphere(
            |w| prefilter::pdf(V3::new(w.x, w.y, -w.z), alpha),
            &[],
            &Config::default(),
        );
        let total = upper.value + lower.value;
        println!(
            "alpha {alpha}: integral of pdf = {total:.9} (below the horizon {:.5})",
            lower.value
        );
        // The cubature meets 1e-7 relative on smooth integrands (integrate.rs docs).
        assert!((total - 1.0).abs() < 1e-6, "alpha {alpha}: {total}");
    }
}

#[test]
fn prefilter_directions_match_their_pdf() {
    for alpha in [0.25, 0.5, 1.0] {
        let stat = chi_square(
            |u1, u2| {
                let s = prefilter::sample_from(u1, u2, alpha);
                let want = prefilter::pdf(s.dir, alpha);
                assert!(
                    (s.pdf - want).abs() <= 1e-12 * want,
                    "returned {} vs pdf {want}",
                    s.pdf
                );
                (fold(s.dir.into()), 2.0 * s.pdf)
            },
            |w| 2.0 * prefilter::pdf(V3::from(unfold(w)), alpha),
        );
        assert_fits(&format!("prefilter alpha {alpha} (sphere folded)"), stat);
    }
}
