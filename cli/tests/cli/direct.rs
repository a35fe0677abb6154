//! Direct calls of every kernel in the table, written by hand from the crate's signatures
//! (not through the table's macro): `direct(path, args)` calls the function with the
//! arguments in the table's order, so a table entry that passes them in another order, or
//! to another function, disagrees with it.

use brdf::beckmann::{self, Beckmann};
use brdf::engine::{self, Convention};
use brdf::frame::{self, Frame};
use brdf::fresnel::ComplexIor;
use brdf::ggx::{self, Ggx};
use brdf::ibl::energy::{Albedo, AverageAlbedo, Reflectance};
use brdf::ibl::{dfg, energy, irradiance, prefilter};
use brdf::iridescence::{self, ThinFilm};
use brdf::layers::layered::Layered;
use brdf::layers::{anisotropy, clearcoat, sheen, specular};
use brdf::material::{self, DiffuseCoupling, MetallicRoughness};
use brdf::microfacet::Alpha;
use brdf::microfacet::{self, Microfacet};
use brdf::rough_dielectric::{self, Transport};
use brdf::tonemap::{self, AgxLook, HableParams, LottesParams, Operator, UchimuraParams};
use brdf::transmission::{self, Transmission, Volume};
use brdf::{Cosines, Real, V3, color, cook_torrance, diffuse, fresnel, lights, phong, sampling};

/// The scalar types the tests call `direct` with.
pub trait Scalar: Real<Scalar = Self> + Into<f64> {}
impl Scalar for f32 {}
impl Scalar for f64 {}

fn v<T: Scalar>(a: &[T], i: usize) -> V3<T> {
    V3::new(a[i], a[i + 1], a[i + 2])
}

/// The shading cosines n.v, n.l, n.h, v.h at `a[i..i + 4]` (the crate's one order).
fn c<T: Scalar>(a: &[T], i: usize) -> Cosines<T> {
    Cosines {
        n_dot_v: a[i],
        n_dot_l: a[i + 1],
        n_dot_h: a[i + 2],
        v_dot_h: a[i + 3],
    }
}

fn f<T: Scalar>(x: T) -> f64 {
    x.into()
}

fn idx<T: Scalar>(x: T) -> usize {
    let x = f(x);
    assert!(
        x >= 0.0 && x.fract() == 0.0,
        "a choice must be a non-negative integer"
    );
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let i = x as usize;
    i
}

/// The convention of choice `k` (an index into `engine::ALL`), spelled out constant by
/// constant so a reordered `ALL` disagrees with the table.
fn convention<T: Scalar>(k: T) -> Convention {
    match idx(k) {
        0 => engine::THREE_JS,
        1 => engine::FILAMENT,
        2 => engine::BEVY,
        3 => engine::UNREAL_4,
        4 => engine::KHRONOS_SAMPLE_VIEWER,
        c => panic!("no convention {c}"),
    }
}

/// The cosines at `a[i..i + 4]`.
fn cosines<T: Scalar>(a: &[T], i: usize) -> Cosines<T> {
    Cosines {
        n_dot_v: a[i],
        n_dot_l: a[i + 1],
        n_dot_h: a[i + 2],
        v_dot_h: a[i + 3],
    }
}

/// The layered material of the table's arguments at `a[0..22]`: the base (`a[0..5]`), then
/// sheen, clearcoat, anisotropy, iridescence (factor, film thickness and index),
/// transmission and volume (thickness, attenuation colour and distance).
fn layered<T: Scalar>(a: &[T]) -> Layered<T> {
    let film = ThinFilm::new(a[14], a[15]).expect("in-domain film");
    let volume = Volume::new(a[17], v(a, 18), a[21]).expect("in-domain volume");
    Layered::new(v(a, 0), a[3], a[4])
        .and_then(|m| m.with_sheen(v(a, 5), a[8]))
        .and_then(|m| m.with_clearcoat(a[9], a[10]))
        .and_then(|m| m.with_anisotropy(a[11], a[12]))
        .and_then(|m| m.with_iridescence(a[13], film))
        .and_then(|m| m.with_transmission(a[16]))
        .expect("in-domain material")
        .with_volume(volume)
}

fn three<T: Scalar>(w: V3<T>) -> Vec<T> {
    vec![w.x, w.y, w.z]
}

fn sample<T: Scalar>((w, p): (V3<T>, T)) -> Vec<T> {
    vec![w.x, w.y, w.z, p]
}

fn ggx<T: Scalar>(a: &[T], i: usize) -> Ggx<T> {
    Ggx::new(a[i], a[i + 1]).expect("in-domain alphas")
}

fn bk<T: Scalar>(a: &[T], i: usize) -> Beckmann<T> {
    Beckmann::new(a[i], a[i + 1]).expect("in-domain alphas")
}

/// The distribution of a `model, alpha_x, alpha_y` triple at `a[i..]`.
fn model<T: Scalar>(a: &[T], i: usize) -> Box<dyn Microfacet<T>> {
    match idx(a[i]) {
        0 => Box::new(ggx(a, i + 1)),
        1 => Box::new(bk(a, i + 1)),
        m => panic!("no model {m}"),
    }
}

/// The transport of choice `k`, spelled out so a reordered table disagrees.
fn transport<T: Scalar>(k: T) -> Transport {
    match idx(k) {
        0 => Transport::Radiance,
        1 => Transport::Importance,
        t => panic!("no transport {t}"),
    }
}

fn look(k: usize) -> AgxLook {
    match k {
        0 => AgxLook::BASE,
        1 => AgxLook::PUNCHY,
        2 => AgxLook::GOLDEN,
        3 => AgxLook::GOLDEN_FILAMENT,
        _ => panic!("no look {k}"),
    }
}

fn mr<T: Scalar>(a: &[T]) -> MetallicRoughness<T> {
    MetallicRoughness::new(v(a, 0), a[3], a[4]).expect("in-domain material")
}

