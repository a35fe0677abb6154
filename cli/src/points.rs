//! Input points for a kernel: the extremes of its domains (the stability sweep) and seeded
//! random points inside them, every row satisfying the kernel's [`Constraint`]s.
//!
//! Unit vectors are not swept component by component (most such triples are not unit
//! vectors): each group of three arguments takes its values from [`unit_directions`] instead,
//! and the rows are kept only where the kernel's other [`Constraint`]s hold.
//!
//! [`Constraint`]: crate::table::Constraint

use crate::table::{Float, Kernel};

/// A deterministic generator (`SplitMix64`, Steele, Lea and Flood 2014): the sweeps must pick
/// the same points on every run and machine.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator with this seed.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform `f64` in [0, 1).
    pub fn unit(&mut self) -> f64 {
        #[allow(clippy::cast_precision_loss)]
        let x = (self.next_u64() >> 11) as f64;
        x * (1.0 / (1u64 << 53) as f64)
    }

    /// A uniform index in 0..n (n > 0).
    pub fn below(&mut self, n: usize) -> usize {
        #[allow(clippy::cast_possible_truncation)]
        let i = (self.next_u64() % n as u64) as usize;
        i
    }
}

/// A seed from a kernel's path (FNV-1a), so each kernel's points differ but never change.
#[must_use]
pub fn seed_of(path: &str) -> u64 {
    path.bytes().fold(0xCBF2_9CE4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01B3)
    })
}

/// The extreme unit directions of the sweep, rounded to `ty`: the six axes, directions at
/// and just above the horizon (z = 0, the smallest subnormal and normal, epsilon, 1e-6), just
/// off the pole (z = 1 - epsilon / 2, 1 - 1e-6), below the horizon, and a few generic ones.
#[must_use]
pub fn unit_directions(ty: Float) -> Vec<[f64; 3]> {
    let mut out: Vec<[f64; 3]> = Vec::new();
    let mut push = |v: [f64; 3]| {
        let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        let r = v.map(|c| ty.round(c / len));
        if !out.contains(&r) {
            out.push(r);
        }
    };
    for axis in 0..3 {
        for s in [1.0, -1.0] {
            let mut v = [0.0; 3];
            v[axis] = s;
            push(v);
        }
    }
    let eps = ty.eps();
    for z in [
        ty.min_subnormal(),
        ty.tiny(),
        eps,
        1e-6,
        0.5,
        1.0 - 1e-6,
        1.0 - eps / 2.0,
        -1e-6,
        -0.5,
    ] {
        let s = (1.0 - z * z).sqrt();
        push([s, 0.0, z]);
        push([0.0, -s, z]);
        push([s * 0.6, s * 0.8, z]);
    }
    for v in [
        [1.0, 1.0, 1.0],
        [-1.0, 1.0, -1.0],
        [0.36, 0.48, 0.8],
        [-0.6, 0.0, 0.8],
        [0.0, 0.28, 0.96],
        [1.0, -1.0, 0.0],
    ] {
        push(v);
    }
    out
}

/// One swept dimension: a scalar argument or a unit vector (three arguments).
enum Dim {
    Scalar(usize, Vec<f64>),
    Vector([usize; 3], Vec<[f64; 3]>),
}

impl Dim {
    fn len(&self) -> usize {
        match self {
            Self::Scalar(_, v) => v.len(),
            Self::Vector(_, v) => v.len(),
        }
    }

    fn write(&self, j: usize, row: &mut [f64]) {
        match self {
            Self::Scalar(i, v) => row[*i] = v[j],
            Self::Vector(idx, v) => {
                for (i, c) in idx.iter().zip(v[j]) {
                    row[*i] = c;
                }
            }
        }
    }
}

/// The swept dimensions of `k`: each unit vector once, each other argument alone.
fn dims(k: &Kernel, ty: Float, scalar: impl Fn(usize) -> Vec<f64>) -> Vec<Dim> {
    let groups = k.unit_vectors();
    let mut dims = Vec::new();
    for g in &groups {
        dims.push(Dim::Vector(*g, unit_directions(ty)));
    }
    for i in 0..k.args.len() {
        if !groups.iter().any(|g| g.contains(&i)) {
            dims.push(Dim::Scalar(i, scalar(i)));
        }
    }
    dims
}

