//! The thin film against the Khronos glTF Sample Viewer's `evalIridescence`
//! (`source/Renderer/shaders/iridescence.glsl` and `artisticIor` in `functions.glsl`, at commit
//! 14c393ecf0292030945fcebdf658b143329b8897), transcribed in f32.
//!
//! The viewer follows Belcour and Barla's supplemental code, as the crate does, and differs in
//! four ways. The transcription takes the first three as switches, so that the test shows each
//! by itself and that, with all three set to the crate's reading, the two agree to f32
//! rounding; the fourth is left out of the comparison by its rows:
//!
//! 1. it sums the Airy series to m = 2 (the crate to m = 3);
//! 2. it adds the incoherent term C0 as white in linear Rec.709, (C0, C0, C0), where the crate
//!    adds it as white in XYZ (an equal-energy reflectance), which the XYZ -> Rec.709 matrix
//!    maps to C0 times its row sums (1.205, 0.948, 0.909);
//! 3. its conductor phase (`fresnelPhaseExact`) is written for a base index n (1 + i kappa)
//!    but is handed the extinction k itself, where kappa = k / n; the crate takes the phase of
//!    the complex Fresnel coefficient of n + i k (a dielectric base, k = 0, is unaffected);
//! 4. it blends the film's index towards the outside's as smoothstep(0, 0.03, d) with d in
//!    nanometres (the crate over 0 to 30 nm, the paper's 0.03 um); compared from d = 30 nm on,
//!    where both blends are complete.
//!
//! Bases are grey (one F0 for the three channels): the viewer applies each RGB channel's phase
//! to the X, Y and Z sensitivities in turn, which only means the same thing for a grey base.

use brdf::iridescence::{ThinFilm, XYZ_TO_REC709, conductor};

const PI: f32 = core::f32::consts::PI;

/// Which reading each of the four differences takes (module docs).
#[derive(Clone, Copy)]
struct Reading {
    m_max: u32,
    dc_white_in_xyz: bool,
    kappa_relative: bool,
}

const VIEWER: Reading = Reading {
    m_max: 2,
    dc_white_in_xyz: false,
    kappa_relative: false,
};
const CRATE: Reading = Reading {
    m_max: 3,
    dc_white_in_xyz: true,
    kappa_relative: true,
};

fn to_rec709(xyz: [f32; 3]) -> [f32; 3] {
    let m = XYZ_TO_REC709.map(|row| row.map(|v| v as f32));
    [0, 1, 2].map(|i| m[i][0] * xyz[0] + m[i][1] * xyz[1] + m[i][2] * xyz[2])
}

/// `evalSensitivity` without its final conversion (returns XYZ).
fn sensitivity(opd: f32, shift: f32) -> [f32; 3] {
    let phase = 2.0 * PI * opd * 1.0e-9;
    let val = [5.4856e-13f32, 4.4201e-13, 5.2481e-13];
    let pos = [1.6810e+06f32, 1.7953e+06, 2.2084e+06];
    let var = [4.3278e+09f32, 9.3046e+09, 6.6121e+09];
    let mut xyz = [0, 1, 2].map(|i| {
        val[i]
            * (2.0 * PI * var[i]).sqrt()
            * (pos[i] * phase + shift).cos()
            * (-(phase * phase) * var[i]).exp()
    });
    xyz[0] += 9.7470e-14
        * (2.0 * PI * 4.5282e+09f32).sqrt()
        * (2.2399e+06 * phase + shift).cos()
        * (-4.5282e+09 * (phase * phase)).exp();
    xyz.map(|v| v / 1.0685e-7)
}

/// `fresnelConductorExact`: (Rp, Rs) for a relative index eta + i k.
fn fresnel_conductor_exact(cos_i: f32, eta: f32, k: f32) -> (f32, f32) {
    let c2 = cos_i * cos_i;
    let s2 = 1.0 - c2;
    let s4 = s2 * s2;
    let temp1 = eta * eta - k * k - s2;
    let a2pb2 = (temp1 * temp1 + 4.0 * k * k * eta * eta).sqrt();
    let a = (0.5 * (a2pb2 + temp1)).sqrt();
    let term1 = a2pb2 + c2;
    let term2 = 2.0 * a * cos_i;
    let rs = ((term1 - term2) / (term1 + term2)).max(0.0);
    let term3 = a2pb2 * c2 + s4;
    let term4 = term2 * s2;
    let rp = (rs * (term3 - term4) / (term3 + term4)).max(0.0);
    (rp, rs)
}

