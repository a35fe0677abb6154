//! The comparisons of `brdf::tonemap` against the peer transcriptions in `tonemap.rs`: one
//! [`Case`] per (our operator, peer operator, mapping), the shared input grid, and the
//! difference statistics. Used by `tests/tonemap/against_peers.rs` (which asserts the bounds) and
//! by the report's tonemapping section (which prints the table).
//!
//! Every difference is |ours - peer| per channel after both are clamped to [0, 1] (ours always
//! is; where a peer does not clamp, its output is clamped here, the frame buffer's clamp). Ours
//! is evaluated twice, in f64 and in f32, on the same f32 input the peer gets. A peer output
//! that is NaN (its source divides 0 by 0 or raises a negative base to a fractional power
//! there) is skipped and counted.

// Shared by the test and the report, each of which uses part of it.
#![allow(dead_code)]

use super::peers::{self, FilamentAgxLook, Rgb, WrenschLook};
use brdf::color::{self, REC709_TO_REC2020, REC2020_TO_REC709};
use brdf::tonemap::{
    AgxLook, HableParams, LottesParams, Operator, UchimuraParams, aces_hill, aces_narkowicz,
    agx_filament, agx_minimal, agx_threejs, hable, lottes, pbr_neutral, reinhard,
    reinhard_extended, reinhard_luminance, uchimura,
};
use brdf::{Real, V3};

/// One comparison: our operator under a mapping against one peer operator.
pub struct Case {
    /// Short key, used by the tests.
    pub id: &'static str,
    /// Our side, as a user writes it.
    pub ours: &'static str,
    /// The peer operator (engine or paper, and the function's name there).
    pub peer: &'static str,
    /// How the peer's parameters and spaces map onto ours.
    pub mapping: &'static str,
    /// True when the mapping is claimed exact (differences are f32 rounding only).
    pub exact: bool,
    ours64: Box<dyn Fn([f64; 3]) -> [f64; 3]>,
    ours32: Box<dyn Fn([f32; 3]) -> [f32; 3]>,
    peer_fn: Box<dyn Fn(Rgb) -> Rgb>,
}

/// The largest difference found and where.
#[derive(Clone, Copy, Debug, Default)]
pub struct Worst {
    /// max |ours - peer| over every point and channel.
    pub max: f64,
    /// The input colour where it occurs.
    pub at: [f32; 3],
    /// The channel.
    pub channel: usize,
    /// Ours there.
    pub ours: f64,
    /// The peer there.
    pub peer: f64,
}

/// The statistics of one case over the grid.
#[derive(Clone, Copy, Debug, Default)]
pub struct Stats {
    /// Ours in f64 against the peer in f32.
    pub f64: Worst,
    /// Ours in f32 against the peer in f32.
    pub f32: Worst,
    /// Points where the peer gave NaN (skipped).
    pub peer_nan: usize,
    /// Points compared.
    pub points: usize,
}

impl Stats {
    /// One line for `--nocapture` output.
    pub fn describe(&self, case: &Case) -> String {
        let w = |n: &str, w: &Worst| {
            format!(
                "{n}: max |diff| {:.3e} at ({:e}, {:e}, {:e}) channel {} (ours {:.9}, peer {:.9})",
                w.max, w.at[0], w.at[1], w.at[2], w.channel, w.ours, w.peer
            )
        };
        format!(
            "{} vs {} [{}]\n  {}\n  {}\n  {} points, {} skipped (peer NaN)",
            case.ours,
            case.peer,
            case.mapping,
            w("ours f64", &self.f64),
            w("ours f32", &self.f32),
            self.points,
            self.peer_nan
        )
    }
}

fn to_v3<T: Real>(c: [T; 3]) -> V3<T> {
    V3::new(c[0], c[1], c[2])
}

fn from_v3<T: Real>(v: V3<T>) -> [T; 3] {
    [v.x, v.y, v.z]
}