/// The cartesian product of the extremes of every argument's domain ([`Domain::extremes_for`]
/// for scalars, [`unit_directions`] for unit vectors), in `ty`, keeping the rows that satisfy
/// the kernel's constraints.
///
/// Where the product has more than `cap` rows, `cap` of them are drawn deterministically
/// (seeded by the kernel's path): first, for every dimension and each of its values, one row
/// holding that value with the other dimensions drawn at random, then random rows. So every
/// extreme of every argument is exercised, and the same rows come back on every run.
///
/// [`Domain::extremes_for`]: crate::table::Domain::extremes_for
#[must_use]
pub fn extreme_rows(k: &Kernel, ty: Float, cap: usize) -> Vec<Vec<f64>> {
    let dims = dims(k, ty, |i| k.args[i].domain.extremes_for(ty));
    let total = dims
        .iter()
        .try_fold(1usize, |acc, d| acc.checked_mul(d.len()));
    let mut rows = Vec::new();
    let mut row = vec![0.0; k.args.len()];
    match total {
        Some(n) if n <= cap => {
            for mut idx in 0..n {
                for d in &dims {
                    d.write(idx % d.len(), &mut row);
                    idx /= d.len();
                }
                rows.push(row.clone());
            }
        }
        _ => {
            let mut rng = SplitMix64::new(seed_of(k.path));
            let mut draw = |fixed: Option<(usize, usize)>, row: &mut Vec<f64>| {
                for (di, d) in dims.iter().enumerate() {
                    let j = match fixed {
                        Some((fd, fj)) if fd == di => fj,
                        _ => rng.below(d.len()),
                    };
                    d.write(j, row);
                }
            };
            for (di, d) in dims.iter().enumerate() {
                for j in 0..d.len() {
                    if rows.len() < cap {
                        draw(Some((di, j)), &mut row);
                        rows.push(row.clone());
                    }
                }
            }
            while rows.len() < cap {
                draw(None, &mut row);
                rows.push(row.clone());
            }
        }
    }
    rows.retain(|r| k.broken_constraint(r, ty).is_none());
    rows
}

/// A random value of `domain`, rounded to `ty` (the caller rejects it if the rounding left
/// the domain).
fn random_in(domain: &crate::table::Domain, ty: Float, rng: &mut SplitMix64) -> f64 {
    if domain.integer {
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let n = (domain.hi - domain.lo) as usize + 1;
        #[allow(clippy::cast_precision_loss)]
        return domain.lo + rng.below(n) as f64;
    }
    let (lo, hi) = (domain.lo.max(-1e6), domain.hi.min(1e6));
    let x = if hi - lo <= 2.0 {
        lo + (hi - lo) * rng.unit()
    } else {
        // Log-uniform magnitudes from 1e-6 to 1e6, with a sign where the domain has both.
        let m = 10f64.powf(12.0 * rng.unit() - 6.0);
        let neg = lo < 0.0 && (hi <= 0.0 || rng.unit() < 0.5);
        (if neg { -m } else { m }).clamp(lo, hi)
    };
    ty.round(x)
}

/// `n` random rows of `k` in `ty`, every value inside its domain and every row satisfying the
/// constraints (unit vectors uniform on the sphere), from the seed `seed`.
#[must_use]
pub fn random_rows(k: &Kernel, ty: Float, n: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut rng = SplitMix64::new(seed ^ seed_of(k.path));
    let groups = k.unit_vectors();
    let mut rows = Vec::new();
    let mut tries = 0;
    while rows.len() < n && tries < 1000 * n {
        tries += 1;
        let mut row: Vec<f64> = k
            .args
            .iter()
            .map(|a| random_in(&a.domain, ty, &mut rng))
            .collect();
        for g in &groups {
            // A uniform direction: z uniform in [-1, 1], azimuth uniform.
            let z = 2.0 * rng.unit() - 1.0;
            let phi = core::f64::consts::TAU * rng.unit();
            let s = (1.0 - z * z).sqrt();
            for (i, c) in g.iter().zip([s * phi.cos(), s * phi.sin(), z]) {
                row[*i] = ty.round(c);
            }
        }
        let in_domain = row
            .iter()
            .zip(k.args)
            .all(|(x, a)| a.domain.contains_as(*x, ty));
        if in_domain && k.broken_constraint(&row, ty).is_none() {
            rows.push(row);
        }
    }
    rows
}
