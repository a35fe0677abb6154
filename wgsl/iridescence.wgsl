// brdf: thin-film iridescence, the twins of the Rust module `iridescence` (Belcour and Barla
// 2017, "A Practical Extension to Microfacet Theory for the Modeling of Varying Iridescence",
// as KHR_materials_iridescence uses it): the Airy summation of the film's reflections with
// the spectral integration done analytically in CIE XYZ by the paper's Gaussian fits. The
// film's `ThinFilm::new(thickness, ior)` comes first, as two arguments. Needs common.wgsl.
//
// Two rewrites keep every step inside what the WGSL accuracy table promises (W3C WGSL,
// "Floating Point Accuracy"), with the Rust kernel's value in exact arithmetic:
//
// - The phases. The m-th term of the sum is |q|^m cos(2 pi t + m arg q), with t = position x
//   OPD (in cycles: up to about 1e5 over the domain) and q = -r12 r23 (the product of the
//   interfaces' complex Fresnel coefficients; its argument is the Rust kernel's
//   phi12 + pi + phi23). WGSL states cos's accuracy on [-pi, pi] only, so the twin carries the
//   phase in half turns u = 2 t, splits u = n + s with n = round(u) and s = u - n in
//   [-1/2, 1/2] (exact in f32: Sterbenz's lemma, for u below 2^23), and takes
//   cos(pi u) = (-1)^n cos(pi s), sin(pi u) = (-1)^n sin(pi s): arguments within [-pi/2, pi/2].
// - The phase shifts. Instead of atan2 (4096 ULP, and a branch cut where a dielectric's
//   coefficient is real and negative), the shift enters through q^m as a complex product:
//   |q|^m cos(2 pi t + m arg q) = Re(q^m) cos(2 pi t) - Im(q^m) sin(2 pi t).

// iridescence's MAX_BASE_RATIO: the base's index relative to the film's is capped there.
const BRDF_IRID_MAX_BASE_RATIO: f32 = 1e6;
// The outside index relative to the film's is capped at 1e18 so that its square stays finite
// (the Rust kernel caps the square at the largest f32 instead): beyond it the top interface
// reflects 1 - 4e-18 (1 in f32) at normal incidence and totally at any other angle (the
// smallest sin^2 of an f32 cosine below 1 is 1.2e-7), either way.
const BRDF_IRID_MAX_E1: f32 = 1e18;
// 2 pi 1e-9: the Gaussians' phase per nanometre of optical path difference.
const BRDF_IRID_TWO_PI_NM: f32 = 6.283185307179586e-9;

// The Fresnel coefficient r = (a - b) / (a + b) of complex a and b: (|r|^2 capped at 1,
// Re r, Im r), r = 1 where a + b = 0 (the Rust kernel's `coefficient`, which gives |r|^2 and
// arg r; arg r is that of (a - b) conj(a + b)).
fn brdf_iridescence_coefficient(a: vec2<f32>, b: vec2<f32>) -> vec3<f32> {
    let n = a - b;
    let d = a + b;
    let d2 = d.x * d.x + d.y * d.y;
    let ok = d2 > 0.0;
    let den = select(1.0, d2, ok);
    let r2 = min((n.x * n.x + n.y * n.y) / den, 1.0);
    let re = (n.x * d.x + n.y * d.y) / den;
    let im = (n.y * d.x - n.x * d.y) / den;
    return vec3<f32>(select(1.0, r2, ok), select(1.0, re, ok), select(0.0, im, ok));
}

// The principal square root of a complex z with Im z >= 0, without the cancellation of
// sqrt((|z| - x) / 2): t = sqrt((|z| + |x|) / 2), then the other part is |y| / (2 t).
fn brdf_iridescence_csqrt(z: vec2<f32>) -> vec2<f32> {
    let m = sqrt(z.x * z.x + z.y * z.y);
    let t = sqrt(0.5 * (m + abs(z.x)));
    // t is 0 or above 2.6e-23 (the root of half the smallest subnormal): the floor only says
    // so to the bound, where the Rust kernel selects 1 for t = 0.
    let safe = max(t, 1e-30);
    let pos = z.x >= 0.0;
    let re = select(abs(z.y) / (2.0 * safe), t, pos);
    let im = select(t, z.y / (2.0 * safe), pos);
    let zero = t == 0.0;
    return vec2<f32>(select(re, 0.0, zero), select(im, 0.0, zero));
}

