//! Point sets: the stiff values of each kind of argument (poles, breakpoints and their
//! neighbouring floats, the ends of the domain) crossed with each other, plus a random sample
//! drawn fresh on every run. The harness rounds each coordinate to the target type, so the
//! reference is evaluated at exactly the value the kernel sees.
//!
//! Fresh points: the random sample of each case is seeded from the run's [`seed`]
//! (`BRDF_ORACLE_SEED` when set, the clock otherwise), so every run measures new points and
//! any failure reproduces with the seed it prints. [`random_points`] per case and type:
//! `BRDF_ORACLE_POINTS` when set, [`DEEP_POINTS`] with `BRDF_ORACLE_DEEP=1`, else
//! [`RANDOM_POINTS`].

use crate::harness::Ty;

/// Random points per case and type in an ordinary run (CI).
pub const RANDOM_POINTS: usize = 2000;

/// Random points per case and type in a deep run (`BRDF_ORACLE_DEEP=1`).
pub const DEEP_POINTS: usize = 100_000;

/// Whether this is a deep run (`BRDF_ORACLE_DEEP` set to anything but `0`): more random
/// points, a longer hill-climb from more starting points.
#[must_use]
pub fn deep() -> bool {
    std::env::var("BRDF_ORACLE_DEEP").is_ok_and(|v| v != "0")
}

/// Random points per case and type: `BRDF_ORACLE_POINTS`, or [`DEEP_POINTS`] in a deep run,
/// or [`RANDOM_POINTS`].
#[must_use]
pub fn random_points() -> usize {
    std::env::var("BRDF_ORACLE_POINTS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(if deep() { DEEP_POINTS } else { RANDOM_POINTS })
}

/// The seed of this run's fresh points: `BRDF_ORACLE_SEED` (a decimal u64) when set,
/// otherwise the clock's nanoseconds. Printed to stderr on first use; failure messages
/// repeat it.
#[must_use]
pub fn seed() -> u64 {
    static SEED: std::sync::OnceLock<u64> = std::sync::OnceLock::new();
    *SEED.get_or_init(|| {
        let s = std::env::var("BRDF_ORACLE_SEED")
            .ok()
            .and_then(|v| v.trim().parse().ok())
            .unwrap_or_else(|| {
                std::time::SystemTime::now()
                    .duration_since(std::time::UNIX_EPOCH)
                    .map_or(1, |d| d.as_nanos() as u64)
            });
        eprintln!("brdf-oracle: fresh points from BRDF_ORACLE_SEED={s}");
        s
    })
}

/// The smallest alpha sampled: `brdf::microfacet::ALPHA_MIN`; below it the kernels clamp
/// alpha on purpose and differ from the paper.
pub const ALPHA_LO: f64 = brdf::microfacet::ALPHA_MIN;

/// The largest alpha sampled: `brdf::microfacet::ALPHA_MAX`; above it the kernels clamp
/// alpha on purpose.
pub const ALPHA_HI: f64 = brdf::microfacet::ALPHA_MAX;

/// A small deterministic generator (xorshift64*, Vigna 2016).
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator seeded from a case name (FNV-1a), so each case has its own stream.
    #[must_use]
    pub fn for_case(name: &str) -> Self {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        for b in name.bytes() {
            h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
        }
        Self(h | 1)
    }

    /// A generator for `name`'s fresh points in this run: [`Rng::for_case`] mixed with the
    /// run's [`seed`].
    #[must_use]
    pub fn fresh(name: &str) -> Self {
        let mut g = Self::for_case(name);
        // splitmix64 of the seed, so that nearby seeds give unrelated streams.
        let mut z = seed().wrapping_add(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        g.0 = (g.0 ^ z) | 1;
        g
    }

    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let r = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (r >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.uniform()
    }

    /// Log-uniform in [lo, hi), lo > 0.
    pub fn log_range(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.uniform()).exp()
    }

    /// A cosine in (0, 1]: a third uniform, a third log-uniform down to 1e-30, a third within
    /// 1e-16 .. 1 of 1 (log-uniform distance), where the sin^2 = 1 - c^2 of the poles lives.
    pub fn cosine(&mut self) -> f64 {
        match (self.uniform() * 3.0) as u32 {
            0 => self.range(1e-3, 1.0),
            1 => self.log_range(1e-30, 1.0),
            _ => 1.0 - self.log_range(1e-16, 1.0),
        }
        .max(1e-30)
    }

    /// alpha log-uniform in [[`ALPHA_LO`], [`ALPHA_HI`]].
    pub fn alpha(&mut self) -> f64 {
        self.log_range(ALPHA_LO, ALPHA_HI)
    }

    /// A value in [0, 1]: uniform half the time, log-uniform in [1e-12, 1] otherwise.
    pub fn unit(&mut self) -> f64 {
        if self.uniform() < 0.5 {
            self.uniform()
        } else {
            self.log_range(1e-12, 1.0)
        }
    }

    /// A unit vector (x, y, z) with z = [`Rng::cosine`] and a uniform azimuth.
    pub fn direction(&mut self) -> [f64; 3] {
        let z = self.cosine();
        direction(z, self.range(0.0, core::f64::consts::TAU))
    }
}

