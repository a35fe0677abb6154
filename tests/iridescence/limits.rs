//! A vanishing film leaves the base's own Fresnel reflectance: thickness 0 (the film's index is
//! blended to the outside's) or a film index equal to the outside's (no first interface).

use brdf::fresnel;
use brdf::iridescence::{ThinFilm, conductor, dielectric};

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 4e-15 + 1e-12 * b.abs()
}

#[test]
fn thickness_zero_is_the_base_fresnel() {
    for film_ior in [1.0, 1.3, 2.5, 10.0] {
        let none = ThinFilm::new(0.0, film_ior).unwrap();
        for (n1, n3, k3) in [
            (1.0, 1.5, 0.0),
            (1.33, 1.1, 0.0),
            (1.5, 1.0, 0.0),
            (1.0, 0.2, 3.9),
            (1.0, 1.1, 6.8),
            (1.33, 2.9, 0.5),
        ] {
            for i in 0..=50 {
                let c = f64::from(i) / 50.0;
                let xyz = if k3 == 0.0 {
                    dielectric(&none, n1, n3, c)
                } else {
                    conductor(&none, n1, n3, k3, c)
                };
                let want = if k3 == 0.0 {
                    fresnel::dielectric(c, n3 / n1)
                } else {
                    fresnel::conductor(c, n3 / n1, k3 / n1)
                };
                for v in [xyz.x, xyz.y, xyz.z] {
                    assert!(
                        close(v, want),
                        "film {film_ior} n1 {n1} base {n3}+{k3}i cos {c}: {v} vs {want}"
                    );
                }
            }
        }
    }
}

#[test]
fn film_index_equal_to_outside_is_the_base_fresnel() {
    for d in [30.0, 250.0, 1000.0, 10_000.0] {
        for (n1, n3, k3) in [(1.0, 1.5, 0.0), (1.3, 1.7, 0.0), (1.0, 0.2, 3.9)] {
            let film = ThinFilm::new(d, n1).unwrap();
            for c in [0.0, 0.3, 0.7, 1.0] {
                let xyz = conductor(&film, n1, n3, k3, c);
                let want = fresnel::conductor(c, n3 / n1, k3 / n1);
                assert!(
                    close(xyz.y, want) && close(xyz.x, want),
                    "{d} {n1} {n3} {k3} {c}: {xyz:?} {want}"
                );
            }
        }
    }
}

/// A film of non-zero thickness changes the reflectance (a test of the tests above: an
/// implementation that ignored the film would pass them).
#[test]
fn a_real_film_changes_the_colour() {
    let film = ThinFilm::new(300.0_f64, 1.33).unwrap();
    let xyz = dielectric(&film, 1.0, 1.5, 1.0);
    let bare = fresnel::dielectric(1.0, 1.5);
    assert!(
        (xyz.x - bare).abs() > 1e-3 && (xyz.x - xyz.z).abs() > 1e-3,
        "{xyz:?}"
    );
}