// (cos(pi u), sin(pi u)) for u >= 0 below 2^22 half turns, reduced to arguments in
// [-pi/2, pi/2]: n = round(u) and s = u - n (exact), the sign (-1)^n from n / 2 - floor(n / 2)
// (0 or 1/2, exactly).
fn brdf_iridescence_half_turns(u: f32) -> vec2<f32> {
    let n = round(u);
    let s = u - n;
    let h = 0.5 * n;
    let sign = 1.0 - 4.0 * (h - floor(h));
    let a = BRDF_PI * s;
    return vec2<f32>(sign * cos(a), sign * sin(a));
}

// One Gaussian of the fits (amplitude, twice its position in 1/nm, variance in 1/m^2) at the
// optical path difference opd (nm): its weight times (cos, sin) of 2 pi position opd.
fn brdf_iridescence_lobe(opd: f32, amp: f32, twice_pos: f32, variance: f32) -> vec2<f32> {
    let phase = BRDF_IRID_TWO_PI_NM * opd;
    let g = amp * exp(-variance * phase * phase);
    return brdf_iridescence_half_turns(twice_pos * opd) * g;
}

// The m-th interference term's XYZ, Re(q^m S(opd)), with S the complex sensitivity at the
// optical path difference opd = m OPD (Belcour and Barla 2017, supplemental `evalSensitivity`:
// two Gaussians for X, one each for Y and Z, normalized by the integral of y-bar, 1.0685e-7 m;
// the amplitudes are val sqrt(2 pi var) / 1.0685e-7, the positions 1.6810e6, 2.2399e6,
// 1.7953e6, 2.2084e6 per metre) and qm = q^m.
fn brdf_iridescence_term(opd: f32, qm: vec2<f32>) -> vec3<f32> {
    let x = brdf_iridescence_lobe(opd, 0.8465900023036574, 3.362e-3, 4.3278e9)
        + brdf_iridescence_lobe(opd, 0.15386830651283523, 4.4798e-3, 4.5282e9);
    let y = brdf_iridescence_lobe(opd, 1.0002218935839293, 3.5906e-3, 9.3046e9);
    let z = brdf_iridescence_lobe(opd, 1.0011224857215686, 4.4168e-3, 6.6121e9);
    return vec3<f32>(
        qm.x * x.x - qm.y * x.y,
        qm.x * y.x - qm.y * y.y,
        qm.x * z.x - qm.y * z.y,
    );
}

// z w for complex z and w.
fn brdf_iridescence_cmul(z: vec2<f32>, w: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(z.x * w.x - z.y * w.y, z.x * w.y + z.y * w.x);
}

// One polarization's XYZ: C0 + 2 (Rs - T121) sum_{m=1..3} Re(q^m S(m OPD)), from the
// interfaces' coefficients (|r|^2, Re r, Im r) and the three terms at q = 1 rotated by q^m.
fn brdf_iridescence_polarization(r12: vec3<f32>, r23: vec3<f32>, opd: f32) -> vec3<f32> {
    let t121 = 1.0 - r12.x;
    let r123 = min(r12.x * r23.x, 1.0);
    // 1 - R12 R23, floored at 2^-24: R12 R23 rounds to 1 in f32 only where R12 = 1, whose
    // T121 = 0 makes Rs = 0 with any divisor (the Rust kernel divides by 1 there), and below 1
    // it is at most 1 - 2^-24. So the floor changes no f32 value; it keeps the divisor off 0
    // for the bound where a total reflection is selected away.
    let den = max(1.0 - r123, 5.9604645e-8);
    let rs = t121 * t121 * r23.x / den;
    let c0 = r12.x + rs;
    // q = -r12 r23: |q| = sqrt(R12 R23), arg q = phi12 + pi + phi23 (r21 = -r12).
    let q1 = brdf_iridescence_cmul(vec2<f32>(-r12.y, -r12.z), vec2<f32>(r23.y, r23.z));
    let q2 = brdf_iridescence_cmul(q1, q1);
    let q3 = brdf_iridescence_cmul(q2, q1);
    let terms = brdf_iridescence_term(opd, q1) + brdf_iridescence_term(2.0 * opd, q2)
        + brdf_iridescence_term(3.0 * opd, q3);
    return vec3<f32>(c0) + terms * (2.0 * (rs - t121));
}