/// Builds a case; `$body` is our side as a generic expression in `c: V3<T>`.
macro_rules! case {
    ($id:expr, $ours:expr, $peer:expr, $mapping:expr, $exact:expr,
     |$c:ident| $body:expr, $peer_fn:expr) => {{
        fn f<T: Real>($c: V3<T>) -> V3<T> {
            $body
        }
        Case {
            id: $id,
            ours: $ours,
            peer: $peer,
            mapping: $mapping,
            exact: $exact,
            ours64: Box::new(|c| from_v3(f::<f64>(to_v3(c)))),
            ours32: Box::new(|c| from_v3(f::<f32>(to_v3(c)))),
            peer_fn: Box::new($peer_fn),
        }
    }};
}

fn each<T: Real>(c: V3<T>, f: impl Fn(T) -> T) -> V3<T> {
    V3::new(f(c.x), f(c.y), f(c.z))
}

fn mat<T: Real>(m: &color::Mat3, c: V3<T>) -> V3<T> {
    color::mul(m, c)
}

/// Lottes' curve with shoulder 1 and Filament's `GenericToneMapper` default parameters.
fn lottes_filament_default() -> LottesParams {
    LottesParams::new(1.55, 1.0, 10.0, 0.18, 0.215).expect("valid Lottes parameters")
}