/// The unit vector at cos(theta) = z and azimuth phi (computed in f64; the harness rounds the
/// components, and the reference uses them as given).
#[must_use]
pub fn direction(z: f64, phi: f64) -> [f64; 3] {
    let s = ((1.0 - z) * (1.0 + z)).sqrt();
    [s * phi.cos(), s * phi.sin(), z]
}

/// Stiff cosines in (0, 1] for `ty`: 1 and the floats just below it, the middle, the tiny,
/// the smallest normal and a subnormal.
#[must_use]
pub fn cosines(ty: Ty) -> Vec<f64> {
    let mut v = vec![
        1.0,
        1.0 - 2f64.powi(-24),
        1.0 - 2f64.powi(-53),
        1.0 - 1e-6,
        0.99,
        0.9,
        core::f64::consts::FRAC_1_SQRT_2,
        0.5,
        0.1,
        1e-3,
        1e-7,
        1e-15,
        1e-30,
    ];
    match ty {
        Ty::F32 => v.extend([f64::from(f32::MIN_POSITIVE), 1e-40]),
        Ty::F64 => v.extend([f64::MIN_POSITIVE, 1e-310]),
    }
    v
}

/// Stiff alphas: [`ALPHA_LO`], 0.01, 0.5, 1, 2, 100, [`ALPHA_HI`] and a few between.
#[must_use]
pub fn alphas() -> Vec<f64> {
    vec![
        ALPHA_LO, 2e-4, 0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0, ALPHA_HI,
    ]
}

/// Stiff relative indices: both sides of 1 within 1e-6 and one f32 epsilon, glass, water,
/// diamond-like, a large one and 1 / 1.5-like values below 1.
#[must_use]
pub fn etas(ty: Ty) -> Vec<f64> {
    let mut v = vec![
        1.0 + 1e-6,
        1.0 - 1e-6,
        1.0 + 2f64.powi(-23),
        1.0 - 2f64.powi(-23),
        1.0 + 1e-3,
        1.0 - 1e-3,
        1.33,
        1.5,
        2.4,
        10.0,
        0.5,
        1.0 / 1.5,
        0.2,
    ];
    if ty == Ty::F64 {
        v.extend([1.0 + 2f64.powi(-52), 1.0 - 2f64.powi(-53)]);
    }
    v
}

/// `x` and its `k` neighbouring floats on each side in `ty`.
#[must_use]
pub fn around(ty: Ty, x: f64, k: usize) -> Vec<f64> {
    let x = ty.round(x);
    let mut v = vec![x];
    let (mut up, mut down) = (x, x);
    for _ in 0..k {
        up = ty.next_up(up);
        down = ty.next_down(down);
        v.extend([up, down]);
    }
    v
}

/// Every combination of one value from each list.
#[must_use]
pub fn grid(axes: &[Vec<f64>]) -> Vec<Vec<f64>> {
    axes.iter().fold(vec![Vec::new()], |acc, axis| {
        acc.iter()
            .flat_map(|p| {
                axis.iter().map(move |&v| {
                    let mut q = p.clone();
                    q.push(v);
                    q
                })
            })
            .collect()
    })
}

