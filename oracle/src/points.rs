//! Point sets: the stiff values of each kind of argument (poles, breakpoints and their
//! neighbouring floats, the ends of the domain) crossed with each other, plus a seeded random
//! sample. Every list is deterministic; the harness rounds each coordinate to the target type,
//! so the reference is evaluated at exactly the value the kernel sees.

use crate::harness::Ty;

/// Random points per case and type.
pub const RANDOM_POINTS: usize = 2000;

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

/// [`RANDOM_POINTS`] points from `f`, seeded by `name`.
#[must_use]
pub fn random(name: &str, mut f: impl FnMut(&mut Rng) -> Vec<f64>) -> Vec<Vec<f64>> {
    let mut rng = Rng::for_case(name);
    (0..RANDOM_POINTS).map(|_| f(&mut rng)).collect()
}
