//! The Fresnel-specific dot-product forms of Cook-Torrance (`ggx_conductor_rgb`,
//! `ggx_schlick_rgb`, `ggx_dielectric` and their Beckmann twins) are the scalar entry points
//! `ggx` / `beckmann` with that Fresnel term, bit for bit per channel; they agree with the
//! direction-vector path `eval_rgb` / `eval` at the same geometry within a printed ULP bound;
//! with F = 1 their directional albedo is <= 1 (measured by `brdf::integrate`); and their
//! SIMD lanes equal the scalar results bit for bit.
//!
//! `cargo test --test cook_torrance rgb:: -- --nocapture` prints the figures.
#![cfg(all(
    feature = "cook-torrance",
    feature = "ggx",
    feature = "beckmann",
    feature = "fresnel",
    feature = "integrate"
))]

use crate::common;

use brdf::Cosines;
use brdf::beckmann::Beckmann;
use brdf::cook_torrance as ct;
use brdf::fresnel;
use brdf::fresnel::ComplexIor;
use brdf::ggx::Ggx;
use brdf::integrate::directional_albedo;
use brdf::microfacet::Alpha;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};
use glam::DVec3;

/// Cosines including the horizon, negative values, tiny and grazing ones.
const COS: [f64; 9] = [-0.1, 0.0, 1e-30, 1e-6, 0.01, 0.3, 0.7, 0.999, 1.0];
const ALPHAS: [f64; 6] = [0.0, 1e-4, 0.01, 0.3, 1.0, 1e4];
/// (eta, k) per channel: gold-like, copper-like, an index-matched near-zero reflector.
const CONDUCTORS: [([f64; 3], [f64; 3]); 3] = [
    ([0.18, 0.42, 1.37], [3.42, 2.35, 1.77]),
    ([0.27, 0.68, 1.32], [3.61, 2.62, 2.29]),
    ([1.0, 1.0, 1.0], [0.0, 1e-3, 1e3]),
];
const F0S: [[f64; 3]; 3] = [[0.04, 0.04, 0.04], [0.95, 0.64, 0.54], [0.0, 0.5, 1.0]];
/// eta > 1 (glass), eta < 1 (seen from inside: total internal reflection), eta = 1 (no F).
const ETAS: [f64; 4] = [1.5, 1.0 / 1.33, 1.0, 2.4];

