//! The film's XYZ stays in [0, 1] and finite over the extreme grid (thickness 0 and at its
//! maximum, film index at its ends, bases from index-matched to the largest), on f32 and f64;
//! lanes follow their scalars; NaN in any input gives NaN.

use brdf::iridescence::{MAX_FILM_IOR, MAX_THICKNESS_NM, ThinFilm, conductor, dielectric};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

const THICK: [f64; 6] = [0.0, 1e-3, 15.0, 300.0, 5000.0, MAX_THICKNESS_NM];
const FILM: [f64; 4] = [1.0, 1.3, 3.0, MAX_FILM_IOR];
const OUTSIDE: [f64; 5] = [1e-30, 0.5, 1.0, 1.33, 1e30];
const BASE: [(f64, f64); 7] = [
    (1.0, 0.0),
    (1.5, 0.0),
    (0.2, 3.9),
    (1e-30, 0.0),
    (1e30, 0.0),
    (1.0, 1e30),
    (1e30, 1e30),
];
const COS: [f64; 6] = [0.0, 1e-7, 0.2, 0.7, 1.0 - 1e-7, 1.0];

fn in_unit<T: Real>(v: V3<T>) -> bool
where
    T::Scalar: Into<f64>,
{
    (0..T::LANES).all(|k| {
        [v.x, v.y, v.z].iter().all(|c| {
            let c: f64 = c.lane(k).into();
            (0.0..=1.0).contains(&c)
        })
    })
}

#[test]
fn values_lie_in_unit_interval_on_the_extreme_grid() {
    let mut count = 0;
    for d in THICK {
        for n2 in FILM {
            let f64_film = ThinFilm::new(d, n2).unwrap();
            let f32_film = ThinFilm::new(d as f32, n2 as f32).unwrap();
            for n1 in OUTSIDE {
                for (n3, k3) in BASE {
                    for c in COS {
                        let a = conductor(&f64_film, n1, n3, k3, c);
                        let b = conductor(&f32_film, n1 as f32, n3 as f32, k3 as f32, c as f32);
                        assert!(in_unit(a), "{d} {n2} {n1} {n3} {k3} {c}: {a:?}");
                        assert!(in_unit(b), "f32 {d} {n2} {n1} {n3} {k3} {c}: {b:?}");
                        if k3 == 0.0 {
                            assert!(in_unit(dielectric(&f64_film, n1, n3, c)));
                        }
                        count += 1;
                    }
                }
            }
        }
    }
    assert!(count > 5000);
}

/// Lanes against scalars: the kernel's cos and exp run through the lane polynomials (1 to 3
/// ULP, crate docs), so lanes differ by a few ULP of the larger terms; bound 1e-5 absolute in
/// f32x8 and 1e-13 in f64x4 (measured: printed).
#[test]
fn lanes_follow_scalars() {
    let (mut w32, mut w64): (f64, f64) = (0.0, 0.0);
    for d in THICK {
        for n2 in FILM {
            for (n3, k3) in BASE {
                for c in COS {
                    let s = conductor(&ThinFilm::new(d, n2).unwrap(), 1.0, n3, k3, c);
                    let l = conductor(
                        &ThinFilm::new(f64x4::splat(d), f64x4::splat(n2)).unwrap(),
                        f64x4::splat(1.0),
                        f64x4::splat(n3),
                        f64x4::splat(k3),
                        f64x4::splat(c),
                    );
                    w64 = w64
                        .max((s.x - l.x.lane(2)).abs())
                        .max((s.z - l.z.lane(0)).abs());
                    let s = conductor(
                        &ThinFilm::new(d as f32, n2 as f32).unwrap(),
                        1.0,
                        n3 as f32,
                        k3 as f32,
                        c as f32,
                    );
                    let l = conductor(
                        &ThinFilm::new(f32x8::splat(d as f32), f32x8::splat(n2 as f32)).unwrap(),
                        f32x8::splat(1.0),
                        f32x8::splat(n3 as f32),
                        f32x8::splat(k3 as f32),
                        f32x8::splat(c as f32),
                    );
                    w32 = w32.max(f64::from((s.y - l.y.lane(5)).abs()));
                }
            }
        }
    }
    println!("max |lane - scalar|: f32x8 {w32:.2e}, f64x4 {w64:.2e}");
    assert!(w32 < 1e-5 && w64 < 1e-13, "{w32} {w64}");
}

#[test]
fn nan_and_invalid_input_give_nan() {
    let film = ThinFilm::new(300.0, 1.33).unwrap();
    let nan = f64::NAN;
    for v in [
        conductor(&film, nan, 1.5, 0.0, 0.5),
        conductor(&film, 1.0, nan, 0.0, 0.5),
        conductor(&film, 1.0, 1.5, nan, 0.5),
        conductor(&film, 1.0, 1.5, 0.0, nan),
        conductor(&film, 1.0, 1.5, -1.0, 0.5),
        conductor(&film, 0.0, 1.5, 0.0, 0.5),
        conductor(&film, 1.0, f64::INFINITY, 0.0, 0.5),
        dielectric(&film, 1.0, -1.5, 0.5),
        dielectric(&film, 1.0, 1.5, nan),
    ] {
        assert!(v.x.is_nan() && v.y.is_nan() && v.z.is_nan(), "{v:?}");
    }
    assert!(ThinFilm::new(-1.0, 1.3).is_err());
    assert!(ThinFilm::new(MAX_THICKNESS_NM * 1.01, 1.3).is_err());
    assert!(ThinFilm::new(100.0, 0.9).is_err());
    assert!(ThinFilm::new(100.0, f64::NAN).is_err());
}