/// [`random_points`] fresh points from `f`, from the generator [`Rng::fresh`] of `name`.
#[must_use]
pub fn random(name: &str, mut f: impl FnMut(&mut Rng) -> Vec<f64>) -> Vec<Vec<f64>> {
    let mut rng = Rng::fresh(name);
    (0..random_points()).map(|_| f(&mut rng)).collect()
}

/// The smallest positive (subnormal) and the largest finite value of `ty`.
#[must_use]
pub fn full_range(ty: Ty) -> (f64, f64) {
    match ty {
        Ty::F32 => (f64::from(f32::from_bits(1)), f64::from(f32::MAX)),
        Ty::F64 => (f64::from_bits(1), f64::MAX),
    }
}

/// Log-uniform over (0, MAX] of `ty` (uniform in the binary exponent).
pub fn log_all(g: &mut Rng, ty: Ty) -> f64 {
    let (lo, hi) = full_range(ty);
    let (a, b) = (lo.log2(), hi.log2());
    (a + (b - a) * g.uniform()).exp2().clamp(lo, hi)
}

/// A value within a few floats (half the time) or a few percent of `x`, either side.
pub fn near(g: &mut Rng, ty: Ty, x: f64) -> f64 {
    if g.uniform() < 0.5 {
        let mut y = ty.round(x);
        for _ in 0..(g.uniform() * 4.0) as u32 {
            y = if g.uniform() < 0.5 {
                ty.next_up(y)
            } else {
                ty.next_down(y)
            };
        }
        y
    } else {
        x * g.log_range(0.9, 1.0 / 0.9)
    }
}

/// A cosine in [0, 1] over the whole range of `ty`: uniform, log-uniform down to the
/// smallest subnormal, near 1, or an end.
pub fn cosine_full(g: &mut Rng, ty: Ty) -> f64 {
    match (g.uniform() * 10.0) as u32 {
        0..=3 => g.uniform(),
        4 | 5 => log_all(g, ty).min(1.0),
        6 | 7 => 1.0 - g.log_range(1e-17, 1.0),
        8 => g.log_range(1e-8, 1.0),
        _ => [0.0, 1.0][(g.uniform() * 2.0) as usize],
    }
}

/// A relative index over the whole documented domain (0, MAX]: log-uniform over it, near 1
/// on either side, common materials in [0.05, 20], and both sides of the dielectric's switch
/// to its ratio form at 1/256 and 256.
pub fn eta_full(g: &mut Rng, ty: Ty) -> f64 {
    match (g.uniform() * 10.0) as u32 {
        0..=2 => log_all(g, ty),
        3 if g.uniform() < 0.5 => near(g, ty, 1.0),
        3 => 1.0 + g.log_range(1e-9, 0.1) * if g.uniform() < 0.5 { 1.0 } else { -1.0 },
        4..=6 => g.log_range(0.05, 20.0),
        7 => near(g, ty, 256.0),
        8 => near(g, ty, 1.0 / 256.0),
        _ => g.log_range(1e-6, 1e6),
    }
}

/// The conductor's threshold EPSILON^2 of `ty` (its tiny-N scaling branch).
#[must_use]
pub fn eps2(ty: Ty) -> f64 {
    match ty {
        Ty::F32 => 2f64.powi(-46),
        Ty::F64 => 2f64.powi(-104),
    }
}

/// An extinction coefficient k over [0, MAX]: 0, log-uniform over the whole range, moderate,
/// and both sides of the conductor's scaling thresholds 2^16 and EPSILON^2.
pub fn k_full(g: &mut Rng, ty: Ty) -> f64 {
    match (g.uniform() * 10.0) as u32 {
        0 => 0.0,
        1..=3 => log_all(g, ty),
        4..=6 => g.log_range(1e-3, 10.0),
        7 => near(g, ty, 65536.0),
        8 => near(g, ty, eps2(ty)),
        _ => g.log_range(1e-8, 1e8),
    }
}
