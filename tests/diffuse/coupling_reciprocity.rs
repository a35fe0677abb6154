//! Reciprocity of the diffuse-Fresnel couplings: the symmetric weight, Shirley et al.'s and
//! Ashikhmin-Shirley's coupled diffuse and the F(v.h) mix are reciprocal; the one-sided
//! weight (1 - F(wi)) / (1 - F0) and the F(n.v) mix are not, and the figures show by how much.
//!
//! `cargo test --no-default-features --features diffuse,integrate --test diffuse
//! coupling_reciprocity:: -- --nocapture`
#![cfg(all(feature = "diffuse", feature = "integrate"))]

use brdf::V3;
use brdf::diffuse::{
    AshikhminShirley, ShirleyCoupled, fresnel_mix, fresnel_mix_schlick, fresnel_weight_normalized,
    fresnel_weight_symmetric, lambert,
};
use brdf::fresnel::schlick;
use brdf::integrate::{Reciprocity, reciprocity};
use core::f64::consts::PI;

use crate::common::{dot, normalize};

/// f64 bound for the reciprocal diffuse forms: the swapped evaluations differ in the order of
/// a few roundings (2^-53 each).
const BOUND: f64 = 1e-14;
/// The F(v.h) mix adds the Phong lobe, whose (r.wi)^20 multiplies the rounding of r.wi
/// against r'.wo by 20, and a half vector normalized in two orders (measured 7.0e-15).
const BOUND_MIX: f64 = 1e-13;
const F0: [f64; 3] = [0.02, 0.04, 0.5];

/// A reciprocal specular lobe with albedo <= 1: normalized modified Phong around the mirror
/// direction, (n + 2) / (2 pi) max(0, r.wi)^n (Lewis 1994), with r.wi = r'.wo.
fn phong(wo: V3<f64>, wi: V3<f64>, n: f64) -> f64 {
    let r = V3::new(-wo.x, -wo.y, wo.z);
    (n + 2.0) / (2.0 * PI) * dot(r, wi).max(0.0).powf(n)
}

fn report(name: &str, rec: &Reciprocity) {
    let (a, b) = rec.worst;
    println!(
        "{name:<52} max_rel {:.3e}  worst pair cos {:.6} / {:.6}",
        rec.max_rel, a.z, b.z
    );
}

#[test]
fn symmetric_couplings_are_reciprocal() {
    let (mut worst, mut worst_mix) = (0.0_f64, 0.0_f64);
    for f0 in F0 {
        let sh = ShirleyCoupled::new(0.9, f0).unwrap();
        let ash = AshikhminShirley::new(0.9, f0).unwrap();
        let cases = [
            (
                "lambert (1 - F(n.l))(1 - F(n.v)), Schlick",
                reciprocity(|o, i| {
                    lambert(o.z, i.z, 0.9)
                        * fresnel_weight_symmetric(schlick(f0, o.z), schlick(f0, i.z))
                }),
            ),
            ("ShirleyCoupled", reciprocity(|o, i| sh.eval(o, i))),
            ("AshikhminShirley", reciprocity(|o, i| ash.eval(o, i))),
            (
                "mix F(v.h): lambert (1 - F) + phong F",
                reciprocity(|o, i| {
                    let v_dot_h = dot(normalize(o + i), o);
                    fresnel_mix_schlick(lambert(o.z, i.z, 0.9), phong(o, i, 20.0), f0, v_dot_h)
                }),
            ),
        ];
        for (name, rec) in cases {
            report(&format!("F0 = {f0}: {name}"), &rec);
            if name.starts_with("mix") {
                worst_mix = worst_mix.max(rec.max_rel);
            } else {
                worst = worst.max(rec.max_rel);
            }
        }
    }
    println!(
        "worst {worst:.2e} (bound {BOUND:e}); F(v.h) mix {worst_mix:.2e} (bound {BOUND_MIX:e})"
    );
    assert!(worst < BOUND, "reciprocity error {worst:e}");
    assert!(
        worst_mix < BOUND_MIX,
        "F(v.h) mix reciprocity error {worst_mix:e}"
    );
}

/// The one-sided weight follows wi alone: f(wo, wi) / f(wi, wo) = (1 - F(wi)) / (1 - F(wo)),
/// which with Schlick at n.l is (1 - (1 - n.l)^5) / (1 - (1 - n.v)^5): near 0 when wi grazes
/// and wo does not. Measured max_rel 0.99995 (cosines 1e-5 and 1). Asserted > 0.9: a
/// reciprocal form gives < 1e-14.
#[test]
fn normalized_one_sided_weight_is_not_reciprocal() {
    let mut least = f64::MAX;
    for f0 in F0 {
        let rec = reciprocity(|o, i| {
            lambert(o.z, i.z, 0.9) * fresnel_weight_normalized(schlick(f0, i.z), f0)
        });
        report(&format!("F0 = {f0}: lambert (1 - F(n.l)) / (1 - F0)"), &rec);
        least = least.min(rec.max_rel);
    }
    assert!(
        least > 0.9,
        "one-sided weight looks reciprocal: max_rel {least}"
    );
}

/// The F(n.v) mix weights the two lobes by the view direction alone, so swapping wo and wi
/// changes the weights. Measured max_rel printed; asserted > 0.1 for every F0.
#[test]
fn view_fresnel_mix_is_not_reciprocal() {
    let mut least = f64::MAX;
    for f0 in F0 {
        let rec = reciprocity(|o, i| {
            fresnel_mix(lambert(o.z, i.z, 0.9), phong(o, i, 20.0), schlick(f0, o.z))
        });
        report(
            &format!("F0 = {f0}: mix F(n.v): lambert (1 - F) + phong F"),
            &rec,
        );
        least = least.min(rec.max_rel);
    }
    assert!(least > 0.1, "F(n.v) mix looks reciprocal: max_rel {least}");
}
