//! Helmholtz reciprocity of Burley's diffuse and of its renormalized form, through `eval` and
//! through the dot-product functions with l.h from a normalized half vector.
//!
//! `cargo test --no-default-features --features diffuse,integrate --test diffuse
//! burley_reciprocity:: -- --nocapture`
#![cfg(all(feature = "diffuse", feature = "integrate"))]

use brdf::V3;
use brdf::diffuse::{Burley, BurleyRenormalized, burley, burley_renormalized};
use brdf::integrate::reciprocity;

use crate::common::{dot, normalize};

/// f64 reciprocity bound: both forms are symmetric in (n.v, n.l) and use l.h = v.h, so the
/// swapped evaluations differ only in the order of a few roundings (each 2^-53 = 1.1e-16);
/// 1e-14 leaves room for the half vector's own rounding. A lobe that used n.v and n.l
/// asymmetrically (say F_D90 - 1 on one factor only) would differ by O(1).
const BOUND: f64 = 1e-14;

#[test]
fn burley_and_renormalized_are_reciprocal() {
    let l_dot_h = |o: V3<f64>, i: V3<f64>| dot(normalize(o + i), i);
    let mut worst = 0.0_f64;
    for r in [0.0, 0.3, 0.5, 0.8, 1.0] {
        let b = Burley::new(0.8, r).unwrap();
        let n = BurleyRenormalized::new(0.8, r).unwrap();
        let results = [
            ("Burley.eval", reciprocity(|o, i| b.eval(o, i))),
            (
                "burley(n.v, n.l, l.h)",
                reciprocity(|o, i| burley(o.z, i.z, l_dot_h(o, i), 0.8, r)),
            ),
            ("BurleyRenormalized.eval", reciprocity(|o, i| n.eval(o, i))),
            (
                "burley_renormalized(n.v, n.l, l.h)",
                reciprocity(|o, i| burley_renormalized(o.z, i.z, l_dot_h(o, i), 0.8, r)),
            ),
        ];
        for (name, rec) in results {
            println!(
                "r = {r}: {name:<36} max_rel {:.2e} over {} pairs",
                rec.max_rel, rec.pairs
            );
            worst = worst.max(rec.max_rel);
        }
    }
    println!("worst {worst:.2e} (bound {BOUND:e})");
    assert!(worst < BOUND, "reciprocity error {worst:e}");
}