/// `fresnelPhaseExact`: (phi_p, phi_s) for a base eta2 (1 + i kappa2) under eta1.
fn fresnel_phase_exact(cost: f32, eta1: f32, eta2: f32, kappa2: f32) -> (f32, f32) {
    let sq = |x: f32| x * x;
    let sin2 = 1.0 - sq(cost);
    let a = sq(eta2) * (1.0 - sq(kappa2)) - sq(eta1) * sin2;
    let b = (sq(a) + sq(2.0 * sq(eta2) * kappa2)).sqrt();
    let u = ((a + b).max(0.0) / 2.0).sqrt();
    let v = ((b - a).max(0.0) / 2.0).sqrt();
    let phi_s = (2.0 * eta1 * v * cost).atan2(sq(u) + sq(v) - sq(eta1 * cost));
    let phi_p = (2.0 * eta1 * sq(eta2) * cost * (2.0 * kappa2 * u - (1.0 - sq(kappa2)) * v))
        .atan2(sq(sq(eta2) * (1.0 + sq(kappa2)) * cost) - sq(eta1) * (sq(u) + sq(v)));
    (phi_p, phi_s)
}

/// `artisticIor` (Gulbrandsen 2014): (n, k) from a reflectivity and an edge tint.
fn artistic_ior(reflectivity: f32, edge: f32) -> (f32, f32) {
    let r = reflectivity.clamp(0.0, 0.99);
    let r_sqrt = r.sqrt();
    let n_min = (1.0 - r) / (1.0 + r);
    let n_max = (1.0 + r_sqrt) / (1.0 - r_sqrt);
    let n = n_max * (1.0 - edge) + n_min * edge;
    let (np1, nm1) = (n + 1.0, n - 1.0);
    let k2 = ((np1 * np1 * r - nm1 * nm1) / (1.0 - r)).max(0.0);
    (n, k2.sqrt())
}

/// `evalIridescence(1.0, eta2, cos_theta1, d, vec3(f0), metallic)` for a grey base and d >= 30
/// nm (no blend, no total internal reflection since eta2 >= 1), in the given reading; returns
/// linear Rec.709 before the viewer's clamp at 0.
fn viewer(r: Reading, eta2: f32, cos1: f32, d: f32, f0: f32, metallic: f32) -> [f32; 3] {
    let eta1 = 1.0f32;
    let (eta3, kappa3) = artistic_ior(f0, f0 * metallic);
    let scale = eta1 / eta2;
    let cos2 = (1.0 - (1.0 - cos1 * cos1) * scale * scale).sqrt();
    let (r12p, r12s) = fresnel_conductor_exact(cos1, eta2 / eta1, 0.0);
    let (r23p, r23s) = fresnel_conductor_exact(cos2, eta3 / eta2, kappa3 / eta2);
    let opd = 2.0 * eta2 * d * cos2;
    let (phi21p, phi21s) = fresnel_phase_exact(cos1, eta1, eta2, 0.0);
    let kappa = if r.kappa_relative {
        kappa3 / eta3
    } else {
        kappa3
    };
    let (phi23p, phi23s) = fresnel_phase_exact(cos2, eta2, eta3, kappa);
    let (phi21p, phi21s) = (PI - phi21p, PI - phi21s);
    let mut rgb = [0.0f32; 3];
    for (r12, r23, phi) in [(r12p, r23p, phi23p + phi21p), (r12s, r23s, phi23s + phi21s)] {
        let t121 = 1.0 - r12;
        let r123 = (r12 * r23).sqrt();
        let rs = t121 * t121 * r23 / (1.0 - r12 * r23);
        let c0 = r12 + rs;
        let dc = if r.dc_white_in_xyz {
            to_rec709([c0; 3])
        } else {
            [c0; 3]
        };
        let mut cm = rs - t121;
        let mut ac = [0.0f32; 3];
        for m in 1..=r.m_max {
            cm *= r123;
            let s = to_rec709(sensitivity(m as f32 * opd, m as f32 * phi));
            for i in 0..3 {
                ac[i] += cm * 2.0 * s[i];
            }
        }
        for i in 0..3 {
            rgb[i] += dc[i] + ac[i];
        }
    }
    rgb.map(|v| 0.5 * v)
}