/// Every comparison, exact mappings first within each peer.
pub fn cases() -> Vec<Case> {
    vec![
        // three.js
        case!(
            "threejs_reinhard",
            "reinhard",
            "three.js ReinhardToneMapping",
            "exposure e: reinhard(e c) per channel (e = 1)",
            true,
            |c| each(c, reinhard),
            |c| peers::threejs_reinhard(c, 1.0)
        ),
        case!(
            "threejs_reinhard_e1p7",
            "reinhard",
            "three.js ReinhardToneMapping",
            "exposure e: reinhard(e c) per channel (e = 1.7)",
            true,
            |c| each(c, |x| reinhard(x * T::splat(1.7))),
            |c| peers::threejs_reinhard(c, 1.7)
        ),
        case!(
            "threejs_aces",
            "aces_hill",
            "three.js ACESFilmicToneMapping",
            "exposure e: aces_hill(c e / 0.6) (e = 1)",
            true,
            |c| aces_hill(c * T::splat(1.0 / 0.6)),
            |c| peers::threejs_aces_filmic(c, 1.0)
        ),
        case!(
            "threejs_aces_e1p7",
            "aces_hill",
            "three.js ACESFilmicToneMapping",
            "exposure e: aces_hill(c e / 0.6) (e = 1.7)",
            true,
            |c| aces_hill(c * T::splat(1.7 / 0.6)),
            |c| peers::threejs_aces_filmic(c, 1.7)
        ),
        case!(
            "threejs_aces_without_0p6",
            "aces_hill",
            "three.js ACESFilmicToneMapping",
            "WRONG on purpose: aces_hill(c) at e = 1, the 1/0.6 left out",
            false,
            |c| aces_hill(c),
            |c| peers::threejs_aces_filmic(c, 1.0)
        ),
        case!(
            "threejs_neutral",
            "pbr_neutral",
            "three.js NeutralToneMapping",
            "exposure e: pbr_neutral(e c) (e = 1)",
            true,
            |c| pbr_neutral(c),
            |c| peers::threejs_neutral(c, 1.0)
        ),
        case!(
            "threejs_agx",
            "agx_threejs",
            "three.js AgXToneMapping (adb06d74, r162+)",
            "exposure e: agx_threejs(e c) (e = 1)",
            true,
            |c| agx_threejs(c),
            |c| peers::threejs_agx(c, 1.0)
        ),
        case!(
            "threejs_agx_0ac1f6ab",
            "agx_threejs",
            "three.js AgXToneMapping (0ac1f6ab, r160)",
            "r160 inverted BT.2407's matrix where r162+ (agx_threejs) uses BT.2087's",
            false,
            |c| agx_threejs(c),
            |c| peers::threejs_agx_0ac1f6ab(c, 1.0)
        ),
        // Filament
        case!(
            "filament_filmic_legacy",
            "aces_narkowicz",
            "Filament FilmicToneMapper, ToneMapping::FILMIC path",
            "aces_narkowicz per channel on linear sRGB (the legacy path skips Rec.2020)",
            true,
            |c| each(c, aces_narkowicz),
            peers::filament_grade_legacy_filmic
        ),
        case!(
            "filament_filmic_rec2020",
            "aces_narkowicz",
            "Filament FilmicToneMapper in ColorGrading",
            "REC2020_TO_REC709 aces_narkowicz(REC709_TO_REC2020 c): ours clamps in Rec.2020",
            false,
            |c| mat(
                &REC2020_TO_REC709,
                each(mat(&REC709_TO_REC2020, c), aces_narkowicz)
            )
            .map(|x| x.saturate()),
            |c| peers::filament_grade(c, peers::filament_filmic)
        ),
        case!(
            "filament_generic",
            "lottes (shoulder 1)",
            "Filament GenericToneMapper(1.55, 0.18, 0.215, 10)",
            "lottes(x, LottesParams::new(1.55, 1.0, 10.0, 0.18, 0.215)) per channel",
            true,
            |c| {
                let p = lottes_filament_default();
                each(c, |x| lottes(x, &p))
            },
            |c| peers::filament_generic(c, 1.55, 0.18, 0.215, 10.0)
        ),
        case!(
            "filament_pbr_neutral",
            "pbr_neutral",
            "Filament PBRNeutralToneMapper (0916f5bb)",
            "REC2020_TO_REC709 pbr_neutral(REC709_TO_REC2020 c): Filament mixes toward 1",
            false,
            |c| mat(&REC2020_TO_REC709, pbr_neutral(mat(&REC709_TO_REC2020, c)))
                .map(|x| x.saturate()),
            |c| peers::filament_grade(c, peers::filament_pbr_neutral)
        ),
        case!(
            "filament_agx",
            "agx_filament(BASE)",
            "Filament AgxToneMapper(NONE)",
            "agx_filament(c, BASE) on linear Rec.2020",
            true,
            |c| agx_filament(c, &AgxLook::BASE),
            |c| peers::filament_agx(c, FilamentAgxLook::None)
        ),
        case!(
            "filament_agx_punchy",
            "agx_filament(PUNCHY)",
            "Filament AgxToneMapper(PUNCHY)",
            "agx_filament(c, PUNCHY) on linear Rec.2020",
            true,
            |c| agx_filament(c, &AgxLook::PUNCHY),
            |c| peers::filament_agx(c, FilamentAgxLook::Punchy)
        ),
        case!(
            "filament_agx_golden",
            "agx_filament(GOLDEN_FILAMENT)",
            "Filament AgxToneMapper(GOLDEN)",
            "agx_filament(c, GOLDEN_FILAMENT) on linear Rec.2020",
            true,
            |c| agx_filament(c, &AgxLook::GOLDEN_FILAMENT),
            |c| peers::filament_agx(c, FilamentAgxLook::Golden)
        ),
        case!(
            "filament_agx_graded",
            "Operator::AgxFilament(BASE)",
            "Filament ColorGrading + AgxToneMapper(NONE)",
            "Operator::AgxFilament(BASE).apply(c) on linear sRGB; Filament's 7-digit matrices",
            false,
            |c| Operator::AgxFilament(AgxLook::BASE).apply(c),
            |c| peers::filament_grade(c, |v| peers::filament_agx(v, FilamentAgxLook::None))
        ),
        case!(
            "filament_agx_golden_as_wrensch",
            "agx_filament(GOLDEN)",
            "Filament AgxToneMapper(GOLDEN)",
            "WRONG on purpose: Wrensch's golden (sat 0.8) for Filament's (sat 1.3)",
            false,
            |c| agx_filament(c, &AgxLook::GOLDEN),
            |c| peers::filament_agx(c, FilamentAgxLook::Golden)
        ),
        // bevy
        case!(
            "bevy_reinhard",
            "reinhard",
            "bevy Tonemapping::Reinhard",
            "reinhard per channel",
            true,
            |c| each(c, reinhard),
            peers::bevy_reinhard
        ),
        case!(
            "bevy_reinhard_luminance",
            "reinhard_luminance",
            "bevy Tonemapping::ReinhardLuminance",
            "reinhard_luminance(c) (bevy gives 0/0 at black)",
            true,
            |c| reinhard_luminance(c),
            peers::bevy_reinhard_luminance
        ),
        case!(
            "bevy_aces_fitted",
            "aces_hill",
            "bevy Tonemapping::AcesFitted",
            "aces_hill(c), no 1/0.6",
            true,
            |c| aces_hill(c),
            peers::bevy_aces_fitted
        ),
        case!(
            "bevy_pbr_neutral",
            "pbr_neutral",
            "bevy Tonemapping::PbrNeutral",
            "pbr_neutral(c)",
            true,
            |c| pbr_neutral(c),
            peers::bevy_pbr_neutral
        ),
        // Authors' code
        case!(
            "wrensch_agx",
            "agx_minimal(BASE)",
            "Wrensch 2023 agx/agxEotf",
            "agx_minimal(c, BASE)",
            true,
            |c| agx_minimal(c, &AgxLook::BASE),
            |c| peers::wrensch_agx(c, WrenschLook::Default)
        ),
        case!(
            "wrensch_agx_golden",
            "agx_minimal(GOLDEN)",
            "Wrensch 2023 agxLook golden",
            "agx_minimal(c, GOLDEN)",
            true,
            |c| agx_minimal(c, &AgxLook::GOLDEN),
            |c| peers::wrensch_agx(c, WrenschLook::Golden)
        ),
        case!(
            "wrensch_agx_punchy",
            "agx_minimal(PUNCHY)",
            "Wrensch 2023 agxLook punchy",
            "agx_minimal(c, PUNCHY)",
            true,
            |c| agx_minimal(c, &AgxLook::PUNCHY),
            |c| peers::wrensch_agx(c, WrenschLook::Punchy)
        ),
        case!(
            "hable_2010",
            "hable(UNCHARTED2)",
            "Hable 2010 Uncharted 2 shader, its pow(1/2.2) undone",
            "hable(16 c, UNCHARTED2) = peer^2.2 (the post's texColor *= 16)",
            true,
            |c| each(c, |x| hable(x * T::splat(16.0), &HableParams::UNCHARTED2)),
            |c| peers::hable_2010(c).map(|x| peers::saturate(x).powf(2.2))
        ),
        case!(
            "hable_2010_encoded",
            "hable(UNCHARTED2)",
            "Hable 2010 Uncharted 2 shader (with its pow 1/2.2)",
            "gamma_encode(hable(16 c, UNCHARTED2), 2.2)",
            false,
            |c| each(c, |x| color::gamma_encode(
                hable(x * T::splat(16.0), &HableParams::UNCHARTED2),
                T::splat(2.2)
            )),
            peers::hable_2010
        ),
        case!(
            "narkowicz_2015",
            "aces_narkowicz",
            "Narkowicz 2015 ACESFilm",
            "aces_narkowicz(x) per channel (original ACES exposure: aces_narkowicz(0.6 x))",
            true,
            |c| each(c, aces_narkowicz),
            peers::narkowicz_2015
        ),
        case!(
            "khronos_pbr_neutral",
            "pbr_neutral",
            "Khronos pbrNeutral.glsl (f5dc1011)",
            "pbr_neutral(c)",
            true,
            |c| pbr_neutral(c),
            peers::khronos_pbr_neutral
        ),
        case!(
            "reinhard_2002_eq3",
            "reinhard",
            "Reinhard 2002 eq. 3 per channel",
            "reinhard(x) per channel",
            true,
            |c| each(c, reinhard),
            |c| c.map(peers::reinhard_2002_eq3)
        ),
        case!(
            "reinhard_2002_eq4",
            "reinhard_extended(w = 4)",
            "Reinhard 2002 eq. 4 per channel, L_white = 4",
            "reinhard_extended(x, 4) per channel",
            true,
            |c| each(c, |x| reinhard_extended(x, T::splat(4.0))),
            |c| c.map(|x| peers::reinhard_2002_eq4(x, 4.0))
        ),
        case!(
            "reinhard_2002_luminance",
            "reinhard_luminance",
            "Reinhard 2002 eq. 3 on Rec.709 luminance, colour scaled by L_d / L",
            "reinhard_luminance(c)",
            true,
            |c| reinhard_luminance(c),
            |c| {
                let l = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
                let s = peers::reinhard_2002_eq3(l) / l;
                c.map(|x| x * s)
            }
        ),
        case!(
            "lottes_2016",
            "lottes(default_curve)",
            "Lottes 2016 (1.6, 0.977, 8, 0.18, 0.267)",
            "lottes(x, LottesParams::default_curve()) per channel",
            true,
            |c| {
                let p = LottesParams::default_curve();
                each(c, |x| lottes(x, &p))
            },
            |c| c.map(|x| peers::lottes_2016(x, 1.6, 0.977, 8.0, 0.18, 0.267))
        ),
        case!(
            "uchimura_2017",
            "uchimura(GRAN_TURISMO)",
            "Uchimura 2017 (1, 1, 0.22, 0.4, 1.33, 0)",
            "uchimura(x, GRAN_TURISMO) per channel",
            true,
            |c| each(c, |x| uchimura(x, &UchimuraParams::GRAN_TURISMO)),
            |c| c.map(|x| peers::uchimura_2017(x, 1.0, 1.0, 0.22, 0.4, 1.33, 0.0))
        ),
    ]
}

