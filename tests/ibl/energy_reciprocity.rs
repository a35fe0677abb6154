//! Reciprocity of Kulla and Conty's lobe and of the compensated GGX: f(a, b) = f(b, a) over
//! the direction pairs of `integrate::reciprocity`.
#![cfg(all(feature = "ibl", feature = "integrate", feature = "cook-torrance"))]

use brdf::cook_torrance;
use brdf::fresnel;
use brdf::ggx::Ggx;
use brdf::ibl::energy::{fresnel_avg_schlick, kulla_conty_ggx};
use brdf::integrate::reciprocity;

#[test]
fn compensated_ggx_is_reciprocal() {
    for alpha in [0.05, 0.3, 1.0] {
        let g = Ggx::isotropic(alpha).unwrap();
        let f_avg = fresnel_avg_schlick(0.5, 1.0);
        let lobe = reciprocity(|o, i| kulla_conty_ggx(o.z, i.z, alpha, f_avg));
        let full = reciprocity(|o, i| {
            cook_torrance::eval(&g, o, i, |c| fresnel::schlick(0.5, c))
                + kulla_conty_ggx(o.z, i.z, alpha, f_avg)
        });
        println!(
            "alpha {alpha}: Kulla-Conty lobe max relative asymmetry {:.1e}, compensated BRDF {:.1e} ({} pairs)",
            lobe.max_rel, full.max_rel, lobe.pairs
        );
        // The lobe is a product of the same two factors in either order: exactly symmetric.
        assert_eq!(lobe.max_rel, 0.0);
        // The single scattering is symmetric up to rounding (cook_torrance::energy: ~1e-15).
        assert!(full.max_rel <= 1e-12, "{full:?}");
    }
}