// The film's XYZ reflectance over a base of complex index n3 + i k3 (the Rust kernel's
// `film_xyz`): the film's index blended to the outside's by smoothstep(0, 30 nm, d), Snell's
// law into the film, the four coefficients, OPD = 2 min(n2 d, 1e7 nm) c2, s and p averaged,
// clamped to [0, 1], and (1, 1, 1) under total internal reflection at the film's top.
fn brdf_iridescence_film(
    thickness: f32, ior: f32, n1: f32, n3: f32, k3: f32, cos_theta: f32,
) -> vec3<f32> {
    let c1 = clamp(cos_theta, 0.0, 1.0);
    let x = saturate(thickness / 30.0);
    let blend = x * x * (3.0 - 2.0 * x);
    let n2 = n1 * (1.0 - blend) + ior * blend;
    let e0 = min(n1 / n2, BRDF_IRID_MAX_E1);
    let e3 = min(n3 / n2, BRDF_IRID_MAX_BASE_RATIO);
    let k = min(k3 / n2, BRDF_IRID_MAX_BASE_RATIO);
    let sin1 = (1.0 - c1) * (1.0 + c1);
    let sin2 = e0 * e0 * sin1;
    let tir = (sin2 >= 1.0) & (sin1 > 0.0);
    let s2 = min(sin2, 1.0);
    // cos^2 theta_2 = 1 - e0^2 (1 - c1^2) as (1 - e0)(1 + e0) + (e0 c1)^2, e0 = n1 / n2: the
    // Rust kernel's 1 - sin^2 in exact arithmetic, without its cancellation at grazing
    // incidence for a film index near the outside's (1 - e0 is exact there, by Sterbenz's
    // lemma).
    let c2_film = sqrt(max((1.0 - e0) * (1.0 + e0) + e0 * c1 * e0 * c1, 0.0));
    // Total reflection at the film's top, or grazing incidence (c1 = 0, where R12 = 1 in both
    // polarizations, T121 = 0 and the sum is C0 = 1): the result is (1, 1, 1), selected at the
    // end. The film is then evaluated at stand-ins (e0 = 1/2, c2 = 1: R12 <= 1/9), so that
    // the bound does not follow a division by 1 - R12 R23 = 0 whose value is selected away.
    let total = tir | (c1 == 0.0);
    let e1 = select(e0, 0.5, total);
    let c2 = select(c2_film, 1.0, total);
    let r12s = brdf_iridescence_coefficient(vec2<f32>(e1 * c1, 0.0), vec2<f32>(c2, 0.0));
    let r12p = brdf_iridescence_coefficient(vec2<f32>(c1, 0.0), vec2<f32>(e1 * c2, 0.0));
    // The base seen from the film: w = N3 cos(theta_3) = sqrt(N3^2 - sin^2 theta_2).
    let n3sq = vec2<f32>(e3 * e3 - k * k, e3 * k + k * e3);
    let w = brdf_iridescence_csqrt(vec2<f32>(n3sq.x - s2, n3sq.y));
    let r23s = brdf_iridescence_coefficient(vec2<f32>(c2, 0.0), w);
    let r23p = brdf_iridescence_coefficient(n3sq * c2, w);
    let opd = min(n2 * thickness, 1e7) * c2 * 2.0;
    let xyz = (brdf_iridescence_polarization(r12s, r23s, opd)
        + brdf_iridescence_polarization(r12p, r23p, opd)) * 0.5;
    let clamped = vec3<f32>(saturate(xyz.x), saturate(xyz.y), saturate(xyz.z));
    return select(clamped, vec3<f32>(1.0), total);
}

// XYZ reflectance (equal-energy illuminant, Y of a perfect reflector = 1) of a dielectric base
// of index base_ior under a film of `thickness` nm and index `ior`, seen from a medium of
// index outside_ior at cos_theta (n.v, or v.h on a microfacet): Belcour and Barla 2017, eq. 10,
// integrated in XYZ; each component in [0, 1]. thickness in [0, 10000], ior in [1, 10], the
// indices in (0, MAX], cos_theta in [0, 1] (clamped into it).
fn iridescence_dielectric(
    thickness: f32, ior: f32, outside_ior: f32, base_ior: f32, cos_theta: f32,
) -> vec3<f32> {
    return brdf_iridescence_film(thickness, ior, outside_ior, base_ior, 0.0, cos_theta);
}

// iridescence_dielectric over a conductor base of complex index base_eta + i base_k: the film
// to base interface's reflectances and phase shifts are those of the complex Fresnel
// coefficients (Born and Wolf, section 14.2; Belcour and Barla 2017, section 4). base_k in
// [0, MAX].
fn iridescence_conductor(
    thickness: f32, ior: f32, outside_ior: f32, base_eta: f32, base_k: f32, cos_theta: f32,
) -> vec3<f32> {
    return brdf_iridescence_film(thickness, ior, outside_ior, base_eta, base_k, cos_theta);
}