/// The case with this id.
pub fn case(id: &str) -> Case {
    cases()
        .into_iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("no case {id}"))
}

/// splitmix64: a deterministic generator, so every run and the report see the same grid.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Log-spaced values from `lo` to `hi`, `n` of them.
fn log_space(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f32> {
    (0..n).map(move |i| (lo.ln() + (hi.ln() - lo.ln()) * i as f64 / (n - 1) as f64).exp() as f32)
}

/// The points where some operator bends or switches branch: PBR Neutral's 0.08 and 0.76,
/// Uchimura's m = 0.22 and S0 = 0.532, the AgX encoding's ends 0.18 * 2^-10 and 0.18 * 2^6.5
/// (and their 1/0.6-scaled and Rec.2020 images roughly), Lottes' hdrMax 8 and 10, Hable's W / 2
/// = 5.6 (and / 16), Narkowicz reaching 1 at 7.24, three.js's 1/0.6 images of them.
const KNEES: [f64; 18] = [
    0.08,
    0.76,
    0.8,
    0.22,
    0.532,
    0.18 / 1024.0,
    0.18 * 90.509_667,
    8.0,
    10.0,
    5.6,
    0.35,
    7.24,
    0.048,
    0.456,
    1.0,
    0.6,
    2e-4,
    1e4,
];

/// The grid every case runs on (f32 colours, about 14,000):
/// - greys: 0; 3,000 log-spaced from 1e-6 to 1e4; 2,001 evenly spaced on [0, 2]; each knee in
///   [`KNEES`] and its neighbours 1, 2, 4 ulps and 1e-4 relative away;
/// - saturated colours: for 401 values x (400 log-spaced from 1e-4 to 1e4, and 0.5),
///   (x,0,0), (0,x,0), (0,0,x), (x,x,0), (x,0,x), (0,x,x), (x,0.01x,0), (0.01x,x,0),
///   (0,0.01x,x), (x,0.5x,0.01x);
/// - 3,000 random colours, each channel log-uniform in [1e-4, 1e4], 0 with probability 0.15;
/// - 1,000 random colours uniform in [0, 1.5]^3.
pub fn grid() -> Vec<[f32; 3]> {
    let mut g: Vec<[f32; 3]> = vec![[0.0; 3]];
    let mut greys: Vec<f32> = log_space(1e-6, 1e4, 3000).collect();
    greys.extend((0..=2000).map(|i| i as f32 * 1e-3));
    for k in KNEES {
        let k32 = k as f32;
        greys.push(k32);
        for d in [1u32, 2, 4] {
            greys.push(f32::from_bits(k32.to_bits() + d));
            greys.push(f32::from_bits(k32.to_bits() - d));
        }
        greys.push((k * (1.0 + 1e-4)) as f32);
        greys.push((k * (1.0 - 1e-4)) as f32);
    }
    g.extend(greys.iter().map(|&x| [x; 3]));
    let mut xs: Vec<f32> = log_space(1e-4, 1e4, 400).collect();
    xs.push(0.5);
    for x in xs {
        let h = 0.01 * x;
        g.extend([
            [x, 0.0, 0.0],
            [0.0, x, 0.0],
            [0.0, 0.0, x],
            [x, x, 0.0],
            [x, 0.0, x],
            [0.0, x, x],
            [x, h, 0.0],
            [h, x, 0.0],
            [0.0, h, x],
            [x, 0.5 * x, h],
        ]);
    }
    let mut rng = SplitMix(0x5eed_70e4_a9b1_0001);
    for _ in 0..3000 {
        let mut c = [0.0f32; 3];
        for ch in &mut c {
            let zero = rng.unit() < 0.15;
            let v = (1e-4f64.ln() + rng.unit() * (1e4f64.ln() - 1e-4f64.ln())).exp();
            *ch = if zero { 0.0 } else { v as f32 };
        }
        g.push(c);
    }
    for _ in 0..1000 {
        g.push([0; 3].map(|_: i32| (rng.unit() * 1.5) as f32));
    }
    g
}

fn clamp01(x: f32) -> f32 {
    peers::saturate(x)
}

fn update(w: &mut Worst, at: [f32; 3], ours: [f64; 3], peer: [f32; 3]) {
    for k in 0..3 {
        let p = f64::from(clamp01(peer[k]));
        // Ours is already in [0, 1]; a NaN from ours where the peer is finite must fail.
        let d = (ours[k] - p).abs();
        let d = if d.is_nan() { f64::INFINITY } else { d };
        if d > w.max || (d == w.max && w.max == 0.0 && w.at == [0.0; 3]) {
            *w = Worst {
                max: d,
                at,
                channel: k,
                ours: ours[k],
                peer: p,
            };
        }
    }
}

/// Runs `case` over [`grid`].
pub fn run(case: &Case) -> Stats {
    let mut s = Stats::default();
    for c in grid() {
        let peer = (case.peer_fn)(c);
        if peer.iter().any(|x| x.is_nan()) {
            s.peer_nan += 1;
            continue;
        }
        s.points += 1;
        let o64 = (case.ours64)(c.map(f64::from));
        let o32 = (case.ours32)(c).map(f64::from);
        update(&mut s.f64, c, o64, peer);
        update(&mut s.f32, c, o32, peer);
    }
    s
}

/// `brdf::tonemap::Exposure::from_ev100` against bevy's camera exposure exp2(-ev100) / 1.2
/// over EV100 in [-20, 30] (step 0.01): the largest relative difference.
pub fn bevy_exposure_max_rel() -> (f64, f64) {
    let mut worst = (0.0, 0.0);
    for i in 0..=5000 {
        let ev = (-20.0 + i as f64 * 0.01) as f32;
        let ours = brdf::tonemap::Exposure::from_ev100(f64::from(ev))
            .expect("finite EV100")
            .value();
        let peer = f64::from(peers::bevy_camera_exposure(ev));
        let rel = ((ours - peer) / ours).abs();
        if rel > worst.0 {
            worst = (rel, f64::from(ev));
        }
    }
    worst
}
