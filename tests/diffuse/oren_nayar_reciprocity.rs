//! Helmholtz reciprocity of the Oren-Nayar family: f(a, b) = f(b, a) by
//! `brdf::integrate::reciprocity`, for every form, on the f64 and f32 kernels, over sigma from
//! smooth to very rough. Every term is symmetric in (theta_i, theta_o) (alpha, beta, |s|) so
//! the kernels are exactly symmetric.
#![cfg(all(feature = "diffuse", feature = "integrate"))]

use brdf::V3;
use brdf::diffuse::{OrenNayar, OrenNayarFujii, OrenNayarFull};
use brdf::integrate::reciprocity;

fn v32(d: V3<f64>) -> V3<f32> {
    V3::new(d.x as f32, d.y as f32, d.z as f32)
}

#[test]
fn oren_nayar_family_is_reciprocal() {
    let (mut w64, mut w32) = (0.0f64, 0.0f64);
    for sigma in [0.0, 0.1, 0.3, 0.7, 1.0, 3.0] {
        let fs = (sigma / 3.0f64).min(1.0);
        let q = OrenNayar::new(0.8, sigma).unwrap();
        let f = OrenNayarFull::new(0.8, sigma).unwrap();
        let j = OrenNayarFujii::new(0.8, fs).unwrap();
        let r = [
            reciprocity(|a, b| q.eval(a, b)).max_rel,
            reciprocity(|a, b| f.eval(a, b)).max_rel,
            reciprocity(|a, b| j.eval(a, b)).max_rel,
        ];
        let q32 = OrenNayar::new(0.8f32, sigma as f32).unwrap();
        let f32_ = OrenNayarFull::new(0.8f32, sigma as f32).unwrap();
        let j32 = OrenNayarFujii::new(0.8f32, fs as f32).unwrap();
        let r32 = [
            reciprocity(|a, b| q32.eval(v32(a), v32(b)) as f64).max_rel,
            reciprocity(|a, b| f32_.eval(v32(a), v32(b)) as f64).max_rel,
            reciprocity(|a, b| j32.eval(v32(a), v32(b)) as f64).max_rel,
        ];
        println!(
            "sigma {sigma:>4}: f64 {:?}  f32 {:?}",
            r.map(|x| format!("{x:.1e}")),
            r32.map(|x| format!("{x:.1e}"))
        );
        w64 = r.iter().fold(w64, |m, &x| m.max(x));
        w32 = r32.iter().fold(w32, |m, &x| m.max(x));
    }
    println!("max relative asymmetry: f64 {w64:.2e}, f32 {w32:.2e}");
    // Exactly 0: every term is a symmetric function of (n.v, n.l) and v.l, and wo . wi rounds
    // the same as wi . wo (products commute). A non-reciprocal term (theta_i in place of
    // alpha, say) gives > 1e-2.
    assert_eq!(w64, 0.0, "f64 {w64}");
    assert_eq!(w32, 0.0, "f32 {w32}");
}