/// The rows compared: (film index, cos theta, thickness nm, grey F0, metallic).
fn rows() -> impl Iterator<Item = (f32, f32, f32, f32, f32)> {
    let films = [1.2f32, 1.33, 1.5, 2.0];
    let thicknesses = [30.0f32, 100.0, 250.0, 400.0, 800.0, 1200.0];
    let bases = [
        (0.04f32, 0.0f32),
        (0.02, 0.0),
        (0.1, 0.0),
        (0.9, 1.0),
        (0.6, 1.0),
    ];
    films.into_iter().flat_map(move |n2| {
        thicknesses.into_iter().flat_map(move |d| {
            bases.into_iter().flat_map(move |(f0, metal)| {
                (1..=20).map(move |i| (n2, i as f32 / 20.0, d, f0, metal))
            })
        })
    })
}

/// The crate's film in linear Rec.709 for the viewer's base, or None where its XYZ met its
/// [0, 1] clamp (the viewer clamps in RGB instead).
fn ours(n2: f32, cos1: f32, d: f32, f0: f32, metallic: f32) -> Option<[f32; 3]> {
    let (eta3, k3) = artistic_ior(f0, f0 * metallic);
    let film = ThinFilm::new(d, n2).unwrap();
    let xyz = conductor(&film, 1.0, eta3, k3, cos1);
    let xyz = [xyz.x, xyz.y, xyz.z];
    xyz.iter()
        .all(|&v| v > 0.0 && v < 1.0)
        .then(|| to_rec709(xyz))
}

fn max_abs(reading: Reading, metals: bool) -> (f64, usize) {
    let (mut worst, mut n) = (0.0f64, 0usize);
    for (n2, c, d, f0, metal) in rows() {
        if (metal > 0.0) != metals {
            continue;
        }
        let Some(o) = ours(n2, c, d, f0, metal) else {
            continue;
        };
        let t = viewer(reading, n2, c, d, f0, metal);
        for i in 0..3 {
            worst = worst.max((f64::from(o[i]) - f64::from(t[i])).abs());
        }
        n += 1;
    }
    (worst, n)
}

#[test]
fn sample_viewer_agrees_once_its_differences_are_read_the_crates_way() {
    let (all, n) = max_abs(CRATE, false);
    let (all_metal, n_metal) = max_abs(CRATE, true);
    let diffs = [
        ("as shipped", VIEWER),
        ("m <= 2 only", Reading { m_max: 2, ..CRATE }),
        (
            "C0 white in RGB only",
            Reading {
                dc_white_in_xyz: false,
                ..CRATE
            },
        ),
        (
            "kappa = k only",
            Reading {
                kappa_relative: false,
                ..CRATE
            },
        ),
    ];
    println!("sample viewer iridescence, max abs difference in linear Rec.709:");
    println!(
        "  crate's reading: dielectric bases {all:.2e} ({n} rows), metals {all_metal:.2e} ({n_metal} rows)"
    );
    let mut each = [(0.0f64, 0.0f64); 4];
    for (k, (name, reading)) in diffs.iter().enumerate() {
        each[k] = (max_abs(*reading, false).0, max_abs(*reading, true).0);
        println!(
            "  {name}: dielectric {:.3e}, metals {:.3e}",
            each[k].0, each[k].1
        );
    }
    // With the four differences read the crate's way: f32 rounding of the viewer's sums and of
    // cosines of phases up to about 80 radians.
    assert!(n > 1000 && n_metal > 400, "{n} {n_metal}");
    // Measured 2.58e-5 (dielectric) and 1.31e-6 (metals).
    assert!(all < 4e-5 && all_metal < 4e-5, "{all} {all_metal}");
    // Each difference alone shows (so the switches are live and the agreement above is not
    // an accident of the grid): the m = 3 term and the white of C0 on every base, the phase's
    // kappa on metals only.
    assert!(each[1].0 > 1e-3 && each[2].0 > 1e-2, "{each:?}");
    assert!(each[3].0 < 2e-4 && each[3].1 > 1e-2, "{each:?}");
    assert!(each[0].0 > 1e-2 && each[0].1 > 1e-2, "{each:?}");
}