fn same<T: Real>(a: T, b: T) -> bool {
    let (a, b): (f64, f64) = (a.lane(0).into(), b.lane(0).into());
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

fn v3<T: Real>(c: [f64; 3]) -> V3<T> {
    V3::new(T::splat(c[0]), T::splat(c[1]), T::splat(c[2]))
}

/// Every point of the grid, as (n.h, n.v, n.l, v.h, alpha).
fn grid() -> Vec<[f64; 5]> {
    let mut g = Vec::new();
    for nh in COS {
        for nv in COS {
            for nl in COS {
                for vh in COS {
                    for a in ALPHAS {
                        g.push([nh, nv, nl, vh, a]);
                    }
                }
            }
        }
    }
    g
}

/// Checks the three forms of one model against its scalar entry point on the whole grid;
/// returns the number of values compared.
#[allow(clippy::type_complexity)]
fn per_channel_bits<T: Real>(
    name: &str,
    scalar: fn(Cosines<T>, Alpha<T>, T) -> T,
    conductor: fn(Cosines<T>, Alpha<T>, ComplexIor<V3<T>>) -> V3<T>,
    schlick: fn(Cosines<T>, Alpha<T>, V3<T>) -> V3<T>,
    dielectric: fn(Cosines<T>, Alpha<T>, T) -> T,
) -> usize {
    let mut n = 0;
    let mut fails = Vec::new();
    for p in grid() {
        let [nh, nv, nl, vh, a] = p.map(T::splat);
        let a = Alpha(a);
        let cs = Cosines {
            n_dot_v: nv,
            n_dot_l: nl,
            n_dot_h: nh,
            v_dot_h: vh,
        };
        let channels = |v: V3<T>| [v.x, v.y, v.z];
        for (eta, k) in CONDUCTORS {
            let got = channels(conductor(
                cs,
                a,
                ComplexIor {
                    eta: v3(eta),
                    k: v3(k),
                },
            ));
            for c in 0..3 {
                let f = fresnel::conductor(vh, T::splat(eta[c]), T::splat(k[c]));
                let want = scalar(cs, a, f);
                n += 1;
                if !same(got[c], want) {
                    fails.push(format!("{name} conductor {p:?} ch {c}"));
                }
            }
        }
        for f0 in F0S {
            let got = channels(schlick(cs, a, v3(f0)));
            for c in 0..3 {
                let want = scalar(cs, a, fresnel::schlick(T::splat(f0[c]), vh));
                n += 1;
                if !same(got[c], want) {
                    fails.push(format!("{name} schlick {p:?} ch {c}"));
                }
            }
        }
        for eta in ETAS {
            let got = dielectric(cs, a, T::splat(eta));
            let f = fresnel::dielectric(vh.saturate(), T::splat(eta));
            n += 1;
            if !same(got, scalar(cs, a, f)) {
                fails.push(format!("{name} dielectric {p:?} eta {eta}"));
            }
        }
    }
    assert!(
        fails.is_empty(),
        "{} differ, first {:?}",
        fails.len(),
        &fails[..fails.len().min(5)]
    );
    n
}

#[test]
fn rgb_forms_equal_the_scalar_entry_points_channel_by_channel_bit_for_bit() {
    let mut total = 0;
    total += per_channel_bits::<f32>(
        "ggx f32",
        ct::ggx,
        ct::ggx_conductor_rgb,
        ct::ggx_schlick_rgb,
        ct::ggx_dielectric,
    );
    total += per_channel_bits::<f64>(
        "ggx f64",
        ct::ggx,
        ct::ggx_conductor_rgb,
        ct::ggx_schlick_rgb,
        ct::ggx_dielectric,
    );
    total += per_channel_bits::<f32>(
        "beckmann f32",
        ct::beckmann,
        ct::beckmann_conductor_rgb,
        ct::beckmann_schlick_rgb,
        ct::beckmann_dielectric,
    );
    total += per_channel_bits::<f64>(
        "beckmann f64",
        ct::beckmann,
        ct::beckmann_conductor_rgb,
        ct::beckmann_schlick_rgb,
        ct::beckmann_dielectric,
    );
    println!("{total} channel values identical to the scalar entry points (f32 and f64)");
}

fn ulp32(a: f32, b: f32) -> u64 {
    let key = |x: f32| {
        let i = x.to_bits() as i32;
        (if i < 0 { i32::MIN - i } else { i }) as i64
    };
    (key(a) - key(b)).unsigned_abs()
}

fn ulp64(a: f64, b: f64) -> u64 {
    let key = |x: f64| {
        let i = x.to_bits() as i64;
        (if i < 0 { i64::MIN - i } else { i }) as i128
    };
    u64::try_from((key(a) - key(b)).unsigned_abs()).unwrap_or(u64::MAX)
}

/// Directions over the upper hemisphere (theta up to 89 degrees, four azimuths of wi).
fn direction_pairs() -> Vec<(DVec3, DVec3)> {
    let dir = |t: f64, p: f64| {
        let (t, p) = (t.to_radians(), p.to_radians());
        DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
    };
    let thetas = [0.0, 10.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0];
    let mut out = Vec::new();
    for to in thetas {
        for ti in thetas {
            for pi in [0.0, 60.0, 120.0, 180.0] {
                out.push((dir(to, 0.0), dir(ti, pi)));
            }
        }
    }
    out
}

/// The largest ULP distance between the dot-product form and the direction path on one
/// precision, over `direction_pairs` x alphas x Fresnel sets, for the three forms of GGX and
/// Beckmann: (ggx, beckmann).
fn direction_path_ulps<T: Real>(
    alphas: &[f64],
    ulp: fn(T::Scalar, T::Scalar) -> u64,
) -> (u64, u64) {
    let mut worst = (0u64, 0u64);
    let scalar = |x: T| x.lane(0);
    for &a in alphas {
        let ggx = Ggx::isotropic(T::splat(a)).unwrap();
        let bk = Beckmann::isotropic(T::splat(a)).unwrap();
        for (o, i) in direction_pairs() {
            let cast = |d: DVec3| V3::new(T::splat(d.x), T::splat(d.y), T::splat(d.z));
            let (wo, wi) = (cast(o), cast(i));
            // The geometry eval uses: the same h and v.h.
            let (h, vh) = ct::half_vector(wo, wi);
            let (nh, nv, nl, al) = (h.z, wo.z, wi.z, T::splat(a));
            let cmp = |dot: V3<T>, dir: V3<T>, slot: &mut u64| {
                for (x, y) in [(dot.x, dir.x), (dot.y, dir.y), (dot.z, dir.z)] {
                    *slot = (*slot).max(ulp(scalar(x), scalar(y)));
                }
            };
            for (eta, k) in CONDUCTORS {
                let (e, kk) = (v3::<T>(eta), v3::<T>(k));
                let fr = |c: T| fresnel::conductor_rgb(c, e, kk);
                cmp(
                    ct::ggx_conductor_rgb(
                        Cosines {
                            n_dot_v: nv,
                            n_dot_l: nl,
                            n_dot_h: nh,
                            v_dot_h: vh,
                        },
                        Alpha(al),
                        ComplexIor { eta: e, k: kk },
                    ),
                    ct::eval_rgb(&ggx, wo, wi, fr),
                    &mut worst.0,
                );
                cmp(
                    ct::beckmann_conductor_rgb(
                        Cosines {
                            n_dot_v: nv,
                            n_dot_l: nl,
                            n_dot_h: nh,
                            v_dot_h: vh,
                        },
                        Alpha(al),
                        ComplexIor { eta: e, k: kk },
                    ),
                    ct::eval_rgb(&bk, wo, wi, fr),
                    &mut worst.1,
                );
            }
            for f0 in F0S {
                let f0 = v3::<T>(f0);
                let fr = |c: T| fresnel::schlick_rgb(f0, c);
                cmp(
                    ct::ggx_schlick_rgb(
                        Cosines {
                            n_dot_v: nv,
                            n_dot_l: nl,
                            n_dot_h: nh,
                            v_dot_h: vh,
                        },
                        Alpha(al),
                        f0,
                    ),
                    ct::eval_rgb(&ggx, wo, wi, fr),
                    &mut worst.0,
                );
                cmp(
                    ct::beckmann_schlick_rgb(
                        Cosines {
                            n_dot_v: nv,
                            n_dot_l: nl,
                            n_dot_h: nh,
                            v_dot_h: vh,
                        },
                        Alpha(al),
                        f0,
                    ),
                    ct::eval_rgb(&bk, wo, wi, fr),
                    &mut worst.1,
                );
            }
            for eta in ETAS {
                let e = T::splat(eta);
                let g = ct::ggx_dielectric(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(al),
                    e,
                );
                let b = ct::beckmann_dielectric(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(al),
                    e,
                );
                cmp(
                    V3::splat(g),
                    V3::splat(ct::dielectric(&ggx, wo, wi, e)),
                    &mut worst.0,
                );
                cmp(
                    V3::splat(b),
                    V3::splat(ct::dielectric(&bk, wo, wi, e)),
                    &mut worst.1,
                );
            }
        }
    }
    worst
}

/// The two routes share h, v.h and F and differ in how D and V read the geometry: from the
/// vectors' components (sin^2 = x^2 + y^2) or from the cosines (sin^2 = (1 - c)(1 + c)).
/// Those agree to an ulp of 1, and the kernels amplify that by their conditioning, which is
/// the input's, not either kernel's error: (1) at the specular peak h.z rounds to 1 while x
/// and y keep the tilt, and D's denominator there is about alpha^2, so the relative gap is
/// about eps / alpha^2 (alpha = 0.01: 1e4 ulps); (2) Beckmann's exp(-E) turns an ulp of
/// E = tan^2 / alpha^2 into a relative E eps, and E reaches 10^3 at grazing angles for
/// alpha = 0.1. Bounds, from the printed figures rounded up to a power of two: alpha >= 0.1
/// within 2^11 ulps, alpha = 0.01 within 2^16 ulps, f32 and f64.
#[test]
fn rgb_forms_match_the_direction_path_at_the_same_geometry() {
    let rough = [0.1, 0.3, 0.6, 1.0];
    let sharp = [0.01];
    let (g32, b32) = direction_path_ulps::<f32>(&rough, ulp32);
    let (g64, b64) = direction_path_ulps::<f64>(&rough, ulp64);
    let (sg32, sb32) = direction_path_ulps::<f32>(&sharp, ulp32);
    let (sg64, sb64) = direction_path_ulps::<f64>(&sharp, ulp64);
    println!("largest ulp distance, dot-product form vs eval_rgb / dielectric on directions:");
    println!("{:>16} {:>10} {:>10}", "", "GGX", "Beckmann");
    println!("{:>16} {g32:>10} {b32:>10}", "f32 alpha>=0.1");
    println!("{:>16} {g64:>10} {b64:>10}", "f64 alpha>=0.1");
    println!("{:>16} {sg32:>10} {sb32:>10}", "f32 alpha=0.01");
    println!("{:>16} {sg64:>10} {sb64:>10}", "f64 alpha=0.01");
    for (u, what) in [
        (g32, "GGX f32"),
        (g64, "GGX f64"),
        (b32, "Beckmann f32"),
        (b64, "Beckmann f64"),
    ] {
        assert!(u <= 1 << 11, "{what} alpha >= 0.1: {u} ulps");
    }
    for (u, what) in [
        (sg32, "GGX f32"),
        (sg64, "GGX f64"),
        (sb32, "Beckmann f32"),
        (sb64, "Beckmann f64"),
    ] {
        assert!(u <= 1 << 16, "{what} alpha = 0.01: {u} ulps");
    }
}

/// Directional albedo of a dot-product form over the hemisphere, with the dot products of the
/// integrator's directions.
fn albedo(wo: V3<f64>, f: impl Fn(f64, f64, f64, f64) -> f64) -> (f64, f64) {
    let e = directional_albedo(wo, |o, i| {
        let (h, vh) = ct::half_vector(o, i);
        f(h.z, o.z, i.z, vh)
    });
    (e.value, e.error)
}

/// With F = 1 (Schlick with F0 = 1) the single-scattering lobe loses energy to the bounces it
/// ignores, so its albedo is <= 1 (the integrator's own error is the only slack); a gold-like
/// conductor and glass reflect less. Prints the albedo table.
#[test]
fn rgb_forms_conserve_energy() {
    let alphas = [0.01, 0.1, 0.3, 0.6, 1.0];
    let thetas = [0.0, 45.0, 75.0, 89.0];
    let gold = (V3::new(0.18, 0.42, 1.37), V3::new(3.42, 2.35, 1.77));
    type Form = Box<dyn Fn(f64, f64, f64, f64, f64) -> f64>;
    let forms: [(&str, Form); 6] = [
        (
            "GGX F=1",
            Box::new(|nh, nv, nl, vh, a| {
                ct::ggx_schlick_rgb(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    V3::splat(1.0),
                )
                .x
            }),
        ),
        (
            "GGX gold red",
            Box::new(move |nh, nv, nl, vh, a| {
                ct::ggx_conductor_rgb(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    ComplexIor {
                        eta: gold.0,
                        k: gold.1,
                    },
                )
                .x
            }),
        ),
        (
            "GGX glass",
            Box::new(|nh, nv, nl, vh, a| {
                ct::ggx_dielectric(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    1.5,
                )
            }),
        ),
        (
            "Beckmann F=1",
            Box::new(|nh, nv, nl, vh, a| {
                ct::beckmann_schlick_rgb(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    V3::splat(1.0),
                )
                .x
            }),
        ),
        (
            "Beckmann gold red",
            Box::new(move |nh, nv, nl, vh, a| {
                ct::beckmann_conductor_rgb(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    ComplexIor {
                        eta: gold.0,
                        k: gold.1,
                    },
                )
                .x
            }),
        ),
        (
            "Beckmann glass",
            Box::new(|nh, nv, nl, vh, a| {
                ct::beckmann_dielectric(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    1.5,
                )
            }),
        ),
    ];
    for (name, f) in &forms {
        println!("\n{name}: directional albedo");
        print!("{:>7}", "alpha");
        for t in thetas {
            print!(" {:>9}", format!("{t}deg"));
        }
        println!();
        for a in alphas {
            print!("{a:>7}");
            for t in thetas {
                let t = f64::to_radians(t);
                let wo = V3::new(t.sin(), 0.0, t.cos());
                let (rho, err) = albedo(wo, |nh, nv, nl, vh| f(nh, nv, nl, vh, a));
                print!(" {rho:>9.6}");
                assert!(
                    rho <= 1.0 + err.max(1e-9),
                    "{name} alpha {a}: {rho} +- {err:e}"
                );
                assert!(rho > 0.0, "{name} alpha {a}: {rho}");
            }
            println!();
        }
    }
}

/// ULP distance between a lane value and the scalar value, through f64 (exact for f32):
/// 0 when both are NaN, u64::MAX when only one is.
fn lane_ulps<S: Real>(a: S, b: S, f32_lanes: bool) -> u64 {
    let (a, b): (f64, f64) = (a.lane(0).into(), b.lane(0).into());
    if a.is_nan() || b.is_nan() {
        return if a.is_nan() && b.is_nan() {
            0
        } else {
            u64::MAX
        };
    }
    if f32_lanes {
        ulp32(a as f32, b as f32)
    } else {
        ulp64(a, b)
    }
}

/// Lanes built from 8 (f32x8) or 4 (f64x4) different grid points against the scalar results
/// of those points: the largest ULP distance per form (GGX conductor, Schlick, dielectric,
/// then Beckmann's three).
fn lanes_vs_scalars<L: Real>() -> [u64; 6] {
    let g = grid();
    let mut worst = [0u64; 6];
    let (eta, k) = CONDUCTORS[0];
    let f0 = F0S[1];
    let f32_lanes = L::LANES == 8;
    for chunk in g.chunks_exact(L::LANES) {
        let col = |j: usize| L::from_fn(|i| L::Scalar::splat(chunk[i][j]));
        let [nh, nv, nl, vh, a] = [0, 1, 2, 3, 4].map(col);
        let outs: [V3<L>; 6] = [
            ct::ggx_conductor_rgb(
                Cosines {
                    n_dot_v: nv,
                    n_dot_l: nl,
                    n_dot_h: nh,
                    v_dot_h: vh,
                },
                Alpha(a),
                ComplexIor {
                    eta: v3(eta),
                    k: v3(k),
                },
            ),
            ct::ggx_schlick_rgb(
                Cosines {
                    n_dot_v: nv,
                    n_dot_l: nl,
                    n_dot_h: nh,
                    v_dot_h: vh,
                },
                Alpha(a),
                v3(f0),
            ),
            V3::splat(ct::ggx_dielectric(
                Cosines {
                    n_dot_v: nv,
                    n_dot_l: nl,
                    n_dot_h: nh,
                    v_dot_h: vh,
                },
                Alpha(a),
                L::splat(1.5),
            )),
            ct::beckmann_conductor_rgb(
                Cosines {
                    n_dot_v: nv,
                    n_dot_l: nl,
                    n_dot_h: nh,
                    v_dot_h: vh,
                },
                Alpha(a),
                ComplexIor {
                    eta: v3(eta),
                    k: v3(k),
                },
            ),
            ct::beckmann_schlick_rgb(
                Cosines {
                    n_dot_v: nv,
                    n_dot_l: nl,
                    n_dot_h: nh,
                    v_dot_h: vh,
                },
                Alpha(a),
                v3(f0),
            ),
            V3::splat(ct::beckmann_dielectric(
                Cosines {
                    n_dot_v: nv,
                    n_dot_l: nl,
                    n_dot_h: nh,
                    v_dot_h: vh,
                },
                Alpha(a),
                L::splat(1.5),
            )),
        ];
        for (i, p) in chunk.iter().enumerate() {
            let [nh, nv, nl, vh, a] = p.map(L::Scalar::splat);
            let s = L::Scalar::splat;
            let want: [V3<L::Scalar>; 6] = [
                ct::ggx_conductor_rgb(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    ComplexIor {
                        eta: v3(eta),
                        k: v3(k),
                    },
                ),
                ct::ggx_schlick_rgb(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    v3(f0),
                ),
                V3::splat(ct::ggx_dielectric(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    s(1.5),
                )),
                ct::beckmann_conductor_rgb(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    ComplexIor {
                        eta: v3(eta),
                        k: v3(k),
                    },
                ),
                ct::beckmann_schlick_rgb(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    v3(f0),
                ),
                V3::splat(ct::beckmann_dielectric(
                    Cosines {
                        n_dot_v: nv,
                        n_dot_l: nl,
                        n_dot_h: nh,
                        v_dot_h: vh,
                    },
                    Alpha(a),
                    s(1.5),
                )),
            ];
            for (form, (o, w)) in outs.iter().zip(&want).enumerate() {
                let got = o.lane(i);
                for (x, y) in [(got.x, w.x), (got.y, w.y), (got.z, w.z)] {
                    worst[form] = worst[form].max(lane_ulps(x, y, f32_lanes));
                }
            }
        }
    }
    worst
}

/// GGX's forms are built from +, *, /, sqrt and selects, which `wide` rounds as the scalar
/// path does: bit for bit. Beckmann's Lambda needs exp and erf, whose lane versions are
/// within a few ulps of libm's (`tests/lanes/vs_scalar.rs`), so its forms get a bound: the
/// printed figure, rounded up to a power of two.
#[test]
fn lanes_equal_scalars() {
    let w32 = lanes_vs_scalars::<f32x8>();
    let w64 = lanes_vs_scalars::<f64x4>();
    println!("largest ulp distance, lanes vs scalar (conductor, Schlick, dielectric):");
    println!("  f32x8 GGX {:?} Beckmann {:?}", &w32[..3], &w32[3..]);
    println!("  f64x4 GGX {:?} Beckmann {:?}", &w64[..3], &w64[3..]);
    for w in [w32, w64] {
        assert_eq!(w[..3], [0, 0, 0], "GGX lanes differ from scalars");
        assert!(w[3..].iter().all(|&u| u <= 4), "Beckmann lanes: {w:?}");
    }
}

/// `half_cosines`: on f32 against the same formulas evaluated in f64 from the same f32
/// directions (v.h = |s| / 2 is the mean of wo.h and wi.h for any lengths, n.h = s.z / |s|),
/// on a grid, 200 000 random pairs and nearly opposite grazing pairs; on f64 against
/// `half_vector` where 1 + wo.wi > 0.3 (closer to opposite, `half_vector`'s wo.h carries wo's
/// own length error divided by 1 + wo.wi); the fallback where wo = -wi, NaN for NaN, lanes = scalars.
#[test]
fn half_cosines_match_the_half_vector() {
    let mut pairs = direction_pairs();
    // Pseudo-random unit pairs on the sphere (wi may point below the horizon: the formulas
    // do not care).
    let mut rng = common::Rng(29);
    let mut uniform = || rng.next_f64();
    let mut dir = || {
        let (z, p) = (
            2.0 * uniform() - 1.0,
            2.0 * std::f64::consts::PI * uniform(),
        );
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * p.cos(), r * p.sin(), z)
    };
    for _ in 0..200_000 {
        let (o, i) = (dir(), dir());
        pairs.push((o, i));
    }
    for k in 1..=40 {
        // Nearly opposite grazing directions: wo = (cos p, sin p, z), wi = -(cos q, sin q, -z).
        let (p, dq, z) = (0.1 * f64::from(k), 1e-3 / f64::from(k), 1e-3 * f64::from(k));
        let a = DVec3::new(p.cos(), p.sin(), z).normalize();
        let b = DVec3::new(-(p + dq).cos(), -(p + dq).sin(), z).normalize();
        pairs.push((a, b));
    }
    let (mut worst32, mut worst64) = (0u64, 0u64);
    for &(o, i) in &pairs {
        let (o32, i32) = (V3::<f32>::from(o.as_vec3()), V3::<f32>::from(i.as_vec3()));
        let (nh, vh) = ct::half_cosines(o32, i32);
        let s = o.as_vec3().as_dvec3() + i.as_vec3().as_dvec3();
        worst32 = worst32
            .max(ulp32(nh, (s.z / s.length()) as f32))
            .max(ulp32(vh, (0.5 * s.length()) as f32));
        let lanes = ct::half_cosines(
            V3::<f32x8>::broadcast(o32.lane(0)),
            V3::broadcast(i32.lane(0)),
        );
        assert!(same(lanes.0.lane(3), nh) && same(lanes.1.lane(5), vh));
        if 1.0 + o.dot(i) > 0.3 {
            let (h, vh) = ct::half_vector(V3::<f64>::from(o), V3::<f64>::from(i));
            let (nh2, vh2) = ct::half_cosines(V3::<f64>::from(o), V3::<f64>::from(i));
            worst64 = worst64.max(ulp64(h.z, nh2)).max(ulp64(vh, vh2));
        }
    }
    println!(
        "half_cosines: {worst32} ULP (f32, against f64), {worst64} ULP (f64, against half_vector)"
    );
    assert!(worst64 <= 8 && worst32 <= 3);
    let z = V3::<f64>::new(0.6, 0.0, 0.8);
    assert_eq!(ct::half_cosines(z, -z), (1.0, 0.0));
    let nan = V3::<f64>::new(f64::NAN, 0.0, 1.0);
    let (a, b) = ct::half_cosines(nan, z);
    assert!(a.is_nan() && b.is_nan());
}