fn sh9<T: Scalar>(a: &[T]) -> irradiance::Sh9<T> {
    irradiance::Sh9::from_coeffs(core::array::from_fn(|k| v(a, 3 * k)))
}

/// The kernel `path` on the arguments `a` (the table's order), or `None` for a path this
/// function does not know.
#[allow(clippy::too_many_lines)]
pub fn direct<T: Scalar>(path: &str, a: &[T]) -> Option<Vec<T>> {
    let out = match path {
        "frame::Frame::from_normal" => {
            let fr = Frame::from_normal(v(a, 0));
            vec![
                fr.t.x, fr.t.y, fr.t.z, fr.b.x, fr.b.y, fr.b.z, fr.n.x, fr.n.y, fr.n.z,
            ]
        }
        "frame::Frame::to_local" => three(Frame::from_normal(v(a, 0)).to_local(v(a, 3))),
        "frame::Frame::to_world" => three(Frame::from_normal(v(a, 0)).to_world(v(a, 3))),
        "frame::cos_theta" => vec![frame::cos_theta(v(a, 0))],
        "frame::cos2_theta" => vec![frame::cos2_theta(v(a, 0))],
        "frame::abs_cos_theta" => vec![frame::abs_cos_theta(v(a, 0))],
        "frame::sin2_theta" => vec![frame::sin2_theta(v(a, 0))],
        "frame::sin_theta" => vec![frame::sin_theta(v(a, 0))],
        "frame::tan2_theta" => vec![frame::tan2_theta(v(a, 0))],
        "frame::cos_phi" => vec![frame::cos_phi(v(a, 0))],
        "frame::sin_phi" => vec![frame::sin_phi(v(a, 0))],
        "frame::spherical_direction" => three(frame::spherical_direction(a[0], a[1])),
        "vec3::V3::dot" => vec![v(a, 0).dot(v(a, 3))],
        "vec3::V3::cross" => three(v(a, 0).cross(v(a, 3))),
        "vec3::V3::length_squared" => vec![v(a, 0).length_squared()],
        "vec3::V3::length" => vec![v(a, 0).length()],
        "vec3::V3::normalize" => three(v(a, 0).normalize()),
        "vec3::V3::normalize_or" => three(v(a, 0).normalize_or(v(a, 3))),
        "vec3::V3::mirror" => three(v(a, 0).mirror(v(a, 3))),
        "vec3::V3::min" => three(v(a, 0).min(v(a, 3))),
        "vec3::V3::max" => three(v(a, 0).max(v(a, 3))),
        "vec3::V3::abs" => three(v(a, 0).abs()),
        "vec3::V3::min_element" => vec![v(a, 0).min_element()],
        "vec3::V3::max_element" => vec![v(a, 0).max_element()],
        "fresnel::f0_from_ior" => vec![fresnel::f0_from_ior(a[0])],
        "fresnel::ior_from_f0" => vec![fresnel::ior_from_f0(a[0])],
        "fresnel::schlick" => vec![fresnel::schlick(a[0], a[1])],
        "fresnel::schlick_f90" => vec![fresnel::schlick_f90(a[0], a[1], a[2])],
        "fresnel::schlick_rgb" => three(fresnel::schlick_rgb(v(a, 0), a[3])),
        "fresnel::schlick_f90_rgb" => three(fresnel::schlick_f90_rgb(v(a, 0), v(a, 3), a[6])),
        "fresnel::schlick_sg" => vec![fresnel::schlick_sg(a[0], a[1])],
        "fresnel::dielectric_polarized" => {
            let (s, p) = fresnel::dielectric_polarized(a[0], a[1]);
            vec![s, p]
        }
        "fresnel::dielectric" => vec![fresnel::dielectric(a[0], a[1])],
        "fresnel::dielectric_fast" => vec![fresnel::dielectric_fast(a[0], a[1])],
        "fresnel::conductor" => vec![fresnel::conductor(a[0], a[1], a[2])],
        "fresnel::conductor_fast" => vec![fresnel::conductor_fast(a[0], a[1], a[2])],
        "fresnel::conductor_rgb" => three(fresnel::conductor_rgb(a[0], v(a, 1), v(a, 4))),
        "fresnel::schlick_f82" => vec![fresnel::schlick_f82(a[0], a[1], a[2])],
        "fresnel::schlick_f82_rgb" => three(fresnel::schlick_f82_rgb(v(a, 0), v(a, 3), a[6])),
        "fresnel::average_dielectric" => vec![T::splat(fresnel::average_dielectric(f(a[0])))],
        "fresnel::average_dielectric_fit" => vec![fresnel::average_dielectric_fit(a[0])],
        "microfacet::alpha_from_perceptual" => vec![microfacet::alpha_from_perceptual(a[0])],
        "microfacet::perceptual_from_alpha" => vec![microfacet::perceptual_from_alpha(a[0])],
        "ggx::d" => vec![ggx::d(a[0], a[1])],
        "ggx::d_fast" => vec![ggx::d_fast(a[0], a[1])],
        "ggx::d_aniso" => vec![ggx::d_aniso(a[0], a[1], a[2], a[3], a[4])],
        "ggx::lambda" => vec![ggx::lambda(a[0], a[1])],
        "ggx::g1" => vec![ggx::g1(a[0], a[1])],
        "ggx::v_correlated" => vec![ggx::v_correlated(a[0], a[1], a[2])],
        "ggx::v_correlated_hammon" => vec![ggx::v_correlated_hammon(a[0], a[1], a[2])],
        "ggx::v_correlated_fast" => vec![ggx::v_correlated_fast(a[0], a[1], a[2])],
        "ggx::g1_schlick" => vec![ggx::g1_schlick(a[0], a[1])],
        "ggx::schlick_k_ibl" => vec![ggx::schlick_k_ibl(a[0])],
        "ggx::schlick_k_analytic" => vec![ggx::schlick_k_analytic(a[0])],
        "ggx::v_schlick" => vec![ggx::v_schlick(a[0], a[1], a[2])],
        "ggx::Ggx::d" => vec![ggx(a, 0).d(v(a, 2))],
        "ggx::Ggx::lambda" => vec![ggx(a, 0).lambda(v(a, 2))],
        "ggx::Ggx::cos_lambda" => vec![ggx(a, 0).cos_lambda(v(a, 2))],
        "ggx::Ggx::g1" => vec![ggx(a, 0).g1(v(a, 2))],
        "ggx::Ggx::g2_correlated" => vec![ggx(a, 0).g2_correlated(v(a, 2), v(a, 5))],
        "ggx::Ggx::g2_separable" => vec![ggx(a, 0).g2_separable(v(a, 2), v(a, 5))],
        "ggx::Ggx::v_correlated" => vec![ggx(a, 0).v_correlated(v(a, 2), v(a, 5))],
        "ggx::Ggx::d_visible" => vec![ggx(a, 0).d_visible(v(a, 2), v(a, 5))],
        "beckmann::d" => vec![beckmann::d(a[0], a[1])],
        "beckmann::d_fast" => vec![beckmann::d_fast(a[0], a[1])],
        "beckmann::a_of" => vec![beckmann::a_of(a[0], a[1])],
        "beckmann::lambda" => vec![beckmann::lambda(a[0], a[1])],
        "beckmann::g1" => vec![beckmann::g1(a[0], a[1])],
        "beckmann::lambda_walter" => vec![beckmann::lambda_walter(a[0], a[1])],
        "beckmann::alpha_from_blinn_phong" => vec![beckmann::alpha_from_blinn_phong(a[0])],
        "beckmann::blinn_phong_from_alpha" => vec![beckmann::blinn_phong_from_alpha(a[0])],
        "beckmann::Beckmann::d" => vec![bk(a, 0).d(v(a, 2))],
        "beckmann::Beckmann::lambda" => vec![bk(a, 0).lambda(v(a, 2))],
        "beckmann::Beckmann::cos_lambda" => vec![bk(a, 0).cos_lambda(v(a, 2))],
        "beckmann::Beckmann::g1" => vec![bk(a, 0).g1(v(a, 2))],
        "beckmann::Beckmann::g2_correlated" => vec![bk(a, 0).g2_correlated(v(a, 2), v(a, 5))],
        "beckmann::Beckmann::g2_separable" => vec![bk(a, 0).g2_separable(v(a, 2), v(a, 5))],
        "beckmann::Beckmann::v_correlated" => vec![bk(a, 0).v_correlated(v(a, 2), v(a, 5))],
        "beckmann::Beckmann::d_visible" => vec![bk(a, 0).d_visible(v(a, 2), v(a, 5))],
        "cook_torrance::half_vector" => {
            let (h, c) = cook_torrance::half_vector(v(a, 0), v(a, 3));
            vec![h.x, h.y, h.z, c]
        }
        "cook_torrance::half_cosines" => {
            let (nh, vh) = cook_torrance::half_cosines(v(a, 0), v(a, 3));
            vec![nh, vh]
        }
        "cook_torrance::eval" => {
            let fr = a[9];
            vec![cook_torrance::eval(
                model(a, 0).as_ref(),
                v(a, 3),
                v(a, 6),
                |_| fr,
            )]
        }
        "cook_torrance::dielectric" => {
            vec![cook_torrance::dielectric(
                model(a, 0).as_ref(),
                v(a, 3),
                v(a, 6),
                a[9],
            )]
        }
        "cook_torrance::conductor" => {
            vec![cook_torrance::conductor(
                model(a, 0).as_ref(),
                v(a, 3),
                v(a, 6),
                a[9],
                a[10],
            )]
        }
        "cook_torrance::eval_rgb" => {
            let fr = v(a, 9);
            three(cook_torrance::eval_rgb(
                model(a, 0).as_ref(),
                v(a, 3),
                v(a, 6),
                |_| fr,
            ))
        }
        "cook_torrance::ggx" => vec![cook_torrance::ggx(c(a, 0), Alpha(a[4]), a[5])],
        "cook_torrance::beckmann" => vec![cook_torrance::beckmann(c(a, 0), Alpha(a[4]), a[5])],
        "cook_torrance::ggx_conductor_rgb" => three(cook_torrance::ggx_conductor_rgb(
            c(a, 0),
            Alpha(a[4]),
            ComplexIor {
                eta: v(a, 5),
                k: v(a, 8),
            },
        )),
        "cook_torrance::ggx_conductor_rgb_fast" => three(cook_torrance::ggx_conductor_rgb_fast(
            c(a, 0),
            Alpha(a[4]),
            ComplexIor {
                eta: v(a, 5),
                k: v(a, 8),
            },
        )),
        "cook_torrance::ggx_conductor_local" => vec![cook_torrance::ggx_conductor_local(
            v(a, 0),
            v(a, 3),
            Alpha(a[6]),
            a[7],
            a[8],
        )],
        "cook_torrance::ggx_conductor_local_fast" => {
            vec![cook_torrance::ggx_conductor_local_fast(
                v(a, 0),
                v(a, 3),
                Alpha(a[6]),
                a[7],
                a[8],
            )]
        }
        "cook_torrance::ggx_schlick_rgb" => three(cook_torrance::ggx_schlick_rgb(
            c(a, 0),
            Alpha(a[4]),
            v(a, 5),
        )),
        "cook_torrance::ggx_dielectric" => {
            vec![cook_torrance::ggx_dielectric(c(a, 0), Alpha(a[4]), a[5])]
        }
        "cook_torrance::ggx_dielectric_fast" => {
            vec![cook_torrance::ggx_dielectric_fast(
                c(a, 0),
                Alpha(a[4]),
                a[5],
            )]
        }
        "cook_torrance::beckmann_conductor_rgb" => three(cook_torrance::beckmann_conductor_rgb(
            c(a, 0),
            Alpha(a[4]),
            ComplexIor {
                eta: v(a, 5),
                k: v(a, 8),
            },
        )),
        "cook_torrance::beckmann_schlick_rgb" => three(cook_torrance::beckmann_schlick_rgb(
            c(a, 0),
            Alpha(a[4]),
            v(a, 5),
        )),
        "cook_torrance::beckmann_dielectric" => {
            vec![cook_torrance::beckmann_dielectric(
                c(a, 0),
                Alpha(a[4]),
                a[5],
            )]
        }
        "sampling::cosine_hemisphere" => sample(sampling::cosine_hemisphere(a[0], a[1])),
        "sampling::cosine_hemisphere_pdf" => vec![sampling::cosine_hemisphere_pdf(v(a, 0))],
        "sampling::reflect_pdf" => vec![sampling::reflect_pdf(a[0], a[1])],
        "sampling::ggx_d_cos" => sample(sampling::ggx_d_cos(&ggx(a, 0), a[2], a[3])),
        "sampling::beckmann_d_cos" => sample(sampling::beckmann_d_cos(&bk(a, 0), a[2], a[3])),
        "sampling::d_cos_pdf" => vec![sampling::d_cos_pdf(model(a, 0).as_ref(), v(a, 3))],
        "sampling::visible_normal_pdf" => {
            vec![sampling::visible_normal_pdf(
                model(a, 0).as_ref(),
                v(a, 3),
                v(a, 6),
            )]
        }
        "sampling::ggx_vndf" => sample(sampling::ggx_vndf(&ggx(a, 0), v(a, 2), a[5], a[6])),
        "sampling::ggx_vndf_spherical_cap" => sample(sampling::ggx_vndf_spherical_cap(
            &ggx(a, 0),
            v(a, 2),
            a[5],
            a[6],
        )),
        "sampling::erf_inv" => vec![sampling::erf_inv(a[0])],
        "sampling::beckmann_vndf" => {
            sample(sampling::beckmann_vndf(&bk(a, 0), v(a, 2), a[5], a[6]))
        }
        "sampling::ggx_reflection" => {
            let fr = a[7];
            let (w, p, wt) = sampling::ggx_reflection(&ggx(a, 0), v(a, 2), a[5], a[6], |_| fr);
            vec![w.x, w.y, w.z, p, wt]
        }
        "sampling::ggx_reflection_rgb" => {
            let fr = v(a, 7);
            let (w, p, wt) = sampling::ggx_reflection_rgb(&ggx(a, 0), v(a, 2), a[5], a[6], |_| fr);
            vec![w.x, w.y, w.z, p, wt.x, wt.y, wt.z]
        }
        "sampling::ggx_reflection_pdf" => {
            vec![sampling::ggx_reflection_pdf(&ggx(a, 0), v(a, 2), v(a, 5))]
        }
        "sampling::beckmann_reflection" => {
            let fr = a[7];
            let (w, p, wt) = sampling::beckmann_reflection(&bk(a, 0), v(a, 2), a[5], a[6], |_| fr);
            vec![w.x, w.y, w.z, p, wt]
        }
        "sampling::beckmann_reflection_rgb" => {
            let fr = v(a, 7);
            let (w, p, wt) =
                sampling::beckmann_reflection_rgb(&bk(a, 0), v(a, 2), a[5], a[6], |_| fr);
            vec![w.x, w.y, w.z, p, wt.x, wt.y, wt.z]
        }
        "rough_dielectric::half_vector" => {
            three(rough_dielectric::half_vector(v(a, 0), v(a, 3), a[6]))
        }
        "rough_dielectric::eval" => vec![rough_dielectric::eval(
            model(a, 0).as_ref(),
            v(a, 3),
            v(a, 6),
            a[9],
            transport(a[10]),
        )],
        "rough_dielectric::pdf" => vec![rough_dielectric::pdf(
            model(a, 0).as_ref(),
            v(a, 3),
            v(a, 6),
            a[9],
        )],
        "rough_dielectric::ggx_sample" => {
            let (w, p, wt) = rough_dielectric::ggx_sample(
                &ggx(a, 0),
                v(a, 2),
                a[5],
                a[6],
                a[7],
                a[8],
                transport(a[9]),
            );
            vec![w.x, w.y, w.z, p, wt]
        }
        "rough_dielectric::beckmann_sample" => {
            let (w, p, wt) = rough_dielectric::beckmann_sample(
                &bk(a, 0),
                v(a, 2),
                a[5],
                a[6],
                a[7],
                a[8],
                transport(a[9]),
            );
            vec![w.x, w.y, w.z, p, wt]
        }
        "transmission::Volume::transmittance" => three(
            Volume::new(a[0], v(a, 1), a[4])
                .expect("in-domain volume")
                .transmittance(a[5]),
        ),
        "transmission::Volume::attenuation_coefficient" => three(
            Volume::new(a[0], v(a, 1), a[4])
                .expect("in-domain volume")
                .attenuation_coefficient(),
        ),
        "transmission::thin_walled_btdf" => {
            vec![transmission::thin_walled_btdf(&ggx(a, 0), v(a, 2), v(a, 5))]
        }
        "transmission::dielectric_bsdf" => three(transmission::dielectric_bsdf(
            &ggx(a, 0),
            v(a, 2),
            v(a, 5),
            v(a, 8),
            a[11],
            &Transmission::new(a[12]).expect("in-domain transmission"),
            &Volume::new(a[13], v(a, 14), a[17]).expect("in-domain volume"),
        )),
        "iridescence::dielectric" => three(iridescence::dielectric(
            &ThinFilm::new(a[0], a[1]).expect("in-domain film"),
            a[2],
            a[3],
            a[4],
        )),
        "iridescence::conductor" => three(iridescence::conductor(
            &ThinFilm::new(a[0], a[1]).expect("in-domain film"),
            a[2],
            a[3],
            a[4],
            a[5],
        )),
        "sampling::beckmann_reflection_pdf" => {
            vec![sampling::beckmann_reflection_pdf(
                &bk(a, 0),
                v(a, 2),
                v(a, 5),
            )]
        }
        "diffuse::lambert" => vec![diffuse::lambert(a[0], a[1], a[2])],
        "diffuse::Lambert::eval" => {
            vec![diffuse::Lambert::new(a[0]).unwrap().eval(v(a, 1), v(a, 4))]
        }
        "diffuse::oren_nayar_a" => vec![diffuse::oren_nayar_a(a[0])],
        "diffuse::oren_nayar_b" => vec![diffuse::oren_nayar_b(a[0])],
        "diffuse::oren_nayar" => vec![diffuse::oren_nayar(a[0], a[1], a[2], a[3], a[4])],
        "diffuse::OrenNayar::eval" => {
            vec![
                diffuse::OrenNayar::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "diffuse::oren_nayar_full" => vec![diffuse::oren_nayar_full(a[0], a[1], a[2], a[3], a[4])],
        "diffuse::OrenNayarFull::eval" => {
            vec![
                diffuse::OrenNayarFull::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "diffuse::oren_nayar_fujii" => {
            vec![diffuse::oren_nayar_fujii(a[0], a[1], a[2], a[3], a[4])]
        }
        "diffuse::OrenNayarFujii::eval" => {
            vec![
                diffuse::OrenNayarFujii::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "diffuse::eon" => vec![diffuse::eon(a[0], a[1], a[2], a[3], a[4])],
        "diffuse::eon_approx" => vec![diffuse::eon_approx(a[0], a[1], a[2], a[3], a[4])],
        "diffuse::eon_fon_albedo" => vec![diffuse::eon_fon_albedo(a[0], a[1])],
        "diffuse::eon_fon_albedo_approx" => vec![diffuse::eon_fon_albedo_approx(a[0], a[1])],
        "diffuse::eon_fon_average_albedo" => vec![diffuse::eon_fon_average_albedo(a[0])],
        "diffuse::eon_multiscatter_albedo" => vec![diffuse::eon_multiscatter_albedo(a[0], a[1])],
        "diffuse::eon_albedo" => vec![diffuse::eon_albedo(a[0], a[1], a[2])],
        "diffuse::eon_albedo_approx" => vec![diffuse::eon_albedo_approx(a[0], a[1], a[2])],
        "diffuse::eon_cltc_sample" => sample(diffuse::eon_cltc_sample(v(a, 0), a[3], a[4], a[5])),
        "diffuse::eon_cltc_pdf" => vec![diffuse::eon_cltc_pdf(v(a, 0), v(a, 3), a[6])],
        "diffuse::eon_sample" => sample(diffuse::eon_sample(v(a, 0), a[3], a[4], a[5])),
        "diffuse::eon_pdf" => vec![diffuse::eon_pdf(v(a, 0), v(a, 3), a[6])],
        "diffuse::Eon::eval" => vec![
            diffuse::Eon::new(a[0], a[1])
                .unwrap()
                .eval(v(a, 2), v(a, 5)),
        ],
        "diffuse::Eon::eval_approx" => {
            vec![
                diffuse::Eon::new(a[0], a[1])
                    .unwrap()
                    .eval_approx(v(a, 2), v(a, 5)),
            ]
        }
        "diffuse::Eon::albedo" => vec![diffuse::Eon::new(a[0], a[1]).unwrap().albedo(v(a, 2))],
        "diffuse::Eon::albedo_approx" => {
            vec![
                diffuse::Eon::new(a[0], a[1])
                    .unwrap()
                    .albedo_approx(v(a, 2)),
            ]
        }
        "diffuse::Eon::sample" => sample(diffuse::Eon::new(a[0], a[1]).unwrap().sample(
            v(a, 2),
            a[5],
            a[6],
        )),
        "diffuse::Eon::pdf" => vec![diffuse::Eon::new(a[0], a[1]).unwrap().pdf(v(a, 2), v(a, 5))],
        "diffuse::burley" => vec![diffuse::burley(a[0], a[1], a[2], a[3], a[4])],
        "diffuse::burley_renormalized" => {
            vec![diffuse::burley_renormalized(a[0], a[1], a[2], a[3], a[4])]
        }
        "diffuse::Burley::eval" => {
            vec![
                diffuse::Burley::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "diffuse::BurleyRenormalized::eval" => {
            vec![
                diffuse::BurleyRenormalized::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "diffuse::fresnel_weight_normalized" => {
            vec![diffuse::fresnel_weight_normalized(a[0], a[1])]
        }
        "diffuse::fresnel_weight_symmetric" => vec![diffuse::fresnel_weight_symmetric(a[0], a[1])],
        "diffuse::fresnel_mix" => vec![diffuse::fresnel_mix(a[0], a[1], a[2])],
        "diffuse::fresnel_mix_schlick" => {
            vec![diffuse::fresnel_mix_schlick(a[0], a[1], a[2], a[3])]
        }
        "diffuse::shirley_coupled" => vec![diffuse::shirley_coupled(a[0], a[1], a[2], a[3])],
        "diffuse::ashikhmin_shirley" => vec![diffuse::ashikhmin_shirley(a[0], a[1], a[2], a[3])],
        "diffuse::ShirleyCoupled::eval" => {
            vec![
                diffuse::ShirleyCoupled::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "diffuse::AshikhminShirley::eval" => {
            vec![
                diffuse::AshikhminShirley::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "phong::phong_normalization" => vec![phong::phong_normalization(a[0])],
        "phong::blinn_phong_normalization_exact" => {
            vec![phong::blinn_phong_normalization_exact(a[0])]
        }
        "phong::blinn_phong_normalization_approx" => {
            vec![phong::blinn_phong_normalization_approx(a[0])]
        }
        "phong::classic" => vec![phong::classic(a[0], a[1], a[2], a[3], a[4])],
        "phong::modified" => vec![phong::modified(a[0], a[1], a[2], a[3], a[4])],
        "phong::normalized" => vec![phong::normalized(a[0], a[1], a[2], a[3], a[4])],
        "phong::diffuse_specular" => {
            vec![phong::diffuse_specular(a[0], a[1], a[2], a[3], a[4], a[5])]
        }
        "phong::blinn_phong" => vec![phong::blinn_phong(a[0], a[1], a[2], a[3], a[4])],
        "phong::blinn_phong_normalized" => {
            vec![phong::blinn_phong_normalized(a[0], a[1], a[2], a[3], a[4])]
        }
        "phong::blinn_phong_normalized_approx" => {
            vec![phong::blinn_phong_normalized_approx(
                a[0], a[1], a[2], a[3], a[4],
            )]
        }
        "phong::blinn_phong_ndf" => vec![phong::blinn_phong_ndf(a[0], a[1])],
        "phong::ClassicPhong::eval" => {
            vec![
                phong::ClassicPhong::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "phong::ModifiedPhong::eval" => {
            vec![
                phong::ModifiedPhong::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "phong::NormalizedPhong::eval" => {
            vec![
                phong::NormalizedPhong::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "phong::BlinnPhong::eval" => {
            vec![
                phong::BlinnPhong::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "phong::NormalizedBlinnPhong::eval" => {
            vec![
                phong::NormalizedBlinnPhong::new(a[0], a[1])
                    .unwrap()
                    .eval(v(a, 2), v(a, 5)),
            ]
        }
        "phong::ApproxNormalizedBlinnPhong::eval" => vec![
            phong::ApproxNormalizedBlinnPhong::new(a[0], a[1])
                .unwrap()
                .eval(v(a, 2), v(a, 5)),
        ],
        "phong::PhongDiffuseSpecular::eval" => vec![
            phong::PhongDiffuseSpecular::new(a[0], a[1], a[2])
                .unwrap()
                .eval(v(a, 3), v(a, 6)),
        ],
        "material::f0_from_reflectance" => vec![material::f0_from_reflectance(a[0])],
        "material::metallic_roughness" => {
            let coupling = match idx(a[10]) {
                0 => DiffuseCoupling::Gltf,
                1 => DiffuseCoupling::OneMinusF,
                2 => DiffuseCoupling::Additive,
                c => panic!("no coupling {c}"),
            };
            three(material::metallic_roughness(
                c(a, 0),
                v(a, 4),
                a[7],
                a[8],
                a[9],
                coupling,
            ))
        }
        "material::metallic_roughness_fast" => {
            let coupling = match idx(a[10]) {
                0 => DiffuseCoupling::Gltf,
                1 => DiffuseCoupling::OneMinusF,
                2 => DiffuseCoupling::Additive,
                c => panic!("no coupling {c}"),
            };
            three(material::metallic_roughness_fast(
                c(a, 0),
                v(a, 4),
                a[7],
                a[8],
                a[9],
                coupling,
            ))
        }
        "material::gltf" => three(material::gltf(c(a, 0), v(a, 4), a[7], a[8])),
        "material::gltf_fast" => three(material::gltf_fast(c(a, 0), v(a, 4), a[7], a[8])),
        "material::MetallicRoughness::eval" => three(mr(a).eval(v(a, 5), v(a, 8))),
        "material::MetallicRoughness::eval_fast" => three(mr(a).eval_fast(v(a, 5), v(a, 8))),
        "material::MetallicRoughness::specular_probability" => {
            vec![mr(a).specular_probability(v(a, 5))]
        }
        "material::MetallicRoughness::pdf" => vec![mr(a).pdf(v(a, 5), v(a, 8))],
        "material::MetallicRoughness::sample" => sample(mr(a).sample(v(a, 5), a[8], a[9])),
        "material::MetallicRoughness::sample_weighted" => {
            let (w, p, wt) = mr(a).sample_weighted(v(a, 5), a[8], a[9]);
            vec![w.x, w.y, w.z, p, wt.x, wt.y, wt.z]
        }
        "layers::sheen::d_charlie" => vec![sheen::d_charlie(a[0], a[1])],
        "layers::sheen::lambda_charlie" => vec![sheen::lambda_charlie(a[0], a[1])],
        "layers::sheen::v_charlie" => vec![sheen::v_charlie(a[0], a[1], a[2])],
        "layers::sheen::v_neubelt" => vec![sheen::v_neubelt(a[0], a[1])],
        "layers::sheen::d_ashikhmin" => vec![sheen::d_ashikhmin(a[0], a[1])],
        "layers::sheen::charlie" => three(sheen::charlie(c(a, 0), v(a, 4), a[7])),
        "layers::sheen::albedo" => vec![sheen::albedo(a[0], a[1])],
        "layers::sheen::albedo_fit_materialx" => vec![sheen::albedo_fit_materialx(a[0], a[1])],
        "layers::sheen::albedo_fit_threejs" => vec![sheen::albedo_fit_threejs(a[0], a[1])],
        "layers::sheen::albedo_scaling" => vec![sheen::albedo_scaling(v(a, 0), a[3], a[4])],
        "layers::clearcoat::fresnel" => vec![clearcoat::fresnel(a[0])],
        "layers::clearcoat::v_kelemen" => vec![clearcoat::v_kelemen(a[0])],
        "layers::clearcoat::coat" => vec![clearcoat::coat(c(a, 0), a[4])],
        "layers::clearcoat::coat_kelemen" => vec![clearcoat::coat_kelemen(c(a, 0), a[4])],
        "layers::clearcoat::layer" => three(clearcoat::layer(v(a, 0), a[3], a[4], a[5])),
        "layers::specular::f0_from_ior" => vec![specular::f0_from_ior(a[0])],
        "layers::specular::dielectric_f0" => three(specular::dielectric_f0(a[0], a[1], v(a, 2))),
        "layers::anisotropy::alpha_t" => vec![anisotropy::alpha_t(a[0], a[1])],
        "layers::anisotropy::direction" => three(anisotropy::direction(a[0], a[1], a[2])),
        "layers::anisotropy::bent_reflection" => three(anisotropy::bent_reflection(
            v(a, 0),
            v(a, 3),
            v(a, 6),
            a[9],
            a[10],
        )),
        "layers::layered::Layered::eval" => three(layered(a).eval(v(a, 22), v(a, 25))),
        "layers::layered::Layered::lobe_probabilities" => {
            three(layered(a).lobe_probabilities(v(a, 22)))
        }
        "layers::layered::Layered::pdf" => vec![layered(a).pdf(v(a, 22), v(a, 25))],
        "layers::layered::Layered::sample" => sample(layered(a).sample(v(a, 22), a[25], a[26])),
        "lights::radiance" => vec![lights::radiance(a[0], a[1], a[2])],
        "lights::radiance_pi" => vec![lights::radiance_pi(a[0], a[1], a[2])],
        "lights::radiance_pi_rgb" => three(lights::radiance_pi_rgb(v(a, 0), v(a, 3), a[6])),
        "lights::irradiance" => vec![lights::irradiance(a[0], a[1])],
        "lights::inverse_square" => vec![lights::inverse_square(a[0], a[1])],
        "lights::windowed" => vec![lights::windowed(a[0], a[1])],
        "lights::windowed_inverse_square" => {
            vec![lights::windowed_inverse_square(a[0], a[1], a[2])]
        }
        "lights::polynomial" => vec![lights::polynomial(a[0], a[1], a[2], a[3])],
        "lights::spot_cone" => vec![lights::spot_cone(a[0], a[1], a[2])],
        "lights::SpotCone::eval" => vec![lights::SpotCone::new(a[0], a[1]).unwrap().eval(a[2])],
        "ibl::dfg::karis_mobile" => dfg::karis_mobile(a[0], a[1]).to_vec(),
        "ibl::dfg::karis_mobile_nonmetal" => vec![dfg::karis_mobile_nonmetal(a[0], a[1])],
        "ibl::dfg::lazarov" => dfg::lazarov(a[0], a[1]).to_vec(),
        "ibl::dfg::narkowicz_lazarov" => dfg::narkowicz_lazarov(a[0], a[1]).to_vec(),
        "ibl::dfg::narkowicz_polynomial" => dfg::narkowicz_polynomial(a[0], a[1]).to_vec(),
        "ibl::dfg::specular_filament" => {
            three(dfg::specular_filament(v(a, 0), v(a, 3), a[6], a[7]))
        }
        "ibl::dfg::specular" => three(dfg::specular(v(a, 0), v(a, 3), a[6], a[7], a[8])),
        "ibl::dfg::mip_from_roughness_linear" => vec![dfg::mip_from_roughness_linear(a[0], a[1])],
        "ibl::dfg::roughness_from_mip_linear" => vec![dfg::roughness_from_mip_linear(a[0], a[1])],
        "ibl::dfg::lod_from_roughness_filament" => {
            vec![dfg::lod_from_roughness_filament(a[0], a[1])]
        }
        "ibl::dfg::roughness_from_lod_filament" => {
            vec![dfg::roughness_from_lod_filament(a[0], a[1])]
        }
        "ibl::dfg::mip_from_roughness_ue4" => vec![dfg::mip_from_roughness_ue4(a[0], a[1])],
        "ibl::dfg::roughness_from_mip_ue4" => vec![dfg::roughness_from_mip_ue4(a[0], a[1])],
        "ibl::prefilter::pdf" => vec![prefilter::pdf(v(a, 0), a[3])],
        "ibl::prefilter::sample_from" => {
            let s = prefilter::sample_from(a[0], a[1], a[2]);
            vec![s.dir.x, s.dir.y, s.dir.z, s.weight, s.pdf]
        }
        "ibl::prefilter::mip_level" => vec![prefilter::mip_level(a[0], a[1], a[2])],
        "ibl::energy::e_ggx" => vec![energy::e_ggx(a[0], a[1])],
        "ibl::energy::e_avg_ggx" => vec![energy::e_avg_ggx(a[0])],
        "ibl::energy::kulla_conty_lobe" => vec![energy::kulla_conty_lobe(
            Albedo(a[0]),
            Albedo(a[1]),
            AverageAlbedo(a[2]),
        )],
        "ibl::energy::kulla_conty_fresnel" => vec![energy::kulla_conty_fresnel(
            Reflectance(a[0]),
            AverageAlbedo(a[1]),
        )],
        "ibl::energy::fresnel_avg_schlick" => vec![energy::fresnel_avg_schlick(a[0], a[1])],
        "ibl::energy::fresnel_avg_conductor" => {
            vec![T::splat(energy::fresnel_avg_conductor(f(a[0]), f(a[1])))]
        }
        "ibl::energy::kulla_conty_ggx" => vec![energy::kulla_conty_ggx(a[0], a[1], a[2], a[3])],
        "ibl::energy::kulla_conty_ggx_rgb" => {
            three(energy::kulla_conty_ggx_rgb(a[0], a[1], a[2], v(a, 3)))
        }
        "ibl::energy::turquin_scale" => {
            vec![energy::turquin_scale(Albedo(a[0]), Reflectance(a[1]))]
        }
        "ibl::energy::fdez_aguera_ms" => vec![energy::fdez_aguera_ms(
            a[0],
            Albedo(a[1]),
            Reflectance(a[2]),
        )],
        "ibl::energy::fdez_aguera" => {
            let (s, m) = energy::fdez_aguera(a[0], a[1], a[2]);
            vec![s, m]
        }
        "ibl::irradiance::sh9_basis" => irradiance::sh9_basis(v(a, 0)).to_vec(),
        "ibl::irradiance::Sh9::eval" => three(sh9(a).eval(v(a, 27))),
        "ibl::irradiance::Sh9::irradiance" => three(sh9(a).irradiance(v(a, 27))),
        "tonemap::sanitize" => vec![tonemap::sanitize(a[0])],
        "tonemap::exposure_curve" => vec![tonemap::exposure_curve(a[0], a[1])],
        "tonemap::reinhard" => vec![tonemap::reinhard(a[0])],
        "tonemap::reinhard_extended" => vec![tonemap::reinhard_extended(a[0], a[1])],
        "tonemap::reinhard_luminance" => three(tonemap::reinhard_luminance(v(a, 0))),
        "tonemap::reinhard_extended_luminance" => {
            three(tonemap::reinhard_extended_luminance(v(a, 0), a[3]))
        }
        "tonemap::reinhard_jodie" => three(tonemap::reinhard_jodie(v(a, 0))),
        "tonemap::aces_narkowicz" => vec![tonemap::aces_narkowicz(a[0])],
        "tonemap::aces_hill" => three(tonemap::aces_hill(v(a, 0))),
        "tonemap::hable" => {
            let p = HableParams::new(
                f(a[1]),
                f(a[2]),
                f(a[3]),
                f(a[4]),
                f(a[5]),
                f(a[6]),
                f(a[7]),
                f(a[8]),
            )
            .unwrap();
            vec![tonemap::hable(a[0], &p)]
        }
        "tonemap::lottes" => {
            let p = LottesParams::new(f(a[1]), f(a[2]), f(a[3]), f(a[4]), f(a[5])).unwrap();
            vec![tonemap::lottes(a[0], &p)]
        }
        "tonemap::uchimura" => {
            let p = UchimuraParams {
                max_brightness: f(a[1]),
                contrast: f(a[2]),
                linear_start: f(a[3]),
                linear_length: f(a[4]),
                black: f(a[5]),
                pedestal: f(a[6]),
            };
            vec![tonemap::uchimura(a[0], &p)]
        }
        "tonemap::pbr_neutral" => three(tonemap::pbr_neutral(v(a, 0))),
        "tonemap::agx_minimal" => three(tonemap::agx_minimal(v(a, 0), &look(idx(a[3])))),
        "tonemap::agx_threejs" => three(tonemap::agx_threejs(v(a, 0))),
        "tonemap::agx_filament" => three(tonemap::agx_filament(v(a, 0), &look(idx(a[3])))),
        "engine::Convention::alpha" => vec![convention(a[0]).alpha(a[1])],
        "engine::Convention::f90" => vec![convention(a[0]).f90(v(a, 1))],
        "engine::Convention::fresnel" => three(convention(a[0]).fresnel(v(a, 1), a[4], a[5])),
        "engine::Convention::specular" => {
            three(convention(a[0]).specular(cosines(a, 1), a[5], v(a, 6), a[9]))
        }
        "engine::Convention::diffuse" => {
            three(convention(a[0]).diffuse(cosines(a, 1), a[5], v(a, 6)))
        }
        "engine::Convention::brdf" => {
            three(convention(a[0]).brdf(cosines(a, 1), v(a, 5), a[8], a[9]))
        }
        "tonemap::Operator::apply" => three(Operator::all()[idx(a[0])].apply(v(a, 1))),
        "tonemap::ev100_from_camera" => {
            vec![T::splat(tonemap::ev100_from_camera(
                f(a[0]),
                f(a[1]),
                f(a[2]),
            ))]
        }
        "color::luminance" => vec![color::luminance(v(a, 0))],
        "color::mul" => {
            let m = [
                [f(a[0]), f(a[1]), f(a[2])],
                [f(a[3]), f(a[4]), f(a[5])],
                [f(a[6]), f(a[7]), f(a[8])],
            ];
            three(color::mul(&m, v(a, 9)))
        }
        "color::srgb_oetf" => vec![color::srgb_oetf(a[0])],
        "color::srgb_oetf_fast" => vec![color::srgb_oetf_fast(a[0])],
        "color::srgb_eotf" => vec![color::srgb_eotf(a[0])],
        "color::rec709_oetf" => vec![color::rec709_oetf(a[0])],
        "color::gamma_encode" => vec![color::gamma_encode(a[0], a[1])],
        "color::gamma_decode" => vec![color::gamma_decode(a[0], a[1])],
        "color::srgb_oetf_rgb" => three(color::srgb_oetf_rgb(v(a, 0))),
        "color::srgb_eotf_rgb" => three(color::srgb_eotf_rgb(v(a, 0))),
        _ => return None,
    };
    Some(out)
}

/// The paths `direct` handles, read from its own source (the string patterns of its
/// `match`), so the set comparison with the table needs no second hand-kept list.
pub fn direct_paths() -> Vec<String> {
    let src = include_str!("direct.rs");
    let body = &src[src.find("let out = match path {").expect("direct's match")..];
    body.lines()
        .filter_map(|l| {
            let t = l.trim_start();
            let rest = t.strip_prefix('"')?;
            let (path, after) = rest.split_once('"')?;
            after
                .trim_start()
                .starts_with("=>")
                .then(|| path.to_string())
        })
        .collect()
}
