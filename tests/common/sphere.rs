//! Chi-square goodness of fit of a direction sampler against its pdf over the whole sphere
//! (reflection and transmission), with the samples the sampler kills (pdf 0) counted in a bin
//! of their own: shared by the transmission samplers' tests (`tests/transmission/sampling.rs`,
//! `tests/layers/transmission.rs`).

use super::Rng;
use brdf::V3;
use core::f64::consts::TAU;

/// Bins in cos theta over [-1, 1].
pub const NZ: usize = 40;
/// Bins in phi over [0, 2 pi).
pub const NP: usize = 32;
/// Midpoints in theta per bin for the expected counts.
pub const SUB_T: usize = 48;
/// Midpoints in phi per bin for the expected counts.
pub const SUB_P: usize = 16;
/// Draws per test.
pub const SAMPLES: usize = 200_000;

/// The statistic of [`chi_square`].
#[derive(Clone, Copy, Debug)]
pub struct Fit {
    /// The chi-square statistic.
    pub stat: f64,
    /// Its degrees of freedom.
    pub dof: usize,
    /// Samples in the pooled bins when those expect fewer than 5 in all (too few to enter
    /// the statistic; a correct sampler puts almost nothing there), else 0.
    pub stray: f64,
    /// What the pdf expects in those pooled bins.
    pub stray_expected: f64,
}

/// [`SAMPLES`] draws of `sample` (which takes its uniforms from the stream it is given, seed
/// 0xbeef, and returns the direction and its pdf, 0 for a killed sample) binned by
/// (cos theta in [-1, 1], phi), against `pdf`. Expected counts by a midpoint rule in
/// (theta, phi) within each bin, weighted by sin(theta): a lobe at a pole (a normal view's
/// transmission, 0.1 rad wide at alpha 0.3) fills one z bin, where a rule in z would sample
/// it a dozen times only. The killed samples' bin expects the mass the pdf misses. Bins
/// expecting fewer than 5 are pooled.
pub fn chi_square(
    mut sample: impl FnMut(&mut Rng) -> (V3<f64>, f64),
    pdf: impl Fn(V3<f64>) -> f64,
) -> Fit {
    let mut observed = vec![0.0; NZ * NP + 1];
    let mut rng = Rng(0xbeef);
    for _ in 0..SAMPLES {
        let (w, p) = sample(&mut rng);
        assert!(w.x.is_finite() && w.y.is_finite() && w.z.is_finite() && p.is_finite() && p >= 0.0);
        if p == 0.0 {
            observed[NZ * NP] += 1.0;
            continue;
        }
        let iz = (((w.z + 1.0) * 0.5 * NZ as f64) as usize).min(NZ - 1);
        let ip = ((w.y.atan2(w.x).rem_euclid(TAU) / TAU * NP as f64) as usize) % NP;
        observed[iz * NP + ip] += 1.0;
    }
    let mut expected = vec![0.0; NZ * NP + 1];
    let mut mass = 0.0;
    for iz in 0..NZ {
        let z0 = -1.0 + 2.0 * iz as f64 / NZ as f64;
        let z1 = -1.0 + 2.0 * (iz + 1) as f64 / NZ as f64;
        let (t0, t1) = (z1.min(1.0).acos(), z0.max(-1.0).acos());
        let dt = (t1 - t0) / SUB_T as f64;
        let dp = TAU / NP as f64 / SUB_P as f64;
        for ip in 0..NP {
            let mut sum = 0.0;
            for a in 0..SUB_T {
                let t = t0 + (a as f64 + 0.5) * dt;
                let (st, ct) = t.sin_cos();
                for b in 0..SUB_P {
                    let phi = (ip * SUB_P + b) as f64 * dp + 0.5 * dp;
                    sum += pdf(V3::new(st * phi.cos(), st * phi.sin(), ct)) * st;
                }
            }
            expected[iz * NP + ip] = sum * dt * dp * SAMPLES as f64;
            mass += sum * dt * dp;
        }
    }
    expected[NZ * NP] = (1.0 - mass).max(0.0) * SAMPLES as f64;
    let (mut stat, mut dof, mut po, mut pe) = (0.0, 0usize, 0.0, 0.0);
    for (o, e) in observed.iter().zip(&expected) {
        if *e < 5.0 {
            po += o;
            pe += e;
        } else {
            stat += (o - e) * (o - e) / e;
            dof += 1;
        }
    }
    let mut stray = 0.0;
    if pe >= 5.0 {
        stat += (po - pe) * (po - pe) / pe;
        dof += 1;
    } else {
        stray = po;
    }
    Fit {
        stat,
        dof: dof.saturating_sub(1),
        stray,
        stray_expected: pe,
    }
}
