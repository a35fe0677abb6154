//! Shared by the test binaries: a deterministic random stream and a chi-square goodness-of-fit
//! test of a direction sampler against its pdf (over the hemisphere here, over the whole sphere
//! in [`sphere`]). Each test binary compiles this module on its
//! own and uses part of it.
#![allow(dead_code)]

use brdf::V3;
use glam::DVec3;

pub mod sphere;

/// A random unit direction of the upper hemisphere: n.v from 1e-6 to 1, log-uniform half the
/// time (grazing angles, where working-precision forms lose most), uniform in z otherwise.
/// The working-precision tiers' tests draw their directions from it.
pub fn random_dir(rng: &mut Rng) -> V3<f64> {
    let z = if rng.next_f64() < 0.5 {
        libm::pow(10.0, -6.0 * rng.next_f64())
    } else {
        rng.next_f64()
    };
    let phi = core::f64::consts::TAU * rng.next_f64();
    let s = ((1.0 - z) * (1.0 + z)).sqrt();
    V3::new(s * phi.cos(), s * phi.sin(), z)
}

/// SplitMix64 (Steele, Lea, Flood 2014): a deterministic stream, so the chi-square statistic
/// below is the same on every run and machine.
pub struct Rng(pub u64);
impl Rng {
    pub fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `a . b` summed as glam's `DVec3::dot` sums it: three rounded products, two rounded sums.
/// [`V3::dot`] fuses them (`mul_add`), which can move the last bit: the kernels the integrator
/// tests hand to `brdf::integrate`, first written on `DVec3`, keep their results to the bit with
/// this one.
pub fn dot(a: V3<f64>, b: V3<f64>) -> f64 {
    a.x * b.x + a.y * b.y + a.z * b.z
}

/// `|w|` as glam's `DVec3::length` forms it: the square root of [`dot`]`(w, w)`.
pub fn length(w: V3<f64>) -> f64 {
    dot(w, w).sqrt()
}

/// `w / |w|` as glam's `DVec3::normalize` forms it: `w` times the rounded `1 / `[`length`]`(w)`
/// (not [`V3::normalize`], which scales by the largest component first).
pub fn normalize(w: V3<f64>) -> V3<f64> {
    w * (1.0 / length(w))
}

pub const NZ: usize = 16;
pub const NP: usize = 32;
pub const SAMPLES: usize = 200_000;

/// Midpoints per side of each bin in the rule that gives [`chi_square`] its expected counts.
pub const SUB: usize = 64;

/// Chi-square statistic of `SAMPLES` draws against `pdf`, binned by (cos theta, phi), which
/// are uniform in solid angle. Expected counts by a `SUB` x `SUB` midpoint rule per bin; bins
/// expecting fewer than 5 are pooled. Returns (statistic, degrees of freedom).
pub fn chi_square(
    sample: impl FnMut(f64, f64) -> (DVec3, f64),
    pdf: impl Fn(DVec3) -> f64,
) -> (f64, usize) {
    chi_square_with(SAMPLES, SUB, sample, pdf)
}

/// [`chi_square`] with `samples` draws and `sub` x `sub` midpoints per bin for the expected
/// counts. These cost `NZ NP sub^2` calls of `pdf` (2 million at `SUB`, which resolves lobes
/// a bin wide); a density that varies over many bins needs far fewer.
pub fn chi_square_with(
    samples: usize,
    sub: usize,
    mut sample: impl FnMut(f64, f64) -> (DVec3, f64),
    pdf: impl Fn(DVec3) -> f64,
) -> (f64, usize) {
    let mut observed = vec![0.0; NZ * NP];
    let mut rng = Rng(0x5eed);
    for _ in 0..samples {
        let (w, p) = sample(rng.next_f64(), rng.next_f64());
        assert!(w.is_finite() && p.is_finite() && p >= 0.0, "{w:?} {p}");
        assert!((w.length() - 1.0).abs() < 1e-9, "not unit: {w:?}");
        // The pdf the sampler returns is the pdf function at its sample.
        let q = pdf(w);
        assert!(
            (p - q).abs() <= 1e-9 * q.max(1.0),
            "returned pdf {p} vs pdf function {q}"
        );
        let z = w.z.clamp(0.0, 1.0 - 1e-12);
        let phi = w.y.atan2(w.x).rem_euclid(core::f64::consts::TAU);
        let (iz, ip) = (
            (z * NZ as f64) as usize,
            ((phi / core::f64::consts::TAU) * NP as f64) as usize % NP,
        );
        observed[iz * NP + ip] += 1.0;
    }
    let mut expected = vec![0.0; NZ * NP];
    for iz in 0..NZ {
        for ip in 0..NP {
            let mut sum = 0.0;
            for a in 0..sub {
                for b in 0..sub {
                    let z = (iz as f64 + (a as f64 + 0.5) / sub as f64) / NZ as f64;
                    let phi = (ip as f64 + (b as f64 + 0.5) / sub as f64) / NP as f64
                        * core::f64::consts::TAU;
                    let r = (1.0 - z * z).sqrt();
                    sum += pdf(DVec3::new(r * phi.cos(), r * phi.sin(), z));
                }
            }
            let area = (1.0 / NZ as f64) * (core::f64::consts::TAU / NP as f64);
            expected[iz * NP + ip] = sum / (sub * sub) as f64 * area * samples as f64;
        }
    }
    let (mut stat, mut dof, mut pool_o, mut pool_e) = (0.0, 0usize, 0.0, 0.0);
    for (o, e) in observed.iter().zip(&expected) {
        if *e < 5.0 {
            pool_o += o;
            pool_e += e;
        } else {
            stat += (o - e) * (o - e) / e;
            dof += 1;
        }
    }
    if pool_e >= 5.0 {
        stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        dof += 1;
    }
    (stat, dof.saturating_sub(1))
}

/// The chi-square value a statistic with `dof` degrees of freedom exceeds with probability
/// 1e-4 (normal approximation, good for dof > 100).
pub fn critical(dof: usize) -> f64 {
    dof as f64 + 3.72 * (2.0 * dof as f64).sqrt()
}

/// Rejects at p = 1e-4 ([`critical`]): a correct sampler fails one seed in 10^4, a wrong one
/// (a missing Jacobian, a swapped axis) scores in the thousands.
pub fn assert_fits(name: &str, (stat, dof): (f64, usize)) {
    let critical = critical(dof);
    println!("{name}: chi^2 = {stat:.1}, dof = {dof}, critical = {critical:.1}");
    assert!(dof > 50, "{name}: too few populated bins ({dof})");
    assert!(
        stat < critical,
        "{name}: chi^2 = {stat} >= {critical} (dof {dof})"
    );
}

/// Proptest's default configuration, its failures persisted beside the test module's source file
/// ([`persist_beside_source`]).
pub fn proptest_config() -> proptest::test_runner::Config {
    persist_beside_source(proptest::test_runner::Config::default())
}

/// [`proptest_config`] with `cases` cases per test.
pub fn proptest_cases(cases: u32) -> proptest::test_runner::Config {
    persist_beside_source(proptest::test_runner::Config::with_cases(cases))
}

/// `config` with failing cases persisted beside the module that found them, in
/// `tests/<binary>/<module>.proptest-regressions`, and read back from there. Proptest's default
/// rule stops at the binary's `main.rs` and writes `tests/proptest-regressions/<module>.txt`, where
/// `fresnel/domains.rs` and `microfacet/domains.rs` would share one file.
fn persist_beside_source(config: proptest::test_runner::Config) -> proptest::test_runner::Config {
    proptest::test_runner::Config {
        failure_persistence: Some(Box::new(
            proptest::test_runner::FileFailurePersistence::WithSource("proptest-regressions"),
        )),
        ..config
    }
}
